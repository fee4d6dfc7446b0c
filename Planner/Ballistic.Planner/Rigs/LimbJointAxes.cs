using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Rigs;

/// <summary>
/// Joint axes for the limb bones of a spec that gives none (a limbs-only spec), derived from the rig's rest pose the
/// way an animator rigs them: a leg's root bone (hip) turns about the body's own axes (flexion about its left, a
/// limited spread about its forward, a limited twist about its up) whatever rest rotation the file gives the bone;
/// each bone between a limb's root and effector (knee, elbow, hock) is a hinge bending the way the rest pose bends it,
/// or, where the rest pose holds it straight, the way such joints bend (a knee takes the foot back, or down on a leg
/// spread sideways; an elbow, and a quadruped's front knee, takes the hand or paw forward); the effector (ankle, wrist) and an arm's root (shoulder) are
/// ball joints of ±90° about their rest frame's axes. Model frame: +Y up, +Z forward, +X the character's left.
/// </summary>
internal static class LimbJointAxes
{
    /// <summary>A rest bend below this (degrees) counts as straight.</summary>
    private const float StraightBelow = 8f;

    /// <summary>Greatest bend of a derived hinge from straight, degrees.</summary>
    private const float MostBend = 150f;

    /// <summary>How far a derived hinge may open past straight, degrees.</summary>
    private const float PastStraight = 5f;

    /// <summary>The ball joint of ±90° about the rest frame's axes (effectors, shoulders).</summary>
    public static readonly JointAxis[] Ball =
    [
        new JointAxis(Vector3.UnitX, Radians(-90f), Radians(90f)),
        new JointAxis(Vector3.UnitY, Radians(-90f), Radians(90f)),
        new JointAxis(Vector3.UnitZ, Radians(-90f), Radians(90f)),
    ];

