using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Authoring.Levels;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using BenchmarkDotNet.Attributes;

namespace Ballistic.Benchmarks;

/// <summary>
/// The planner's stages on the generated desert with the skeleton: a bake to the paper's 22 nodes, a query on a
/// 1,000-node roadmap, one steering call between nearby nodes, one trunk-box query against 47,636 triangles.
/// </summary>
[MemoryDiagnoser]
public class PlanningBenchmarks
{
    private PlanningScene _scene = null!;
    private RoadmapBaker _baker = null!;
    private PathQuery _query = null!;
    private (RoadmapNode A, RoadmapNode B)[] _pairs = [];
    private OrientedBox[] _boxes = [];
    private (Vector3 From, Vector3 To)[] _requests = [];
    private int _next;

    /// <summary>Builds the desert scene, a 1,000-node roadmap, nearby node pairs and trunk boxes.</summary>
    [GlobalSetup]
    public void Setup()
    {
        _scene = PlanningScene.Create(LevelGenerator.BuildLevel("desert"), CharacterPresets.Skeleton());
        _baker = new RoadmapBaker(_scene);
        Roadmap roadmap = _baker.Bake(new BakeSettings { Locomotion = Locomotion.Jump, Seed = 7, MaxNodes = 1_000 }).Roadmap;
        _query = new PathQuery(_scene, roadmap);
        var random = new Random(3);
        _pairs = [.. Enumerable.Range(0, 20_000)
            .Select(_ => (roadmap.Nodes[random.Next(roadmap.Nodes.Count)], roadmap.Nodes[random.Next(roadmap.Nodes.Count)]))
            .Where(p => Vector3.Distance(p.Item1.Pose.Position, p.Item2.Pose.Position) < 6f)
            .Take(1_024)];
        _boxes = [.. roadmap.Nodes.Select(n => new OrientedBox(n.Pose.Position - new Vector3(0f, 0.3f, 0f), _scene.Character.TrunkHalfExtents, n.Pose.Rotation))];
        _requests = [.. Enumerable.Range(0, 256).Select(_ => (roadmap.Nodes[random.Next(roadmap.Nodes.Count)].Contacts[0].Position, roadmap.Nodes[random.Next(roadmap.Nodes.Count)].Contacts[0].Position))];
    }

    /// <summary>Bake to the paper's 22 nodes, one thread.</summary>
    [Benchmark]
    public int BakeDesertTo22Nodes() => _baker.Bake(new BakeSettings { Locomotion = Locomotion.Jump, Seed = 1, MaxNodes = 22, Threads = 1 }).Roadmap.Edges.Count;

    /// <summary>A start-to-goal query on the 1,000-node roadmap (projection, connection, A*).</summary>
    [Benchmark]
    public int QueryOn1000Nodes()
    {
        (Vector3 from, Vector3 to) = _requests[_next++ % _requests.Length];
        return _query.Plan(from, to).Jumps.Count;
    }

    /// <summary>One steering call between nodes less than 6 m apart, collision checks included.</summary>
    [Benchmark(OperationsPerInvoke = 1_024)]
    public int SteerNearbyPair()
    {
        int valid = 0;
        foreach ((RoadmapNode a, RoadmapNode b) in _pairs)
        {
            valid += _scene.Steering.Steer(a.Pose, a.Cone, b.Pose, b.Cone).Succeeded ? 1 : 0;
        }

        return valid;
    }

    /// <summary>One trunk-box query against the desert's BVH.</summary>
    [Benchmark(OperationsPerInvoke = 1_000)]
    public int TrunkBoxQuery()
    {
        int hits = 0;
        for (int i = 0; i < 1_000; i++)
        {
            hits += _scene.Bvh.Overlaps(_boxes[i % _boxes.Length]) ? 1 : 0;
        }

        return hits;
    }
}
