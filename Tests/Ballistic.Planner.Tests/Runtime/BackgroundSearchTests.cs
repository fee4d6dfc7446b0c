using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>
/// Path requests are searched off the tick (like their animation): however long a search, the tick thread only starts
/// requests and delivers outcomes, and every outcome (a path, a failure) reaches its agent exactly
/// <see cref="WorldSettings.PathLatencyTicks"/> after its start whatever the thread count.
/// </summary>
public sealed class BackgroundSearchTests
{
    [TestCase(2)]
    [TestCase(0)]
    public void WithBackgroundThreadsTheTickThreadNeverSearches(int threads)
    {
        // The desert skeleton's kind on a scene whose game validators note the threads that call them: every stance
        // and jump a search places or steers goes through them.
        CharacterKind desert = RuntimeWorlds.DesertSkeleton;
        var watch = new ThreadWatch();
        var scene = PlanningScene.Create(desert.Scene.Level, desert.Scene.Character, poseValidator: watch, arcValidator: watch);
        var kind = new CharacterKind(scene, desert.Roadmap, desert.Animator, new SimpleMoveAnimator(desert.Animator));
        // A real-time world (its ticks wait a bounded time): a world without a limit lends its waiting tick thread to
        // the jobs (AnimationWaitTests).
        using var world = new JumpWorld(scene.Level, RuntimeWorlds.JumpOnly with { AnimationThreads = threads, MaxAnimationWait = TimeSpan.FromSeconds(30) });
        KindHandle handle = world.AddKind(kind).Kind;

        // Targets beside roadmap nodes (not on one): each search places its goal and steers it in.
        Roadmap roadmap = desert.Roadmap;
        foreach ((RoadmapNode from, RoadmapNode to) in RuntimeWorlds.ConnectedPairs(roadmap, 6, seed: 9))
        {
            AgentHandle agent = world.AddAgent(handle, RuntimeWorlds.Point(from)).Agent;
            Assert.That(world.SetTarget(agent, RuntimeWorlds.Point(to) + new Vector3(0.12f, 0f, -0.09f)).Ok, Is.True);
        }

        watch.Clear();
        var found = new List<JumpEvent>();
        for (int tick = 0; tick < 40; tick++)
        {
            watch.TickThread = Environment.CurrentManagedThreadId;
            world.Step();
            watch.TickThread = -1;
            found.AddRange(world.Events.ToArray().Where(e => e.Kind is JumpEventKind.PathFound or JumpEventKind.PathFailed));
        }

        Assert.That(found, Has.Count.EqualTo(6), "every request concluded");
        Assert.That(watch.Calls, Is.GreaterThan(0), "the searches placed and steered through the validators");
        if (threads > 0)
        {
            Assert.That(watch.OnTick, Is.Zero, $"{watch.OnTick} of {watch.Calls} validator calls ran on the tick thread");
        }
        else
        {
            Assert.That(watch.OnTick, Is.EqualTo(watch.Calls), "with no background thread, searches run on the tick");
        }
    }

