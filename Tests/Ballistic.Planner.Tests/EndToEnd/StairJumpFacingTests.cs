using System.Numerics;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.EndToEnd;

/// <summary>
/// Issue 21's facing on stairs a small quadruped can only stand across: the tailed quadruped's body (0.55 m) is longer
/// than a tread (0.30 m) is deep, so its stances on the flight face along the treads, and every stance turned to face a
/// jump up the flight straddles two treads, where its front legs' upper bones meet the riser above when it lands.
/// Before, its jumps onto the treads took off 136° and 48° off their way and landed 86° and 48° off (the eye asks at
/// most 30° and 45°): the turned stances did not animate, so the jumps were flown as searched. Now the jump is swung
/// round toward the way its landing faces (<c>JumpFacer.Swing</c>): it takes off facing its way from a stance the
/// walk before it leads to, and lands at most 45° off it, across the tread.
/// </summary>
[Category("EndToEnd")]
public sealed class StairJumpFacingTests
{
    /// <summary>Where the rig's files are written (removed when the fixture ends).</summary>
    private static readonly string RigFolder = RigFolders.For("stair-facing");

    private static readonly Lazy<(Sweep.Setup Setup, (Vector3 From, Vector3 To)[] Requests)> Stairs = new(() => Sweep.PrepareForeign("stairs", "tailed", RigFolder));

    [OneTimeTearDown]
    public void RemoveTheRigFiles() => RigFolders.Remove(RigFolder);

    [TestCase(1, TestName = "A tailed quadruped walks to the flight and jumps up onto the fourth tread facing its jump")]
    [TestCase(3, TestName = "A tailed quadruped jumps from the floor onto the third tread facing its jump")]
    public void ASmallQuadrupedFacesItsJumpOntoATread(int request)
    {
        (Sweep.Setup setup, (Vector3 From, Vector3 To)[] requests) = Stairs.Value;
        (AnimatedPlan plan, AuditReport report, _) = Sweep.Plan(setup, requests[request].From, requests[request].To);
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        Assert.That(report.FullyRight, Is.True, report.ToString());
        Assert.That(report.Look!.Facing.Passes, Is.True, $"facing: {report.Look.Facing}");

        Jump[] far = [.. plan.Result.Jumps.Where(j => Across(j).Length() >= AnimatorEye.FacingDistance)];
        Assert.That(far, Is.Not.Empty, "the plan jumps onto the flight");
        foreach (Jump jump in far)
        {
            // Takeoff within 30° of the jump's way, landing within 45°, the landing standing across the flight
            // (its heading within 20° of the treads' run, ±Z): the jump was swung, not the landing turned.
            Assert.That(Off(jump.From, jump), Is.LessThanOrEqualTo(30f), "takeoff off its way, degrees");
            Assert.That(Off(jump.To, jump), Is.LessThanOrEqualTo(45f), "landing off its way, degrees");
            Assert.That(MathF.Abs(jump.To.Pose.Forward.Z), Is.GreaterThan(MathF.Cos(20f * MathF.PI / 180f)), "the landing stands along the tread");
        }

        Assert.That(plan.Result.Moves[^2], Is.InstanceOf<Walk>(), "a walk leads to the swung takeoff");
    }

    /// <summary>
    /// From the floor to the top landing (the sweep's stairs/0) the route jumps off a tread where the front feet stand
    /// just short of the next riser. Retracted however quickly, their skin entered that riser 8–17 ms after takeoff in
    /// every flight pose tried ("left_front passes through the level in flight (0.004 s after takeoff) whatever pose it
    /// takes"): the feet rode forward with the body before their joints lifted them. The plan set 6 jumps and 3 walks
    /// aside and its jump onto the landing took off 112° and landed 154° off its way. Now such a foot is lifted straight
    /// off its contact first, as far as the body has risen, up to the step height, and retracted from there: no jump is
    /// set aside for a limb in flight, and every far jump lands within the eye's 45° of its way.
    /// </summary>
    [Test]
    public void AFootJustShortOfARiserIsLiftedOffItsTreadBeforeItSwingsOn()
    {
        (Sweep.Setup setup, (Vector3 From, Vector3 To)[] requests) = Stairs.Value;
        (AnimatedPlan plan, AuditReport report, _) = Sweep.Plan(setup, requests[0].From, requests[0].To);
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        Assert.That(report.FullyRight, Is.True, report.ToString());
        Assert.That(plan.Rejected.Select(r => r.Reason), Has.None.Contains("in flight"), "no jump set aside for a limb passing through the level in flight");
        Jump[] far = [.. plan.Result.Jumps.Where(j => Across(j).Length() >= AnimatorEye.FacingDistance)];
        Assert.That(far, Is.Not.Empty, "the plan jumps up the flight");
        Assert.That(far.Select(j => Off(j.To, j)), Has.All.LessThanOrEqualTo(AnimatorEye.LandingFacing), "landings off their way, degrees");
    }

    private static Vector2 Across(Jump jump) => new(jump.Arc.End.X - jump.Arc.Start.X, jump.Arc.End.Z - jump.Arc.Start.Z);

    /// <summary>Degrees between a stance's heading and a jump's direction across.</summary>
    private static float Off(RoadmapNode stance, Jump jump)
    {
        Vector3 f = stance.Pose.Forward;
        var a = Vector2.Normalize(new Vector2(f.X, f.Z));
        return MathF.Acos(Math.Clamp(Vector2.Dot(a, Vector2.Normalize(Across(jump))), -1f, 1f)) * 180f / MathF.PI;
    }
}
