using System.Numerics;
using System.Text.Json.Nodes;
using Ballistic.Authoring.Animation;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Rigs;

public sealed class CharacterSpecFileTests
{
    private string _folder = "";

    [SetUp]
    public void MakeFolder()
    {
        _folder = Path.Combine(Path.GetTempPath(), $"ballistic-rig-{Guid.NewGuid():N}");
        Directory.CreateDirectory(_folder);
    }

    [TearDown]
    public void RemoveFolder() => Directory.Delete(_folder, recursive: true);

    [TestCase("skeleton")]
    [TestCase("frog")]
    [TestCase("ant")]
    [TestCase("jumperman")]
    public void BundledCharacterFilesLoadBackToTheSameRig(string name)
    {
        string folder = Path.Combine(RepositoryFiles.Root, "Scenes", "characters");
        (CharacterModel loaded, ReducedCharacter reduced) = CharacterSpecFile.Load(Path.Combine(folder, name + ".glb"), Path.Combine(folder, name + ".limbs.json"));
        CharacterModel original = CharacterPresets.Model(name);
        ReducedCharacter preset = CharacterPresets.Get(name);
        Assert.That(loaded.Rig.DofCount, Is.EqualTo(original.Rig.DofCount));
        Assert.That(loaded.Limbs.Select(l => l.Name), Is.EqualTo(original.Limbs.Select(l => l.Name)));

        var root = new RootPose(new Vector3(1f, 2f, 3f), Quaternion.CreateFromAxisAngle(Vector3.UnitY, 0.4f));
        var a = new Vector3[original.Rig.Joints.Count];
        var b = new Vector3[loaded.Rig.Joints.Count];
        var ra = new Quaternion[a.Length];
        var rb = new Quaternion[b.Length];
        foreach ((float[] mine, float[] theirs) in new[] { (original.ContactPose, loaded.ContactPose), (original.FlexionPose, loaded.FlexionPose) })
        {
            original.Rig.Solve(root, mine, a, ra);
            loaded.Rig.Solve(root, theirs, b, rb);
            for (int j = 0; j < a.Length; j++)
            {
                Assert.That(Vector3.Distance(a[j], b[j]), Is.LessThan(1e-3f), $"{name}: bone {original.Rig.Joints[j].Name}");
            }
        }

        Assert.Multiple(() =>
        {
            Assert.That(Vector3.Distance(reduced.TrunkHalfExtents, preset.TrunkHalfExtents), Is.LessThan(1e-3f));
            Assert.That(reduced.TakeoffSpeedMax, Is.EqualTo(preset.TakeoffSpeedMax));
            Assert.That(reduced.RequiredContacts, Is.EqualTo(preset.RequiredContacts));
        });
    }

    [TestCase("skeleton")]
    [TestCase("frog")]
    [TestCase("ant")]
    [TestCase("jumperman")]
    public void CommittedCharacterFilesAreWhatTheGeneratorWrites(string name)
    {
        string folder = Path.Combine(RepositoryFiles.Root, "Scenes", "characters");
        Assert.Multiple(() =>
        {
            Assert.That(File.ReadAllBytes(Path.Combine(folder, name + ".glb")).SequenceEqual(AnimatedGlbWriter.ToBytes(CharacterPresets.Model(name))), Is.True, "run 'ballistic characters generate'");
            Assert.That(File.ReadAllBytes(Path.Combine(folder, name + ".limbs.json")).SequenceEqual(CharacterSpecFile.ToBytes(CharacterPresets.Model(name), CharacterPresets.Get(name))), Is.True, "run 'ballistic characters generate'");
        });
    }

    [TestCase(null, null, 22.5f, 25f)]
    [TestCase(20f, null, 20f, 20f)]
    [TestCase(null, 30f, 22.5f, 30f)]
    [TestCase(15f, 28f, 15f, 28f)]
    public void TheWalkableSlopesComeFromTheRigUnlessTheSpecGivesThem(float? maxSlope, float? maxSlopeAlong, float slope, float along)
    {
        // The bundled skeleton's spec without its slopes derives them from its ankles (22.5° any way, 25° straight up
        // or down); maxSlope alone gives one limit whichever way the ground falls; maxSlopeAlong alone keeps the derived
        // maxSlope.
        string folder = Path.Combine(RepositoryFiles.Root, "Scenes", "characters");
        var json = (JsonObject)JsonNode.Parse(File.ReadAllText(Path.Combine(folder, "skeleton.limbs.json")))!;
        json.Remove("maxSlope");
        json.Remove("maxSlopeAlong");
        if (maxSlope is float s)
        {
            json["maxSlope"] = s;
        }

        if (maxSlopeAlong is float a)
        {
            json["maxSlopeAlong"] = a;
        }

        string spec = Path.Combine(_folder, "skeleton.limbs.json");
        File.WriteAllText(spec, json.ToJsonString());
        (_, ReducedCharacter reduced) = CharacterSpecFile.Load(Path.Combine(folder, "skeleton.glb"), spec);
        Assert.Multiple(() =>
        {
            Assert.That(reduced.Walking.MaxSlopeDegrees, Is.EqualTo(slope));
            Assert.That(reduced.Walking.MaxSlopeAlongDegrees, Is.EqualTo(along));
        });
    }

