using Ballistic.Authoring.Characters;
using Ballistic.Planner.Planning;
using BenchmarkDotNet.Attributes;

namespace Ballistic.Benchmarks;

/// <summary>
/// Large bakes on the bundled rooftops with the skeleton, on every core: at 20,000 nodes the search for each new
/// node's neighbours matters next to the steering calls.
/// </summary>
[MemoryDiagnoser]
[MedianColumn]
public class BakeBenchmarks
{
    private PlanningScene _scene = null!;

    /// <summary>Nodes of the bake.</summary>
    [Params(2_000, 20_000)]
    public int Nodes { get; set; }

    /// <summary>Loads the rooftops and builds the skeleton's scene.</summary>
    [GlobalSetup]
    public void Setup() => _scene = PlanningScene.Create(BundledLevels.Load("rooftops"), CharacterPresets.Skeleton());

    /// <summary>A bake of <see cref="Nodes"/> nodes, seed 1, one thread per core.</summary>
    [Benchmark]
    public int BakeRooftops() =>
        new RoadmapBaker(_scene).Bake(new BakeSettings { Locomotion = Locomotion.Jump, Seed = 1, MaxNodes = Nodes, Threads = Environment.ProcessorCount }).Roadmap.Edges.Count;
}
