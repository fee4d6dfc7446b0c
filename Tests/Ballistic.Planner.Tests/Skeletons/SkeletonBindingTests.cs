using System.Numerics;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Tests.Runtime;
using Ballistic.Planner.Tests.Support;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Skeletons;

namespace Ballistic.Planner.Tests.Skeletons;

/// <summary>
/// Binding runtime rigs to engine skeletons: the bundled skeleton to its own bones, rigs exported the way other tools
/// export them (helper nodes between bones, Z-up armatures, several root bones) to the skeleton Godot's importer
/// makes of them, and skeletons whose rests differ; the converted pose puts every bone where the runtime puts its
/// joint.
/// </summary>
public sealed class SkeletonBindingTests
{
    private const float Metre = 1e-4f;
    private string _folder = "";

    [SetUp]
    public void CreateFolder()
    {
        _folder = Path.Combine(Path.GetTempPath(), $"ballistic-skeletons-{Guid.NewGuid():N}");
        Directory.CreateDirectory(_folder);
    }

    [TearDown]
    public void DeleteFolder() => Directory.Delete(_folder, recursive: true);

    internal static string SkeletonGlb => Path.Combine(RepositoryFiles.Root, "Scenes", "characters", "skeleton.glb");

    internal static GodotSkeleton BundledSkeleton() => GodotSkeletonImport.Import(SkeletonGlb);

    internal static SkeletonBinding Bind(CharacterModel model, TargetSkeleton target, SkeletonBindingOptions? options = null)
    {
        SkeletonBindingResult result = SkeletonBinding.Create(model, target, options);
        Assert.That(result.Ok, Is.True, result.ToString());
        return result.Binding!;
    }

    [Test]
    public void TheBundledSkeletonBindsEveryJointToItsOwnBones()
    {
        (CharacterModel model, _) = CharacterSpecFile.Load(SkeletonGlb, Path.Combine(RepositoryFiles.Root, "Scenes", "characters", "skeleton.limbs.json"));
        GodotSkeleton godot = BundledSkeleton();
        SkeletonBinding binding = Bind(model, godot.Skeleton);
        Assert.Multiple(() =>
        {
            Assert.That(binding.UnmatchedJoints, Is.Empty);
            Assert.That(binding.JointBones, Has.All.GreaterThanOrEqualTo(0));
            for (int j = 0; j < model.Rig.Joints.Count; j++)
            {
                Assert.That(godot.Skeleton.Names[binding.JointBones[j]], Is.EqualTo(model.Rig.Joints[j].Name));
                Assert.That(binding.Matches[j], Is.EqualTo(JointMatch.Exact));
            }

            Assert.That(binding.PositionedBones, Is.EqualTo(new[] { binding.JointBones[0] }), "only the root bone is placed");
            Assert.That(Angle(binding.RestAlignment, Quaternion.Identity), Is.LessThan(1e-4), "the file's armature is the identity");
        });
        AssertReproduces(binding, godot.Global, seed: 1, poses: 20);
    }

