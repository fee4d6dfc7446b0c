using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Rigs;

namespace Ballistic.Authoring.Rigs;

/// <summary>
/// A 35 cm frog: body and head, long folded hind legs (hip 3, knee 1, ankle 1, toes 1) and short fore legs
/// (shoulder 3, elbow 1, wrist 1), every limb a contact limb. Rig frame: +Y up, +Z forward, +X the frog's left.
/// </summary>
public static class FrogBuilder
{
    /// <summary>Builds the frog.</summary>
    public static CharacterModel Build()
    {
        var s = new RigSketch();
        s.Add("body", null, Vector3.Zero, 0.065f);
        s.Add("head", "body", new Vector3(0f, 0.02f, 0.11f), 0.045f, RigSketch.X(-25, 25), RigSketch.Y(-20, 20));
        foreach ((string side, float x) in new[] { ("left", 1f), ("right", -1f) })
        {
            s.Add($"{side}_hip", "body", new Vector3(0.05f * x, -0.01f, -0.08f), 0.03f, RigSketch.X(-150, 40), RigSketch.Z(x > 0 ? -20 : -80, x > 0 ? 80 : 20), RigSketch.Y(-45, 45));
            s.Add($"{side}_knee", $"{side}_hip", new Vector3(0f, -0.10f, 0f), 0.022f, RigSketch.X(0, 165));
            s.Add($"{side}_ankle", $"{side}_knee", new Vector3(0f, -0.10f, 0f), 0.016f, RigSketch.X(-160, 20));
            s.Add($"{side}_toes", $"{side}_ankle", new Vector3(0f, -0.05f, 0f), 0.012f, RigSketch.X(-60, 60));
            s.Add($"{side}_shoulder", "body", new Vector3(0.05f * x, -0.02f, 0.07f), 0.018f, RigSketch.X(-100, 60), RigSketch.Z(x > 0 ? -20 : -70, x > 0 ? 70 : 20), RigSketch.Y(-45, 45));
            s.Add($"{side}_elbow", $"{side}_shoulder", new Vector3(0f, -0.05f, 0f), 0.014f, RigSketch.X(-20, 140));
            s.Add($"{side}_wrist", $"{side}_elbow", new Vector3(0f, -0.05f, 0f), 0.012f, RigSketch.X(-70, 70), RigSketch.Z(-30, 30));
        }

        int[] trunk = [s.IndexOf("body"), s.IndexOf("head")];
        var rig0 = new Rig(s.Joints, Vector3.Zero);
        (Vector3 centre, _) = ReducedModelBuilder.TrunkBox(s.Joints, trunk, s.Radii, Contact(s, rig0));
        var rig = new Rig(s.Joints, -centre);
        NormalFilter any = NormalFilter.None;
        RigLimb[] limbs =
        [
            new(rig, "left_fore", LimbKind.Hand, "left_shoulder", "left_wrist", new Vector3(0f, -0.015f, 0.01f), -Vector3.UnitY, any),
            new(rig, "right_fore", LimbKind.Hand, "right_shoulder", "right_wrist", new Vector3(0f, -0.015f, 0.01f), -Vector3.UnitY, any),
            new(rig, "left_hind", LimbKind.Foot, "left_hip", "left_toes", new Vector3(0f, -0.02f, 0f), -Vector3.UnitY, any),
            new(rig, "right_hind", LimbKind.Foot, "right_hip", "right_toes", new Vector3(0f, -0.02f, 0f), -Vector3.UnitY, any),
        ];
        float[] flexion = s.Pose(rig,
            ("left_hip", [-120f, 35f]), ("right_hip", [-120f, -35f]), ("left_knee", [155f]), ("right_knee", [155f]),
            ("left_ankle", [-140f]), ("right_ankle", [-140f]), ("left_toes", [50f]), ("right_toes", [50f]),
            ("left_shoulder", [-30f, 20f]), ("right_shoulder", [-30f, -20f]), ("left_elbow", [90f]), ("right_elbow", [90f]));
        float[] extending = s.Pose(rig,
            ("left_hip", [30f, 10f]), ("right_hip", [30f, -10f]), ("left_knee", [10f]), ("right_knee", [10f]),
            ("left_ankle", [10f]), ("right_ankle", [10f]),
            ("left_shoulder", [-80f, 10f]), ("right_shoulder", [-80f, -10f]), ("left_elbow", [0f]), ("right_elbow", [0f]));
        return new CharacterModel("frog", rig, limbs, trunk, s.Radii, Contact(s, rig), flexion, extending);
    }

    private static float[] Contact(RigSketch s, Rig rig) => s.Pose(rig,
        ("left_hip", [-100f, 30f]), ("right_hip", [-100f, -30f]), ("left_knee", [140f]), ("right_knee", [140f]),
        ("left_ankle", [-120f]), ("right_ankle", [-120f]), ("left_toes", [40f]), ("right_toes", [40f]),
        ("left_shoulder", [-20f, 15f]), ("right_shoulder", [-20f, -15f]), ("left_elbow", [40f]), ("right_elbow", [40f]));
}
