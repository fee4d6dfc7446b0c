using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Rigs;

/// <summary>
/// A limbs-only spec gets the joints an animator would rig, whatever rest rotations the file's bones carry: knees bend
/// the foot back (or the way the rest pose bends them), elbows the hand forward, hips spread only a little, and the
/// flight poses are tucked and stretched poses of the rig, not its bind pose.
/// </summary>
public sealed class DerivedLimbJointTests
{
    private static readonly RootPose Origin = new(Vector3.Zero, Quaternion.Identity);

    public static IEnumerable<TestCaseData> Rigs()
    {
        yield return new TestCaseData("human").SetName("{m}(human: Z-up armature, bones along their Y, 90° rest rotations)");
        yield return new TestCaseData("human-zup").SetName("{m}(human in a Z-up scene)");
        yield return new TestCaseData("dog").SetName("{m}(dog: bent rest legs, anchors between bones)");
        yield return new TestCaseData("tailed").SetName("{m}(tailed quadruped facing +X)");
    }

    [TestCaseSource(nameof(Rigs))]
    public void BonesBetweenRootAndEffectorAreHingesBendingTheWayTheRigBends(string name)
    {
        (CharacterModel model, _) = ForeignCharacters.Named(name).Load();
        Rig rig = model.Rig;
        Assert.Multiple(() =>
        {
            foreach (RigLimb limb in model.Limbs)
            {
                foreach (int joint in limb.Chain.Skip(1).SkipLast(1))
                {
                    Assert.That(rig.DofsOf(joint), Is.EqualTo(1), $"{name}: {rig.Joints[joint].Name} is a hinge");
                    int d = rig.FirstDof(joint);
                    JointAxis axis = rig.Dofs[d];
                    Vector3 parent = At(rig, limb.Chain[limb.Chain.ToList().IndexOf(joint) - 1], new float[rig.DofCount]);
                    float[] bent = new float[rig.DofCount];
                    bent[d] = MathF.Min(axis.Max, 60f * MathF.PI / 180f);
                    Vector3 restEnd = End(rig, limb, new float[rig.DofCount]);
                    Vector3 bentEnd = End(rig, limb, bent);

                    // Bending folds the limb: its end comes nearer the bone above the hinge.
                    Assert.That(Vector3.Distance(bentEnd, parent), Is.LessThan(Vector3.Distance(restEnd, parent) - 0.01f), $"{name}: bending {rig.Joints[joint].Name} folds {limb.Name}");
                    Assert.That(axis.Min, Is.LessThanOrEqualTo(0f), $"{name}: {rig.Joints[joint].Name} straightens back to its rest pose");
                    if (name.StartsWith("human", StringComparison.Ordinal))
                    {
                        // A straight human leg bends the foot back, a straight arm the hand forward.
                        float forward = bentEnd.Z - restEnd.Z;
                        Assert.That(limb.Kind == LimbKind.Foot ? -forward : forward, Is.GreaterThan(0.1f), $"{name}: {rig.Joints[joint].Name} bends {limb.Name} {(limb.Kind == LimbKind.Foot ? "back" : "forward")} (moved {forward:0.00} m forward)");
                    }
                }
            }
        });
    }

    [TestCaseSource(nameof(Rigs))]
    public void HipsSpreadTheFeetOnlyALittle(string name)
    {
        (CharacterModel model, _) = ForeignCharacters.Named(name).Load();
        Rig rig = model.Rig;
        foreach (RigLimb limb in model.Limbs.Where(l => l.Kind == LimbKind.Foot))
        {
            int hip = limb.RootJoint;
            float reach = Vector3.Distance(At(rig, hip, new float[rig.DofCount]), End(rig, limb, new float[rig.DofCount]));
            float restSide = End(rig, limb, new float[rig.DofCount]).X;

            // Every corner of the hip's limits (knee and ankle at rest) keeps the foot within sin 30° of its reach sideways.
            float worst = 0f;
            int first = rig.FirstDof(hip);
            for (int corner = 0; corner < 1 << rig.DofsOf(hip); corner++)
            {
                float[] q = new float[rig.DofCount];
                for (int k = 0; k < rig.DofsOf(hip); k++)
                {
                    q[first + k] = (corner >> k & 1) == 0 ? rig.Dofs[first + k].Min : rig.Dofs[first + k].Max;
                }

                worst = MathF.Max(worst, MathF.Abs(End(rig, limb, q).X - restSide));
            }

            Assert.That(worst, Is.LessThanOrEqualTo((MathF.Sin(30f * MathF.PI / 180f) + 0.15f) * reach), $"{name}: {limb.Name} spreads {worst:0.00} m sideways of its rest place at most");
        }
    }

