using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Animation;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Query;

/// <summary>
/// A stance the body cannot crouch on (or absorb a landing on) is set aside for every jump from (to) it at once, not
/// one jump per search: each jump would have the same contact pose there.
/// </summary>
public sealed class StanceRepairTests
{
    private static Lazy<(PlanningScene Scene, BakeResult Bake)> GapCourseBake => AnimatedPlannerTests.GapCourseBake;

    /// <summary>Searched moves as they are: no cutting, no turning, so node ids are the roadmap's.</summary>
    private static readonly QuerySettings AsSearched = new() { TightenJumps = false, FaceJumps = false };

    /// <summary>Reports the stance problem <paramref name="stance"/> on every jump from (to) node <paramref name="node"/>, and counts the paths it refused.</summary>
    private sealed class StanceRefuser(int node, ProblemStance stance) : IJumpAnimator
    {
        public int PathsRefused { get; private set; }

        public JumpAnimation Animate(IReadOnlyList<Move> moves, float frameRate = 60f)
        {
            var problems = new List<JumpProblem>();
            for (int m = 0; m < moves.Count; m++)
            {
                if ((stance == ProblemStance.Takeoff ? moves[m].From.Id : moves[m].To.Id) == node)
                {
                    problems.Add(new JumpProblem(m, "the body cannot crouch (test)") { Stance = stance });
                }
            }

            PathsRefused += problems.Count > 0 ? 1 : 0;
            return new JumpAnimation(CharacterPresets.Model("skeleton"), moves, new float[moves.Count - 1], [], [], problems, 0, 0);
        }

        public bool CanStand(PoseEvaluation pose) => true;
    }

    /// <summary>The first jump of the best path that takes off from (or lands on) a roadmap node other than the start and goal.</summary>
    private static (Roadmap Roadmap, int Node) Inner(ProblemStance stance)
    {
        (PlanningScene scene, BakeResult bake) = GapCourseBake.Value;
        PlanResult best = new PathQuery(scene, bake.Roadmap).Plan(GapCourse.From, GapCourse.To, AsSearched);
        Assume.That(best.Status, Is.EqualTo(PlannerStatus.Exact));
        Assume.That(best.Jumps, Has.Count.GreaterThanOrEqualTo(2));
        return (bake.Roadmap, stance == ProblemStance.Takeoff ? best.Jumps[1].From.Id : best.Jumps[0].To.Id);
    }

    [Test]
    public void NoJumpTakesOffFromOrLandsOnAStanceSetAside()
    {
        (PlanningScene scene, BakeResult bake) = GapCourseBake.Value;
        (_, int takeoff) = Inner(ProblemStance.Takeoff);
        (_, int landing) = Inner(ProblemStance.Landing);
        var query = new PathQuery(scene, bake.Roadmap);
        PlanResult noTakeoff = query.Plan(GapCourse.From, GapCourse.To, AsSearched with { NoTakeoffs = new HashSet<int> { takeoff } });
        PlanResult noLanding = query.Plan(GapCourse.From, GapCourse.To, AsSearched with { NoLandings = new HashSet<int> { landing } });
        Assert.Multiple(() =>
        {
            Assert.That(noTakeoff.Status, Is.EqualTo(PlannerStatus.Exact), noTakeoff.Reason);
            Assert.That(noTakeoff.Jumps.Select(j => j.From.Id), Has.No.Member(takeoff));
            Assert.That(noLanding.Status, Is.EqualTo(PlannerStatus.Exact), noLanding.Reason);
            Assert.That(noLanding.Jumps.Select(j => j.To.Id), Has.No.Member(landing));
        });
    }

    [TestCase(true)]
    [TestCase(false)]
    public void AStanceTheBodyCannotDipOnIsSetAsideInOneRound(bool takeoff)
    {
        ProblemStance stance = takeoff ? ProblemStance.Takeoff : ProblemStance.Landing;
        (PlanningScene scene, _) = GapCourseBake.Value;
        (Roadmap roadmap, int node) = Inner(stance);
        var animator = new StanceRefuser(node, stance);
        AnimatedPlan plan = new AnimatedPlanner(scene, animator).Plan(roadmap, GapCourse.From, GapCourse.To, AsSearched, rounds: 20);
        Assert.Multiple(() =>
        {
            Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
            Assert.That(animator.PathsRefused, Is.EqualTo(1), "every jump from (to) the stance set aside with the first");
            Assert.That(plan.Rejected, Has.Count.EqualTo(1));
            Assert.That(plan.Result.Jumps.Select(j => stance == ProblemStance.Takeoff ? j.From.Id : j.To.Id), Has.No.Member(node));
            Assert.That(plan.Result.Reason, Does.Contain("after setting aside 1 jump"));
        });
    }

