using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Planning;

/// <summary>Extra pose and arc validators given to a planning scene decide what bakes and queries may use.</summary>
public sealed class ValidatorTests
{
    private static readonly BakeSettings Settings = new() { Seed = 5, MaxNodes = 80, Threads = 2 };

    [Test]
    public void APoseValidatorKeepsNodesStartsAndGoalsOutOfAForbiddenZone()
    {
        var zone = new ForbiddenZone(new Aabb(new Vector3(-1.6f, -1f, 0f), new Vector3(1.6f, 3f, 2.1f)));
        var plain = PlanningScene.Create(GapCourse.Build(), CharacterPresets.Skeleton());
        var guarded = PlanningScene.Create(GapCourse.Build(), CharacterPresets.Skeleton(), poseValidator: zone);

        Roadmap before = new RoadmapBaker(plain).Bake(Settings).Roadmap;
        BakeResult after = new RoadmapBaker(guarded).Bake(Settings);
        Assert.That(before.Nodes.Count(n => zone.Box.Contains(n.Pose.Position)), Is.GreaterThan(0), "without the validator the zone holds nodes, so the test can fail");
        Assert.That(after.Status, Is.EqualTo(PlannerStatus.Exact), after.Reason);
        Assert.Multiple(() =>
        {
            Assert.That(after.Roadmap.Nodes.Where(n => zone.Box.Contains(n.Pose.Position)).Select(n => n.Id), Is.Empty, "no node in the zone");
            Assert.That(after.Roadmap.Nodes, Has.Count.EqualTo(Settings.MaxNodes), "the sampler finds its nodes elsewhere");
            Assert.That(zone.SawOnlyValidPoses, Is.True, "the validator is asked only about poses the built-in checks accept");
        });

        var query = new PathQuery(guarded, after.Roadmap);
        PlanResult intoZone = query.Plan(GapCourse.From, new Vector3(0f, 0f, 1f));
        Assert.That(intoZone.Status, Is.EqualTo(PlannerStatus.InvalidGoal), intoZone.Reason);
        PlanResult across = query.Plan(GapCourse.From, GapCourse.To);
        Assert.That(across.Status, Is.EqualTo(PlannerStatus.Exact), across.Reason);
        Assert.That(across.Jumps.Select(j => j.Landing.Pose.Position).Where(zone.Box.Contains), Is.Empty, "the path lands nowhere in the zone");
    }

    [Test]
    public void AnEstimatorReportsAPoseItsValidatorRefusesAsRejected()
    {
        var refuseAll = new ForbiddenZone(new Aabb(new Vector3(-100f), new Vector3(100f)));
        var scene = PlanningScene.Create(GapCourse.Build(), CharacterPresets.Skeleton(), poseValidator: refuseAll);
        var plain = PlanningScene.Create(GapCourse.Build(), CharacterPresets.Skeleton());
        RoadmapNode node = new RoadmapBaker(plain).Bake(Settings with { MaxNodes = 5 }).Roadmap.Nodes[0];
        Assert.Multiple(() =>
        {
            Assert.That(plain.Estimator.Evaluate(node.Pose).Validity, Is.EqualTo(PoseValidity.Valid));
            Assert.That(scene.Estimator.Evaluate(node.Pose).Validity, Is.EqualTo(PoseValidity.Rejected));
            Assert.That(scene.Estimator.Evaluate(new RootPose(new Vector3(0f, 0.05f, 0f), Quaternion.Identity)).Validity, Is.EqualTo(PoseValidity.TrunkCollides), "built-in failures keep their reason");
        });
    }