    [TestCaseSource(nameof(Rigs))]
    public void FlightPosesAreTuckedAndStretchedNotTheBindPose(string name)
    {
        (CharacterModel model, _) = ForeignCharacters.Named(name).Load();
        Rig rig = model.Rig;
        int[] limbJoints = [.. model.Limbs.SelectMany(l => l.Chain)];

        // The limbs' joints turned from the bind pose, on average (degrees), as an importer sees their local rotations.
        float Away(float[] pose) => limbJoints.Average(j =>
            2f * MathF.Acos(MathF.Min(1f, MathF.Abs(Quaternion.Dot(rig.LocalRotation(j, pose), rig.LocalRotation(j, model.ContactPose))))) * 180f / MathF.PI);
        Assert.Multiple(() =>
        {
            Assert.That(rig.WithinLimits(model.FlexionPose) && rig.WithinLimits(model.ExtendingPose), Is.True, $"{name}: the derived poses keep the joint limits");
            Assert.That(Away(model.FlexionPose), Is.GreaterThan(10f), $"{name}: the tucked pose is not the bind pose");
            Assert.That(Away(model.ExtendingPose), Is.GreaterThan(10f), $"{name}: the stretched pose is not the bind pose");
            foreach (RigLimb limb in model.Limbs.Where(l => l.Kind == LimbKind.Foot))
            {
                Vector3 hip = At(rig, limb.RootJoint, model.ContactPose);
                float reach = Vector3.Distance(hip, End(rig, limb, model.ContactPose));
                Assert.That(Vector3.Distance(hip, End(rig, limb, model.FlexionPose)), Is.LessThan(0.8f * reach), $"{name}: {limb.Name} tucks toward its hip");
            }

            foreach (RigLimb limb in model.Limbs.Where(l => l.Kind == LimbKind.Hand))
            {
                Assert.That(End(rig, limb, model.ExtendingPose).Y, Is.GreaterThan(End(rig, limb, model.ContactPose).Y + 0.1f), $"{name}: {limb.Name} reaches up when the body stretches");
            }
        });
    }

    /// <summary>
    /// A spider's eight legs fan out around its body from roots close together along it: its front legs stretch ahead
    /// and its hind legs behind for the flight, as a quadruped's do, and the stretched pose turns the legs' joints well
    /// away from rest. Before, the rig's feet were taken for one walker's (their roots 0.19 m apart along the body,
    /// under half their 0.67 m reach): every leg swung a little back, the front feet 0.19 m behind their rest places,
    /// 10.0° from rest on average, and the animator's eye saw no flight pose on 12 of the spider's 26 plans on levels in
    /// other tools' shapes (9° at the apex).
    /// </summary>
    [Test]
    public void AFannedRigsFrontLegsStretchAheadAndItsHindLegsBehind()
    {
        (CharacterModel model, _) = ForeignCharacters.Spider().Load();
        Rig rig = model.Rig;
        int[] limbJoints = [.. model.Limbs.SelectMany(l => l.Chain)];
        float away = limbJoints.Average(j =>
            2f * MathF.Acos(MathF.Min(1f, MathF.Abs(Quaternion.Dot(rig.LocalRotation(j, model.ExtendingPose), rig.LocalRotation(j, model.ContactPose))))) * 180f / MathF.PI);
        Assert.Multiple(() =>
        {
            foreach (RigLimb limb in model.Limbs.Where(l => l.Name is "l1" or "r1"))
            {
                Assert.That(End(rig, limb, model.ExtendingPose).Z, Is.GreaterThan(End(rig, limb, model.ContactPose).Z + 0.05f), $"{limb.Name} stretches ahead");
            }

            foreach (RigLimb limb in model.Limbs.Where(l => l.Name is "l4" or "r4"))
            {
                Assert.That(End(rig, limb, model.ExtendingPose).Z, Is.LessThan(End(rig, limb, model.ContactPose).Z - 0.05f), $"{limb.Name} stretches behind");
            }

            Assert.That(away, Is.GreaterThan(12f), "the stretched legs' joints, from rest on average (degrees)");
            Assert.That(rig.WithinLimits(model.ExtendingPose), Is.True, "within the joints' limits");
        });
    }

    private static Vector3 At(Rig rig, int joint, float[] q)
    {
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        rig.Solve(Origin, q, positions, rotations);
        return positions[joint];
    }

    private static Vector3 End(Rig rig, RigLimb limb, float[] q)
    {
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        rig.Solve(Origin, q, positions, rotations);
        return limb.EffectorPosition(positions, rotations);
    }
}
