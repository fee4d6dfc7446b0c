using System.Text.Json.Nodes;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Rigs;

/// <summary>Every bad spec or rig gives one RigException sentence naming the file, the limb or bone and the key; never a runtime message.</summary>
public sealed class SpecErrorTests
{
    private const string Foot = "\"left_foot\":{\"rootBone\":\"left_hip\",\"effectorBone\":\"left_ankle\"";
    private string _folder = "";

    public static IEnumerable<TestCaseData> BadSpecs()
    {
        static TestCaseData Case(string name, string json, params string[] fragments) => new TestCaseData(json, fragments).SetName($"{{m}}({name})");
        static string Spec(string limbs, string extra = "") => "{\"schema\":\"ballistic.character/1\"," + extra + "\"limbs\":{" + limbs + "}}";

        yield return Case("unknown contact", Spec(Foot + ",\"contact\":\"paw\"}"), "limb 'left_foot'", "'contact'", "\"paw\"", "\"foot\" or \"hand\"");
        yield return Case("unknown top-level key", Spec(Foot + "}", "\"trunkbones\":[\"pelvis\"],"), "unknown key 'trunkbones'", "trunkBones");
        yield return Case("unknown limb key", Spec(Foot + ",\"effectorOfset\":[0,0,0]}"), "limb 'left_foot'", "unknown key 'effectorOfset'");
        yield return Case("unknown filter key", Spec(Foot + ",\"normalFilter\":{\"direction\":[0,1,0],\"minCosine\":0,\"max\":1}}"), "limb 'left_foot'", "'normalFilter'", "unknown key 'max'");
        yield return Case("number as a string", Spec(Foot + "}", "\"friction\":\"high\","), "key 'friction'", "must be a number", "\"high\"");
        yield return Case("limbs as a list", "{\"schema\":\"ballistic.character/1\",\"limbs\":[]}", "key 'limbs'", "must be an object");
        yield return Case("no limbs", "{\"schema\":\"ballistic.character/1\"}", "key 'limbs'", "missing");
        yield return Case("too many limbs", Spec(string.Join(",", Enumerable.Range(0, 129).Select(i => $"\"leg{i}\":{{\"rootBone\":\"left_hip\",\"effectorBone\":\"left_ankle\"}}"))), "key 'limbs'", "names 129 limbs", "more than the 128");
        yield return Case("short vector", Spec(Foot + ",\"effectorOffset\":[0,1]}"), "limb 'left_foot'", "'effectorOffset'", "3 numbers");
        yield return Case("zero normal", Spec(Foot + ",\"contactNormal\":[0,0,0]}"), "limb 'left_foot'", "'contactNormal'", "zero vector");
        yield return Case("filter without minCosine", Spec(Foot + ",\"normalFilter\":{\"direction\":[0,1,0]}}"), "limb 'left_foot'", "normalFilter", "no minCosine");
        yield return Case("minCosine out of range", Spec(Foot + ",\"normalFilter\":{\"direction\":[0,1,0],\"minCosine\":2}}"), "limb 'left_foot'", "normalFilter.minCosine", "[−1, 1]");
        yield return Case("bone name as a number", Spec("\"left_foot\":{\"rootBone\":3,\"effectorBone\":\"left_ankle\"}"), "limb 'left_foot'", "'rootBone'", "must be a string", "3");
        yield return Case("no effector bone", Spec("\"left_foot\":{\"rootBone\":\"left_hip\"}"), "limb 'left_foot'", "no effectorBone");
        yield return Case("limb not an object", Spec("\"left_foot\":\"left_ankle\""), "limb 'left_foot'", "must be an object");
        yield return Case("unknown up axis", Spec(Foot + "}", "\"upAxis\":\"up\","), "key 'upAxis'", "\"+Z\"", "\"up\"");
        yield return Case("parallel axes", Spec(Foot + "}", "\"upAxis\":\"+Z\",\"forwardAxis\":\"-Z\","), "'upAxis' and 'forwardAxis'", "perpendicular");
        yield return Case("axis as a list", Spec(Foot + "}", "\"forwardAxis\":[0,0,1],"), "key 'forwardAxis'", "must be a string");
        yield return Case("joint of an unknown bone", Spec(Foot + "}", "\"joints\":{\"tail\":{\"axes\":[]}},"), "joints, bone 'tail'", "not a bone");
        yield return Case("inverted limits", Spec(Foot + "}", "\"joints\":{\"left_knee\":{\"axes\":[{\"axis\":[1,0,0],\"min\":10,\"max\":-10}]}},"), "bone 'left_knee'", "axis 0", "above max");
        yield return Case("axis without max", Spec(Foot + "}", "\"joints\":{\"left_knee\":{\"axes\":[{\"axis\":[1,0,0],\"min\":10}]}},"), "bone 'left_knee'", "axis 0", "no max");
        yield return Case("negative radius", Spec(Foot + "}", "\"boneRadii\":{\"left_hip\":-1},"), "boneRadii, bone 'left_hip'", "positive");
        yield return Case("radius of an unknown bone", Spec(Foot + "}", "\"boneRadii\":{\"tail\":0.1},"), "boneRadii, bone 'tail'", "not a bone");
        yield return Case("unknown pose", Spec(Foot + "}", "\"poses\":{\"crouch\":{}},"), "'poses'", "unknown key 'crouch'");
        yield return Case("pose with too few angles", Spec(Foot + "}", "\"poses\":{\"contact\":{\"left_hip\":[1,2]}},"), "pose 'contact', bone 'left_hip'", "2 angles", "3 degrees");
        yield return Case("pose of a fixed bone", Spec(Foot + "}", "\"trunkBones\":[\"pelvis\",\"spine\",\"chest\",\"neck\",\"head\"],\"poses\":{\"flexion\":{\"head\":[10]}},"), "pose 'flexion', bone 'head'", "fixed");
        yield return Case("pose beyond the limits", Spec(Foot + "}", "\"poses\":{\"contact\":{\"left_knee\":[170]}},"), "pose 'contact', bone 'left_knee'", "170", "limits");
        yield return Case("pose angle not a number", Spec(Foot + "}", "\"poses\":{\"contact\":{\"left_knee\":[\"a\",0,0]}},"), "pose 'contact', bone 'left_knee'", "angle 0", "must be a number");
        yield return Case("trunk bones not a list", Spec(Foot + "}", "\"trunkBones\":\"pelvis\","), "key 'trunkBones'", "must be a list");
        yield return Case("unknown trunk bone", Spec(Foot + "}", "\"trunkBones\":[\"torso\"],"), "'trunkBones'", "'torso'", "not a bone");
        yield return Case("fractional required contacts", Spec(Foot + "}", "\"requiredContacts\":1.5,"), "key 'requiredContacts'", "whole number");
        yield return Case("too many required contacts", Spec(Foot + "}", "\"requiredContacts\":3,"), "key 'requiredContacts'", "3 required contacts");
        yield return Case("slope ahead below the slope", Spec(Foot + "}", "\"maxSlope\":30,\"maxSlopeAlong\":20,"), "key 'maxSlopeAlong'", "20 degrees", "below", "30 degrees, key 'maxSlope'");
        yield return Case("slope ahead below the derived slope", Spec(Foot + "}", "\"maxSlopeAlong\":10,"), "key 'maxSlopeAlong'", "10 degrees", "derived from the rig");
        yield return Case("slope ahead out of range", Spec(Foot + "}", "\"maxSlopeAlong\":95,"), "key 'maxSlopeAlong'", "between 0 and 80");
        yield return Case("zero speed", Spec(Foot + "}", "\"takeoffSpeedMax\":0,"), "key 'takeoffSpeedMax'", "positive");
        yield return Case("null name", Spec(Foot + "}", "\"name\":null,"), "key 'name'", "is null");
        yield return Case("repeated key", Spec(Foot + ",\"contact\":\"foot\",\"contact\":\"hand\"}"), "limbs.left_foot", "'contact' appears twice");
        yield return Case("huge offset", Spec(Foot + ",\"effectorOffset\":[10000,0,0]}"), "limb 'left_foot'", "'effectorOffset'", "within ±1000");
        yield return Case("offset beyond single precision", Spec(Foot + ",\"effectorOffset\":[1e39,0,0]}"), "limb 'left_foot'", "'effectorOffset'", "finite number");
        yield return Case("huge normal", Spec(Foot + ",\"contactNormal\":[0,-1e30,0]}"), "limb 'left_foot'", "'contactNormal'", "within ±1000");
        yield return Case("NaN as a string", Spec(Foot + ",\"contactNormal\":[0,\"NaN\",0]}"), "limb 'left_foot'", "'contactNormal'", "must be a number", "\"NaN\"");
        yield return Case("zero filter direction", Spec(Foot + ",\"normalFilter\":{\"direction\":[0,0,0],\"minCosine\":0}}"), "limb 'left_foot'", "normalFilter.direction", "zero vector");
        yield return Case("huge filter direction", Spec(Foot + ",\"normalFilter\":{\"direction\":[0,1e38,0],\"minCosine\":0}}"), "limb 'left_foot'", "normalFilter.direction", "within ±1000");
        yield return Case("unknown contact kind as a number", Spec(Foot + ",\"contact\":1}"), "limb 'left_foot'", "'contact'", "must be a string");
        yield return Case("limits beyond a turn", Spec(Foot + "}", "\"joints\":{\"left_knee\":{\"axes\":[{\"axis\":[1,0,0],\"min\":-720,\"max\":10}]}},"), "bone 'left_knee'", "axis 0", "'min'", "between -360 and 360");
        yield return Case("zero joint axis", Spec(Foot + "}", "\"joints\":{\"left_knee\":{\"axes\":[{\"axis\":[0,0,0],\"min\":-10,\"max\":10}]}},"), "bone 'left_knee'", "axis 0", "'axis'", "zero vector");
        yield return Case("huge radius", Spec(Foot + "}", "\"boneRadii\":{\"left_hip\":100000},"), "boneRadii, bone 'left_hip'", "at most 1000");
        yield return Case("huge default radius", Spec(Foot + "}", "\"boneRadius\":1e20,"), "key 'boneRadius'", "at most 1000");
        yield return Case("huge speed", Spec(Foot + "}", "\"takeoffSpeedMax\":1e6,"), "key 'takeoffSpeedMax'", "at most 1000");
        yield return Case("huge friction", Spec(Foot + "}", "\"friction\":1e6,"), "key 'friction'", "between 0 and 1000");
        yield return Case("repeated top-level key", Spec(Foot + "}", "\"friction\":1,\"friction\":2,"), "the spec", "'friction' appears twice");
        yield return Case("repeated limb", "{\"schema\":\"ballistic.character/1\",\"limbs\":{" + Foot + "}," + Foot + "}}}", "object 'limbs'", "'left_foot' appears twice");
        yield return Case("unknown joint key", Spec(Foot + "}", "\"joints\":{\"left_knee\":{\"axes\":[],\"limits\":1}},"), "joints, bone 'left_knee'", "unknown key 'limits'");
        yield return Case("deeply nested", Spec(Foot + "}", "\"name\":" + new string('[', 100) + new string(']', 100) + ","), "is not valid JSON");
        yield return Case("lone surrogate", Spec(Foot + "}", "\"name\":\"\\uD800\","), "object 'name'", "not valid Unicode");
        yield return Case("line break in a limb name", "{\"schema\":\"ballistic.character/1\",\"limbs\":{\"left\\nfoot\":{\"rootBone\":\"left_hip\",\"effectorBone\":\"ankle\"}}}", "limb 'left\\u000afoot'", "'ankle'");
        yield return Case("not JSON", "{\"schema\": ", "is not valid JSON");
        yield return Case("limb rooted at the root bone", Spec("\"left_foot\":{\"rootBone\":\"pelvis\",\"effectorBone\":\"left_ankle\"}"), "limb 'left_foot'", "starts at 'pelvis', the rig's root bone");
        yield return Case("overlapping chains", Spec(Foot + "},\"left_toes\":{\"rootBone\":\"left_knee\",\"effectorBone\":\"left_toe\"}"), "limbs 'left_foot' and 'left_toes'", "both run through the bone 'left_ankle'");
        yield return Case("limb bone in trunkBones", Spec(Foot + "}", "\"trunkBones\":[\"pelvis\",\"left_hip\",\"left_knee\"],"), "key 'trunkBones'", "lists 'left_knee', a bone of limb 'left_foot' below its root bone");
        yield return Case("trailing comma", "{\n  \"schema\": \"ballistic.character/1\",\n  \"limbs\": {},\n}", "is not valid JSON: The JSON object contains a trailing comma at the end (line 4, column 1).");
        yield return Case("JSON but not an object", "[1, 2]", "is not a Ballistic limb spec");
        yield return Case("unknown effector", Spec("\"tail\":{\"rootBone\":\"pelvis\",\"effectorBone\":\"tail_tip\"}"), "limb 'tail'", "'tail_tip'", "skeleton.glb");
        yield return Case("root bone the effector itself", Spec("\"left_foot\":{\"rootBone\":\"left_ankle\",\"effectorBone\":\"left_ankle\"}"), "limb 'left_foot'", "'left_ankle' as both its rootBone and its effectorBone", "rootBone");
        yield return Case("root bone not above the effector", Spec("\"left_foot\":{\"rootBone\":\"right_hip\",\"effectorBone\":\"left_ankle\"}"), "left_foot", "'right_hip' is not above 'left_ankle'");
        yield return Case("effector without vertices", Spec("\"nod\":{\"rootBone\":\"neck\",\"effectorBone\":\"head\"}"), "limb 'nod'", "no effectorOffset", "effector bone 'head'", "give effectorOffset");
    }