    [Test]
    public void TheRuntimeSkeletonDrivesTheBundledModelOverASampledJump()
    {
        // The desert world animates the preset skeleton; the Godot scene shows Scenes/characters/skeleton.glb.
        GodotSkeleton godot = BundledSkeleton();
        SkeletonBinding binding = Bind(RuntimeWorlds.DesertSkeleton.Model, godot.Skeleton);
        (JumpWorld world, var kind) = RuntimeWorlds.Desert();
        using (world)
        {
            (AgentHandle agent, _, _) = RuntimeWorlds.SendAcross(world, kind, seed: 4);
            Rig rig = RuntimeWorlds.DesertSkeleton.Model.Rig;
            var expected = new Vector3[rig.Joints.Count];
            var expectedRotations = new Quaternion[rig.Joints.Count];
            var rotations = new Quaternion[binding.BoneCount];
            var positions = new Vector3[binding.BoneCount];

            // The character's scene placed somewhere, turned: the bones still go where the joints are in the world.
            var global = new BoneTransform(new Vector3(3f, -1f, 2f), Quaternion.CreateFromAxisAngle(Vector3.UnitY, 0.7f));
            int flying = 0;
            double worst = 0.0;
            RuntimeWorlds.Run(world, 60 * 20, RuntimeWorlds.Concluded, w =>
            {
                Assert.That(binding.Convert(w, agent, global, rotations, positions).Ok, Is.True);
                rig.Solve(w.GetRootPose(agent), w.GetJointAngles(agent), expected, expectedRotations);
                (Vector3[] bones, Quaternion[] boneRotations) = TargetPose.World(binding, global, rotations, positions);
                for (int j = 0; j < rig.Joints.Count; j++)
                {
                    worst = Math.Max(worst, Vector3.Distance(bones[binding.JointBones[j]], expected[j]));
                    worst = Math.Max(worst, Angle(boneRotations[binding.JointBones[j]], expectedRotations[j]) * 1e-2);
                }

                flying += w.GetState(agent) is AgentState.Flight ? 1 : 0;
            });
            Assert.That(flying, Is.GreaterThan(10), "ticks sampled in flight");
            Assert.That(worst, Is.LessThan(Metre), "largest distance between a bone and its joint (m), or rotation error (×0.01 rad)");
        }
    }

    [TestCase("human")]
    [TestCase("human-zup")]
    [TestCase("dog")]
    [TestCase("tailed")]
    public void ForeignRigsBindToTheSkeletonGodotImportsAndReproduceTheirPoses(string name)
    {
        ForeignCharacter character = name switch
        {
            "human" => ForeignCharacters.Human(zUpScene: false),
            "human-zup" => ForeignCharacters.Human(zUpScene: true),
            "dog" => ForeignCharacters.Dog(),
            _ => ForeignCharacters.TailedQuadruped(),
        };
        (string gltf, string spec) = character.Write(_folder);
        (CharacterModel model, _) = CharacterSpecFile.Load(gltf, spec);
        GodotSkeleton godot = GodotSkeletonImport.Import(gltf);
        SkeletonBinding binding = Bind(model, godot.Skeleton);
        int helpers = godot.Skeleton.BoneCount - model.Rig.Joints.Count;
        Assert.Multiple(() =>
        {
            Assert.That(binding.UnmatchedJoints, Is.Empty, "every joint of the rig is a bone");
            Assert.That(binding.BoneJoints.Count(j => j < 0), Is.EqualTo(helpers), "the other bones are the file's helper nodes");
            Assert.That(Angle(binding.RestAlignment, character.ToBallistic * godot.Global.Rotation), Is.LessThan(1e-3), "the fitted alignment is the axis conversion times the armature's rotation");
            if (name.StartsWith("human", StringComparison.Ordinal))
            {
                Assert.That(binding.Matches, Has.All.EqualTo(JointMatch.Sanitized), "'mixamorig:Hips' is the bone 'mixamorig_Hips'");
            }

            if (name == "dog")
            {
                Assert.That(helpers, Is.EqualTo(5), "the foot anchors between bones became bones");
            }

            if (name == "tailed")
            {
                Assert.That(godot.Skeleton.Parents.Count(p => p < 0), Is.EqualTo(3), "three root bones");
                Assert.That(binding.PositionedBones.Select(b => godot.Skeleton.Names[b]), Is.EquivalentTo(new[] { "tail_root", "ik_target", "hips" }));
            }
        });
        AssertReproduces(binding, godot.Global, seed: 3, poses: 25);
    }

