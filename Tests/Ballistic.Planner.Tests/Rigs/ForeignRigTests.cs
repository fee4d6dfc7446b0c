using System.Numerics;
using System.Text.Json.Nodes;
using Ballistic.Authoring.Animation;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Gltf;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;
using SharpGLTF.Schema2;

namespace Ballistic.Planner.Tests.Rigs;

/// <summary>Rigs in other tools' shapes (armatures, anchors, several root bones, Z up, centimetres) load from limbs-only specs, stand upright with sensible derived defaults, and export with their own meshes.</summary>
public sealed class ForeignRigTests
{
    private const float Degree = MathF.PI / 180f;
    private string _folder = "";

    public static IEnumerable<TestCaseData> Characters()
    {
        yield return new TestCaseData("human").SetName("{m}(human under a rotated, scaled armature)");
        yield return new TestCaseData("human-zup").SetName("{m}(human in a Z-up scene with upAxis and forwardAxis)");
        yield return new TestCaseData("dog").SetName("{m}(dog with anchors between bones, .gltf with external files)");
        yield return new TestCaseData("tailed").SetName("{m}(tailed quadruped with three root bones, facing +X)");
    }

    [SetUp]
    public void MakeFolder()
    {
        _folder = Path.Combine(Path.GetTempPath(), $"ballistic-foreign-{Guid.NewGuid():N}");
        Directory.CreateDirectory(_folder);
    }

    [TearDown]
    public void RemoveFolder() => Directory.Delete(_folder, recursive: true);

    [TestCaseSource(nameof(Characters))]
    public void LoadsUprightWithTheTrunkAndSolesOfItsMesh(string name)
    {
        ForeignCharacter character = Character(name);
        (CharacterModel model, ReducedCharacter reduced, Vector3[] positions, Quaternion[] rotations) = LoadAtRest(character);
        Rig rig = model.Rig;

        // Where a scene point lands in the trunk frame at rest: the hand-worked rotation, then the root's place.
        Vector3 shift = positions[0] - Vector3.Transform(character.BonePosition(character.Root), character.ToBallistic);
        Vector3 ToTrunk(Vector3 scene) => Vector3.Transform(scene, character.ToBallistic) + shift;

        Assert.Multiple(() =>
        {
            // Every bone where the scene puts it (so the rig is upright and faces +Z), and the named checks.
            foreach (Joint joint in rig.Joints)
            {
                Assert.That(Vector3.Distance(positions[rig.IndexOf(joint.Name)], ToTrunk(character.BonePosition(joint.Name))), Is.LessThan(1e-3f), $"{name}: bone {joint.Name}");
            }

            Assert.That(positions[rig.IndexOf(character.Head)].Y, Is.GreaterThan(positions[0].Y + 0.03f), $"{name}: the head is above the root");
            foreach (ForeignFoot foot in character.Feet)
            {
                Assert.That(model.Limbs.Single(l => l.Name == foot.Limb).EffectorPosition(positions, rotations).Y, Is.LessThan(positions[0].Y - 0.25f), $"{name}: {foot.Limb} is below the root");
            }

            Vector3 ahead = positions[rig.IndexOf(character.Ahead)] - positions[rig.IndexOf(character.Behind)];
            Assert.That(ahead.Z, Is.GreaterThan(0.05f), $"{name}: faces +Z");
            Assert.That(MathF.Abs(ahead.X), Is.LessThan(0.01f), $"{name}: faces +Z, not sideways");
        });

        // The trunk box bounds the trunk bones' vertices, tightly, and holds no tail or head.
        Assert.That(model.TrunkJoints.Select(j => rig.Joints[j].Name), Is.EquivalentTo(character.TrunkBones));
        Vector3[] trunk = [.. character.Vertices(character.TrunkBones).Select(ToTrunk)];
        Vector3 min = trunk.Aggregate(Vector3.Min);
        Vector3 max = trunk.Aggregate(Vector3.Max);
        Assert.Multiple(() =>
        {
            Assert.That(Vector3.Distance(max, reduced.TrunkHalfExtents), Is.LessThan(1e-3f), $"{name}: trunk box top corner vs the trunk vertices");
            Assert.That(Vector3.Distance(min, -reduced.TrunkHalfExtents), Is.LessThan(1e-3f), $"{name}: trunk box bottom corner vs the trunk vertices");
            Vector3 head = character.Vertices(character.Head).Select(ToTrunk).Aggregate(Vector3.Max);
            Assert.That(head.Y > reduced.TrunkHalfExtents.Y + 0.01f || head.Z > reduced.TrunkHalfExtents.Z + 0.01f, Is.True, $"{name}: the head sticks out of the trunk box");
        });

        // Soles at the bottom of the feet, contact normals pointing down.
        foreach (ForeignFoot foot in character.Feet)
        {
            RigLimb limb = model.Limbs.Single(l => l.Name == foot.Limb);
            Vector3[] vertices = [.. character.Vertices(foot.Bones).Select(ToTrunk)];
            Vector3 contact = limb.EffectorPosition(positions, rotations);
            Assert.Multiple(() =>
            {
                Assert.That(contact.Y, Is.EqualTo(vertices.Min(v => v.Y)).Within(0.01f), $"{name} {foot.Limb}: contact point at the lowest foot vertex");
                Assert.That(contact.X, Is.InRange(vertices.Min(v => v.X), vertices.Max(v => v.X)), $"{name} {foot.Limb}: contact point under the foot");
                Assert.That(contact.Z, Is.InRange(vertices.Min(v => v.Z), vertices.Max(v => v.Z)), $"{name} {foot.Limb}: contact point under the foot");
                Assert.That(limb.Filter, Is.EqualTo(new NormalFilter(Vector3.UnitY, 0.5f)), $"{name} {foot.Limb}: feet accept surfaces within 60° of up");
            });
        }

        foreach (RigLimb limb in model.Limbs)
        {
            float angle = MathF.Acos(Math.Clamp(Vector3.Dot(limb.EffectorNormal(rotations), -Vector3.UnitY), -1f, 1f)) / Degree;
            Assert.That(angle, Is.LessThan(10f), $"{name} {limb.Name}: the contact normal points down in the rest pose");
        }
    }

