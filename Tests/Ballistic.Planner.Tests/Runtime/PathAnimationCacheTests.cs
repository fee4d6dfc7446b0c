using Ballistic.Planner.Animation;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>
/// Each distinct path of a kind is animated once: agents sent between the same stances share the motion, which is
/// exactly what animating their moves again gives; a path differing in any input is animated anew.
/// </summary>
public sealed class PathAnimationCacheTests
{
    [Test]
    public void AgentsSentTheSameWayShareOneAnimationAndMoveAlike()
    {
        CharacterKind desert = RuntimeWorlds.DesertSkeleton;
        var counting = new SimpleMoveAnimator(desert.Animator);
        var kind = new CharacterKind(desert.Scene, desert.Roadmap, desert.Animator, counting);
        using var world = new JumpWorld(desert.Scene.Level, RuntimeWorlds.JumpOnly);
        KindHandle handle = world.AddKind(kind).Kind;
        (RoadmapNode from, RoadmapNode to) = RuntimeWorlds.ConnectedPairs(desert.Roadmap, 1, 11)[0];
        AgentHandle[] agents = [.. Enumerable.Range(0, 3).Select(_ => world.AddAgent(handle, RuntimeWorlds.Point(from)).Agent)];
        foreach (AgentHandle agent in agents)
        {
            Assert.That(world.SetTarget(agent, RuntimeWorlds.Point(to)).Ok, Is.True);
        }

        bool following = false;
        for (int tick = 0; tick < 240; tick++)
        {
            world.Step();
            following |= world.GetState(agents[0]) is AgentState.Flight or AgentState.Walking;
            RootPose first = world.GetRootPose(agents[0]);
            foreach (AgentHandle other in agents.Skip(1))
            {
                Assert.That(world.GetRootPose(other), Is.EqualTo(first), $"tick {tick}: agents sent the same way move alike");
            }
        }

        Assert.That(following, Is.True, "the agents set off");
        Assert.That(counting.Calls, Is.EqualTo(1), "three agents, one path animated");
        Assert.That(kind.PathAnimator.Solved, Is.EqualTo(1));
    }

    /// <summary>A path animator that animates in steps too, counting the calls of each kind.</summary>
    private sealed class CountingStepwise(JumpAnimator inner) : IJumpAnimator, IStepwiseAnimator
    {
        private int _whole;
        private int _stepwise;

        public int Whole => _whole;

        public int InSteps => _stepwise;

        public JumpAnimation Animate(IReadOnlyList<Move> moves, float frameRate = 60f)
        {
            Interlocked.Increment(ref _whole);
            return inner.Animate(moves, frameRate);
        }

        public IEnumerable<JumpAnimation?> AnimateSteps(IReadOnlyList<Move> moves, float frameRate)
        {
            Interlocked.Increment(ref _stepwise);
            return ((IStepwiseAnimator)inner).AnimateSteps(moves, frameRate);
        }

        public bool CanStand(PoseEvaluation pose) => inner.CanStand(pose);
    }

    /// <summary>
    /// Three agents sent the same way in one tick, their requests run whole on two background threads: the path is
    /// animated once, the others wait for it (a request run whole takes the cache's shared solve, never the steps,
    /// which nobody waits for); on the tick thread in slices, the same path is animated in steps.
    /// </summary>
    [Test]
    public void RequestsRunWholeShareOneSolveAndOnlySlicedOnesAnimateInSteps()
    {
        CharacterKind desert = RuntimeWorlds.DesertSkeleton;
        (RoadmapNode from, RoadmapNode to) = RuntimeWorlds.ConnectedPairs(desert.Roadmap, 1, 11)[0];
        foreach (int threads in new[] { 2, 0 })
        {
            var counting = new CountingStepwise(desert.Animator);
            var kind = new CharacterKind(desert.Scene, desert.Roadmap, desert.Animator, counting);
            using var world = new JumpWorld(desert.Scene.Level, RuntimeWorlds.JumpOnly with { AnimationThreads = threads });
            KindHandle handle = world.AddKind(kind).Kind;
            AgentHandle[] agents = [.. Enumerable.Range(0, 3).Select(_ => world.AddAgent(handle, RuntimeWorlds.Point(from)).Agent)];
            foreach (AgentHandle agent in agents)
            {
                Assert.That(world.SetTarget(agent, RuntimeWorlds.Point(to)).Ok, Is.True);
            }

            for (int tick = 0; tick < 30 && agents.Any(world.IsPathPending); tick++)
            {
                world.Step();
            }

            Assert.That(agents.Select(a => world.GetPath(a) is not null), Has.All.True, $"{threads} threads: every agent has its path");
            if (threads > 0)
            {
                Assert.That((counting.Whole, counting.InSteps), Is.EqualTo((1, 0)), "run whole: one solve, shared");
                Assert.That(kind.PathAnimator.Solved, Is.EqualTo(1));
            }
            else
            {
                Assert.That(counting.InSteps, Is.GreaterThanOrEqualTo(1), "in slices: animated in steps");
                Assert.That(kind.PathAnimator.Solved, Is.EqualTo(counting.Whole + counting.InSteps), "each path given to the animator counted");
            }
        }
    }