    [Test]
    public void ASkeletonWithRotatedRestsFollowsTheWorldBoneDirections()
    {
        // Every bone's frame turned by a random rotation, the children's rests compensated so that the rest pose
        // stands where it stood (other bone axes, as another exporter or Godot's rest fixer would make them).
        GodotSkeleton godot = BundledSkeleton();
        TargetSkeleton original = godot.Skeleton;
        var random = new Random(5);
        var turn = new Quaternion[original.BoneCount];
        var rests = new BoneTransform[original.BoneCount];
        for (int b = 0; b < original.BoneCount; b++)
        {
            turn[b] = RandomRotation(random, MathF.PI);
            BoneTransform rest = original.Rests[b];
            int p = original.Parents[b];
            Quaternion parentTurn = p < 0 ? Quaternion.Identity : Quaternion.Conjugate(turn[p]);
            rests[b] = new BoneTransform(Vector3.Transform(rest.Position, parentTurn), Quaternion.Normalize(parentTurn * rest.Rotation * turn[b]), rest.Scale);
        }

        var turned = new TargetSkeleton(original.Names, original.Parents, rests);
        CharacterModel model = RuntimeWorlds.DesertSkeleton.Model;
        SkeletonBinding plain = Bind(model, original);
        SkeletonBinding binding = Bind(model, turned);
        Assert.That(Angle(binding.RestAlignment, Quaternion.Identity), Is.LessThan(1e-4), "the rest positions did not move");

        Rig rig = model.Rig;
        var random2 = new Random(8);
        var expected = new Vector3[rig.Joints.Count];
        var expectedRotations = new Quaternion[rig.Joints.Count];
        var rotations = new Quaternion[binding.BoneCount];
        var positions = new Vector3[binding.BoneCount];
        var plainRotations = new Quaternion[binding.BoneCount];
        double differs = 0.0;
        for (int i = 0; i < 20; i++)
        {
            (RootPose root, float[] angles) = RandomPose(rig, random2);
            rig.Solve(root, angles, expected, expectedRotations);
            binding.ConvertAngles(root, angles, godot.Global, rotations, positions);
            plain.ConvertAngles(root, angles, godot.Global, plainRotations, positions);
            (Vector3[] bones, _) = TargetPose.World(binding, godot.Global, rotations, positions);
            for (int j = 1; j < rig.Joints.Count; j++)
            {
                int parent = rig.Joints[j].Parent;
                Vector3 want = Vector3.Normalize(expected[j] - expected[parent]);
                Vector3 got = Vector3.Normalize(bones[binding.JointBones[j]] - bones[binding.JointBones[parent]]);
                Assert.That(MathF.Acos(Math.Clamp(Vector3.Dot(want, got), -1f, 1f)), Is.LessThan(1e-3f), $"direction of the bone to '{rig.Joints[j].Name}'");
                Assert.That(Vector3.Distance(bones[binding.JointBones[j]], expected[j]), Is.LessThan(Metre), $"'{rig.Joints[j].Name}'");
                differs = Math.Max(differs, Angle(rotations[binding.JointBones[j]], plainRotations[binding.JointBones[j]]));
            }
        }

        Assert.That(differs, Is.GreaterThan(0.5), "the turned skeleton's local rotations differ from the plain one's");
    }

    [Test]
    public void ASkeletonInAnotherFrameIsAlignedByItsRestPositions()
    {
        // The same bones with the whole skeleton laid Z up (its root rest turned by −90° about X), the skeleton node
        // left unturned: the fit finds the turn, and the pose still stands upright in the world.
        GodotSkeleton godot = BundledSkeleton();
        TargetSkeleton original = godot.Skeleton;
        Quaternion zUp = Quaternion.CreateFromAxisAngle(Vector3.UnitX, -MathF.PI / 2f);
        BoneTransform[] rests = [.. original.Rests];
        for (int b = 0; b < rests.Length; b++)
        {
            if (original.Parents[b] < 0)
            {
                rests[b] = new BoneTransform(Vector3.Transform(rests[b].Position, zUp), zUp * rests[b].Rotation, rests[b].Scale);
            }
        }

        SkeletonBinding binding = Bind(RuntimeWorlds.DesertSkeleton.Model, new TargetSkeleton(original.Names, original.Parents, rests));
        Assert.That(Angle(binding.RestAlignment, Quaternion.Conjugate(zUp)), Is.LessThan(1e-4));
        AssertReproduces(binding, BoneTransform.Identity, seed: 6, poses: 10);

        // And an explicit alignment is used as given.
        SkeletonBinding given = Bind(RuntimeWorlds.DesertSkeleton.Model, new TargetSkeleton(original.Names, original.Parents, rests), new SkeletonBindingOptions { RestAlignment = Quaternion.Conjugate(zUp) });
        AssertReproduces(given, BoneTransform.Identity, seed: 6, poses: 5);
    }

