using System.Numerics;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Query;

/// <summary>
/// A route found on the first connection's sparse roadmap may wander: <see cref="AnimatedPlanner.BakeAndPlan"/> bakes
/// on and plans again while the route runs more than <see cref="AnimatedPlanner.DetourLimit"/> times the straight
/// distance between its ends and a larger roadmap shortens it (issue 24: the frog from the floor up onto a beam's
/// middle hopped round the beam's end and under it, 9 hops).
/// </summary>
[Category("EndToEnd")]
public sealed class WanderingRouteTests
{
    private static readonly Lazy<Sweep.Setup> BeamFrog = new(() => Sweep.Prepare("beam", ForeignLevels.Get("beam").Level, "frog"));

    private static readonly BakeSettings Settings = new() { Seed = 1, Threads = 2, MaxNodes = 600 };

    /// <summary>
    /// The sweep's beam request from the floor 3 m off the beam up onto its middle: planned on the roadmap baked until
    /// it first connects, the frog hops 9 times, 2.4 times the straight distance; baked on, with stances on the ground
    /// within a hop of the raised goal, it hops to the beam's side and up: 2 hops, at most 1.2 times the straight
    /// distance, fully right by the audit (before those stances: 5 hops, under the beam and up from its far side, 1.6
    /// times, every stance on the near side too far to jump up from).
    /// </summary>
    [Test]
    public void AWanderingRouteIsPlannedAgainOnALargerRoadmap()
    {
        Sweep.Setup setup = BeamFrog.Value;
        (Vector3 from, Vector3 to) = ForeignLevels.Get("beam").Requests[2];
        BakeResult first = new RoadmapBaker(setup.Scene).Bake(Settings with { Start = from, Goal = to, StopWhenConnected = true, CanStand = setup.Planner.Animator.CanStand });
        AnimatedPlan sparse = setup.Planner.Plan(first.Roadmap, from, to, new QuerySettings { Tolerance = Settings.Tolerance });
        Assert.That(sparse.Result.Status, Is.EqualTo(PlannerStatus.Exact), sparse.Result.Reason);
        float wandered = AnimatedPlanner.Detour(sparse.Result);

        (AnimatedPlan plan, BakeResult bake) = setup.Planner.BakeAndPlan(from, to, Settings);
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        float detour = AnimatedPlanner.Detour(plan.Result);
        TestContext.Out.WriteLine($"first connection: {first.Roadmap.Nodes.Count} nodes, {sparse.Result.Moves.Count} moves, {wandered:0.00} × the straight distance; baked on: {bake.Roadmap.Nodes.Count} nodes, {plan.Result.Moves.Count} moves, {detour:0.00} ×");
        Assert.Multiple(() =>
        {
            Assert.That(wandered, Is.GreaterThan(AnimatedPlanner.DetourLimit), "the first connection's route wanders");
            Assert.That(bake.Roadmap.Nodes.Count, Is.GreaterThan(first.Roadmap.Nodes.Count), "the roadmap was baked on");
            Assert.That(detour, Is.LessThan(wandered - 0.5f), "the route planned again is shorter");
            Assert.That(plan.Result.Moves.Count, Is.LessThan(sparse.Result.Moves.Count), "in fewer hops");
            Assert.That(plan.Result.Moves, Has.Count.LessThanOrEqualTo(2), "a hop to the beam's side and one up");
            Assert.That(detour, Is.LessThanOrEqualTo(1.2f), "about the straight distance");
        });
        AuditReport audit = PlanAudit.Check("beam frog baked on", setup.Scene, from, to, plan.Result, plan.Animation);
        Assert.That(audit.FullyRight, Is.True, audit.ToString());
    }

    /// <summary>
    /// A request cancelled while the roadmap is baked on for a wandering route keeps the exact plan already found on
    /// the first connection's roadmap: the cancellation stops the refinement, not the answer.
    /// </summary>
    [Test]
    public void ARefinementCancelledKeepsTheExactPlanFound()
    {
        Sweep.Setup setup = BeamFrog.Value;
        (Vector3 from, Vector3 to) = ForeignLevels.Get("beam").Requests[2];
        BakeResult first = new RoadmapBaker(setup.Scene).Bake(Settings with { Start = from, Goal = to, StopWhenConnected = true, CanStand = setup.Planner.Animator.CanStand });
        int connected = first.Roadmap.Nodes.Count;
        using var cancel = new CancellationTokenSource();
        var progress = new Reported(state =>
        {
            if (state.Nodes > connected)
            {
                cancel.Cancel();
            }
        });
        (AnimatedPlan plan, BakeResult bake) = setup.Planner.BakeAndPlan(from, to, Settings, TerminationCondition.Cancellation(cancel.Token), progress);
        Assert.Multiple(() =>
        {
            Assert.That(cancel.IsCancellationRequested, Is.True, "the roadmap was being baked on when the request was cancelled");
            Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
            Assert.That(bake.Roadmap.Nodes, Has.Count.EqualTo(connected), "the first connection's roadmap");
            Assert.That(AnimatedPlanner.Detour(plan.Result), Is.GreaterThan(AnimatedPlanner.DetourLimit), "its wandering route");
        });
    }

    /// <summary>Progress reported on the baking thread as it happens (<see cref="Progress{T}"/> posts it later, elsewhere).</summary>
    private sealed class Reported(Action<BakeState> report) : IProgress<BakeState>
    {
        public void Report(BakeState value) => report(value);
    }

    /// <summary>A route that runs straight (along the beam end to end) is planned on the first connection's roadmap: nothing is baked on.</summary>
    [Test]
    public void AStraightRouteIsNotBakedOn()
    {
        Sweep.Setup setup = BeamFrog.Value;
        (Vector3 from, Vector3 to) = ForeignLevels.Get("beam").Requests[0];
        BakeResult first = new RoadmapBaker(setup.Scene).Bake(Settings with { Start = from, Goal = to, StopWhenConnected = true, CanStand = setup.Planner.Animator.CanStand });
        (AnimatedPlan plan, BakeResult bake) = setup.Planner.BakeAndPlan(from, to, Settings);
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        Assert.That(AnimatedPlanner.Detour(plan.Result), Is.LessThanOrEqualTo(AnimatedPlanner.DetourLimit));
        Assert.That(bake.Roadmap.Nodes.Count, Is.EqualTo(first.Roadmap.Nodes.Count), "the first connection's roadmap");
    }
}
