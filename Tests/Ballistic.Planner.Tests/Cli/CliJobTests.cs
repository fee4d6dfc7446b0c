using System.Numerics;
using System.Text.Json;
using Ballistic.Authoring.Levels;
using Ballistic.Cli;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Cli;

public sealed class CliJobTests
{
    private string _folder = "";

    [SetUp]
    public void MakeFolder()
    {
        _folder = Path.Combine(Path.GetTempPath(), $"ballistic-cli-{Guid.NewGuid():N}");
        Directory.CreateDirectory(_folder);
    }

    [TearDown]
    public void RemoveFolder() => Directory.Delete(_folder, recursive: true);

    [Test]
    public void ARigWithStaleAccessorBoundsLoadsAsRepairedAndSaysSoOnce()
    {
        string characters = Path.Combine(RepositoryFiles.Root, "Scenes", "characters");
        (System.Text.Json.Nodes.JsonObject json, byte[] bin) = Fuzz.FuzzInputs.SplitGlb(File.ReadAllBytes(Path.Combine(characters, "frog.glb")));
        int position = json["meshes"]![0]!["primitives"]![0]!["attributes"]!["POSITION"]!.GetValue<int>();
        json["accessors"]![position]!["max"] = new System.Text.Json.Nodes.JsonArray(0.01, 0.01, 0.01);
        string rig = Path.Combine(_folder, "frog.glb");
        File.WriteAllBytes(rig, Fuzz.FuzzInputs.JoinGlb(System.Text.Encoding.UTF8.GetBytes(json.ToJsonString()), bin));
        File.Copy(Path.Combine(characters, "frog.limbs.json"), Path.Combine(_folder, "frog.limbs.json"));

        (int code, string output, string error) = Run("bake", "--level", RepositoryFiles.Level("gap-course"), "--character", Path.Combine(_folder, "frog.limbs.json"), "--max-nodes", "30", "--out", Path.Combine(_folder, "frog.roadmap"));
        string[] notes = [.. error.Split('\n').Where(l => l.StartsWith("note: ", StringComparison.Ordinal))];
        Assert.Multiple(() =>
        {
            Assert.That(code, Is.Zero, error);
            Assert.That(output, Does.Contain("30 nodes"));
            Assert.That(notes, Has.Length.EqualTo(1));
            Assert.That(notes.FirstOrDefault(), Does.StartWith($"note: {rig} is not valid glTF (accessor {position} (POSITION of primitive 0 of mesh 0").And.EndWith("); loaded as repaired."));
        });
    }

    [Test]
    public void ALevelWithStaleAccessorBoundsLoadsAsRepairedAndSaysSoOnce()
    {
        // An exporter that moved a vertex after writing the bounds: SharpGLTF's validation refuses the file in both its
        // modes, Godot and Blender import it, and so do we, with one note.
        (System.Text.Json.Nodes.JsonObject json, byte[] bin) = Fuzz.FuzzInputs.SplitGlb(File.ReadAllBytes(RepositoryFiles.Level("gap-course")));
        json["accessors"]![0]!["max"] = new System.Text.Json.Nodes.JsonArray(0.5, 0.5, 0.5);
        string level = Path.Combine(_folder, "stale.glb");
        File.WriteAllBytes(level, Fuzz.FuzzInputs.JoinGlb(System.Text.Encoding.UTF8.GetBytes(json.ToJsonString()), bin));
        Assert.That(Ballistic.Planner.Levels.GltfLevelLoader.Load(RepositoryFiles.Level("gap-course")).Repaired, Is.Null, "the bundled level is valid as it is");

        (int code, string output, string error) = Run("bake", "--level", level, "--character", "skeleton", "--max-nodes", "30", "--out", Path.Combine(_folder, "stale.roadmap"));
        string[] notes = [.. error.Split('\n').Where(l => l.StartsWith("note: ", StringComparison.Ordinal))];
        Assert.Multiple(() =>
        {
            Assert.That(code, Is.Zero, error);
            Assert.That(output, Does.Contain("30 nodes"));
            Assert.That(notes, Has.Length.EqualTo(1));
            Assert.That(notes.FirstOrDefault(), Does.StartWith($"note: {level} is not valid glTF (accessor 0 (POSITION of primitive 0 of mesh 0").And.EndWith("); loaded as repaired."));
        });
    }

