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
using Ballistic.Runtime.Paths;
using BenchmarkDotNet.Attributes;

namespace Ballistic.Benchmarks;

/// <summary>
/// The runtime's systems on the generated desert with the skeleton (39 degrees of freedom) and a 1,000-node roadmap:
/// one tick of 1,000 agents spread along their paths (walking and jumping, or jumping only), the pose fill of 100
/// agents, serving 100 path requests under a budget of 25 searches per tick, and the tick in which 50 path requests start while 1,000 agents move (the requests
/// run in the background, or on the tick thread: whole, or in slices under the default planning budget).
/// </summary>
/// <remarks>
/// The agents follow 20 distinct long paths (each shared by 50 agents, as agents sent between the same stances share
/// one animation): a tick reads each agent's own path and clock whichever path it is, and the setup animates 20 paths
/// once for all the benchmarks of the process instead of 200 per benchmark (which took more than 14 minutes).
/// </remarks>
[MemoryDiagnoser]
[MedianColumn]
[MaxColumn]
public class RuntimeBenchmarks
{
    /// <summary>Distinct start/goal pairs the agents are sent between.</summary>
    private const int Pairs = 20;

    /// <summary>The kind and the pairs, made once per process (BenchmarkDotNet's in-process runs share them).</summary>
    private static readonly Lazy<(CharacterKind Kind, List<(RoadmapNode From, RoadmapNode To)> Pairs)> Shared = new(() =>
    {
        var scene = PlanningScene.Create(LevelGenerator.BuildLevel("desert"), CharacterPresets.Skeleton());
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Locomotion = Locomotion.Jump, Seed = 7, MaxNodes = 1_000 }).Roadmap;
        var kind = new CharacterKind(scene, roadmap, new JumpAnimator(scene, CharacterPresets.Model("skeleton")));
        var random = new Random(5);
        var pairs = new List<(RoadmapNode From, RoadmapNode To)>();
        while (pairs.Count < Pairs)
        {
            RoadmapNode a = roadmap.Nodes[random.Next(roadmap.Nodes.Count)];
            RoadmapNode b = roadmap.Nodes[random.Next(roadmap.Nodes.Count)];
            if (Vector3.Distance(a.Pose.Position, b.Pose.Position) > 12f && roadmap.Reaches(a.Id, b.Id))
            {
                pairs.Add((a, b));
            }
        }