    [Test]
    public void ARiggedCharacterAnimatesGivenOnlyItsLimbs()
    {
        // Only limbs and speeds: no joint axes, no poses, no radii. Hips and ankles become ball joints, knees hinges;
        // the contact pose is the rest pose, the flight poses are derived.
        string spec = Path.Combine(_folder, "minimal.limbs.json");
        File.WriteAllText(spec, """
        {"schema":"ballistic.character/1","name":"borrowed","requiredContacts":2,"takeoffSpeedMax":8,"landingSpeedMax":12,"friction":0.5,
         "trunkBones":["pelvis","spine","chest","neck","head"],
         "limbs":{
           "left_foot":{"rootBone":"left_hip","effectorBone":"left_ankle","effectorOffset":[0,-0.06,0.04],"contactNormal":[0,-1,0],"contact":"foot","normalFilter":{"direction":[0,1,0],"minCosine":0.3}},
           "right_foot":{"rootBone":"right_hip","effectorBone":"right_ankle","effectorOffset":[0,-0.06,0.04],"contactNormal":[0,-1,0],"contact":"foot","normalFilter":{"direction":[0,1,0],"minCosine":0.3}}}}
        """);
        (CharacterModel model, ReducedCharacter reduced) = CharacterSpecFile.Load(Path.Combine(RepositoryFiles.Root, "Scenes", "characters", "skeleton.glb"), spec);
        Assert.That(model.Limbs.Sum(l => l.Chain.Sum(model.Rig.DofsOf)), Is.EqualTo(2 * (3 + 1 + 3)), "hip and ankle of each leg as ball joints, the knee a hinge");
        Assert.That(((string[])["pelvis", "spine", "chest", "neck", "head"]).Sum(b => model.Rig.DofsOf(model.Rig.IndexOf(b))), Is.Zero, "the trunk the spec names stays rigid");
        Assert.That(model.Rig.DofsOf(model.Rig.IndexOf("left_shoulder")), Is.EqualTo(2), "an arm the spec does not animate bends freely, to stay out of the level");

        var scene = PlanningScene.Create(GapCourse.Build(), reduced);
        BakeResult bake = new RoadmapBaker(scene).Bake(new BakeSettings { MaxNodes = 300, Start = GapCourse.From, Goal = GapCourse.To, StopWhenConnected = true, Threads = 2 });
        PlanResult plan = new PathQuery(scene, bake.Roadmap).Plan(GapCourse.From, GapCourse.To);
        Assert.That(plan.Status, Is.EqualTo(PlannerStatus.Exact), plan.Reason);
        JumpAnimation animation = new JumpAnimator(scene, model).Animate(plan.Jumps);
        Assert.Multiple(() =>
        {
            Assert.That(animation.ContactPhases, Is.Not.Empty);
            Assert.That(animation.Duration, Is.EqualTo(animation.LeadIn + plan.TotalFlightTime + animation.Stances.Sum() + animation.LeadOut).Within(1e-3f));
            Assert.That(animation.CollidingFrames, Is.Zero);
        });
    }

    [Test]
    public void BadSpecsNameTheBoneOrLimb()
    {
        string glb = Path.Combine(RepositoryFiles.Root, "Scenes", "characters", "skeleton.glb");
        JsonObject Spec(string limbs, int required = 1) =>
            (JsonObject)JsonNode.Parse("{\"schema\":\"ballistic.character/1\",\"name\":\"bad\",\"requiredContacts\":" + required + ",\"limbs\":{" + limbs + "}}")!;
        string Write(JsonObject json)
        {
            string path = Path.Combine(_folder, $"{Guid.NewGuid():N}.json");
            File.WriteAllText(path, json.ToJsonString());
            return path;
        }

        Assert.Multiple(() =>
        {
            Assert.That(() => CharacterSpecFile.Load(glb, Write(Spec("""
                "tail":{"rootBone":"pelvis","effectorBone":"tail_tip"}
                """))), Throws.TypeOf<RigException>().With.Message.Contains("'tail_tip'").And.Message.Contains("tail"));
            Assert.That(() => CharacterSpecFile.Load(glb, Write(Spec("""
                "frozen":{"rootBone":"pelvis","effectorBone":"pelvis"}
                """))), Throws.TypeOf<RigException>().With.Message.Contains("limb 'frozen'").And.Message.Contains("'pelvis' as both its rootBone and its effectorBone"));
            Assert.That(() => CharacterSpecFile.Load(glb, Write(Spec("""
                "left_foot":{"rootBone":"left_hip","effectorBone":"left_ankle"}
                """, required: 3))), Throws.TypeOf<RigException>().With.Message.Contains("3 required contacts"));
            Assert.That(() => CharacterSpecFile.Load(glb, Write((JsonObject)JsonNode.Parse("""{"schema":"something/else"}""")!)), Throws.TypeOf<RigException>().With.Message.Contains("not a Ballistic limb spec"));
            Assert.That(() => CharacterSpecFile.Load(Path.Combine(RepositoryFiles.Root, "Scenes", "levels", "gap-course.glb"), Write(Spec("\"a\":{\"rootBone\":\"x\",\"effectorBone\":\"y\"}"))), Throws.TypeOf<RigException>().With.Message.Contains("has no skin"));
        });
    }
}