    [Test]
    public void PlanWritesAReportWhoseJumpsObeyThePhysics()
    {
        string report = Path.Combine(_folder, "plan.json");
        string svg = Path.Combine(_folder, "plan.svg");
        (int code, string output, string error) = Run("plan", "--level", RepositoryFiles.Level("gap-course"), "--character", "skeleton",
            "--from", "-6,0,0", "--to", "11.5,1,0", "--threads", "2", "--report", report, "--svg", svg);
        Assert.That(code, Is.Zero, error);
        Assert.That(output, Does.Contain("status: exact"));

        using JsonDocument json = JsonDocument.Parse(File.ReadAllBytes(report));
        JsonElement root = json.RootElement;
        Assert.Multiple(() =>
        {
            Assert.That(root.GetProperty("schema").GetString(), Is.EqualTo("ballistic.plan/2"));
            Assert.That(root.GetProperty("status").GetString(), Is.EqualTo("exact"));
            Assert.That(root.GetProperty("character").GetProperty("name").GetString(), Is.EqualTo("skeleton"));
            Assert.That(Vec(root.GetProperty("character").GetProperty("gravity")), Is.EqualTo(new Vector3(0f, -9.81f, 0f)));
            Assert.That(root.GetProperty("roadmap").GetProperty("nodes").GetInt32(), Is.GreaterThan(1));
            Assert.That(root.GetProperty("request").GetProperty("from").GetArrayLength(), Is.EqualTo(3));
            Assert.That(root.TryGetProperty("timings", out _), Is.True);
        });

        // The walking limits under the spec's keys: the skeleton's derived ones (the README's 1.53 m/s, 22.5°, 25°,
        // 0.24 m), and no walk of the plan faster than its speed.
        JsonElement walking = root.GetProperty("character").GetProperty("walking");
        Assert.Multiple(() =>
        {
            Assert.That(walking.GetProperty("walkSpeed").GetSingle(), Is.EqualTo(1.53f).Within(0.005f));
            Assert.That(walking.GetProperty("maxSlope").GetSingle(), Is.EqualTo(22.5f));
            Assert.That(walking.GetProperty("maxSlopeAlong").GetSingle(), Is.EqualTo(25f));
            Assert.That(walking.GetProperty("stepHeight").GetSingle(), Is.EqualTo(0.24f).Within(0.005f));
            foreach (JsonElement move in root.GetProperty("moves").EnumerateArray().Where(m => m.GetProperty("kind").GetString() == "walk"))
            {
                Assert.That(move.GetProperty("speed").GetSingle(), Is.LessThanOrEqualTo(walking.GetProperty("walkSpeed").GetSingle() * 1.0001f));
            }
        });

        // Re-check the physics from the report alone, as another tool would.
        float takeoffMax = root.GetProperty("character").GetProperty("takeoffSpeedMax").GetSingle();
        float landingMax = root.GetProperty("character").GetProperty("landingSpeedMax").GetSingle();
        JsonElement jumps = root.GetProperty("jumps");
        Assert.That(jumps.GetArrayLength(), Is.GreaterThanOrEqualTo(3));
        foreach (JsonElement jump in jumps.EnumerateArray())
        {
            Vector3 p0 = Vec(jump.GetProperty("takeoff").GetProperty("position"));
            Vector3 p1 = Vec(jump.GetProperty("landing").GetProperty("position"));
            Vector3 v0 = Vec(jump.GetProperty("takeoffVelocity"));
            Vector3 v1 = Vec(jump.GetProperty("landingVelocity"));
            float t = jump.GetProperty("flightTime").GetSingle();
            Vector3 end = p0 + (v0 * t) + (0.5f * t * t * new Vector3(0f, -9.81f, 0f));
            Assert.That(Vector3.Distance(end, p1), Is.LessThan(5e-3f), "the arc lands on the landing pose");
            Assert.That(Vector3.Distance(v0 + (t * new Vector3(0f, -9.81f, 0f)), v1), Is.LessThan(1e-3f));
            Assert.That(v0.Length(), Is.LessThanOrEqualTo(takeoffMax * 1.0001f));
            Assert.That(v1.Length(), Is.LessThanOrEqualTo(landingMax * 1.0001f));
            Assert.That(InCone(jump.GetProperty("takeoff").GetProperty("cone"), v0), Is.True, "takeoff velocity in the takeoff cone");
            Assert.That(InCone(jump.GetProperty("landing").GetProperty("cone"), -v1), Is.True, "reversed landing velocity in the landing cone");
            Assert.That(jump.GetProperty("takeoff").GetProperty("contacts").GetArrayLength(), Is.GreaterThanOrEqualTo(2));
        }

        // Each move (jump or walk) starts where the previous one ended.
        Vector3? previousEnd = null;
        foreach (JsonElement move in root.GetProperty("moves").EnumerateArray())
        {
            bool isJump = move.GetProperty("kind").GetString() == "jump";
            Vector3 start = Vec(move.GetProperty(isJump ? "takeoff" : "from").GetProperty("position"));
            if (previousEnd is Vector3 end)
            {
                Assert.That(start, Is.EqualTo(end), "each move starts where the previous one ended");
            }

            previousEnd = Vec(move.GetProperty(isJump ? "landing" : "to").GetProperty("position"));
        }

        string picture = File.ReadAllText(svg);
        Assert.That(picture, Does.StartWith("<svg").And.Contain("Top view").And.Contain("Side profile").And.Contain("data:image/png;base64,"));
    }

