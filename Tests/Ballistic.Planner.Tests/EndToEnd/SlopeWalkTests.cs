using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.EndToEnd;

/// <summary>
/// A rig made elsewhere, standing on straight legs in its contact pose (the user's dog, with anchor nodes between its
/// bones), walks up and down plain ramps of 5°, 10° and 15°, fully right, passing the animator's eye. Its derived walking
/// limit was 0° (<see cref="ReducedModelBuilder.WalkableSlope"/> kept the trunk at the contact pose's height, where a
/// straight leg reaches no further), so it hopped up and down any ramp. Its hips cruise upright (the eye's 0.88 of
/// each leg above its held foot) on 10° too: its trunk pitches with the ground (<see cref="Walk.PitchSpan"/>), where
/// a level trunk folded its uphill legs (0.84–0.86 L).
/// </summary>
[Category("EndToEnd")]
public sealed class SlopeWalkTests
{
    /// <summary>A ramp of <paramref name="degrees"/> with the dog loaded from <paramref name="folder"/> (its files stay there until its GLBs are written).</summary>
    private static Sweep.Setup Ramp(float degrees, string folder)
    {
        // Seven metres of ground rising along +X, four wide, through the origin: a floor turned about Z.
        Level ramp = new LevelBuilder("ramp").AddFloor(-3.5f, -2f, 3.5f, 2f, 0f, n: 8, toWorld: Matrix4x4.CreateRotationZ(degrees * MathF.PI / 180f)).Build();
        (CharacterModel model, ReducedCharacter reduced) = ForeignCharacters.Dog().Load(folder);
        Assert.That(reduced.Walking.MaxSlopeAlongDegrees, Is.GreaterThanOrEqualTo(degrees), "the dog's derived walking limit");
        return Sweep.Prepare("ramp", ramp, model, reduced);
    }

    [TestCase(5f, -2.5f, 2.5f)]
    [TestCase(5f, 2.5f, -2.5f)]
    [TestCase(10f, -2.5f, 2.5f)]
    [TestCase(10f, 2.5f, -2.5f)]
    [TestCase(15f, -2.5f, 2.5f)]
    [TestCase(15f, 2.5f, -2.5f)]
    public void ADogWithStraightLegsWalksUpAndDownARamp(float degrees, float x0, float x1)
    {
        float rise = MathF.Tan(degrees * MathF.PI / 180f); // the ground's height per metre along X
        string folder = RigFolders.For($"dog-ramp-{degrees}-{x0}");
        try
        {
            (AnimatedPlan plan, AuditReport report, AnimatorEye? _) = Sweep.Plan(Ramp(degrees, folder), new Vector3(x0, x0 * rise, 0f), new Vector3(x1, x1 * rise, 0f));
            Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
            Assert.That(plan.Result.Moves.OfType<Jump>(), Is.Empty, $"no hop up or down a plain ramp: {plan.Result.Reason}");
            Assert.That(plan.Result.Moves.OfType<Walk>(), Is.Not.Empty);
            Assert.That(report.FullyRight, Is.True, report.ToString());
            SweepTests.AssertEveryCriterion(report.Look!, $"the dog from x = {x0} to {x1} on {degrees}°", _ => false, "no list");
        }
        finally
        {
            RigFolders.Remove(folder);
        }
    }
}