    /// <summary>
    /// A crowd sent to a new target whenever it arrives or fails, with a background thread and a real-time world's
    /// bounded wait: once the pools have grown, the tick thread allocates nothing, neither in the ticks that start
    /// requests and deliver their paths nor in the game's calls that send agents on. The request, its job and its
    /// repair record are reused or made on the job's thread, the path its agent follows too, and the kind's stance
    /// lessons are taught from arrays made when they were learned.
    /// </summary>
    [Test]
    public void ACrowdSentToNewTargetsAllocatesNothingOnTheTickThread()
    {
        using var world = new JumpWorld(RuntimeWorlds.DesertSkeleton.Scene.Level, RuntimeWorlds.JumpOnly with { AnimationThreads = 1, MaxAnimationWait = TimeSpan.FromSeconds(30) });
        KindHandle kind = world.AddKind(RuntimeWorlds.DesertSkeleton).Kind;
        Roadmap roadmap = RuntimeWorlds.DesertSkeleton.Roadmap;
        var random = new Random(5);
        Vector3 Anywhere() => RuntimeWorlds.Point(roadmap.Nodes[random.Next(roadmap.Nodes.Count)]);
        for (int i = 0; i < 40; i++)
        {
            AgentHandle agent = world.AddAgent(kind, Anywhere()).Agent;
            Assert.That(world.SetTarget(agent, Anywhere()).Ok, Is.True);
        }

        var sendOn = new List<AgentHandle>(64);
        int started = 0;
        int delivered = 0;
        long allocated = 0;
        for (int tick = 0; tick < 900; tick++)
        {
            bool measured = tick >= 300; // the first 5 s grow the pools, the queues and the event buffer
            long before = GC.GetAllocatedBytesForCurrentThread();
            world.Step();
            sendOn.Clear();
            foreach (JumpEvent e in world.Events)
            {
                delivered += measured && e.Kind is JumpEventKind.PathFound or JumpEventKind.PathFailed ? 1 : 0;
                if (e.Kind is JumpEventKind.TargetReached or JumpEventKind.PathFailed)
                {
                    sendOn.Add(e.Agent);
                }
            }

            foreach (AgentHandle agent in sendOn)
            {
                world.SetTarget(agent, Anywhere());
            }

            started += measured ? world.LastTickSearches : 0;
            allocated += measured ? GC.GetAllocatedBytesForCurrentThread() - before : 0;
        }

        Assert.Multiple(() =>
        {
            Assert.That(started, Is.GreaterThanOrEqualTo(20), "requests started while measured");
            Assert.That(delivered, Is.GreaterThanOrEqualTo(20), "outcomes delivered while measured");
            Assert.That(allocated, Is.Zero, $"bytes allocated on the tick thread over 600 ticks ({started} requests started, {delivered} delivered)");
        });
    }

