using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Runtime;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Query;

/// <summary>
/// Jumps made facing the way they go (<see cref="QuerySettings.FaceJumps"/>): roadmap stances face whichever way they
/// were sampled; the query turns a jump's takeoff and landing to face it, the character turning in place (a turn walk
/// for a walker, a hop for the frog), every new stance and move checked like the roadmap's.
/// </summary>
public sealed class JumpFacingTests
{
    /// <summary>The desert request of the tightening tests, and one across the pond.</summary>
    private static readonly Lazy<Case> Desert = new(() => Make("desert", "skeleton", -9.5f, -7.5f, 9.5f, 7.5f, Locomotion.WalkAndJump));

    private static readonly Lazy<Case> Pond = new(() => Make("pond", "frog", -0.5f, -5.8f, 0.5f, 4.6f, Locomotion.Jump));

    private sealed record Case(PlanningScene Scene, Vector3 From, Vector3 To, Roadmap Roadmap, JumpAnimator Real);

    private static Case Make(string level, string character, float x0, float z0, float x1, float z1, Locomotion locomotion)
    {
        PlanningScene scene = SharedLevels.Scene(level, character);
        Vector3 from = LevelPoints.Highest(scene.Bvh, x0, z0);
        Vector3 to = LevelPoints.Highest(scene.Bvh, x1, z1);
        var real = new JumpAnimator(scene, CharacterPresets.Model(character));
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 1, MaxNodes = 300, Threads = 2, Start = from, Goal = to, Locomotion = locomotion, CanStand = real.CanStand }).Roadmap;
        return new Case(scene, from, to, roadmap, real);
    }

    /// <summary>Degrees between a stance's heading and a jump's direction across.</summary>
    private static float Off(RoadmapNode stance, Jump jump)
    {
        Vector3 f = stance.Pose.Forward;
        Vector3 d = jump.Arc.End - jump.Arc.Start;
        var a = Vector2.Normalize(new Vector2(f.X, f.Z));
        var b = Vector2.Normalize(new Vector2(d.X, d.Z));
        return MathF.Acos(Math.Clamp(Vector2.Dot(a, b), -1f, 1f)) * 180f / MathF.PI;
    }

    private static bool Far(Jump jump) => new Vector2(jump.Arc.End.X - jump.Arc.Start.X, jump.Arc.End.Z - jump.Arc.Start.Z).Length() >= AnimatorEye.FacingDistance;

    /// <summary>The worst heading off a jump's direction at takeoff and at landing, over the jumps of a metre or more.</summary>
    private static (float Takeoff, float Landing) Worst(PlanResult plan)
    {
        Jump[] far = [.. plan.Jumps.Where(Far)];
        return far.Length == 0 ? (0f, 0f) : (far.Max(j => Off(j.From, j)), far.Max(j => Off(j.To, j)));
    }

    /// <summary>The desert's or the pond's request and its settings (the desert walks and jumps, the frog only jumps).</summary>
    private static (Case Case, QuerySettings Settings) Request(string level)
    {
        Case c = level == "desert" ? Desert.Value : Pond.Value;
        return (c, new QuerySettings { CanStand = c.Real.CanStand, Locomotion = level == "desert" ? Locomotion.WalkAndJump : Locomotion.Jump });
    }

    /// <summary>
    /// When the repair stops turning jumps (turned ones failed to animate), its searches prefer the roadmap's jumps that
    /// already face their way (<see cref="QuerySettings.PreferFacedJumps"/>): each jump of a metre or more whose
    /// stances do not face it costs <see cref="PathQuery.UnfacedJumpCost"/> more. On the desert the path searched
    /// without turning flies jumps off their way; preferring faced jumps, the search takes fewer of them, and what it
    /// pays for that in time is at most that cost per jump it avoids (the search's optimum with the extra cost).
    /// </summary>
    [Test]
    public void ASearchWhoseJumpsAreNotTurnedPrefersJumpsThatFaceTheirWay()
    {
        (Case c, QuerySettings settings) = Request("desert");
        QuerySettings unturned = settings with { FaceJumps = false, TightenJumps = false };
        PlanResult searched = new PathQuery(c.Scene, c.Roadmap).Plan(c.From, c.To, unturned);
        PlanResult preferred = new PathQuery(c.Scene, c.Roadmap).Plan(c.From, c.To, unturned with { PreferFacedJumps = true });
        Assert.That(searched.Status, Is.EqualTo(PlannerStatus.Exact), searched.Reason);
        Assert.That(preferred.Status, Is.EqualTo(PlannerStatus.Exact), preferred.Reason);
        int offBefore = Unfaced(searched);
        int offAfter = Unfaced(preferred);
        TestContext.Out.WriteLine($"searched: {searched.Moves.Count} moves, {offBefore} jumps off their way, {Cost(searched):0.0} s; preferring faced: {preferred.Moves.Count} moves, {offAfter} off, {Cost(preferred):0.0} s");
        Assert.Multiple(() =>
        {
            Assert.That(offBefore, Is.GreaterThan(0), "the path searched without turning has a jump off its way (else this test shows nothing)");
            Assert.That(offAfter, Is.LessThan(offBefore), "jumps off their way when faced ones are preferred");
            Assert.That(Cost(preferred), Is.LessThanOrEqualTo(Cost(searched) + ((offBefore - offAfter) * PathQuery.UnfacedJumpCost) + 1e-2f), "seconds paid for the faced jumps");
            Assert.That(preferred.Moves[0].From, Is.EqualTo(preferred.Start));
            Assert.That(preferred.Moves[^1].To, Is.EqualTo(preferred.Goal));
            for (int i = 1; i < preferred.Moves.Count; i++)
            {
                Assert.That(preferred.Moves[i].From, Is.EqualTo(preferred.Moves[i - 1].To), $"move {i} starts where move {i - 1} ends");
            }
        });

        static int Unfaced(PlanResult plan) => plan.Jumps.Count(j => !JumpFacer.Faces(j.From, j.To, j.Arc));
        float Cost(PlanResult plan) => plan.Moves.Sum(m => m is Jump j ? settings.JumpCost(j.Arc) : ((Walk)m).Length / ((Walk)m).Speed);
    }

    [TestCase("desert")]
    [TestCase("pond")]
    public void EveryJumpOfAMetreOrMoreLeavesAndLandsFacingItsWay(string level)
    {
        (Case c, QuerySettings settings) = Request(level);
        PlanResult searched = new PathQuery(c.Scene, c.Roadmap).Plan(c.From, c.To, settings with { FaceJumps = false });
        PlanResult faced = new PathQuery(c.Scene, c.Roadmap).Plan(c.From, c.To, settings);
        Assert.That(searched.Status, Is.EqualTo(PlannerStatus.Exact), searched.Reason);
        Assert.That(faced.Status, Is.EqualTo(PlannerStatus.Exact), faced.Reason);
        (float offBefore, float onBefore) = Worst(searched);
        (float off, float on) = Worst(faced);
        TestContext.Out.WriteLine($"{level}: takeoff {offBefore:0}° → {off:0}°, landing {onBefore:0}° → {on:0}°; {searched.Moves.Count} → {faced.Moves.Count} moves");
        Assert.Multiple(() =>
        {
            Assert.That(MathF.Max(offBefore / AnimatorEye.TakeoffFacing, onBefore / AnimatorEye.LandingFacing), Is.GreaterThan(1f), "the searched path has a jump not facing its way (else this test shows nothing)");
            Assert.That(off, Is.LessThanOrEqualTo(AnimatorEye.TakeoffFacing), "worst takeoff heading off the jump's direction, degrees");
            Assert.That(on, Is.LessThanOrEqualTo(AnimatorEye.LandingFacing), "worst landing heading off the jump's direction, degrees");
            Assert.That(faced.Jumps.Where(Far), Is.Not.Empty);

            // The path is continuous from the request's own start to its own goal stance.
            Assert.That(faced.Moves[0].From, Is.EqualTo(faced.Start));
            Assert.That(faced.Moves[^1].To, Is.EqualTo(faced.Goal));
            // The goal, or placed again where it stands turned toward a last jump landing off its way.
            Assert.That(Vector3.Distance(faced.Goal!.Pose.Position, searched.Goal!.Pose.Position), Is.LessThan(1e-3f), "the faced path ends where the searched one does");
            for (int i = 1; i < faced.Moves.Count; i++)
            {
                Assert.That(faced.Moves[i].From, Is.EqualTo(faced.Moves[i - 1].To), $"move {i} starts where move {i - 1} ends");
            }

            // Every new move records the jump it stands in for, so that the repair can give that jump back.
            int n = c.Roadmap.Nodes.Count;
            Assert.That(faced.Moves.Where(m => m.From.Id >= n + 2 || m.To.Id >= n + 2).Select(m => m.CutFrom.Count), Has.All.Positive, "moves to and from new stances carry the jump they were made from");
            if (level == "pond")
            {
                Assert.That(faced.Walks, Is.Empty, "a frog turns by hopping");
            }
        });

        // The independent checker: arcs land where reported, velocities in their cones and under the limits, walks on the ground.
        AuditReport audit = PlanAudit.Check($"{level} faced", c.Scene, c.From, c.To, faced, null);
        Assert.That(audit.Violations, Is.Empty, string.Join("; ", audit.Violations));

        // Deterministic.
        PlanResult again = new PathQuery(c.Scene, c.Roadmap).Plan(c.From, c.To, settings);
        Assert.That(again.Moves.Select(m => (m.From.Id, m.To.Id, m.From.Pose, m.To.Pose)), Is.EqualTo(faced.Moves.Select(m => (m.From.Id, m.To.Id, m.From.Pose, m.To.Pose))));
    }

    /// <summary>
    /// Where no stance facing a jump within 12° of its way can stand (the request's own stance check refuses them), the
    /// facer places the turned stance further round (up to 20° off) rather than leaving the jump sideways: every jump
    /// of a metre or more still leaves and lands within the eye's limits, and some turned stance stands 12–30° off.
    /// </summary>
    [Test]
    public void AJumpWhoseNearestTurnCannotStandIsTurnedFurtherRound()
    {
        Case c = Desert.Value;
        var settings = new QuerySettings { CanStand = c.Real.CanStand };
        PlanResult searched = new PathQuery(c.Scene, c.Roadmap).Plan(c.From, c.To, settings with { FaceJumps = false });
        float[] ways = [.. searched.Jumps.Where(Far).Select(j => MathF.Atan2(j.Arc.End.X - j.Arc.Start.X, j.Arc.End.Z - j.Arc.Start.Z))];
        bool Near(PoseEvaluation pose)
        {
            float yaw = MathF.Atan2(pose.Pose.Forward.X, pose.Pose.Forward.Z);
            return ways.Any(w => MathF.Abs(MathF.IEEERemainder(yaw - w, 2f * MathF.PI)) < 12f * MathF.PI / 180f);
        }

        PlanResult faced = new PathQuery(c.Scene, c.Roadmap).Plan(c.From, c.To, settings with { CanStand = pose => c.Real.CanStand(pose) && !Near(pose) });
        Assert.That(faced.Status, Is.EqualTo(PlannerStatus.Exact), faced.Reason);
        Jump[] far = [.. faced.Jumps.Where(Far)];
        int n = c.Roadmap.Nodes.Count;
        (float off, float on) = Worst(faced);
        TestContext.Out.WriteLine($"takeoff {off:0}°, landing {on:0}°; turned stances off by {string.Join(", ", far.SelectMany(j => new[] { (j.From, j), (j.To, j) }).Where(s => s.Item1.Id >= n + 2).Select(s => $"{Off(s.Item1, s.j):0}°"))}");
        Assert.Multiple(() =>
        {
            Assert.That(off, Is.LessThanOrEqualTo(AnimatorEye.TakeoffFacing), "worst takeoff heading off the jump's direction, degrees");
            Assert.That(on, Is.LessThanOrEqualTo(AnimatorEye.LandingFacing), "worst landing heading off the jump's direction, degrees");
            Assert.That(far.SelectMany(j => new[] { (j.From, j), (j.To, j) }).Where(s => s.Item1.Id >= n + 2).Select(s => Off(s.Item1, s.j)), Has.Some.InRange(12f, 30f), "a turned stance stands further round");
        });
        AuditReport audit = PlanAudit.Check("desert turned further", c.Scene, c.From, c.To, faced, null);
        Assert.That(audit.Violations, Is.Empty, string.Join("; ", audit.Violations));
    }

    /// <summary>
    /// A turn hop the body cannot push off for or land from is not made: the request's <see cref="QuerySettings.CanPush"/>
    /// refuses every stance facing within 12° of a searched jump's way, so the frog, which turns by hops, reaches no
    /// such turned takeoff and leaves no such turned landing, while the check was asked about its hops (on the curved
    /// level the skeleton's turn hops, the steepest arcs their cones allow, landed on stances whose generated contacts'
    /// cone held no hop: the repair gave those jumps back and they flew 82° and 83° off their way).
    /// </summary>
    [Test]
    public void ATurnHopTheBodyCannotPushOffForOrLandFromIsNotMade()
    {
        Case c = Pond.Value;
        var settings = new QuerySettings { CanStand = c.Real.CanStand, Locomotion = Locomotion.Jump };
        PlanResult searched = new PathQuery(c.Scene, c.Roadmap).Plan(c.From, c.To, settings with { FaceJumps = false });
        float[] ways = [.. searched.Jumps.Where(Far).Select(j => MathF.Atan2(j.Arc.End.X - j.Arc.Start.X, j.Arc.End.Z - j.Arc.Start.Z))];
        bool Near(RootPose pose)
        {
            float yaw = MathF.Atan2(pose.Forward.X, pose.Forward.Z);
            return ways.Any(w => MathF.Abs(MathF.IEEERemainder(yaw - w, 2f * MathF.PI)) < 12f * MathF.PI / 180f);
        }

        int asked = 0;
        PlanResult faced = new PathQuery(c.Scene, c.Roadmap).Plan(c.From, c.To, settings with
        {
            CanPush = (root, contacts, velocity) =>
            {
                Interlocked.Increment(ref asked);
                return c.Real.CanPush(root, contacts, velocity) && !Near(root);
            },
        });
        Assert.That(faced.Status, Is.EqualTo(PlannerStatus.Exact), faced.Reason);
        int n = c.Roadmap.Nodes.Count;
        RoadmapNode[] turned = [.. faced.Jumps.Where(Far).SelectMany(j => new[] { j.From, j.To }).Where(s => s.Id >= n + 2)];
        TestContext.Out.WriteLine($"asked {asked} times; turned ends {string.Join(", ", turned.Select(s => s.Id))}");
        Assert.That(asked, Is.Positive, "the facer asks about the hops it turns by");
        Assert.That(turned.Where(s => Near(s.Pose)).Select(s => s.Id), Is.Empty, "a far jump leaves or lands on a turned end the check refused");
        AuditReport audit = PlanAudit.Check("pond hops checked", c.Scene, c.From, c.To, faced, null);
        Assert.That(audit.Violations, Is.Empty, string.Join("; ", audit.Violations));
    }

    /// <summary>
    /// The animator's push check is the contact pose its jumps take off on: a faced jump's own takeoff velocity passes on
    /// its takeoff's contacts, a velocity into the ground (outside every friction cone) does not.
    /// </summary>
    [Test]
    public void TheAnimatorPushesOffWithAJumpsVelocityOnlyInsideItsCone()
    {
        Case c = Desert.Value;
        PlanResult faced = new PathQuery(c.Scene, c.Roadmap).Plan(c.From, c.To, new QuerySettings { CanStand = c.Real.CanStand, CanPush = c.Real.CanPush });
        Assert.That(faced.Status, Is.EqualTo(PlannerStatus.Exact), faced.Reason);
        Jump jump = faced.Jumps.Where(Far).First();
        Assert.Multiple(() =>
        {
            Assert.That(c.Real.CanPush(jump.From.Pose, jump.From.Contacts, jump.Arc.TakeoffVelocity), Is.True, "its takeoff");
            Assert.That(c.Real.CanPush(jump.To.Pose, jump.To.Contacts, -jump.Arc.LandingVelocity), Is.True, "its landing");
            Assert.That(c.Real.CanPush(jump.From.Pose, jump.From.Contacts, new Vector3(0f, -5f, 0f)), Is.False, "into the ground");
        });
    }

    /// <summary>
    /// On the curved level's slopes the dog jumping only (as it did before its walking limit stood its trunk lower to
    /// reach, when it walked on the level only) turns by hops; where a hop in place ahead down the slope
    /// lands outside its cone and one on the spot has no parabola, it hops back up the slope (or further ahead) to turn:
    /// every jump of a metre or more leaves and lands facing its way (before: the last jump left 69° off its way, no
    /// takeoff facing it linked), and the independent checker passes the path.
    /// </summary>
    [Test]
    public void ADogThatCannotHopAheadOnASlopeTurnsByAHopBehind()
    {
        (Sweep.Setup setup, Vector3 from, Vector3 to, AnimatedPlan plan) = Foreign("curved", "dog", 1, Locomotion.Jump);
        (float off, float on) = Worst(plan.Result);
        TestContext.Out.WriteLine($"takeoff {off:0}°, landing {on:0}°, {plan.Result.Jumps.Count} jumps, {plan.Result.Jumps.Count(j => !Far(j))} of them hops");
        Assert.Multiple(() =>
        {
            Assert.That(off, Is.LessThanOrEqualTo(AnimatorEye.TakeoffFacing), "worst takeoff heading off the jump's direction, degrees");
            Assert.That(on, Is.LessThanOrEqualTo(AnimatorEye.LandingFacing), "worst landing heading off the jump's direction, degrees");
            Assert.That(plan.Result.Walks, Is.Empty, "the dog jumping only turns by hops");
        });
        AuditReport audit = PlanAudit.Check("curved dog", setup.Scene, from, to, plan.Result, plan.Animation);
        Assert.That(plan.Animation, Is.Not.Null, "the path animates");
        Assert.That(audit.Violations, Is.Empty, string.Join("; ", audit.Violations));
    }

    /// <summary>
    /// Where a jump takes off from a stance the body can neither walk nor hop round on (its turned takeoffs link by no
    /// turn), the jump before it lands on a takeoff turned part of the way toward it instead: the frog on the pond,
    /// jumping only, every push slower than 0.6 m/s across refused (so no hop in place turns it), lands its far jumps on
    /// stances it takes off from more than <see cref="JumpFacer.TakeoffTurn"/> off the next jump's way (a takeoff the
    /// facer turned to face its jump would stand within it) and every far jump still leaves and lands within the
    /// eye's limits (first seen on the curved level's dog, the takeoff 98° off before; then on the tailed quadruped
    /// between two holes, until its feet stood in from the holes' brinks and it walked between them).
    /// </summary>
    [Test]
    public void AJumpTakingOffWhereTheBodyCannotTurnIsLandedOnTurnedTowardIt()
    {
        Case c = Pond.Value;
        var settings = new QuerySettings
        {
            CanStand = c.Real.CanStand,
            Locomotion = Locomotion.Jump,
            CanPush = (root, contacts, velocity) => c.Real.CanPush(root, contacts, velocity) && new Vector2(velocity.X, velocity.Z).Length() >= 0.6f,
        };
        PlanResult faced = new PathQuery(c.Scene, c.Roadmap).Plan(c.From, c.To, settings);
        Assert.That(faced.Status, Is.EqualTo(PlannerStatus.Exact), faced.Reason);
        Jump[] jumps = [.. faced.Jumps];
        int n = c.Roadmap.Nodes.Count;
        (float Landing, float Takeoff)[] shared = [.. Enumerable.Range(1, jumps.Length - 1)
            .Where(i => Far(jumps[i - 1]) && Far(jumps[i]) && jumps[i].From == jumps[i - 1].To && jumps[i].From.Id >= n + 2)
            .Select(i => (Off(jumps[i].From, jumps[i - 1]), Off(jumps[i].From, jumps[i])))];
        (float off, float on) = Worst(faced);
        TestContext.Out.WriteLine($"{jumps.Length} jumps, worst takeoff {off:0}°, landing {on:0}°; placed stances landed on and taken off from: {string.Join(", ", shared.Select(r => $"landing {r.Landing:0}°, takeoff {r.Takeoff:0}°"))}");
        Assert.Multiple(() =>
        {
            Assert.That(shared.Select(r => r.Takeoff), Has.Some.GreaterThan(JumpFacer.TakeoffTurn * 180f / MathF.PI), "some far jump lands on a takeoff turned part of the way toward the next far jump");
            Assert.That(off, Is.LessThanOrEqualTo(AnimatorEye.TakeoffFacing), "worst takeoff heading off the jump's direction, degrees");
            Assert.That(on, Is.LessThanOrEqualTo(AnimatorEye.LandingFacing), "worst landing heading off the jump's direction, degrees");
        });
        AuditReport audit = PlanAudit.Check("pond landed turned", c.Scene, c.From, c.To, faced, null);
        Assert.That(audit.Violations, Is.Empty, string.Join("; ", audit.Violations));
    }

    /// <summary>The animated plan of a foreign rig on a foreign level's request <paramref name="request"/>, as the sweep makes it (walking and jumping unless <paramref name="locomotion"/> says otherwise).</summary>
    private static (Sweep.Setup Setup, Vector3 From, Vector3 To, AnimatedPlan Plan) Foreign(string levelName, string rig, int request, Locomotion locomotion = Locomotion.WalkAndJump)
    {
        string folder = Path.Combine(Path.GetTempPath(), $"ballistic-{rig}-{Guid.NewGuid():N}");
        try
        {
            (Sweep.Setup setup, (Vector3 From, Vector3 To)[] requests) = Sweep.PrepareForeign(levelName, rig, folder);
            (Vector3 from, Vector3 to) = requests[request];
            (AnimatedPlan plan, _) = setup.Planner.BakeAndPlan(from, to, new BakeSettings { Seed = 1, Threads = 2, MaxNodes = 600, Locomotion = locomotion });
            Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
            return (setup, from, to, plan);
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    [Test]
    public void AJumpGivenBackByTheRepairIsFacedAgainTurningByHops()
    {
        // A walk turning into a faced jump (a turn in place, or the walk before steered to the turned takeoff) that the
        // gait cannot perform makes the repair give its jump back (UncutJumps); that jump is then turned by hops,
        // which the jump animator performs, and still faces its way.
        Case c = Desert.Value;
        var settings = new QuerySettings { CanStand = c.Real.CanStand };
        PlanResult faced = new PathQuery(c.Scene, c.Roadmap).Plan(c.From, c.To, settings);
        HashSet<(int From, int To)> walked = [.. faced.Walks.SelectMany(w => w.CutFrom)];
        Assert.That(walked, Is.Not.Empty, "the desert path walks into a turned jump somewhere");
        PlanResult again = new PathQuery(c.Scene, c.Roadmap).Plan(c.From, c.To, settings with { UncutJumps = walked });
        Assert.That(again.Status, Is.EqualTo(PlannerStatus.Exact), again.Reason);
        (float off, float on) = Worst(again);
        (int From, int To)[] used = [.. again.Moves.SelectMany(m => m.CutFrom).Where(walked.Contains).Distinct()];
        Assert.Multiple(() =>
        {
            Assert.That(again.Walks.Where(w => w.CutFrom.Any(walked.Contains)), Is.Empty, "no walk stands in for a jump given back");
            Assert.That(used, Is.Not.Empty, "the path searched again still takes a given-back jump");
            Assert.That(used.Where(p => again.Jumps.Count(j => j.CutFrom.Contains(p)) < 2), Is.Empty, "each given-back jump the path takes turns by a hop (two jumps or more stand for it)");
            Assert.That(off, Is.LessThanOrEqualTo(AnimatorEye.TakeoffFacing));
            Assert.That(on, Is.LessThanOrEqualTo(AnimatorEye.LandingFacing));
        });
        AuditReport audit = PlanAudit.Check("desert hops", c.Scene, c.From, c.To, again, null);
        Assert.That(audit.Violations, Is.Empty, string.Join("; ", audit.Violations));
    }

    /// <summary>
    /// A faced jump the body cannot crouch for on its turned takeoff is turned another way the next round
    /// (<see cref="QuerySettings.RefusedTurns"/>), not flown as searched: the stance refused is never jumped from
    /// again, and every jump still faces its way.
    /// </summary>
    [Test]
    public void AFacedJumpTheBodyCannotCrouchForOnItsTurnedTakeoffIsTurnedAnotherWay()
    {
        Case c = Pond.Value;
        RoadmapNode? refused = null;
        int n = c.Roadmap.Nodes.Count;

        // Refuses every jump from the first turned takeoff it sees (a faced jump's takeoff placed for it).
        bool Refuses(Move m)
        {
            if (m is not Jump || m.CutFrom.Count == 0 || m.From.Id < n + 2)
            {
                return false;
            }

            refused ??= m.From;
            return m.From.Pose == refused.Pose;
        }

        var animator = new RefusingAnimator(new SimpleMoveAnimator(c.Real), Refuses, "cannot crouch on this turn", ProblemStance.Takeoff);
        AnimatedPlan plan = new AnimatedPlanner(c.Scene, animator).Plan(c.Roadmap, c.From, c.To, new QuerySettings { Locomotion = Locomotion.Jump });
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        (float off, float on) = Worst(plan.Result);
        Assert.Multiple(() =>
        {
            Assert.That(refused, Is.Not.Null, "the pond path turns a jump");
            Assert.That(animator.PathsRefused, Is.GreaterThanOrEqualTo(1));
            Assert.That(plan.Result.Jumps.Select(j => j.From.Pose), Has.No.Member(refused!.Pose), "no jump from the refused stance");
            Assert.That(off, Is.LessThanOrEqualTo(AnimatorEye.TakeoffFacing), "worst takeoff heading off the jump's direction, degrees");
            Assert.That(on, Is.LessThanOrEqualTo(AnimatorEye.LandingFacing), "worst landing heading off the jump's direction, degrees");
            Assert.That(plan.Rejected.Select(r => r.Reason), Has.All.EqualTo("cannot crouch on this turn"));
        });
    }

    /// <summary>
    /// A jump the facer cannot turn (here: every jump of the searched path off its way, given back unturned by the
    /// repair, <see cref="QuerySettings.UnfacedJumps"/>) is not flown sideways: a walker's jump is swung once toward
    /// the way its landing faces (taken off from a new stance it walks to, landing on the jump's own landing), and
    /// where that does not steer (and for the frog, which only jumps) the query searches again without it when another
    /// path costs little more (<see cref="PathQuery.FacingSearches"/>). The path taken faces every jump and flies none
    /// of the jumps left unturned; a move standing for one is a walk into a swung jump or that jump.
    /// </summary>
    [TestCase("desert")]
    [TestCase("pond")]
    public void AJumpThatCannotBeTurnedIsSwungOrSearchedAround(string level)
    {
        (Case c, QuerySettings settings) = Request(level);
        PlanResult searched = new PathQuery(c.Scene, c.Roadmap).Plan(c.From, c.To, settings with { FaceJumps = false });
        HashSet<(int From, int To)> unturnable = [.. searched.Jumps.Where(j => Far(j) && (Off(j.From, j) > AnimatorEye.TakeoffFacing || Off(j.To, j) > AnimatorEye.LandingFacing)).Select(j => (j.From.Id, j.To.Id))];
        Assert.That(unturnable, Is.Not.Empty, "the searched path has a jump off its way (else this test shows nothing)");

        PlanResult plan = new PathQuery(c.Scene, c.Roadmap).Plan(c.From, c.To, settings with { UnfacedJumps = unturnable });
        Assert.That(plan.Status, Is.EqualTo(PlannerStatus.Exact), plan.Reason);
        (float off, float on) = Worst(plan);
        TestContext.Out.WriteLine($"{level}: {unturnable.Count} jumps left unturned; the path taken: takeoff {off:0}°, landing {on:0}° off, {plan.Moves.Count} moves");
        Assert.Multiple(() =>
        {
            Assert.That(plan.Jumps.Select(j => (j.From.Id, j.To.Id)), Has.None.Matches<(int, int)>(unturnable.Contains), "no jump left unturned is flown whole");
            for (int m = 0; m < plan.Moves.Count; m++)
            {
                if (plan.Moves[m].CutFrom.FirstOrDefault(unturnable.Contains) is var (from, to) && (from, to) != default)
                {
                    // Swung: a jump onto the unturned jump's own landing from a stance placed for it, or the walk into that jump.
                    Jump swung = plan.Moves[m] as Jump ?? (Jump)plan.Moves[m + 1];
                    Assert.That((swung.To.Id, swung.From.Id >= c.Roadmap.Nodes.Count + 2), Is.EqualTo((to, true)), $"move {m} stands for jump {from}->{to} only as a swung jump or the walk into it");
                }
            }

            Assert.That(off, Is.LessThanOrEqualTo(AnimatorEye.TakeoffFacing), "worst takeoff heading off the jump's direction, degrees");
            Assert.That(on, Is.LessThanOrEqualTo(AnimatorEye.LandingFacing), "worst landing heading off the jump's direction, degrees");
        });
        AuditReport audit = PlanAudit.Check($"{level} searched around", c.Scene, c.From, c.To, plan, null);
        Assert.That(audit.Violations, Is.Empty, string.Join("; ", audit.Violations));
    }

    [Test]
    public void AFacedMoveTheBodyCannotPerformGivesTheJumpBackAsSearched()
    {
        Case c = Pond.Value;
        var animator = new RefusingAnimator(new SimpleMoveAnimator(c.Real), m => m.CutFrom.Count > 0, "cannot turn here");
        AnimatedPlan plan = new AnimatedPlanner(c.Scene, animator).Plan(c.Roadmap, c.From, c.To, new QuerySettings { Locomotion = Locomotion.Jump }, rounds: 1);
        Assert.Multiple(() =>
        {
            Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
            Assert.That(plan.Result.Moves.SelectMany(m => m.CutFrom), Is.Empty, "every turn given back");
            Assert.That(animator.PathsRefused, Is.InRange(1, JumpRepair.CutRounds));
        });
    }
}
