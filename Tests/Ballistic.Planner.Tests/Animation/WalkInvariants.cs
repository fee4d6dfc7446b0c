using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Tests.Animation;

/// <summary>
/// What an independent checker asserts of the walks in an animation, from the promises alone: the root on the walk,
/// held feet on the ground and not sliding, no foot under the ground, no bone in the level, feet alternating.
/// </summary>
internal static class WalkInvariants
{
    /// <summary>Sampling rate of the checks, Hz.</summary>
    public const float Rate = 240f;

    /// <summary>A contact counts as held this long (seconds) before and after its phase, as in the plan audit.</summary>
    public const float Tolerance = 1e-4f;

    /// <summary>Largest distance (metres) of a held foot from its contact point, and of a contact point from the ground.</summary>
    public const float Slip = 0.01f;

    /// <summary>Checks every walk of <paramref name="animation"/>; returns the least number of feet seen holding at once and each foot's phase count over the walks.</summary>
    public static (int LeastHolding, int[] PhasesPerFoot) Check(WalkWorld world, JumpAnimation animation)
    {
        CharacterModel model = animation.Model;
        Rig rig = model.Rig;
        var collision = new BodyCollision(world.Scene.Bvh, model);
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        int[] feet = [.. Enumerable.Range(0, model.Limbs.Count).Where(l => model.Limbs[l].Kind == LimbKind.Foot)];
        int least = int.MaxValue;
        int[] phaseCounts = new int[model.Limbs.Count];
        Assert.That(animation.Problems.Select(p => $"move {p.Jump}: {p.Reason}"), Is.Empty, "a clean animation");
        Assert.That(animation.CollidingFrames, Is.Zero);
        for (int m = 0; m < animation.Moves.Count; m++)
        {
            if (animation.Moves[m] is not Walk walk)
            {
                continue;
            }

            float t0 = animation.MoveStart(m);
            float t1 = animation.MoveEnd(m);
            Assert.That(t1 - t0, Is.EqualTo(walk.Duration).Within(1e-4f));

            // The root is the walk's at every frame, raised straight up by the upright walk's lift (lowered only by the
            // dip as the feet change over where it is not lifted: WalkGait.LeastBob of the rest leg at most), which the
            // clip's root gives between frames too.
            float dip = WalkGait.LeastBob * StanceDip.RestLegLength(model);
            foreach (AnimationFrame frame in animation.Frames.Where(f => f.Time >= t0 && f.Time <= t1))
            {
                RootPose expected = walk.PoseAt(frame.Time - t0);
                Vector3 off = frame.Root.Position - expected.Position;
                Assert.That(new Vector2(off.X, off.Z).Length(), Is.LessThan(1e-4f), $"root off the walk at {frame.Time:0.000} s");
                Assert.That(off.Y, Is.GreaterThan(-dip - 1e-4f), $"root below the walk at {frame.Time:0.000} s");
                Assert.That(animation.WalkLift(frame.Time), Is.EqualTo(off.Y).Within(1e-4f), $"the clip's lift at {frame.Time:0.000} s");
                Assert.That(MathF.Abs(Quaternion.Dot(frame.Root.Rotation, expected.Rotation)), Is.GreaterThan(1f - 1e-5f), $"root turned off the walk at {frame.Time:0.000} s");
                Assert.That(Vector3.Distance(animation.RootAt(frame.Time).Position, frame.Root.Position), Is.LessThan(1e-4f));
            }

            // Held feet: on the ground, and not sliding; every foot's phases during the walk counted.
            ContactPhase[] during = [.. animation.ContactPhases.Where(p => p.To >= t0 && p.From <= t1)];
            foreach (ContactPhase phase in during)
            {
                Vector3? ground = world.Ground(phase.Position.X, phase.Position.Z, phase.Position.Y + 0.3f);
                Assert.That(ground, Is.Not.Null, $"{model.Limbs[phase.Limb].Name} holds a point above no ground");
                Assert.That(MathF.Abs(ground!.Value.Y - phase.Position.Y), Is.LessThanOrEqualTo(0.02f), $"{model.Limbs[phase.Limb].Name} holds a point off the ground at {phase.From:0.000} s");
                phaseCounts[phase.Limb]++;
            }

            int samples = (int)MathF.Ceiling((t1 - t0) * Rate);
            for (int k = 0; k <= samples; k++)
            {
                float t = MathF.Min(t1, t0 + (k / Rate));
                animation.Joints(t, positions, rotations);
                int holding = 0;
                var held = new Vector3?[model.Limbs.Count];
                foreach (ContactPhase phase in during)
                {
                    if (t >= phase.From - Tolerance && t <= phase.To + Tolerance)
                    {
                        float slip = Vector3.Distance(phase.Touching(model.Limbs[phase.Limb], positions, rotations), phase.Position);
                        Assert.That(slip, Is.LessThanOrEqualTo(Slip), $"{model.Limbs[phase.Limb].Name} slides {slip * 100f:0.0} cm at {t:0.000} s (held {phase.From:0.000}–{phase.To:0.000} s{(phase.OnBall ? ", on its ball" : "")})");
                        // Where a foot's phase on its sole ends as one on its ball begins (both within the tolerance),
                        // it stands on its sole: that point is the one its bones may touch the ground at.
                        holding += model.Limbs[phase.Limb].Kind == LimbKind.Foot && held[phase.Limb] is null ? 1 : 0;
                        held[phase.Limb] = held[phase.Limb] is not null && phase.OnBall ? held[phase.Limb] : phase.Position;
                    }
                }

                // Over the first frame of a roll the heel is still lifting off the sole's point: its bones may touch the
                // ground there too.
                foreach (ContactPhase phase in during)
                {
                    if (!phase.OnBall && t > phase.To && t <= phase.To + (1f / 60f) && held[phase.Limb] is not null
                        && during.Any(b => b.Limb == phase.Limb && b.OnBall && MathF.Abs(b.From - phase.To) <= Tolerance && t >= b.From && t <= b.To))
                    {
                        held[phase.Limb] = phase.Position;
                    }
                }

                least = Math.Min(least, holding);
                foreach (int l in feet)
                {
                    Vector3 p = model.Limbs[l].EffectorPosition(positions, rotations);
                    Vector3? ground = world.Ground(p.X, p.Z, p.Y + 0.3f);
                    Assert.That(ground is null || p.Y >= ground.Value.Y - Slip, Is.True, $"{model.Limbs[l].Name} {(ground!.Value.Y - p.Y) * 100f:0.0} cm under the ground at {t:0.000} s");
                }

                for (int l = 0; l < model.Limbs.Count; l++)
                {
                    Assert.That(collision.LimbCollides(model.Limbs[l], positions, rotations, held[l]), Is.False, $"{model.Limbs[l].Name} in the level at {t:0.000} s, its effector at {model.Limbs[l].EffectorPosition(positions, rotations)}, phases about then {string.Join(" ", during.Where(p => p.Limb == l && p.To >= t - 0.1f && p.From <= t + 0.1f))}");
                }

                Assert.That(collision.OtherBoneColliding(positions), Is.EqualTo(-1), $"a bone of no limb in the level at {t:0.000} s");
            }
        }

        return (least, [.. feet.Select(l => phaseCounts[l])]);
    }

    /// <summary>The largest change of any angle between consecutive frames divided by their time apart (radians per second), and where.</summary>
    public static (float Speed, float Time, string Dof) FastestAngle(JumpAnimation animation)
    {
        (float Speed, float Time, string Dof) fastest = (0f, 0f, "");
        for (int f = 1; f < animation.Frames.Count; f++)
        {
            AnimationFrame a = animation.Frames[f - 1];
            AnimationFrame b = animation.Frames[f];
            float dt = MathF.Max(b.Time - a.Time, 1e-4f);
            for (int d = 0; d < a.Angles.Length; d++)
            {
                float speed = MathF.Abs(b.Angles[d] - a.Angles[d]) / dt;
                if (speed > fastest.Speed)
                {
                    fastest = (speed, b.Time, animation.Model.Rig.Joints[animation.Model.Rig.JointOfDof(d)].Name);
                }
            }
        }

        return fastest;
    }
}
