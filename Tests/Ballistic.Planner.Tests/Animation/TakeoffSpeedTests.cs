using Ballistic.Planner.Animation;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Animation;

/// <summary>
/// The body goes into a flight as fast as it rises on the ground, and comes out of one as fast as it came down: the
/// crouch's drive up ends rising at the takeoff's own vertical speed, the landing's sink starts at the landing's, as far
/// as the dip's depth and duration allow (<see cref="StanceDip.MostDipRate"/> times the dip's mean rate). Before, both
/// ran at twice the mean rate whatever the jump: a push rising at 3.3 m/s into a flight leaving at 7.2 m/s, the legs,
/// held on the ground into the flight, snapping straight in the frame of takeoff.
/// </summary>
public sealed class TakeoffSpeedTests
{
    /// <summary>Seconds over which the root's speed is read on either side of a takeoff or landing.</summary>
    private const float Read = 0.002f;

    [Test]
    public void ACrouchEndsRisingAsFastAsItsTakeoffAndALandingSinksAsFastAsItCameDown()
    {
        // The desert crossing the eye's tests read (shared): walks, and jumps taken off after a walk or a landing.
        (_, _, AnimatedPlan plan) = BundledPlans.Plan("desert", "skeleton", 7.7f, 5.8f, -7.5f, -8.5f);
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        JumpAnimation animation = plan.Animation!;
        Assert.That(animation.Arcs, Has.Count.GreaterThan(2));

        int matched = 0;
        int fast = 0;
        Assert.Multiple(() =>
        {
            for (int j = 0; j < animation.Arcs.Count; j++)
            {
                float takeoff = animation.JumpStart(j);
                float landing = takeoff + animation.Arcs[j].FlightTime;
                float up = animation.Arcs[j].TakeoffVelocity.Y;
                float down = -animation.Arcs[j].LandingVelocity.Y;

                // The drive up: from the crouch's lowest point (the last time the root is there) to the takeoff.
                (float bottom, float low) = Lowest(animation, MathF.Max(0f, takeoff - 0.6f), takeoff, last: true);
                float depth = Height(animation, takeoff) - low;
                float rising = (Height(animation, takeoff) - Height(animation, takeoff - Read)) / Read;
                float expected = Expected(up, depth, takeoff - bottom);
                Assert.That(rising, Is.EqualTo(expected).Within(Tolerance(expected, depth, takeoff - bottom)), $"jump {j + 1}: rising {rising:0.00} m/s into a takeoff at {up:0.00} m/s (a {depth:0.000} m drive over {takeoff - bottom:0.000} s)");
                matched++;
                fast += up > 2.2f * depth / (takeoff - bottom) ? 1 : 0;

                // The sink: from the landing to the lowest point of the absorption after it.
                float end = j + 1 < animation.Arcs.Count ? animation.JumpStart(j + 1) : animation.Duration;
                (float deepest, float under) = Lowest(animation, landing, MathF.Min(end, landing + 0.6f), last: false);
                float sunk = Height(animation, landing) - under;
                float sinking = (Height(animation, landing) - Height(animation, landing + Read)) / Read;
                float sinks = Expected(down, sunk, deepest - landing);
                Assert.That(sinking, Is.EqualTo(sinks).Within(Tolerance(sinks, sunk, deepest - landing)), $"landing {j + 1}: sinking {sinking:0.00} m/s after coming down at {down:0.00} m/s (a {sunk:0.000} m sink over {deepest - landing:0.000} s)");
            }
        });

        // Jumps leaving faster than twice the drive's mean rate are the ones the old push did not match.
        Assert.That(fast, Is.GreaterThan(0), $"of {matched} takeoffs, none leaves faster than the old push rose");
    }

    /// <summary>The speed (m/s) a dip of <paramref name="depth"/> metres over <paramref name="duration"/> seconds ends (or starts) at for a flight along the vertical at <paramref name="speed"/>: that speed, within 0 and <see cref="StanceDip.MostDipRate"/> times the mean rate.</summary>
    private static float Expected(float speed, float depth, float duration) => Math.Clamp(speed, 0f, StanceDip.MostDipRate * depth / duration);

    /// <summary>
    /// How far (m/s) a speed read over the last (first) frames of a dip may be from <paramref name="expected"/>: a tenth
    /// of it, plus a fifth of the dip's mean rate for reading a curve over a frame's secant (the old push was off by the
    /// mean rate or more wherever it did not match).
    /// </summary>
    private static float Tolerance(float expected, float depth, float duration) => (0.1f * expected) + (0.2f * depth / duration);

    private static float Height(JumpAnimation animation, float time) => animation.RootAt(time).Position.Y;

    /// <summary>The time and height of the root's lowest point between <paramref name="from"/> and <paramref name="to"/> (read every millisecond; the last such time or the first).</summary>
    private static (float Time, float Height) Lowest(JumpAnimation animation, float from, float to, bool last)
    {
        (float Time, float Height) lowest = (from, float.PositiveInfinity);
        for (float t = from; t <= to; t += 0.001f)
        {
            float y = Height(animation, t);
            if (y < lowest.Height - 1e-5f || (last && y <= lowest.Height + 1e-5f))
            {
                lowest = (t, MathF.Min(y, lowest.Height));
            }
        }

        return lowest;
    }
}
