using Ballistic.Authoring.Characters;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Planning;

/// <summary>One termination condition, carried from the caller into the bake's parallel loops and the queries.</summary>
public sealed class TerminationConditionTests
{
    private static readonly Lazy<PlanningScene> Scene = new(() => PlanningScene.Create(GapCourse.Build(), CharacterPresets.Skeleton()));

    [Test]
    public void OnlyTheClockAndCancellationAnswerBetweenWorkItems()
    {
        using var source = new CancellationTokenSource();
        TerminationCondition budget = TerminationCondition.Timeout(TimeSpan.FromSeconds(2));
        TerminationCondition cancel = TerminationCondition.Cancellation(source.Token);
        TerminationCondition others = TerminationCondition.NodeCount(1) | TerminationCondition.StartGoalConnected() | TerminationCondition.When(_ => true, PlannerStatus.NoPath, "always");
        Assert.Multiple(() =>
        {
            Assert.That(budget.ShouldStopNow(TimeSpan.FromSeconds(1), out _, out _), Is.False);
            Assert.That(budget.ShouldStopNow(TimeSpan.FromSeconds(2), out PlannerStatus status, out string reason), Is.True);
            Assert.That(status, Is.EqualTo(PlannerStatus.Timeout));
            Assert.That(reason, Is.EqualTo("time budget of 2 s spent"));
            Assert.That(cancel.ShouldStopNow(TimeSpan.MaxValue, out _, out _), Is.False);
            Assert.That(others.ShouldStopNow(TimeSpan.MaxValue, out _, out _), Is.False, "conditions on the bake's state wait for the end of the round");
            Assert.That(others.ShouldStop(new BakeState(0, 0, TimeSpan.Zero, false, 0), out status, out _), Is.True);
            Assert.That(status, Is.EqualTo(PlannerStatus.NoPath));
        });

        source.Cancel();
        TerminationCondition both = others | budget | cancel;
        Assert.Multiple(() =>
        {
            Assert.That(both.ShouldStopNow(TimeSpan.Zero, out PlannerStatus status, out string reason), Is.True);
            Assert.That((status, reason), Is.EqualTo((PlannerStatus.Cancelled, "cancelled")));
            Assert.That(both.ShouldStopNow(TimeSpan.FromSeconds(3), out status, out _), Is.True);
            Assert.That(status, Is.EqualTo(PlannerStatus.Timeout), "the left one's verdict wins");
            Assert.That(() => TerminationCondition.Timeout(TimeSpan.Zero), Throws.TypeOf<ArgumentOutOfRangeException>());
        });
    }

    [Test]
    public void ABakeCutShortMidRoundIsAPrefixOfALongerBake()
    {
        // Both cut a round short after at least one whole round, however busy the machine: the time limit is three
        // first rounds' time (400 ms at least), the cancellation comes 100 ms after the first round is reported.
        var baker = new RoadmapBaker(Scene.Value);
        TimeSpan round = baker.Bake(new BakeSettings { Seed = 6, MaxNodes = 1, Threads = 2 }).Elapsed;
        TimeSpan limit = TimeSpan.FromTicks(Math.Max(TimeSpan.FromMilliseconds(400).Ticks, 3 * round.Ticks));
        BakeResult timed = baker.Bake(new BakeSettings { Seed = 6, MaxNodes = null, TimeLimit = limit, Threads = 2 });
        using var source = new CancellationTokenSource();
        int reports = 0;
        var firstRound = new OnReport(_ =>
        {
            if (Interlocked.Increment(ref reports) == 1)
            {
                source.CancelAfter(100);
            }
        });
        BakeResult cancelled = baker.Bake(new BakeSettings { Seed = 6, MaxNodes = 5_000, Threads = 2 }, TerminationCondition.Cancellation(source.Token), firstRound);
        Roadmap full = baker.Bake(new BakeSettings { Seed = 6, MaxNodes = Math.Max(timed.Roadmap.Nodes.Count, cancelled.Roadmap.Nodes.Count) + 64, Threads = 2 }).Roadmap;
        Assert.Multiple(() =>
        {
            Assert.That(timed.Status, Is.EqualTo(PlannerStatus.Timeout));
            Assert.That(timed.Elapsed, Is.LessThan(limit + TimeSpan.FromSeconds(5)), "the budget cuts the round short, not just the bake");
            Assert.That(cancelled.Status, Is.EqualTo(PlannerStatus.Cancelled));
            Assert.That(cancelled.Reason, Is.EqualTo("cancelled"));
        });
        foreach (Roadmap part in new[] { timed.Roadmap, cancelled.Roadmap })
        {
            Assert.That(part.Nodes, Is.Not.Empty);
            Assert.That(part.Nodes.Select(n => n.Pose), Is.EqualTo(full.Nodes.Take(part.Nodes.Count).Select(n => n.Pose)), "whole rounds only");
            Assert.That(part.Edges, Is.EqualTo(full.Edges.Take(part.Edges.Count)));
        }
    }

    [Test]
    public void PlansStopOnTheirCondition()
    {
        PlanningScene scene = Scene.Value;
        var planner = new AnimatedPlanner(scene, new JumpAnimator(scene, CharacterPresets.Model("skeleton")));
        using var source = new CancellationTokenSource();
        source.Cancel();
        TerminationCondition cancelled = TerminationCondition.Cancellation(source.Token);
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 2, MaxNodes = 60, Threads = 2 }).Roadmap;
        AnimatedPlan plan = planner.Plan(roadmap, GapCourse.From, GapCourse.To, termination: cancelled);
        (AnimatedPlan baked, BakeResult bake) = planner.BakeAndPlan(GapCourse.From, GapCourse.To, new BakeSettings { Seed = 2, MaxNodes = 200, Threads = 2 }, cancelled);
        AnimatedPlan late = planner.Plan(roadmap, GapCourse.From, GapCourse.To, termination: TerminationCondition.Timeout(TimeSpan.FromTicks(1)));
        Assert.Multiple(() =>
        {
            Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Cancelled));
            Assert.That(plan.Animation, Is.Null);
            Assert.That(baked.Result.Status, Is.EqualTo(PlannerStatus.Cancelled));
            Assert.That(bake.Status, Is.EqualTo(PlannerStatus.Cancelled));
            Assert.That(late.Result.Status, Is.EqualTo(PlannerStatus.Timeout));
            Assert.That(late.Result.Reason, Does.Contain("time budget"));
        });
    }

    /// <summary>Progress reported on the baking thread itself, as it happens.</summary>
    private sealed class OnReport(Action<BakeState> report) : IProgress<BakeState>
    {
        public void Report(BakeState value) => report(value);
    }
}
