using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Planning;

public sealed class RoadmapBakerTests
{
    private static readonly Lazy<PlanningScene> Scene = new(() => PlanningScene.Create(GapCourse.Build(), CharacterPresets.Skeleton().WithWalking(WalkingLimits.None))); // the paper's jumping skeleton: these test the jump planner

    [Test]
    public void EveryNodeAndEveryJumpOfABakeIsValid()
    {
        BakeResult result = new RoadmapBaker(Scene.Value).Bake(new BakeSettings { Seed = 3, MaxNodes = 60, Threads = 2 });
        Assert.That(result.Status, Is.EqualTo(PlannerStatus.Exact), result.Reason);
        Assert.That(result.Roadmap.Nodes, Has.Count.EqualTo(60));
        Assert.That(result.Roadmap.Edges, Has.Count.GreaterThan(60));
        Assert.That(result.SteeringRejections.Values.Sum() + result.Roadmap.Edges.Count, Is.EqualTo(result.SteeringCalls), "every steering call is an edge or a counted rejection");
        foreach (RoadmapNode node in result.Roadmap.Nodes)
        {
            PhysicsChecks.AssertNode(Scene.Value, node, $"node {node.Id}");
        }

        foreach (RoadmapEdge edge in result.Roadmap.Edges)
        {
            PhysicsChecks.AssertJump(Scene.Value, result.Roadmap.Nodes[edge.From], result.Roadmap.Nodes[edge.To], edge.Arc, $"edge {edge.From}→{edge.To}");
        }
    }

