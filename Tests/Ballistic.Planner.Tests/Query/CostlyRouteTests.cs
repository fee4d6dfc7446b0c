using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Runtime;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Query;

/// <summary>
/// A route found on the first connection's roadmap may jump where a walk would cost less, the walk never sampled
/// because the bake stopped as soon as the start reached the goal: with <see cref="BakeSettings.Refine"/> (the
/// default), <see cref="AnimatedPlanner.BakeAndPlan"/> bakes on and searches again while the route jumps and costs more than
/// walking <see cref="AnimatedPlanner.DetourLimit"/> times the straight distance would, and keeps a route only when it
/// costs at least <see cref="AnimatedPlanner.CheaperBy"/> less (issue 24: the skeleton vaulted a maze's 0.8 m hedges
/// instead of walking round their ends, whatever jump effort a designer set).
/// </summary>
[Category("EndToEnd")]
public sealed class CostlyRouteTests
{
    private static readonly Lazy<Sweep.Setup> MazeSkeleton = new(() => Sweep.Prepare("maze", ForeignLevels.Get("maze").Level, "skeleton"));

    private static readonly BakeSettings Settings = new() { Seed = 1, Threads = 2, MaxNodes = 600 };

    /// <summary>Whether <paramref name="move"/> is a jump across the hedge at x = −4 m (open to the south of z = −3 m).</summary>
    private static bool Vaults(Move move) => move is Jump jump && (jump.Arc.Start.X + 4f) * (jump.Arc.End.X + 4f) < 0f;

    /// <summary>
    /// The maze's request into the next corridor, 2 m straight through a hedge: the first connection's roadmap (its
    /// start and goal only) vaults the hedge, at a cost of more than 1.5 times walking the straight distance; baked on,
    /// the skeleton walks round the hedge's open end (more than 5 m: down the corridor, past the end, back up), a
    /// route the search costs lower, fully right by the audit.
    /// </summary>
    [Test]
    public void AHedgeVaultedOnTheFirstConnectionIsWalkedRoundOnceBakedOn()
    {
        Sweep.Setup setup = MazeSkeleton.Value;
        (Vector3 from, Vector3 to) = ForeignLevels.Get("maze").Requests[0];
        BakeResult first = new RoadmapBaker(setup.Scene).Bake(Settings with { Start = from, Goal = to, StopWhenConnected = true, CanStand = setup.Planner.Animator.CanStand });
        AnimatedPlan sparse = setup.Planner.Plan(first.Roadmap, from, to, new QuerySettings { Tolerance = Settings.Tolerance });
        Assert.That(sparse.Result.Status, Is.EqualTo(PlannerStatus.Exact), sparse.Result.Reason);
        float walkFloor = AnimatedPlanner.DetourLimit * 2f / setup.Scene.Character.Walking.Speed;

        (AnimatedPlan plan, BakeResult bake) = setup.Planner.BakeAndPlan(from, to, Settings);
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        TestContext.Out.WriteLine($"first connection: {first.Roadmap.Nodes.Count} nodes, {sparse.Result.Reason}, cost {sparse.Result.Cost:0.00} s; baked on: {bake.Roadmap.Nodes.Count} nodes, {plan.Result.Reason}, cost {plan.Result.Cost:0.00} s");
        Assert.Multiple(() =>
        {
            Assert.That(sparse.Result.Moves.Any(Vaults), Is.True, "the first connection's route vaults the hedge");
            Assert.That(sparse.Result.Cost, Is.GreaterThan(walkFloor), "at a cost a walk round might beat");
            Assert.That(bake.Roadmap.Nodes.Count, Is.GreaterThan(first.Roadmap.Nodes.Count), "the roadmap was baked on");
            Assert.That(plan.Result.Moves.Any(Vaults), Is.False, "baked on, no jump crosses the hedge");
            Assert.That(plan.Result.Walks.Sum(w => w.Length), Is.GreaterThan(5f), "it walks round the hedge's open end");
            Assert.That(plan.Result.Cost, Is.LessThan((1f - AnimatedPlanner.CheaperBy) * sparse.Result.Cost), "at a lower cost");

            // The README's figures.
            Assert.That(first.Roadmap.Nodes, Has.Count.EqualTo(2), "the first connection: its start and goal alone");
            Assert.That(sparse.Result.Cost, Is.EqualTo(5.06f).Within(0.005f), "the vault's cost, seconds");
            Assert.That(plan.Result.Cost, Is.EqualTo(4.21f).Within(0.005f), "the walk round's cost, seconds");
            Assert.That(bake.Roadmap.Nodes, Has.Count.EqualTo(64), "baked on once");
        });
        AuditReport audit = PlanAudit.Check("maze skeleton baked on", setup.Scene, from, to, plan.Result, plan.Animation);
        Assert.That(audit.FullyRight, Is.True, audit.ToString());
    }

