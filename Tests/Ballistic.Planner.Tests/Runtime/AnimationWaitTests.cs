using Ballistic.Planner.Animation;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>
/// A tick waits for late animations at most <see cref="WorldSettings.MaxAnimationWait"/> where one is set (the Godot
/// server's host sets one): on a starved machine the game hitches, it does not freeze (before: the wait blocked one
/// tick for 29 s with 200 requests at once).
/// </summary>
public sealed class AnimationWaitTests
{
    private const int Latency = 2;

    /// <summary>An animator that animates nothing until the test lets it: an animation as late as the test wants.</summary>
    private sealed class GatedAnimator(IJumpAnimator inner, ManualResetEventSlim gate) : IJumpAnimator
    {
        public JumpAnimation Animate(IReadOnlyList<Move> moves, float frameRate = 60f)
        {
            gate.Wait();
            return inner.Animate(moves, frameRate);
        }

        public bool CanStand(PoseEvaluation pose) => inner.CanStand(pose);
    }

    /// <summary>An animator whose first call animates nothing until the test lets it; it notes the threads that call it.</summary>
    private sealed class FirstGatedAnimator(IJumpAnimator inner, ManualResetEventSlim gate) : IJumpAnimator
    {
        private int _calls;

        public System.Collections.Concurrent.ConcurrentBag<int> Threads { get; } = [];

        public JumpAnimation Animate(IReadOnlyList<Move> moves, float frameRate = 60f)
        {
            Threads.Add(Environment.CurrentManagedThreadId);
            if (Interlocked.Increment(ref _calls) == 1)
            {
                gate.Wait();
            }

            return inner.Animate(moves, frameRate);
        }

        public bool CanStand(PoseEvaluation pose) => inner.CanStand(pose);
    }

    private static (JumpWorld World, AgentHandle Agent) Start(ManualResetEventSlim gate, TimeSpan? wait)
    {
        CharacterKind desert = RuntimeWorlds.DesertSkeleton;
        var kind = new CharacterKind(desert.Scene, desert.Roadmap, desert.Animator, new GatedAnimator(new SimpleMoveAnimator(desert.Animator), gate));
        var world = new JumpWorld(desert.Scene.Level, RuntimeWorlds.JumpOnly with { AnimationThreads = 1, PathLatencyTicks = Latency, MaxAnimationWait = wait });
        KindHandle handle = world.AddKind(kind).Kind;
        (RoadmapNode from, RoadmapNode to) = RuntimeWorlds.ConnectedPairs(desert.Roadmap, 1, seed: 57)[0];
        AgentHandle agent = world.AddAgent(handle, RuntimeWorlds.Point(from)).Agent;
        Assert.That(world.SetTarget(agent, RuntimeWorlds.Point(to)).Ok, Is.True);
        return (world, agent);
    }

    /// <summary>
    /// A bare world waits as long as it takes (a loop stepping as fast as it can, like a test or the CI's game program,
    /// must not outrun its animations); the Godot server's world, stepped in real time, bounds the wait.
    /// </summary>
    [Test]
    public void ABareWorldWaitsWhileTheRealTimeServerBoundsTheWait()
    {
        Assert.That(new WorldSettings().MaxAnimationWait, Is.Null);
        Assert.That(WorldSettings.RealTime.MaxAnimationWait, Is.EqualTo(WorldSettings.RealTimeAnimationWait));
        Assert.That(WorldSettings.RealTime with { MaxAnimationWait = null }, Is.EqualTo(new WorldSettings()), "otherwise the defaults");
        string server = File.ReadAllText(Path.Combine(Support.RepositoryFiles.Root, "addons", "ballistic", "Nodes", "JumpNavigationServer.cs"));
        Assert.That(server, Does.Contain("new(WorldSettings.RealTime)"), "the Godot server's world is made with them");
        Assert.That(new WorldSettings { MaxAnimationWait = TimeSpan.Zero }.Problem(), Does.Contain("MaxAnimationWait must be positive"));
    }

