using System.Numerics;
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
        using var world = new JumpWorld(scene.Level, RuntimeWorlds.JumpOnly with { AnimationThreads = threads });
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