    /// <summary>
    /// A stance no limb reaches from (here a landing whose trunk stands 1.5 m above the contacts it reports on the
    /// platform: a roadmap node that the reduced character's estimates accepted and the whole body cannot stand on) fails every jump to it, whatever the jump's
    /// velocity: the animator reports it as a problem of the landing stance, which the repair sets aside for every jump
    /// at once (<see cref="AStanceTheBodyCannotDipOnIsSetAsideInOneRound"/>), not one jump per search. Before, such a
    /// node beside a door's wall cost a user's human rig 13 searches and 23 jumps set aside, two by two.
    /// </summary>
    [Test]
    public void AStanceNoLimbReachesIsAProblemOfTheStanceForEveryJump()
    {
        WalkWorld world = WalkWorld.Create(WalkWorld.GapCourse(), "skeleton");
        RoadmapNode from = world.Stance(new Vector3(-7.3f, 0f, 0.5f), 0, Vector3.UnitX);
        RoadmapNode ground = world.Stance(new Vector3(-5.5f, 0f, 0f), 1, Vector3.UnitX);
        var lift = new Vector3(0f, 1.5f, 0f);
        var floating = new RoadmapNode(1, ground.Pose with { Position = ground.Pose.Position + lift }, ground.Cone, ground.Contacts);
        JumpAnimation animation = world.Animator.Animate([world.Jump(from, floating)]);
        JumpProblem[] landing = [.. animation.Problems.Where(p => p.Reason.StartsWith("landing: no limb could reach a surface", StringComparison.Ordinal))];
        Assert.Multiple(() =>
        {
            Assert.That(landing, Has.Length.EqualTo(1), () => string.Join("; ", animation.Problems.Select(p => p.Reason)));
            Assert.That(landing.Select(p => p.Stance), Has.All.EqualTo(ProblemStance.Landing), "a problem of the landing stance");
            Assert.That(animation.Problems.Where(p => p.Reason.StartsWith("takeoff:", StringComparison.Ordinal)), Is.Empty, "the takeoff stands");
        });
    }

    /// <summary>The gap course's best path as searched (the ant's: jumps only).</summary>
    private static PlanResult BestAsSearched()
    {
        (PlanningScene scene, BakeResult bake) = GapCourseBake.Value;
        PlanResult best = new PathQuery(scene, bake.Roadmap).Plan(GapCourse.From, GapCourse.To, AsSearched);
        Assume.That(best.Status, Is.EqualTo(PlannerStatus.Exact));
        return best;
    }

    [Test]
    public void AStanceProblemOfAMoveCutFromAJumpGivesTheJumpBackWhole()
    {
        var repair = new JumpRepair();
        PlanResult best = BestAsSearched();
        Jump jump = best.Jumps[0];
        Jump cut = jump with { CutFrom = [(jump.From.Id, jump.To.Id)] };
        var animation = new JumpAnimation(CharacterPresets.Model("skeleton"), [cut], [], [], [], [new JumpProblem(0, "cannot crouch (test)") { Stance = ProblemStance.Takeoff }], 0, 0);
        repair.Reject([cut], animation);
        Assert.Multiple(() =>
        {
            Assert.That(repair.NoTakeoffs, Is.Empty, "a cut move's takeoff is not a searched stance");
            Assert.That(repair.Uncut, Does.Contain((jump.From.Id, jump.To.Id)));
        });
    }

