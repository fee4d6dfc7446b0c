using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.EndToEnd;

/// <summary>
/// Issue 21's facing on stairs a small quadruped can hardly stand on: the tailed quadruped's body (0.55 m) is longer
/// than a tread (0.30 m) is deep, so its sampled stances on the flight face along the treads, and a stance turned to
/// face a jump up the flight has its chest over the riser above. Before, its jumps onto the treads took off 136° and
/// 48° off their way and landed 86° and 48° off (the eye asks at most 30° and 45°). The jumps are now met by stances
/// the whole body can stand on (<c>JumpAnimator.CanStand</c> checks the bones of no limb too, as the animator does,
/// so that no turned stance with a bone in the level is placed), a short hop onto a tread lands already facing up the
/// flight where the body cannot turn round on the tread (<c>JumpFacer.Relandings</c>), and where the treads can only
/// be stood across, the jump is swung round toward the way its landing faces (<c>JumpFacer.Swing</c>).
/// </summary>
[Category("EndToEnd")]
public sealed class StairJumpFacingTests
{
    /// <summary>Where the rig's files are written (removed when the fixture ends).</summary>
    private static readonly string RigFolder = RigFolders.For("stair-facing");

    private static readonly Lazy<(Sweep.Setup Setup, (Vector3 From, Vector3 To)[] Requests)> Stairs = new(() => Sweep.PrepareForeign("stairs", "tailed", RigFolder));

    [OneTimeTearDown]
    public void RemoveTheRigFiles() => RigFolders.Remove(RigFolder);

    /// <summary>
    /// Every jump the facer turns (0.9 m or more across) takes off within the eye's 30° and lands within its 45° of its
    /// way, the plan fully right. From the floor to the top landing (request 0) the jump off the flight took off 68°
    /// off its way: its takeoff, turned to face the landing, had its chest in the riser ahead, so the jump was flown
    /// from the tread as the search found it, across the flight.
    /// </summary>
    [TestCase(0, TestName = "A tailed quadruped climbs from the floor to the stairs' top landing facing its jumps")]
    [TestCase(1, TestName = "A tailed quadruped walks to the flight and jumps up onto the fourth tread facing its jumps")]
    [TestCase(3, TestName = "A tailed quadruped jumps from the floor onto the third tread facing its jump")]
    public void ASmallQuadrupedFacesItsJumpsUpTheFlight(int request)
    {
        (Sweep.Setup setup, (Vector3 From, Vector3 To)[] requests) = Stairs.Value;
        (AnimatedPlan plan, AuditReport report, _) = Sweep.Plan(setup, requests[request].From, requests[request].To);
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        Assert.That(report.FullyRight, Is.True, report.ToString());
        Assert.That(report.Look!.Facing.Passes, Is.True, $"facing: {report.Look.Facing}");

        Jump[] far = [.. plan.Result.Jumps.Where(j => Across(j).Length() >= JumpFacer.MinDistance)];
        Assert.That(far, Is.Not.Empty, "the plan jumps up the flight");
        Assert.Multiple(() =>
        {
            foreach (Jump jump in far)
            {
                Assert.That(Off(jump.From, jump), Is.LessThanOrEqualTo(AnimatorEye.TakeoffFacing), $"takeoff of the jump from {jump.Arc.Start} off its way, degrees");
                Assert.That(Off(jump.To, jump), Is.LessThanOrEqualTo(AnimatorEye.LandingFacing), $"landing of the jump to {jump.Arc.End} off its way, degrees");
            }
        });
    }

