using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;
using BenchmarkDotNet.Attributes;

namespace Ballistic.Benchmarks;

/// <summary>
/// Path queries on a 1,000-node jump roadmap (seed 7) of the bundled desert with the skeleton and of the rooftops with
/// the jumperman: from point to point (placement, steering into the roadmap, A*), between roadmap nodes (A* alone),
/// from a node to a point, and the lookup of a roadmap node near a point. Each invocation takes the next of 256 fixed
/// random requests.
/// </summary>
[MemoryDiagnoser]
[MedianColumn]
public class QueryBenchmarks
{
    private Roadmap _roadmap = null!;
    private PathQuery _query = null!;
    private (Vector3 From, Vector3 To)[] _points = [];
    private (RoadmapNode From, RoadmapNode To)[] _nodes = [];
    private int _next;

    private static readonly QuerySettings PreferNodes = new() { PreferRoadmapNodes = true, Locomotion = Locomotion.Jump };
    private static readonly QuerySettings JumpOnly = new() { Locomotion = Locomotion.Jump };

    /// <summary>Level and character, as "level/character".</summary>
    [Params("desert/skeleton", "rooftops/jumperman")]
    public string Case { get; set; } = "desert/skeleton";

    /// <summary>Bakes the roadmap and draws 256 requests between random nodes (and their first contacts).</summary>
    [GlobalSetup]
    public void Setup()
    {
        string[] parts = Case.Split('/');
        var scene = PlanningScene.Create(BundledLevels.Load(parts[0]), CharacterPresets.Get(parts[1]));
        _roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Locomotion = Locomotion.Jump, Seed = 7, MaxNodes = 1_000 }).Roadmap;
        _query = new PathQuery(scene, _roadmap);
        var random = new Random(3);
        _points = [.. Enumerable.Range(0, 256).Select(_ => (_roadmap.Nodes[random.Next(_roadmap.Nodes.Count)].Contacts[0].Position, _roadmap.Nodes[random.Next(_roadmap.Nodes.Count)].Contacts[0].Position))];
        _nodes = [.. Enumerable.Range(0, 256).Select(_ => (_roadmap.Nodes[random.Next(_roadmap.Nodes.Count)], _roadmap.Nodes[random.Next(_roadmap.Nodes.Count)]))];
    }

    /// <summary>From a point to a point: both endpoints placed and steered into the roadmap, then A*.</summary>
    [Benchmark]
    public int PointToPoint()
    {
        (Vector3 from, Vector3 to) = _points[_next++ % _points.Length];
        return _query.Plan(from, to, JumpOnly).Jumps.Count;
    }

    /// <summary>From a point to a point, taking a roadmap node standing close enough instead of placing a stance (<see cref="QuerySettings.PreferRoadmapNodes"/>).</summary>
    [Benchmark]
    public int PointToPointPreferringNodes()
    {
        (Vector3 from, Vector3 to) = _points[_next++ % _points.Length];
        return _query.Plan(from, to, PreferNodes).Jumps.Count;
    }

    /// <summary>Between two roadmap nodes: A* over the roadmap alone.</summary>
    [Benchmark]
    public int NodeToNode()
    {
        (RoadmapNode from, RoadmapNode to) = _nodes[_next++ % _nodes.Length];
        return _query.Plan(from, to, JumpOnly).Jumps.Count;
    }

    /// <summary>From a roadmap node to a point: the goal placed and steered into the roadmap, then A*.</summary>
    [Benchmark]
    public int NodeToPoint()
    {
        int k = _next++ % _nodes.Length;
        return _query.Plan(_nodes[k].From, _points[k].To, JumpOnly).Jumps.Count;
    }

    /// <summary>The roadmap node standing nearest a point within the default endpoint tolerance.</summary>
    [Benchmark]
    public int? FindNode() => _roadmap.FindNode(_points[_next++ % _points.Length].To, new EndpointTolerance());
}
