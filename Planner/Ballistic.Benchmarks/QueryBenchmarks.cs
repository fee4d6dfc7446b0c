using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using BenchmarkDotNet.Attributes;

namespace Ballistic.Benchmarks;

/// <summary>Path queries on a 1,000-node roadmap of the bundled desert with the skeleton (seed 7).</summary>
[MemoryDiagnoser]
[MedianColumn]
public class QueryBenchmarks
{
    private PathQuery _query = null!;
    private (Vector3 From, Vector3 To)[] _points = [];
    private int _next;

    /// <summary>Bakes the roadmap and draws 256 requests between random nodes' first contacts.</summary>
    [GlobalSetup]
    public void Setup()
    {
        var scene = PlanningScene.Create(BundledLevels.Load("desert"), CharacterPresets.Skeleton());
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 7, MaxNodes = 1_000 }).Roadmap;
        _query = new PathQuery(scene, roadmap);
        var random = new Random(3);
        _points = [.. Enumerable.Range(0, 256).Select(_ => (roadmap.Nodes[random.Next(roadmap.Nodes.Count)].Contacts[0].Position, roadmap.Nodes[random.Next(roadmap.Nodes.Count)].Contacts[0].Position))];
    }

    /// <summary>From a point to a point: both endpoints placed and steered into the roadmap, then A*.</summary>
    [Benchmark]
    public int PointToPoint()
    {
        (Vector3 from, Vector3 to) = _points[_next++ % _points.Length];
        return _query.Plan(from, to).Jumps.Count;
    }
}
