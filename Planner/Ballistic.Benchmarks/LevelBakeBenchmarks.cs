using Ballistic.Authoring.Characters;
using Ballistic.Planner.Planning;
using BenchmarkDotNet.Attributes;

namespace Ballistic.Benchmarks;

/// <summary>
/// Whole-level bakes of 1,000 nodes with walks and jumps, seed 1, on one thread and on one thread per core, on each
/// bundled level with a character that crosses it (issue 23's whole-level bake figures; the roadmap is the same on any
/// number of threads): the jumperman's long, fast rooftop leaps are the trunk sweep's heaviest work.
/// </summary>
[MemoryDiagnoser]
[MedianColumn]
public class LevelBakeBenchmarks
{
    private PlanningScene _scene = null!;

    /// <summary>Level and character, as "level/character".</summary>
    [Params("desert/skeleton", "gap-course/skeleton", "pond/frog", "rooftops/jumperman")]
    public string Case { get; set; } = "";

    /// <summary>Bake threads: 1, or 0 for one per core.</summary>
    [Params(1, 0)]
    public int Threads { get; set; }

    /// <summary>Loads the level and builds the character's scene.</summary>
    [GlobalSetup]
    public void Setup()
    {
        string[] parts = Case.Split('/');
        _scene = PlanningScene.Create(BundledLevels.Load(parts[0]), CharacterPresets.Get(parts[1]));
    }

    /// <summary>A bake of 1,000 nodes; the edges it made.</summary>
    [Benchmark]
    public int Bake() =>
        new RoadmapBaker(_scene).Bake(new BakeSettings { Locomotion = Locomotion.WalkAndJump, Seed = 1, MaxNodes = 1_000, Threads = Threads > 0 ? Threads : Environment.ProcessorCount }).Roadmap.Edges.Count;
}
