using System.Text.Json.Nodes;
using Ballistic.Cli;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Sampling;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Sampling;

/// <summary>
/// Specs within the documented ranges whose bodies cannot stand anywhere end in seconds with a clear reason (before: a
/// frog whose bone radii are 1000 m, the documented maximum, baked for more than 15 minutes with 0 nodes; radii of
/// 3 m on the pond took 35 s).
/// </summary>
public sealed class HopelessCharacterTests
{
    private string _folder = "";

    [SetUp]
    public void MakeFolder()
    {
        _folder = Path.Combine(Path.GetTempPath(), $"ballistic-hopeless-{Guid.NewGuid():N}");
        Directory.CreateDirectory(_folder);
    }

    [TearDown]
    public void RemoveFolder() => Directory.Delete(_folder, recursive: true);

    /// <summary>The bundled frog with every bone radius set to <paramref name="radius"/> metres, written beside a copy of its rig.</summary>
    private string Frog(float radius)
    {
        string characters = Path.Combine(RepositoryFiles.Root, "Scenes", "characters");
        JsonObject spec = JsonNode.Parse(File.ReadAllText(Path.Combine(characters, "frog.limbs.json")))!.AsObject();
        spec["boneRadius"] = radius;
        if (spec["boneRadii"] is JsonObject radii)
        {
            foreach (string bone in radii.Select(p => p.Key).ToArray())
            {
                radii[bone] = radius;
            }
        }

        string path = Path.Combine(_folder, "frog.limbs.json");
        File.WriteAllText(path, spec.ToJsonString());
        File.Copy(Path.Combine(characters, "frog.glb"), Path.Combine(_folder, "frog.glb"), overwrite: true);
        return path;
    }

    [Test]
    public void ATrunkLargerThanTheLevelIsRefusedBeforeAnyBake()
    {
        string spec = Frog(1000f);
        (CharacterModel _, ReducedCharacter reduced) = CharacterSpecFile.Load(Path.Combine(_folder, "frog.glb"), spec);
        Level pond = SharedLevels.Bundled("pond");
        Assert.That(() => PlanningScene.Create(pond, reduced), Throws.TypeOf<CharacterException>()
            .With.Message.Contains("Character 'frog' can stand nowhere on").And.Message.Contains("is larger than the whole level").And.Message.Contains("check the rig's scale and its bone radii"));

        using var output = new StringWriter();
        using var error = new StringWriter();
        int code = BallisticCli.Run(["bake", "--level", RepositoryFiles.Level("pond"), "--character", spec, "--max-nodes", "20", "--out", Path.Combine(_folder, "x.roadmap")], output, error);
        Assert.That(code, Is.EqualTo(ExitCode.Input), error.ToString());
        Assert.That(error.ToString().TrimEnd().Split('\n'), Has.Length.EqualTo(1));
        Assert.That(error.ToString(), Does.Contain("can stand nowhere on"));
        Assert.That(File.Exists(Path.Combine(_folder, "x.roadmap")), Is.False);
    }

    [Test]
    public void ASampleOfATrunkNearlyAsLargeAsTheLevelStopsAtItsWorkBound()
    {
        (CharacterModel _, ReducedCharacter reduced) = CharacterSpecFile.Load(Path.Combine(_folder, "frog.glb"), Frog(3f));
        Level pond = SharedLevels.Bundled("pond");
        PlanningScene scene = PlanningScene.Create(pond, reduced);
        PoseEvaluation? pose = scene.Sampler.Sample(new Random(5), out long work);
        Assert.That(pose, Is.Null, "a 6 m trunk stands nowhere on the pond");

        // One attempt overlaps at most every triangle at each repair step, so the bound is passed by one attempt at most.
        long oneAttempt = (long)pond.Triangles.Count * (scene.Sampler.Settings.RepairSteps + 1);
        Assert.That(work, Is.GreaterThan(TrunkSampler.MaxSampleWork).And.LessThanOrEqualTo(TrunkSampler.MaxSampleWork + oneAttempt),
            $"triangles overlapped by one sample's repairs (1,000 attempts would overlap about {1000 * oneAttempt:N0})");

        BakeResult bake = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 2, MaxNodes = 20, Threads = 1 });
        Assert.That((bake.Status, bake.Roadmap.Nodes.Count), Is.EqualTo((PlannerStatus.NoPath, 0)));
        Assert.That(bake.Reason, Does.Contain("no valid root pose found in the last").And.Contain("samples"));
    }
}
