using System.Numerics;
using System.Text.Json.Nodes;
using Ballistic.Authoring.Animation;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Gltf;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;
using SharpGLTF.Schema2;

namespace Ballistic.Planner.Tests.Rigs;

/// <summary>
/// A user's rig that already has clips: the animated GLB puts our <c>jumps</c> clip first, the clip Blender's importer
/// makes the armature's action and Godot lists first, and keeps the user's clips after it, unchanged.
/// </summary>
public sealed class ClipOrderTests
{
    private string _folder = "";

    [SetUp]
    public void MakeFolder()
    {
        _folder = Path.Combine(Path.GetTempPath(), $"ballistic-clips-{Guid.NewGuid():N}");
        Directory.CreateDirectory(_folder);
    }

    [TearDown]
    public void RemoveFolder() => Directory.Delete(_folder, recursive: true);

    [Test]
    public void OurClipComesFirstAndTheUsersClipsFollowUnchanged()
    {
        ForeignCharacter dog = ForeignCharacters.Dog();
        (string gltf, string spec) = dog.Write(_folder);
        AddClips(gltf, dog.Rig["pelvis"], "Idle", "Run");
        (CharacterModel model, _) = CharacterSpecFile.Load(gltf, spec);

        var frames = new List<AnimationFrame>
        {
            new(0f, new RootPose(new Vector3(0f, 0.5f, 0f), Quaternion.Identity), new float[model.Rig.DofCount]),
            new(0.5f, new RootPose(new Vector3(1f, 0.8f, 0f), Quaternion.Identity), new float[model.Rig.DofCount]),
        };
        byte[] glb = AnimatedGlbWriter.ToBytes(new JumpAnimation(model, Array.Empty<Move>(), [], frames, [], [], 0, 0), "jumps");

        // CI runs the Khronos validator on it too (it sets BALLISTIC_GLTF_OUT).
        if (Environment.GetEnvironmentVariable("BALLISTIC_GLTF_OUT") is { Length: > 0 } validate)
        {
            Directory.CreateDirectory(validate);
            File.WriteAllBytes(Path.Combine(validate, "dog-with-clips-animated.glb"), glb);
        }

        ModelRoot original = GltfModel.Load(gltf).Root;
        ModelRoot written = ModelRoot.ParseGLB(glb);
        IReadOnlyList<SharpGLTF.Schema2.Animation> clips = written.LogicalAnimations;
        Assert.Multiple(() =>
        {
            Assert.That(clips.Select(c => c.Name), Is.EqualTo(new[] { "jumps", "Idle", "Run" }));
            for (int i = 0; i < 2; i++)
            {
                var theirs = GlbChannels.Of(original.LogicalAnimations[i]);
                var ours = GlbChannels.Of(clips[i + 1]);
                Assert.That(ours.Keys, Is.EqualTo(theirs.Keys), $"{clips[i + 1].Name}: channels kept");
                foreach (var channel in theirs)
                {
                    Assert.That(ours[channel.Key].Times, Is.EqualTo(channel.Value.Times), $"{clips[i + 1].Name}: key times kept");
                    Assert.That(ours[channel.Key].Values, Is.EqualTo(channel.Value.Values), $"{clips[i + 1].Name}: keys kept");
                }
            }

            Assert.That(clips[0].Channels, Is.Not.Empty, "our clip is keyed");
        });
    }

    /// <summary>Adds clips of two keys each rotating <paramref name="node"/>, in a buffer of their own (a data URI).</summary>
    private static void AddClips(string gltfPath, int node, params string[] names)
    {
        var root = JsonNode.Parse(File.ReadAllText(gltfPath))!.AsObject();
        var floats = new List<float>();
        var animations = new JsonArray();
        var buffers = root["buffers"]!.AsArray();
        var views = root["bufferViews"]!.AsArray();
        var accessors = root["accessors"]!.AsArray();
        int buffer = buffers.Count;
        foreach (string name in names)
        {
            Quaternion turn = Quaternion.CreateFromAxisAngle(Vector3.UnitY, 0.3f * (animations.Count + 1));
            int timeOffset = floats.Count * 4;
            floats.AddRange([0f, 1f]);
            int rotationOffset = floats.Count * 4;
            floats.AddRange([0f, 0f, 0f, 1f, turn.X, turn.Y, turn.Z, turn.W]);
            views.Add(new JsonObject { ["buffer"] = buffer, ["byteOffset"] = timeOffset, ["byteLength"] = 8 });
            accessors.Add(new JsonObject { ["bufferView"] = views.Count - 1, ["componentType"] = 5126, ["count"] = 2, ["type"] = "SCALAR", ["min"] = new JsonArray(0f), ["max"] = new JsonArray(1f) });
            int input = accessors.Count - 1;
            views.Add(new JsonObject { ["buffer"] = buffer, ["byteOffset"] = rotationOffset, ["byteLength"] = 32 });
            accessors.Add(new JsonObject { ["bufferView"] = views.Count - 1, ["componentType"] = 5126, ["count"] = 2, ["type"] = "VEC4" });
            animations.Add(new JsonObject
            {
                ["name"] = name,
                ["samplers"] = new JsonArray(new JsonObject { ["input"] = input, ["output"] = accessors.Count - 1, ["interpolation"] = "LINEAR" }),
                ["channels"] = new JsonArray(new JsonObject { ["sampler"] = 0, ["target"] = new JsonObject { ["node"] = node, ["path"] = "rotation" } }),
            });
        }

        byte[] bytes = new byte[floats.Count * 4];
        System.Buffer.BlockCopy(floats.ToArray(), 0, bytes, 0, bytes.Length);
        buffers.Add(new JsonObject { ["byteLength"] = bytes.Length, ["uri"] = "data:application/octet-stream;base64," + Convert.ToBase64String(bytes) });
        root["animations"] = animations;
        File.WriteAllText(gltfPath, root.ToJsonString());
    }
}
