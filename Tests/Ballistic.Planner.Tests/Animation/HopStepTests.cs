using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Animation;

/// <summary>
/// A spider's low hops across open floor, animated by hand (<see cref="WalkWorld"/>): its long legs hold their takeoff
/// contacts until the apex (or take their landing contacts before it), so their whole time in the air lies on one side
/// of the apex. Such a leg now steps across from the one contact to the other on a lifted curve, as a walking foot
/// swings. Before, its angles were interpolated straight from the one held pose to the other, and the foot swept
/// through the floor between them: the hop was reported ("r1 passes through the level in flight (0.284 s after
/// takeoff) whatever pose it takes") and the planner set it aside; jumping only from (−1.7, 0.7) up onto a platform it
/// set aside 7 jumps, now 3.
/// </summary>
[Category("EndToEnd")]
public sealed class HopStepTests
{
    private static readonly Lazy<WalkWorld> Platform = new(() => WalkWorld.Create(
        new LevelBuilder("platform").AddFloor(-4f, -3f, 4f, 3f, 0f).AddBox(new Vector3(1f, 0f, -3f), new Vector3(4f, 0.6f, 3f)).Build(), "spider"));

    /// <summary>A stance at a root pose (yaw in degrees about +Y, 0 facing +Z), its contacts estimated there.</summary>
    private static RoadmapNode Node(WalkWorld world, int id, Vector3 position, float yaw)
    {
        PoseEvaluation pose = world.Scene.Estimator.Evaluate(new RootPose(position, Quaternion.CreateFromAxisAngle(Vector3.UnitY, yaw * MathF.PI / 180f)));
        Assert.That(pose.IsValid, Is.True, $"the spider stands at {position}: {pose.Validity}");
        return new RoadmapNode(id, pose.Pose, pose.Cone, pose.Contacts);
    }

    /// <summary>
    /// Hops the facer placed for the spider on the platform level's floor, jumping only from (−1.7, 0.7) to (1.7, 1.8)
    /// (root poses as the plan had them: position, yaw in degrees about +Y from +Z), steered as the planner steers them:
    /// each animates cleanly, and every foot in the air between two contacts on one side of the apex is lifted clear of
    /// the floor between them, its effector never below the floor and at its highest at least 1 cm above it (a third of
    /// the step on a step shorter than 3 cm).
    /// </summary>
    [TestCase(-0.88f, 0.27f, 0.84f, 88f, -0.72f, 0.27f, 0.90f, 65f)]
    [TestCase(0.17f, 0.26f, -0.39f, 84f, 0.41f, 0.26f, -0.26f, 62f)]
    [TestCase(-1.57f, 0.34f, -0.38f, 172f, -1.40f, 0.34f, -0.51f, 84f)]
    public void ALowHopsLegsStepAcrossClearOfTheFloor(float x0, float y0, float z0, float yaw0, float x1, float y1, float z1, float yaw1)
    {
        WalkWorld world = Platform.Value;
        RoadmapNode from = Node(world, 0, new Vector3(x0, y0, z0), yaw0);
        RoadmapNode to = Node(world, 1, new Vector3(x1, y1, z1), yaw1);
        SteeringResult steered = world.Scene.Steering.SteerSteep(from.Pose, from.Cone, to.Pose, to.Cone);
        Assert.That(steered.Succeeded, Is.True, steered.Failure.ToString());
        var hop = new Jump(from, to, steered.Arc);
        TestContext.Out.WriteLine($"hop {Vector3.Distance(from.Pose.Position, to.Pose.Position):0.00} m, {hop.Arc.FlightTime:0.000} s, up at {hop.Arc.TakeoffVelocity.Y:0.00} m/s");
        JumpAnimation animation = world.Animator.Animate([hop]);
        Assert.That(animation.Problems.Select(p => p.Reason), Is.Empty, "the hop animates cleanly");

        CharacterModel model = animation.Model;
        var positions = new Vector3[model.Rig.Joints.Count];
        var rotations = new Quaternion[model.Rig.Joints.Count];
        float takeoff = animation.MoveStart(0);
        float landing = animation.MoveEnd(0);
        int across = 0;
        foreach (IGrouping<int, ContactPhase> phases in animation.ContactPhases.GroupBy(p => p.Limb))
        {
            ContactPhase[] ordered = [.. phases.OrderBy(p => p.From)];
            for (int k = 1; k < ordered.Length; k++)
            {
                (ContactPhase before, ContactPhase after) = (ordered[k - 1], ordered[k]);
                bool intoFlight = before.To > takeoff + 0.01f || after.From < landing - 0.01f;
                if (before.To < takeoff - 1e-3f || after.From > landing + 1e-3f || !intoFlight || Vector3.Distance(before.Position, after.Position) <= 0.02f)
                {
                    continue;
                }

                // Holding its takeoff contact into the flight, or taking its landing contact before the flight ends: a
                // leg stepping across.
                across++;
                RigLimb limb = model.Limbs[ordered[k].Limb];
                float lowest = float.PositiveInfinity;
                float highest = float.NegativeInfinity;
                for (float t = before.To; t <= after.From; t += 1f / 240f)
                {
                    animation.Joints(t, positions, rotations);
                    float y = limb.EffectorPosition(positions, rotations).Y;
                    (lowest, highest) = (MathF.Min(lowest, y), MathF.Max(highest, y));
                }

                // While it holds a contact in the air, it turns no faster than a landing folds a knee.
                float fastest = 0f;
                foreach (ContactPhase held in (ContactPhase[])[before, after])
                {
                    AnimationFrame[] frames = [.. animation.Frames.Where(f => f.Time >= MathF.Max(held.From, takeoff) - 1e-5f && f.Time <= MathF.Min(held.To, landing) + 1e-5f)];
                    for (int f = 1; f < frames.Length; f++)
                    {
                        foreach (int d in limb.ChainDofSpan)
                        {
                            fastest = MathF.Max(fastest, MathF.Abs(frames[f].Angles[d] - frames[f - 1].Angles[d]) / (frames[f].Time - frames[f - 1].Time));
                        }
                    }
                }

                Assert.Multiple(() =>
                {
                    Assert.That(fastest, Is.LessThanOrEqualTo(JumpAnimator.MostHeldTurnRate * 1.001f), $"{limb.Name} turns {fastest * 180f / MathF.PI:0}°/s holding a contact in the air");
                    Assert.That(lowest, Is.GreaterThanOrEqualTo(-0.002f), $"{limb.Name}'s effector stays on or above the floor from {before.To:0.000} to {after.From:0.000} s");
                    Assert.That(highest, Is.GreaterThanOrEqualTo(MathF.Min(0.01f, Vector3.Distance(before.Position, after.Position) / 3f)), $"{limb.Name} is lifted as it steps across");
                });
            }
        }

        Assert.That(across, Is.GreaterThan(0), "some leg holds its contact into the flight and steps across to its landing");
    }

