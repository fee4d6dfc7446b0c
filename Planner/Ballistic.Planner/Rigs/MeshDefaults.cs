using System.Numerics;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Rigs;

/// <summary>
/// Limb spec defaults derived from a rig's skinned vertices (each vertex belongs to the bone with its largest weight
/// and is given in that bone's rest frame): bone radii, and a limb's contact point and sole normal.
/// </summary>
internal static class MeshDefaults
{
    /// <summary>Fraction of a bone's vertices that its radius covers.</summary>
    public const float RadiusPercentile = 0.9f;

    /// <summary>
    /// The radius of each bone (the segment from the joint's parent to the joint), or <c>null</c> where no vertex
    /// says: the 90th percentile of the distance to that segment of the parent's vertices that lie nearer it than
    /// any other of the parent's child segments. The root's radius is that of its own vertices to its nearest child
    /// segment (or to the joint when it has no child).
    /// </summary>
    public static float?[] Radii(IReadOnlyList<Joint> joints, IReadOnlyList<List<Vector3>> points)
    {
        var radii = new float?[joints.Count];
        var distances = new List<float>[joints.Count];
        for (int j = 0; j < joints.Count; j++)
        {
            distances[j] = [];
        }

        for (int p = 0; p < joints.Count; p++)
        {
            int[] children = [.. Enumerable.Range(0, joints.Count).Where(c => joints[c].Parent == p)];
            foreach (Vector3 point in points[p])
            {
                int nearest = -1;
                float best = point.Length();
                foreach (int c in children)
                {
                    float d = SegmentDistance(point, Vector3.Zero, joints[c].Offset);
                    if (nearest < 0 || d < best)
                    {
                        best = d;
                        nearest = c;
                    }
                }

                if (nearest >= 0)
                {
                    distances[nearest].Add(best);
                }

                if (p == 0)
                {
                    distances[0].Add(best);
                }
            }
        }

        for (int j = 0; j < joints.Count; j++)
        {
            if (distances[j].Count > 0)
            {
                distances[j].Sort();
                radii[j] = MathF.Max(1e-3f, distances[j][(int)(RadiusPercentile * (distances[j].Count - 1))]);
            }
        }

        return radii;
    }

    /// <summary>
    /// Of <paramref name="points"/>, the farthest along each of 14 directions (±X, ±Y, ±Z and the 8 diagonals), each
    /// point once: a handful of points on the hull of a bone's skinned vertices.
    /// </summary>
    public static Vector3[] Extremes(IReadOnlyList<Vector3> points)
    {
        ArgumentNullException.ThrowIfNull(points);
        if (points.Count == 0)
        {
            return [];
        }

        var found = new List<Vector3>();
        foreach (Vector3 direction in Directions)
        {
            Vector3 best = points[0];
            foreach (Vector3 p in points)
            {
                if (Vector3.Dot(p, direction) > Vector3.Dot(best, direction))
                {
                    best = p;
                }
            }

            if (!found.Contains(best))
            {
                found.Add(best);
            }
        }

        return [.. found];
    }

    /// <summary>
    /// Of <paramref name="points"/>, one in each occupied cell of a grid <see cref="SpreadSpacing"/> metres wide (the
    /// first met, in order), the grid widened by half again until at most <see cref="SpreadCap"/> remain: points spread
    /// over the whole skin of a bone, not only its hull's extremes. A level's edge that enters a flat face of the skin
    /// (a door's jamb into a box-shaped head) passes between the extremes; one entering more than about half the
    /// spacing deep has a spread point inside it.
    /// </summary>
    public static Vector3[] Spread(IReadOnlyList<Vector3> points)
    {
        ArgumentNullException.ThrowIfNull(points);
        var kept = new List<Vector3>();
        var cells = new HashSet<(int, int, int)>();
        for (float spacing = SpreadSpacing; ; spacing *= 1.5f)
        {
            kept.Clear();
            cells.Clear();
            foreach (Vector3 p in points)
            {
                if (cells.Add(((int)MathF.Floor(p.X / spacing), (int)MathF.Floor(p.Y / spacing), (int)MathF.Floor(p.Z / spacing))))
                {
                    kept.Add(p);
                }
            }

            if (kept.Count <= SpreadCap)
            {
                return [.. kept];
            }
        }
    }

    /// <summary>Width (metres) of the grid cells of <see cref="Spread"/>: a level edge 1.5 cm into a flat skin face (the body check's depth) reaches a point.</summary>
    public const float SpreadSpacing = 0.03f;

    /// <summary>Most points <see cref="Spread"/> keeps of one bone's skin.</summary>
    public const int SpreadCap = 240;

    /// <summary>Slices along a bone over which <see cref="BlendedExtremes"/> looks for blended skin's extremes.</summary>
    public const int BlendSlices = 3;

