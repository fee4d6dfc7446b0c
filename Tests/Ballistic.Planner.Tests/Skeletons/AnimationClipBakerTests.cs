using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;
using Ballistic.Planner.Tests.Runtime;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Paths;
using Ballistic.Runtime.Skeletons;

namespace Ballistic.Planner.Tests.Skeletons;

/// <summary>
/// Baking a planned path's animation into Godot tracks: the thinned tracks, re-sampled, give back the binding's
/// conversion of the animation within the epsilons; the clip lasts as long as the animation; the track paths are
/// "Skeleton3D:bone".
/// </summary>
public sealed class AnimationClipBakerTests
{
    private static readonly Lazy<AgentPath> DesertPath = new(() =>
    {
        (JumpWorld world, var kind) = RuntimeWorlds.Desert();
        using (world)
        {
            (AgentHandle agent, _, _) = RuntimeWorlds.SendAcross(world, kind, seed: 4);
            RuntimeWorlds.Run(world, 600, (w, _) => w.GetPath(agent) is not null);
            return world.GetPath(agent) ?? throw new InvalidOperationException("no path found across the desert");
        }
    });

    /// <summary>A path an agent found across the desert (seeded), shared with the debug drawing tests.</summary>
    internal static AgentPath SampledPath => DesertPath.Value;

    [Test]
    public void ResampledTracksEqualTheAnimationWithinTheEpsilons()
    {
        GodotSkeleton godot = SkeletonBindingTests.BundledSkeleton();
        SkeletonBinding binding = SkeletonBindingTests.Bind(RuntimeWorlds.DesertSkeleton.Model, godot.Skeleton);
        JumpAnimation animation = DesertPath.Value.Animation;
        var global = new BoneTransform(new Vector3(1f, 0f, -2f), Quaternion.CreateFromAxisAngle(Vector3.UnitY, 0.4f), new Vector3(1f));
        var settings = new ClipBakeSettings { FrameRate = 30f, RotationEpsilon = 2e-3f, PositionEpsilon = 1e-3f };
        BakedClip clip = AnimationClipBaker.Bake(animation, binding, global, settings);

        int frames = (int)Math.Ceiling((animation.Duration * 30.0) - 1e-4) + 1;
        Assert.Multiple(() =>
        {
            Assert.That(clip.Length, Is.EqualTo(animation.Duration));
            Assert.That(clip.RotationTracks.Select(t => t.Bone), Is.EqualTo(binding.DrivenBones));
            Assert.That(clip.PositionTracks.Select(t => t.Bone), Is.EqualTo(binding.PositionedBones));
            Assert.That(clip.RotationTracks.Select(t => t.Path), Has.Member("Skeleton3D:pelvis").And.Member("Skeleton3D:left_knee"));
            Assert.That(clip.PositionTracks.Single().Path, Is.EqualTo("Skeleton3D:pelvis"));
            Assert.That(clip.KeyCount, Is.LessThan(frames * (clip.RotationTracks.Count + clip.PositionTracks.Count) * 0.8), "thinned");
            foreach (BoneRotationTrack track in clip.RotationTracks)
            {
                Assert.That(track.Times[0], Is.Zero, track.Path);
                Assert.That(track.Times, Is.Ordered.Ascending.And.Unique, track.Path);
                Assert.That(track.Times.Length == 1 || track.Times[^1] == animation.Duration, Is.True, $"{track.Path} ends on the clip's end");
                Assert.That(track.Times, Has.Length.EqualTo(track.Rotations.Length));
            }
        });

        // Every bake frame, re-sampled from the thinned tracks, against the binding's conversion of the animation.
        float[] angles = new float[animation.Model.Rig.DofCount];
        var rotations = new Quaternion[binding.BoneCount];
        var positions = new Vector3[binding.BoneCount];
        double worstAngle = 0.0;
        double worstDistance = 0.0;
        for (int k = 0; k < frames; k++)
        {
            float t = k == frames - 1 ? animation.Duration : k / 30f;
            RootPose root = animation.Sample(t, angles);
            binding.ConvertAngles(root, angles, global, rotations, positions);
            foreach (BoneRotationTrack track in clip.RotationTracks)
            {
                worstAngle = Math.Max(worstAngle, AnimationClipBaker.Angle(track.Sample(t), rotations[track.Bone])); // accurate for tiny angles, where 2 acos(a·b) in floats is not
            }

            foreach (BonePositionTrack track in clip.PositionTracks)
            {
                worstDistance = Math.Max(worstDistance, Vector3.Distance(track.Sample(t), positions[track.Bone]));
            }
        }

        Assert.That(worstAngle, Is.LessThan(2e-3 + 1e-4), "rotation error at the frames (rad)");
        Assert.That(worstDistance, Is.LessThan(1e-3 + 1e-5), "root position error at the frames (m)");
        Assert.That(worstAngle, Is.GreaterThan(1e-5), "the thinning used its epsilon");
    }