    [Test]
    public void RenamedAndLooselyNamedBonesMatch()
    {
        GodotSkeleton godot = BundledSkeleton();
        TargetSkeleton original = godot.Skeleton;

        // Upper case with dots ("LEFT.HIP"), and the pelvis called "Hips".
        string[] names = [.. original.Names.Select(n => n == "pelvis" ? "Hips" : n.ToUpperInvariant().Replace('_', '.'))];
        var target = new TargetSkeleton(names, original.Parents, original.Rests);
        CharacterModel model = RuntimeWorlds.DesertSkeleton.Model;
        SkeletonBindingResult unrenamed = SkeletonBinding.Create(model, target);
        Assert.That(unrenamed.Ok, Is.False, "the pelvis has no bone without the rename");
        Assert.That(unrenamed.Error, Does.Contain("'pelvis'").And.Contain("root joint"));

        SkeletonBinding binding = Bind(model, target, new SkeletonBindingOptions { Renames = new Dictionary<string, string> { ["pelvis"] = "Hips" } });
        Assert.Multiple(() =>
        {
            Assert.That(binding.Matches[0], Is.EqualTo(JointMatch.Renamed));
            Assert.That(binding.Matches.Skip(1), Has.All.EqualTo(JointMatch.Loose));
            Assert.That(names[binding.JointBones[model.Rig.IndexOf("left_hip")]], Is.EqualTo("LEFT.HIP"));
            Assert.That(SkeletonBinding.Create(model, target, new SkeletonBindingOptions { MatchLoosely = false, Renames = new Dictionary<string, string> { ["pelvis"] = "Hips" } }).Error, Does.Contain("'left_hip'"));
            Assert.That(SkeletonBinding.Create(model, target, new SkeletonBindingOptions { Renames = new Dictionary<string, string> { ["pelvis"] = "Pelvis" } }).Error, Does.Contain("'Pelvis'").And.Contain("not a bone"));
            Assert.That(SkeletonBinding.Create(model, target, new SkeletonBindingOptions { Renames = new Dictionary<string, string> { ["tail"] = "Hips" } }).Error, Does.Contain("'tail'").And.Contain("not a joint"));
        });
        AssertReproduces(binding, godot.Global, seed: 9, poses: 5);

        // Two bones with the same loose key match neither: "LEFT.HIP" and "Left_Hip".
        string[] twins = [.. original.Names.Select(n => n == "right_knee" ? "Left_Hip" : n == "left_hip" ? "LEFT.HIP" : n)];
        SkeletonBindingResult ambiguous = SkeletonBinding.Create(model, new TargetSkeleton(twins, original.Parents, original.Rests));
        Assert.That(ambiguous.Error, Does.Contain("'left_hip'"));
    }

    [Test]
    public void GodotSanitisesColonsAndSlashes()
    {
        Assert.Multiple(() =>
        {
            Assert.That(GodotBoneNames.Sanitize("mixamorig:LeftUpLeg"), Is.EqualTo("mixamorig_LeftUpLeg"));
            Assert.That(GodotBoneNames.Sanitize("rig/arm.L"), Is.EqualTo("rig_arm.L"));
            Assert.That(GodotBoneNames.Sanitize(""), Is.EqualTo("bone"));
            Assert.That(GodotBoneNames.LooseKey("Mixamorig.Left-Up Leg_01"), Is.EqualTo("mixamorigleftupleg01"));
        });
    }