    /// <summary>
    /// In steps (a request advanced on the tick in slices): a path not remembered is animated a move at a time and then
    /// remembered, the animation its moves give whole; asked again, it is given in one step, not animated again.
    /// </summary>
    [Test]
    public void APathAnimatedInStepsIsTheWholeAnimationAndIsRemembered()
    {
        CharacterKind desert = RuntimeWorlds.DesertSkeleton;
        var cache = new PathAnimationCache(desert.Animator, desert.Model);
        (RoadmapNode from, RoadmapNode to) = RuntimeWorlds.ConnectedPairs(desert.Roadmap, 1, 3)[0];
        PlanResult path = new PathQuery(desert.Scene, desert.Roadmap).Plan(from, to, new QuerySettings { Locomotion = Locomotion.Jump });
        Assume.That(path.Moves, Has.Count.GreaterThan(1));
        JumpAnimation whole = desert.Animator.Animate(path.Moves, 60f);

        List<JumpAnimation?> steps = [.. ((IStepwiseAnimator)cache).AnimateSteps(path.Moves, 60f)];
        List<JumpAnimation?> again = [.. ((IStepwiseAnimator)cache).AnimateSteps(path.Moves, 60f)];
        Assert.Multiple(() =>
        {
            Assert.That(steps, Has.Count.EqualTo(path.Moves.Count + 1), "a pause after each move, then the animation");
            Assert.That(steps[..^1], Has.All.Null);
            Assert.That(steps[^1]!.Frames.Select(f => (f.Time, f.Root)), Is.EqualTo(whole.Frames.Select(f => (f.Time, f.Root))));
            Assert.That(steps[^1]!.Frames.SelectMany(f => f.Angles), Is.EqualTo(whole.Frames.SelectMany(f => f.Angles)));
            Assert.That(again, Has.Count.EqualTo(1), "remembered: one step");
            Assert.That(again[0]!.Frames.Select(f => f.Root), Is.EqualTo(whole.Frames.Select(f => f.Root)));
            Assert.That(cache.Solved, Is.EqualTo(1), "animated once");
        });
    }

    [Test]
    public void ARememberedPathIsTheAnimationOfItsMovesAndAnyChangeIsAnimatedAnew()
    {
        CharacterKind desert = RuntimeWorlds.DesertSkeleton;
        var cache = new PathAnimationCache(desert.Animator, desert.Model);
        RoadmapEdge edge = desert.Roadmap.Edges.First(e => e.Arc.FlightTime > 0.3f);
        Move[] moves = [new Jump(desert.Roadmap.Nodes[edge.From], desert.Roadmap.Nodes[edge.To], edge.Arc)];
        JumpAnimation fresh = desert.Animator.Animate(moves, 60f);
        JumpAnimation solved = cache.Animate(moves, 60f);

        // The same moves again, as new objects equal to the bit (a second agent's search): remembered.
        Move[] again = [new Jump(desert.Roadmap.Nodes[edge.From] with { }, desert.Roadmap.Nodes[edge.To] with { }, edge.Arc)];
        JumpAnimation remembered = cache.Animate(again, 60f);
        Assert.Multiple(() =>
        {
            Assert.That(cache.Solved, Is.EqualTo(1), "the same moves are solved once");
            Assert.That(remembered.Moves[0], Is.SameAs(again[0]), "the caller's own moves");
            foreach (JumpAnimation animation in (JumpAnimation[])[solved, remembered])
            {
                Assert.That(animation.Frames.Select(f => (f.Time, f.Root)), Is.EqualTo(fresh.Frames.Select(f => (f.Time, f.Root))));
                Assert.That(animation.Frames.SelectMany(f => f.Angles), Is.EqualTo(fresh.Frames.SelectMany(f => f.Angles)));
                Assert.That(animation.ContactPhases, Is.EqualTo(fresh.ContactPhases));
                Assert.That(animation.Problems, Is.EqualTo(fresh.Problems));
                Assert.That(animation.Duration, Is.EqualTo(fresh.Duration));
            }
        });

        // A takeoff stance moved by the least float step, or another frame rate, is another path.
        RoadmapNode takeoff = desert.Roadmap.Nodes[edge.From];
        RoadmapNode nudged = takeoff with { Pose = takeoff.Pose with { Position = takeoff.Pose.Position with { X = MathF.BitIncrement(takeoff.Pose.Position.X) } } };
        cache.Animate([new Jump(nudged, desert.Roadmap.Nodes[edge.To], edge.Arc)], 60f);
        Assert.That(cache.Solved, Is.EqualTo(2), "a stance one float step away is animated anew");
        cache.Animate(moves, 30f);
        Assert.That(cache.Solved, Is.EqualTo(3), "another frame rate is animated anew");
        cache.Animate(moves, 60f);
        Assert.That(cache.Solved, Is.EqualTo(3), "and the first is still remembered");
    }
}