    [Test]
    public void TheClipPlacesTheBonesOnTheJointsInTheWorld()
    {
        // Without thinning, the clip at a frame time is the pose: forward kinematics of the sampled tracks puts the
        // bones where the rig puts the joints.
        GodotSkeleton godot = SkeletonBindingTests.BundledSkeleton();
        SkeletonBinding binding = SkeletonBindingTests.Bind(RuntimeWorlds.DesertSkeleton.Model, godot.Skeleton);
        AgentPath path = DesertPath.Value;
        BakedClip clip = AnimationClipBaker.Bake(path, binding, BoneTransform.Identity, new ClipBakeSettings { FrameRate = 20f, RotationEpsilon = 0f, PositionEpsilon = 0f, SkeletonPath = "Body/Skeleton3D" });
        Assert.That(clip.RotationTracks[0].Path, Does.StartWith("Body/Skeleton3D:"));

        var rig = path.Animation.Model.Rig;
        var expected = new Vector3[rig.Joints.Count];
        var expectedRotations = new Quaternion[rig.Joints.Count];
        var rotations = new Quaternion[binding.BoneCount];
        var positions = new Vector3[binding.BoneCount];
        double worst = 0.0;
        for (int k = 0; k * 0.05f <= path.Duration; k++)
        {
            float t = k * 0.05f;
            path.Animation.Joints(t, expected, expectedRotations);
            foreach (BoneRotationTrack track in clip.RotationTracks)
            {
                rotations[track.Bone] = track.Sample(t);
            }

            foreach (BonePositionTrack track in clip.PositionTracks)
            {
                positions[track.Bone] = track.Sample(t);
            }

            (Vector3[] bones, _) = TargetPose.World(binding, BoneTransform.Identity, rotations, positions);
            for (int j = 0; j < rig.Joints.Count; j++)
            {
                worst = Math.Max(worst, Vector3.Distance(bones[binding.JointBones[j]], expected[j]));
            }
        }

        Assert.That(worst, Is.LessThan(1e-3), "bones against joints at the frames (m)");
    }

    [Test]
    public void BakingIsDeterministicAndRefusesBadInput()
    {
        GodotSkeleton godot = SkeletonBindingTests.BundledSkeleton();
        SkeletonBinding binding = SkeletonBindingTests.Bind(RuntimeWorlds.DesertSkeleton.Model, godot.Skeleton);
        JumpAnimation animation = DesertPath.Value.Animation;
        BakedClip a = AnimationClipBaker.Bake(animation, binding, godot.Global);
        BakedClip b = AnimationClipBaker.Bake(animation, binding, godot.Global);
        Assert.Multiple(() =>
        {
            for (int i = 0; i < a.RotationTracks.Count; i++)
            {
                Assert.That(b.RotationTracks[i].Times, Is.EqualTo(a.RotationTracks[i].Times));
                Assert.That(b.RotationTracks[i].Rotations, Is.EqualTo(a.RotationTracks[i].Rotations));
            }

            Assert.That(() => AnimationClipBaker.Bake(animation, binding, godot.Global, new ClipBakeSettings { FrameRate = 0f }), Throws.ArgumentException.With.Message.Contains("frame rate"));
            Assert.That(() => AnimationClipBaker.Bake(animation, binding, godot.Global, new ClipBakeSettings { SkeletonPath = "A:B" }), Throws.ArgumentException.With.Message.Contains("skeleton path"));
            Assert.That(() => AnimationClipBaker.Bake(animation, binding, godot.Global, new ClipBakeSettings { RotationEpsilon = float.NaN }), Throws.ArgumentException.With.Message.Contains("rotation epsilon"));
        });

        // An animation of another character than the binding's.
        CharacterModel frog = CharacterPresets.Model("frog");
        var frogAnimation = new JumpAnimation(frog, [], [], [new AnimationFrame(0f, new RootPose(Vector3.Zero, Quaternion.Identity), new float[frog.Rig.DofCount])], [], [], 0, 0);
        Assert.That(() => AnimationClipBaker.Bake(frogAnimation, binding, godot.Global), Throws.ArgumentException.With.Message.Contains("'frog'"));

        // An animation without moves cannot be sampled.
        var model = RuntimeWorlds.DesertSkeleton.Model;
        var noMoves = new JumpAnimation(model, [], [], [new AnimationFrame(0f, new RootPose(Vector3.Zero, Quaternion.Identity), model.ContactPose)], [], [], 0, 0);
        Assert.That(() => AnimationClipBaker.Bake(noMoves, binding, godot.Global), Throws.ArgumentException.With.Message.Contains("0 moves"));
    }