    [Test]
    public void ALateAnimationStopsTheWaitAtTheLimitAndArrivesWhenReady()
    {
        using var gate = new ManualResetEventSlim(false);
        (JumpWorld world, AgentHandle agent) = Start(gate, TimeSpan.FromMilliseconds(50));
        using (world)
        {
            var found = new List<long>();
            var longest = TimeSpan.Zero;
            for (int tick = 0; tick <= Latency + 2; tick++)
            {
                long before = System.Diagnostics.Stopwatch.GetTimestamp();
                world.Step();
                longest = TimeSpan.FromTicks(Math.Max(longest.Ticks, System.Diagnostics.Stopwatch.GetElapsedTime(before).Ticks));
                found.AddRange(world.Events.ToArray().Where(e => e.Kind == JumpEventKind.PathFound).Select(e => e.Tick));
            }

            Assert.That(found, Is.Empty, "no path while its animation is held back");
            Assert.That(world.LateRequests, Is.EqualTo(1), "the request is counted late once");
            Assert.That(world.IsPathPending(agent), Is.True, "still pending, not dropped");
            Assert.That(longest, Is.LessThan(TimeSpan.FromSeconds(5)), "no tick waited for the held animation (the limit is 50 ms; the bound leaves room for a loaded machine)");

            // Ticks until the released job ends: on a loaded machine (fixtures run two at a time) that may take longer
            // than 600 ticks of a millisecond, so the bound is wall-clock time.
            gate.Set();
            var released = System.Diagnostics.Stopwatch.StartNew();
            while (found.Count == 0 && released.Elapsed < TimeSpan.FromSeconds(30))
            {
                world.Step();
                found.AddRange(world.Events.ToArray().Where(e => e.Kind == JumpEventKind.PathFound).Select(e => e.Tick));
                Thread.Sleep(1);
            }

            Assert.That(found, Has.Count.EqualTo(1), "the late path arrives once its animation is ready");
            Assert.That(world.GetPath(agent), Is.Not.Null);
            Assert.That(world.LateRequests, Is.EqualTo(1));
        }
    }

    /// <summary>
    /// Without a limit the waiting tick thread works instead of idling (the 20-agent desert playtest went from 61 to
    /// 48 s on two cores): one background thread is held on the first request's animation, and the tick, due for both
    /// requests, solves a request no background thread has started itself; both paths arrive on their due tick, the
    /// same as solved anywhere.
    /// </summary>
    [Test]
    public void WithoutALimitTheWaitingTickThreadSolvesRequestsNoBackgroundThreadStarted()
    {
        using var gate = new ManualResetEventSlim(false);
        CharacterKind desert = RuntimeWorlds.DesertSkeleton;
        var animator = new FirstGatedAnimator(new SimpleMoveAnimator(desert.Animator), gate);
        var kind = new CharacterKind(desert.Scene, desert.Roadmap, desert.Animator, animator);
        using var world = new JumpWorld(desert.Scene.Level, RuntimeWorlds.JumpOnly with { AnimationThreads = 1, PathLatencyTicks = Latency, MaxAnimationWait = null });
        KindHandle handle = world.AddKind(kind).Kind;
        foreach ((RoadmapNode from, RoadmapNode to) in RuntimeWorlds.ConnectedPairs(desert.Roadmap, 2, seed: 57))
        {
            AgentHandle agent = world.AddAgent(handle, RuntimeWorlds.Point(from)).Agent;
            Assert.That(world.SetTarget(agent, RuntimeWorlds.Point(to)).Ok, Is.True);
        }

        var found = new List<long>();
        long started = world.Tick + 1;
        int tickThread = Environment.CurrentManagedThreadId;
        using var release = new Timer(_ => gate.Set(), null, 300, Timeout.Infinite);
        for (int tick = 0; tick <= Latency + 1; tick++)
        {
            world.Step();
            found.AddRange(world.Events.ToArray().Where(e => e.Kind == JumpEventKind.PathFound).Select(e => e.Tick));
        }

        Assert.That(found, Is.EqualTo(new[] { started + Latency, started + Latency }), "both delivered on their due tick");
        Assert.That(animator.Threads, Has.Count.EqualTo(2), "each path animated once");
        Assert.That(animator.Threads, Does.Contain(tickThread), "the waiting tick thread solved one of them");
        Assert.That(world.LateRequests, Is.Zero);
    }

    [Test]
    public void WithoutALimitTheDueTickWaitsAndThePathStartsExactlyOnTime()
    {
        using var gate = new ManualResetEventSlim(false);
        (JumpWorld world, AgentHandle _) = Start(gate, wait: null);
        using (world)
        {
            var found = new List<long>();
            long started = world.Tick + 1;
            using var release = new Timer(_ => gate.Set(), null, 300, Timeout.Infinite);
            for (int tick = 0; tick <= Latency + 1; tick++)
            {
                world.Step();
                found.AddRange(world.Events.ToArray().Where(e => e.Kind == JumpEventKind.PathFound).Select(e => e.Tick));
            }

            Assert.That(found, Is.EqualTo(new[] { started + Latency }), "delivered on its due tick, however late its animation");
            Assert.That(world.LateRequests, Is.Zero);
        }
    }
}
