using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Animation;

/// <summary>
/// A tail (any bone that carries no limb and hangs from none) is bent out of the level instead of through it: a
/// limbs-only spec gets free bends for it, its skinned tip is seen past its last joint, and the clearance bends it as
/// little as clears, smoothly, leaving limbs and trunk alone.
/// </summary>
public sealed class FreeBonesTests
{
    private static readonly Lazy<CharacterModel> Tailed = new(() =>
    {
        string folder = Path.Combine(Path.GetTempPath(), $"ballistic-free-{Guid.NewGuid():N}");
        try
        {
            (CharacterModel model, _) = ForeignCharacters.Named("tailed").Load(folder);
            return model;
        }
        finally
        {
            if (Directory.Exists(folder))
            {
                Directory.Delete(folder, recursive: true);
            }
        }
    });

    private static (Vector3[] Positions, Quaternion[] Rotations) Solve(CharacterModel model, RootPose root, float[] q)
    {
        var positions = new Vector3[model.Rig.Joints.Count];
        var rotations = new Quaternion[model.Rig.Joints.Count];
        model.Rig.Solve(root, q, positions, rotations);
        return (positions, rotations);
    }

    [Test]
    public void ALimbsOnlySpecBendsItsTailButNotItsTrunk()
    {
        Rig rig = Tailed.Value.Rig;
        Assert.Multiple(() =>
        {
            foreach (string tail in (string[])["tail_root", "tail_1", "tail_2"])
            {
                Assert.That(rig.DofsOf(rig.IndexOf(tail)), Is.EqualTo(2), $"{tail} bends and turns");
            }

            Assert.That(rig.DofsOf(rig.IndexOf("hips")), Is.Zero, "the trunk the legs hang from stays as the spec says");
            Assert.That(rig.DofsOf(rig.IndexOf("chest")), Is.Zero);
        });
    }

    [Test]
    public void ATailsSkinnedTipIsSeenPastItsLastJoint()
    {
        CharacterModel model = Tailed.Value;
        (Vector3[] positions, Quaternion[] rotations) = Solve(model, new RootPose(Vector3.Zero, Quaternion.Identity), model.ContactPose);
        int tip = model.Rig.IndexOf("tail_2");
        float lastJoint = model.Rig.Joints.Select((_, j) => positions[j].Z).Min();
        Assume.That(positions[tip].Z, Is.EqualTo(lastJoint).Within(1e-4f), "the tail's last joint is the body's hindmost");

        // A wall 13 cm behind the last joint, inside the tail's skinned tip (which reaches 20 cm past it).
        Level wall = new LevelBuilder("wall").AddBox(new Vector3(-5f, -5f, lastJoint - 1f), new Vector3(5f, 5f, lastJoint - 0.13f)).Build();
        var bvh = new TriangleBvh(wall.Triangles);
        Assert.Multiple(() =>
        {
            Assert.That(new BodyCollision(bvh, model, wall.Triangles).OtherBoneColliding(positions), Is.EqualTo(-1), "no bone's segment reaches the wall");
            Assert.That(new BodyCollision(bvh, model, wall.Triangles).OtherBoneColliding(positions, rotations), Is.EqualTo(tip), "the tip's skin does");
        });
    }

    [Test]
    public void ATailOverAStepBehindBendsOutOfItSmoothlyAndNothingElseMoves()
    {
        CharacterModel model = Tailed.Value;
        Rig rig = model.Rig;
        (Vector3[] rest, _) = Solve(model, new RootPose(Vector3.Zero, Quaternion.Identity), model.ContactPose);
        Vector3 tail1 = rest[rig.IndexOf("tail_1")];

        // A step behind the hind legs, its top just above the tail: the body walks back toward it over a second.
        float hindmostFoot = model.Limbs.Min(l => rest[l.EffectorJoint].Z) - 0.1f;
        Level step = new LevelBuilder("step").AddBox(new Vector3(-1f, -1f, -3f), new Vector3(1f, tail1.Y + 0.01f, tail1.Z)).Build();
        Assume.That(hindmostFoot, Is.GreaterThan(tail1.Z), "the step is clear of the feet");
        var collision = new BodyCollision(new TriangleBvh(step.Triangles), model, step.Triangles);
        int frames = 61;
        float[] times = [.. Enumerable.Range(0, frames).Select(k => k / 60f)];
        RootPose Root(int k) => new(new Vector3(0f, 0f, 1.5f * (1f - times[k])), Quaternion.Identity);
        float[][] angles = [.. Enumerable.Range(0, frames).Select(_ => (float[])model.ContactPose.Clone())];
        int[] hit = [.. Enumerable.Range(0, frames).Where(Colliding)];
        Assume.That(hit, Has.Length.GreaterThan(10), "the tail enters the step");
        Assume.That(hit[0], Is.GreaterThan(30), "the body starts well clear of the step");

        int changed = new FreeBones(model, collision).Clear(times, Root, angles);

        bool Colliding(int k)
        {
            (Vector3[] p, Quaternion[] r) = Solve(model, Root(k), angles[k]);
            return collision.OtherBoneColliding(p, r) >= 0;
        }

        int[] free = [.. Enumerable.Range(0, rig.DofCount).Where(d => rig.Joints[rig.JointOfDof(d)].Name.StartsWith("tail", StringComparison.Ordinal))];
        float largestJump = Enumerable.Range(1, frames - 1).Max(k => free.Max(d => MathF.Abs(angles[k][d] - angles[k - 1][d])));
        int firstBent = Enumerable.Range(0, frames).First(k => free.Any(d => angles[k][d] != model.ContactPose[d]));
        Assert.Multiple(() =>
        {
            Assert.That(changed, Is.GreaterThanOrEqualTo(hit.Length));
            Assert.That(Enumerable.Range(0, frames).Where(Colliding), Is.Empty, "no frame has the tail in the step");
            Assert.That(Enumerable.Range(0, frames).All(k => Enumerable.Range(0, rig.DofCount).Except(free).All(d => angles[k][d] == model.ContactPose[d])), Is.True, "limbs and trunk untouched");
            Assert.That(angles[0], Is.EqualTo(model.ContactPose), "a frame far from the step is not bent");
            Assert.That(largestJump * 180f / MathF.PI, Is.LessThan(10f), "the bend rises smoothly, not in one frame");
            Assert.That(times[hit[0]] - times[firstBent], Is.GreaterThan(0.5f * FreeBones.Ramp), "the bend starts before the frames that need it");
        });
    }
}
