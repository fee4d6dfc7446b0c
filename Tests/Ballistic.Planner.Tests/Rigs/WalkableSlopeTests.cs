using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Rigs;

/// <summary>The steepest ground a rig walks on comes from its feet (<see cref="ReducedModelBuilder.WalkableSlope"/>), not a fixed angle.</summary>
public sealed class WalkableSlopeTests
{
    [Test]
    public void TheHumanoidWalksOnSlopesItsAnklesCanFollow()
    {
        // Its ankles roll ±20° and bend −45°…40°: with the trunk upright over a foot, a sole on a side slope of 25°
        // cannot lie flat, one of 20° can.
        CharacterModel model = RigTests.Humanoid.Value;
        float leg = LegLength(model);
        float slope = ReducedModelBuilder.WalkableSlope(model, leg);
        Assert.That(slope, Is.InRange(15f, 25f));
        Assert.That(slope % ReducedModelBuilder.SlopeStep, Is.EqualTo(0f).Within(1e-4f));
        Assert.That(ReducedModelBuilder.Walking(model, 2).MaxSlopeDegrees, Is.EqualTo(slope), "the derived walking limits use it");
    }

    [Test]
    public void StifferAnklesWalkOnGentlerSlopesAndLooserOnesOnSteeper()
    {
        CharacterModel model = RigTests.Humanoid.Value;
        float leg = LegLength(model);
        float normal = ReducedModelBuilder.WalkableSlope(model, leg);
        float stiff = ReducedModelBuilder.WalkableSlope(WithAnkleRoll(model, 5f), leg);
        float loose = ReducedModelBuilder.WalkableSlope(WithAnkleRoll(model, 40f), leg);
        Assert.Multiple(() =>
        {
            Assert.That(stiff, Is.LessThan(normal), "ankles that barely roll hold the foot on gentler side slopes only");
            Assert.That(loose, Is.GreaterThan(normal), "ankles that roll further hold it on steeper ones");
            Assert.That(loose, Is.LessThanOrEqualTo(WalkingLimits.DefaultMaxSlopeDegrees), "never above the default limit");
        });
    }

    [Test]
    public void OnTheSlopeItGetsEveryFootHoldsFlatWithItsToesAboveTheGround()
    {
        // An independent check of the answer: a fresh IK with restarts, the foot on planes of the derived slope falling
        // each way, the trunk upright above it; and on planes 10° steeper, some foot cannot.
        CharacterModel model = RigTests.Humanoid.Value;
        float slope = ReducedModelBuilder.WalkableSlope(model, LegLength(model));
        Assert.Multiple(() =>
        {
            Assert.That(AllFeetHold(model, slope), Is.True, $"{slope}°");
            Assert.That(AllFeetHold(model, slope + 10f), Is.False, $"{slope + 10f}°");
        });
    }

    [Test]
    public void StraightUpOrDownTheFeetWalkSteeperThanAcross()
    {
        // Its ankles bend further (−45°…40°) than they roll (±20°): on planes falling ahead or behind its feet hold
        // steeper slopes than on planes falling to the side. The limit stays a step (2.5°) below the steepest plane held.
        CharacterModel model = RigTests.Humanoid.Value;
        float leg = LegLength(model);
        float slope = ReducedModelBuilder.WalkableSlope(model, leg);
        float along = ReducedModelBuilder.WalkableSlopeAlong(model, leg, slope);
        Vector3[] ahead = [Vector3.UnitZ, -Vector3.UnitZ];
        Assert.Multiple(() =>
        {
            Assert.That(along, Is.GreaterThan(slope));
            Assert.That(along % ReducedModelBuilder.SlopeStep, Is.EqualTo(0f).Within(1e-4f));
            Assert.That(ReducedModelBuilder.Walking(model, 2).MaxSlopeAlongDegrees, Is.EqualTo(along), "the derived walking limits use it");
            Assert.That(AllFeetHold(model, along + ReducedModelBuilder.SlopeStep, ahead), Is.True, $"{along + ReducedModelBuilder.SlopeStep}° ahead");
            Assert.That(AllFeetHold(model, along + 10f, ahead), Is.False, $"{along + 10f}° ahead");

            // The independent IK (restarts, the trunk still) holds a little more either way, and still more ahead.
            Assert.That(AllFeetHold(model, along + 5f, ahead), Is.True, $"{along + 5f}° ahead");
            Assert.That(AllFeetHold(model, along + 5f, [Vector3.UnitX, -Vector3.UnitX]), Is.False, $"{along + 5f}° to the side");
            Assert.That(ReducedModelBuilder.WalkableSlopeAlong(WithAnkleRoll(model, 40f), leg, ReducedModelBuilder.WalkableSlope(WithAnkleRoll(model, 40f), leg)), Is.GreaterThanOrEqualTo(along), "looser ankles never walk less steep");
        });
    }