    [TestCase(null, 0.5f, 0.25f)]
    [TestCase("0.15,0.05", 0.15f, 0.05f)]
    [TestCase("0.2", 0.2f, 0.25f)]
    public void TheReportSaysHowFarTheStancesStandFromTheRequestedPoints(string? tolerance, float across, float upDown)
    {
        string report = Path.Combine(_folder, "plan.json");
        string[] args = ["plan", "--level", RepositoryFiles.Level("gap-course"), "--character", "skeleton", "--from", "-6,0,0.3", "--to", "11.5,1,-0.4", "--threads", "2", "--report", report];
        (int code, string output, string error) = Run([.. args, .. tolerance is null ? Array.Empty<string>() : ["--goal-tolerance", tolerance]]);
        Assert.That(code, Is.Zero, error);
        Assert.That(output, Does.Contain("start: stance").And.Contain("goal: stance"));
        using JsonDocument json = JsonDocument.Parse(File.ReadAllBytes(report));
        JsonElement root = json.RootElement;
        Assert.That(root.GetProperty("request").GetProperty("tolerance").GetProperty("across").GetSingle(), Is.EqualTo(across));
        foreach ((string name, Vector3 requested) in new[] { ("start", new Vector3(-6f, 0f, 0.3f)), ("goal", new Vector3(11.5f, 1f, -0.4f)) })
        {
            JsonElement placement = root.GetProperty(name);
            Vector3 centre = Vec(placement.GetProperty("contactCentre"));
            Assert.That(placement.GetProperty("placed").GetBoolean(), Is.True);
            Assert.That(placement.GetProperty("across").GetSingle(), Is.LessThanOrEqualTo(across));
            Assert.That(placement.GetProperty("upDown").GetSingle(), Is.LessThanOrEqualTo(upDown));
            Assert.That(new Vector2(centre.X - requested.X, centre.Z - requested.Z).Length(), Is.EqualTo(placement.GetProperty("across").GetSingle()).Within(1e-4f));
        }

        // The first stance's own contacts, as the report lists them, are where the placement says (a walk's "from",
        // a jump's "takeoff").
        JsonElement move = root.GetProperty("moves")[0];
        JsonElement first = move.GetProperty(move.GetProperty("kind").GetString() == "walk" ? "from" : "takeoff").GetProperty("contacts");
        Vector3 sum = Vector3.Zero;
        foreach (JsonElement c in first.EnumerateArray())
        {
            sum += Vec(c.GetProperty("position"));
        }

        Assert.That(Vector3.Distance(sum / first.GetArrayLength(), Vec(root.GetProperty("start").GetProperty("contactCentre"))), Is.LessThan(1e-4f));
        Assert.That(root.GetProperty("rejectedJumps").ValueKind, Is.EqualTo(JsonValueKind.Array));
    }