        return (kind, pairs);
    });

    private CharacterKind _kind = null!;
    private JumpWorld? _crowd;
    private JumpWorld _posed = null!;
    private JumpWorld _busy = null!;
    private JumpWorld? _requests;
    private List<(RoadmapNode From, RoadmapNode To)> _pairs = null!;
    private readonly List<AgentHandle> _askers = [];
    private JumpWorld _inline = null!;
    private JumpWorld _inlineWhole = null!;
    private readonly List<AgentHandle> _inlineAskers = [];
    private readonly List<AgentHandle> _inlineWholeAskers = [];
    private int _round;

    /// <summary>Bakes the roadmap (once) and sends 1,000 + 100 + 1,000 agents along long paths (every path animated before measuring).</summary>
    [GlobalSetup]
    public void Setup()
    {
        (_kind, _pairs) = Shared.Value;

        // A fast tick rate keeps every agent mid-path for the whole measurement; a tick's cost does not depend on it.
        _posed = Moving(100, poses: true, new WorldSettings { TickRate = 10_000, MaxSearchesPerTick = 1_000, AnimationThreads = 2 }, out _);

        // The default budget (MaxSearchesPerTick 16) and one background thread; 50 more agents stand, to be sent off.
        _busy = Moving(1_000, poses: false, new WorldSettings { TickRate = 10_000, AnimationThreads = 1 }, out KindHandle kind);
        AddAskers(_busy, kind, _askers);

        // The same on the tick thread (no background threads): requests advanced in slices under the default planning
        // budget (WorldSettings.PlanningTimePerTick, 2 ms), and solved whole on the tick they start (no budget).
        _inline = Moving(1_000, poses: false, new WorldSettings { TickRate = 10_000, AnimationThreads = 0 }, out kind);
        AddAskers(_inline, kind, _inlineAskers);
        _inlineWhole = Moving(1_000, poses: false, new WorldSettings { TickRate = 10_000, AnimationThreads = 0, PlanningTimePerTick = null }, out kind);
        AddAskers(_inlineWhole, kind, _inlineWholeAskers);
    }

    /// <summary>Adds 50 standing agents to <paramref name="world"/>, one on each pair's start in turn, to be sent off.</summary>
    private void AddAskers(JumpWorld world, KindHandle kind, List<AgentHandle> askers)
    {
        for (int i = 0; i < 50; i++)
        {
            askers.Add(world.AddAgent(kind, _kind.Roadmap.ContactCentres[_pairs[i % _pairs.Count].From.Id]).Agent);
        }
    }

    /// <summary>
    /// A world with <paramref name="count"/> agents following the pairs' paths: the first agent of each pair searched
    /// and animated, the others given the same moves (no search; the animation shared), every path animated before
    /// it returns.
    /// </summary>
    private JumpWorld Moving(int count, bool poses, WorldSettings settings, out KindHandle kind)
    {
        var world = new JumpWorld(_kind.Scene.Level, settings);
        kind = world.AddKind(_kind).Kind;
        var agents = new List<AgentHandle>();
        for (int i = 0; i < count; i++)
        {
            (RoadmapNode from, RoadmapNode to) = _pairs[i % _pairs.Count];
            AgentHandle agent = world.AddAgent(kind, _kind.Roadmap.ContactCentres[from.Id]).Agent;
            world.SetPoseEnabled(agent, poses);
            if (i < _pairs.Count)
            {
                world.SetTarget(agent, _kind.Roadmap.ContactCentres[to.Id]);
            }

            agents.Add(agent);
        }

        Settle(world);
        _moves ??= [.. agents.Take(_pairs.Count).Select(a => world.GetPath(a)?.Moves.Select(m => m.ToMove()).ToList()
            ?? throw new InvalidOperationException("A benchmark pair found no path."))];
        _shortest = MathF.Min(_shortest, agents.Take(_pairs.Count).Min(a => world.GetPath(a)!.Duration));
        for (int i = _pairs.Count; i < count; i++)
        {
            world.PerformMoves(agents[i], _moves[i % _pairs.Count]);
        }

        Settle(world);
        return world;
    }

    /// <summary>The pairs' paths as moves (from the first world made), and the shortest path's duration, seconds.</summary>
    private List<List<Move>>? _moves;
    private float _shortest = float.PositiveInfinity;

    /// <summary>
    /// A 60 Hz world of 1,000 agents spread along the pairs' paths: sent off in 50 waves of one agent per pair, the
    /// waves spaced over most of the shortest path's duration, so that the agents are at every phase of their paths
    /// (standing between moves, walking, taking off, flying, landing) when the tick is measured; every path animated
    /// before it returns. The same world every time it is made.
    /// </summary>
    private JumpWorld Staggered(Locomotion locomotion, List<List<Move>> moves, float shortest)
    {
        var world = new JumpWorld(_kind.Scene.Level, new WorldSettings { MaxSearchesPerTick = 1_000, AnimationThreads = 2, Locomotion = locomotion });
        KindHandle kind = world.AddKind(_kind).Kind;
        var agents = new List<AgentHandle>();
        for (int i = 0; i < CrowdSize; i++)
        {
            AgentHandle agent = world.AddAgent(kind, _kind.Roadmap.ContactCentres[_pairs[i % _pairs.Count].From.Id]).Agent;
            world.SetPoseEnabled(agent, false);
            agents.Add(agent);
        }

        int waves = CrowdSize / _pairs.Count;
        int ticksApart = Math.Max(1, (int)(0.9f * shortest / waves * world.Settings.TickRate));
        for (int wave = 0; wave < waves; wave++)
        {
            for (int p = 0; p < _pairs.Count; p++)
            {
                world.PerformMoves(agents[(wave * _pairs.Count) + p], moves[p]);
            }

            for (int tick = 0; tick < ticksApart; tick++)
            {
                world.Step();
            }
        }

        return world;
    }

    /// <summary>Agents in the crowd whose tick is measured.</summary>
    private const int CrowdSize = 1_000;

    /// <summary>Steps <paramref name="world"/> until no request waits or animates.</summary>
    private static void Settle(JumpWorld world)
    {
        while (world.QueuedRequests > 0 || world.AnimatingRequests > 0)
        {
            world.Step();
        }
    }

    /// <summary>The crowd made anew (<see cref="Staggered"/>): every iteration measures the same tick of the same world.</summary>
    [IterationSetup(Target = nameof(TickThousandAgents))]
    public void SpreadCrowd() => MakeCrowd(Locomotion.WalkAndJump, _moves!, _shortest);

    /// <summary>The crowd made anew on jump-only paths (<see cref="Staggered"/>).</summary>
    [IterationSetup(Target = nameof(TickThousandJumpingAgents))]
    public void SpreadJumpingCrowd()
    {
        SearchJumpOnlyPaths();
        MakeCrowd(Locomotion.Jump, _jumpMoves!, _jumpShortest);
    }

    /// <summary>
    /// A 1,000 Hz world of 1,000 agents sent off together on the pairs' jump-only paths, 50 on each (the mix of the
    /// first runtime benchmark, 2026-11-21: every agent at the same phase of one of 20 paths), its paths delivered.
    /// </summary>
    [IterationSetup(Target = nameof(TickThousandAgentsSentTogether))]
    public void SendCrowdTogether()
    {
        SearchJumpOnlyPaths();
        _crowd?.Dispose();
        _crowd = new JumpWorld(_kind.Scene.Level, new WorldSettings { TickRate = 1_000, MaxSearchesPerTick = 1_000, AnimationThreads = 2, Locomotion = Locomotion.Jump });
        KindHandle kind = _crowd.AddKind(_kind).Kind;
        for (int i = 0; i < CrowdSize; i++)
        {
            AgentHandle agent = _crowd.AddAgent(kind, _kind.Roadmap.ContactCentres[_pairs[i % _pairs.Count].From.Id]).Agent;
            _crowd.SetPoseEnabled(agent, false);
            _crowd.PerformMoves(agent, _jumpMoves![i % _pairs.Count]);
        }

        Settle(_crowd);
        CollectGarbage();
    }

    /// <summary>
    /// The mean tick over the first 7 s of <see cref="SendCrowdTogether"/>'s world (7,000 ticks at 1,000 Hz: takeoff
    /// crouches, flights, landings and stances, all agents of a path at the same phase): today's code on the mix the
    /// README's first runtime figure (78 µs, 2026-11-21) was measured on, before walks and body points.
    /// </summary>
    [Benchmark(OperationsPerInvoke = TogetherTicks)]
    public void TickThousandAgentsSentTogether() => StepCrowd(TogetherTicks);

    /// <summary>Ticks measured per iteration of <see cref="TickThousandAgentsSentTogether"/>: 7 s at 1,000 Hz.</summary>
    private const int TogetherTicks = 7_000;

    /// <summary>Searches and animates the pairs' jump-only paths, once.</summary>
    private void SearchJumpOnlyPaths()
    {
        if (_jumpMoves is null)
        {
            // The pairs' jump-only paths, searched and animated once.
            using var world = new JumpWorld(_kind.Scene.Level, new WorldSettings { MaxSearchesPerTick = 1_000, AnimationThreads = 2, Locomotion = Locomotion.Jump });
            KindHandle kind = world.AddKind(_kind).Kind;
            var agents = _pairs.Select(pair => world.AddAgent(kind, _kind.Roadmap.ContactCentres[pair.From.Id]).Agent).ToList();
            for (int i = 0; i < agents.Count; i++)
            {
                world.SetTarget(agents[i], _kind.Roadmap.ContactCentres[_pairs[i].To.Id]);
            }

            Settle(world);
            List<AgentPath> paths = [.. agents.Select(a => world.GetPath(a) ?? throw new InvalidOperationException("A benchmark pair found no jump-only path."))];
            _jumpMoves = [.. paths.Select(path => path.Moves.Select(m => m.ToMove()).ToList())];
            _jumpShortest = paths.Min(path => path.Duration);
        }
    }

    /// <summary>The pairs' jump-only paths as moves, and the shortest one's duration, seconds (made by <see cref="SearchJumpOnlyPaths"/>).</summary>
    private List<List<Move>>? _jumpMoves;
    private float _jumpShortest;

    /// <summary>The crowd's making's garbage collected now, not during the ticks measured.</summary>
    private static void CollectGarbage()
    {
        GC.Collect();
        GC.WaitForPendingFinalizers();
        GC.Collect();
    }

    /// <summary>Steps the crowd <paramref name="ticks"/> times.</summary>
    private void StepCrowd(int ticks)
    {
        for (int i = 0; i < ticks; i++)
        {
            _crowd!.Step();
        }
    }

    private void MakeCrowd(Locomotion locomotion, List<List<Move>> moves, float shortest)
    {
        _crowd?.Dispose();
        _crowd = Staggered(locomotion, moves, shortest);
        CollectGarbage();
    }

    /// <summary>
    /// One 60 Hz tick of 1,000 agents spread along their paths (locomotion, body points and events; poses off): the
    /// mean of the second of ticks that follows the crowd's making (a tick alone would measure caches the making left
    /// cold).
    /// </summary>
    [Benchmark(OperationsPerInvoke = TicksMeasured)]
    public void TickThousandAgents() => StepCrowd(TicksMeasured);

    /// <summary>
    /// <see cref="TickThousandAgents"/> on jump-only paths (the world's <see cref="WorldSettings.Locomotion"/> is
    /// <see cref="Locomotion.Jump"/>: every move a jump, as every path was before walks): the agents stand, crouch, fly
    /// and absorb their landings, and none walks.
    /// </summary>
    [Benchmark(OperationsPerInvoke = TicksMeasured)]
    public void TickThousandJumpingAgents() => StepCrowd(TicksMeasured);

    /// <summary>Ticks measured per iteration of <see cref="TickThousandAgents"/>: a second at 60 Hz.</summary>
    private const int TicksMeasured = 60;

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

    /// <summary>
    /// The 50 standing agents of the busy world are each sent to the end of their pair (50 requests queued: each is
    /// searched anew, its animation the one the crowd's agents share).
    /// </summary>
    [IterationSetup(Target = nameof(TickStartingRequests))]
    public void SendFifty() => Send(_busy, _askers);

    private void Send(JumpWorld world, List<AgentHandle> askers)
    {
        for (int i = 0; i < askers.Count; i++)
        {
            world.SetTarget(askers[i], _kind.Roadmap.ContactCentres[_pairs[i % _pairs.Count].To.Id]);
        }
    }

    /// <summary>
    /// One tick of 1,000 moving agents in which path requests start, under the default budget (16 searches started;
    /// the searches and animations run on the background thread). The worst such tick is the Max column.
    /// </summary>
    [Benchmark]
    public void TickStartingRequests() => _busy.Step();

    /// <summary>The 50 agents' requests are let finish; each is put back on its start, without a target.</summary>
    [IterationCleanup(Target = nameof(TickStartingRequests))]
    public void SettleFifty() => Return(_busy, _askers);

    private void Return(JumpWorld world, List<AgentHandle> askers)
    {
        Settle(world);
        for (int i = 0; i < askers.Count; i++)
        {
            world.ClearTarget(askers[i]);
            world.Warp(askers[i], _kind.Roadmap.ContactCentres[_pairs[i % _pairs.Count].From.Id]);
        }
    }

    /// <summary>The 50 standing agents of the sliced on-tick world are sent off, and its first tick taken (the requests started).</summary>
    [IterationSetup(Target = nameof(TickAdvancingRequestsInSlices))]
    public void SendFiftyInline()
    {
        Send(_inline, _inlineAskers);
        _inline.Step();
    }

    /// <summary>
    /// One tick of 1,000 moving agents on the tick thread while 16 started requests are advanced in slices under the
    /// default planning budget (2 ms), the tick after they started (none due yet). The worst such tick is the Max column.
    /// </summary>
    [Benchmark]
    public void TickAdvancingRequestsInSlices() => _inline.Step();

    /// <summary>The sliced on-tick world's requests are let finish and the agents put back.</summary>
    [IterationCleanup(Target = nameof(TickAdvancingRequestsInSlices))]
    public void SettleFiftyInline() => Return(_inline, _inlineAskers);

    /// <summary>The 50 standing agents of the sliced on-tick world are sent off, and the ticks before the first requests' due tick taken.</summary>
    [IterationSetup(Target = nameof(TickFinishingRequestsOnTheirDueTick))]
    public void SendFiftyInlineToTheirDueTick()
    {
        Send(_inline, _inlineAskers);
        for (int i = 0; i < _inline.Settings.PathLatencyTicks; i++)
        {
            _inline.Step();
        }
    }

    /// <summary>
    /// The due tick of the 16 requests started first in the sliced on-tick world: what their slices left is finished
    /// here (deterministic arrival, <see cref="WorldSettings.WaitForAnimation"/>), so the work the budget spread is
    /// paid on this tick unless the slices before it covered it.
    /// </summary>
    [Benchmark]
    public void TickFinishingRequestsOnTheirDueTick() => _inline.Step();

    /// <summary>The sliced on-tick world's requests are let finish and the agents put back.</summary>
    [IterationCleanup(Target = nameof(TickFinishingRequestsOnTheirDueTick))]
    public void SettleFiftyInlineAfterTheirDueTick() => Return(_inline, _inlineAskers);

    /// <summary>The 50 standing agents of the whole-request on-tick world are sent off.</summary>
    [IterationSetup(Target = nameof(TickSolvingRequestsWhole))]
    public void SendFiftyWhole() => Send(_inlineWhole, _inlineWholeAskers);

    /// <summary>
    /// One tick of 1,000 moving agents on the tick thread in which 16 requests start and are solved whole (no planning
    /// budget): what a tick cost on the tick thread before requests were sliced.
    /// </summary>
    [Benchmark]
    public void TickSolvingRequestsWhole() => _inlineWhole.Step();

    /// <summary>The whole-request on-tick world's requests are let finish and the agents put back.</summary>
    [IterationCleanup(Target = nameof(TickSolvingRequestsWhole))]
    public void SettleFiftyWhole() => Return(_inlineWhole, _inlineWholeAskers);

    /// <summary>Stops the worlds.</summary>
    [GlobalCleanup]
    public void Cleanup()
    {
        _crowd?.Dispose();
        _posed.Dispose();
        _busy.Dispose();
        _inline.Dispose();
        _inlineWhole.Dispose();
    }
}
