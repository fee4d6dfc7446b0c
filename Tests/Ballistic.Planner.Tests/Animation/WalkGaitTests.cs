using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Tests.Animation;

/// <summary>The gait of walks built by hand on flat ground: root on the walk, feet holding, alternating, clean.</summary>
public sealed class WalkGaitTests
{
    [TestCase("skeleton", 1, 3)]
    [TestCase("ant", 3, 3)]
    public void AWalkOnFlatGroundAlternatesItsFeetAndHoldsThem(string character, int leastHolding, int leastPhases)
    {
        WalkWorld world = WalkWorld.Create(WalkWorld.GapCourse(), character);
        RoadmapNode from = world.Stance(new Vector3(-7.3f, 0f, 0.5f), 0, Vector3.UnitX);
        RoadmapNode to = world.Stance(new Vector3(-3.8f, 0f, -0.3f), 1, Vector3.UnitX);
        Walk walk = world.Walk(from, to);
        JumpAnimation animation = world.Animator.Animate([walk]);
        TestContext.Out.WriteLine($"{character}: {walk.Length:0.00} m in {walk.Duration:0.00} s, {animation.Frames.Count} frames, {animation.ContactPhases.Count} phases");
        foreach (JumpProblem p in animation.Problems)
        {
            TestContext.Out.WriteLine(p.Reason);
        }

        (int least, int[] phases) = WalkInvariants.Check(world, animation);
        (float speed, float time, string dof) = WalkInvariants.FastestAngle(animation);
        TestContext.Out.WriteLine($"least holding {least}, phases per foot {string.Join(", ", phases)}, fastest angle {speed:0.0} rad/s at {time:0.000} s ({dof})");
        Assert.That(least, Is.GreaterThanOrEqualTo(leastHolding));
        Assert.That(phases, Has.All.GreaterThanOrEqualTo(leastPhases));
    }

    [Test]
    public void AVeryShortWalkStepsWithoutSliding()
    {
        // Two stances 6 cm apart: the walk lasts 0.28 s; no foot may move to a new contact more than 2 cm away within a
        // tenth of a second (the audit's slide), and the gait says so when it would have to.
        WalkWorld world = WalkWorld.Create(WalkWorld.GapCourse(), "skeleton");
        RoadmapNode from = world.Stance(new Vector3(-6f, 0f, 0f), 0, Vector3.UnitX);
        RoadmapNode to = world.Stance(new Vector3(-5.94f, 0f, 0f), 1, Vector3.UnitX);
        Walk walk = world.Walk(from, to);
        JumpAnimation animation = world.Animator.Animate([walk]);
        bool slide = animation.ContactPhases.GroupBy(p => p.Limb).Any(g =>
        {
            ContactPhase[] ordered = [.. g.OrderBy(p => p.From)];
            return ordered.Zip(ordered.Skip(1)).Any(pair => pair.Second.From - pair.First.To < JumpAnimator.MinAirTime && Vector3.Distance(pair.First.Position, pair.Second.Position) > 0.02f);
        });
        TestContext.Out.WriteLine($"{walk.Length:0.000} m in {walk.Duration:0.000} s; {string.Join("; ", animation.Problems.Select(p => p.Reason))}");
        Assert.That(walk.Duration, Is.LessThan(0.4f));
        Assert.That(slide, Is.False, "a foot slides to a new contact");
        Assert.That(animation.Problems.Select(p => p.Reason), Is.Empty);
        Assert.That(animation.ContactPhases.Select(p => p.Limb).Distinct().Count(), Is.EqualTo(2), "both feet stand");
    }
}
