using System.Numerics;
using System.Text.Json.Nodes;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Rigs;

/// <summary>
/// A rig modelled in its T-pose (as Mixamo exports are) whose limbs-only spec gives no contact pose stands with its
/// free hands hanging at its sides (<see cref="CharacterModel.HangingPose"/>), not held out as in its bind pose: before,
/// the human stood every stance with its arms out, and on the house's gallery, 0.7 m from the back wall, its left hand
/// stood 9 cm inside the wall (the wrist on the wall's face, so no bone crossed it), a plan reported exact that the
/// audit refused.
/// </summary>
public sealed class HangingArmsTests
{
    [TestCase(false)]
    [TestCase(true)]
    public void AT_PosedRigsFreeHandsHangAtItsSidesAndItsFeetKeepTheirPose(bool zUp)
    {
        CharacterModel model = ForeignCharacters.Human(zUpScene: zUp).Load().Model;
        RigLimb[] hands = [.. model.Limbs.Where(l => l.Kind == LimbKind.Hand)];
        Assert.That(hands, Has.Length.EqualTo(2));
        foreach (RigLimb hand in hands)
        {
            Assert.Multiple(() =>
            {
                Assert.That(OffDown(model, model.ContactPose, hand), Is.GreaterThan(80f), $"{hand.Name} is held out in the contact pose (the rest pose)");
                Assert.That(OffDown(model, model.HangingPose, hand), Is.LessThan(20f), $"{hand.Name} hangs standing");
                Assert.That(Reach(model, model.HangingPose, hand), Is.GreaterThan(0.85f * Reach(model, model.ContactPose, hand)), $"{hand.Name}'s elbow only a little bent");
            });
        }

        int[] handDofs = [.. hands.SelectMany(h => h.ChainDofs)];
        int[] others = [.. Enumerable.Range(0, model.Rig.DofCount).Where(d => !handDofs.Contains(d))];
        Assert.That(others.Select(d => model.HangingPose[d]), Is.EqualTo(others.Select(d => model.ContactPose[d])), "only the hands move");
        Assert.That(model.Rig.WithinLimits(model.HangingPose), Is.True);
    }

    [Test]
    public void ASpecThatGivesAContactPoseKeepsItsHandsWhereItSays()
    {
        string folder = Path.Combine(Path.GetTempPath(), $"ballistic-hanging-{Guid.NewGuid():N}");
        try
        {
            Directory.CreateDirectory(folder);
            ForeignCharacter human = ForeignCharacters.Human(zUpScene: false);
            (string gltf, string specPath) = human.Write(folder);
            JsonObject spec = JsonNode.Parse(File.ReadAllText(specPath))!.AsObject();
            spec["poses"] = new JsonObject { ["contact"] = new JsonObject() };
            File.WriteAllText(specPath, spec.ToJsonString());
            CharacterModel model = CharacterSpecFile.Load(gltf, specPath).Model;
            Assert.That(model.HangingPose, Is.EqualTo(model.ContactPose), "the spec's own contact pose, arms out, is kept");
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    [Test]
    public void TheHumanGoesUpToTheGalleryAndStandsThereWithItsArmsDownClearOfTheWall()
    {
        (Sweep.Setup setup, (Vector3 From, Vector3 To)[] requests) = Sweep.PrepareForeign("house", "human", RigFolders.For("hanging"));
        Sweep.Planned planned = Sweep.Plan(setup, requests[1].From, requests[1].To);
        TestContext.Out.WriteLine(planned.Report);
        Assert.That(planned.Report.FullyRight, Is.True, planned.Report.ToString());
        AnimatorEye.Criterion arms = planned.Report.Look!.ArmsAtRest;
        TestContext.Out.WriteLine(string.Join(Environment.NewLine, arms.Seen.Select(s => s.Seen)));
        Assert.Multiple(() =>
        {
            Assert.That(arms.Seen, Has.Count.EqualTo(4), "both arms measured at the start and at the end");
            Assert.That(arms.Passes, Is.True, arms.ToString());
        });
    }

    /// <summary>Degrees between straight down and the shoulder-to-hand direction of <paramref name="hand"/> in <paramref name="pose"/>, the trunk upright.</summary>
    private static float OffDown(CharacterModel model, float[] pose, RigLimb hand)
    {
        (Vector3 shoulder, Vector3 tip) = Ends(model, pose, hand);
        return MathF.Acos(Math.Clamp(Vector3.Dot(Vector3.Normalize(tip - shoulder), -Vector3.UnitY), -1f, 1f)) * 180f / MathF.PI;
    }

    private static float Reach(CharacterModel model, float[] pose, RigLimb hand)
    {
        (Vector3 shoulder, Vector3 tip) = Ends(model, pose, hand);
        return Vector3.Distance(shoulder, tip);
    }

    private static (Vector3 Shoulder, Vector3 Tip) Ends(CharacterModel model, float[] pose, RigLimb hand)
    {
        var positions = new Vector3[model.Rig.Joints.Count];
        var rotations = new Quaternion[model.Rig.Joints.Count];
        model.Rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), pose, positions, rotations);
        return (positions[hand.RootJoint], hand.EffectorPosition(positions, rotations));
    }
}