    [SetUp]
    public void MakeFolder()
    {
        _folder = Path.Combine(Path.GetTempPath(), $"ballistic-spec-{Guid.NewGuid():N}");
        Directory.CreateDirectory(_folder);
    }

    [TearDown]
    public void RemoveFolder() => Directory.Delete(_folder, recursive: true);

    [TestCaseSource(nameof(BadSpecs))]
    public void ABadSpecIsOneSentenceNamingTheFileAndKey(string json, string[] fragments)
    {
        string spec = Path.Combine(_folder, "bad.limbs.json");
        File.WriteAllText(spec, json);
        RigException error = Assert.Throws<RigException>(() => CharacterSpecFile.Load(Path.Combine(RepositoryFiles.Root, "Scenes", "characters", "skeleton.glb"), spec))!;
        TestContext.Out.WriteLine(error.Message);
        Assert.Multiple(() =>
        {
            Assert.That(error.Message, Does.Contain("bad.limbs.json").Or.Contain("skeleton.glb"));
            foreach (string fragment in fragments)
            {
                Assert.That(error.Message, Does.Contain(fragment));
            }

            AssertNoRuntimeWords(error.Message);
        });
    }

    [Test]
    public void BadRigsNameTheNodeAndTheProblem()
    {
        var dog = new BrokenDog(_folder);
        JsonObject pristine = dog.Pristine;
        int Node(JsonObject json, string name) => json["nodes"]!.AsArray().Select((n, i) => (n, i)).First(p => p.n!["name"]!.GetValue<string>() == name).i;
        string Broken(Action<JsonObject> change)
        {
            string message = dog.Load(change);
            AssertNoRuntimeWords(message);
            return message;
        }

        Assert.Multiple(() =>
        {
            string message = Broken(j => j["nodes"]![Node(j, "left_knee")]!["scale"] = new JsonArray(1, 2, 1));
            Assert.That(message, Does.Contain("dog.gltf").And.Contain("bone 'left_knee'").And.Contain("non-uniformly"));
            message = Broken(j => j["nodes"]![Node(j, "left_hind_foot_anchor")]!["scale"] = new JsonArray(1, 1, 3));
            Assert.That(message, Does.Contain("node 'left_hind_foot_anchor' (above bone 'left_hind_paw')").And.Contain("non-uniformly"));
            message = Broken(j => j["nodes"]![Node(j, "left_hind_foot_anchor")]!["scale"] = new JsonArray(-1, 1, 1));
            Assert.That(message, Does.Contain("left_hind_foot_anchor").And.Contain("mirrored"));
            message = Broken(j => j["nodes"]![Node(j, "right_knee")]!["name"] = "left_knee");
            Assert.That(message, Does.Contain("two bones are called 'left_knee'"));
            message = Broken(j => j["skins"]![0]!["joints"]![3] = 999);
            Assert.That(message, Does.Contain("dog.gltf").And.Contain("skin 0").And.Contain("999"));
            message = Broken(j => j["accessors"]![0]!.AsObject().Remove("count"));
            Assert.That(message, Does.Contain("dog.gltf").And.Contain("accessor 0").And.Contain("_count: 0 must be greater or equal to 1"));
            message = Broken(j => j["nodes"]![0]!["translation"] = new JsonArray("a", 0, 0));
            Assert.That(message, Does.Contain("dog.gltf: node 0 ('pelvis') has a malformed translation: it must be a list of 3 numbers; item 0 is the string \"a\""));
            message = Broken(j => j["nodes"]![Node(j, "chest")]!["children"] = new JsonArray(0));
            Assert.That(message, Does.Contain("dog.gltf").And.Contain("cycle"));
            message = Broken(j => j["skins"]![0]!["joints"] = 5);
            Assert.That(message, Does.Contain("dog.gltf: skins[0].joints: its JSON does not follow the glTF 2.0 schema"));
            message = Broken(j => j["nodes"]![Node(j, "Body")]!["skin"] = "zero");
            Assert.That(message, Does.Contain("dog.gltf").And.Contain("skin"));
        });
    }

    private static void AssertNoRuntimeWords(string message)
    {
        foreach (string runtime in new[] { "Object reference", "(Parameter", "Value cannot be null", "Unable to cast", "Index was outside", "The node must be of type", "An item with the same key", "LineNumber", "BytePositionInLine", "reader options" })
        {
            Assert.That(message, Does.Not.Contain(runtime));
        }
    }
}
