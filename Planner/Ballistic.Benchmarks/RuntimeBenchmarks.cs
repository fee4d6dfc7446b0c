using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Authoring.Levels;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Kinds;
using BenchmarkDotNet.Attributes;

namespace Ballistic.Benchmarks;

/// <summary>
/// The runtime's systems on the generated desert with the skeleton (39 degrees of freedom) and a 1,000-node roadmap:
/// one tick of 1,000 agents in stance or flight, the pose fill of 100 agents, and serving 100 path requests under a
/// budget of 25 searches per tick.
/// </summary>
[MemoryDiagnoser]
[MedianColumn]
public class RuntimeBenchmarks
{
    private CharacterKind _kind = null!;
    private JumpWorld _crowd = null!;
    private JumpWorld _posed = null!;
    private JumpWorld? _requests;
    private readonly List<(RoadmapNode From, RoadmapNode To)> _pairs = [];
    private int _round;

    /// <summary>Bakes the roadmap and sends 1,000 + 100 agents along long paths (every path animated before measuring).</summary>
    [GlobalSetup]
    public void Setup()
    {
        var scene = PlanningScene.Create(LevelGenerator.BuildLevel("desert"), CharacterPresets.Skeleton());
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Locomotion = Locomotion.Jump, Seed = 7, MaxNodes = 1_000 }).Roadmap;
        _kind = new CharacterKind(scene, roadmap, new JumpAnimator(scene, CharacterPresets.Model("skeleton")));
        var random = new Random(5);
        while (_pairs.Count < 200)
        {
            RoadmapNode a = roadmap.Nodes[random.Next(roadmap.Nodes.Count)];
            RoadmapNode b = roadmap.Nodes[random.Next(roadmap.Nodes.Count)];
            if (Vector3.Distance(a.Pose.Position, b.Pose.Position) > 12f && roadmap.Reaches(a.Id, b.Id))
            {
                _pairs.Add((a, b));
            }
        }

        // A fast tick rate keeps every agent mid-path for the whole measurement; a tick's cost does not depend on it.
        _crowd = Moving(1_000, poses: false);
        _posed = Moving(100, poses: true);
    }

    private JumpWorld Moving(int count, bool poses)
    {
        var world = new JumpWorld(_kind.Scene.Level, new WorldSettings { TickRate = 10_000, MaxSearchesPerTick = 1_000, AnimationThreads = 2 });
        KindHandle kind = world.AddKind(_kind).Kind;
        for (int i = 0; i < count; i++)
        {
            (RoadmapNode from, RoadmapNode to) = _pairs[i % _pairs.Count];
            AgentHandle agent = world.AddAgent(kind, _kind.Roadmap.ContactCentres[from.Id]).Agent;
            world.SetPoseEnabled(agent, poses);
            world.SetTarget(agent, _kind.Roadmap.ContactCentres[to.Id]);
        }

        while (world.QueuedRequests > 0 || world.AnimatingRequests > 0)
        {
            world.Step();
        }

        return world;
    }

    /// <summary>One tick of 1,000 agents following their paths (locomotion and events; poses off).</summary>
    [Benchmark]
    public void TickThousandAgents() => _crowd.Step();

    /// <summary>The pose fill of 100 agents in flight or stance: joint angles from the animation and 39 local rotations each.</summary>
    [Benchmark]
    public void PoseFillHundredAgents() => _posed.FillPoses();

    /// <summary>A fresh world with 100 standing agents, each just given a target.</summary>
    [IterationSetup(Target = nameof(ServeHundredRequests))]
    public void QueueHundredRequests()
    {
        _requests = new JumpWorld(_kind.Scene.Level, new WorldSettings { MaxSearchesPerTick = 25, AnimationThreads = 1 });
        KindHandle kind = _requests.AddKind(_kind).Kind;
        int shift = _round++ * 7;
        for (int i = 0; i < 100; i++)
        {
            (RoadmapNode from, _) = _pairs[(i + shift) % _pairs.Count];
            (_, RoadmapNode to) = _pairs[(i + shift + 1) % _pairs.Count];
            AgentHandle agent = _requests.AddAgent(kind, _kind.Roadmap.ContactCentres[from.Id]).Agent;
            _requests.SetTarget(agent, _kind.Roadmap.ContactCentres[to.Id]);
        }
    }

    /// <summary>Ticks until 100 queued path requests are all searched, 25 per tick (their animations start in the background).</summary>
    [Benchmark]
    public int ServeHundredRequests()
    {
        int ticks = 0;
        while (_requests!.QueuedRequests > 0)
        {
            _requests.Step();
            ticks++;
        }

        return ticks;
    }

    /// <summary>Waits for the background animations of the iteration before the next one.</summary>
    [IterationCleanup(Target = nameof(ServeHundredRequests))]
    public void DropRequests() => _requests?.Dispose();

    /// <summary>Stops the worlds.</summary>
    [GlobalCleanup]
    public void Cleanup()
    {
        _crowd.Dispose();
        _posed.Dispose();
    }
}