    [Test]
    public void SkinBlendedBetweenThighAndShinIsKeptOutOfTheLevelWhereSkinningPutsIt()
    {
        // The human's shin box is skinned 0.7 to the shin and 0.3 to the thigh. With the knee bent, linear blend
        // skinning (as an importer draws it) puts that skin centimetres away from where the shin alone carries it:
        // the body check probes it there (on stairs its back went 3.3 cm into a step while every rigid probe was clear).
        ForeignCharacter character = ForeignCharacters.Human(zUpScene: false);
        (CharacterModel model, _, _, _) = LoadAtRest(character);
        Rig rig = model.Rig;
        int shin = rig.IndexOf("mixamorig:LeftLeg");
        SkinBlend[][] blends = model.Source!.BlendProbes[shin];
        float[] q = new float[rig.DofCount];
        JointAxis knee = rig.Dofs[rig.FirstDof(shin)];
        q[rig.FirstDof(shin)] = 0.8f * (MathF.Abs(knee.Max) > MathF.Abs(knee.Min) ? knee.Max : knee.Min);
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        rig.Solve(new RootPose(new Vector3(0f, 1f, 0f), Quaternion.Identity), q, positions, rotations);
        Vector3 Blended(SkinBlend[] blend) => blend.Aggregate(Vector3.Zero, (sum, part) => sum + (part.Weight * (positions[part.Joint] + Vector3.Transform(part.Point, rotations[part.Joint]))));
        Vector3 Rigid(SkinBlend[] blend) => blend.Where(part => part.Joint == shin).Select(part => positions[shin] + Vector3.Transform(part.Point, rotations[shin])).Single();
        SkinBlend[] moved = blends.MaxBy(b => Vector3.Distance(Blended(b), Rigid(b)))!;
        Vector3 at = Blended(moved);

        // A 5 cm block around that skin point, clear of the limb's bones and of every rigid skin probe.
        var block = new Ballistic.Authoring.Levels.MeshBuilder();
        block.Box(at - new Vector3(0.025f), at + new Vector3(0.025f));
        Triangle[] triangles = [.. Enumerable.Range(0, block.TriangleCount).Select(t => new Triangle(block.Positions[block.Indices[3 * t]], block.Positions[block.Indices[(3 * t) + 1]], block.Positions[block.Indices[(3 * t) + 2]]))];
        RigLimb foot = model.Limbs.Single(l => l.Name == "left_foot");
        var rigidProbes = foot.Chain.SelectMany(j => model.Source.SkinProbes[j].Select(p => positions[j] + Vector3.Transform(p, rotations[j]))).ToArray();
        Assert.Multiple(() =>
        {
            Assert.That(blends, Is.Not.Empty, "the shin's blended skin is probed");
            Assert.That(blends.Select(b => b.Sum(part => part.Weight)), Has.All.EqualTo(1f).Within(1e-5f), "each probe's shares sum to 1");
            Assert.That(blends.SelectMany(b => b.Select(part => rig.Joints[part.Joint].Name)).Distinct(), Is.EquivalentTo(new[] { "mixamorig:LeftLeg", "mixamorig:LeftUpLeg" }));
            Assert.That(Vector3.Distance(at, Rigid(moved)), Is.GreaterThan(0.05f), "skinning moves it off the shin");
            Assert.That(rigidProbes.Min(p => Vector3.Distance(p, at)), Is.GreaterThan(0.045f), "no rigid probe is in the block");
            Assert.That(foot.Chain.Skip(1).Min(j => SegmentDistance(at, positions[rig.Joints[j].Parent], positions[j])), Is.GreaterThan(0.045f), "no bone crosses the block");
            var collision = new BodyCollision(new Ballistic.Planner.Collision.TriangleBvh(triangles), model, triangles);
            Assert.That(collision.LimbCollides(foot, positions, rotations, null), Is.True, "the blended skin is seen inside the block");
        });
    }