    /// <summary>
    /// Of the vertices of <paramref name="points"/> weighted to several bones (those whose <paramref name="blends"/>
    /// entry, same order, is not empty), in each of <see cref="BlendSlices"/> equal slices along the axis (X, Y or Z
    /// of the bone's frame) over which they spread farthest, the farthest along each of the 14 directions of
    /// <see cref="Extremes"/>: the blended skin around a joint and along the bone (a shin skinned partly to the thigh
    /// folds at its middle too, not only at its ends), each with its bones' shares.
    /// </summary>
    public static SkinBlend[][] BlendedExtremes(IReadOnlyList<Vector3> points, IReadOnlyList<SkinBlend[]> blends)
    {
        ArgumentNullException.ThrowIfNull(points);
        ArgumentNullException.ThrowIfNull(blends);
        var blended = new List<Vector3>();
        var of = new Dictionary<Vector3, SkinBlend[]>();
        for (int i = 0; i < points.Count && i < blends.Count; i++)
        {
            if (blends[i].Length > 0 && of.TryAdd(points[i], blends[i]))
            {
                blended.Add(points[i]);
            }
        }

        if (blended.Count == 0)
        {
            return [];
        }

        Vector3 low = blended[0];
        Vector3 high = blended[0];
        foreach (Vector3 p in blended)
        {
            (low, high) = (Vector3.Min(low, p), Vector3.Max(high, p));
        }

        Vector3 spread = high - low;
        Vector3 axis = spread.X >= spread.Y && spread.X >= spread.Z ? Vector3.UnitX : spread.Y >= spread.Z ? Vector3.UnitY : Vector3.UnitZ;
        float from = Vector3.Dot(low, axis);
        float length = Vector3.Dot(spread, axis);
        var found = new List<Vector3>();
        for (int slice = 0; slice < BlendSlices; slice++)
        {
            List<Vector3> inSlice = [.. blended.Where(p => (length > 0f ? Math.Min(BlendSlices - 1, (int)((Vector3.Dot(p, axis) - from) / length * BlendSlices)) : 0) == slice)];
            found.AddRange(Extremes(inSlice).Where(p => !found.Contains(p)));
        }

        return [.. found.Select(p => of[p])];
    }

    private static readonly Vector3[] Directions =
    [
        Vector3.UnitX, -Vector3.UnitX, Vector3.UnitY, -Vector3.UnitY, Vector3.UnitZ, -Vector3.UnitZ,
        new(1f, 1f, 1f), new(1f, 1f, -1f), new(1f, -1f, 1f), new(1f, -1f, -1f),
        new(-1f, 1f, 1f), new(-1f, 1f, -1f), new(-1f, -1f, 1f), new(-1f, -1f, -1f),
    ];

    /// <summary>
    /// The contact point and sole normal of a limb in its effector's frame, from the vertices of the effector and
    /// its descendants in the rest pose (every angle 0): the normal is the rest pose's down direction; the point lies
    /// at the height of the lowest vertex, at the centre (in the horizontal plane) of the vertices within
    /// 5 mm + 5 % of the effector's height of it. <c>null</c> when no vertex belongs to the effector or below it.
    /// </summary>
    public static (Vector3 Offset, Vector3 Normal)? Contact(Rig rig, int effector, IReadOnlyList<List<Vector3>> points)
    {
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), new float[rig.DofCount], positions, rotations);
        Quaternion toEffector = Quaternion.Conjugate(rotations[effector]);
        Vector3 normal = Vector3.Normalize(Vector3.Transform(-Vector3.UnitY, toEffector));
        var cloud = new List<Vector3>();
        for (int j = 0; j < rig.Joints.Count; j++)
        {
            if (rig.IsAncestor(effector, j))
            {
                cloud.AddRange(points[j].Select(p => positions[j] + Vector3.Transform(p, rotations[j])));
            }
        }

        if (cloud.Count == 0)
        {
            return null;
        }

        float low = cloud.Min(p => p.Y);
        float band = 0.005f + (0.05f * (cloud.Max(p => p.Y) - low));
        Vector3[] sole = [.. cloud.Where(p => p.Y <= low + band)];
        float x = (sole.Min(p => p.X) + sole.Max(p => p.X)) * 0.5f;
        float z = (sole.Min(p => p.Z) + sole.Max(p => p.Z)) * 0.5f;
        Vector3 offset = Vector3.Transform(new Vector3(x, low, z) - positions[effector], toEffector);
        return (offset, normal);
    }

    private static float SegmentDistance(Vector3 p, Vector3 a, Vector3 b)
    {
        Vector3 ab = b - a;
        float t = ab.LengthSquared() > 1e-12f ? Math.Clamp(Vector3.Dot(p - a, ab) / ab.LengthSquared(), 0f, 1f) : 0f;
        return Vector3.Distance(p, a + (ab * t));
    }
}