    /// <summary>
    /// Two moves made from one faced jump (the hop turning into its takeoff and the jump itself) failing in the same
    /// animation are one failure of that jump: it is given back whole (turned by hops next time), not also left
    /// unturned, which only a second failing animation does.
    /// </summary>
    [Test]
    public void MovesOfOneFacedJumpFailingTogetherGiveItBackOnce()
    {
        var repair = new JumpRepair();
        PlanResult best = BestAsSearched();
        Assume.That(best.Jumps, Has.Count.GreaterThanOrEqualTo(2));
        Jump jump = best.Jumps[1];
        (int, int) id = (jump.From.Id, jump.To.Id);
        Move[] path = [best.Jumps[0] with { CutFrom = [id] }, jump with { CutFrom = [id] }];
        JumpAnimation Failing() => new(CharacterPresets.Model("skeleton"), path, new float[path.Length - 1], [], [], [new JumpProblem(0, "left_foot cannot hold its foothold (test)"), new JumpProblem(1, "bone 'tail_1' passes through the level (test)")], 0, 0);

        int first = repair.Reject(path, Failing());
        bool unturnedAfterOne = repair.Unfaced.Contains(id);
        repair.Reject(path, Failing());
        Assert.Multiple(() =>
        {
            Assert.That(first, Is.EqualTo(1), "one jump given back");
            Assert.That(repair.Uncut, Does.Contain(id));
            Assert.That(unturnedAfterOne, Is.False, "one failing animation does not also leave the jump unturned");
            Assert.That(repair.Unfaced, Does.Contain(id), "a second failing animation does");
        });
    }

    /// <summary>
    /// A walk into a turned takeoff, made from the same jump as the jump from it, failing in the animation in which the
    /// body cannot crouch on that takeoff: the takeoff is refused (the next search places another, and the walk is
    /// made again to it), and the jump is not given back whole for the walk. Given back, it was flown as searched (a
    /// tailed quadruped's jump onto a tread landed 48° off its way). A walk failing beside a jump that fails otherwise
    /// still gives the jump back.
    /// </summary>
    [TestCase(true, TestName = "A walk into a turned takeoff refused in the same animation does not give its jump back")]
    [TestCase(false, TestName = "A walk into a turned takeoff failing beside a jump that fails otherwise gives its jump back")]
    public void AWalkIntoATakeoffRefusedNowDoesNotGiveItsJumpBack(bool crouch)
    {
        (Jump jump, (int, int) id, JumpRepair repair, RoadmapNode takeoff) = TurnedTakeoff();
        Vector3 start = jump.From.ContactCentre - new Vector3(1f, 0f, 0f);
        var before = new RoadmapNode(5, new Ballistic.Planner.Geometry.RootPose(jump.From.Pose.Position - new Vector3(1f, 0f, 0f), jump.From.Pose.Rotation), jump.From.Cone, jump.From.Contacts);
        Move[] path = [new Walk(before, takeoff, [start, jump.From.ContactCentre], 1f) { CutFrom = [id] }, new Jump(takeoff, jump.To, jump.Arc) { CutFrom = [id] }];
        JumpProblem jumping = crouch ? new JumpProblem(1, "the body cannot crouch before takeoff (test)") { Stance = ProblemStance.Takeoff } : new JumpProblem(1, "bone 'tail_1' passes through the level (test)");
        var animation = new JumpAnimation(CharacterPresets.Model("skeleton"), path, new float[path.Length - 1], [], [], [new JumpProblem(0, "left_foot cannot hold its foothold (test)", 0.9f), jumping], 0, 0);
        repair.Reject(path, animation);
        Assert.Multiple(() =>
        {
            Assert.That(repair.RefusedTurns.Any(r => JumpRepair.IsRefused(r, takeoff.Pose)), Is.EqualTo(crouch), "the turned takeoff refused");
            Assert.That(repair.Uncut.Contains(id), Is.EqualTo(!crouch), "the jump given back whole");
        });
    }