    /// <summary>
    /// A stance whose trunk and paws are clear but whose head is in a wall it cannot bend out of (a wall from the floor
    /// up, 0.1 m beyond the front of the trunk box) is not one the body can stand on: the animator checks the bones of
    /// no limb, a free head bent clear where it can; 0.1 m farther, where the head clears the wall, it is. Once the
    /// check counted contacts only; then, on the stairs, it refused a stance on a tread facing up the flight for "the
    /// chest in the riser above", which was the link from the chest to the shoulder checked as thick as half its
    /// radius (measured over the chest's skin) standing out of the body: by its skin the chest clears that riser.
    /// </summary>
    [Test]
    public void AStanceWithItsHeadInAWallItCannotBendOutOfIsNotOneTheBodyCanStandOn()
    {
        (CharacterModel model, ReducedCharacter reduced) = ForeignCharacters.Named("tailed").Load();
        var root = new RootPose(new Vector3(0f, 0.276f, 0f), Quaternion.Identity);
        (bool Valid, int Contacts, string? Bone, bool CanStand) Stand(float ahead)
        {
            float face = reduced.TrunkHalfExtents.Z + ahead;
            Level level = new LevelBuilder("wall").AddFloor(-3f, -3f, 3f, 3f, 0f).AddBox(new Vector3(-2f, 0f, face), new Vector3(2f, 2f, face + 0.5f)).Build();
            Sweep.Setup setup = Sweep.Prepare("wall", level, model, reduced);
            var animator = (JumpAnimator)setup.Planner.Animator;
            PoseEvaluation pose = setup.Scene.Estimator.Evaluate(root);
            ContactConfiguration stance = animator.Contacts.Generate(pose.Pose, pose.Contacts, pose.Cone.Axis);
            var positions = new Vector3[model.Rig.Joints.Count];
            var rotations = new Quaternion[model.Rig.Joints.Count];
            model.Rig.Solve(stance.Root, stance.Angles, positions, rotations);
            int bone = animator.Contacts.Collision.OtherBoneColliding(positions, rotations);
            return (pose.IsValid, stance.Contacts.Count, bone >= 0 ? model.Rig.Joints[bone].Name : null, animator.CanStand(pose));
        }

        var near = Stand(0.1f);
        var far = Stand(0.2f);
        Assert.Multiple(() =>
        {
            Assert.That(near.Valid && far.Valid, Is.True, "the trunk is clear of the wall");
            Assert.That(near.Contacts, Is.EqualTo(4), "four paws on the floor");
            Assert.That(near.Bone, Is.EqualTo("head"), "the head in the wall");
            Assert.That(near.CanStand, Is.False, "a stance the body cannot stand on");
            Assert.That(far.Bone, Is.Null, "0.1 m farther the head clears the wall");
            Assert.That(far.CanStand, Is.True, "a stance the body can stand on");
        });
    }

    /// <summary>
    /// Where the flight's treads can only be stood on across (simulated: every stance on the flight turned more than
    /// 20° from the treads' run, ±Z, refused), a jump onto a tread cannot be landed facing its way: it is swung round
    /// toward the way its landing faces (<c>JumpFacer.Swing</c>), taken off facing its way from a stance the walk
    /// before it leads to, and landed at most 45° off it, across the tread.
    /// </summary>
    [Test]
    public void AJumpOntoATreadStoodOnAcrossOnlyIsSwungRound()
    {
        const int request = 3;
        (Sweep.Setup setup, (Vector3 From, Vector3 To)[] requests) = Stairs.Value;
        Sweep.Setup across = setup with { Planner = new AnimatedPlanner(setup.Scene, new AcrossTheTreads((JumpAnimator)setup.Planner.Animator)) };
        (AnimatedPlan plan, AuditReport report, _) = Sweep.Plan(across, requests[request].From, requests[request].To);
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        Assert.That(report.FullyRight, Is.True, report.ToString());
        Assert.That(report.Look!.Facing.Passes, Is.True, $"facing: {report.Look.Facing}");

        Jump[] far = [.. plan.Result.Jumps.Where(j => Across(j).Length() >= AnimatorEye.FacingDistance)];
        Assert.That(far, Is.Not.Empty, "the plan jumps onto the flight");
        foreach (Jump jump in far)
        {
            // Takeoff within 30° of the jump's way, landing within 45°, the landing standing across the flight
            // (its heading within 20° of the treads' run, ±Z): the jump was swung, not the landing turned.
            Assert.That(Off(jump.From, jump), Is.LessThanOrEqualTo(30f), "takeoff off its way, degrees");
            Assert.That(Off(jump.To, jump), Is.LessThanOrEqualTo(45f), "landing off its way, degrees");
            Assert.That(MathF.Abs(jump.To.Pose.Forward.Z), Is.GreaterThan(MathF.Cos(20f * MathF.PI / 180f)), "the landing stands along the tread");
        }

        Assert.That(plan.Result.Moves[^2], Is.InstanceOf<Walk>(), "a walk leads to the swung takeoff");
    }

