using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.EndToEnd;

/// <summary>
/// Issue 24's stairs, climbed as a designer expects (the foreign staircase: eight 17 cm risers, 30 cm treads, 2 m
/// wide, each step its own mesh): the skeleton walks from the floor up to the landing, and to a tread halfway up, in
/// one walk, no jump, fully right by the audit and every criterion of the animator's eye read from its GLB. On the
/// flight it slows (<see cref="Walk.ClimbShare"/>) and shortens its steps by as much, and every foot it sets down
/// there lies on a tread, clear of the riser behind and the nosing ahead. Before, the upright walk put a foot two
/// treads and 0.66 m up in one swing at full speed and failed; the walk fell back to short steps (4.4 a second on the
/// floor before the stairs) or was set aside for jumps. Down the whole flight the skeleton walks too: before, its
/// trailing foot on the tread above was set down at the nosing, chosen where the unlifted hips stood a riser too low
/// for it to hold behind them, and once the lift raised the hips it could not roll onto its ball (past the edge), so
/// the walk was replaced by hops over the flight; its footholds are now chosen again where the lift holds the hips.
/// </summary>
[Category("EndToEnd")]
public sealed class StairWalkTests
{
    private static readonly Lazy<Sweep.Setup> Stairs = new(() => Sweep.Prepare("stairs", ForeignLevels.Get("stairs").Level, "skeleton"));

    /// <summary>Where the user's human rig's files are written (removed when the fixture ends).</summary>
    private static readonly string RigFolder = RigFolders.For("stairs");

    private static readonly Lazy<Sweep.Setup> HumanOnStairs = new(() => Sweep.PrepareForeign("stairs", "human", RigFolder).Setup);

    [OneTimeTearDown]
    public void RemoveTheRigFiles() => RigFolders.Remove(RigFolder);

    /// <summary>
    /// A user's human rig (pelvis and legs with 90° rest rotations, a limbs-only spec) walks up the whole flight and
    /// back down it, one walk each way, fully right; before, it hopped up (two walks and a jump) and down (two walks
    /// and two jumps). Steps shorten by the pace where the foot lands as well as where the trunk is, so the last step
    /// onto the flight is already a stair step (the skeleton's full stride from the landing's edge, 1.16 m down to the
    /// second tread, was out of reach).
    /// </summary>
    [TestCase(-4f, 0f, 0f, 6.5f, 1.36f, 0f, TestName = "A user's human rig walks up the whole flight")]
    [TestCase(6.5f, 1.36f, 1.5f, -4f, 0f, -2f, TestName = "A user's human rig walks down the whole flight")]
    public void AUsersHumanRigWalksUpAndDownTheStairs(float x0, float y0, float z0, float x1, float y1, float z1)
    {
        (AnimatedPlan plan, AuditReport report, _) = Sweep.Plan(HumanOnStairs.Value, new Vector3(x0, y0, z0), new Vector3(x1, y1, z1));
        SweepTests.AssertOneCleanWalk(plan, report);
    }

    /// <summary>
    /// Up the flight the skeleton steps at the cadence of its steps on the floor, a tread a step, and the step onto the
    /// flight too (the walk slows a quarter step before the first riser, <see cref="Walk.ClimbLead"/>): each at least
    /// 0.85 of the floor's median time between foot placements. Before, a walk ending on a tread took its steps up the
    /// flight 0.22-0.26 s apart (3.8-4.5 a second: its steps on the stairs were those its legs reach on the one tread it
    /// ends on, at the walk's pace there) and the step onto the flight 0.26 s after the last on the floor, 0.42 s
    /// apart; the eye counted 2.77 steps a second on the floor for the short walk onto the third tread.
    /// </summary>
    [TestCase(0f, 0f, -2f, 2.75f, 0.51f, 0.5f, TestName = "The skeleton steps onto and up the stairs to the third tread at its cadence on the floor")]
    [TestCase(-2f, 0f, 2f, 3.35f, 0.68f, 0f, TestName = "The skeleton steps onto and up the stairs to a tread halfway up at its cadence on the floor")]
    [TestCase(-4f, 0f, 0f, 6.5f, 1.36f, 0f, TestName = "The skeleton steps onto and up the whole flight at its cadence on the floor")]
    public void TheSkeletonStepsUpTheStairsAtItsCadenceOnTheFloor(float x0, float y0, float z0, float x1, float y1, float z1)
    {
        (AnimatedPlan plan, _, _) = Sweep.Plan(Stairs.Value, new Vector3(x0, y0, z0), new Vector3(x1, y1, z1));
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        Assert.That(plan.Result.Moves, Has.Count.EqualTo(1).And.All.InstanceOf<Walk>(), "one walk");
        var walk = (Walk)plan.Result.Moves[0];
        JumpAnimation animation = plan.Animation!;

        // Placements while the walk cruises (after it speeds up, before it slows to its end stance), in time order.
        float from = walk.StartTurn + Walk.RampTime;
        float to = walk.StartTurn + walk.WalkTime - Walk.RampTime;
        ContactPhase[] placed = [.. animation.ContactPhases.Where(p => !p.OnBall && p.From >= from && p.From <= to).OrderBy(p => p.From)];
        var floor = new List<float>();
        var flight = new List<float>();
        float? onto = null;
        for (int k = 1; k < placed.Length; k++)
        {
            float interval = placed[k].From - placed[k - 1].From;
            bool before = placed[k - 1].Position.Y < 0.01f;
            bool after = placed[k].Position.Y < 0.01f;
            if (before && after)
            {
                floor.Add(interval);
            }
            else if (before)
            {
                onto ??= interval;
            }
            else if (!after && placed[k].Position.Y > placed[k - 1].Position.Y + 0.1f && placed[k].Position.Y < 1.3f)
            {
                flight.Add(interval);
            }
        }

        string seen = string.Join(", ", placed.Select(p => $"{animation.Model.Limbs[p.Limb].Name} {p.From:0.000} s at y {p.Position.Y:0.00}"));
        Assert.That(floor, Has.Count.GreaterThanOrEqualTo(2), seen);
        Assert.That(flight, Is.Not.Empty, seen);
        float level = floor.Order().ElementAt(floor.Count / 2);
        Assert.Multiple(() =>
        {
            Assert.That(onto, Is.GreaterThanOrEqualTo(0.85f * level), $"the step onto the flight, against {level:0.000} s on the floor: {seen}");
            Assert.That(flight.Order().ElementAt(flight.Count / 2), Is.GreaterThanOrEqualTo(0.85f * level), $"the steps up the flight ({string.Join(", ", flight.Select(f => f.ToString("0.000")))} s), against {level:0.000} s on the floor: {seen}");
        });
    }

