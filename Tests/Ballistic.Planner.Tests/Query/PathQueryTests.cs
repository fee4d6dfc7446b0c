using System.Numerics;
using System.Text;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Query;

/// <summary>Requests from stances already on (or off) the roadmap, rejected jumps, search effort and early stops.</summary>
public sealed class PathQueryTests
{
    private static readonly Lazy<PlanningScene> Scene = new(() => PlanningScene.Create(GapCourse.Build(), CharacterPresets.Skeleton().WithWalking(WalkingLimits.None))); // the paper's jumping skeleton: these test the jump planner

    /// <summary>A bake given the course's start and goal: they are roadmap nodes.</summary>
    private static readonly Lazy<BakeResult> WithEndpoints = new(() =>
        new RoadmapBaker(Scene.Value).Bake(new BakeSettings { Seed = 2, MaxNodes = 150, Threads = 2, Start = GapCourse.From, Goal = GapCourse.To }));

    /// <summary>A bake of random samples only: requested points are placed off the roadmap.</summary>
    private static readonly Lazy<Roadmap> Plain = new(() =>
        new RoadmapBaker(Scene.Value).Bake(new BakeSettings { Seed = 5, MaxNodes = 150, Threads = 2 }).Roadmap);

    /// <summary>Points on the course's platforms, for requests.</summary>
    private static readonly Vector3[] Points =
    [
        GapCourse.From, GapCourse.To, new(-4f, 0f, 1f), new(0f, 0f, -1f), new(4f, 0f, 0.5f), new(7f, 0f, -1f), new(10.5f, 1f, 1f), new(12f, 1f, -1f),
    ];

    /// <summary>Everything a result says about its path: status, end ids, and each jump's nodes and arc.</summary>
    internal static string Describe(PlanResult result)
    {
        var text = new StringBuilder();
        text.Append(FormattableString.Invariant($"{result.Status} start {result.Start?.Id} {result.Start?.Pose.Position:R} goal {result.Goal?.Id} {result.Goal?.Pose.Position:R}:"));
        foreach (Jump j in result.Jumps)
        {
            text.Append(FormattableString.Invariant($" {j.Takeoff.Id}>{j.Landing.Id} {j.Arc.TakeoffVelocity:R} {j.Arc.FlightTime:R} {j.Arc.Start:R}"));
        }

        return text.ToString();
    }

    /// <summary>The search alone: turning jumps to face their way adds stances of its own (and places a goal again), see <see cref="JumpFacingTests"/>.</summary>
    private static readonly QuerySettings Searched = new() { FaceJumps = false };

    [Test]
    public void BetweenTheNodesAPointRequestPlacedOnTheSearchIsTheSame()
    {
        BakeResult bake = WithEndpoints.Value;
        Roadmap roadmap = bake.Roadmap;
        var query = new PathQuery(Scene.Value, roadmap);
        PlanResult byPoints = query.Plan(GapCourse.From, GapCourse.To, Searched);
        Assert.That(byPoints.Status, Is.EqualTo(PlannerStatus.Exact), byPoints.Reason);
        Assert.That(byPoints.Start!.Id, Is.EqualTo(bake.StartNode), "the start point places on the baked start node");
        Assert.That(byPoints.Goal!.Id, Is.EqualTo(bake.GoalNode));

        RoadmapNode start = roadmap.Nodes[bake.StartNode!.Value];
        RoadmapNode goal = roadmap.Nodes[bake.GoalNode!.Value];
        PlanResult byNodes = query.Plan(start, goal, Searched);
        PlanResult byNodeAndPoint = query.Plan(start, GapCourse.To, Searched);
        Assert.Multiple(() =>
        {
            Assert.That(Describe(byNodes), Is.EqualTo(Describe(byPoints)));
            Assert.That(Describe(byNodeAndPoint), Is.EqualTo(Describe(byPoints)));
            Assert.That(byNodes.Start, Is.SameAs(start), "a roadmap node is used as is");
            Assert.That(byNodes.StartPlacement, Is.Null, "nothing was placed");
            Assert.That(byNodes.GoalPlacement, Is.Null);
            Assert.That(byNodeAndPoint.GoalPlacement!.Placed, Is.True);
            Assert.That(byNodes.Expansions, Is.EqualTo(byPoints.Expansions).And.GreaterThan(0));
        });
    }