    [Test]
    public void PlanAnimateWritesAGlbAndTheAnimationSection()
    {
        string report = Path.Combine(_folder, "animated.json");
        string glb = Path.Combine(_folder, "models", "skeleton.glb");
        (int code, string output, string error) = Run("plan", "--level", RepositoryFiles.Level("gap-course"), "--character", "skeleton",
            "--from", "-6,0,0", "--to", "11.5,1,0", "--report", report, "--animate", "--glb", glb);
        Assert.That(code, Is.Zero, error);
        Assert.That(output, Does.Contain("animation:"));
        Assert.That(File.Exists(glb), Is.True);

        using JsonDocument json = JsonDocument.Parse(File.ReadAllBytes(report));
        JsonElement animation = json.RootElement.GetProperty("animation");
        Assert.Multiple(() =>
        {
            Assert.That(animation.GetProperty("glb").GetString(), Is.EqualTo("models/skeleton.glb"), "relative to the report");
            Assert.That(animation.GetProperty("clip").GetString(), Is.EqualTo("jumps"));
            // The clip lasts the moves and the stances between them: the last move ends where the clip does.
            Assert.That(animation.GetProperty("duration").GetSingle(), Is.GreaterThanOrEqualTo(json.RootElement.GetProperty("summary").GetProperty("totalDuration").GetSingle() - 1e-3f));
            Assert.That(animation.GetProperty("moves")[animation.GetProperty("moves").GetArrayLength() - 1].GetProperty("end").GetSingle(), Is.EqualTo(animation.GetProperty("duration").GetSingle()).Within(1e-3f));
            Assert.That(animation.GetProperty("limbs").GetProperty("left_foot").GetProperty("effectorBone").GetString(), Is.EqualTo("left_ankle"));
            Assert.That(animation.GetProperty("contactPhases").GetArrayLength(), Is.GreaterThan(0));
        });
        foreach (JsonElement phase in animation.GetProperty("contactPhases").EnumerateArray())
        {
            Assert.That(phase.GetProperty("to").GetSingle(), Is.GreaterThanOrEqualTo(phase.GetProperty("from").GetSingle()));
        }

        // Another plan whose picture cannot be written (its path is a folder) replaces neither the animation nor the
        // report: the files of one plan are written as one set, the report last.
        byte[] oldReport = File.ReadAllBytes(report);
        byte[] oldGlb = File.ReadAllBytes(glb);
        string folder = Path.Combine(_folder, "a-folder.svg");
        Directory.CreateDirectory(folder);
        (int failed, _, string failure) = Run("plan", "--level", RepositoryFiles.Level("gap-course"), "--character", "skeleton",
            "--from", "-6,0,0", "--to", "4,0,0", "--report", report, "--animate", "--glb", glb, "--svg", folder);
        Assert.That(failed, Is.EqualTo(ExitCode.Output), failure);
        Assert.That(failure, Does.Contain("a-folder.svg"));
        Assert.That(File.ReadAllBytes(report), Is.EqualTo(oldReport), "the old report stays");
        Assert.That(File.ReadAllBytes(glb), Is.EqualTo(oldGlb), "the old animation stays");
        Assert.That(Directory.GetFiles(Path.GetDirectoryName(glb)!, "*.tmp").Concat(Directory.GetFiles(_folder, "*.tmp")), Is.Empty, "no temporary file is left");
    }

    [Test]
    public void ACharacterCanBeGivenAsALimbSpecFile()
    {
        string spec = Path.Combine(RepositoryFiles.Root, "Scenes", "characters", "ant.limbs.json");
        string report = Path.Combine(_folder, "ant.json");
        (int code, string output, string error) = Run("plan", "--level", RepositoryFiles.Level("gap-course"), "--character", spec,
            "--from", "-6,0,0", "--to", "11.5,1,0", "--report", report, "--animate");
        Assert.That(code, Is.Zero, error);
        Assert.That(output, Does.Contain("animation:"));

        string lonely = Path.Combine(_folder, "lonely.limbs.json");
        File.Copy(spec, lonely);
        (int missing, _, string missingError) = Run("plan", "--level", RepositoryFiles.Level("gap-course"), "--character", lonely,
            "--from", "-6,0,0", "--to", "11.5,1,0", "--report", report);
        Assert.That(missing, Is.EqualTo(ExitCode.Input));
        Assert.That(missingError, Does.Contain("lonely.glb"));
    }