    [Test]
    public void AMissingLimbRootIsOneLineNamingTheBone()
    {
        GodotSkeleton godot = BundledSkeleton();
        TargetSkeleton original = godot.Skeleton;
        CharacterModel model = RuntimeWorlds.DesertSkeleton.Model;
        string[] names = [.. original.Names.Select(n => n == "left_hip" ? "thigh_helper" : n)];
        SkeletonBindingResult result = SkeletonBinding.Create(model, new TargetSkeleton(names, original.Parents, original.Rests));
        Assert.Multiple(() =>
        {
            Assert.That(result.Ok, Is.False);
            Assert.That(result.Binding, Is.Null);
            Assert.That(result.Error, Does.Contain("'left_hip'").And.Contain("the root of limb 'left_foot'"));
            Assert.That(result.Error, Does.Not.Contain('\n'));
            Assert.That(result.MissingRequired, Is.EqualTo(new[] { "left_hip" }));
        });

        // A joint no limb needs (the head) may be missing: its bone stays at rest, the rest is bound.
        string[] headless = [.. original.Names.Select(n => n == "head" ? "skull" : n)];
        SkeletonBinding binding = Bind(model, new TargetSkeleton(headless, original.Parents, original.Rests));
        Assert.That(binding.UnmatchedJoints, Is.EqualTo(new[] { "head" }));
        Assert.That(binding.BoneJoints[Array.IndexOf(headless, "skull")], Is.EqualTo(-1));
    }