    [Test]
    public void ThePlacedEndsOfAPointRequestGiveTheSamePathAsNodes()
    {
        Roadmap roadmap = Plain.Value;
        var query = new PathQuery(Scene.Value, roadmap);
        int n = roadmap.Nodes.Count;
        int compared = 0;
        foreach (Vector3 from in Points)
        {
            foreach (Vector3 to in Points)
            {
                PlanResult byPoints = query.Plan(from, to, Searched);
                if (byPoints.Start is null || byPoints.Goal is null)
                {
                    continue;
                }

                // The placed stances off the roadmap keep their ids (n and n + 1), so the node requests repeat the point request.
                Assert.That(Describe(query.Plan(byPoints.Start, byPoints.Goal, Searched)), Is.EqualTo(Describe(byPoints)), $"{from} → {to}");
                Assert.That(Describe(query.Plan(byPoints.Start, to, Searched)), Is.EqualTo(Describe(byPoints)), $"{from} → {to}");
                compared += byPoints.Status == PlannerStatus.Exact && byPoints.Start.Id == n && byPoints.Goal.Id == n + 1 ? 1 : 0;
            }
        }

        Assert.That(compared, Is.GreaterThan(20), "most requests place both ends off the roadmap and find a path");
    }

    [Test]
    public void AStartOffTheRoadmapIsSteeredIntoIt()
    {
        Roadmap roadmap = Plain.Value;
        var query = new PathQuery(Scene.Value, roadmap);
        int n = roadmap.Nodes.Count;

        // An agent ends a first plan on its goal (id n + 1, off the roadmap) and plans on from there.
        PlanResult first = query.Plan(GapCourse.From, new Vector3(4f, 0f, 0.5f));
        Assert.That(first.Status, Is.EqualTo(PlannerStatus.Exact), first.Reason);
        Assert.That(first.Goal!.Id, Is.EqualTo(n + 1));
        PlanResult second = query.Plan(first.Goal, GapCourse.To);
        PlanResult toNode = query.Plan(first.Goal, roadmap.Nodes[roadmap.Nodes.Count / 2]);

        // Any evaluated stance, whatever id it carries, is steered in as id n.
        RoadmapNode stance = first.Goal with { Id = 123_456 };
        PlanResult third = query.Plan(stance, GapCourse.To);
        Assert.Multiple(() =>
        {
            Assert.That(second.Status, Is.EqualTo(PlannerStatus.Exact), second.Reason);
            Assert.That(second.Start!.Id, Is.EqualTo(n));
            Assert.That(second.Start.Pose, Is.EqualTo(first.Goal.Pose));
            Assert.That(second.Jumps[0].Takeoff, Is.SameAs(second.Start));
            Assert.That(third.Start!.Id, Is.EqualTo(n));
            Assert.That(Describe(third), Is.EqualTo(Describe(second)));
            Assert.That(toNode.Status, Is.EqualTo(PlannerStatus.Exact), toNode.Reason);
            Assert.That(toNode.Goal, Is.SameAs(roadmap.Nodes[roadmap.Nodes.Count / 2]));
        });
        for (int k = 0; k < second.Jumps.Count; k++)
        {
            Jump jump = second.Jumps[k];
            PhysicsChecks.AssertJump(Scene.Value, jump.Takeoff, jump.Landing, jump.Arc, $"jump {k}");
        }

        // A stance standing exactly on a roadmap node is that node, whatever id it carries.
        RoadmapNode onRoadmap = roadmap.Nodes[7] with { Id = 99_999 };
        Assert.That(query.Plan(onRoadmap, GapCourse.To).Start, Is.SameAs(roadmap.Nodes[7]));
    }

    [Test]
    public void RejectedJumpsAreNeverUsed()
    {
        BakeResult bake = WithEndpoints.Value;
        Roadmap roadmap = bake.Roadmap;
        var query = new PathQuery(Scene.Value, roadmap);
        RoadmapNode start = roadmap.Nodes[bake.StartNode!.Value];
        RoadmapNode goal = roadmap.Nodes[bake.GoalNode!.Value];
        var rejected = new HashSet<(int From, int To)>();
        float previous = 0f;
        PlanResult result = query.Plan(start, goal, Searched, rejected: rejected);
        int rounds = 0;
        for (; result.Status == PlannerStatus.Exact && rounds < 40; rounds++)
        {
            Assert.That(result.Jumps.Any(j => rejected.Contains((j.Takeoff.Id, j.Landing.Id))), Is.False, "a rejected jump was used");
            Assert.That(result.TotalFlightTime, Is.GreaterThanOrEqualTo(previous - 1e-4f), "removing jumps never shortens the best path");
            previous = result.TotalFlightTime;
            Jump middle = result.Jumps[result.Jumps.Count / 2];
            rejected.Add((middle.Takeoff.Id, middle.Landing.Id));
            result = query.Plan(start, goal, Searched, rejected: rejected);
        }

        Assert.That(rounds, Is.GreaterThan(1));
        if (result.Status != PlannerStatus.Exact)
        {
            Assert.That(result.Status, Is.EqualTo(PlannerStatus.NoPath));
            Assert.That(result.Reason, Does.Contain("set aside"));
        }

        // Off the roadmap too: the start's own jumps (from id n) can be rejected.
        Roadmap plain = Plain.Value;
        var plainQuery = new PathQuery(Scene.Value, plain);
        PlanResult open = plainQuery.Plan(GapCourse.From, GapCourse.To);
        Assert.That(open.Status, Is.EqualTo(PlannerStatus.Exact), open.Reason);
        var firstJump = new HashSet<(int From, int To)> { (open.Jumps[0].Takeoff.Id, open.Jumps[0].Landing.Id) };
        foreach (PlanResult again in new[] { plainQuery.Plan(GapCourse.From, GapCourse.To, null, firstJump), plainQuery.Plan(open.Start!, GapCourse.To, rejected: firstJump), plainQuery.Plan(open.Start!, open.Goal!, rejected: firstJump) })
        {
            Assert.That(again.Jumps.Any(j => firstJump.Contains((j.Takeoff.Id, j.Landing.Id))), Is.False);
        }
    }