    /// <summary>The least distance (metres) from a foothold on the flight to its tread's front and back edges.</summary>
    private const float EdgeClearance = 0.03f;

    [TestCase(-4f, 0f, 0f, 6.5f, 1.36f, 0f, TestName = "The skeleton walks up the stairs from the floor to the landing")]
    [TestCase(-2f, 0f, 2f, 3.35f, 0.68f, 0f, TestName = "The skeleton walks up to a tread halfway up the stairs")]
    [TestCase(6.5f, 1.36f, 1.5f, -4f, 0f, -2f, TestName = "The skeleton walks down the stairs from the landing to the floor")]
    public void TheSkeletonWalksUpAndDownTheStairs(float x0, float y0, float z0, float x1, float y1, float z1)
    {
        (AnimatedPlan plan, AuditReport report, _) = Sweep.Plan(Stairs.Value, new Vector3(x0, y0, z0), new Vector3(x1, y1, z1));
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        Assert.That(plan.Result.Moves.OfType<Jump>(), Is.Empty, "no jump on stairs the legs climb");
        Assert.That(plan.Result.Moves, Has.Count.EqualTo(1), "one walk");
        Assert.That(report.FullyRight, Is.True, report.ToString());
        foreach ((string name, AnimatorEye.Criterion criterion) in report.Look!.All)
        {
            Assert.That(criterion.Passes, Is.True, $"{name}: {criterion}");
        }

        // The walk slows on the flight, to about ClimbShare over the flight's grade (0.17 m per 0.3 m across), and
        // further where the gait shortens its steps to fit the treads (WalkGait.ShortStep, 0.85, at the least: going
        // down, 0.34).
        var walk = (Walk)plan.Result.Moves[0];
        float slowest = Enumerable.Range(0, 400).Select(i => walk.PaceAt(walk.Length * i / 399f)).Min();
        Assert.That(slowest, Is.InRange(0.85f * 0.35f, 0.75f), "the pace on the flight");

        // Every foothold on the flight lies on its tread, clear of both its edges (the top step is flush with the landing).
        JumpAnimation animation = plan.Animation!;
        ContactPhase[] onFlight = [.. animation.ContactPhases.Where(p => !p.OnBall && p.Position.X > 2f && p.Position.X < 4.1f && p.Position.Y > 0.1f)];
        Assert.That(onFlight, Is.Not.Empty, "feet set down on the stairs");
        foreach (ContactPhase phase in onFlight)
        {
            int tread = (int)MathF.Floor((phase.Position.X - 2f) / 0.3f);
            float back = 2f + (0.3f * tread);
            string where = $"{animation.Model.Limbs[phase.Limb].Name} at {phase.Position} ({phase.From:0.00}–{phase.To:0.00} s)";
            Assert.That(phase.Position.Y, Is.EqualTo(0.17f * (tread + 1)).Within(0.015f), $"{where}: on tread {tread}");
            Assert.That(MathF.Min(phase.Position.X - back, back + 0.3f - phase.Position.X), Is.GreaterThanOrEqualTo(EdgeClearance), $"{where}: clear of the tread's edges");
        }
    }
}