    [Test]
    public void ConvertingAPoseAllocatesNothing()
    {
        GodotSkeleton godot = BundledSkeleton();
        SkeletonBinding binding = Bind(RuntimeWorlds.DesertSkeleton.Model, godot.Skeleton);
        (JumpWorld world, var kind) = RuntimeWorlds.Desert();
        using (world)
        {
            AgentHandle agent = world.AddAgent(kind, RuntimeWorlds.Point(RuntimeWorlds.DesertSkeleton.Roadmap.Nodes[0])).Agent;
            world.Step();
            var rotations = new Quaternion[binding.BoneCount];
            var positions = new Vector3[binding.BoneCount];
            float[] angles = world.GetJointAngles(agent).ToArray();
            RootPose root = world.GetRootPose(agent);
            BoneTransform global = godot.Global;
            binding.Convert(world, agent, global, rotations, positions);
            binding.ConvertAngles(root, angles, global, rotations, positions);
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < 200; i++)
            {
                binding.Convert(world, agent, global, rotations, positions);
                binding.Convert(root, world.GetJointRotations(agent), global, rotations, positions);
                binding.ConvertAngles(root, angles, global, rotations, positions);
            }

            Assert.That(GC.GetAllocatedBytesForCurrentThread() - before, Is.Zero);
        }
    }

    [Test]
    public void BadInputsAreRefusedWithTheReason()
    {
        GodotSkeleton godot = BundledSkeleton();
        TargetSkeleton s = godot.Skeleton;
        SkeletonBinding binding = Bind(RuntimeWorlds.DesertSkeleton.Model, s);
        var rotations = new Quaternion[binding.BoneCount];
        var positions = new Vector3[binding.BoneCount];
        var root = new RootPose(Vector3.Zero, Quaternion.Identity);
        Quaternion[] joints = [.. Enumerable.Repeat(Quaternion.Identity, RuntimeWorlds.DesertSkeleton.JointCount)];
        Assert.Multiple(() =>
        {
            Assert.That(() => binding.Convert(root, joints.AsSpan(1), BoneTransform.Identity, rotations, positions), Throws.ArgumentException.With.Message.Contains("joint rotations"));
            Assert.That(() => binding.Convert(root, joints, BoneTransform.Identity, rotations.AsSpan(1), positions), Throws.ArgumentException.With.Message.Contains($"{binding.BoneCount} bones"));
            Assert.That(() => binding.Convert(root, joints, new BoneTransform(Vector3.Zero, Quaternion.Identity, new Vector3(1f, 2f, 1f)), rotations, positions), Throws.ArgumentException.With.Message.Contains("uniform"));
            Assert.That(() => new TargetSkeleton(["a", "b:c"], [-1, 0], [BoneTransform.Identity, BoneTransform.Identity]), Throws.ArgumentException.With.Message.Contains("'b:c'"));
            Assert.That(() => new TargetSkeleton(["a", "a"], [-1, 0], [BoneTransform.Identity, BoneTransform.Identity]), Throws.ArgumentException.With.Message.Contains("both called 'a'"));
            Assert.That(() => new TargetSkeleton(["a", "b"], [1, -1], [BoneTransform.Identity, BoneTransform.Identity]), Throws.ArgumentException.With.Message.Contains("Bone 0 'a'"));
            Assert.That(() => new TargetSkeleton(["a"], [-1], [new BoneTransform(Vector3.Zero, default)]), Throws.ArgumentException.With.Message.Contains("zero rotation"));
        });

        // A non-uniform scale above driven bones cannot hold rotations.
        BoneTransform[] rests = [.. s.Rests];
        int pelvis = s.IndexOf("pelvis");
        rests[pelvis] = rests[pelvis] with { Scale = new Vector3(1f, 1.5f, 1f) };
        SkeletonBindingResult scaled = SkeletonBinding.Create(RuntimeWorlds.DesertSkeleton.Model, new TargetSkeleton(s.Names, s.Parents, rests));
        Assert.That(scaled.Error, Does.Contain("'pelvis'").And.Contain("non-uniform"));

        // An agent of an unknown handle or another character is refused.
        (JumpWorld world, _) = RuntimeWorlds.Desert();
        using (world)
        {
            Assert.That(binding.Convert(world, default, BoneTransform.Identity, rotations, positions).Status, Is.EqualTo(RuntimeStatus.UnknownAgent));
        }
    }

    /// <summary>Random root poses and in-limit angles: every driven bone lands on its joint, within 0.1 mm.</summary>
    private static void AssertReproduces(SkeletonBinding binding, BoneTransform global, int seed, int poses)
    {
        Rig rig = binding.Model.Rig;
        var random = new Random(seed);
        var expected = new Vector3[rig.Joints.Count];
        var expectedRotations = new Quaternion[rig.Joints.Count];
        var rotations = new Quaternion[binding.BoneCount];
        var positions = new Vector3[binding.BoneCount];
        double worst = 0.0;
        string where = "";
        for (int i = 0; i < poses; i++)
        {
            (RootPose root, float[] angles) = RandomPose(rig, random);
            rig.Solve(root, angles, expected, expectedRotations);
            binding.ConvertAngles(root, angles, global, rotations, positions);
            (Vector3[] bones, _) = TargetPose.World(binding, global, rotations, positions);
            for (int j = 0; j < rig.Joints.Count; j++)
            {
                if (binding.JointBones[j] >= 0 && Vector3.Distance(bones[binding.JointBones[j]], expected[j]) is float d && d > worst)
                {
                    worst = d;
                    where = rig.Joints[j].Name;
                }
            }
        }

        Assert.That(worst, Is.LessThan(Metre), $"largest distance between a bone and its joint, at '{where}' (m)");
    }

    internal static (RootPose Root, float[] Angles) RandomPose(Rig rig, Random random)
    {
        var root = new RootPose(new Vector3((random.NextSingle() * 20f) - 10f, random.NextSingle() * 3f, (random.NextSingle() * 20f) - 10f), RandomRotation(random, 1.5f));
        float[] q = new float[rig.DofCount];
        for (int d = 0; d < q.Length; d++)
        {
            q[d] = rig.Dofs[d].Min + (random.NextSingle() * (rig.Dofs[d].Max - rig.Dofs[d].Min));
        }

        return (root, q);
    }

    internal static Quaternion RandomRotation(Random random, float maxAngle)
    {
        var axis = Vector3.Normalize(new Vector3(random.NextSingle() - 0.5f, random.NextSingle() - 0.5f, random.NextSingle() - 0.5f));
        return Quaternion.CreateFromAxisAngle(axis, random.NextSingle() * maxAngle);
    }

    /// <summary>The angle between two rotations, radians.</summary>
    internal static double Angle(Quaternion a, Quaternion b) => 2.0 * Math.Acos(Math.Min(1.0, Math.Abs((double)Quaternion.Dot(Quaternion.Normalize(a), Quaternion.Normalize(b)))));
}