    /// <summary>Distance (metres) from <paramref name="p"/> to the segment from <paramref name="a"/> to <paramref name="b"/>.</summary>
    internal static float SegmentDistance(Vector3 p, Vector3 a, Vector3 b)
    {
        Vector3 ab = b - a;
        float t = Math.Clamp(Vector3.Dot(p - a, ab) / MathF.Max(ab.LengthSquared(), 1e-12f), 0f, 1f);
        return Vector3.Distance(p, a + (t * ab));
    }

    [Test]
    public void BoneRadiiComeFromTheMeshAndHandsAcceptAnySurface()
    {
        ForeignCharacter character = ForeignCharacters.Human(zUpScene: false);
        (CharacterModel model, _, _, _) = LoadAtRest(character);
        Rig rig = model.Rig;

        // The thigh (hip to knee) is a 12 × 14 cm box: its radius lies between the half width and the half diagonal.
        Assert.That(model.BoneRadii[rig.IndexOf("mixamorig:LeftLeg")], Is.InRange(0.06f, 0.093f));
        Assert.That(model.BoneRadii[rig.IndexOf("mixamorig:LeftForeArm")], Is.InRange(0.05f, 0.0715f), "upper arm: a 10 × 10 cm box");
        Assert.That(model.Limbs.Single(l => l.Name == "left_hand").Filter.MinCosine, Is.EqualTo(-1f));
        Assert.That(model.Limbs.Single(l => l.Name == "left_hand").Kind, Is.EqualTo(LimbKind.Hand));
    }

