using System.Numerics;
using Ballistic.Authoring.Animation;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

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

    /// <summary>
    /// Seen in the exported GLB (<see cref="AnimatorEye"/>), a walk on flat ground is upright: while it cruises the
    /// hips stay at least 0.88 L above the held feet (before issue 21's upright gait: 0.78 L on this walk; before the
    /// trunk cruised at <see cref="WalkGait.CruiseHips"/> with its step measured there: 0.85–0.86 L), rising and
    /// falling 0.02–0.08 L with the steps, at most 2.6 steps a second at 1.5 m/s (before: 3.3–3.8, steps 0.44–0.51 L;
    /// then 2.7–2.8 with the sole held flat to the end of each step: 2.4 once the trailing foot rolls onto its ball),
    /// and each arm swings at least 20° against the leg on its side (it hung still). The trailing foot peels off: in
    /// the clip its heel rises at least 1 cm before it swings while the ball of its foot stays on the ground.
    /// </summary>
    [TestCase("skeleton")]
    [TestCase("jumperman")]
    public void AWalkOnFlatGroundIsUprightBobsAndSwingsItsArms(string character)
    {
        WalkWorld world = WalkWorld.Create(WalkWorld.GapCourse(), character);
        JumpAnimation animation = world.AcrossFirstPlatform();
        AnimatorEye.Look look = Seen(world, animation);
        Assert.That(look.Upright.Seen, Is.Not.Empty, "the walk cruises on flat ground");
        Assert.Multiple(() =>
        {
            Assert.That(look.Upright.Worst!.Value.Score * AnimatorEye.UprightHips, Is.GreaterThanOrEqualTo(0.88f), look.Upright.ToString());
            Assert.That(look.Cadence.Seen, Is.Not.Empty, "the cadence measured");
            Assert.That(look.Cadence.Passes, Is.True, look.Cadence.ToString());
            Assert.That(look.Bob.Passes, Is.True, look.Bob.ToString());
            Assert.That(look.ArmSwing.Seen, Has.Count.EqualTo(2), "both arms measured");
            Assert.That(look.ArmSwing.Passes, Is.True, look.ArmSwing.ToString());
        });

        // Heel off: at the end of each phase on the ball, the sole's contact point is above the ground and the ball on it.
        var positions = new Vector3[world.Model.Rig.Joints.Count];
        var rotations = new Quaternion[world.Model.Rig.Joints.Count];
        ContactPhase[] rolled = [.. animation.ContactPhases.Where(p => p.OnBall)];
        Assert.That(rolled, Has.Length.GreaterThanOrEqualTo(2), "the trailing feet roll onto their balls");
        foreach (ContactPhase phase in rolled)
        {
            animation.Joints(phase.To, positions, rotations);
            RigLimb foot = world.Model.Limbs[phase.Limb];
            Assert.Multiple(() =>
            {
                Assert.That(foot.EffectorPosition(positions, rotations).Y - phase.Position.Y, Is.GreaterThan(0.01f), $"{foot.Name}'s heel is up at {phase.To:0.00} s");
                Assert.That(Vector3.Distance(phase.Touching(foot, positions, rotations), phase.Position), Is.LessThan(0.01f), $"{foot.Name}'s ball is down at {phase.To:0.00} s");
            });
        }
    }

    /// <summary>
    /// A rig modelled with its legs spread flat (the ant: its hips level with its feet at rest, 13 cm above them in
    /// its contact pose) walks at the height it stands at and bobs with its steps, seen in the exported GLB: while it
    /// cruises its hips stay at least 0.88 L above the held feet and rise and fall 0.02–0.08 L (0.93 L and 0.036 L;
    /// before, the gait measured the leg from the rest pose and the hips glided low: 0.83 L, 0.000 L).
    /// </summary>
    [Test]
    public void ARigWithSpreadLegsWalksAtItsStandingHeightAndBobs()
    {
        WalkWorld world = WalkWorld.Create(WalkWorld.GapCourse(), "ant");
        JumpAnimation animation = world.AcrossFirstPlatform();
        AnimatorEye.Look look = Seen(world, animation);
        Assert.That(look.Upright.Seen, Is.Not.Empty, "the walk cruises on flat ground");
        Assert.Multiple(() =>
        {
            Assert.That(look.Upright.Passes, Is.True, look.Upright.ToString());
            Assert.That(look.Bob.Passes, Is.True, look.Bob.ToString());
        });
    }

    /// <summary>A straight walk of <paramref name="character"/> 6.5 m along +X across the block level's open floor, as the eye sees it in the GLB.</summary>
    private static (JumpAnimation Animation, AnimatorEye.Look Look) AcrossTheBlocksFloor(string character)
    {
        WalkWorld world = WalkWorld.Create(ForeignLevels.Get("block").Level, character);
        RoadmapNode from = world.Stance(new Vector3(-6.5f, 0f, 6f), 0, Vector3.UnitX);
        RoadmapNode to = world.Stance(new Vector3(0f, 0f, 6f), 1, Vector3.UnitX);
        JumpAnimation animation = world.Animator.Animate([world.Walk(from, to)]);
        return (animation, Seen(world, animation));
    }

    /// <summary>
    /// A rig with more than two feet (the dog from another tool, 6.5 m across the block level's open floor) walks with
    /// its hips upright, seen in the exported GLB: with four feet one is always near the end of its range, so its steps are those its legs reach holding the
    /// hips <see cref="WalkGait.ManyFeetHips"/> of the leg up: 0.89 L here (before: 0.87 L here and on every walk of
    /// the sweep's dog, held down by whichever foot was most stretched).
    /// </summary>
    [Test]
    public void ARigWithFourFeetWalksWithItsHipsUpright()
    {
        (_, AnimatorEye.Look look) = AcrossTheBlocksFloor("dog");
        Assert.That(look.Upright.Seen, Is.Not.Empty, "the walk cruises on flat ground");
        Assert.That(look.Upright.Passes, Is.True, look.Upright.ToString());
    }

    /// <summary>
    /// A four-footed rig whose stances plant a front foot wide and far ahead (the tailed rig from another tool, whose
    /// legs stand straight in their contact pose, 6.5 m across the block level's open floor) walks with its feet set
    /// down where its contact pose holds them under the trunk and steps its legs reach holding the hips high, seen in
    /// the exported GLB: hips 0.90 of each leg's own length above the held feet (before: 0.86, the left front foot
    /// kept 8 cm out to the side all the way, found only half a step back, and no step limit at all, the legs' reach
    /// with the hips high measured as nothing because a straight leg gave the IK no bend to follow).
    /// </summary>
    [Test]
    public void AFourFootedRigSetsItsFeetUnderItsTrunkAndWalksUpright()
    {
        (JumpAnimation animation, AnimatorEye.Look look) = AcrossTheBlocksFloor("tailed");
        TestContext.Out.WriteLine($"{look.Upright}; {look.UnderHips}; {look.Bob}");
        Assert.That(look.Upright.Seen, Is.Not.Empty, "the walk cruises on flat ground");
        Assert.Multiple(() =>
        {
            Assert.That(animation.Problems, Is.Empty);
            Assert.That(look.Upright.Passes, Is.True, look.Upright.ToString());
            Assert.That(look.UnderHips.Passes, Is.True, look.UnderHips.ToString());
            Assert.That(look.Bob.Passes, Is.True, look.Bob.ToString());
        });
    }

    /// <summary>
    /// An ant (its front and hind feet stand about twice its leg ahead of and behind its trunk's centre) turning in
    /// place a quarter turn at both ends of a short walk across open floor keeps every foot within 0.35 of its leg
    /// sideways of where its contact pose holds it, seen in the exported GLB: it turns more slowly
    /// (<see cref="ReducedModelBuilder.TurnRate"/>) and less during each step (<see cref="WalkGait.TurnDrift"/>)
    /// (before, this walk could not be animated at all, and the sweep's turns in place read 0.40–0.58 L: each held
    /// front foot carried 20° round at the planner's 86°/s).
    /// </summary>
    [Test]
    public void AnAntTurningInPlaceKeepsItsFeetUnderItsHips()
    {
        WalkWorld world = WalkWorld.Create(ForeignLevels.Get("block").Level, "ant");
        RoadmapNode from = world.Stance(new Vector3(-6.5f, 0f, 6f), 0, -Vector3.UnitZ);
        RoadmapNode to = world.Stance(new Vector3(-5f, 0f, 6f), 1, Vector3.UnitZ);
        Walk walk = world.Walk(from, to);
        Assert.That(walk.StartTurn * walk.TurnRate, Is.GreaterThan(1.2f), "it turns about a quarter turn in place before it walks");
        JumpAnimation animation = world.Animator.Animate([walk]);
        AnimatorEye.Look look = Seen(world, animation);
        TestContext.Out.WriteLine(look.UnderHips.ToString());
        Assert.That(look.UnderHips.Passes, Is.True, look.UnderHips.ToString());
    }

    /// <summary>
    /// A spider's short walk that is mostly a turn in place (23° in 0.49 s, then 4 cm in 0.3 s) lets go of its start
    /// contacts by the time its trunk has made about half the turn (47 %): the walk is stepped in three half-cycles,
    /// the first half a cycle of cost long (drawn toward a third of the walk so that each lasts a half-cycle). Before,
    /// it had two, split at half its time, and the group held on the start contacts until the turn, made first, was
    /// over (99 %; 73–77 % with the two split where half the cost is reached): on the doorway level (the sweep's
    /// request 2 there) the spider's right front foot, 0.6 m from its trunk's centre, held its contact as the trunk
    /// turned 23° and was 0.62 L sideways of its place; 0.27 L now.
    /// </summary>
    [Test]
    public void ASpiderTurningInAShortWalkLetsGoOfItsStartContactsWhileItTurns()
    {
        WalkWorld world = WalkWorld.Create(ForeignLevels.Get("doorway").Level, "spider");
        Vector3 facing = Vector3.Normalize(new Vector3(MathF.Sin(0.4f), 0f, MathF.Cos(0.4f)));
        RoadmapNode from = world.Stance(new Vector3(-3f, 0f, 2.5f), 0, Vector3.UnitZ);
        RoadmapNode to = world.Stance(WalkWorld.Centre(from) + (0.02f * facing), 1, facing);
        Walk walk = world.Walk(from, to);
        float turn = Rotations.AngleBetween(from.Pose.Rotation, to.Pose.Rotation);
        TestContext.Out.WriteLine($"turn {turn * 180f / MathF.PI:0.0}°, start turn {walk.StartTurn:0.00} s, end turn {walk.EndTurn:0.00} s, {walk.Length:0.00} m, {walk.Duration:0.00} s");
        Assert.That(walk.StartTurn + walk.EndTurn, Is.GreaterThan(0.5f * walk.Duration), "mostly a turn in place");
        JumpAnimation animation = world.Animator.Animate([walk]);
        Assert.That(animation.Problems.Select(p => p.Reason), Is.Empty);
        Assert.Multiple(() =>
        {
            for (int l = 0; l < world.Model.Limbs.Count; l++)
            {
                if (world.Model.Limbs[l].Kind != LimbKind.Foot || from.Contacts.Count == 0)
                {
                    continue;
                }

                // The foot's first hold (from the walk's start) and how far the trunk has turned when it ends.
                ContactPhase first = animation.ContactPhases.Where(c => c.Limb == l).MinBy(c => c.From);
                float turned = Rotations.AngleBetween(from.Pose.Rotation, animation.RootAt(first.To).Rotation) / turn;
                TestContext.Out.WriteLine($"{world.Model.Limbs[l].Name}: held {first.From:0.00}-{first.To:0.00} s, trunk {turned:P0} round");
                Assert.That(turned, Is.LessThanOrEqualTo(LetGoShare), $"{world.Model.Limbs[l].Name} lets go of its start contact");
            }
        });
    }

    /// <summary>
    /// The most of its turn a trunk has made when a foot lets go of its start contact in
    /// <see cref="ASpiderTurningInAShortWalkLetsGoOfItsStartContactsWhileItTurns"/>: half, and what it turns while the
    /// swings overlap after the first half-cycle's end.
    /// </summary>
    private const float LetGoShare = 0.6f;

    /// <summary>
    /// A walk whose upright steps cannot all be held (here beside a block, where the stance the walk ends on is cramped)
    /// is walked again with shorter steps only around the trouble, not at the classic short step all along: seen in
    /// the GLB, the walk keeps its upright cadence (before: 3.4 steps a second, 0.49 L each, on this walk in the sweep).
    /// </summary>
    [Test]
    public void AWalkThatMeetsTroubleShortensItsStepsOnlyThere()
    {
        WalkWorld world = WalkWorld.Create(ForeignLevels.Get("block").Level, "skeleton");
        RoadmapNode from = world.Stance(new Vector3(-4f, 0f, 3f), 0, Vector3.UnitZ);
        // The stance the roadmap placed beside the block, its trunk higher above its feet than the walk's start.
        PoseEvaluation beside = world.Scene.Estimator.Evaluate(new RootPose(new Vector3(0.112f, 1.2249f, 0.8399f), Quaternion.CreateFromAxisAngle(Vector3.UnitY, MathF.Atan2(0.9937f, 0.1119f))));
        Assert.That(beside.IsValid && world.Animator.CanStand(beside), Is.True, beside.Validity.ToString());
        var to = new RoadmapNode(1, beside.Pose, beside.Cone, beside.Contacts);
        Walk walk = world.Walk(from, to);
        JumpAnimation animation = world.Animator.Animate([walk]);
        AnimatorEye.Look look = Seen(world, animation);
        Assert.Multiple(() =>
        {
            Assert.That(look.Upright.Worst!.Value.Score * AnimatorEye.UprightHips, Is.GreaterThanOrEqualTo(0.88f), look.Upright.ToString());
            Assert.That(look.Cadence.Passes, Is.True, look.Cadence.ToString());
        });
    }

    /// <summary>
    /// A walk animated again between the same poses (the repair's next round, another agent of the kind) is the clip
    /// a fresh gait animates, its problems on the move asked, its angles its own; a walk ending on another pose is
    /// animated anew.
    /// </summary>
    [Test]
    public void AWalkAnimatedAgainBetweenTheSamePosesIsTheClipAFreshGaitAnimates()
    {
        (WalkWorld world, Walk walk, ContactConfiguration start, ContactConfiguration end) = ShortFlatWalk();
        ContactGenerator contacts = world.Animator.Contacts;
        ContactConfiguration bent = end with { Angles = [.. end.Angles.Select((a, d) => d == 0 ? a + 0.05f : a)] };
        var gait = new WalkGait(world.Scene, world.Model, contacts);
        WalkGait.Clip first = gait.Animate(0, walk, start, end, 60f);
        first.Frames[^1].Angles[0] += 1f; // a caller changing its clip in place changes no other
        WalkGait.Clip again = gait.Animate(3, walk, start, end, 60f);
        WalkGait.Clip other = gait.Animate(3, walk, start, bent, 60f);
        WalkGait.Clip fresh = new WalkGait(world.Scene, world.Model, contacts).Animate(3, walk, start, end, 60f);
        WalkGait.Clip freshOther = new WalkGait(world.Scene, world.Model, contacts).Animate(3, walk, start, bent, 60f);
        Assert.Multiple(() =>
        {
            foreach ((WalkGait.Clip clip, WalkGait.Clip expected, string name) in new[] { (again, fresh, "again"), (other, freshOther, "to another pose") })
            {
                Assert.That(clip.Frames.Select(f => (f.Time, f.Root)), Is.EqualTo(expected.Frames.Select(f => (f.Time, f.Root))), name);
                Assert.That(clip.Frames.SelectMany(f => f.Angles), Is.EqualTo(expected.Frames.SelectMany(f => f.Angles)), name);
                Assert.That(clip.Phases, Is.EqualTo(expected.Phases), name);
                Assert.That(clip.Problems, Is.EqualTo(expected.Problems), name);
                Assert.That(clip.Problems.Select(p => p.Jump), Has.All.EqualTo(3), name);
            }

            Assert.That(other.Frames.SelectMany(f => f.Angles), Is.Not.EqualTo(again.Frames.SelectMany(f => f.Angles)), "a walk to another pose is another clip");
        });
    }

    /// <summary>The skeleton on the desert and the desert's walking roadmap (600 nodes, seed 1).</summary>
    private static readonly Lazy<(WalkWorld World, Roadmap Roadmap)> DesertWalking = new(() =>
    {
        WalkWorld world = WalkWorld.Create(SharedLevels.Bundled("desert"), "skeleton");
        return (world, new RoadmapBaker(world.Scene).Bake(new BakeSettings { Locomotion = Locomotion.WalkAndJump, Seed = 1, MaxNodes = 600, Threads = 2 }).Roadmap);
    });

    /// <summary>Turn of a joint (radians per second) between two fine steps inside a swing that an eye reads as a snap: 3,600°/s, 60° a frame at 60 frames a second, ten times a walker's knee in swing.</summary>
    private const float SnapSpeed = 3600f * MathF.PI / 180f;

    /// <summary>
    /// A swinging foot held flat on its lifted curve does not snap to another solution of its leg: a flat-sole solve
    /// that turns a joint faster than <see cref="WalkGait.MaxJointTurn"/> from the step before gives way to the sole
    /// held along the curve's normal within its looser tolerance. On five walks over the dunes of the desert's walking
    /// roadmap (600 nodes, seed 1), the fine steps strictly inside a swing (its foot held at neither, nor at the steps
    /// either side) at which a joint of the swinging leg turns faster than 3,600°/s: 13 before (a hip held at its limit
    /// let go, twisting as much as 42° in 1/240 s), 5 now. Those left are where no solve holds the sole smoothly, as
    /// where the sole comes back to its way after a stretch held free.
    /// </summary>
    [Test]
    public void ASwingingLegSnapsToAnotherSolutionOnlyWhereNoSmoothOneHolds()
    {
        (WalkWorld world, Roadmap roadmap) = DesertWalking.Value;
        ContactGenerator contacts = world.Animator.Contacts;
        Rig rig = world.Model.Rig;
        var gait = new WalkGait(world.Scene, world.Model, contacts);
        int keys = 0;
        var snaps = new List<string>();
        foreach ((int a, int b) in new[] { (12, 14), (25, 21), (32, 21), (46, 35), (7, 35) })
        {
            RoadmapNode from = roadmap.Nodes[a];
            RoadmapNode to = roadmap.Nodes[b];
            Walk walk = world.Scene.Walking.SteerRemembered(from, to).Walk ?? throw new AssertionException($"walk {a} to {b} traces");
            WalkGait.Clip clip = gait.Animate(0, walk, contacts.Generate(from.Pose, from.Contacts, from.Cone.Axis), contacts.Generate(to.Pose, to.Contacts, to.Cone.Axis), 60f);
            for (int l = 0; l < world.Model.Limbs.Count; l++)
            {
                RigLimb limb = world.Model.Limbs[l];
                if (limb.Kind != LimbKind.Foot)
                {
                    continue;
                }

                bool Held(int f) => clip.Phases.Any(p => p.Limb == l && clip.Frames[f].Time >= p.From - 1e-4f && clip.Frames[f].Time <= p.To + 1e-4f);
                for (int f = 2; f < clip.Frames.Length - 1; f++)
                {
                    if (Held(f - 2) || Held(f - 1) || Held(f) || Held(f + 1))
                    {
                        continue;
                    }

                    keys++;
                    AnimationFrame before = clip.Frames[f - 1];
                    AnimationFrame now = clip.Frames[f];
                    float turn = limb.Chain.Max(j => rig.JointTurn(j, now.Angles, before.Angles));
                    if (turn / (now.Time - before.Time) > SnapSpeed)
                    {
                        snaps.Add($"walk {a} to {b}: {limb.Name} at {now.Time:0.000} s, {turn * 180f / MathF.PI:0.0}°");
                    }
                }
            }
        }

        Assert.Multiple(() =>
        {
            Assert.That(keys, Is.GreaterThan(4000), "fine steps inside swings");
            Assert.That(snaps, Has.Count.LessThanOrEqualTo(6), string.Join("; ", snaps));
        });
    }

    /// <summary>
    /// Two shortcuts of the gait leave every clip as it was. A run kept only when it has fewer problems than the best
    /// so far (the feet flat instead of rolled, the hips judged where an earlier lift held them, the classic steps last)
    /// stops as soon as it has as many; and the runs of one walk measure its stances (the hips' cruising lift, each
    /// foot's reach along the trunk) once between them. On the desert's walking roadmap (600 nodes, seed 1), three
    /// walks over the dunes whose upright run meets trouble, one of them clean only at the classic steps and one with
    /// problems whatever the gait tries, have the same frames, contact phases and problems as with a gait finishing
    /// every run and one measuring the stances in every run; runs were stopped, and the stances measured at most six
    /// times a walk (stopping a run one problem sooner changes the first two clips).
    /// </summary>
    [Test]
    public void TheGaitsShortcutsChangeNoClip()
    {
        (WalkWorld world, Roadmap roadmap) = DesertWalking.Value;
        ContactGenerator contacts = world.Animator.Contacts;
        var shortcut = new WalkGait(world.Scene, world.Model, contacts);
        var finishing = new WalkGait(world.Scene, world.Model, contacts) { StopsRunsOfNoUse = false };
        var measuring = new WalkGait(world.Scene, world.Model, contacts) { SharesStanceMeasures = false };
        var problems = new List<int>();
        (int From, int To)[] walks = [(7, 32), (32, 21), (8, 23)];
        Assert.Multiple(() =>
        {
            foreach ((int a, int b) in walks)
            {
                Assert.That(roadmap.Walks.Any(w => w.From == a && w.To == b), Is.True, $"the bake has a walk from node {a} to node {b}");
                RoadmapNode from = roadmap.Nodes[a];
                RoadmapNode to = roadmap.Nodes[b];
                Walk walk = world.Scene.Walking.SteerRemembered(from, to).Walk ?? throw new AssertionException($"walk {a} to {b} traces");
                ContactConfiguration start = contacts.Generate(from.Pose, from.Contacts, from.Cone.Axis);
                ContactConfiguration end = contacts.Generate(to.Pose, to.Contacts, to.Cone.Axis);
                WalkGait.Clip clip = shortcut.Animate(0, walk, start, end, 60f);
                foreach ((WalkGait other, string how) in new[] { (finishing, "finishing every run"), (measuring, "measuring the stances in every run") })
                {
                    WalkGait.Clip expected = other.Animate(0, walk, start, end, 60f);
                    string name = $"walk {a} to {b}, against {how}";
                    Assert.That(clip.Frames.Select(f => (f.Time, f.Root)), Is.EqualTo(expected.Frames.Select(f => (f.Time, f.Root))), name);
                    Assert.That(clip.Frames.SelectMany(f => f.Angles), Is.EqualTo(expected.Frames.SelectMany(f => f.Angles)), name);
                    Assert.That(clip.Phases, Is.EqualTo(expected.Phases), name);
                    Assert.That(clip.Problems, Is.EqualTo(expected.Problems), name);
                }

                problems.Add(clip.Problems.Count);
            }

            Assert.That(problems, Is.EqualTo(new[] { 0, 0, 1 }), "problems per walk");
            Assert.That(shortcut.RunsStopped, Is.GreaterThan(0), "runs stopped early");
            Assert.That(finishing.RunsStopped, Is.EqualTo(0), "every run finished");
            Assert.That(shortcut.StanceMeasures, Is.LessThanOrEqualTo(6 * walks.Length), "stances measured once a walk");
            Assert.That(measuring.StanceMeasures, Is.GreaterThan(2 * shortcut.StanceMeasures), "stances measured in every run");
        });
    }

    /// <summary>
    /// Two agents of one kind asking for the same walk at once (two animation threads) get it animated once: the
    /// second waits for the first's clip instead of animating it again, and each gets its own copy, on its own move.
    /// </summary>
    [Test]
    public void AWalkAskedForByTwoThreadsAtOnceIsAnimatedOnce()
    {
        (WalkWorld world, Walk walk, ContactConfiguration start, ContactConfiguration end) = ShortFlatWalk();
        var gait = new WalkGait(world.Scene, world.Model, world.Animator.Contacts);
        using var together = new Barrier(2);
        var clips = new WalkGait.Clip[2];
        Parallel.For(0, 2, new ParallelOptions { MaxDegreeOfParallelism = 2 }, i =>
        {
            together.SignalAndWait();
            clips[i] = gait.Animate(i + 1, walk, start, end, 60f);
        });

        WalkGait.Clip fresh = new WalkGait(world.Scene, world.Model, world.Animator.Contacts).Animate(1, walk, start, end, 60f);
        Assert.Multiple(() =>
        {
            Assert.That(gait.Solved, Is.EqualTo(1), "walks animated anew");
            for (int i = 0; i < 2; i++)
            {
                Assert.That(clips[i].Frames.SelectMany(f => f.Angles), Is.EqualTo(fresh.Frames.SelectMany(f => f.Angles)), $"thread {i}'s clip");
                Assert.That(clips[i].Problems.Select(p => p.Jump), Has.All.EqualTo(i + 1), $"thread {i}'s problems are on its move");
            }

            Assert.That(clips[0].Frames[0].Angles, Is.Not.SameAs(clips[1].Frames[0].Angles), "each thread's clip has its own angles");
        });
    }

    /// <summary>
    /// The hips' lift never rises or falls faster than a walker's (the desert skeleton's hips fell 9 cm in 0.07 s from
    /// a lift its next step did not allow): limited, each lift is the least of every measured lift plus the rate times
    /// the steps between them, never raised, the steps where no foot is held left alone. Seeded sweep against that
    /// definition, computed the slow way.
    /// </summary>
    [Test]
    public void TheHipsLiftIsLoweredAheadOfADropNeverRaised()
    {
        var random = new Random(21);
        for (int trial = 0; trial < 200; trial++)
        {
            int n = random.Next(1, 80);
            float rate = 0.001f + (0.01f * (float)random.NextDouble());
            float[] lift = [.. Enumerable.Range(0, n).Select(_ => random.Next(4) == 0 ? 0f : 0.1f * (float)random.NextDouble())];
            bool[] measured = [.. Enumerable.Range(0, n).Select(_ => random.Next(5) > 0)];
            float[] limited = (float[])lift.Clone();
            WalkGait.LimitRate(limited, measured, rate);
            for (int i = 0; i < n; i++)
            {
                float expected = !measured[i] ? lift[i] : Enumerable.Range(0, n).Where(k => measured[k]).Min(k => lift[k] + (rate * Math.Abs(i - k)));
                Assert.That(limited[i], Is.EqualTo(expected).Within(1e-6f), $"trial {trial}, step {i} of {n}");
                Assert.That(limited[i], Is.LessThanOrEqualTo(lift[i]), $"trial {trial}: step {i} raised");
            }

            int[] held = [.. Enumerable.Range(0, n).Where(k => measured[k])];
            Assert.That(held.Zip(held.Skip(1)).All(p => MathF.Abs(limited[p.Second] - limited[p.First]) <= (rate * (p.Second - p.First)) + 1e-6f), Is.True, $"trial {trial}: a faster rise or fall");
        }
    }

    /// <summary>
    /// The least dip is added where the hips' swing falls short, and the swing is read about the walk's own grade: hips
    /// rising steadily up a 1 in 10 slope (2.4 cm over the window's 24 steps of 1 cm) swing nothing; a 1.5 cm rise and
    /// fall over each step on that slope swings 3 cm, however the slope runs; steps where no foot is held are left out.
    /// </summary>
    [Test]
    public void TheHipsSwingIsTheirRiseAndFallAboutTheGrade()
    {
        const int Window = 12;
        bool[] all = [.. Enumerable.Repeat(true, 61)];
        float[] Heights(float grade, float bob) => [.. Enumerable.Range(0, 61).Select(j => (grade * 0.01f * j) + (bob * MathF.Cos(MathF.PI * j / Window)))];
        bool[] gaps = [.. Enumerable.Range(0, 61).Select(j => j % 5 != 2)];
        float[] spiked = Heights(0.1f, 0.015f);
        foreach (int j in Enumerable.Range(0, 61).Where(j => !gaps[j]))
        {
            spiked[j] = 5f;
        }

        Assert.Multiple(() =>
        {
            Assert.That(WalkGait.HipSwing(Heights(0.1f, 0f), all, 24, Window), Is.LessThan(1e-4f), "a steady rise is no swing");
            Assert.That(WalkGait.HipSwing(Heights(-0.1f, 0f), all, 24, Window), Is.LessThan(1e-4f), "nor a steady sink");
            Assert.That(WalkGait.HipSwing(Heights(0f, 0.015f), all, 24, Window), Is.EqualTo(0.03f).Within(0.004f), "a 1.5 cm bob on the level");
            Assert.That(WalkGait.HipSwing(Heights(0.1f, 0.015f), all, 24, Window), Is.EqualTo(0.03f).Within(0.004f), "the same bob up the slope");
            Assert.That(WalkGait.HipSwing(spiked, gaps, 24, Window), Is.EqualTo(0.03f).Within(0.006f), "steps not held are left out");
        });
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

    [Test]
    public void ALegThatWouldPassThroughTheGroundBetweenTwoStepsIsReportedNeverPlayedAsClean()
    {
        // Found by the audit (sampling at 120 Hz, between the gait's fine steps): on another tool's thin slabs, a
        // Z-up human's short walks after and before a jump; the leg's IK jumped to another solution one fine step before
        // touch-down, and played between the two steps the toe went 3 to 9 cm into the slab. The gait now checks each
        // swing between its steps as a player shows it, so such a walk is a problem and the plan does without it.
        string folder = Path.Combine(Path.GetTempPath(), $"ballistic-flip-{Guid.NewGuid():N}");
        Directory.CreateDirectory(folder);
        try
        {
            (string gltf, string spec) = ForeignCharacters.Human(zUpScene: true).Write(folder);
            (CharacterModel model, ReducedCharacter reduced) = CharacterSpecFile.Load(gltf, spec);
            (Level level, _) = ForeignLevels.Get("thin-slabs");
            Sweep.Setup setup = Sweep.Prepare("thin-slabs", level, model, reduced);
            foreach ((Vector3 from, Vector3 to) in new[] { (new Vector3(-3f, 0.62f, 0f), new Vector3(0.5f, 0.95f, 0f)), (new Vector3(6f, 0f, 4f), new Vector3(4f, 0.5f, 4f)) })
            {
                var bake = new BakeSettings { Seed = 1, Threads = 2, MaxNodes = 600, Start = from, Goal = to, StopWhenConnected = true, CanStand = setup.Planner.Animator.CanStand };
                Roadmap roadmap = new RoadmapBaker(setup.Scene).Bake(bake).Roadmap;
                AnimatedPlan plan = setup.Planner.Plan(roadmap, from, to, new QuerySettings { MinCutWalk = 0.4f });
                AuditReport audit = PlanAudit.Check("thin slabs", setup.Scene, from, to, plan.Result, plan.Animation);
                Assert.That(audit.WrongAnswer, Is.False, audit.ToString());
                Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
            }
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    [TestCase("left_foot")]
    [TestCase("right_foot")]
    public void AWalkEndingWithAFootFreeNeverLeavesEveryFootInTheAirUnreported(string freeFoot)
    {
        // The next jump may take off without one foot. Whichever group swings last, every moment has a foot on the
        // ground or the gait says it has not.
        (WalkWorld world, Walk walk, ContactConfiguration start, ContactConfiguration full) = ShortFlatWalk();
        ContactGenerator contacts = world.Animator.Contacts;
        int foot = Enumerable.Range(0, world.Model.Limbs.Count).Single(l => world.Model.Limbs[l].Name == freeFoot);
        Assume.That(full.Contacts.Any(c => c.Limb == foot), Is.True);
        ContactConfiguration end = full with { Contacts = [.. full.Contacts.Where(c => c.Limb != foot)] };
        WalkGait.Clip clip = new WalkGait(world.Scene, world.Model, contacts).Animate(0, walk, start, end, 60f);
        bool reported = clip.Problems.Any(p => p.Reason.Contains("in the air with every other foot", StringComparison.Ordinal));
        int[] feet = [.. Enumerable.Range(0, world.Model.Limbs.Count).Where(l => world.Model.Limbs[l].Kind == LimbKind.Foot)];
        bool everyMomentHeld = clip.Frames.All(f => clip.Phases.Any(p => feet.Contains(p.Limb) && f.Time >= p.From - 1e-4f && f.Time <= p.To + 1e-4f));
        TestContext.Out.WriteLine($"{freeFoot} free at the end: {(everyMomentHeld ? "a foot down throughout" : "a moment with no foot down")}; problems: {string.Join("; ", clip.Problems.Select(p => p.Reason))}");
        Assert.That(everyMomentHeld || reported, Is.True, "every foot in the air at some moment, and the gait said nothing");
        Assert.That(reported, Is.EqualTo(!everyMomentHeld), "reported exactly when it happens");

        // Each problem is placed on the walk's path where it first shows, as its sentence says (the repair hops there).
        foreach (JumpProblem problem in clip.Problems)
        {
            Assert.That(problem.IsLocated, Is.True, problem.Reason);
            Assert.That(problem.Along, Is.InRange(0f, walk.Length), problem.Reason);
            if (problem.Reason.Contains("along the walk", StringComparison.Ordinal))
            {
                Assert.That(problem.Reason, Does.Contain($"{problem.Along:0.00} m along the walk"));
            }
        }
    }

    /// <summary>The skeleton's 2.9 m walk along the gap course's first platform, with the contact poses it starts and ends in.</summary>
    private static (WalkWorld World, Walk Walk, ContactConfiguration Start, ContactConfiguration End) ShortFlatWalk()
    {
        WalkWorld world = WalkWorld.Create(WalkWorld.GapCourse(), "skeleton");
        RoadmapNode from = world.Stance(new Vector3(-7.3f, 0f, 0.5f), 0, Vector3.UnitX);
        RoadmapNode to = world.Stance(new Vector3(-4.4f, 0f, -0.2f), 1, Vector3.UnitX);
        ContactGenerator contacts = world.Animator.Contacts;
        return (world, world.Walk(from, to), contacts.Generate(from.Pose, from.Contacts, from.Cone.Axis), contacts.Generate(to.Pose, to.Contacts, to.Cone.Axis));
    }

    /// <summary>A walk animated without problems, as the eye sees its exported GLB (printed).</summary>
    /// <summary>
    /// A person walking a gentle curve keeps the length of their steps: the skeleton on a 6.5 m arc bowing 1.5 m to the
    /// side across the block level's open floor (its heading turning 72° in all) walks at most 2.6 steps a second, each
    /// at least 0.5 L, seen in the exported GLB: 2.3 steps a second of 0.71 L. A turn of the trunk costs a step only as
    /// far as it moves the feet under it (before, every 20° of turn counted as a whole step on top of the distance:
    /// 3.2 steps a second of 0.53 L here).
    /// </summary>
    [Test]
    public void AWalkAlongACurveKeepsItsStepLength()
    {
        WalkWorld world = WalkWorld.Create(ForeignLevels.Get("block").Level, "skeleton");
        RoadmapNode from = world.Stance(new Vector3(-6.5f, 0f, 6f), 0, Vector3.Normalize(new Vector3(1f, 0f, -0.7f)));
        RoadmapNode to = world.Stance(new Vector3(0f, 0f, 6f), 1, Vector3.Normalize(new Vector3(1f, 0f, 0.7f)));
        Vector3 a = WalkWorld.Centre(from);
        Vector3 b = WalkWorld.Centre(to);
        var path = new List<Vector3>();
        for (int i = 0; i <= 40; i++)
        {
            float t = i / 40f;
            Vector3 p = Vector3.Lerp(a, b, t) - (Vector3.UnitZ * (1.5f * MathF.Sin(MathF.PI * t)));
            path.Add(world.Ground(p.X, p.Z, 1f) ?? throw new AssertionException($"no ground below {p}"));
        }

        path[0] = a;
        path[^1] = b;
        JumpAnimation animation = world.Animator.Animate([new Walk(from, to, path, world.Scene.Character.Walking.Speed, turnRate: world.Scene.Character.Walking.TurnRate)]);
        AnimatorEye.Look look = Seen(world, animation);
        Assert.That(look.Cadence.Seen, Is.Not.Empty, "the walk cruises on level ground");
        Assert.That(look.Cadence.Passes, Is.True, look.Cadence.ToString());
    }

    /// <summary>
    /// Between two steps a walker's hips stay high because its trailing foot peels off its heel: the gait lifts the
    /// hips as far as that foot reaches rolled onto its ball, not only flat. Seen in the exported GLB on a 6.5 m
    /// straight walk over level ground: the skeleton's and jumperman's hips cruise at least 0.91 L above the held
    /// feet (0.90 L when the lift allowed only for flat feet). A rig whose toes would go into the ground if its foot
    /// rolled so (the limbs-only human: its skinned toes do not bend) walks lifted as far as its feet reach flat, upright
    /// and without problems (lifted for rolled feet alone, its toes went into the ground while it held its footholds
    /// and the walk fell back to a 0.79 L crouch at 2.7 steps a second).
    /// </summary>
    [TestCase("skeleton", 0.91f)]
    [TestCase("jumperman", 0.91f)]
    [TestCase("human", 0.88f)]
    public void ATrailingFootPeelsOffSoTheHipsStayHighBetweenSteps(string character, float leastHips)
    {
        WalkWorld world = WalkWorld.Create(ForeignLevels.Get("block").Level, character);
        RoadmapNode from = world.Stance(new Vector3(-6.5f, 0f, 6f), 0, Vector3.UnitX);
        RoadmapNode to = world.Stance(new Vector3(0f, 0f, 6f), 1, Vector3.UnitX);
        JumpAnimation animation = world.Animator.Animate([world.Walk(from, to)]);
        AnimatorEye.Look look = Seen(world, animation);
        Assert.That(look.Upright.Seen, Is.Not.Empty, "the walk cruises on level ground");
        Assert.Multiple(() =>
        {
            Assert.That(look.Upright.Worst!.Value.Score * AnimatorEye.UprightHips, Is.GreaterThanOrEqualTo(leastHips), look.Upright.ToString());
            Assert.That(look.Bob.Passes, Is.True, look.Bob.ToString());
            Assert.That(look.Cadence.Passes, Is.True, look.Cadence.ToString());
        });
    }

    /// <summary>
    /// A spider walking up to the foot of a 0.6 m face and turning in place there to face along it, its right front
    /// legs swung toward the face, sets every foot on the floor it walks, its soles on the ground. Before, the turn set
    /// r1 and r2 down on the platform's top, 0.6 m above the floor and above their own hips (a climb, where its walk
    /// steps 9 cm), their soles tipped 2.5–2.7 cm off the ground: a foothold's height was checked against the walk's
    /// ground only as a step plus the walkable grade times the distance out, which a leg reaching 0.55 m sideways
    /// passes at any height. Now the ground from the walk's path out to the foothold may rise by no more than a step
    /// (plus the grade) between samples 5 cm apart.
    /// </summary>
    [Test]
    public void ASpiderTurningAtTheFootOfAFaceKeepsItsFeetOnTheFloorItWalks()
    {
        Level level = new LevelBuilder("platform").AddFloor(-4f, -3f, 4f, 3f, 0f).AddBox(new Vector3(1f, 0f, -3f), new Vector3(4f, 0.6f, 3f)).Build();
        WalkWorld world = WalkWorld.Create(level, "spider");
        RoadmapNode from = world.Stance(new Vector3(0.1f, 0f, 1.4f), 0, new Vector3(0.6f, 0f, -0.8f));
        RoadmapNode to = world.Stance(new Vector3(0.55f, 0f, 0.83f), 1, new Vector3(0.95f, 0f, 0.31f));
        JumpAnimation animation = world.Animator.Animate([world.Walk(from, to)]);
        AnimatorEye.Look look = Seen(world, animation);
        Assert.That(animation.ContactPhases.Where(p => p.Position.Y > 0.1f).Select(p => $"{world.Model.Limbs[p.Limb].Name} at {p.From:0.00} s, {p.Position.Y:0.00} m up"), Is.Empty, "every foothold is on the floor");
        Assert.That(look.Soles.Passes, Is.True, look.Soles.ToString());
    }

    private static AnimatorEye.Look Seen(WalkWorld world, JumpAnimation animation)
    {
        Assert.That(animation.Problems.Select(p => p.Reason), Is.Empty);
        AnimatorEye.Look look = AnimatorEye.Read(AnimatedGlbWriter.ToBytes(animation), world.Model).Measure(animation, world.Scene);
        TestContext.Out.WriteLine($"{look.Upright}; {look.Bob}; {look.Cadence}; {look.ArmSwing}");
        return look;
    }

    /// <summary>
    /// A walk that bends 22° (the heading turning over half a metre, as the walk's path turns) keeps the cadence of
    /// the straight: no interval between foot placements while it cruises is under 0.8 of their median, and biped
    /// cadence stays at most <see cref="AnimatorEye.MostCadence"/>. Before, the half-cycles were cut to 20° of turn
    /// each (<see cref="WalkGait.MaxTurn"/>, the limit of a turn in place) and the user's human rig stepped 0.29 s
    /// apart at the bend, 0.43–0.52 s on the straight, 2.64 steps a second through a doorway.
    /// </summary>
    [TestCase("human")]
    [TestCase("skeleton")]
    public void AWalkRoundingABendKeepsTheCadenceOfTheStraight(string character)
    {
        Level level = new LevelBuilder("flat").AddFloor(-8f, -8f, 8f, 8f, 0f).Build();
        WalkWorld world = WalkWorld.Create(level, character);
        Vector3 bend = new(3f * MathF.Cos(22f * MathF.PI / 180f), 0f, -3f * MathF.Sin(22f * MathF.PI / 180f));
        RoadmapNode from = world.Stance(new Vector3(-3f, 0f, 0f), 0, Vector3.UnitX);
        RoadmapNode to = world.Stance(bend, 1, Vector3.Normalize(bend));
        Vector3[] path = [.. world.GroundPath(WalkWorld.Centre(from), Vector3.Zero), .. world.GroundPath(Vector3.Zero, WalkWorld.Centre(to)).Skip(1)];
        var walk = new Walk(from, to, path, world.Scene.Character.Walking.Speed, turnRate: world.Scene.Character.Walking.TurnRate);
        JumpAnimation animation = world.Animator.Animate([walk]);
        Assert.That(animation.Problems, Is.Empty, string.Join("; ", animation.Problems.Select(p => p.Reason)));

        float cruiseFrom = walk.StartTurn + Walk.RampTime;
        float cruiseTo = walk.StartTurn + walk.WalkTime - Walk.RampTime;
        float[] placed = [.. animation.ContactPhases
            .Where(p => !p.OnBall && world.Model.Limbs[p.Limb].Kind == LimbKind.Foot && p.From >= cruiseFrom && p.From <= cruiseTo)
            .Select(p => p.From).Order()];
        float[] intervals = [.. placed.Skip(1).Zip(placed, (b, a) => b - a)];
        Assume.That(intervals, Has.Length.GreaterThanOrEqualTo(3), "the walk cruises over several steps");
        float median = intervals.Order().ElementAt(intervals.Length / 2);
        float cadence = intervals.Length / (placed[^1] - placed[0]);
        TestContext.Out.WriteLine($"{character}: placements {string.Join(", ", placed.Select(t => t.ToString("0.00")))}; {cadence:0.00} steps per second");
        Assert.That(intervals.Min(), Is.GreaterThanOrEqualTo(0.8f * median), $"intervals {string.Join(", ", intervals.Select(i => i.ToString("0.00")))} s");
        Assert.That(cadence, Is.LessThanOrEqualTo(AnimatorEye.MostCadence));
    }
}