    [Test]
    public void AWallBlocksJumpsThroughItAndTheBakeSaysSo()
    {
        Level walled = new LevelBuilder("walled")
            .AddBox(new Vector3(-6f, -1f, -3f), new Vector3(6f, 0f, 3f))
            .AddBox(new Vector3(-0.05f, 0f, -3f), new Vector3(0.05f, 2.2f, 3f))
            .Build();
        var scene = PlanningScene.Create(walled, CharacterPresets.Skeleton());
        BakeResult result = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 3, MaxNodes = 60, Threads = 2 });
        Assert.That(result.SteeringRejections.Keys, Does.Contain(SteeringFailure.Collision), "jumps through the wall are rejected as collisions");
        foreach (RoadmapEdge edge in result.Roadmap.Edges)
        {
            PhysicsChecks.AssertJump(scene, result.Roadmap.Nodes[edge.From], result.Roadmap.Nodes[edge.To], edge.Arc, $"edge {edge.From}→{edge.To}");
        }
    }

    [Test]
    public void TheBakeIsIdenticalWhateverTheThreadCount()
    {
        var baker = new RoadmapBaker(Scene.Value);
        string one = Describe(baker.Bake(new BakeSettings { Seed = 11, MaxNodes = 40, Threads = 1 }).Roadmap);
        string two = Describe(baker.Bake(new BakeSettings { Seed = 11, MaxNodes = 40, Threads = 2 }).Roadmap);
        string four = Describe(baker.Bake(new BakeSettings { Seed = 11, MaxNodes = 40, Threads = 4, BatchSize = 16 }).Roadmap);
        string otherSeed = Describe(baker.Bake(new BakeSettings { Seed = 12, MaxNodes = 40, Threads = 2 }).Roadmap);
        Assert.Multiple(() =>
        {
            Assert.That(two, Is.EqualTo(one));
            Assert.That(four, Is.EqualTo(one));
            Assert.That(otherSeed, Is.Not.EqualTo(one));
        });
    }

    [Test]
    public void APlanAcrossTheGapCourseChainsValidJumps()
    {
        BakeResult bake = new RoadmapBaker(Scene.Value).Bake(new BakeSettings { Seed = 5, MaxNodes = 120, Threads = 2 });
        PlanResult plan = new PathQuery(Scene.Value, bake.Roadmap).Plan(GapCourse.From, GapCourse.To);
        Assert.That(plan.Status, Is.EqualTo(PlannerStatus.Exact), plan.Reason);
        Assert.That(plan.Jumps, Has.Count.GreaterThanOrEqualTo(3), "four platforms need at least three jumps");
        // The radius bounds where the character stands: on these flat platforms, the root's horizontal offset.
        Assert.That(Horizontal(plan.Start!.Pose.Position - GapCourse.From), Is.LessThan(1.5f + 1e-3f));
        Assert.That(Horizontal(plan.Goal!.Pose.Position - GapCourse.To), Is.LessThan(1.5f + 1e-3f));
        for (int k = 0; k < plan.Jumps.Count; k++)
        {
            Jump jump = plan.Jumps[k];
            PhysicsChecks.AssertJump(Scene.Value, jump.Takeoff, jump.Landing, jump.Arc, $"jump {k}");
            if (k > 0)
            {
                Assert.That(jump.Takeoff, Is.SameAs(plan.Jumps[k - 1].Landing), $"jump {k} does not start where jump {k - 1} landed");
            }
        }

        Assert.Multiple(() =>
        {
            Assert.That(plan.Jumps[0].Takeoff, Is.SameAs(plan.Start));
            Assert.That(plan.Jumps[^1].Landing, Is.SameAs(plan.Goal));
            Assert.That(plan.TotalFlightTime, Is.EqualTo(plan.Jumps.Sum(j => j.Arc.FlightTime)));
        });
    }

    [Test]
    public void QueryFailuresSayWhy()
    {
        BakeResult bake = new RoadmapBaker(Scene.Value).Bake(new BakeSettings { Seed = 5, MaxNodes = 30 });
        var query = new PathQuery(Scene.Value, bake.Roadmap);
        PlanResult inTheAir = query.Plan(new Vector3(0f, 30f, 0f), GapCourse.To);
        PlanResult goalInTheAir = query.Plan(GapCourse.From, new Vector3(0f, 30f, 40f));
        Assert.Multiple(() =>
        {
            Assert.That(inTheAir.Status, Is.EqualTo(PlannerStatus.InvalidStart));
            Assert.That(inTheAir.Reason, Does.Contain("start").And.Contain("0.5 m across and 0.25 m up/down"));
            Assert.That(goalInTheAir.Status, Is.EqualTo(PlannerStatus.InvalidGoal));
        });

        // Two islands 30 m apart: nothing can jump that far.
        Level islands = new LevelBuilder("islands")
            .AddBox(new Vector3(-3f, -1f, -2f), new Vector3(0f, 0f, 2f))
            .AddBox(new Vector3(30f, -1f, -2f), new Vector3(33f, 0f, 2f))
            .Build();
        var scene = PlanningScene.Create(islands, CharacterPresets.Skeleton());
        BakeResult islandBake = new RoadmapBaker(scene).Bake(new BakeSettings { MaxNodes = 20 });
        PlanResult none = new PathQuery(scene, islandBake.Roadmap).Plan(new Vector3(-1.5f, 0f, 0f), new Vector3(31.5f, 0f, 0f));
        Assert.That(none.Status, Is.EqualTo(PlannerStatus.NoPath));
        Assert.That(none.Reason, Does.Contain("no sequence of moves (jumps or walks)"));
    }

    [Test]
    public void TerminationConditionsCompose()
    {
        var baker = new RoadmapBaker(Scene.Value);
        using var cancelled = new CancellationTokenSource();
        cancelled.Cancel();
        BakeResult cancelledBake = baker.Bake(new BakeSettings { MaxNodes = 1_000 }, TerminationCondition.Cancellation(cancelled.Token));
        BakeResult timed = baker.Bake(new BakeSettings { MaxNodes = null, TimeLimit = TimeSpan.FromMilliseconds(200) });
        BakeResult custom = baker.Bake(new BakeSettings { MaxNodes = 1_000 }, TerminationCondition.When(s => s.Edges >= 30, PlannerStatus.Exact, "enough jumps"));
        BakeResult connected = baker.Bake(new BakeSettings { MaxNodes = 500, Start = GapCourse.From, Goal = GapCourse.To, StopWhenConnected = true });

        Assert.Multiple(() =>
        {
            Assert.That(cancelledBake.Status, Is.EqualTo(PlannerStatus.Cancelled));
            Assert.That(timed.Status, Is.EqualTo(PlannerStatus.Timeout));
            Assert.That(timed.Reason, Does.Contain("time budget"));
            Assert.That(custom.Status, Is.EqualTo(PlannerStatus.Exact));
            Assert.That(custom.Reason, Is.EqualTo("enough jumps"));
            Assert.That(custom.Roadmap.Edges, Has.Count.GreaterThanOrEqualTo(30));
            Assert.That(connected.Status, Is.EqualTo(PlannerStatus.Exact), connected.Reason);
            Assert.That(connected.Roadmap.Reaches(connected.StartNode!.Value, connected.GoalNode!.Value), Is.True);
            Assert.That(connected.Roadmap.Nodes, Has.Count.LessThan(500), "stopped as soon as connected");
        });
        Assert.That(() => baker.Bake(new BakeSettings { MaxNodes = null }), Throws.ArgumentException.With.Message.Contains("Nothing would stop"));
    }

    [Test]
    public void ALevelWithNowhereToStandEndsInsteadOfHanging()
    {
        // A vertical wall only: the skeleton's limbs all need upward surfaces.
        Level wall = new LevelBuilder("wall").AddBox(new Vector3(0f, 0f, 0f), new Vector3(0.001f, 5f, 5f)).Build();
        var scene = PlanningScene.Create(wall, CharacterPresets.Skeleton());
        BakeResult result = new RoadmapBaker(scene).Bake(new BakeSettings { MaxNodes = 10 });
        Assert.Multiple(() =>
        {
            Assert.That(result.Status, Is.EqualTo(PlannerStatus.NoPath));
            Assert.That(result.Reason, Does.Contain("can stand nowhere"));
            Assert.That(result.Roadmap.Nodes, Is.Empty);
        });
    }

    private static float Horizontal(Vector3 v) => new Vector2(v.X, v.Z).Length();

    internal static string Describe(Roadmap roadmap)
    {
        var text = new System.Text.StringBuilder();
        foreach (RoadmapNode n in roadmap.Nodes)
        {
            text.Append(System.FormattableString.Invariant($"n{n.Id} {n.Pose.Position:R} {n.Pose.Rotation:R} {n.Cone.Axis:R} {n.Cone.Mu:R} {n.Contacts.Count}\n"));
        }

        foreach (RoadmapEdge e in roadmap.Edges)
        {
            text.Append(System.FormattableString.Invariant($"e{e.From}-{e.To} {e.Arc.TakeoffVelocity:R} {e.Arc.FlightTime:R}\n"));
        }

        return text.ToString();
    }
}