    [TestCaseSource(nameof(Characters))]
    public void TheAnimatedGlbCarriesTheUsersMeshAndReloadsToTheSamePoses(string name)
    {
        ForeignCharacter character = Character(name);
        (string gltf, string spec) = character.Write(_folder);
        (CharacterModel model, _) = CharacterSpecFile.Load(gltf, spec);
        Rig rig = model.Rig;

        // Frames with random root poses and joint angles within their limits.
        var random = new Random(7);
        var frames = new List<AnimationFrame>();
        for (int f = 0; f < 12; f++)
        {
            var axis = Vector3.Normalize(new Vector3((float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f));
            var root = new RootPose(new Vector3(random.NextSingle() * 4f, random.NextSingle(), random.NextSingle() * 4f), Quaternion.CreateFromAxisAngle(axis, random.NextSingle() * 2f));
            float[] q = new float[rig.DofCount];
            for (int d = 0; d < q.Length; d++)
            {
                q[d] = rig.Dofs[d].Min + (random.NextSingle() * (rig.Dofs[d].Max - rig.Dofs[d].Min));
            }

            frames.Add(new AnimationFrame(f / 30f, root, q));
        }

        var animation = new JumpAnimation(model, Array.Empty<Move>(), [], frames, [], [], 0, 0);
        byte[] glb = AnimatedGlbWriter.ToBytes(animation, "jumps");

        // CI runs the Khronos validator on these too (it sets BALLISTIC_GLTF_OUT).
        if (Environment.GetEnvironmentVariable("BALLISTIC_GLTF_OUT") is { Length: > 0 } validate)
        {
            Directory.CreateDirectory(validate);
            File.WriteAllBytes(Path.Combine(validate, name + "-animated.glb"), glb);
        }

        GltfModel originalModel = GltfModel.Load(gltf);
        GltfModel writtenModel = GltfModel.Parse(glb, name + ".glb", null);
        ModelRoot original = originalModel.Root;
        ModelRoot written = writtenModel.Root;
        JsonObject originalJson = gltf.EndsWith(".glb", StringComparison.Ordinal) ? Fuzz.FuzzInputs.SplitGlb(File.ReadAllBytes(gltf)).Json : JsonNode.Parse(File.ReadAllText(gltf))!.AsObject();
        JsonObject writtenJson = Fuzz.FuzzInputs.SplitGlb(glb).Json;

        // The user's own content is there, unchanged.
        Assert.Multiple(() =>
        {
            foreach (string key in new[] { "meshes", "materials", "textures", "samplers", "skins" })
            {
                Assert.That(JsonNode.DeepEquals(writtenJson[key], originalJson[key]), Is.True, $"{name}: {key} copied");
            }

            Assert.That(written.LogicalNodes.Select(n => n.Name), Is.EqualTo(original.LogicalNodes.Select(n => n.Name)));
            Assert.That(written.LogicalImages[0].Content.Content.ToArray(), Is.EqualTo(ForeignRig.Png), "texture embedded");
            Assert.That(written.LogicalBuffers, Has.Count.EqualTo(1));
            Assert.That(written.LogicalAnimations, Has.Count.EqualTo(1));
        });
        Assert.That(written.LogicalSkins[0].InverseBindMatrices, Is.EqualTo(original.LogicalSkins[0].InverseBindMatrices), "inverse bind matrices");
        Assert.That(written.LogicalMeshes[0].Primitives[0].GetVertexAccessor("POSITION").AsVector3Array(), Is.EqualTo(original.LogicalMeshes[0].Primitives[0].GetVertexAccessor("POSITION").AsVector3Array()), "vertices");

        // Evaluate the written node hierarchy at each key: every bone where forward kinematics puts it, with the
        // rotation it has in the rig and the scale it has in the user's file.
        IReadOnlyList<Node> nodes = written.LogicalNodes;
        int[] parents = writtenModel.NodeParents();
        Matrix4x4[] restWorld = originalModel.WorldTransforms();
        var channels = GlbChannels.Of(written.LogicalAnimations[0]);
        Assert.That(channels.Values.Select(c => c.Times), Has.All.EqualTo(frames.Select(f => f.Time)));
        var keyed = channels.ToDictionary(c => c.Key, c => c.Value.Values);

        var expected = new Vector3[rig.Joints.Count];
        var expectedRotations = new Quaternion[rig.Joints.Count];
        for (int f = 0; f < frames.Count; f++)
        {
            rig.Solve(frames[f].Root, frames[f].Angles, expected, expectedRotations);
            var world = new Matrix4x4?[nodes.Count];
            Matrix4x4 World(int n)
            {
                if (world[n] is Matrix4x4 done)
                {
                    return done;
                }

                Matrix4x4 local = writtenModel.LocalTransform(nodes[n]);
                if (keyed.ContainsKey((n, "translation")) || keyed.ContainsKey((n, "rotation")))
                {
                    Assert.That(nodes[n].LocalTransform.IsMatrix, Is.False, "animated nodes have no matrix");
                    Matrix4x4.Decompose(local, out Vector3 s, out Quaternion r, out Vector3 t);
                    if (keyed.TryGetValue((n, "translation"), out float[]? tk))
                    {
                        t = new Vector3(tk[3 * f], tk[(3 * f) + 1], tk[(3 * f) + 2]);
                    }

                    if (keyed.TryGetValue((n, "rotation"), out float[]? rk))
                    {
                        r = new Quaternion(rk[4 * f], rk[(4 * f) + 1], rk[(4 * f) + 2], rk[(4 * f) + 3]);
                    }

                    local = Matrix4x4.CreateScale(s) * Matrix4x4.CreateFromQuaternion(r) * Matrix4x4.CreateTranslation(t);
                }

                Matrix4x4 result = parents[n] >= 0 ? local * World(parents[n]) : local;
                world[n] = result;
                return result;
            }

            for (int j = 0; j < rig.Joints.Count; j++)
            {
                int node = model.Source!.JointNodes[j];
                Assert.That(nodes[node].Name, Is.EqualTo(rig.Joints[j].Name));
                Matrix4x4 m = World(node);
                Assert.That(Vector3.Distance(m.Translation, expected[j]), Is.LessThan(1e-3f), $"{name}: bone {rig.Joints[j].Name} at frame {f}");
                float scale = new Vector3(m.M11, m.M12, m.M13).Length();
                float restScale = new Vector3(restWorld[node].M11, restWorld[node].M12, restWorld[node].M13).Length();
                Assert.That(scale, Is.EqualTo(restScale).Within(1e-4f * restScale), $"{name}: bone {rig.Joints[j].Name} keeps its scale");
                Vector3 xAxis = Vector3.Normalize(new Vector3(m.M11, m.M12, m.M13));
                Vector3 yAxis = Vector3.Normalize(new Vector3(m.M21, m.M22, m.M23));
                Assert.Multiple(() =>
                {
                    Assert.That(Vector3.Distance(xAxis, Vector3.Transform(Vector3.UnitX, expectedRotations[j])), Is.LessThan(2e-3f), $"{name}: bone {rig.Joints[j].Name} rotation at frame {f}");
                    Assert.That(Vector3.Distance(yAxis, Vector3.Transform(Vector3.UnitY, expectedRotations[j])), Is.LessThan(2e-3f), $"{name}: bone {rig.Joints[j].Name} rotation at frame {f}");
                });
            }
        }
    }

    [TestCaseSource(nameof(Characters))]
    public void ASavedSpecReloadsToTheSameCharacter(string name)
    {
        ForeignCharacter character = Character(name);
        (string gltf, string spec) = character.Write(_folder);
        (CharacterModel model, ReducedCharacter reduced) = CharacterSpecFile.Load(gltf, spec);
        string saved = Path.Combine(_folder, "saved.limbs.json");
        CharacterSpecFile.Save(model, reduced, saved);
        (CharacterModel again, ReducedCharacter againReduced) = CharacterSpecFile.Load(gltf, saved);
        Assert.Multiple(() =>
        {
            Assert.That(again.Rig.Joints.Select(j => j.Name), Is.EqualTo(model.Rig.Joints.Select(j => j.Name)));
            Assert.That(again.Rig.DofCount, Is.EqualTo(model.Rig.DofCount));
            Assert.That(Vector3.Distance(again.Rig.RootOffset, model.Rig.RootOffset), Is.LessThan(1e-5f));
            Assert.That(Vector3.Distance(againReduced.TrunkHalfExtents, reduced.TrunkHalfExtents), Is.LessThan(1e-5f));
            Assert.That(again.BoneRadii, Is.EqualTo(model.BoneRadii).Within(1e-6f));
            Assert.That(again.TrunkJoints, Is.EqualTo(model.TrunkJoints));
            for (int l = 0; l < model.Limbs.Count; l++)
            {
                Assert.That(Vector3.Distance(again.Limbs[l].EffectorOffset, model.Limbs[l].EffectorOffset), Is.LessThan(1e-5f), model.Limbs[l].Name);
                Assert.That(Vector3.Distance(again.Limbs[l].ContactNormal, model.Limbs[l].ContactNormal), Is.LessThan(1e-5f), model.Limbs[l].Name);
                Assert.That(again.Limbs[l].Filter, Is.EqualTo(model.Limbs[l].Filter), model.Limbs[l].Name);
            }
        });
        Assert.That(File.ReadAllText(saved), character.Spec.Contains("forwardAxis", StringComparison.Ordinal) ? Does.Contain("\"forwardAxis\": \"") : Does.Not.Contain("forwardAxis"));
    }

    [TestCaseSource(nameof(Characters))]
    public void TheReducedModelLoadsIntoAPlanningScene(string name)
    {
        ForeignCharacter character = Character(name);
        (_, ReducedCharacter reduced, _, _) = LoadAtRest(character);
        var scene = PlanningScene.Create(GapCourse.Build(), reduced);
        Assert.That(scene.Character.Limbs, Has.Count.EqualTo(reduced.Limbs.Count));
        foreach (Limb limb in reduced.Limbs.Where(l => character.Feet.Any(f => f.Limb == l.Name)))
        {
            Assert.That(limb.WorkspaceCenter.Y, Is.LessThan(0f), $"{name} {limb.Name}: the foot's workspace lies below the trunk centre");
        }
    }

    [Test]
    [Category("EndToEnd")]
    public void TheHumanPlansAcrossTheGapCourse()
    {
        (_, ReducedCharacter reduced, _, _) = LoadAtRest(ForeignCharacters.Human(zUpScene: true));
        var scene = PlanningScene.Create(GapCourse.Build(), reduced);
        BakeResult bake = new RoadmapBaker(scene).Bake(new BakeSettings { MaxNodes = 300, Start = GapCourse.From, Goal = GapCourse.To, StopWhenConnected = true, Threads = 2 });
        PlanResult plan = new PathQuery(scene, bake.Roadmap).Plan(GapCourse.From, GapCourse.To);
        Assert.That(plan.Status, Is.EqualTo(PlannerStatus.Exact), plan.Reason);
    }

    private static ForeignCharacter Character(string name) => name switch
    {
        "human" => ForeignCharacters.Human(zUpScene: false),
        "human-zup" => ForeignCharacters.Human(zUpScene: true),
        "dog" => ForeignCharacters.Dog(),
        "tailed" => ForeignCharacters.TailedQuadruped(),
        _ => throw new ArgumentException(name),
    };

    private (CharacterModel Model, ReducedCharacter Reduced, Vector3[] Positions, Quaternion[] Rotations) LoadAtRest(ForeignCharacter character)
    {
        (string gltf, string spec) = character.Write(_folder);
        (CharacterModel model, ReducedCharacter reduced) = CharacterSpecFile.Load(gltf, spec);
        var positions = new Vector3[model.Rig.Joints.Count];
        var rotations = new Quaternion[model.Rig.Joints.Count];
        model.Rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), new float[model.Rig.DofCount], positions, rotations);
        return (model, reduced, positions, rotations);
    }
}