    [Test]
    public void BakeThenPlanWithTheSavedRoadmap()
    {
        string roadmap = Path.Combine(_folder, "course.roadmap");
        (int bakeCode, string bakeOutput, string bakeError) = Run("bake", "--level", RepositoryFiles.Level("gap-course"), "--character", "skeleton", "--max-nodes", "80", "--out", roadmap);
        Assert.That(bakeCode, Is.Zero, bakeError);
        Assert.That(bakeOutput, Does.Contain("80 nodes"));
        Assert.Multiple(() =>
        {
            Assert.That(bakeOutput, Does.StartWith("bake: done (reached 80 nodes)"), "a bake is done, not 'exact'");
            Assert.That(bakeOutput, Does.Contain("jump candidates refused: "));
            foreach (Ballistic.Planner.Steering.SteeringFailure failure in Enum.GetValues<Ballistic.Planner.Steering.SteeringFailure>())
            {
                Assert.That(bakeOutput, Does.Not.Contain(failure.ToString() + " "), "refusals in words, not enum names");
            }
        });

        string report = Path.Combine(_folder, "r.json");
        (int code, string output, string error) = Run("plan", "--level", RepositoryFiles.Level("gap-course"), "--character", "skeleton", "--roadmap", roadmap, "--from", "-6,0,0", "--to", "11.5,1,0", "--report", report);
        Assert.That(code, Is.Zero, error);
        Assert.That(output, Does.Contain("roadmap: 80 nodes"));
        Assert.That(output, Does.Contain("loadRoadmap"));

        // The jump costs reach the search: jumps free of effort, the path jumps more than when each costs a minute.
        int JumpsWith(string effort)
        {
            string costed = Path.Combine(_folder, $"effort-{effort}.json");
            (int c, _, string e) = Run("plan", "--level", RepositoryFiles.Level("gap-course"), "--character", "skeleton", "--roadmap", roadmap, "--from", "-6,0,0", "--to", "11.5,1,0", "--report", costed, "--jump-effort", effort);
            Assert.That(c, Is.Zero, e);
            using JsonDocument doc = JsonDocument.Parse(File.ReadAllText(costed));
            return doc.RootElement.GetProperty("jumps").GetArrayLength();
        }

        Assert.That(JumpsWith("0"), Is.GreaterThan(JumpsWith("60")), "free jumps are taken where a minute's would be walked");

        // The same roadmap for another character is refused in one line.
        (int wrong, _, string wrongError) = Run("plan", "--level", RepositoryFiles.Level("gap-course"), "--character", "frog", "--roadmap", roadmap, "--from", "-6,0,0", "--to", "11.5,1,0", "--report", report);
        Assert.Multiple(() =>
        {
            Assert.That(wrong, Is.EqualTo(ExitCode.Input));
            Assert.That(wrongError.Trim(), Does.StartWith("error: ").And.Contain("'skeleton', not 'frog'"));
            Assert.That(wrongError.Trim().Split('\n'), Has.Length.EqualTo(1), "one line, no stack trace");
        });
    }

    [Test]
    public void ABakeThatPlacesNoNodeSaysWhyAsTheEditorsBakeJobDoes()
    {
        // Only a ceiling, facing down: no foot can stand on it. The CLI's bake and the editor's BakeJob classify the
        // ending in one place (BakeJob.Run), so the CLI gives the job's reason, in one line, and writes nothing.
        string level = Path.Combine(_folder, "ceiling.glb");
        var ceiling = new LevelMesh("Ceiling", [new(-4f, 3f, -4f), new(4f, 3f, -4f), new(4f, 3f, 4f), new(-4f, 3f, 4f)], [0, 1, 2, 0, 2, 3], new LevelMaterial("rock", null), Vector4.One);
        GltfLevelWriter.Save(level, [ceiling]);
        string roadmap = Path.Combine(_folder, "ceiling.roadmap");
        (int code, string output, string error) = Run("bake", "--level", level, "--character", "skeleton", "--max-nodes", "30", "--out", roadmap);
        Assert.Multiple(() =>
        {
            Assert.That(code, Is.EqualTo(ExitCode.NotFound), error);
            Assert.That(error.Trim(), Does.StartWith("error: nothing written: skeleton can stand nowhere on the level ").And.Contain("no valid pose in "));
            Assert.That(error.Trim().Split('\n'), Has.Length.EqualTo(1), "one line");
            Assert.That(output, Does.Contain("roadmap: 0 nodes"), "the bake's own counts are still printed");
            Assert.That(File.Exists(roadmap), Is.False);
        });
    }