    /// <summary>
    /// The axes of every bone on the limb chains of <paramref name="bare"/> (joints with their rest transforms in the
    /// model frame; their own axes are ignored), limb by limb (kind, root bone, effector bone); with
    /// <paramref name="free"/> (a spec that gives no joint axes at all), also a bend of <see cref="FreeBend"/>° and a
    /// turn of <see cref="FreeTurn"/>° for every bone that carries no limb, hangs from none and is not in
    /// <paramref name="trunk"/> (the spec's trunk bones). The rig's root joint
    /// gets none.
    /// </summary>
    public static Dictionary<int, JointAxis[]> Derive(IReadOnlyList<Joint> bare, IReadOnlyList<(LimbKind Kind, int Root, int Effector)> limbs, bool free = false, IReadOnlyCollection<int>? trunk = null)
    {
        var rest = new Rig([.. bare.Select(j => j with { Axes = [] })], Vector3.Zero);
        var positions = new Vector3[bare.Count];
        var rotations = new Quaternion[bare.Count];
        rest.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), [], positions, rotations);
        // Feet spread along the body (a quadruped's, a hexapod's) have a front: front legs are arms, bending at the
        // elbow the way hands do.
        var feet = limbs.Where(l => l.Kind == LimbKind.Foot && l.Root >= 0).ToArray();
        float back = feet.Length < 2 ? 0f : feet.Min(l => positions[l.Root].Z);
        float front = feet.Length < 2 ? 0f : feet.Max(l => positions[l.Root].Z);
        float reach = feet.Length == 0 ? 1f : feet.Average(l => Vector3.Distance(positions[l.Root], positions[Math.Max(l.Effector, 0)]));
        bool frontAndBack = front - back > 0.5f * reach;
        var axes = new Dictionary<int, JointAxis[]>();
        foreach ((LimbKind kind, int root, int effector) in limbs)
        {
            bool arm = kind == LimbKind.Hand || (frontAndBack && root >= 0 && positions[root].Z > 0.5f * (front + back));
            var chain = new List<int>();
            for (int j = effector; j >= 0; j = bare[j].Parent)
            {
                chain.Add(j);
                if (j == root)
                {
                    break;
                }
            }

            chain.Reverse();
            for (int k = 0; k < chain.Count; k++)
            {
                int j = chain[k];
                if (j == 0 || axes.ContainsKey(j))
                {
                    continue;
                }

                axes[j] = k == chain.Count - 1 ? Ball
                    : k == 0 ? (kind == LimbKind.Foot ? Hip(positions, rotations, j, chain[^1]) : Ball)
                    : Hinge(arm, positions[chain[k - 1]], positions[j], positions[chain[k + 1]], rotations[j]);
            }
        }

        if (!free)
        {
            return axes;
        }

        // With free: bones that carry no limb and hang from none (a tail, a head, a helper bone) get a free bend, so
        // that the animation can lift a tail out of a step behind the body instead of through it.
        var carries = new bool[bare.Count];
        foreach ((LimbKind _, int root, int effector) in limbs)
        {
            for (int j = Math.Max(effector, 0); j >= 0; j = bare[j].Parent)
            {
                carries[j] = true;
            }

            for (int j = 0; j < bare.Count; j++)
            {
                carries[j] |= root >= 0 && rest.IsAncestor(root, j);
            }
        }

        for (int j = 1; j < bare.Count; j++)
        {
            if (!carries[j] && !axes.ContainsKey(j) && trunk?.Contains(j) != true)
            {
                Quaternion toLocal = Quaternion.Conjugate(rotations[j]);
                axes[j] =
                [
                    new JointAxis(Local(Vector3.UnitX, toLocal), Radians(-FreeBend), Radians(FreeBend)),
                    new JointAxis(Local(Vector3.UnitY, toLocal), Radians(-FreeTurn), Radians(FreeTurn)),
                ];
            }
        }

        return axes;
    }

    /// <summary>How far a free bone (<see cref="Derive"/>) bends up or down, about the body's left, degrees.</summary>
    public const float FreeBend = 45f;

    /// <summary>How far a free bone turns left or right, about the body's up, degrees.</summary>
    public const float FreeTurn = 30f;

    /// <summary>
    /// A hip: flexion about the body's left (−90° to 90°), a spread about its forward (away from the body at most 30°,
    /// toward it 15°; ±45° for a leg the rest pose spreads sideways more than it hangs), and a twist about its up
    /// (±45°), in the joint's rest frame.
    /// </summary>
    private static JointAxis[] Hip(Vector3[] positions, Quaternion[] rotations, int hip, int effector)
    {
        Quaternion toLocal = Quaternion.Conjugate(rotations[hip]);
        Vector3 leg = positions[effector] - positions[hip];
        float side = MathF.Sign(positions[hip].X - positions[0].X);
        bool spread = leg.LengthSquared() > 1e-10f && MathF.Abs(Vector3.Normalize(leg).Y) < 0.7f;
        (float outward, float inward) = spread ? (45f, 45f) : (30f, 15f);

        // A positive turn about +Z takes a hanging leg toward +X, the left: away from the body for a left leg.
        (float min, float max) = side >= 0f ? (-inward, outward) : (-outward, inward);
        return
        [
            new JointAxis(Local(Vector3.UnitX, toLocal), Radians(-90f), Radians(90f)),
            new JointAxis(Local(Vector3.UnitZ, toLocal), Radians(min), Radians(max)),
            new JointAxis(Local(Vector3.UnitY, toLocal), Radians(-45f), Radians(45f)),
        ];
    }

    /// <summary>
    /// A hinge at <paramref name="joint"/> between the bone arriving from <paramref name="parent"/> and the one leaving
    /// toward <paramref name="child"/>: bending the way the rest pose bends it, from straight (a little past) to
    /// <see cref="MostBend"/>; straight at rest, the way a knee bends (foot back; down on a leg spread sideways) or, for
    /// an <paramref name="arm"/> (a hand, or a front leg of a body with feet front and back), an elbow (forward).
    /// </summary>
    private static JointAxis[] Hinge(bool arm, Vector3 parent, Vector3 joint, Vector3 child, Quaternion rotation)
    {
        Vector3 arriving = Direction(joint - parent);
        Vector3 leaving = Direction(child - joint);
        float bend = MathF.Acos(Math.Clamp(Vector3.Dot(arriving, leaving), -1f, 1f)) * 180f / MathF.PI;
        Vector3 axis = Vector3.Cross(arriving, leaving);
        if (bend < StraightBelow || axis.LengthSquared() < 1e-8f)
        {
            // Straight: a knee takes the foot back (down, on a leg spread sideways), an elbow the hand forward (up).
            Vector3 toward = !arm
                ? (-Vector3.UnitZ * MathF.Abs(leaving.Y)) - (Vector3.UnitY * (1f - MathF.Abs(leaving.Y)))
                : MathF.Abs(leaving.Z) < 0.9f ? Vector3.UnitZ : Vector3.UnitY;
            axis = Vector3.Cross(leaving, toward);
            if (axis.LengthSquared() < 1e-4f)
            {
                axis = Vector3.UnitX;
            }

            bend = 0f;
        }

        return [new JointAxis(Local(Vector3.Normalize(axis), Quaternion.Conjugate(rotation)), Radians(-bend - PastStraight), Radians(MathF.Max(MostBend, bend + PastStraight) - bend))];
    }

    private static Vector3 Direction(Vector3 v) => v.LengthSquared() > 1e-12f ? Vector3.Normalize(v) : -Vector3.UnitY;

    private static Vector3 Local(Vector3 world, Quaternion toLocal) => Vector3.Normalize(Vector3.Transform(world, toLocal));

    private static float Radians(float degrees) => degrees * MathF.PI / 180f;
}
