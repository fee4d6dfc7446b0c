using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;

namespace Ballistic.Planner.Tests.Rigs;

/// <summary>
/// A walking foot left behind the trunk farther than its sole can lie flat rolls onto its ball, heel up
/// (<see cref="SoleHold.Hold"/> with roll), as a walker's trailing foot peels off before it swings.
/// </summary>
public sealed class RollingFootTests
{
    [Test]
    public void AFootTooFarBehindToLieFlatRollsOntoItsBallWhereItStood()
    {
        CharacterModel model = CharacterPresets.Model("skeleton");
        Rig rig = model.Rig;
        RigLimb foot = model.Limbs.Single(l => l.Name == "left_foot");
        var hold = new SoleHold(rig);
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];

        // The foot stands where the contact pose puts it, on ground level with it; the trunk moves ahead (+Z) over it.
        var stand = new RootPose(Vector3.Zero, Quaternion.Identity);
        rig.Solve(stand, model.ContactPose, positions, rotations);
        Vector3 point = foot.EffectorPosition(positions, rotations);
        int toe = Enumerable.Range(0, rig.Joints.Count).Single(j => rig.Joints[j].Parent == foot.EffectorJoint);
        Vector3 ballLocal = rig.Joints[toe].Offset - (Vector3.Dot(rig.Joints[toe].Offset - foot.EffectorOffset, foot.ContactNormal) * foot.ContactNormal);
        Vector3 flatBall = positions[foot.EffectorJoint] + Vector3.Transform(ballLocal, rotations[foot.EffectorJoint]);

        // The farthest ahead the trunk goes with the sole flat (or tilted within the IK's 15°), by 1 cm.
        float[] q = (float[])model.ContactPose.Clone();
        float ahead = 0f;
        for (float z = 0.01f; z < 1f; z += 0.01f)
        {
            float[] trial = (float[])q.Clone();
            if (!hold.Hold(new RootPose(new Vector3(0f, 0f, z), Quaternion.Identity), trial, foot, point, Vector3.UnitY))
            {
                break;
            }

            (q, ahead) = (trial, z);
        }

        // 4 cm farther the flat foot cannot hold; rolled onto its ball, it can.
        var past = new RootPose(new Vector3(0f, 0f, ahead + 0.04f), Quaternion.Identity);
        float[] flat = (float[])q.Clone();
        float[] rolled = (float[])q.Clone();
        Assert.That(hold.Hold(past, flat, foot, point, Vector3.UnitY), Is.False, $"the sole lies flat only up to {ahead:0.00} m");
        Assert.That(hold.Hold(past, rolled, foot, point, Vector3.UnitY, p => p with { Y = point.Y }), Is.True, "rolled onto its ball");

        // In a hollow (the level 6 mm below the ground's plane at the held point where the ball comes down, as on a
        // dune), the ball goes down onto the level, not onto the plane: without that the skeleton's sole floated.
        float[] hollow = (float[])q.Clone();
        Assert.That(hold.Hold(past, hollow, foot, point, Vector3.UnitY, p => p with { Y = point.Y - 0.006f }), Is.True, "rolled onto its ball in a hollow");
        rig.Solve(past, hollow, positions, rotations);
        float ballY = (positions[foot.EffectorJoint] + Vector3.Transform(ballLocal, rotations[foot.EffectorJoint])).Y;
        Assert.That(ballY - (point.Y - 0.006f), Is.EqualTo(0f).Within(0.0015f), "the ball rests on the level in the hollow");

        rig.Solve(past, rolled, positions, rotations);
        Vector3 ball = positions[foot.EffectorJoint] + Vector3.Transform(ballLocal, rotations[foot.EffectorJoint]);
        Vector3 sole = foot.EffectorNormal(rotations);
        float tilt = MathF.Acos(Math.Clamp(Vector3.Dot(sole, -Vector3.UnitY), -1f, 1f));
        TestContext.Out.WriteLine($"flat up to {ahead:0.00} m; rolled: ball moved {Vector3.Distance(ball, flatBall) * 1000f:0.0} mm, heel up {tilt * 180f / MathF.PI:0.0}°, sole centre {(foot.EffectorPosition(positions, rotations).Y - point.Y) * 100f:0.0} cm up");
        Assert.Multiple(() =>
        {
            Assert.That(Vector3.Distance(ball, flatBall), Is.LessThan(0.003f), "the ball stays where it stood flat: the foot does not slide");
            Assert.That(foot.EffectorPosition(positions, rotations).Y - point.Y, Is.GreaterThan(0.005f), "the heel rises off the ground");
            Assert.That(sole.Z, Is.LessThan(0f), "the sole faces back: heel up, toes down");
            Assert.That(tilt, Is.LessThanOrEqualTo(SoleHold.MostRoll + (2f * MathF.PI / 180f)), "no more than the most roll");
        });
    }
}
