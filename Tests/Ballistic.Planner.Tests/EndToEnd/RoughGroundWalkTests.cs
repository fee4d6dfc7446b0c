using System.Numerics;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.EndToEnd;

/// <summary>
/// A walk over rough ground whose steps must shorten there (the foreign level's debris, the skeleton's third request:
/// a 2.4 m walk among the rubble) slows where they shorten, at the cadence of its level steps, as a person picks their
/// way over rubble. Before, that walk could not be animated and was set aside for jumps; with its hips held up over
/// gentler grades it was animated with steps shortened at full speed, 3.0 a second (the eye allows 2.6).
/// </summary>
[Category("EndToEnd")]
public sealed class RoughGroundWalkTests
{
    [Test]
    public void AWalkWhoseStepsShortenOverDebrisSlowsThereAtTheCadenceOfItsLevelSteps()
    {
        (Level level, (Vector3 From, Vector3 To)[] requests) = ForeignLevels.Get("holes-debris");
        Sweep.Setup setup = Sweep.Prepare("holes-debris", level, "skeleton");
        // Planned on the first connection's roadmap (not refined): baked on, the request walks elsewhere, off the rubble.
        (Vector3 from, Vector3 to) = requests[2];
        (AnimatedPlan plan, _) = setup.Planner.BakeAndPlan(from, to, new BakeSettings { Seed = 1, Threads = 2, MaxNodes = 600, Refine = false });
        Sweep.Planned planned = Sweep.Audit(setup, from, to, plan);
        Assert.That(planned.Report.FullyRight, Is.True, planned.Report.ToString());

        // The plan's moves are those animated (PlanJob): the slowed walk, whose time the animation takes.
        IReadOnlyList<Move> moves = planned.Plan.Result.Moves;
        Assert.That(moves, Is.EqualTo(planned.Plan.Animation!.Moves));
        Walk[] slowed = [.. moves.OfType<Walk>().Where(w => Enumerable.Range(0, 200).Any(i => w.PaceAt(w.Length * i / 199f) < 1f))];
        Assert.That(slowed, Is.Not.Empty, "a walk slowed where its steps shorten");
        Assert.That(slowed.All(w => !w.SlowsForSteps), Is.True, "slowed for its steps, not for stairs");

        // Its steps, read from the GLB, come at a walker's cadence; every other criterion of the eye passes too.
        AnimatorEye.Look look = planned.Report.Look!;
        Assert.That(look.Cadence.Seen, Is.Not.Empty, "the walk's cadence is measured");
        foreach ((string name, AnimatorEye.Criterion criterion) in look.All)
        {
            Assert.That(criterion.Passes, Is.True, $"{name}: {criterion}");
        }
    }
}
