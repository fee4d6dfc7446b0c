using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Authoring.Levels;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Runtime;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Query;

/// <summary>Walk where you can, jump where you must: jumps cut down to the ground they must cross, and given back whole when the body cannot perform the cut.</summary>
public sealed class JumpTighteningTests
{
    private static readonly Lazy<(PlanningScene Scene, Vector3 From, Vector3 To, Roadmap Roadmap, JumpAnimator Real)> Desert = new(() =>
    {
        var scene = PlanningScene.Create(LevelGenerator.BuildLevel("desert"), CharacterPresets.Skeleton());
        Vector3 from = Ground(scene, -9.5f, -7.5f);
        Vector3 to = Ground(scene, 9.5f, 7.5f);
        var real = new JumpAnimator(scene, CharacterPresets.Model("skeleton"));
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 1, MaxNodes = 300, Threads = 2, Start = from, Goal = to, Locomotion = Locomotion.WalkAndJump, CanStand = real.CanStand }).Roadmap;
        return (scene, from, to, roadmap, real);
    });

    private static Vector3 Ground(PlanningScene scene, float x, float z) =>
        scene.Bvh.Raycast(new Vector3(x, 100f, z), -Vector3.UnitY, 200f, out RayHit hit) ? hit.Point : throw new InvalidOperationException("no ground");

    private static float Across(Vector3 a, Vector3 b) => new Vector2(b.X - a.X, b.Z - a.Z).Length();

    private static float Flown(PlanResult plan) => plan.Jumps.Sum(j => Across(j.From.ContactCentre, j.To.ContactCentre));

    private static float Walked(PlanResult plan) => plan.Walks.Sum(w => w.Length);

    [Test]
    public void OnTheDesertJumpsAreCutDownToTheDunesAndTheRestIsWalked()
    {
        (PlanningScene scene, Vector3 from, Vector3 to, Roadmap roadmap, JumpAnimator real) = Desert.Value;
        var settings = new QuerySettings { CanStand = real.CanStand, FaceJumps = false }; // cutting alone: facing adds moves of its own
        PlanResult whole = new PathQuery(scene, roadmap).Plan(from, to, settings with { TightenJumps = false });
        PlanResult cut = new PathQuery(scene, roadmap).Plan(from, to, settings);
        Assert.That(whole.Status, Is.EqualTo(PlannerStatus.Exact), whole.Reason);
        Assert.That(cut.Status, Is.EqualTo(PlannerStatus.Exact), cut.Reason);
        Dictionary<(int, int), Jump> searched = whole.Jumps.ToDictionary(j => (j.From.Id, j.To.Id));
        int n = roadmap.Nodes.Count;
        Assert.Multiple(() =>
        {
            Assert.That(cut.Moves.Where(m => m.CutFrom.Count > 0), Is.Not.Empty, "some jump is cut");
            Assert.That(Walked(cut), Is.GreaterThan(Walked(whole) + 2f), "metres walked");
            Assert.That(Flown(cut), Is.LessThan(Flown(whole) - 2f), "metres in the air");
            Assert.That(cut.Jumps, Has.Count.LessThanOrEqualTo(whole.Jumps.Count), "no jump added");

            // The path is continuous from the start to the goal.
            Assert.That(cut.Moves[0].From, Is.EqualTo(cut.Start));
            Assert.That(cut.Moves[^1].To, Is.EqualTo(cut.Goal));
            for (int i = 1; i < cut.Moves.Count; i++)
            {
                Assert.That(cut.Moves[i].From, Is.EqualTo(cut.Moves[i - 1].To), $"move {i} starts where move {i - 1} ends");
            }

            // Each cut jump is shorter than the searched jump it stands in for, and moves forward along it.
            foreach (Jump jump in cut.Jumps.Where(j => j.CutFrom.Count > 0))
            {
                Assert.That(jump.CutFrom, Has.Count.EqualTo(1));
                Assert.That(searched.TryGetValue(jump.CutFrom[0], out Jump? original), Is.True, "cut from a jump of the searched path");
                Vector3 a = original!.From.ContactCentre;
                Vector3 b = original.To.ContactCentre;
                Assert.That(Across(jump.From.ContactCentre, jump.To.ContactCentre), Is.LessThan(Across(a, b) - 0.5f));
                var line = Vector2.Normalize(new Vector2(b.X - a.X, b.Z - a.Z));
                Vector3 hop = jump.Arc.End - jump.Arc.Start;
                Assert.That(Vector2.Dot(new Vector2(hop.X, hop.Z), line), Is.GreaterThan(0f), "the cut jump goes the original's way");
            }

            // New stances have fresh ids beyond the start's and goal's.
            int[] added = [.. cut.Moves.SelectMany(m => new[] { m.From.Id, m.To.Id }).Where(id => id >= n + 2).Distinct()];
            Assert.That(added, Is.Not.Empty);
            Assert.That(cut.Moves.SelectMany(m => new[] { m.From, m.To }).Where(s => s.Id >= n + 2).DistinctBy(s => s.Id).Select(s => s.Pose).Distinct().Count(), Is.EqualTo(added.Length), "one pose per id");
        });

        // The independent checker: arcs land where reported, velocities in their cones and under the limits, walks on the ground.
        AuditReport audit = PlanAudit.Check("desert cut", scene, from, to, cut, null);
        Assert.That(audit.Violations, Is.Empty, string.Join("; ", audit.Violations));

        // Deterministic.
        PlanResult again = new PathQuery(scene, roadmap).Plan(from, to, settings);
        Assert.That(again.Moves.Select(m => (m.From.Id, m.To.Id, m.From.Pose, m.To.Pose)), Is.EqualTo(cut.Moves.Select(m => (m.From.Id, m.To.Id, m.From.Pose, m.To.Pose))));
    }

    [Test]
    public void AJumpKeptWholeIsNotCutAndNeitherIsAnyWithCuttingOff()
    {
        (PlanningScene scene, Vector3 from, Vector3 to, Roadmap roadmap, JumpAnimator real) = Desert.Value;
        var settings = new QuerySettings { CanStand = real.CanStand, FaceJumps = false }; // cutting alone: facing adds moves of its own
        PlanResult cut = new PathQuery(scene, roadmap).Plan(from, to, settings);
        PlanResult whole = new PathQuery(scene, roadmap).Plan(from, to, settings with { TightenJumps = false });
        HashSet<(int From, int To)> all = [.. cut.Moves.SelectMany(m => m.CutFrom)];
        Assume.That(all, Is.Not.Empty);
        (int, int) first = all.First();
        PlanResult oneWhole = new PathQuery(scene, roadmap).Plan(from, to, settings with { UncutJumps = new HashSet<(int, int)> { first } });
        PlanResult allWhole = new PathQuery(scene, roadmap).Plan(from, to, settings with { UncutJumps = all });
        Assert.Multiple(() =>
        {
            Assert.That(whole.Moves.SelectMany(m => m.CutFrom), Is.Empty);
            Assert.That(oneWhole.Moves.SelectMany(m => m.CutFrom), Does.Not.Contain(first));
            Assert.That(oneWhole.Jumps.Select(j => (j.From.Id, j.To.Id)), Does.Contain(first), "the jump kept whole is flown as searched");
            Assert.That(allWhole.Moves.Select(m => (m.GetType(), m.From.Id, m.To.Id)), Is.EqualTo(whole.Moves.Select(m => (m.GetType(), m.From.Id, m.To.Id))));
        });
    }

    [Test]
    public void ACutTheBodyCannotPerformGivesTheJumpBackWholeWithoutCostingWalksOrRounds()
    {
        (PlanningScene scene, Vector3 from, Vector3 to, Roadmap roadmap, JumpAnimator real) = Desert.Value;
        var animator = new RefusingAnimator(new SimpleMoveAnimator(real), m => m.CutFrom.Count > 0, "cannot cut here");
        AnimatedPlan plan = new AnimatedPlanner(scene, animator).Plan(roadmap, from, to, new QuerySettings(), rounds: 1);
        Assert.Multiple(() =>
        {
            Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
            Assert.That(plan.Result.Moves.SelectMany(m => m.CutFrom), Is.Empty, "every cut given back");
            Assert.That(plan.Result.Walks, Is.Not.Empty, "walking is still allowed: a refused cut is no failed walk");
            Assert.That(animator.PathsRefused, Is.InRange(1, JumpRepair.CutRounds));
            Assert.That(plan.Rounds, Is.EqualTo(animator.PathsRefused + 1), "one search besides the cut rounds, as allowed");
            Assert.That(plan.Rejected, Is.Not.Empty);
            Assert.That(plan.Rejected.Select(r => r.Reason), Has.All.Contain("cannot cut here"));
        });
    }

    [Test]
    public void TheRepairRecordKeepsCutJumpsWholeAndStopsCuttingAfterItsRounds()
    {
        (PlanningScene scene, Vector3 from, Vector3 to, Roadmap roadmap, JumpAnimator real) = Desert.Value;
        PlanResult path = new PathQuery(scene, roadmap).Plan(from, to, new QuerySettings { CanStand = real.CanStand });
        Assume.That(path.Moves.Where(m => m.CutFrom.Count > 0), Is.Not.Empty);
        var repair = new JumpRepair();
        var settings = new QuerySettings();
        JumpAnimation refused = new RefusingAnimator(new SimpleMoveAnimator(real), m => m.CutFrom.Count > 0, "cannot cut here").Animate(path.Moves);
        repair.Reject(path.Moves, refused);
        Assert.Multiple(() =>
        {
            Assert.That(repair.WalkFailures, Is.Zero, "a refused cut walk is not a failed walk");
            Assert.That(repair.CutFailures, Is.EqualTo(1));
            Assert.That(repair.Excluded, Is.Empty, "nothing set aside: the jumps are kept whole instead");
            Assert.That(repair.Uncut, Is.EquivalentTo(path.Moves.SelectMany(m => m.CutFrom).Distinct()));
            Assert.That(repair.Adjust(settings).UncutJumps, Is.EquivalentTo(repair.Uncut));
            Assert.That(repair.Adjust(settings).TightenJumps, Is.True);
            Assert.That(repair.Adjust(settings).PreferFacedJumps, Is.False, "jumps are still turned: no search needs to prefer faced ones");
        });

        for (int round = 1; round < JumpRepair.CutRounds; round++)
        {
            repair.Reject(path.Moves, refused);
        }

        Assert.That(repair.CuttingAllowed, Is.False);
        Assert.That(repair.Adjust(settings).TightenJumps, Is.False);
        Assert.That(repair.Adjust(settings).FaceJumps, Is.False, "nor turned to face their way");
        Assert.That(repair.Adjust(settings).PreferFacedJumps, Is.True, "the searches prefer jumps that already face their way instead");
        Assert.That(repair.IsExhausted(JumpRepair.CutRounds, 1), Is.False, "cut rounds do not count against the searches");
    }

    /// <summary>
    /// A walking request whose cut and turned moves failed in <see cref="JumpRepair.CutRounds"/> rounds stops cutting and
    /// turning; once its walks have failed too and it searches jumps only, its jumps are turned to face their way again
    /// (by hops) for as many rounds, since the moves that failed were made for walks. Before, a spider on thin slabs fell
    /// back to jumps only with facing off, and its first jump left 43° off its way.
    /// </summary>
    [Test]
    public void AfterFallingBackToJumpsOnlyTheJumpsAreTurnedAgainForTheirOwnRounds()
    {
        (PlanningScene scene, Vector3 from, Vector3 to, Roadmap roadmap, JumpAnimator real) = Desert.Value;
        PlanResult path = new PathQuery(scene, roadmap).Plan(from, to, new QuerySettings { CanStand = real.CanStand });
        Assume.That(path.Moves.Where(m => m.CutFrom.Count > 0), Is.Not.Empty);
        Assume.That(path.Moves.Where(m => m is Walk && m.CutFrom.Count == 0), Is.Not.Empty);
        var repair = new JumpRepair();
        var settings = new QuerySettings();
        JumpAnimation cutRefused = new RefusingAnimator(new SimpleMoveAnimator(real), m => m.CutFrom.Count > 0, "cannot cut here").Animate(path.Moves);
        JumpAnimation walkRefused = new RefusingAnimator(new SimpleMoveAnimator(real), m => m is Walk && m.CutFrom.Count == 0, "cannot walk here").Animate(path.Moves);
        for (int round = 0; round < JumpRepair.CutRounds; round++)
        {
            repair.Reject(path.Moves, cutRefused);
        }

        bool whileWalking = repair.CuttingAllowed;
        for (int round = 0; round < JumpRepair.WalkRounds; round++)
        {
            repair.Reject(path.Moves, walkRefused);
        }

        QuerySettings jumping = repair.Adjust(settings);
        bool jumpsOnlyFirst = repair.CuttingAllowed;
        for (int round = 0; round < JumpRepair.CutRounds; round++)
        {
            repair.Reject(path.Moves, cutRefused);
        }

        Assert.Multiple(() =>
        {
            Assert.That(whileWalking, Is.False, "cutting stops while the request walks");
            Assert.That(repair.WalksAllowed, Is.False);
            Assert.That(jumping.Locomotion, Is.EqualTo(Locomotion.Jump));
            Assert.That(jumpsOnlyFirst, Is.True, "jumps only: turned again");
            Assert.That(jumping.FaceJumps, Is.True);
            Assert.That(repair.CuttingAllowed, Is.False, "until its own rounds fail too");
            Assert.That(repair.Adjust(settings).FaceJumps, Is.False);
        });
    }
}