    [Test]
    public void AnArcValidatorBoundsEveryJumpOfTheBake()
    {
        var shortHops = new MaxFlightTime(0.55f);
        var plain = PlanningScene.Create(GapCourse.Build(), CharacterPresets.Skeleton());
        var bounded = PlanningScene.Create(GapCourse.Build(), CharacterPresets.Skeleton(), arcValidator: shortHops);

        Roadmap before = new RoadmapBaker(plain).Bake(Settings).Roadmap;
        BakeResult after = new RoadmapBaker(bounded).Bake(Settings);
        Assert.That(before.Edges.Count(e => e.Arc.FlightTime > shortHops.Seconds), Is.GreaterThan(0), "without the validator some jumps are longer, so the test can fail");
        Assert.That(after.Roadmap.Edges, Is.Not.Empty);
        Assert.That(after.SteeringRejections.Keys, Does.Contain(SteeringFailure.Collision), "refused arcs are counted as refused by the arc validator");
        foreach (RoadmapEdge edge in after.Roadmap.Edges)
        {
            Assert.That(edge.Arc.FlightTime, Is.LessThanOrEqualTo(shortHops.Seconds), $"edge {edge.From}→{edge.To}");
            PhysicsChecks.AssertJump(bounded, after.Roadmap.Nodes[edge.From], after.Roadmap.Nodes[edge.To], edge.Arc, $"edge {edge.From}→{edge.To}");
        }
    }

    [Test]
    public void TheTrunkSweepStillRunsBeforeAnExtraArcValidator()
    {
        Level walled = new LevelBuilder("walled")
            .AddBox(new Vector3(-6f, -1f, -3f), new Vector3(6f, 0f, 3f))
            .AddBox(new Vector3(-0.05f, 0f, -3f), new Vector3(0.05f, 2.2f, 3f))
            .Build();
        BakeResult plain = new RoadmapBaker(PlanningScene.Create(walled, CharacterPresets.Skeleton())).Bake(Settings);
        BakeResult accepting = new RoadmapBaker(PlanningScene.Create(walled, CharacterPresets.Skeleton(), arcValidator: new MaxFlightTime(float.PositiveInfinity))).Bake(Settings);
        Assert.That(plain.SteeringRejections.GetValueOrDefault(SteeringFailure.Collision), Is.GreaterThan(0), "the sweep refuses jumps through the wall");
        Assert.That(
            accepting.Roadmap.Edges.Select(e => (e.From, e.To, e.Arc.TakeoffVelocity)),
            Is.EqualTo(plain.Roadmap.Edges.Select(e => (e.From, e.To, e.Arc.TakeoffVelocity))),
            "an extra validator that accepts everything changes nothing: the sweep still refuses the same jumps");
    }

    [Test]
    public void ASteeringMethodUsesTheArcValidatorItIsGiven()
    {
        var limits = new Ballistic.Planner.Characters.SteeringLimits(8f, 12f);
        var up = new FrictionCone(Vector3.UnitY, 1f);
        var a = new RootPose(Vector3.Zero, Quaternion.Identity);
        var b = new RootPose(new Vector3(2f, 0f, 0f), Quaternion.Identity);
        Assert.Multiple(() =>
        {
            Assert.That(new ParabolaSteering(limits, new Vector3(0.2f), arcValidator: new MaxFlightTime(10f)).Steer(a, up, b, up).Succeeded, Is.True);
            Assert.That(new ParabolaSteering(limits, new Vector3(0.2f), arcValidator: new MaxFlightTime(0.01f)).Steer(a, up, b, up).Failure, Is.EqualTo(SteeringFailure.Collision));
        });
    }

    /// <summary>Refuses poses whose root lies in a box, and notes whether it was ever asked about an invalid pose.</summary>
    private sealed class ForbiddenZone(Aabb box) : IPoseValidator
    {
        private int _sawInvalid;

        public Aabb Box { get; } = box;

        public bool SawOnlyValidPoses => Volatile.Read(ref _sawInvalid) == 0;

        public bool IsValid(PoseEvaluation evaluation)
        {
            if (!evaluation.IsValid || evaluation.Contacts.Count == 0)
            {
                Interlocked.Exchange(ref _sawInvalid, 1);
            }

            return !Box.Contains(evaluation.Pose.Position);
        }
    }

    /// <summary>Refuses arcs whose flight lasts longer than a bound.</summary>
    private sealed class MaxFlightTime(float seconds) : IArcValidator
    {
        public float Seconds { get; } = seconds;

        public bool IsValid(in BallisticArc arc) => arc.FlightTime <= Seconds;
    }
}
