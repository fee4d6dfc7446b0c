using System.Numerics;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;

namespace Ballistic.Planner.Animation;

/// <summary>
/// Keeps a rig's free bones (those that carry no limb and hang from none: a tail, a head on its neck) out of the
/// level: where a bone of no limb passes through it, the free chain it hangs from bends (up or down, left or right,
/// every joint of the chain toward the same limit) as little as clears every such bone, and the bend rises and falls
/// smoothly over <see cref="Ramp"/> seconds either side, so a tail lifts over the step behind a crouching body
/// instead of cutting through it. The limbs, the trunk and the root are not moved. Thread-safe.
/// </summary>
internal sealed class FreeBones
{
    /// <summary>Seconds over which a bend rises before and falls after the frames that need it.</summary>
    public const float Ramp = 0.25f;

    /// <summary>Bends tried, as shares of the way to the joints' limits.</summary>
    private const int Scales = 8;

    private readonly Rig _rig;
    private readonly BodyCollision _collision;
    private readonly bool[] _free;

    /// <summary>Creates the clearance of <paramref name="model"/>'s free bones against the level of <paramref name="collision"/>.</summary>
    public FreeBones(CharacterModel model, BodyCollision collision)
    {
        _rig = model.Rig;
        _collision = collision;
        _free = new bool[_rig.Joints.Count];
        for (int j = 1; j < _free.Length; j++)
        {
            _free[j] = _rig.DofsOf(j) > 0 && !model.Limbs.Any(l => _rig.IsAncestor(j, l.RootJoint) || _rig.IsAncestor(l.RootJoint, j));
        }

        Any = _free.Any(f => f);
    }

    /// <summary>Whether the rig has any free bone to bend.</summary>
    public bool Any { get; }

    /// <summary>
    /// Bends the free chains in <paramref name="angles"/> (one pose per frame, at <paramref name="times"/> seconds, the
    /// root of frame k at <paramref name="root"/>(k)) where a bone of no limb passes through the level; returns how
    /// many frames changed. Frames no bend clears are left as they were.
    /// </summary>
    public int Clear(IReadOnlyList<float> times, Func<int, RootPose> root, float[][] angles)
    {
        if (!Any || angles.Length == 0)
        {
            return 0;
        }

        var positions = new Vector3[_rig.Joints.Count];
        var rotations = new Quaternion[_rig.Joints.Count];
        var changed = new bool[angles.Length];

        // Twice: a chain bent clear may show another one behind it.
        for (int pass = 0; pass < 2; pass++)
        {
            var colliding = new Dictionary<int, List<int>>();
            for (int k = 0; k < angles.Length; k++)
            {
                _rig.Solve(root(k), angles[k], positions, rotations);
                int bone = _collision.OtherBoneColliding(positions, rotations);
                if (bone >= 0 && ChainOf(bone) is int chain and >= 0)
                {
                    (colliding.TryGetValue(chain, out List<int>? frames) ? frames : colliding[chain] = []).Add(k);
                }
            }

            if (colliding.Count == 0)
            {
                break;
            }

            foreach ((int chain, List<int> frames) in colliding)
            {
                Bend(chain, frames, times, root, angles, changed, positions, rotations);
            }
        }

        return changed.Count(c => c);
    }

    /// <summary>
    /// One pose (root <paramref name="root"/>, angles <paramref name="angles"/>) checked for bones of no limb in the
    /// level, its free chains bent clear first where one is (<see cref="Clear"/>): the first such bone still in the
    /// level (−1 for none) and the angles checked (<paramref name="angles"/> itself when nothing was bent).
    /// <paramref name="positions"/> and <paramref name="rotations"/> are left holding the pose as checked.
    /// </summary>
    public (int Bone, float[] Angles) Colliding(RootPose root, float[] angles, Vector3[] positions, Quaternion[] rotations)
    {
        _rig.Solve(root, angles, positions, rotations);
        int bone = _collision.OtherBoneColliding(positions, rotations);
        if (bone < 0 || !Any)
        {
            return (bone, angles);
        }

        float[][] one = [angles];
        Clear([0f], _ => root, one);
        _rig.Solve(root, one[0], positions, rotations);
        return (_collision.OtherBoneColliding(positions, rotations), one[0]);
    }

