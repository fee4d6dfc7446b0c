using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Authoring.Levels;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Animation;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Walking;

/// <summary>Walks in the roadmap and in paths: baked, saved, searched and shortcut, checked by the independent audit.</summary>
public sealed class WalkPlanTests
{
    private static readonly Lazy<(PlanningScene Scene, Roadmap Walking, Roadmap Jumping)> Course = new(() =>
    {
        var scene = PlanningScene.Create(GapCourse.Build(), CharacterPresets.Skeleton());
        var settings = new BakeSettings { Seed = 2, MaxNodes = 150, Threads = 2, Locomotion = Locomotion.WalkAndJump };
        return (scene, new RoadmapBaker(scene).Bake(settings).Roadmap, new RoadmapBaker(scene).Bake(settings with { Locomotion = Locomotion.Jump }).Roadmap);
    });

    private static readonly Lazy<(PlanningScene Scene, Vector3 From, Vector3 To, Roadmap Roadmap)> Desert = new(() =>
    {
        var scene = PlanningScene.Create(LevelGenerator.BuildLevel("desert"), CharacterPresets.Skeleton());
        Vector3 from = Ground(scene, -9.5f, -7.5f);
        Vector3 to = Ground(scene, 9.5f, 7.5f);
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 1, MaxNodes = 300, Threads = 2, Start = from, Goal = to, Locomotion = Locomotion.WalkAndJump }).Roadmap;
        return (scene, from, to, roadmap);
    });

    private static readonly QuerySettings Walking = new() { Locomotion = Locomotion.WalkAndJump };

    private static Vector3 Ground(PlanningScene scene, float x, float z) =>
        scene.Bvh.Raycast(new Vector3(x, 100f, z), -Vector3.UnitY, 200f, out RayHit hit) ? hit.Point : throw new InvalidOperationException("no ground");

    [Test]
    public void WalksAreAddedToTheSameJumpsAndEachTracesAgainOnTheSamePlatform()
    {
        (PlanningScene scene, Roadmap walking, Roadmap jumping) = Course.Value;
        Assert.That(walking.Walks, Is.Not.Empty);
        Assert.That(jumping.Walks, Is.Empty);

        // Walking adds edges; it changes no node and no jump.
        Assert.That(walking.Nodes.Select(n => n.Pose), Is.EqualTo(jumping.Nodes.Select(n => n.Pose)));
        Assert.That(walking.Edges, Is.EqualTo(jumping.Edges));

        // Platforms of the course along X (a walk never crosses a gap): -8..-3, -1.5..1.5, 3..8, 9.5..13.
        static int Platform(float x) => x < -2.25f ? 0 : x < 2.25f ? 1 : x < 8.75f ? 2 : 3;
        foreach (RoadmapWalk edge in walking.Walks)
        {
            Vector3 a = walking.ContactCentres[edge.From];
            Vector3 b = walking.ContactCentres[edge.To];
            Assert.That(Platform(a.X), Is.EqualTo(Platform(b.X)), $"walk {edge.From} → {edge.To} crosses a gap");
            Walk? again = scene.Walking.Steer(walking.Nodes[edge.From], walking.Nodes[edge.To]).Walk;
            Assert.That(again, Is.Not.Null);
            Assert.That(again!.Length, Is.EqualTo(edge.Length).Within(1e-4f));
            Assert.That(edge.Duration, Is.EqualTo(edge.Length / scene.Character.Walking.Speed).Within(1e-4f));
        }
    }

    [Test]
    public void ARoadmapWithWalksRoundTripsAsVersionTwoAndAJumpOnlyOneStaysVersionOne()
    {
        (PlanningScene scene, Roadmap walking, Roadmap jumping) = Course.Value;
        byte[] bytes = RoadmapFile.ToBytes(walking);
        byte[] jumpBytes = RoadmapFile.ToBytes(jumping);
        Roadmap back = RoadmapFile.FromBytes(bytes, "walks.roadmap", scene.Level, scene.Character);
        Assert.Multiple(() =>
        {
            Assert.That(BitConverter.ToUInt16(bytes, 8), Is.EqualTo(2));
            Assert.That(BitConverter.ToUInt16(jumpBytes, 8), Is.EqualTo(1));
            Assert.That(back.Walks, Is.EqualTo(walking.Walks));
            Assert.That(RoadmapFile.ToBytes(back), Is.EqualTo(bytes));
            Assert.That(RoadmapFile.FromBytes(jumpBytes, "jumps.roadmap", scene.Level, scene.Character).Edges, Is.EqualTo(jumping.Edges));
        });

        // A character that does not walk cannot use a roadmap with walks (its fingerprint differs, and it is said).
        Assert.That(() => RoadmapFile.FromBytes(bytes, "walks.roadmap", scene.Level, scene.Character.WithWalking(Ballistic.Planner.Characters.WalkingLimits.None)),
            Throws.InstanceOf<RoadmapFileException>().With.Message.Contains("walks.roadmap"));
    }

    [Test]
    public void OnTheGapCourseTheSkeletonWalksThePlatformsAndJumpsOnlyTheGaps()
    {
        (PlanningScene scene, Roadmap walking, Roadmap jumping) = Course.Value;
        PlanResult walked = new PathQuery(scene, walking).Plan(GapCourse.From, GapCourse.To, Walking);
        PlanResult jumped = new PathQuery(scene, jumping).Plan(GapCourse.From, GapCourse.To, new QuerySettings { Locomotion = Locomotion.Jump });
        Assert.That(walked.Status, Is.EqualTo(PlannerStatus.Exact), walked.Reason);
        Assert.That(jumped.Status, Is.EqualTo(PlannerStatus.Exact), jumped.Reason);
        Assert.Multiple(() =>
        {
            Assert.That(walked.Walks, Is.Not.Empty);
            Assert.That(walked.Jumps, Has.Count.LessThan(jumped.Jumps.Count));
            Assert.That(jumped.Walks, Is.Empty, "jump-only mode is the paper's planner");

            // Every jump left is one the ground requires: no walk links its ends.
            foreach (Jump jump in walked.Jumps)
            {
                Assert.That(scene.Walking.Steer(jump.Takeoff, jump.Landing).Succeeded, Is.False, $"jump {jump.Takeoff.Id} → {jump.Landing.Id} could be walked");
            }
        });

        AuditReport audit = PlanAudit.Check("gap course walk+jump", scene, GapCourse.From, GapCourse.To, walked, null);
        Assert.That(audit.Violations, Is.Empty, string.Join("; ", audit.Violations));
        Assert.That(audit.Walks, Is.EqualTo(walked.Walks.Count()));
    }

    [Test]
    public void OnTheDesertTheSkeletonWalksWhereItsFeetHoldWithFewerJumpsAndNoBacktrackingHop()
    {
        (PlanningScene scene, Vector3 from, Vector3 to, Roadmap roadmap) = Desert.Value;
        PlanResult walked = new PathQuery(scene, roadmap).Plan(from, to, Walking);
        PlanResult jumped = new PathQuery(scene, roadmap).Plan(from, to, new QuerySettings { Locomotion = Locomotion.Jump });
        Assert.That(walked.Status, Is.EqualTo(PlannerStatus.Exact), walked.Reason);
        Assert.That(jumped.Status, Is.EqualTo(PlannerStatus.Exact), jumped.Reason);
        Assert.Multiple(() =>
        {
            // Its ankles hold a foot on slopes of 22.5° at most, 25° straight up or down (ReducedModelBuilder.WalkableSlope
            // and WalkableSlopeAlong): the dunes' steeper flanks are jumped, the gentler stretches walked.
            Assert.That(scene.Character.Walking.MaxSlopeDegrees, Is.LessThan(25f));
            Assert.That(scene.Character.Walking.MaxSlopeAlongDegrees, Is.LessThan(27.5f));
            Assert.That(walked.Jumps, Has.Count.LessThan(jumped.Jumps.Count));
            Assert.That(walked.Walks, Is.Not.Empty, "walks where the ground allows");
            foreach (Jump jump in walked.Jumps)
            {
                var hop = new Vector2(jump.Arc.End.X - jump.Arc.Start.X, jump.Arc.End.Z - jump.Arc.Start.Z);
                var ahead = new Vector2(to.X - jump.Arc.Start.X, to.Z - jump.Arc.Start.Z);
                Assert.That(Vector2.Dot(hop, ahead), Is.GreaterThan(0f), $"jump {jump.Takeoff.Id} → {jump.Landing.Id} goes back");

                // Jumps only where the ground requires it: no walk links its ends faster than the jump plus its effort.
                if (scene.Walking.Steer(jump.From, jump.To).Walk is Walk instead)
                {
                    Assert.That(instead.Length / instead.Speed, Is.GreaterThanOrEqualTo(Walking.JumpCost(jump.Arc)), $"jump {jump.From.Id} → {jump.To.Id} could be walked");
                }
            }
        });

        AuditReport audit = PlanAudit.Check("desert walk+jump", scene, from, to, walked, null);
        Assert.That(audit.Violations, Is.Empty, string.Join("; ", audit.Violations));
    }

    [Test]
    public void TheDesertDemoRequestWalksAndItsWalksAnimate()
    {
        // The planner walks only on ground the skeleton's feet can hold, so the demo request's walks are animated
        // (feet on the ground, not sliding, no bone in the level) rather than set aside for jumps.
        PlanningScene scene = SharedLevels.Scene("desert", "skeleton");
        CharacterModel model = CharacterPresets.Model("skeleton");
        var animator = new JumpAnimator(scene, model);
        (AnimatedPlan plan, _) = new AnimatedPlanner(scene, animator).BakeAndPlan(new Vector3(-9.5f, 0.31f, -7.5f), new Vector3(9.5f, 0.5f, 7.5f), new BakeSettings { Seed = 1, Threads = 2, MaxNodes = 200 });
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        Assert.That(plan.Result.Walks, Is.Not.Empty);
        // Most of the way is walked: straight up and down the dunes (25°) and hopping spots the gait cannot hold, with
        // jumps cut down to the ridges: 21.2 m walked of about 30 m (7.8 m with the 22.5° limit every way and no hops,
        // 2.8 m before cutting).
        float walked = plan.Result.Walks.Sum(w => w.Length);
        float flown = plan.Result.Jumps.Sum(j => new Vector2(j.Arc.End.X - j.Arc.Start.X, j.Arc.End.Z - j.Arc.Start.Z).Length());
        TestContext.Out.WriteLine($"{plan.Result.Reason}: {walked:0.0} m walked, {flown:0.0} m flown");
        Assert.That(walked, Is.GreaterThan(flown), plan.Result.Reason);
        Assert.That(walked, Is.GreaterThan(15f), plan.Result.Reason);
        Assert.That(plan.Animation, Is.Not.Null);
        (int leastHolding, _) = WalkInvariants.Check(new WalkWorld(scene, model, animator), plan.Animation!);
        Assert.That(leastHolding, Is.GreaterThanOrEqualTo(1), "a foot is down at every moment of every walk");
    }

    [Test]
    public void ASeededSweepOfWalkingPlansPassesTheAudit()
    {
        (PlanningScene scene, _, _, Roadmap roadmap) = Desert.Value;
        var random = new Random(11);
        var query = new PathQuery(scene, roadmap);
        int exact = 0;
        int withWalks = 0;
        for (int k = 0; k < 12; k++)
        {
            Vector3 from = Ground(scene, (random.NextSingle() * 20f) - 10f, (random.NextSingle() * 16f) - 8f);
            Vector3 to = Ground(scene, (random.NextSingle() * 20f) - 10f, (random.NextSingle() * 16f) - 8f);
            PlanResult plan = query.Plan(from, to, Walking);
            if (plan.Status != PlannerStatus.Exact)
            {
                Assert.That(plan.Moves, Is.Empty);
                Assert.That(plan.Reason, Is.Not.Empty);
                continue;
            }

            exact++;
            withWalks += plan.Walks.Any() ? 1 : 0;
            AuditReport audit = PlanAudit.Check($"sweep {k}", scene, from, to, plan, null);
            Assert.That(audit.Violations, Is.Empty, $"request {k}: " + string.Join("; ", audit.Violations));
        }

        Assert.That(exact, Is.GreaterThanOrEqualTo(9));
        Assert.That(withWalks, Is.GreaterThanOrEqualTo(exact / 2));
    }

    [Test]
    public void AWalkSetAsideIsNeverUsedAndAJumpTakesItsPlace()
    {
        (PlanningScene scene, Roadmap walking, _) = Course.Value;
        var query = new PathQuery(scene, walking);
        PlanResult first = query.Plan(GapCourse.From, GapCourse.To, Walking);
        Assume.That(first.Status, Is.EqualTo(PlannerStatus.Exact));
        var rejected = new HashSet<(int, int)>();
        foreach (Walk walk in first.Walks)
        {
            rejected.UnionWith(walk.Segments);
            rejected.Add((walk.From.Id, walk.To.Id));
        }

        PlanResult second = query.Plan(GapCourse.From, GapCourse.To, Walking, rejected);
        Assert.That(second.Status, Is.EqualTo(PlannerStatus.Exact).Or.EqualTo(PlannerStatus.NoPath), second.Reason);
        // A jump set aside is never taken; a walk is made of walk edges none of which was set aside (a joined walk
        // may go between the same two stances by another way, through other stances).
        Assert.That(second.Walks.Any(w => w.Segments.SequenceEqual(first.Walks.First().Segments)), Is.False);
        foreach (Move move in second.Moves)
        {
            IEnumerable<(int, int)> used = move is Walk walk ? walk.Segments : [(move.From.Id, move.To.Id)];
            Assert.That(used.Where(rejected.Contains), Is.Empty, $"{move.GetType().Name} {move.From.Id} → {move.To.Id}");
        }
    }

    [Test]
    public void ACharacterThatDoesNotWalkPlansAsBeforeInEitherMode()
    {
        var scene = PlanningScene.Create(GapCourse.Build(), CharacterPresets.Frog());
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 3, MaxNodes = 80, Threads = 2, Locomotion = Locomotion.WalkAndJump }).Roadmap;
        Assert.That(roadmap.Walks, Is.Empty);
        var query = new PathQuery(scene, roadmap);
        PlanResult a = query.Plan(new Vector3(-6f, 0f, 0f), new Vector3(-4f, 0f, 1f), Walking);
        PlanResult b = query.Plan(new Vector3(-6f, 0f, 0f), new Vector3(-4f, 0f, 1f), new QuerySettings { Locomotion = Locomotion.Jump });
        Assert.That(a.Moves.Select(m => (m.From.Id, m.To.Id)), Is.EqualTo(b.Moves.Select(m => (m.From.Id, m.To.Id))));
        Assert.That(a.Walks, Is.Empty);
    }
}
