using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Rigs;

namespace Ballistic.Authoring.Rigs;

/// <summary>
/// A 1.8 m humanoid: pelvis, spine, chest, neck, head; legs (hip 3, knee 1, ankle 2, toe 1) and arms (shoulder 3,
/// elbow 1, wrist 3): 39 degrees of freedom. Rig frame: +Y up, +Z forward, +X the character's left.
/// </summary>
public static class HumanoidBuilder
{
    /// <summary>The humanoid called <paramref name="name"/>; <paramref name="handsOnWalls"/> lets the hands touch any surface.</summary>
    public static CharacterModel Build(string name, bool handsOnWalls)
    {
        var s = new RigSketch();
        s.Add("pelvis", null, Vector3.Zero, 0.14f);
        s.Add("spine", "pelvis", new Vector3(0f, 0.10f, 0f), 0.13f, RigSketch.X(-25, 35), RigSketch.Z(-20, 20), RigSketch.Y(-25, 25));
        s.Add("chest", "spine", new Vector3(0f, 0.25f, 0f), 0.16f, RigSketch.X(-20, 25), RigSketch.Z(-15, 15), RigSketch.Y(-20, 20));
        s.Add("neck", "chest", new Vector3(0f, 0.25f, 0f), 0.06f, RigSketch.X(-35, 40), RigSketch.Z(-30, 30), RigSketch.Y(-60, 60));
        s.Add("head", "neck", new Vector3(0f, 0.12f, 0.02f), 0.11f, RigSketch.X(-30, 30), RigSketch.Z(-20, 20));
        foreach ((string side, float x) in new[] { ("left", 1f), ("right", -1f) })
        {
            // Leg: flexion forward is a negative rotation about +X (the leg, pointing −Y, swings toward +Z).
            s.Add($"{side}_hip", "pelvis", new Vector3(0.10f * x, -0.05f, 0f), 0.08f, RigSketch.X(-110, 30), RigSketch.Z(x > 0 ? -15 : -45, x > 0 ? 45 : 15), RigSketch.Y(-35, 35));
            s.Add($"{side}_knee", $"{side}_hip", new Vector3(0f, -0.43f, 0f), 0.06f, RigSketch.X(0, 140));
            s.Add($"{side}_ankle", $"{side}_knee", new Vector3(0f, -0.42f, 0f), 0.05f, RigSketch.X(-45, 40), RigSketch.Z(-20, 20));
            s.Add($"{side}_toe", $"{side}_ankle", new Vector3(0f, -0.05f, 0.14f), 0.03f, RigSketch.X(-40, 40));

            // Arm hanging down; raising it forward is a negative rotation about +X.
            s.Add($"{side}_shoulder", "chest", new Vector3(0.19f * x, 0.20f, 0f), 0.05f, RigSketch.X(-170, 60), RigSketch.Z(x > 0 ? -10 : -170, x > 0 ? 170 : 10), RigSketch.Y(-80, 80));
            s.Add($"{side}_elbow", $"{side}_shoulder", new Vector3(0f, -0.30f, 0f), 0.04f, RigSketch.X(-150, 0));
            s.Add($"{side}_wrist", $"{side}_elbow", new Vector3(0f, -0.27f, 0f), 0.035f, RigSketch.X(-70, 70), RigSketch.Z(-30, 30), RigSketch.Y(-80, 80));
        }

        int[] trunk = [s.IndexOf("pelvis"), s.IndexOf("spine"), s.IndexOf("chest"), s.IndexOf("neck"), s.IndexOf("head"), s.IndexOf("left_hip"), s.IndexOf("right_hip"), s.IndexOf("left_shoulder"), s.IndexOf("right_shoulder")];
        var rig0 = new Rig(s.Joints, Vector3.Zero);
        float[] contact0 = ContactPose(s, rig0);
        (Vector3 centre, _) = ReducedModelBuilder.TrunkBox(s.Joints, trunk, s.Radii, contact0);
        var rig = new Rig(s.Joints, -centre);

        NormalFilter feet = NormalFilter.Upward(handsOnWalls ? 0.6f : 0.3f);
        NormalFilter hands = handsOnWalls ? NormalFilter.None : NormalFilter.Upward(0.3f);
        RigLimb[] limbs =
        [
            new(rig, "left_foot", LimbKind.Foot, "left_hip", "left_ankle", new Vector3(0f, -0.06f, 0.04f), -Vector3.UnitY, feet),
            new(rig, "right_foot", LimbKind.Foot, "right_hip", "right_ankle", new Vector3(0f, -0.06f, 0.04f), -Vector3.UnitY, feet),
            new(rig, "left_hand", LimbKind.Hand, "left_shoulder", "left_wrist", new Vector3(0f, -0.08f, 0f), -Vector3.UnitY, hands),
            new(rig, "right_hand", LimbKind.Hand, "right_shoulder", "right_wrist", new Vector3(0f, -0.08f, 0f), -Vector3.UnitY, hands),
        ];

        float[] flexion = s.Pose(rig,
            ("spine", [25f]), ("chest", [10f]),
            ("left_hip", [-85f]), ("right_hip", [-85f]), ("left_knee", [115f]), ("right_knee", [115f]),
            ("left_ankle", [-25f]), ("right_ankle", [-25f]),
            ("left_shoulder", [40f, 10f]), ("right_shoulder", [40f, -10f]), ("left_elbow", [-30f]), ("right_elbow", [-30f]));
        float[] extending = s.Pose(rig,
            ("spine", [-10f]),
            ("left_hip", [10f]), ("right_hip", [10f]), ("left_knee", [5f]), ("right_knee", [5f]),
            ("left_ankle", [30f]), ("right_ankle", [30f]),
            ("left_shoulder", [-160f, 15f]), ("right_shoulder", [-160f, -15f]), ("left_elbow", [-10f]), ("right_elbow", [-10f]));
        return new CharacterModel(name, rig, limbs, trunk, s.Radii, ContactPose(s, rig), flexion, extending);
    }

    private static float[] ContactPose(RigSketch s, Rig rig) => s.Pose(rig,
        ("spine", [10f]),
        ("left_hip", [-30f]), ("right_hip", [-30f]), ("left_knee", [50f]), ("right_knee", [50f]),
        ("left_ankle", [-20f]), ("right_ankle", [-20f]),
        ("left_shoulder", [-20f, 12f]), ("right_shoulder", [-20f, -12f]), ("left_elbow", [-35f]), ("right_elbow", [-35f]));
}
