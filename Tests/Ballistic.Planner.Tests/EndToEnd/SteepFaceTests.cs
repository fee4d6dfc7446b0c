using System.Numerics;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.EndToEnd;

/// <summary>
/// Quadrupeds made elsewhere crossing the curved terrain corner to corner (the sweep's request 1 there), whose dune
/// faces tilt past 30°: on a face steeper than the friction cone is wide and than the rig walks, no turn is physical,
/// walked or hopped, so a jump leaving such a stance off its way stays off it. Such a jump now costs as much more in
/// the search as an unturned jump does where jumps are not turned (<see cref="PathQuery.UnfacedJumpCost"/>), and the
/// routes go round those faces. And a free forelimb folding as the body absorbs a landing on such a face, where the
/// slope ahead comes near, is moved the least way that stays clear at each depth (a quarter, then half the way to the
/// flexion pose before tucking it fully): it had tucked fully at one depth and unfolded at the next, 33° and 35° in a
/// displayed frame between frames of 9–15°.
/// </summary>
[Category("EndToEnd")]
public sealed class SteepFaceTests
{
    /// <summary>Where the foreign rigs' files are written (removed when the fixture ends).</summary>
    private static readonly string RigFolder = RigFolders.For("steep-face");

    [OneTimeTearDown]
    public void RemoveTheRigFiles() => RigFolders.Remove(RigFolder);

    private static (AnimatedPlan Plan, AuditReport Report) Cross(string rig)
    {
        (Sweep.Setup setup, (Vector3 From, Vector3 To)[] requests) = Sweep.PrepareForeign("curved", rig, Path.Combine(RigFolder, rig));
        (AnimatedPlan plan, AuditReport report, _) = Sweep.Plan(setup, requests[1].From, requests[1].To);
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        return (plan, report);
    }

    /// <summary>
    /// The dog (anchor empties between its bones) and the tailed quadruped (several root bones): before, one walk and six
    /// jumps, and one walk and seven; now one walk and two jumps, and three walks and five, every criterion of the
    /// animator's eye passing.
    /// </summary>
    [TestCase("dog", 3, 1)]
    [TestCase("tailed", 5, 2)]
    public void AQuadrupedCrossingTheDunesGoesRoundFacesItCouldNotTurnOn(string rig, int mostJumps, int leastWalks)
    {
        (AnimatedPlan plan, AuditReport report) = Cross(rig);
        Assert.Multiple(() =>
        {
            Assert.That(plan.Result.Jumps, Has.Count.LessThanOrEqualTo(mostJumps), plan.Result.Reason);
            Assert.That(plan.Result.Walks.Count(), Is.GreaterThanOrEqualTo(leastWalks), plan.Result.Reason);
            Assert.That(report.FullyRight, Is.True, report.ToString());
            foreach ((string name, AnimatorEye.Criterion criterion) in report.Look!.All)
            {
                Assert.That(criterion.Passes, Is.True, $"{name}: {criterion}");
            }
        });
    }

    /// <summary>
    /// The Rigify panda (foot IK helpers, modelled mid-stride): its route now lands last on a 29° face where only its
    /// hind feet hold, its forelimbs free as it absorbs the landing; no limb joint snaps anywhere in its clip. (It still
    /// takes off 161° off its way from a 31° face that rings its start: <c>SweepTests.NotYetEveryPlan</c>.)
    /// </summary>
    [Test]
    public void APandasFreeForelimbAbsorbingALandingOnASteepFaceDoesNotSnap()
    {
        (AnimatedPlan plan, AuditReport report) = Cross("panda");
        Assert.Multiple(() =>
        {
            Assert.That(plan.Result.Jumps, Has.Count.LessThanOrEqualTo(9), "eleven before");
            Assert.That(report.Look!.Snaps.Passes, Is.True, report.Look.Snaps.ToString());
        });
    }
}