    [Test]
    public void AFailedSearchIsToldExactlyPathLatencyTicksAfterItsStartWhateverTheThreads()
    {
        var told = new List<(long Started, long Told, string Reason)>();
        foreach (int threads in new[] { 0, 1, 4 })
        {
            (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert(RuntimeWorlds.JumpOnly with { AnimationThreads = threads, PathLatencyTicks = 5 });
            using (world)
            {
                AgentHandle agent = world.AddAgent(kind, RuntimeWorlds.Point(RuntimeWorlds.DesertSkeleton.Roadmap.Nodes[0])).Agent;
                Assert.That(world.SetTarget(agent, new Vector3(500f, 40f, 500f)).Ok, Is.True, "a target far off the level");
                long started = 0;
                JumpEvent? failed = null;
                for (int tick = 0; tick < 30 && failed is null; tick++)
                {
                    world.Step();
                    started = started == 0 && world.LastTickSearches > 0 ? world.Tick : started;
                    failed = world.Events.ToArray().Cast<JumpEvent?>().FirstOrDefault(e => e!.Value.Kind == JumpEventKind.PathFailed);
                }

                Assert.That(failed, Is.Not.Null, $"{threads} threads");
                told.Add((started, failed!.Value.Tick, failed.Value.Reason!));
            }
        }

        Assert.That(told.Select(t => t.Told - t.Started), Is.All.EqualTo(5));
        Assert.That(told.Select(t => t.Reason).Distinct().Count(), Is.EqualTo(1), string.Join(" | ", told.Select(t => t.Reason)));
    }

    [Test]
    public void ARequestWhosePathsNeverAnimateIsRepairedInItsJobAndFailsOnItsOneDueTickWhateverTheThreads()
    {
        var told = new List<(long Latency, string Reason, int Animated)>();
        foreach (int threads in new[] { 0, 2 })
        {
            // Every path's first move is refused by the body: each round sets it aside and searches again.
            CharacterKind desert = RuntimeWorlds.DesertSkeleton;
            var refusing = new RefusingAnimator(new SimpleMoveAnimator(desert.Animator));
            var kind = new CharacterKind(desert.Scene, desert.Roadmap, desert.Animator, refusing);
            using var world = new JumpWorld(desert.Scene.Level, RuntimeWorlds.JumpOnly with { AnimationThreads = threads, RepairRounds = 3 });
            KindHandle handle = world.AddKind(kind).Kind;
            (RoadmapNode from, RoadmapNode to) = RuntimeWorlds.ConnectedPairs(desert.Roadmap, 1, seed: 4, minDistance: 8f)[0];
            AgentHandle agent = world.AddAgent(handle, RuntimeWorlds.Point(from)).Agent;
            Assert.That(world.SetTarget(agent, RuntimeWorlds.Point(to)).Ok, Is.True);
            long started = 0;
            JumpEvent? failed = null;
            for (int tick = 0; tick < 60 && failed is null; tick++)
            {
                world.Step();
                Assert.That(world.Events.ToArray().Select(e => e.Kind), Has.No.Member(JumpEventKind.PathFound));
                started = started == 0 && world.LastTickSearches > 0 ? world.Tick : started;
                Assert.That(world.LastTickSearches == 0 || world.Tick == started, Is.True, "one start: the repairs run inside the job");
                failed = world.Events.ToArray().Cast<JumpEvent?>().FirstOrDefault(e => e!.Value.Kind == JumpEventKind.PathFailed);
            }

            Assert.That(failed, Is.Not.Null, $"{threads} threads");
            told.Add((failed!.Value.Tick - started, failed.Value.Reason!, refusing.Calls));
        }

        Assert.That(told.Select(t => t.Latency), Is.All.EqualTo(RuntimeWorlds.JumpOnly.PathLatencyTicks));
        int searches = int.Parse(System.Text.RegularExpressions.Regex.Match(told[0].Reason, @"^no path animated cleanly in (\d+) searches: \1 jumps? set aside").Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture);
        Assert.That(searches, Is.GreaterThanOrEqualTo(3), $"at least RepairRounds searches, each setting one jump aside (rounds whose cut or hop failed come on top): {told[0].Reason}");
        Assert.That(told[0].Animated, Is.InRange(2, searches), "the rounds animated inside the one job (a path met again comes from the kind's cache)");
        Assert.That(told[1], Is.EqualTo(told[0]), "the same outcome at 0 and 2 threads");
    }

    /// <summary>Animates as <paramref name="inner"/> does, with a problem on the first move of every path.</summary>
    private sealed class RefusingAnimator(SimpleMoveAnimator inner) : IJumpAnimator
    {
        private int _calls;

        public int Calls => Volatile.Read(ref _calls);

        public JumpAnimation Animate(IReadOnlyList<Move> moves, float frameRate = 60f)
        {
            Interlocked.Increment(ref _calls);
            JumpAnimation a = inner.Animate(moves, frameRate);
            return new JumpAnimation(a.Model, a.Moves, a.Stances, a.Frames, a.ContactPhases, [new JumpProblem(0, "test: the body refuses this move")], 1, 0, a.LeadIn, a.LeadOut);
        }

        public bool CanStand(PoseEvaluation pose) => inner.CanStand(pose);
    }

    /// <summary>Accepts every pose and arc, counting the calls and those made on the tick thread.</summary>
    private sealed class ThreadWatch : IPoseValidator, IArcValidator
    {
        private int _calls;
        private int _onTick;

        public volatile int TickThread = -1;

        public int Calls => Volatile.Read(ref _calls);

        public int OnTick => Volatile.Read(ref _onTick);

        public void Clear()
        {
            Interlocked.Exchange(ref _calls, 0);
            Interlocked.Exchange(ref _onTick, 0);
        }

        public bool IsValid(PoseEvaluation evaluation) => Note();

        public bool IsValid(in BallisticArc arc) => Note();

        private bool Note()
        {
            Interlocked.Increment(ref _calls);
            if (Environment.CurrentManagedThreadId == TickThread)
            {
                Interlocked.Increment(ref _onTick);
            }

            return true;
        }
    }
}
