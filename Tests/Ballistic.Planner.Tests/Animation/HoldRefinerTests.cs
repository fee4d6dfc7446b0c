using Ballistic.Planner.Animation;

namespace Ballistic.Planner.Tests.Animation;

/// <summary>
/// The hold refiner solves and checks each frame's holds once: a frame ends one interval and starts the next, and a
/// halved interval's halves share its ends. What it adds is the same to the bit as checking every interval's ends anew.
/// </summary>
public sealed class HoldRefinerTests
{
    /// <summary>
    /// A walk across the gap course's first platform, its frames thinned to every third (so that held feet sag between
    /// them and the refiner adds frames, halving intervals), refined remembering each frame's holds and not: the same
    /// frames, angles and failures, with at most 55 % of the checks (each frame checked once instead of twice, the
    /// halvings' shared ends too).
    /// </summary>
    [Test]
    public void RememberingEachFramesHoldsChangesNoRefinement()
    {
        WalkWorld world = WalkWorld.Create(WalkWorld.GapCourse(), "skeleton");
        JumpAnimation walked = world.AcrossFirstPlatform();
        AnimationFrame[] thinned = [.. walked.Frames.Where((_, i) => i % 3 == 0 || i == walked.Frames.Count - 1)];
        var clip = new JumpAnimation(walked.Model, walked.Moves, walked.Stances, thinned, walked.ContactPhases, [], 0, 0, walked.LeadIn, walked.LeadOut);
        var collision = new BodyCollision(world.Scene.Bvh, world.Model, world.Scene.Level.Triangles);
        var remembering = new HoldRefiner(world.Model, collision);
        var checking = new HoldRefiner(world.Model, collision) { RemembersFrames = false };

        (List<AnimationFrame> frames, List<(int Limb, float Time)> failures) = remembering.Refine(clip);
        (List<AnimationFrame> expected, List<(int Limb, float Time)> expectedFailures) = checking.Refine(clip);

        Assert.Multiple(() =>
        {
            Assert.That(frames.Count, Is.GreaterThan(thinned.Length), "frames added where held feet sag between the thinned ones");
            Assert.That(frames.Select(f => (f.Time, f.Root)), Is.EqualTo(expected.Select(f => (f.Time, f.Root))));
            Assert.That(frames.SelectMany(f => f.Angles), Is.EqualTo(expected.SelectMany(f => f.Angles)));
            Assert.That(failures, Is.EqualTo(expectedFailures));
            Assert.That(remembering.HoldChecks, Is.LessThanOrEqualTo(0.55 * checking.HoldChecks), $"{remembering.HoldChecks} checks remembering, {checking.HoldChecks} not");
        });
    }
}