    /// <summary>
    /// A leg stepping across a jump arrives in the landing's own pose: the ant crossing the curved terrain (a level in
    /// other tools' shape, the sweep's first request there) holds its left foreleg's takeoff contact to the apex of its
    /// sixth jump and steps it across to the landing contact. The IK along the lifted curve, each solve from the step
    /// before, ended on another solution holding the same point, and the leg took the landing's pose in the frame of
    /// landing (its tarsus 38.5°, its last joint 38.6°); each solve is now drawn toward the landing's angles as the step
    /// ends, and in the last displayed frame (1/60 s) before it takes hold no joint of the leg turns more than a
    /// snap's 15°.
    /// </summary>
    [Test]
    public void AnAntsForelegSteppingAcrossArrivesInItsLandingPose()
    {
        (Level level, (Vector3 From, Vector3 To)[] requests) = ForeignLevels.Get("curved");
        Sweep.Planned planned = Sweep.Plan(Sweep.Prepare("curved", level, "ant"), requests[0].From, requests[0].To);
        Assert.That(planned.Report.FullyRight, Is.True, planned.Report.ToString());
        JumpAnimation animation = planned.Plan.Animation!;
        CharacterModel model = animation.Model;
        Assert.That(animation.Arcs, Has.Count.GreaterThan(5));
        float landing = animation.JumpStart(5) + animation.Arcs[5].FlightTime;
        int foreleg = model.Limbs.ToList().FindIndex(l => l.Name == "left_front");
        ContactPhase taken = animation.ContactPhases.Single(p => p.Limb == foreleg && MathF.Abs(p.From - landing) < 2e-3f);
        ContactPhase left = animation.ContactPhases.Where(p => p.Limb == foreleg && p.To < taken.From).MaxBy(p => p.To);
        Assert.That(left.To, Is.GreaterThan(animation.JumpStart(5) + 0.1f), "the foreleg holds its takeoff contact into the flight: it steps across");

        (_, float[] arriving) = animation.Sample(taken.From - (1f / AnimatorEye.DisplayRate));
        (_, float[] holding) = animation.Sample(taken.From);
        float turn = model.Limbs[foreleg].Chain.Max(j => model.Rig.JointTurn(j, arriving, holding)) * 180f / MathF.PI;
        Assert.That(turn, Is.LessThanOrEqualTo(AnimatorEye.LeastSnap), $"the foreleg turns {turn:0.0}° in the frame before it takes hold at {taken.From:0.000} s");
    }
}
