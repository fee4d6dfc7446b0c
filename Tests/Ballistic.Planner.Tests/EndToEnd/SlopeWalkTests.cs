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
/// Rigs made elsewhere with feet ahead of and behind their trunks walk up and down plain ramps fully right, passing
/// the animator's eye: quadrupeds standing on straight legs in their contact pose (the user's dog, with anchor nodes
/// between its bones; the tailed quadruped, with several root bones; the Rigify panda, mid-stride), the 10 cm rat
/// (5° and 10°) and the eight-legged spider (10° and 20°). The quadrupeds' derived walking limits were 0°
/// (<see cref="ReducedModelBuilder.WalkableSlope"/> kept the trunk at the contact pose's height, where a straight leg
/// reaches no further), so they hopped up and down any ramp; the dog walks 5°, 10° and 15°, and the tailed
/// quadruped and the panda, whose feet hold no slope with the trunk a twentieth of the leg lower
/// (<see cref="ReducedModelBuilder.LowSlopeSink"/>), 5° and 10°. Their hips cruise upright (the eye's 0.88 of each leg
/// above its held foot) on 10° too, but for the tailed quadruped going up (<see cref="NotYetUpright"/>): the trunk
/// pitches with the ground (<see cref="Walk.PitchSpan"/>), where a level trunk folded the dog's uphill legs (0.84–0.86 L).
/// With a level trunk the tailed quadruped's hips sank on 5° too, it, the panda and the rat hopped 10° ramps (the rat
/// 15 times), and the spider failed walking down 10°.
/// </summary>
[Category("EndToEnd")]
public sealed class SlopeWalkTests
{
    /// <summary>
    /// Ramps on which a rig's hips cruise lower than the eye's upright walk asks (0.88 of each leg above its held foot),
    /// as (rig, degrees, from x): the tailed quadruped walking up 10° cruises at 0.865 L (down the same ramp it passes).
    /// Its straight legs hold its feet on slopes only with the trunk a tenth of the leg lower (0.9 L) in the first
    /// place, and going up its hind legs reach no higher. It must still fail there: the list only shrinks.
    /// </summary>
    private static readonly (string Rig, float Degrees, float From)[] NotYetUpright = [("tailed", 10f, -2.5f)];

    /// <summary>Rigs on ramps they walk up and down: (rig, degrees), from x = −2.5 to 2.5 m and back.</summary>
    private static readonly (string Rig, float Degrees)[] Ramps =
    [
        ("dog", 5f), ("dog", 10f), ("dog", 15f), ("tailed", 5f), ("tailed", 10f), ("panda", 5f), ("panda", 10f), ("spider", 10f), ("spider", 20f),
    ];

    /// <summary>Each of <see cref="Ramps"/> walked up (from x = −2.5 m) and down (from 2.5 m).</summary>
    public static IEnumerable<TestCaseData> UpAndDown() =>
        Ramps.SelectMany(r => new[] { new TestCaseData(r.Rig, r.Degrees, -2.5f, 2.5f), new TestCaseData(r.Rig, r.Degrees, 2.5f, -2.5f) });

    /// <summary>A ramp of <paramref name="degrees"/> with the rig <paramref name="rig"/> loaded from <paramref name="folder"/> (its files stay there until its GLBs are written).</summary>
    private static Sweep.Setup Ramp(string rig, float degrees, string folder)
    {
        // Seven metres of ground rising along +X, four wide, through the origin: a floor turned about Z.
        Level ramp = new LevelBuilder("ramp").AddFloor(-3.5f, -2f, 3.5f, 2f, 0f, n: 8, toWorld: Matrix4x4.CreateRotationZ(degrees * MathF.PI / 180f)).Build();
        (CharacterModel model, ReducedCharacter reduced) = ForeignCharacters.Named(rig).Load(folder);
        Assert.That(reduced.Walking.MaxSlopeAlongDegrees, Is.GreaterThanOrEqualTo(degrees), $"the {rig}'s derived walking limit");
        return Sweep.Prepare("ramp", ramp, model, reduced);
    }

    [TestCaseSource(nameof(UpAndDown))]
    [TestCase("rat", 5f, -1f, 1f)]
    [TestCase("rat", 10f, 1f, -1f)]
    public void ARigWithFeetAheadAndBehindWalksUpAndDownARamp(string rig, float degrees, float x0, float x1)
    {
        float rise = MathF.Tan(degrees * MathF.PI / 180f); // the ground's height per metre along X
        string folder = RigFolders.For($"{rig}-ramp-{degrees}-{x0}");
        try
        {
            (AnimatedPlan plan, AuditReport report, AnimatorEye? _) = Sweep.Plan(Ramp(rig, degrees, folder), new Vector3(x0, x0 * rise, 0f), new Vector3(x1, x1 * rise, 0f));
            Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
            Assert.That(plan.Result.Moves.OfType<Jump>(), Is.Empty, $"no hop up or down a plain ramp: {plan.Result.Reason}");
            Assert.That(plan.Result.Moves.OfType<Walk>(), Is.Not.Empty);
            Assert.That(report.FullyRight, Is.True, report.ToString());
            SweepTests.AssertEveryCriterion(report.Look!, $"the {rig} from x = {x0} to {x1} on {degrees}°", name => name == "upright" && NotYetUpright.Contains((rig, degrees, x0)), nameof(NotYetUpright));
        }
        finally
        {
            RigFolders.Remove(folder);
        }
    }
}
