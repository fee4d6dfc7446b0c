using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Rigs;

namespace Ballistic.Authoring.Rigs;

/// <summary>
/// A 60 cm ant: thorax, head and abdomen, six legs of coxa (yaw and lift), femur-tibia knee and tarsus: 4 degrees of
/// freedom a leg. Rig frame: +Y up, +Z forward, +X the ant's left; legs point sideways at rest.
/// </summary>
public static class AntBuilder
{
    /// <summary>Builds the ant.</summary>
    public static CharacterModel Build()
    {
        var s = new RigSketch();
        s.Add("thorax", null, Vector3.Zero, 0.06f);
        s.Add("head", "thorax", new Vector3(0f, 0.02f, 0.17f), 0.055f, RigSketch.X(-30, 30), RigSketch.Y(-30, 30));
        s.Add("abdomen", "thorax", new Vector3(0f, 0.01f, -0.22f), 0.08f, RigSketch.X(-25, 25));
        string[] rows = ["front", "middle", "hind"];
        float[] z = [0.09f, 0f, -0.09f];
        foreach ((string side, float x) in new[] { ("left", 1f), ("right", -1f) })
        {
            for (int r = 0; r < 3; r++)
            {
                string leg = $"{side}_{rows[r]}";
                // Lift: positive about +Z raises a left leg (+X toward +Y) and lowers a right one.
                s.Add($"{leg}_coxa", "thorax", new Vector3(0.05f * x, -0.02f, z[r]), 0.02f, RigSketch.Y(-40, 40), RigSketch.Z(x > 0 ? -30 : -60, x > 0 ? 60 : 30));
                s.Add($"{leg}_femur", $"{leg}_coxa", new Vector3(0.05f * x, 0f, 0f), 0.016f, RigSketch.Z(x > 0 ? -10 : -70, x > 0 ? 70 : 10));
                s.Add($"{leg}_tibia", $"{leg}_femur", new Vector3(0.13f * x, 0f, 0f), 0.012f, RigSketch.Z(x > 0 ? -130 : 0, x > 0 ? 0 : 130));
                s.Add($"{leg}_tarsus", $"{leg}_tibia", new Vector3(0.15f * x, 0f, 0f), 0.009f, RigSketch.Z(-40, 40));
            }
        }

        int[] trunk = [s.IndexOf("thorax"), s.IndexOf("head"), s.IndexOf("abdomen")];
        var rig0 = new Rig(s.Joints, Vector3.Zero);
        (Vector3 centre, _) = ReducedModelBuilder.TrunkBox(s.Joints, trunk, s.Radii, Stance(s, rig0, 25f, -95f));
        var rig = new Rig(s.Joints, -centre);
        NormalFilter up = NormalFilter.Upward(0.3f);
        var limbs = new List<RigLimb>();
        foreach (string side in new[] { "left", "right" })
        {
            float sign = side == "left" ? 1f : -1f;
            foreach (string row in rows)
            {
                string leg = $"{side}_{row}";
                limbs.Add(new RigLimb(rig, leg, LimbKind.Foot, $"{leg}_coxa", $"{leg}_tarsus", new Vector3(0.04f * sign, 0f, 0f), new Vector3(sign, 0f, 0f), up));
            }
        }

        // Interleave like the hand-set ant: left_front, right_front, left_middle, …
        RigLimb[] ordered = [.. rows.SelectMany(row => limbs.Where(l => l.Name.EndsWith(row, StringComparison.Ordinal)))];
        return new CharacterModel("ant", rig, ordered, trunk, s.Radii, Stance(s, rig, 25f, -95f), Stance(s, rig, 45f, -125f), Stance(s, rig, -10f, -40f));
    }

    /// <summary>All six legs with the femur raised by <paramref name="lift"/> and the tibia bent down by <paramref name="knee"/> degrees (left-side signs).</summary>
    private static float[] Stance(RigSketch s, Rig rig, float lift, float knee)
    {
        var angles = new List<(string, float[])>();
        foreach ((string side, float x) in new[] { ("left", 1f), ("right", -1f) })
        {
            foreach (string row in new[] { "front", "middle", "hind" })
            {
                string leg = $"{side}_{row}";
                float yaw = row == "front" ? 25f : row == "hind" ? -25f : 0f;
                angles.Add(($"{leg}_coxa", [-yaw * x, 0f])); // a positive yaw turns a left leg backward
                angles.Add(($"{leg}_femur", [lift * x]));
                angles.Add(($"{leg}_tibia", [knee * x]));
                angles.Add(($"{leg}_tarsus", [-20f * x]));
            }
        }

        return s.Pose(rig, [.. angles]);
    }
}
