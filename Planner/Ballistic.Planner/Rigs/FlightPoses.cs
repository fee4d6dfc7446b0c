using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Rigs;

/// <summary>
/// The flexion (tucked) and extending (stretched) poses of a rig whose spec gives none, derived from its limbs'
/// workspaces and joint limits rather than left in the bind pose: each limb's effector is placed by IK, from the
/// contact pose and within the joints' limits, at a point of its workspace around its root joint. Feet tuck under the
/// body (a biped's and hind legs' forward, front legs' back) and stretch out (a biped's a little behind, front legs
/// forward, hind legs back); hands fold in front of the chest and reach forward and up. A limb whose targets are all
/// out of its reach keeps its contact pose. Model frame: +Y up, +Z forward, +X the character's left.
/// </summary>
internal static class FlightPoses
{
    /// <summary>Share of a limb's reach (root to effector at rest) the tucked effector lies from the root.</summary>
    private const float Tuck = 0.6f;

    /// <summary>Feet whose roots lie further apart along the body than this share of the mean reach have a front and a back.</summary>
    private const float FrontAndBack = 0.5f;

    /// <summary>Bend (radians) added to each hinge of a limb before IK places it.</summary>
    private const float SeedBend = 0.4f;

    private static readonly IkSettings Settings = new() { Restarts = 0, MaxIterations = 120, PositionTolerance = 0.2f, NormalTolerance = 60f * MathF.PI / 180f };

    /// <summary>The (flexion, extending) poses of <paramref name="rig"/> with <paramref name="limbs"/>, from <paramref name="contact"/>.</summary>
    public static (float[] Flexion, float[] Extending) Derive(Rig rig, IReadOnlyList<RigLimb> limbs, float[] contact)
    {
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        var identity = new RootPose(Vector3.Zero, Quaternion.Identity);
        rig.Solve(identity, contact, positions, rotations);
        RigLimb[] feet = [.. limbs.Where(l => l.Kind == LimbKind.Foot)];
        float spread = feet.Length < 2 ? 0f : feet.Max(l => positions[l.RootJoint].Z) - feet.Min(l => positions[l.RootJoint].Z);
        float meanReach = feet.Length == 0 ? 1f : feet.Average(l => Vector3.Distance(positions[l.RootJoint], l.EffectorPosition(positions, rotations)));
        float middle = feet.Length == 0 ? 0f : 0.5f * (feet.Max(l => positions[l.RootJoint].Z) + feet.Min(l => positions[l.RootJoint].Z));
        bool frontAndBack = spread > FrontAndBack * meanReach || Fanned(feet, positions, rotations);

        float[] flexion = (float[])contact.Clone();
        float[] extending = (float[])contact.Clone();
        var ik = new LimbIk(rig, Settings);
        foreach (RigLimb limb in limbs)
        {
            Vector3 hip = positions[limb.RootJoint];
            Vector3 effector = limb.EffectorPosition(positions, rotations);
            Vector3 normal = limb.EffectorNormal(rotations);
            float reach = Vector3.Distance(hip, effector);
            if (reach < 1e-4f)
            {
                continue;
            }

            Vector3 rest = (effector - hip) / reach;
            Vector3 outward = new(MathF.Sign(hip.X - positions[0].X), 0f, 0f);
            Vector3 tucked;
            Vector3 stretched;
            if (limb.Kind == LimbKind.Foot)
            {
                bool front = frontAndBack && hip.Z > middle;
                Vector3 fold = front ? -Vector3.UnitZ : Vector3.UnitZ;
                tucked = Tuck * Vector3.Normalize(rest + (0.6f * fold) + (0.2f * Vector3.UnitY));
                stretched = 0.95f * Vector3.Normalize(rest + (frontAndBack ? (front ? 0.8f : -0.8f) * Vector3.UnitZ : -0.35f * Vector3.UnitZ));
            }
            else
            {
                tucked = Tuck * Vector3.Normalize(Vector3.UnitZ - (0.4f * Vector3.UnitY) + (0.2f * outward));
                stretched = 0.9f * Vector3.Normalize((0.5f * Vector3.UnitZ) + (0.9f * Vector3.UnitY) + (0.4f * outward));
            }

            Place(ik, identity, flexion, limb, hip, reach, rest, tucked, normal);
            Place(ik, identity, extending, limb, hip, reach, rest, stretched, normal);
        }

        return (flexion, extending);
    }

    /// <summary>
    /// Whether <paramref name="feet"/> fan out around the body (a spider's: their roots close together along it, some
    /// feet reaching ahead of their roots by more than <see cref="FanShare"/> of their reach and some as far behind),
    /// so that they too have a front and a back: treated as one walker's feet, a spider's eight legs all swung a
    /// little back for its stretched pose, 10° from its rest on average, and read as no flight pose.
    /// </summary>
    private static bool Fanned(RigLimb[] feet, Vector3[] positions, Quaternion[] rotations)
    {
        bool ahead = false;
        bool behind = false;
        foreach (RigLimb foot in feet)
        {
            Vector3 reach = foot.EffectorPosition(positions, rotations) - positions[foot.RootJoint];
            float along = reach.Length() < 1e-4f ? 0f : reach.Z / reach.Length();
            ahead |= along > FanShare;
            behind |= along < -FanShare;
        }

        return ahead && behind;
    }

    /// <summary>Share of a foot's reach (root to effector at rest) it must lie ahead of or behind its root, along the body, for its rig's feet to fan out (<see cref="Fanned"/>).</summary>
    private const float FanShare = 0.4f;

    /// <summary>
    /// Moves <paramref name="limb"/> in <paramref name="q"/> so that its effector lies at <paramref name="hip"/> plus
    /// <paramref name="reach"/> times <paramref name="toward"/> (turning its contact normal as its direction turns);
    /// failing that, at points part of the way back toward the rest direction; failing all, it stays as it is.
    /// </summary>
    internal static void Place(LimbIk ik, RootPose root, float[] q, RigLimb limb, Vector3 hip, float reach, Vector3 rest, Vector3 toward, Vector3 normal)
    {
        for (int k = 0; k < 4; k++)
        {
            Vector3 direction = Vector3.Lerp(toward, rest * toward.Length(), k / 4f);
            Vector3 unit = Vector3.Normalize(direction);
            Quaternion turn = Between(rest, unit);

            // From the pose with its hinges (knees, elbows) a little bent: a straight limb is singular, IK cannot
            // shorten it.
            float[] trial = (float[])q.Clone();
            foreach (int joint in limb.Chain.Skip(1).SkipLast(1).Where(j => ik.Rig.DofsOf(j) == 1))
            {
                int d = ik.Rig.FirstDof(joint);
                trial[d] = ik.Rig.Dofs[d].Clamp(trial[d] + SeedBend);
            }

            if (ik.Reaches(root, trial, limb, hip + (reach * direction), Vector3.Transform(normal, turn)))
            {
                Array.Copy(trial, q, q.Length);
                return;
            }
        }
    }

    /// <summary>The shortest rotation taking unit <paramref name="from"/> to unit <paramref name="to"/>.</summary>
    private static Quaternion Between(Vector3 from, Vector3 to)
    {
        Vector3 axis = Vector3.Cross(from, to);
        float dot = Math.Clamp(Vector3.Dot(from, to), -1f, 1f);
        if (axis.LengthSquared() < 1e-10f)
        {
            return dot > 0f ? Quaternion.Identity : Quaternion.CreateFromAxisAngle(Vector3.UnitX, MathF.PI);
        }

        return Quaternion.CreateFromAxisAngle(Vector3.Normalize(axis), MathF.Acos(dot));
    }
}
