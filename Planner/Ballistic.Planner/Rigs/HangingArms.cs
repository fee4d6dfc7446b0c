using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Rigs;

/// <summary>
/// The standing pose of the free hands of a rig whose spec gives no contact pose (<see cref="CharacterModel.HangingPose"/>):
/// humanoid exports are modelled in a T- or A-pose, arms held out, and a character standing between its moves with its
/// arms out reads as a rig in its bind pose, not as a body at rest. Each hand whose rest pose holds it more than
/// <see cref="Hanging"/> off straight down from its shoulder is lowered by IK, within the joint limits, to hang a
/// little outward and forward of its shoulder, the elbow slightly bent; a hand already hanging, or one the IK cannot
/// lower, keeps its rest pose. Feet are never moved. Model frame: +Y up, +Z forward, +X the character's left.
/// </summary>
internal static class HangingArms
{
    /// <summary>Angle (radians, 30°) off straight down within which a hand counts as hanging at rest already.</summary>
    public const float Hanging = 30f * MathF.PI / 180f;

    /// <summary>Share of the arm's reach (shoulder to hand at rest) the hanging hand lies from its shoulder: the elbow a little bent.</summary>
    private const float Reach = 0.92f;

    /// <summary>The hanging direction's outward and forward parts, per unit down: the hand clear of the thigh, a little ahead of the hip.</summary>
    private const float Outward = 0.15f;

    private const float Forward = 0.08f;

    private static readonly IkSettings Settings = new() { Restarts = 0, MaxIterations = 120, PositionTolerance = 0.03f, NormalTolerance = 60f * MathF.PI / 180f };

    /// <summary>
    /// <paramref name="contact"/> with each hand of <paramref name="limbs"/> that <paramref name="contact"/> holds out
    /// lowered to hang (with <paramref name="every"/>, every hand, however it hangs already); the same array's values
    /// when no hand needs it.
    /// </summary>
    public static float[] Derive(Rig rig, IReadOnlyList<RigLimb> limbs, float[] contact, bool every = false)
    {
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        var identity = new RootPose(Vector3.Zero, Quaternion.Identity);
        rig.Solve(identity, contact, positions, rotations);
        float[] hanging = (float[])contact.Clone();
        var ik = new LimbIk(rig, Settings);
        foreach (RigLimb limb in limbs.Where(l => l.Kind == LimbKind.Hand))
        {
            Vector3 shoulder = positions[limb.RootJoint];
            Vector3 hand = limb.EffectorPosition(positions, rotations);
            float reach = Vector3.Distance(shoulder, hand);
            if (reach < 1e-4f)
            {
                continue;
            }

            Vector3 rest = (hand - shoulder) / reach;
            if (!every && Vector3.Dot(rest, -Vector3.UnitY) >= MathF.Cos(Hanging))
            {
                continue;
            }

            Vector3 outward = new(MathF.Sign(shoulder.X - positions[0].X), 0f, 0f);
            Vector3 down = Reach * Vector3.Normalize(-Vector3.UnitY + (Outward * outward) + (Forward * Vector3.UnitZ));
            FlightPoses.Place(ik, identity, hanging, limb, shoulder, reach, rest, down, limb.EffectorNormal(rotations));
        }

        return hanging;
    }
}