    /// <summary>The animator, standing on the flight (x 2-4.4 m, above the floor) only along the treads.</summary>
    private sealed class AcrossTheTreads(JumpAnimator animator) : IJumpAnimator
    {
        public JumpAnimation Animate(IReadOnlyList<Move> moves, float frameRate = 60f) => animator.Animate(moves, frameRate);

        public bool CanStand(PoseEvaluation pose)
        {
            Vector3 at = pose.Pose.Position;
            bool onTheFlight = at.X is >= 2f and < 4.4f && TrunkSampler.ContactCentre(pose).Y > 0.1f;
            return animator.CanStand(pose) && (!onTheFlight || MathF.Abs(pose.Pose.Forward.Z) >= MathF.Cos(20f * MathF.PI / 180f));
        }

        public bool CanPush(RootPose root, IReadOnlyList<Contact> contacts, Vector3 velocity) => animator.CanPush(root, contacts, velocity);
    }

    /// <summary>
    /// From the floor to the top landing (the sweep's stairs/0) the route jumps off a tread where the front feet stand
    /// just short of the next riser. Retracted however quickly, their skin entered that riser 8–17 ms after takeoff in
    /// every flight pose tried ("left_front passes through the level in flight (0.004 s after takeoff) whatever pose it
    /// takes"): the feet rode forward with the body before their joints lifted them. The plan set 6 jumps and 3 walks
    /// aside and its jump onto the landing took off 112° and landed 154° off its way. Now such a foot is lifted straight
    /// off its contact first, as far as the body has risen, up to the step height, and retracted from there: no jump is
    /// set aside for a limb in flight, and every far jump lands within the eye's 45° of its way.
    /// </summary>
    [Test]
    public void AFootJustShortOfARiserIsLiftedOffItsTreadBeforeItSwingsOn()
    {
        (Sweep.Setup setup, (Vector3 From, Vector3 To)[] requests) = Stairs.Value;
        (AnimatedPlan plan, AuditReport report, _) = Sweep.Plan(setup, requests[0].From, requests[0].To);
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        Assert.That(report.FullyRight, Is.True, report.ToString());
        Assert.That(plan.Rejected.Select(r => r.Reason), Has.None.Contains("in flight"), "no jump set aside for a limb passing through the level in flight");
        Jump[] far = [.. plan.Result.Jumps.Where(j => Across(j).Length() >= AnimatorEye.FacingDistance)];
        Assert.That(far, Is.Not.Empty, "the plan jumps up the flight");
        Assert.That(far.Select(j => Off(j.To, j)), Has.All.LessThanOrEqualTo(AnimatorEye.LandingFacing), "landings off their way, degrees");
    }

    private static Vector2 Across(Jump jump) => new(jump.Arc.End.X - jump.Arc.Start.X, jump.Arc.End.Z - jump.Arc.Start.Z);

    /// <summary>Degrees between a stance's heading and a jump's direction across.</summary>
    private static float Off(RoadmapNode stance, Jump jump)
    {
        Vector3 f = stance.Pose.Forward;
        var a = Vector2.Normalize(new Vector2(f.X, f.Z));
        return MathF.Acos(Math.Clamp(Vector2.Dot(a, Vector2.Normalize(Across(jump))), -1f, 1f)) * 180f / MathF.PI;
    }
}
