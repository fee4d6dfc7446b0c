using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.EndToEnd;

/// <summary>
/// A small quadruped loaded from a user's files (issue 24's rat: 4.5 cm legs, a tail lying on (1–2 mm into) the ground in its rest
/// pose, a limbs-only spec with no speeds, poses or tail axes) walks where its legs can: across two metres of floor it
/// walks, at the speed and stride its legs give, its feet never outrunning their reach, and jumps only as far as a body
/// its size does. Before, it hopped 1.3 m at up to 8 m/s, and its walks were set aside ("l_hind cannot swing to its
/// next foothold within reach and clear of the level"): the gait's least swing of 0.16 s carried its feet three leg
/// lengths per step.
/// </summary>
[Category("EndToEnd")]
public sealed class SmallQuadrupedTests
{
    private static readonly Lazy<(CharacterModel Model, ReducedCharacter Reduced)> Rat = new(() => ForeignCharacters.Rat().Load());

    private static readonly Lazy<Sweep.Setup> Floor = new(() =>
        Sweep.Prepare("floor", new LevelBuilder("floor").AddFloor(-2f, -2f, 2f, 2f, 0f).Build(), Rat.Value.Model, Rat.Value.Reduced));

    [Test]
    public void ASmallRigsDefaultJumpSpeedsScaleWithItsSize()
    {
        ReducedCharacter rat = Rat.Value.Reduced;
        float scale = MathF.Sqrt(rat.StanceLift.Max / 0.96f);
        Assert.That(rat.StanceLift.Max, Is.InRange(0.04f, 0.05f), "the rat stands about 4.5 cm tall");
        Assert.That(rat.TakeoffSpeedMax, Is.EqualTo(8f * scale).Within(1e-4f));
        Assert.That(rat.LandingSpeedMax, Is.EqualTo(12f * scale).Within(1e-4f));
        Assert.That(rat.TakeoffSpeedMax, Is.InRange(1.6f, 1.9f), "the README's figure: 1.74 m/s");
        Assert.That(rat.LandingSpeedMax, Is.InRange(2.5f, 2.7f), "the README's figure: 2.61 m/s");

        // A full-size rig keeps 8 and 12; speeds a spec gives are kept whatever the size.
        Assert.That(CharacterSpecFile.JumpSpeedScale(1.2f), Is.EqualTo(1f));
        Assert.That(CharacterSpecFile.JumpSpeedScale(0.96f), Is.EqualTo(1f));
        Assert.That(CharacterSpecFile.JumpSpeedScale(0.24f), Is.EqualTo(0.5f).Within(1e-6f));
        ReducedCharacter human = ForeignCharacters.Human(zUpScene: false).Load().Reduced;
        Assert.That((human.TakeoffSpeedMax, human.LandingSpeedMax), Is.EqualTo((8f, 12f)));
        ReducedCharacter dog = ForeignCharacters.Dog().Load().Reduced;
        Assert.That(dog.StanceLift.Max, Is.LessThan(0.96f), "the dog is smaller than the skeleton");
        Assert.That((dog.TakeoffSpeedMax, dog.LandingSpeedMax), Is.EqualTo((8f, 12f)), "its spec gives 8 and 12");
    }