    [Test]
    public void TheSameStanceAtBothEndsIsAPlanOfNoJumps()
    {
        Roadmap roadmap = Plain.Value;
        var query = new PathQuery(Scene.Value, roadmap);
        PlanResult same = query.Plan(roadmap.Nodes[3], roadmap.Nodes[3]);
        PlanResult offRoadmap = query.Plan(GapCourse.From, GapCourse.From);
        PlanResult sameOff = query.Plan(offRoadmap.Start!, offRoadmap.Start! with { Id = 5_000 });
        Assert.Multiple(() =>
        {
            Assert.That(same.Status, Is.EqualTo(PlannerStatus.Exact));
            Assert.That(same.Jumps, Is.Empty);
            Assert.That(same.Expansions, Is.Zero);
            Assert.That(sameOff.Jumps, Is.Empty);
            Assert.That(sameOff.Start, Is.SameAs(sameOff.Goal));
        });
    }

    [Test]
    public void RequestsStopOnTheirTerminationCondition()
    {
        BakeResult bake = WithEndpoints.Value;
        Roadmap roadmap = bake.Roadmap;
        var query = new PathQuery(Scene.Value, roadmap);
        using var source = new CancellationTokenSource();
        source.Cancel();
        TerminationCondition cancelled = TerminationCondition.Cancellation(source.Token);
        TerminationCondition expired = TerminationCondition.Timeout(TimeSpan.FromTicks(1));
        RoadmapNode start = roadmap.Nodes[bake.StartNode!.Value];
        RoadmapNode goal = roadmap.Nodes[bake.GoalNode!.Value];
        PlanResult[] stopped =
        [
            query.Plan(GapCourse.From, GapCourse.To, null, null, cancelled),
            query.Plan(start, GapCourse.To, termination: cancelled),
            query.Plan(start, goal, termination: TerminationCondition.NodeCount(1) | cancelled),
        ];
        Assert.Multiple(() =>
        {
            foreach (PlanResult result in stopped)
            {
                Assert.That(result.Status, Is.EqualTo(PlannerStatus.Cancelled));
                Assert.That(result.Reason, Is.EqualTo("cancelled"));
                Assert.That(result.Jumps, Is.Empty);
            }

            PlanResult late = query.Plan(GapCourse.From, GapCourse.To, null, null, expired);
            Assert.That(late.Status, Is.EqualTo(PlannerStatus.Timeout));
            Assert.That(late.Reason, Does.Contain("time budget"));

            // Conditions that only a bake can answer never stop a request.
            PlanResult unbothered = query.Plan(start, goal, termination: TerminationCondition.NodeCount(1) | TerminationCondition.When(_ => true, PlannerStatus.Exact, "always"));
            Assert.That(unbothered.Status, Is.EqualTo(PlannerStatus.Exact));
        });
    }