    /// <summary>The topmost free joint the bone <paramref name="bone"/> (its segment from its parent joint, or its skin) hangs from, or −1.</summary>
    private int ChainOf(int bone)
    {
        int top = _free[bone] ? bone : -1;
        for (int j = _rig.Joints[bone].Parent; j > 0 && _free[j]; j = _rig.Joints[j].Parent)
        {
            top = j;
        }

        return top;
    }

    /// <summary>Bends the chain from <paramref name="chain"/> at the frames given (and smoothly around them) the one way that clears the most of them.</summary>
    private void Bend(int chain, List<int> frames, IReadOnlyList<float> times, Func<int, RootPose> root, float[][] angles, bool[] changed, Vector3[] positions, Quaternion[] rotations)
    {
        int[] joints = [.. Enumerable.Range(0, _free.Length).Where(j => _free[j] && _rig.IsAncestor(chain, j))];
        int slots = joints.Max(_rig.DofsOf);
        float[]? best = null;
        (int Cleared, float Sum) bestScore = (0, 0f);
        (int Slot, bool Up) bestWay = (0, true);
        for (int slot = 0; slot < slots; slot++)
        {
            foreach (bool up in (bool[])[true, false])
            {
                float[] need = new float[frames.Count];
                int cleared = 0;
                float sum = 0f;
                for (int f = 0; f < frames.Count; f++)
                {
                    need[f] = float.NaN;
                    for (int s = 1; s <= Scales; s++)
                    {
                        float[] trial = Bent(angles[frames[f]], joints, slot, up, s / (float)Scales);
                        _rig.Solve(root(frames[f]), trial, positions, rotations);
                        if (_collision.OtherBoneColliding(positions, rotations) < 0)
                        {
                            need[f] = s / (float)Scales;
                            cleared++;
                            sum += need[f];
                            break;
                        }
                    }
                }

                if (cleared > bestScore.Cleared || (cleared == bestScore.Cleared && cleared > 0 && sum < bestScore.Sum))
                {
                    (best, bestScore, bestWay) = (need, (cleared, sum), (slot, up));
                }
            }
        }

        if (best is null)
        {
            return;
        }

        // The bend at every frame: the most any cleared frame needs, faded out over Ramp seconds from it.
        for (int k = 0; k < angles.Length; k++)
        {
            float share = 0f;
            for (int f = 0; f < frames.Count; f++)
            {
                if (float.IsFinite(best[f]))
                {
                    float x = 1f - (MathF.Abs(times[k] - times[frames[f]]) / Ramp);
                    share = MathF.Max(share, best[f] * Smooth(x));
                }
            }

            if (share > 0f)
            {
                angles[k] = Bent(angles[k], joints, bestWay.Slot, bestWay.Up, share);
                changed[k] = true;
            }
        }
    }

    /// <summary><paramref name="q"/> with each joint of <paramref name="joints"/> turned <paramref name="share"/> of the way to its limit on axis <paramref name="slot"/> (its max when <paramref name="up"/>, else its min).</summary>
    private float[] Bent(float[] q, int[] joints, int slot, bool up, float share)
    {
        float[] bent = (float[])q.Clone();
        foreach (int j in joints)
        {
            if (slot < _rig.DofsOf(j))
            {
                int d = _rig.FirstDof(j) + slot;
                JointAxis axis = _rig.Dofs[d];
                bent[d] = float.Lerp(q[d], up ? axis.Max : axis.Min, share);
            }
        }

        return bent;
    }

    private static float Smooth(float x) => Easing.Smooth(x);
}