    /// <summary>
    /// Two metres of floor, either way across: one walk, no jump, fully right by the audit and every criterion of the
    /// animator's eye read from the exported GLB; its feet step about 0.9 of its leg (the README's figure) and leave
    /// their contacts for at least 0.1 s × √(leg ÷ 1 m) (about 0.02 s), not the three legs' lengths a 0.16 s swing would need.
    /// Its tail, lying on the ground at rest, never enters the level more than 5 mm; no foot's contact phases overlap
    /// (its 1.2 cm re-steps as it turns came within 8 mm of both points at once).
    /// </summary>
    [TestCase(-1f, 0f, 1f, 0f)]
    [TestCase(-0.5f, 0.3f, 0.6f, -0.4f)]
    public void ARatWalksAcrossTwoMetresOfFloor(float x0, float z0, float x1, float z1)
    {
        Sweep.Setup setup = Floor.Value;
        Vector3 from = new(x0, 0f, z0);
        Vector3 to = new(x1, 0f, z1);
        (AnimatedPlan plan, AuditReport report, AnimatorEye? seen) = Sweep.Plan(setup, from, to);
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        Assert.That(plan.Rejected, Is.Empty, "no walk set aside");
        Assert.That(plan.Result.Moves.OfType<Jump>(), Is.Empty, "no jump across flat floor");
        Assert.That(plan.Result.Moves.OfType<Walk>().Count(), Is.EqualTo(1));

        JumpAnimation animation = plan.Animation!;
        Assert.That(report.FullyRight, Is.True, report.ToString());
        AnimatorEye eye = seen!;
        AnimatorEye.Look look = report.Look!;
        foreach ((string name, AnimatorEye.Criterion criterion) in look.All)
        {
            Assert.That(criterion.Passes, Is.True, $"{name}: {criterion}");
        }

        Assert.That(look.Upright.Seen, Is.Not.Empty, "the walk cruises on level ground");
        Assert.That(look.Bob.Seen, Is.Not.Empty, "its hips rise and fall with its steps");
        Assert.That(look.Inside.Worst!.Value.Score, Is.GreaterThanOrEqualTo(4f), $"no vertex, the tail's included, 5 mm inside the level: {look.Inside}");

        // Judged at its own size, no joint snaps: a frame's turn counts from 15° × √(0.9 m ÷ its leg), about 69°
        // (at 15°, its paws lifting read as dozens of snapping frames).
        Assert.That(eye.SnapFloor, Is.EqualTo(AnimatorEye.LeastSnap * MathF.Sqrt(AnimatorEye.HumanLeg / eye.Leg)).Within(1e-3f));
        Assert.That(look.Snaps.Seen.Count(s => s.Score > 1f), Is.Zero, $"no joint snaps at the rat's size: {look.Snaps}");

        // Each foot's steps, from one contact to the next while the walk cruises (not the re-steps of its turns in place).
        var steps = new List<float>();
        var air = new List<float>();
        Walk walk = plan.Result.Moves.OfType<Walk>().Single();
        float start = animation.MoveStart(0);
        foreach (IGrouping<int, ContactPhase> foot in animation.ContactPhases.GroupBy(p => p.Limb))
        {
            ContactPhase[] ordered = [.. foot.OrderBy(p => p.From)];
            for (int i = 1; i < ordered.Length; i++)
            {
                Assert.That(ordered[i].From, Is.GreaterThanOrEqualTo(ordered[i - 1].To - 1e-5f), $"limb {foot.Key}'s contact phases overlap (a short re-step near both points at once)");
                if (Vector3.Distance(ordered[i].Position, ordered[i - 1].Position) > 0.02f)
                {
                    air.Add(ordered[i].From - ordered[i - 1].To);
                }
                // Cruising: sped up from rest (where the gait slows the walk for shorter steps, at its pace there).
                if (walk.CruiseAt(ordered[i].From - start) >= 0.99f && walk.CruiseAt(ordered[i - 1].To - start) >= 0.99f)
                {
                    steps.Add(Vector3.Distance(ordered[i].Position, ordered[i - 1].Position));
                }
            }
        }

        float leg = eye.Leg;
        Assert.That(walk.Speed, Is.EqualTo(MathF.Sqrt(0.25f * 9.81f * leg)).Within(0.1f * walk.Speed), "a walk at a Froude number of 0.25 of its leg");
        Assert.That(steps, Is.Not.Empty);
        float median = steps.Order().ElementAt(steps.Count / 2) / leg;
        Assert.That(median, Is.InRange(0.7f, 1.1f), "steps of about 0.9 leg lengths (3.8 cm) while cruising, the README's figure");
        Assert.That(air.Min(), Is.GreaterThanOrEqualTo(0.095f * MathF.Sqrt(leg)), "no foot faster than a full-size foot (0.1 s) scaled to the leg");
        Assert.That(air.Order().ElementAt(air.Count / 2), Is.InRange(0.015f, 0.03f), "each foot off its contact about 0.02 s per step (the README's figure)");
    }

    /// <summary>
    /// The rat's jumps are a small body's: over an 8 cm rail across the floor, none across farther than its takeoff
    /// speed carries it on the level (v²/g, 0.31 m; at 8 m/s it was 6.5 m).
    /// </summary>
    [Test]
    public void ARatsJumpsAreItsSize()
    {
        Sweep.Setup setup = Sweep.Prepare("crate", new LevelBuilder("crate")
            .AddFloor(-1f, -1f, 1f, 1f, 0f)
            .AddBox(new Vector3(-0.1f, 0f, -1f), new Vector3(0.1f, 0.08f, 1f))
            .Build(), Rat.Value.Model, Rat.Value.Reduced);
        (AnimatedPlan plan, AuditReport report, _) = Sweep.Plan(setup, new Vector3(-0.5f, 0f, 0f), new Vector3(0.5f, 0f, 0f));
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        float reach = setup.Scene.Character.TakeoffSpeedMax * setup.Scene.Character.TakeoffSpeedMax / 9.81f;
        Assert.That(reach, Is.LessThan(0.35f));
        Assert.That(plan.Result.Moves.OfType<Jump>(), Is.Not.Empty, "the 8 cm rail across the floor is above its 1.1 cm step: it hops over");
        foreach (Jump jump in plan.Result.Moves.OfType<Jump>())
        {
            Vector3 d = jump.Arc.End - jump.Arc.Start;
            Assert.That(new Vector2(d.X, d.Z).Length(), Is.LessThanOrEqualTo(reach + 0.1f), $"jump {jump.From.Id}→{jump.To.Id}");
        }

        Assert.That(report.FullyRight, Is.True, report.ToString());
    }
}
