using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Runtime;
using Ballistic.Planner.Tests.Support;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Planner.Tests.Query;

/// <summary>A walk the body cannot perform at one spot hops over that spot and is walked the rest of the way, instead of being set aside whole.</summary>
public sealed class WalkHopTests
{
    private static readonly Vector3 From = new(-5f, 0f, 0f);
    private static readonly Vector3 To = new(5f, 0f, 0f);

    /// <summary>A 14 m × 4 m floor, its top at y = 0; the skeleton walks it from x = −5 to x = 5 in one walk.</summary>
    private static readonly Lazy<(PlanningScene Scene, Roadmap Roadmap, JumpAnimator Real)> Floor = new(() =>
    {
        Level level = new LevelBuilder("floor").AddBox(new Vector3(-7f, -1f, -2f), new Vector3(7f, 0f, 2f)).Build();
        var scene = PlanningScene.Create(level, CharacterPresets.Skeleton());
        var real = new JumpAnimator(scene, CharacterPresets.Model("skeleton"));
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 1, MaxNodes = 60, Threads = 2, Start = From, Goal = To, StopWhenConnected = true, CanStand = real.CanStand }).Roadmap;
        return (scene, roadmap, real);
    });

    private static float Across(Vector3 a, Vector3 b) => new Vector2(b.X - a.X, b.Z - a.Z).Length();

    private static PlanResult Plan(IReadOnlyList<Vector3>? spots)
    {
        (PlanningScene scene, Roadmap roadmap, JumpAnimator real) = Floor.Value;
        PlanResult plan = new PathQuery(scene, roadmap).Plan(From, To, new QuerySettings { CanStand = real.CanStand, HopSpots = spots });
        Assert.That(plan.Status, Is.EqualTo(PlannerStatus.Exact), plan.Reason);
        return plan;
    }

    private static void AssertContinuous(PlanResult plan)
    {
        Assert.That(plan.Moves[0].From, Is.EqualTo(plan.Start));
        Assert.That(plan.Moves[^1].To, Is.EqualTo(plan.Goal));
        for (int i = 1; i < plan.Moves.Count; i++)
        {
            Assert.That(plan.Moves[i].From, Is.EqualTo(plan.Moves[i - 1].To), $"move {i} starts where move {i - 1} ends");
        }
    }

    [Test]
    public void AWalkPastASpotHopsOverItAndWalksTheRest()
    {
        PlanResult walked = Plan(null);
        Assume.That(walked.Moves, Has.Count.EqualTo(1).And.All.InstanceOf<Walk>(), "the floor is walked in one walk");
        var spot = new Vector3(0f, 0f, (walked.Moves[0].From.ContactCentre.Z + walked.Moves[0].To.ContactCentre.Z) / 2f);
        PlanResult hopped = Plan([spot]);
        (PlanningScene scene, Roadmap roadmap, _) = Floor.Value;
        int n = roadmap.Nodes.Count;
        (int, int)[] searched = [.. ((Walk)walked.Moves[0]).Segments];
        Assert.Multiple(() =>
        {
            Assert.That(hopped.Moves.Select(m => m.GetType().Name), Is.EqualTo(new[] { "Walk", "Jump", "Walk" }));
            AssertContinuous(hopped);
            Jump hop = hopped.Jumps.Single();
            Assert.That(hop.From.ContactCentre.X, Is.LessThan(spot.X - JumpTightener.SpotRadius), "takes off before the spot");
            Assert.That(hop.To.ContactCentre.X, Is.GreaterThan(spot.X + JumpTightener.SpotRadius), "lands after it");
            Assert.That(Across(hop.From.ContactCentre, hop.To.ContactCentre), Is.InRange(JumpTightener.MinHop - 0.45f, 3f), "a hop, not a leap over the floor");
            Assert.That(hopped.Walks.SelectMany(w => w.Path).Select(p => Across(p, spot)), Has.All.GreaterThan(JumpTightener.SpotRadius), "no walk steps on the spot");
            Assert.That(hopped.Walks.Sum(w => w.Length), Is.GreaterThan(6f), "the rest is walked");
            Assert.That(hopped.Moves.Select(m => m.HoppedFrom), Has.All.EqualTo(searched), "each move stands in for the searched walk");
            Assert.That(new[] { hop.From.Id, hop.To.Id }, Has.All.GreaterThanOrEqualTo(n + 2), "new stances get fresh ids");
        });

        AuditReport audit = PlanAudit.Check("hop over a spot", scene, From, To, hopped, null);
        Assert.That(audit.Violations, Is.Empty, audit.ToString());
        PlanResult again = Plan([spot]);
        Assert.That(again.Moves.Select(m => (m.From.Pose, m.To.Pose)), Is.EqualTo(hopped.Moves.Select(m => (m.From.Pose, m.To.Pose))), "deterministic");
    }

    [Test]
    public void SpotsCloseTogetherAreHoppedAtOnceAndSpotsApartEachOnce()
    {
        PlanResult walked = Plan(null);
        float z = walked.Moves[0].From.ContactCentre.Z;
        PlanResult close = Plan([new Vector3(-0.3f, 0f, z), new Vector3(0.3f, 0f, z)]);
        PlanResult apart = Plan([new Vector3(-2f, 0f, z), new Vector3(2f, 0f, z)]);
        PlanResult beside = Plan([new Vector3(0f, 0f, 1.9f * MathF.Sign(0.5f - z))]);
        Assert.Multiple(() =>
        {
            Assert.That(close.Jumps, Has.Count.EqualTo(1), "one hop over both");
            Jump hop = close.Jumps.Single();
            Assert.That(hop.From.ContactCentre.X, Is.LessThan(-0.3f - JumpTightener.SpotRadius));
            Assert.That(hop.To.ContactCentre.X, Is.GreaterThan(0.3f + JumpTightener.SpotRadius));
            Assert.That(apart.Jumps, Has.Count.EqualTo(2), "one hop each");
            Assert.That(apart.Walks.Count(), Is.EqualTo(3));
            AssertContinuous(apart);
            Assert.That(beside.Moves.Select(m => (m.From.Pose, m.To.Pose)), Is.EqualTo(walked.Moves.Select(m => (m.From.Pose, m.To.Pose))), "a spot the walk does not pass changes nothing");
        });
    }

    [Test]
    public void TheRepairRecordHopsOverLocatedProblemsAndSetsTheWalkAsideWhenTheHopFails()
    {
        (PlanningScene scene, Roadmap roadmap, JumpAnimator real) = Floor.Value;
        PlanResult walked = Plan(null);
        var walk = (Walk)walked.Moves[0];
        var simple = new SimpleMoveAnimator(real);
        JumpAnimation located = Problems(simple, walked.Moves, new JumpProblem(0, "left_foot cannot hold its foothold (4.90 m along the walk)", 4.9f));
        var repair = new JumpRepair();
        repair.Reject(walked.Moves, located);
        Assert.Multiple(() =>
        {
            Assert.That(repair.HopSpots, Has.Count.EqualTo(1));
            Assert.That(Vector3.Distance(repair.HopSpots[0], walk.PointAt(4.9f)), Is.LessThan(1e-4f), "the ground point of the problem");
            Assert.That(repair.Excluded, Is.Empty, "the walk is not set aside");
            Assert.That((repair.WalkFailures, repair.HopFailures), Is.EqualTo((0, 1)));
            Assert.That(repair.Adjust(new QuerySettings()).HopSpots, Is.EqualTo(repair.HopSpots));
            Assert.That(repair.IsExhausted(1, 1), Is.False, "a round that found a spot does not count against the searches");
        });

        // The same problem again: the hop did not pass there, so the walk is set aside.
        repair.Reject(walked.Moves, located);
        Assert.That(repair.Excluded, Does.Contain((walk.From.Id, walk.To.Id)));
        Assert.That(repair.WalkFailures, Is.EqualTo(1));
        Assert.That(repair.SuccessNote(), Is.EqualTo(" after setting aside 1 walk the body could not perform"), "a walk is counted as a walk");

        // A problem with no place on the walk sets it aside at once; a hop's move that fails sets the searched walk aside.
        var unlocated = new JumpRepair();
        unlocated.Reject(walked.Moves, Problems(simple, walked.Moves, new JumpProblem(0, "the walk's end stance: no limb could reach a surface")));
        PlanResult hopped = Plan([walk.PointAt(4.9f)]);
        var hops = new JumpRepair();
        int jump = hopped.Moves.ToList().FindIndex(m => m is Jump);
        hops.Reject(hopped.Moves, Problems(simple, hopped.Moves, new JumpProblem(jump, "takeoff: the generated contacts' cone does not contain the jump's velocity")));
        Assert.Multiple(() =>
        {
            Assert.That(unlocated.Excluded, Does.Contain((walk.From.Id, walk.To.Id)));
            Assert.That(unlocated.HopSpots, Is.Empty);
            Assert.That(hops.Excluded, Is.EquivalentTo(walk.Segments), "the searched walk, not the hop's own stances");
            Assert.That(hops.WalkFailures, Is.EqualTo(1));
            Assert.That(hops.SuccessNote(), Does.Contain("1 jump the body"), "the hop's jump");
        });

        // After HopRounds rounds that found spots, problems set walks aside again.
        var rounds = new JumpRepair();
        for (int k = 0; k < JumpRepair.HopRounds; k++)
        {
            rounds.Reject(walked.Moves, Problems(simple, walked.Moves, new JumpProblem(0, "a foot slips", 1f + (2f * k))));
        }

        Assert.That(rounds.HoppingAllowed, Is.False);
        Assert.That(rounds.Excluded, Is.Empty);
        rounds.Reject(walked.Moves, Problems(simple, walked.Moves, new JumpProblem(0, "a foot slips", 9.5f)));
        Assert.That(rounds.Excluded, Does.Contain((walk.From.Id, walk.To.Id)));
    }

    [Test]
    public void APlanWhoseWalkFailsAtOneSpotIsWalkedAroundItWithAHop()
    {
        // An animator double that cannot walk within 0.15 m of x = 0: every walk passing there has a problem placed
        // where it gets there; the planner hops over the spot and the request succeeds, walking the rest.
        (PlanningScene scene, Roadmap roadmap, JumpAnimator real) = Floor.Value;
        var animator = new SpotAnimator(new SimpleMoveAnimator(real), 0f, 0.15f);
        AnimatedPlan plan = new AnimatedPlanner(scene, animator).Plan(roadmap, From, To, new QuerySettings(), rounds: 1);
        Assert.Multiple(() =>
        {
            Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
            Assert.That(plan.Animation!.IsClean, Is.True);
            Assert.That(plan.Result.Jumps, Has.Count.EqualTo(1), "one hop");
            Assert.That(plan.Result.Walks.Sum(w => w.Length), Is.GreaterThan(6f));
            Assert.That(plan.Rounds, Is.EqualTo(2), "one round found the spot, one hopped it");
            Assert.That(animator.Refused, Is.EqualTo(1));
        });
    }

    /// <summary>
    /// Ground the body can neither walk over nor hop (a spider's legs, 1.3 m across, meeting a 0.9 m door's jambs
    /// whether it walks or hops through): the walk failing there again, in the round that would have ended walking,
    /// bars the spot instead (<see cref="JumpRepair.NoWalkSpots"/>), and the request walks everywhere else. Before, it
    /// gave up walking for the whole request: the doorway's spider went from corner to corner in nine jumps.
    /// </summary>
    [Test]
    public void TheRepairRecordBarsASpotWhereAWalkFailsAgainAfterItsHopFailedInsteadOfGivingUpWalking()
    {
        (_, _, JumpAnimator real) = Floor.Value;
        PlanResult walked = Plan(null);
        var walk = (Walk)walked.Moves[0];
        var simple = new SimpleMoveAnimator(real);
        JumpAnimation located = Problems(simple, walked.Moves, new JumpProblem(0, "l2 cannot swing to its next foothold (4.90 m along the walk)", 4.9f));
        var repair = new JumpRepair();
        repair.Reject(walked.Moves, located); // a spot to hop over
        PlanResult hopped = Plan([walk.PointAt(4.9f)]);
        int jump = hopped.Moves.ToList().FindIndex(m => m is Jump);
        repair.Reject(hopped.Moves, Problems(simple, hopped.Moves, new JumpProblem(jump, "r2 passes through the level in flight")));
        Assume.That((repair.WalkFailures, repair.HopFailures, repair.NoWalkSpots.Count), Is.EqualTo((1, 1, 0)), "the hop failed: one round with a failed walk");

        // The walk fails there again: the round would end walking; the spot is barred instead.
        var settings = new QuerySettings();
        repair.Reject(walked.Moves, located);
        Assert.Multiple(() =>
        {
            Assert.That(repair.NoWalkSpots, Has.Count.EqualTo(1));
            Assert.That(Vector3.Distance(repair.NoWalkSpots[0], walk.PointAt(4.9f)), Is.LessThan(1e-4f), "the ground point of the problem");
            Assert.That(repair.WalksAllowed, Is.True, "walking goes on elsewhere");
            Assert.That(repair.WalkFailures, Is.EqualTo(1));
            Assert.That(repair.NoWalkFailures, Is.EqualTo(1));
            Assert.That(repair.Excluded, Does.Contain((walk.From.Id, walk.To.Id)), "the walk itself is set aside too");
            Assert.That(repair.Adjust(settings).NoWalkSpots, Is.EqualTo(repair.NoWalkSpots));
            Assert.That(repair.Adjust(settings).Locomotion, Is.EqualTo(Locomotion.WalkAndJump));
            Assert.That(repair.IsExhausted(3, 1), Is.False, "a round that barred a spot does not count against the searches");
        });

        // A walk failing again at a barred spot (it is not searched again; its problem found twice) is the round that ends walking.
        repair.Reject(walked.Moves, located);
        Assert.That(repair.WalksAllowed, Is.False);

        // A first failure at a known spot still only sets the walk aside, as before: the search finds another walk.
        var once = new JumpRepair();
        once.Reject(walked.Moves, located);
        once.Reject(walked.Moves, located);
        Assert.That((once.NoWalkSpots.Count, once.WalkFailures, once.WalksAllowed), Is.EqualTo((0, 1, true)));
    }

    [TestCase(0)]
    [TestCase(2)]
    public void ARuntimeAgentWhoseWalkFailsAtOneSpotHopsOverItAndArrives(int threads)
    {
        // The runtime's path requests share the repair: the same double, through a world's agent.
        (PlanningScene scene, Roadmap roadmap, JumpAnimator real) = Floor.Value;
        var kind = new CharacterKind(scene, roadmap, real, new SpotAnimator(new SimpleMoveAnimator(real), 0f, 0.15f));
        using var world = new JumpWorld(scene.Level, new WorldSettings { AnimationThreads = threads, MaxAnimationWait = null });
        AgentHandle agent = world.AddAgent(world.AddKind(kind).Kind, From).Agent;
        Assert.That(world.SetTarget(agent, To).Ok, Is.True);
        List<JumpEvent> events = RuntimeWorlds.Run(world, 60 * 60, RuntimeWorlds.Concluded);
        JumpEvent[] jumps = [.. events.Where(e => e.Kind == JumpEventKind.JumpStarted)];
        Assert.Multiple(() =>
        {
            Assert.That(events.Select(e => e.Kind), Does.Contain(JumpEventKind.TargetReached), string.Join("; ", events.Select(e => $"{e.Kind} {e.Reason}")));
            Assert.That(events.Select(e => e.Kind), Does.Not.Contain(JumpEventKind.PathFailed));
            Assert.That(jumps, Has.Length.EqualTo(1), "one hop");
            Assert.That(jumps[0].From.X, Is.LessThan(-0.15f), "takes off before the spot");
            Assert.That(jumps[0].To.X, Is.GreaterThan(0.15f), "lands after it");
            Assert.That(events.Count(e => e.Kind == JumpEventKind.WalkStarted), Is.EqualTo(2), "walks before and after");
        });
    }

    private static JumpAnimation Problems(SimpleMoveAnimator inner, IReadOnlyList<Move> moves, params JumpProblem[] problems)
    {
        JumpAnimation a = inner.Animate(moves);
        return new JumpAnimation(a.Model, moves, [.. Enumerable.Range(0, Math.Max(0, moves.Count - 1)).Select(_ => inner.Stance)], a.Frames, a.ContactPhases, problems, 0, 0);
    }

    /// <summary>Animates like the inner double, with a located problem on every walk passing within <paramref name="radius"/> of x = <paramref name="x"/>.</summary>
    private sealed class SpotAnimator(SimpleMoveAnimator inner, float x, float radius) : IJumpAnimator
    {
        public int Refused { get; private set; }

        public JumpAnimation Animate(IReadOnlyList<Move> moves, float frameRate = 60f)
        {
            var problems = new List<JumpProblem>();
            for (int m = 0; m < moves.Count; m++)
            {
                if (moves[m] is Walk walk)
                {
                    float along = 0f;
                    for (int i = 0; i < walk.Path.Count; i++)
                    {
                        along += i == 0 ? 0f : Vector3.Distance(walk.Path[i - 1], walk.Path[i]);
                        if (MathF.Abs(walk.Path[i].X - x) <= radius)
                        {
                            problems.Add(new JumpProblem(m, $"a foot cannot hold ({along:0.00} m along the walk)", along));
                            break;
                        }
                    }
                }
            }

            Refused += problems.Count > 0 ? 1 : 0;
            return Problems(inner, moves, [.. problems]);
        }

        public bool CanStand(PoseEvaluation pose) => inner.CanStand(pose);
    }
}
