using System.Numerics;
using Ballistic.Authoring.Animation;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Tests.Support;
using SharpGLTF.Schema2;

namespace Ballistic.Planner.Tests.Animation;

[Category("EndToEnd")]
public sealed class JumpAnimatorTests
{
    private static readonly Lazy<(PlanningScene Scene, PlanResult Plan, JumpAnimation Animation)> Desert = new(() =>
    {
        Level level = SharedLevels.Bundled("desert");
        var scene = PlanningScene.Create(level, CharacterPresets.Skeleton());
        Vector3 from = LevelPoints.Ground(scene.Bvh, -9.5f, -7.5f)!.Value;
        Vector3 to = LevelPoints.Ground(scene.Bvh, 9.5f, 7.5f)!.Value;
        var planner = new AnimatedPlanner(scene, new JumpAnimator(scene, CharacterPresets.Model("skeleton")));
        (AnimatedPlan plan, _) = planner.BakeAndPlan(from, to, new BakeSettings { MaxNodes = 600, Threads = 2, Locomotion = Locomotion.Jump }); // the jump animation: jumps only
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        return (scene, plan.Result, plan.Animation!);
    });

    [Test]
    public void StanceEffectorsHoldTheirContactPointsWithinACentimetre()
    {
        (PlanningScene scene, _, JumpAnimation animation) = Desert.Value;
        CharacterModel model = animation.Model;
        var positions = new Vector3[model.Rig.Joints.Count];
        var rotations = new Quaternion[model.Rig.Joints.Count];
        Assert.That(animation.ContactPhases, Has.Count.GreaterThanOrEqualTo(animation.Arcs.Count), "contacts at takeoff and landing");
        foreach (ContactPhase phase in animation.ContactPhases)
        {
            RigLimb limb = model.Limbs[phase.Limb];
            for (float t = phase.From; t <= phase.To + 1e-6f; t += 1f / 240f)
            {
                animation.Joints(MathF.Min(t, phase.To), positions, rotations);
                Assert.That(Vector3.Distance(phase.Touching(limb, positions, rotations), phase.Position), Is.LessThanOrEqualTo(0.01f), $"{limb.Name} slides at t = {t:0.000} s");
            }

            // The contact lies on the level, and the contact face lies against it.
            Assert.That(DistanceToLevel(scene, phase.Position), Is.LessThanOrEqualTo(0.01f), $"{limb.Name}: contact off the level");
            animation.Joints(phase.From, positions, rotations);
            Vector3 surfaceNormal = SurfaceNormal(scene, phase.Position);
            float angle = MathF.Acos(Math.Clamp(Vector3.Dot(-limb.EffectorNormal(rotations), surfaceNormal), -1f, 1f));
            Assert.That(angle, Is.LessThanOrEqualTo(15f * MathF.PI / 180f), $"{limb.Name}: contact face {angle * 180f / MathF.PI:0}° off the surface");
        }
    }

    [Test]
    public void NoBonePassesThroughTheLevelAndTheRootFollowsTheArcs()
    {
        (PlanningScene scene, PlanResult plan, JumpAnimation animation) = Desert.Value;
        CharacterModel model = animation.Model;
        var collision = new BodyCollision(scene.Bvh, model);
        var positions = new Vector3[model.Rig.Joints.Count];
        var rotations = new Quaternion[model.Rig.Joints.Count];
        Assert.That(animation.CollidingFrames, Is.Zero);
        Assert.That(animation.Duration, Is.EqualTo(animation.LeadIn + plan.TotalFlightTime + animation.Stances.Sum() + animation.LeadOut).Within(1e-3f));
        Assert.That(animation.Problems, Is.Empty);
        foreach (AnimationFrame frame in animation.Frames)
        {
            RootPose expected = animation.RootAt(frame.Time);
            Assert.That(Vector3.Distance(frame.Root.Position, expected.Position), Is.LessThan(1e-4f), $"root off the arc at {frame.Time:0.000} s");
            model.Rig.Solve(frame.Root, frame.Angles, positions, rotations);
            Assert.That(model.Rig.WithinLimits(frame.Angles), Is.True, $"joint limits at {frame.Time:0.000} s");
            for (int l = 0; l < model.Limbs.Count; l++)
            {
                Vector3? held = null;
                foreach (ContactPhase p in animation.ContactPhases)
                {
                    if (p.Limb == l && frame.Time >= p.From - 1e-4f && frame.Time <= p.To + 1e-4f)
                    {
                        held = p.Position;
                    }
                }

                Assert.That(collision.LimbCollides(model.Limbs[l], positions, rotations, held), Is.False, $"{model.Limbs[l].Name} through the level at {frame.Time:0.000} s");
            }
        }
    }