    [Test]
    public void AClipOfAPathWithWalksCoversTheWalksToo()
    {
        GodotSkeleton godot = SkeletonBindingTests.BundledSkeleton();
        SkeletonBinding binding = SkeletonBindingTests.Bind(RuntimeWorlds.DesertSkeleton.Model, godot.Skeleton);
        IReadOnlyList<Move> moves = WalkingPaths.WalkJumpWalk();
        var animator = new SimpleMoveAnimator(RuntimeWorlds.DesertSkeleton.Animator);
        var path = new AgentPath(Vector3.Zero, moves, animator.Animate(moves, 30f));
        var settings = new ClipBakeSettings { FrameRate = 30f, RotationEpsilon = 1e-3f, PositionEpsilon = 1e-3f };
        BakedClip clip = AnimationClipBaker.Bake(path, binding, godot.Global, settings);
        Assert.That(clip.Length, Is.EqualTo(path.Animation.Duration), "the whole clip: walks, stances and the jump");
        Assert.That(clip.Length, Is.EqualTo(moves.Sum(m => m.Duration) + (2 * animator.Stance)).Within(1e-4f));

        // The root bone's track follows the walks: at each bake frame inside a walk it is the binding's conversion of
        // the animation there, within the epsilon.
        BonePositionTrack root = clip.PositionTracks.Single();
        float[] angles = new float[binding.Model.Rig.DofCount];
        var rotations = new Quaternion[binding.BoneCount];
        var positions = new Vector3[binding.BoneCount];
        foreach (int m in new[] { 0, 2 })
        {
            float start = path.Animation.MoveStart(m);
            float end = path.Animation.MoveEnd(m);
            int frames = 0;
            for (int k = (int)MathF.Ceiling(start * 30f); k / 30f <= end; k++, frames++)
            {
                float t = k / 30f;
                binding.ConvertAngles(path.Animation.Sample(t, angles), angles, godot.Global, rotations, positions);
                Assert.That(Vector3.Distance(root.Sample(t), positions[root.Bone]), Is.LessThan(1e-3f + 1e-5f), $"move {m} at frame {k}");
            }

            Assert.That(frames, Is.GreaterThan(20), $"frames in walk {m}");

            Assert.That(root.Times.Count(t => t > start && t < end), Is.GreaterThan(0), $"keys inside walk {m}");
            Assert.That(Vector3.Distance(root.Sample(end), root.Sample(start)), Is.GreaterThan(0.01f), $"the root moves through walk {m}");
        }

        // A path of one walk alone bakes too (a clip needs a move, not a jump).
        IReadOnlyList<Move> walkOnly = [moves[0]];
        BakedClip walking = AnimationClipBaker.Bake(animator.Animate(walkOnly), binding, godot.Global);
        Assert.That(walking.Length, Is.EqualTo(moves[0].Duration));
    }

    [Test]
    public void ATrackThatDoesNotMoveKeepsOneKey()
    {
        // A one-second "jump" without gravity or velocity, the pose held: every track is one key.
        GodotSkeleton godot = SkeletonBindingTests.BundledSkeleton();
        var model = RuntimeWorlds.DesertSkeleton.Model;
        SkeletonBinding binding = SkeletonBindingTests.Bind(model, godot.Skeleton);
        var pose = new RootPose(new Vector3(0f, 1f, 0f), Quaternion.CreateFromAxisAngle(Vector3.UnitY, 0.3f));
        var frames = new List<AnimationFrame> { new(0f, pose, model.ContactPose), new(1f, pose, model.ContactPose) };
        var node = new RoadmapNode(0, pose, new FrictionCone(Vector3.UnitY, 1f), []);
        var still = new JumpAnimation(model, [new Jump(node, node, new BallisticArc(pose, pose, Vector3.Zero, 1f, 0f))], [], frames, [], [], 0, 0);
        BakedClip clip = AnimationClipBaker.Bake(still, binding, BoneTransform.Identity);
        Assert.Multiple(() =>
        {
            Assert.That(clip.Length, Is.EqualTo(1f));
            Assert.That(clip.RotationTracks.Select(t => t.Times.Length), Has.All.EqualTo(1));
            Assert.That(clip.PositionTracks.Single().Sample(5f), Is.EqualTo(clip.PositionTracks.Single().Positions[0]));
        });
    }
}