    [Test]
    public void FindNodeKeepsToBothPartsOfTheTolerance()
    {
        // Contact centres (the mean of each node's contacts) at known places; node 3 has no contacts (its trunk counts).
        var builder = new RoadmapBuilder(new string('a', 64), new string('b', 64), "test", 1);
        Vector3[] centres = [new(0f, 0f, 0f), new(0.4f, 0f, 0f), new(0f, 0.2f, 0f), new(-0.1f, 1f, 0f), new(0.4f, 0f, 0f)];
        for (int i = 0; i < centres.Length; i++)
        {
            Contact[] contacts = i == 3
                ? []
                : [new(0, centres[i] + new Vector3(0.1f, 0f, 0.1f), Vector3.UnitY, 1f, 0), new(1, centres[i] - new Vector3(0.1f, 0f, 0.1f), Vector3.UnitY, 1f, 0)];
            var pose = new RootPose(i == 3 ? centres[i] : centres[i] + new Vector3(0f, 0.9f, 0f), Quaternion.Identity);
            builder.AddNode(new RoadmapNode(i, pose, new FrictionCone(Vector3.UnitY, 1f), contacts));
        }

        Roadmap roadmap = builder.Freeze();
        var tolerance = new EndpointTolerance(0.5f, 0.25f);
        Assert.Multiple(() =>
        {
            Assert.That(roadmap.ContactCentres[1], Is.EqualTo(centres[1]));
            Assert.That(roadmap.ContactCentres[3], Is.EqualTo(centres[3]), "a node without contacts is measured from its trunk");
            Assert.That(roadmap.FindNode(new Vector3(0.1f, 0f, 0f), tolerance), Is.EqualTo(0));
            Assert.That(roadmap.FindNode(new Vector3(0.3f, 0f, 0f), tolerance), Is.EqualTo(1), "nearest wins; of two at the same place, the lower id");
            Assert.That(roadmap.FindNode(new Vector3(0.3f, 0f, 0f), new EndpointTolerance(0.05f, 0.25f)), Is.Null, "too far across");
            Assert.That(roadmap.FindNode(new Vector3(0f, 0.3f, 0f), tolerance), Is.EqualTo(2), "node 0 is 0.3 m below, beyond 0.25 m");
            Assert.That(roadmap.FindNode(new Vector3(0f, 0.3f, 0f), new EndpointTolerance(0.5f, 0.05f)), Is.Null, "too far up or down");
            Assert.That(roadmap.FindNode(new Vector3(0f, 0.7f, 0.45f), tolerance), Is.Null, "across and up/down each within bounds of some node, never both");
            Assert.That(roadmap.FindNode(new Vector3(0f, 0.9f, 0f), tolerance), Is.EqualTo(3));
            Assert.That(roadmap.FindNode(new Vector3(5f, 0f, 0f), tolerance), Is.Null);
            Assert.That(() => roadmap.FindNode(new Vector3(float.NaN, 0f, 0f), tolerance), Throws.ArgumentException);
            Assert.That(() => roadmap.FindNode(Vector3.Zero, new EndpointTolerance(0f, 1f)), Throws.ArgumentException);
        });
    }

    [Test]
    public void PreferringRoadmapNodesSkipsPlacementWhenOneStandsWithinTheTolerance()
    {
        Roadmap roadmap = Plain.Value;
        var query = new PathQuery(Scene.Value, roadmap);
        var settings = new QuerySettings { PreferRoadmapNodes = true };
        int reused = 0;
        Vector3[] points = [.. Points, .. Enumerable.Range(0, 6).Select(k => roadmap.ContactCentres[k * 20] + new Vector3(0.05f, 0.02f, 0f))];
        foreach (Vector3 from in points)
        {
            foreach (Vector3 to in points)
            {
                PlanResult result = query.Plan(from, to, settings);
                PlanResult placed = query.Plan(from, to);
                if (result.Start is not { } start)
                {
                    continue;
                }

                Assert.That(result.StartPlacement!.Across, Is.LessThanOrEqualTo(0.5f));
                Assert.That(result.StartPlacement.UpDown, Is.LessThanOrEqualTo(0.25f));
                var close = new EndpointTolerance();
                int? nearTo = roadmap.FindNode(to, close);
                if (roadmap.FindNode(from, close) is int near)
                {
                    Assert.That(start, Is.SameAs(roadmap.Nodes[near]));
                    Assert.That(result.StartPlacement.Pose!.Pose, Is.EqualTo(start.Pose));
                    reused++;
                }
                else if (nearTo is null)
                {
                    Assert.That(Describe(result), Is.EqualTo(Describe(placed)), "without a node close enough, the stances are placed as usual");
                }
            }
        }

        Assert.That(reused, Is.GreaterThan(0));

        // A node that cannot stand there is not taken.
        Vector3 atNode = roadmap.ContactCentres[10];
        PlanResult refused = query.Plan(atNode, GapCourse.To, settings with { CanStand = p => p.Pose != roadmap.Nodes[10].Pose });
        PlanResult taken = query.Plan(atNode, GapCourse.To, settings);
        Assert.That(taken.Start, Is.SameAs(roadmap.Nodes[10]));
        Assert.That(refused.Start, Is.Not.SameAs(roadmap.Nodes[10]));
    }
}