    private static bool AllFeetHold(CharacterModel model, float degrees, Vector3[]? downs = null, float sink = 0f)
    {
        Rig rig = model.Rig;
        var ik = new LimbIk(rig, new IkSettings { Restarts = 4, MaxIterations = 80 });
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), model.ContactPose, positions, rotations);
        var root = new RootPose(new Vector3(0f, -sink, 0f), Quaternion.Identity);
        float angle = degrees * MathF.PI / 180f;
        foreach (RigLimb foot in model.Limbs.Where(l => l.Kind == LimbKind.Foot))
        {
            Vector3 stand = foot.EffectorPosition(positions, rotations);
            foreach (Vector3 down in downs ?? [Vector3.UnitZ, -Vector3.UnitZ, Vector3.UnitX, -Vector3.UnitX])
            {
                Vector3 normal = (down * MathF.Sin(angle)) + (Vector3.UnitY * MathF.Cos(angle));
                float[] q = (float[])model.ContactPose.Clone();
                if (!ik.Solve(root, q, foot, stand, -normal).Success)
                {
                    return false;
                }

                var solved = new Vector3[rig.Joints.Count];
                rig.Solve(root, q, solved, rotations);
                for (int j = 0; j < rig.Joints.Count; j++)
                {
                    if (j != foot.EffectorJoint && rig.IsAncestor(foot.EffectorJoint, j) && Vector3.Dot(solved[j] - stand, normal) < -0.005f)
                    {
                        return false;
                    }
                }
            }
        }

        return true;
    }

    [TestCase("human", 27.5f)]
    [TestCase("human-zup", 27.5f)]
    [TestCase("dog", 20f)]
    [TestCase("tailed", 15f)]
    [TestCase("panda", 12.5f)]
    public void RigsMadeElsewhereWithStraightLegsWalkOnSlopes(string name, float expected)
    {
        // Rigs made elsewhere stand on straight legs in their contact pose: moving the trunk a tenth of the leg over a
        // planted foot at that height is out of the leg's reach, so these walked on no slope at all (0°, the level
        // only). A walker lowers its hips: with the trunk a twentieth of the leg lower they walk on slopes, and the
        // tailed quadruped and the panda, whose feet hold no slope there, a tenth lower.
        string folder = Path.Combine(Path.GetTempPath(), $"ballistic-slope-{name}-{Environment.ProcessId}");
        try
        {
            (CharacterModel model, ReducedCharacter reduced) = ForeignCharacters.Named(name).Load(folder);
            float slope = reduced.Walking.MaxSlopeDegrees;
            float leg = reduced.Walking.StepHeight / WalkingLimits.StepShare; // the leg the rig's walking comes from
            Assert.Multiple(() =>
            {
                Assert.That(slope, Is.EqualTo(expected), $"{name} walks on slopes of {expected}° (the README's figure)");
                Assert.That(reduced.Walking.MaxSlopeAlongDegrees, Is.GreaterThanOrEqualTo(slope));

                // An independent check: a fresh IK with restarts holds every foot flat on the derived slope falling
                // each way with the trunk at its height, or a twentieth or a tenth of the leg lower.
                Assert.That(AllFeetHold(model, slope) || AllFeetHold(model, slope, sink: ReducedModelBuilder.SlopeSink * leg) || AllFeetHold(model, slope, sink: ReducedModelBuilder.LowSlopeSink * leg), Is.True, $"{name}'s feet hold {slope}°");
            });
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    private static float LegLength(CharacterModel model)
    {
        var positions = new Vector3[model.Rig.Joints.Count];
        var rotations = new Quaternion[model.Rig.Joints.Count];
        model.Rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), model.Rig.Neutral(), positions, rotations);
        return positions[0].Y - model.Limbs.Where(l => l.Kind == LimbKind.Foot).Min(l => l.EffectorPosition(positions, rotations).Y);
    }

    /// <summary>The model with its ankles' roll (the axis along the foot, ±<paramref name="degrees"/>) changed.</summary>
    private static CharacterModel WithAnkleRoll(CharacterModel model, float degrees)
    {
        Rig rig = model.Rig;
        float limit = degrees * MathF.PI / 180f;
        Joint[] joints = [.. rig.Joints.Select(j => j.Name.EndsWith("_ankle", StringComparison.Ordinal)
            ? j with { Axes = [.. j.Axes.Select(a => MathF.Abs(a.Axis.Z) > 0.9f ? a with { Min = -limit, Max = limit } : a)] }
            : j)];
        var changed = new Rig(joints, rig.RootOffset);
        RigLimb[] limbs = [.. model.Limbs.Select(l => new RigLimb(changed, l.Name, l.Kind, rig.Joints[l.RootJoint].Name, rig.Joints[l.EffectorJoint].Name, l.EffectorOffset, l.ContactNormal, l.Filter))];
        return new CharacterModel(model.Name, changed, limbs, model.TrunkJoints, model.BoneRadii, model.ContactPose, model.FlexionPose, model.ExtendingPose);
    }
}
