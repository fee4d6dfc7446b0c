using Ballistic.Authoring.Characters;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Runtime;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Query;

/// <summary>Walking never makes a request fail that jumps alone would solve: walks that fail to animate twice give way to jumps only.</summary>
public sealed class WalkFallbackTests
{
    private static readonly Lazy<(PlanningScene Scene, Roadmap Roadmap, JumpAnimator Real)> Course = new(() =>
    {
        var scene = PlanningScene.Create(GapCourse.Build(), CharacterPresets.Skeleton());
        var real = new JumpAnimator(scene, CharacterPresets.Model("skeleton"));
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 2, MaxNodes = 150, Threads = 2, Locomotion = Locomotion.WalkAndJump, CanStand = real.CanStand }).Roadmap;
        return (scene, roadmap, real);
    });

    [Test]
    public void AfterTwoRoundsOfFailedWalksTheRequestSearchesJumpsOnlyAndSucceeds()
    {
        (PlanningScene scene, Roadmap roadmap, JumpAnimator real) = Course.Value;
        var animator = new RefusingAnimator(new SimpleMoveAnimator(real), m => m is Walk, "cannot walk here");
        // Walks as searched: a refused walk turning into a faced jump is the turn's failure (the jump given back), not the walk's.
        AnimatedPlan plan = new AnimatedPlanner(scene, animator).Plan(roadmap, GapCourse.From, GapCourse.To, new QuerySettings { Locomotion = Locomotion.WalkAndJump, TightenJumps = false, FaceJumps = false });
        Assert.Multiple(() =>
        {
            Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
            Assert.That(plan.Result.Walks, Is.Empty, "jumps only in the end");
            Assert.That(plan.Result.Jumps, Is.Not.Empty);
            Assert.That(animator.PathsRefused, Is.EqualTo(JumpRepair.WalkRounds), "two rounds with walks, then none");
            Assert.That(plan.Rounds, Is.EqualTo(JumpRepair.WalkRounds + 1));
            Assert.That(plan.Rejected, Is.Not.Empty);
            Assert.That(plan.Rejected.Select(r => r.Reason), Has.All.Contain("cannot walk here"));
        });
    }

    [Test]
    public void TheRepairRecordSwitchesToJumpsOnlyAfterTwoRoundsWithAFailedWalk()
    {
        (PlanningScene scene, Roadmap roadmap, JumpAnimator real) = Course.Value;
        // Walks as searched: neither cut from jumps nor turning into them (their failures are the cut's, not the walk's).
        PlanResult path = new PathQuery(scene, roadmap).Plan(GapCourse.From, GapCourse.To, new QuerySettings { Locomotion = Locomotion.WalkAndJump, TightenJumps = false, FaceJumps = false });
        Assume.That(path.Walks, Is.Not.Empty);
        var repair = new JumpRepair();
        var walking = new QuerySettings { Locomotion = Locomotion.WalkAndJump, TightenJumps = false, FaceJumps = false };
        JumpAnimation refused = new RefusingAnimator(new SimpleMoveAnimator(real), m => m is Walk, "cannot walk here").Animate(path.Moves);
        JumpAnimation clean = new SimpleMoveAnimator(real).Animate(path.Moves);

        Assert.That(repair.Adjust(walking).Locomotion, Is.EqualTo(Locomotion.WalkAndJump));
        repair.Reject(path.Moves, clean);
        Assert.That(repair.WalkFailures, Is.Zero, "a clean animation is no failure");
        repair.Reject(path.Moves, refused);
        Assert.That(repair.WalksAllowed, Is.True, "one round");
        Assert.That(repair.Adjust(walking), Is.SameAs(walking));
        repair.Reject(path.Moves, refused);
        Assert.That(repair.WalksAllowed, Is.False, "two rounds");
        Assert.That(repair.Adjust(walking).Locomotion, Is.EqualTo(Locomotion.Jump));
        Assert.That(repair.Adjust(walking) with { Locomotion = Locomotion.WalkAndJump }, Is.EqualTo(walking), "nothing else changes");
        var jumpsOnly = new QuerySettings { Locomotion = Locomotion.Jump };
        Assert.That(repair.Adjust(jumpsOnly), Is.SameAs(jumpsOnly));
    }
}