    [Test]
    public void ExportedGlbReloadsToTheSamePoses()
    {
        JumpAnimation animation = Desert.Value.Animation;
        byte[] glb = AnimatedGlbWriter.ToBytes(animation, "desert");
        ModelRoot document = ModelRoot.ParseGLB(glb);
        IReadOnlyList<Node> nodes = document.LogicalNodes;
        Assert.That(document.LogicalAnimations[0].Name, Is.EqualTo("desert"));
        Assert.That(document.LogicalSkins, Has.Count.EqualTo(1));

        // Local transforms per node at each key: the rest transform, overridden by the clip's channels.
        var channels = GlbChannels.Of(document.LogicalAnimations[0]);
        var keyed = channels.ToDictionary(c => c.Key, c => c.Value.Values);
        float[] times = channels.Values.First().Times;
        Assert.That(channels.Values.Select(c => c.Times), Has.All.EqualTo(times), "every channel keyed at the same times");

        Rig rig = animation.Model.Rig;
        var expected = new Vector3[rig.Joints.Count];
        var expectedRotations = new Quaternion[rig.Joints.Count];
        Assert.That(times, Has.Length.EqualTo(animation.Frames.Count));
        for (int f = 0; f < times.Length; f += 7)
        {
            AnimationFrame frame = animation.Frames[f];
            Assert.That(times[f], Is.EqualTo(frame.Time).Within(1e-6f));
            rig.Solve(frame.Root, frame.Angles, expected, expectedRotations);
            var world = new Matrix4x4[nodes.Count];
            for (int n = 0; n < rig.Joints.Count + 1; n++)
            {
                Vector3 t = nodes[n].LocalTransform.Translation;
                Quaternion r = nodes[n].LocalTransform.Rotation;
                if (keyed.TryGetValue((n, "translation"), out float[]? tk))
                {
                    t = new Vector3(tk[3 * f], tk[(3 * f) + 1], tk[(3 * f) + 2]);
                }

                if (keyed.TryGetValue((n, "rotation"), out float[]? rk))
                {
                    r = new Quaternion(rk[4 * f], rk[(4 * f) + 1], rk[(4 * f) + 2], rk[(4 * f) + 3]);
                }

                Matrix4x4 local = Matrix4x4.CreateFromQuaternion(r) * Matrix4x4.CreateTranslation(t);
                int parent = n == 0 ? -1 : rig.Joints[n - 1].Parent + 1;
                world[n] = parent < 0 ? local : local * world[parent];
                if (n > 0)
                {
                    Assert.That(Vector3.Distance(world[n].Translation, expected[n - 1]), Is.LessThan(1e-3f), $"joint {rig.Joints[n - 1].Name} at frame {f}");
                }
            }
        }
    }

    [TestCase("pond", "frog", -0.5f, -5.8f, 0.5f, 4.6f)]
    [TestCase("gap-course", "ant", -6f, 0f, 11.5f, 0f)]
    [TestCase("rooftops", "jumperman", -130f, -70f, 96f, 41f)]
    public void EveryCharacterAnimatesOnItsLevel(string levelName, string characterName, float x0, float z0, float x1, float z1)
    {
        (_, _, AnimatedPlan plan) = BundledPlans.Plan(levelName, characterName, x0, z0, x1, z1);
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        CharacterModel model = CharacterPresets.Model(characterName);
        JumpAnimation animation = plan.Animation!;
        var positions = new Vector3[model.Rig.Joints.Count];
        var rotations = new Quaternion[model.Rig.Joints.Count];
        Assert.Multiple(() =>
        {
            Assert.That(animation.Problems, Is.Empty, "a clean animation");
            Assert.That(animation.CollidingFrames, Is.Zero, "no limb through the level");
            Assert.That(animation.FailedContactPoses, Is.Zero, "contact poses pass the no-slip test");
            Assert.That(animation.ContactPhases, Is.Not.Empty);
        });
        foreach (ContactPhase phase in animation.ContactPhases)
        {
            for (float t = phase.From; t <= phase.To + 1e-6f; t += 1f / 240f)
            {
                animation.Joints(MathF.Min(t, phase.To), positions, rotations);
                Assert.That(Vector3.Distance(phase.Touching(model.Limbs[phase.Limb], positions, rotations), phase.Position), Is.LessThanOrEqualTo(0.01f), $"{characterName} {model.Limbs[phase.Limb].Name} slides at {t:0.000} s");
            }
        }
    }

    [Test]
    public void ContactGenerationSucceedsAlmostAlways()
    {
        JumpAnimation animation = Desert.Value.Animation;
        int poses = 2 * animation.Arcs.Count;
        Assert.That(animation.FailedContactPoses, Is.LessThanOrEqualTo(poses / 10), $"{animation.FailedContactPoses} of {poses} contact poses failed");
    }

    private static float DistanceToLevel(PlanningScene scene, Vector3 p)
    {
        var near = new List<int>();
        scene.Bvh.TrianglesNear(new Aabb(p - new Vector3(0.05f), p + new Vector3(0.05f)), near);
        return near.Count == 0 ? float.PositiveInfinity : near.Min(t => Vector3.Distance(scene.Level.Triangles[t].ClosestPoint(p), p));
    }

    private static Vector3 SurfaceNormal(PlanningScene scene, Vector3 p)
    {
        var near = new List<int>();
        scene.Bvh.TrianglesNear(new Aabb(p - new Vector3(0.05f), p + new Vector3(0.05f)), near);
        int best = near.MinBy(t => Vector3.Distance(scene.Level.Triangles[t].ClosestPoint(p), p));
        return scene.Level.Triangles[best].Normal;
    }
}