    /// <summary>
    /// On a roadmap baked for the whole level (600 nodes, as <c>bake</c> and the editor bake one), the same request walks
    /// round the hedge without any refinement: the walk is there to be found.
    /// </summary>
    [Test]
    public void OnAWholeLevelRoadmapTheHedgeIsWalkedRound()
    {
        Sweep.Setup setup = MazeSkeleton.Value;
        (Vector3 from, Vector3 to) = ForeignLevels.Get("maze").Requests[0];
        BakeResult whole = new RoadmapBaker(setup.Scene).Bake(Settings with { Refine = false });
        AnimatedPlan plan = setup.Planner.Plan(whole.Roadmap, from, to, new QuerySettings { Tolerance = Settings.Tolerance });
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        Assert.Multiple(() =>
        {
            Assert.That(plan.Result.Moves.Any(Vaults), Is.False, "no jump crosses the hedge");
            Assert.That(plan.Result.Walks.Sum(w => w.Length), Is.GreaterThan(5f), "it walks round the hedge's open end");
        });
    }

    /// <summary>Not refined (<see cref="BakeSettings.Refine"/> off), the same request keeps the first connection's vault, on its roadmap.</summary>
    [Test]
    public void UnrefinedTheFirstConnectionsRouteIsKept()
    {
        Sweep.Setup setup = MazeSkeleton.Value;
        (Vector3 from, Vector3 to) = ForeignLevels.Get("maze").Requests[0];
        BakeSettings unrefined = Settings with { Refine = false };
        BakeResult first = new RoadmapBaker(setup.Scene).Bake(unrefined with { Start = from, Goal = to, StopWhenConnected = true, CanStand = setup.Planner.Animator.CanStand });
        (AnimatedPlan plan, BakeResult bake) = setup.Planner.BakeAndPlan(from, to, unrefined);
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        Assert.Multiple(() =>
        {
            Assert.That(plan.Result.Moves.Any(Vaults), Is.True, "it vaults the hedge");
            Assert.That(bake.Roadmap.Nodes.Count, Is.EqualTo(first.Roadmap.Nodes.Count), "the first connection's roadmap");
        });
    }

    /// <summary>
    /// Jumping only, the same request refined is not baked on: no walk could be cheaper, so the first connection's
    /// vault is the plan, on the first connection's roadmap.
    /// </summary>
    [Test]
    public void JumpingOnlyTheFirstConnectionsRouteIsKept()
    {
        Sweep.Setup setup = MazeSkeleton.Value;
        (Vector3 from, Vector3 to) = ForeignLevels.Get("maze").Requests[0];
        BakeSettings jumps = Settings with { Locomotion = Locomotion.Jump };
        BakeResult first = new RoadmapBaker(setup.Scene).Bake(jumps with { Start = from, Goal = to, StopWhenConnected = true, CanStand = setup.Planner.Animator.CanStand });
        (AnimatedPlan plan, BakeResult bake) = setup.Planner.BakeAndPlan(from, to, jumps);
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        Assert.Multiple(() =>
        {
            Assert.That(plan.Result.Moves.Any(Vaults), Is.True, "it vaults the hedge");
            Assert.That(bake.Roadmap.Nodes.Count, Is.EqualTo(first.Roadmap.Nodes.Count), "the first connection's roadmap");
        });
    }

    /// <summary>
    /// The refined roadmap's route (3 walks round the hedge) is searched but may not animate: with every move but a jump
    /// across the hedge refused, its walks are set aside and its repair ends on a vault, no cheaper than the first
    /// connection's; that route is animated too and kept, on its own roadmap (the smaller one, at an equal cost).
    /// </summary>
    [Test]
    public void ARefinedRouteTheBodyCannotPerformFallsBackToTheFirstConnectionsRoute()
    {
        Sweep.Setup setup = MazeSkeleton.Value;
        (Vector3 from, Vector3 to) = ForeignLevels.Get("maze").Requests[0];
        var animator = new RefusingAnimator(new SimpleMoveAnimator((JumpAnimator)setup.Planner.Animator), m => !Vaults(m), "cannot move here");
        (AnimatedPlan plan, BakeResult bake) = new AnimatedPlanner(setup.Scene, animator).BakeAndPlan(from, to, Settings);
        TestContext.Out.WriteLine($"{bake.Roadmap.Nodes.Count} nodes, {plan.Result.Reason}, {animator.PathsRefused} paths refused, {plan.Rounds} rounds");
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        Assert.Multiple(() =>
        {
            Assert.That(plan.Result.Moves, Has.Count.EqualTo(1).And.All.Matches<Move>(Vaults), "the first connection's vault");
            Assert.That(animator.PathsRefused, Is.GreaterThan(0), "the refined route was animated first, and refused");
            Assert.That(bake.Roadmap.Nodes, Has.Count.EqualTo(2), "on the first connection's roadmap");
        });
    }
}