    /// <summary>
    /// A faced jump from a placed takeoff on which a limb hits the level in flight: when the hit is next to the takeoff
    /// (in the first tenth of the flight: a spider's front leg, free against the face it jumps up, swept into it as the
    /// body rises), the takeoff is refused and the next search's facer places another, the jump not given back whole;
    /// a hit mid-flight is the jump's own and gives the jump back, the takeoff not refused. Before, every such hit
    /// gave the jump back and the spider, after two rounds, leapt up the face as searched, backwards.
    /// </summary>
    [TestCase(true, TestName = "A limb hitting the level just after a turned takeoff refuses that takeoff")]
    [TestCase(false, TestName = "A limb hitting the level mid-flight gives the turned jump back whole")]
    public void ALimbHittingTheLevelNextToATurnedTakeoffRefusesIt(bool nearTakeoff)
    {
        (Jump jump, (int, int) id, JumpRepair repair, RoadmapNode takeoff) = TurnedTakeoff();
        Move[] path = [new Jump(takeoff, jump.To, jump.Arc) { CutFrom = [id] }];
        var hit = new JumpProblem(0, "l1 passes through the level in flight (test) whatever pose it takes") { Near = nearTakeoff ? ProblemStance.Takeoff : ProblemStance.None };
        var animation = new JumpAnimation(CharacterPresets.Model("skeleton"), path, [], [], [], [hit], 0, 0);
        repair.Reject(path, animation);
        Assert.Multiple(() =>
        {
            Assert.That(repair.RefusedTurns.Any(r => JumpRepair.IsRefused(r, takeoff.Pose)), Is.EqualTo(nearTakeoff), "the turned takeoff refused");
            Assert.That(repair.Uncut.Contains(id), Is.EqualTo(!nearTakeoff), "the jump given back whole");
            Assert.That(repair.NoTakeoffs, Is.Empty, "no stance set aside for every jump");
        });
    }

    /// <summary>
    /// A walk from a turned stance (placed for a faced jump, so made from that jump) to a stance the search gave,
    /// failing far along it (past half its length and 0.5 m), where it steps as the searched walk would: it hops over
    /// that spot and the jump stays turned. Before, the jump was given back whole for it, and the spider on the
    /// holes-and-debris level, whose walk into its goal failed in its last centimetre whichever stance it left, leapt
    /// 157° off its way. Failing near the turned stance, the walk still gives its jump back.
    /// </summary>
    [TestCase(1.9f, true, TestName = "A walk from a turned stance failing far from it hops over the spot and keeps its jump turned")]
    [TestCase(0.3f, false, TestName = "A walk from a turned stance failing next to it gives its jump back whole")]
    public void AWalkFromATurnedStanceFailingFarFromItHopsOverTheSpot(float along, bool far)
    {
        (Jump jump, (int, int) id, JumpRepair repair, RoadmapNode turned) = TurnedTakeoff();
        Vector3 start = turned.ContactCentre;
        var searched = new RoadmapNode(5, new Ballistic.Planner.Geometry.RootPose(turned.Pose.Position + new Vector3(2f, 0f, 0f), turned.Pose.Rotation), turned.Cone, turned.Contacts);
        var walk = new Walk(turned, searched, [start, start + new Vector3(2f, 0f, 0f)], 1f) { CutFrom = [id] };
        Move[] path = [walk];
        var animation = new JumpAnimation(CharacterPresets.Model("skeleton"), path, [], [], [], [new JumpProblem(0, "l2 cannot swing to its next foothold (test)", along)], 0, 0);
        repair.Reject(path, animation);
        Assert.Multiple(() =>
        {
            Assert.That(repair.HopSpots, Has.Count.EqualTo(far ? 1 : 0), "the spot hopped over");
            Assert.That(repair.Uncut.Contains(id), Is.EqualTo(!far), "the jump given back whole");
            Assert.That(repair.CutFailures, Is.EqualTo(far ? 0 : 1), "a round that cut rounds count");
            Assert.That(repair.Excluded, Is.Empty, "nothing set aside for every search");
        });
        if (far)
        {
            Assert.That(Vector3.Distance(repair.HopSpots[0], walk.PointAt(along)), Is.LessThan(1e-4f), "where it failed");
        }
    }

    /// <summary>
    /// The first jump of the best path as searched, its id, a repair whose placed stances start at id 1000, and a
    /// takeoff placed there (id 1000) standing where the jump's own does, as the facer places a turned one.
    /// </summary>
    private static (Jump Jump, (int, int) Id, JumpRepair Repair, RoadmapNode Takeoff) TurnedTakeoff()
    {
        Jump jump = BestAsSearched().Jumps[0];
        const int placed = 1000;
        return (jump, (jump.From.Id, jump.To.Id), new JumpRepair(placed), new RoadmapNode(placed, jump.From.Pose, jump.From.Cone, jump.From.Contacts));
    }
}
