using System.Numerics;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Readme;

/// <summary>
/// The README's rooftops rows: an 800-node walking roadmap of the rooftops (440,000 triangles) for the jumperman,
/// baked once in the fixture's one-time setup (about 30 to 60 s on two cores) and shared by the tests below.
/// </summary>
[Category("EndToEnd")]
public sealed class RooftopsRowTests
{
    [OneTimeSetUp]
    public void BakeTheRooftops() => SideBySide.Roadmap("rooftops", "jumperman");

    [Test]
    public void TheSideBySideRowsAreWhatThePlannerGives() => ReadmeFiguresTests.CheckRows("rooftops");

    [Test]
    public void OnTheRooftopsTheJumpermanWalksTheRoofsAndJumpsFewerTimes()
    {
        // The rooftops row of the README's side-by-side table: an 800-node roadmap (seed 1) and the first of its seeded
        // node pairs. Jump only: 5 jumps; walk + jump: 2 jumps and walks across the roofs between them, each jump going
        // from one roof to another (no walk links its ends).
        (PlanningScene scene, Roadmap roadmap) = SideBySide.Roadmap("rooftops", "jumperman");
        (Vector3 from, Vector3 to) = SideBySide.Requests("rooftops")[0];
        var query = new PathQuery(scene, roadmap);
        PlanResult jumped = query.Plan(from, to, new QuerySettings { Locomotion = Locomotion.Jump });
        PlanResult walked = query.Plan(from, to, new QuerySettings { Locomotion = Locomotion.WalkAndJump });
        TestContext.Out.WriteLine($"({from.X:0.#}, {from.Z:0.#}) → ({to.X:0.#}, {to.Z:0.#}): jump only {jumped.Reason}; walk + jump {walked.Reason}");
        Assert.That(jumped.Status, Is.EqualTo(PlannerStatus.Exact), jumped.Reason);
        Assert.That(walked.Status, Is.EqualTo(PlannerStatus.Exact), walked.Reason);
        Assert.Multiple(() =>
        {
            Assert.That(walked.Jumps, Has.Count.LessThan(jumped.Jumps.Count));
            Assert.That(walked.Walks, Is.Not.Empty, "the roofs are walked");
            foreach (Jump jump in walked.Jumps)
            {
                Assert.That(scene.Walking.Steer(jump.From, jump.To).Walk, Is.Null, $"jump {jump.From.Id} → {jump.To.Id} could be walked");
            }
        });

        AuditReport audit = PlanAudit.Check("rooftops walk+jump", scene, from, to, walked, null);
        Assert.That(audit.Violations, Is.Empty, audit.ToString());
    }

}
