using Ballistic.Authoring.Animation;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Animation;

/// <summary>
/// A limb that keeps its takeoff contact into the flight, or takes its landing contact before the body lands, turns no
/// faster than a landing folds a knee (<see cref="JumpAnimator.MostHeldTurnRate"/>). The body moves at the flight's
/// speed by then: a frog's foreleg that touched down 12 ms before its trunk folded its elbow 68° in those 12 ms, in the
/// frame of landing, and such snaps were most of the sweep's (the field's frogs had 112, 68 and 32 snapping frames).
/// </summary>
public sealed class TouchdownTests
{
    [Test]
    public void AFrogsLimbsTouchDownWithoutSnapping()
    {
        // A crossing of the pond the sweep also plans (its plan there snapped in 10 frames at takeoffs and landings).
        // Held as long as the IK held the point, this plan's limbs kept contacts in the air over 376 frames, turning
        // up to 8,870°/s.
        (PlanningScene scene, _, AnimatedPlan plan) = BundledPlans.Plan("pond", "frog", 2.9f, -3.2f, 3.1f, 0.7f);
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        JumpAnimation animation = plan.Animation!;
        CharacterModel model = animation.Model;
        Assert.That(animation.Arcs, Has.Count.GreaterThan(0));

        int heldFrames = 0;
        var fastest = (Rate: 0f, Seen: "none");
        for (int j = 0; j < animation.Arcs.Count; j++)
        {
            float takeoff = animation.JumpStart(j);
            float landing = takeoff + animation.Arcs[j].FlightTime;
            foreach (ContactPhase phase in animation.ContactPhases)
            {
                // The part of the phase in the air: after the takeoff or before the landing.
                float from = MathF.Max(phase.From, takeoff);
                float to = MathF.Min(phase.To, landing);
                if (to - from < 1e-4f)
                {
                    continue;
                }

                AnimationFrame[] frames = [.. animation.Frames.Where(f => f.Time >= from - 1e-5f && f.Time <= to + 1e-5f)];
                for (int k = 1; k < frames.Length; k++)
                {
                    float dt = frames[k].Time - frames[k - 1].Time;
                    foreach (int d in model.Limbs[phase.Limb].ChainDofSpan)
                    {
                        float rate = MathF.Abs(frames[k].Angles[d] - frames[k - 1].Angles[d]) / dt;
                        if (rate > fastest.Rate)
                        {
                            fastest = (rate, $"{model.Limbs[phase.Limb].Name} at {frames[k].Time:0.000} s (jump {j + 1}: {takeoff:0.000}–{landing:0.000} s)");
                        }
                    }

                    heldFrames++;
                }
            }
        }

        AnimatorEye.Look look = AnimatorEye.Read(AnimatedGlbWriter.ToBytes(animation), model).Measure(animation, scene);
        Assert.Multiple(() =>
        {
            // Where a limb still holds a contact in the air (here none: each lets go at takeoff and takes hold at
            // landing, the body already too fast for it), it turns within the bound (HopStepTests reads low hops that do).
            TestContext.Out.WriteLine($"{heldFrames} held frames in flight; fastest {fastest.Rate * 180f / MathF.PI:0}°/s: {fastest.Seen}");
            Assert.That(fastest.Rate, Is.LessThanOrEqualTo(JumpAnimator.MostHeldTurnRate * 1.001f), $"fastest held turn {fastest.Rate * 180f / MathF.PI:0}°/s: {fastest.Seen}");

            // As an importer plays the GLB at 60 frames a second: no joint snaps.
            Assert.That(look.Snaps.Seen.Count(s => s.Score > 1f), Is.Zero, look.Snaps.ToString());
        });
    }
}