    [Test]
    public void BadInputIsOneLineNamingTheProblem()
    {
        string level = RepositoryFiles.Level("gap-course");
        string report = Path.Combine(_folder, "r.json");
        string notGltf = Path.Combine(_folder, "level.obj");
        File.WriteAllText(notGltf, "v 0 0 0");
        var cases = new (string[] Args, string Expected)[]
        {
            (["plan", "--level", "nope.glb", "--character", "skeleton", "--from", "0,0,0", "--to", "1,0,0", "--report", report], "does not exist"),
            (["plan", "--level", notGltf, "--character", "skeleton", "--from", "0,0,0", "--to", "1,0,0", "--report", report], "not glTF"),
            (["plan", "--level", level, "--character", "dragon", "--from", "0,0,0", "--to", "1,0,0", "--report", report], "Unknown character 'dragon'"),
            (["plan", "--level", level, "--character", "skeleton", "--from", "0;0", "--to", "1,0,0", "--report", report], "--from takes a point"),
            (["bake", "--level", level, "--character", "skeleton", "--threads", "0", "--out", Path.Combine(_folder, "x")], "--threads takes 1 to 1024 threads, not 0"),
            (["plan", "--level", level, "--character", "skeleton", "--from", "0,40,0", "--to", "11.5,1,0", "--report", report], "no valid pose stands within 0.5 m across and 0.25 m up/down of the start"),
            (["plan", "--level", level, "--character", "skeleton", "--from", "-6,0,0", "--to", "11.5,1,0", "--report", report, "--goal-tolerance", "0,1"], "--goal-tolerance takes ACROSS[,UPDOWN]"),
            (["plan", "--level", level, "--character", "skeleton", "--from", "-6,0,0", "--to", "11.5,1,0", "--report", report, "--goal-tolerance", "wide"], "--goal-tolerance takes ACROSS[,UPDOWN]"),
            (["plan", "--level", level, "--character", "skeleton", "--from", "-6,0,0", "--to", "11.5,1,0", "--report", report, "--jump-height-effort", "-1"], "--jump-height-effort takes 0 to 3600 seconds per metre, not -1"),
            (["plan", "--level", level, "--character", "skeleton", "--from", "-6,0,0", "--to", "11.5,1,0", "--report", report, "--jump-effort", "lots"], "--jump-effort takes a number"),
            (["playtest", "--level", level, "--character", "skeleton", "--out", _folder, "--jump-effort", "1e9"], "--jump-effort takes 0 to 3600 seconds"),
            (["plan", "--level", level, "--character", "skeleton", "--roadmap", Path.Combine(_folder, "x.roadmap"), "--from", "-6,0,0", "--to", "11.5,1,0", "--report", report, "--no-refine"], "--no-refine is about baking from the request: it goes without --roadmap."),
        };
        foreach ((string[] args, string expected) in cases)
        {
            (int code, _, string error) = Run(args);
            Assert.That(code, Is.Not.Zero, string.Join(' ', args));
            Assert.That(error + (File.Exists(report) ? File.ReadAllText(report) : ""), Does.Contain(expected), string.Join(' ', args));
        }
    }

    private static bool InCone(JsonElement cone, Vector3 v)
    {
        Vector3 axis = Vec(cone.GetProperty("axis"));
        float mu = cone.GetProperty("mu").GetSingle();
        float angle = MathF.Acos(Math.Clamp(Vector3.Dot(Vector3.Normalize(v), Vector3.Normalize(axis)), -1f, 1f));
        return angle <= MathF.Atan(mu) + 1e-3f;
    }

    private static Vector3 Vec(JsonElement e) => new(e[0].GetSingle(), e[1].GetSingle(), e[2].GetSingle());

    private static (int Code, string Output, string Error) Run(params string[] args)
    {
        using var output = new StringWriter();
        using var error = new StringWriter();
        int code = BallisticCli.Run(args, output, error);
        return (code, output.ToString(), error.ToString());
    }
}
