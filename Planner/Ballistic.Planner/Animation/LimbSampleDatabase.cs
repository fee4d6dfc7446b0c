using System.Numerics;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;

namespace Ballistic.Planner.Animation;

/// <summary>
/// Random configurations of one limb, indexed by where they put the contact point in the trunk frame (a hash grid
/// of cubic cells), as the original planner's limb databases were: the nearest sample to a target point is the
/// IK's starting guess. Samples are kept in order of closeness to the contact reference pose. Thread-safe once built.
/// </summary>
internal sealed class LimbSampleDatabase
{
    private readonly float[][] _angles;
    private readonly Vector3[] _points;
    private readonly Dictionary<(int, int, int), List<int>> _grid = [];

    /// <summary>Samples <paramref name="count"/> configurations of <paramref name="limb"/> (deterministic for a seed).</summary>
    public LimbSampleDatabase(CharacterModel model, RigLimb limb, int count = 2_000, float cellSize = 0.05f, int seed = 17)
    {
        ArgumentNullException.ThrowIfNull(model);
        ArgumentNullException.ThrowIfNull(limb);
        Limb = limb;
        CellSize = cellSize;
        Rig rig = model.Rig;
        var random = new Random(seed);
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        var samples = new List<(float Distance, float[] Angles, Vector3 Point)>(count + 1);
        float[] q = (float[])model.ContactPose.Clone();
        for (int s = 0; s <= count; s++)
        {
            float distance = 0f;
            for (int c = 0; c < limb.ChainDofs.Count; c++)
            {
                int d = limb.ChainDofs[c];
                JointAxis axis = rig.Dofs[d];
                q[d] = s == 0 ? model.ContactPose[d] : axis.Min + ((float)random.NextDouble() * (axis.Max - axis.Min));
                distance += MathF.Abs(q[d] - model.ContactPose[d]);
            }

            rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), q, positions, rotations);
            samples.Add((distance, [.. limb.ChainDofs.Select(d => q[d])], limb.EffectorPosition(positions, rotations)));
        }

        samples.Sort((a, b) => a.Distance.CompareTo(b.Distance));
        _angles = [.. samples.Select(x => x.Angles)];
        _points = [.. samples.Select(x => x.Point)];
        for (int i = 0; i < _points.Length; i++)
        {
            (int, int, int) key = Cell(_points[i]);
            if (!_grid.TryGetValue(key, out List<int>? list))
            {
                _grid[key] = list = [];
            }

            list.Add(i);
        }
    }

    /// <summary>The limb.</summary>
    public RigLimb Limb { get; }

    /// <summary>Edge of a grid cell, metres.</summary>
    public float CellSize { get; }

    /// <summary>Number of samples.</summary>
    public int Count => _points.Length;

    /// <summary>The contact point of sample <paramref name="index"/> in the trunk frame.</summary>
    public Vector3 PointOf(int index) => _points[index];

    /// <summary>
    /// The sample whose contact point is nearest <paramref name="trunkPoint"/> (trunk frame), searching outward
    /// ring by ring up to <paramref name="maxRings"/> cells; ties go to the sample closer to the contact pose.
    /// −1 when no sample lies that close.
    /// </summary>
    public int Nearest(Vector3 trunkPoint, int maxRings = 4)
    {
        (int cx, int cy, int cz) = Cell(trunkPoint);
        int best = -1;
        float bestDistance = float.PositiveInfinity;
        for (int ring = 0; ring <= maxRings; ring++)
        {
            for (int x = cx - ring; x <= cx + ring; x++)
            {
                for (int y = cy - ring; y <= cy + ring; y++)
                {
                    for (int z = cz - ring; z <= cz + ring; z++)
                    {
                        if (Math.Max(Math.Abs(x - cx), Math.Max(Math.Abs(y - cy), Math.Abs(z - cz))) != ring ||
                            !_grid.TryGetValue((x, y, z), out List<int>? list))
                        {
                            continue;
                        }

                        foreach (int i in list)
                        {
                            float d = Vector3.DistanceSquared(_points[i], trunkPoint);
                            if (d < bestDistance || (d == bestDistance && i < best))
                            {
                                best = i;
                                bestDistance = d;
                            }
                        }
                    }
                }
            }

            // Everything in later rings is at least ring × cell away.
            if (best >= 0 && MathF.Sqrt(bestDistance) <= ring * CellSize)
            {
                break;
            }
        }

        return best;
    }

    /// <summary>Writes sample <paramref name="index"/>'s chain angles into <paramref name="q"/>.</summary>
    public void Apply(int index, Span<float> q)
    {
        float[] angles = _angles[index];
        for (int c = 0; c < angles.Length; c++)
        {
            q[Limb.ChainDofs[c]] = angles[c];
        }
    }

    private (int, int, int) Cell(Vector3 p) =>
        ((int)MathF.Floor(p.X / CellSize), (int)MathF.Floor(p.Y / CellSize), (int)MathF.Floor(p.Z / CellSize));
}
