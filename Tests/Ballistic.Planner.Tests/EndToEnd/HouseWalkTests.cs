using System.Numerics;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.EndToEnd;

/// <summary>
/// Issue 24's staircase with a landing and a door, in a closed two-storey house (<see cref="ForeignLevels.House"/>:
/// a 1.2 m front door, two flights of eight 17.6 cm risers and 28 cm treads with a 1.2 m landing between them, up to
/// a gallery 2.82 m up), on the roadmap the editor bakes (the whole level, not a corridor round one request): the
/// skeleton walks from the yard in through the door and up both flights to the gallery, and from the ground floor up,
/// walks only, fully right by the audit and every criterion of the animator's eye read from its GLB. (Baked only
/// until the request connects, the corridor the bake samples first misses the stairs along the north wall: the
/// skeleton leaps the 2.8 m onto the gallery from the floor, a jump its speeds allow.)
/// </summary>
[Category("EndToEnd")]
public sealed class HouseWalkTests
{
    private static readonly Lazy<(Sweep.Setup Setup, Roadmap Roadmap)> House = new(() =>
    {
        Sweep.Setup setup = Sweep.Prepare("house", ForeignLevels.House().Level, "skeleton");
        Roadmap roadmap = new RoadmapBaker(setup.Scene).Bake(new BakeSettings { Seed = 1, Threads = 2, MaxNodes = 600, FocusOnRequest = false }).Roadmap;
        return (setup, roadmap);
    });

    [TestCase(-9f, 0f, 0f, TestName = "From the yard the skeleton walks in through the front door and up both flights to the gallery")]
    [TestCase(-3f, 0f, 2f, TestName = "From the ground floor the skeleton walks up both flights to the gallery")]
    public void TheSkeletonWalksUpTheStairsToTheGallery(float x, float y, float z)
    {
        (Sweep.Setup setup, Roadmap roadmap) = House.Value;
        Vector3 from = new(x, y, z);
        Vector3 gallery = ForeignLevels.House().Requests[1].To; // on the gallery, the sweep's goal up the stairs
        AnimatedPlan plan = setup.Planner.Plan(roadmap, from, gallery);
        AuditReport report = Sweep.Audit(setup, from, gallery, plan).Report;
        TestContext.Out.WriteLine(report);
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        Walk[] walks = [.. plan.Result.Moves.OfType<Walk>()];
        Vector3[] points = [.. walks.SelectMany(w => w.Path)];
        Assert.Multiple(() =>
        {
            Assert.That(plan.Result.Moves, Has.All.InstanceOf<Walk>(), "walks only: no leap onto the gallery or up the flight");
            Assert.That(report.FullyRight, Is.True, report.ToString());
            Assert.That(report.Look!.All.Where(c => !c.Criterion.Passes).Select(c => $"{c.Name}: {c.Criterion}"), Is.Empty);
            Assert.That(points.Any(p => p.Y > 1.3f && p.Y < 1.5f && p.Z > 2.8f), Is.True, "the walk crosses the landing");
            Assert.That(points.Any(p => p.X > -1f && p.X < 4.68f && p.Z > 2.8f && p.Y > 0.1f), Is.True, "the walk goes up the flights along the north wall");
        });

        if (x < -6.2f)
        {
            // Through the door: the path crosses the front wall's plane, and wherever it does, within the door's width.
            int crossings = 0;
            for (int k = 1; k < points.Length; k++)
            {
                if ((points[k - 1].X + 6.1f) * (points[k].X + 6.1f) <= 0f)
                {
                    crossings++;
                    Assert.That(MathF.Abs(points[k].Z), Is.LessThan(0.6f), $"the path crosses the front wall at z = {points[k].Z:0.00}, in the door");
                }
            }

            Assert.That(crossings, Is.GreaterThan(0), "the walks cross the front wall");
        }
    }
}
