using System.Numerics;
using System.Runtime.InteropServices;
using System.Text.Json.Nodes;
using Ballistic.Authoring.Animation;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;
using SharpGLTF.Schema2;

namespace Ballistic.Planner.Tests.Rigs;

/// <summary>
/// The animated GLB of a user's rig, written through SharpGLTF and read back by it as an importer would: the same
/// bytes for the same input, the user's generator named beside ours, skin weights an exporter left summing a little off
/// one normalised, and a rig that loaded repaired (stale accessor bounds) written with bounds that hold.
/// </summary>
public sealed class WrittenRigTests
{
    private string _folder = "";

    [SetUp]
    public void MakeFolder()
    {
        _folder = Path.Combine(Path.GetTempPath(), $"ballistic-written-{Guid.NewGuid():N}");
        Directory.CreateDirectory(_folder);
    }

    [TearDown]
    public void RemoveFolder() => Directory.Delete(_folder, recursive: true);

    [Test]
    public void TheSameRigAndClipGiveTheSameBytesAndNameBothGenerators()
    {
        (string gltf, string spec) = ForeignCharacters.Dog().Write(_folder);
        byte[] first = Animated(CharacterSpecFile.Load(gltf, spec).Model);
        byte[] second = Animated(CharacterSpecFile.Load(gltf, spec).Model);

        ModelRoot written = ModelRoot.ParseGLB(first);
        Assert.Multiple(() =>
        {
            Assert.That(first.AsSpan().SequenceEqual(second), Is.True, "loaded twice, written twice: the same bytes");
            Assert.That(written.Asset.Generator, Is.EqualTo("Ballistic (from ForeignRig test exporter)"));
            Assert.That(written.LogicalAnimations.Select(a => a.Name), Is.EqualTo(new[] { "jumps" }));
        });
    }

    [Test]
    public void WeightsSummingALittleOffOneAsAssimpWritesThemAreWrittenNormalised()
    {
        // Written as a .gltf with its buffer in a .bin file beside it, to be changed in place.
        ForeignCharacter dog = ForeignCharacters.Dog();
        string gltf = dog.Rig.WriteGltf(_folder, "dog");
        string spec = Path.Combine(_folder, "dog.limbs.json");
        File.WriteAllText(spec, dog.Spec);
        JsonObject json = JsonNode.Parse(File.ReadAllText(gltf))!.AsObject();
        int weights = json["meshes"]![0]!["primitives"]![0]!["attributes"]!["WEIGHTS_0"]!.GetValue<int>();
        int count = json["accessors"]![weights]!["count"]!.GetValue<int>();
        string bin = Path.Combine(_folder, json["buffers"]![0]!["uri"]!.GetValue<string>());
        byte[] bytes = File.ReadAllBytes(bin);
        (Memory<byte> at, int type) = BrokenDog.Bytes(json, bytes, weights);
        Assert.That(type, Is.EqualTo(5126), "the dog's weights are floats");
        Span<float> values = MemoryMarshal.Cast<byte, float>(at.Span)[..(4 * count)];
        float[] before = values.ToArray();
        Assert.That(before.Where((w, i) => i % 4 == 0), Has.Some.LessThan(1f), "some vertices are blended between two bones");
        for (int i = 0; i < values.Length; i++)
        {
            values[i] *= 0.999999f;
        }

        File.WriteAllBytes(bin, bytes);

        // SharpGLTF's strict validation refuses sums more than about 2e-7 off one; its repairing mode, which the rig is
        // then read in (and read again in to be written), rescales them.
        CharacterModel model = CharacterSpecFile.Load(gltf, spec).Model;
        Assert.That(model.Source!.Model.Repaired, Does.Contain("Weight Sum invalid"), "loaded as repaired");
        byte[] glb = Animated(model);
        Keep(glb, "dog-weights-off-animated.glb");

        Vector4[] written = [.. ModelRoot.ParseGLB(glb).LogicalMeshes[0].Primitives[0].GetVertexAccessor("WEIGHTS_0").AsVector4Array()];
        Assert.Multiple(() =>
        {
            Assert.That(written, Has.Length.EqualTo(count));
            for (int v = 0; v < count; v++)
            {
                float sum = written[v].X + written[v].Y + written[v].Z + written[v].W;
                Assert.That(sum, Is.EqualTo(1f).Within(2.5e-7f), $"vertex {v}'s weights sum to one");
                for (int k = 0; k < 4; k++)
                {
                    Assert.That(written[v][k], Is.EqualTo(before[(4 * v) + k]).Within(1e-6f), $"vertex {v}'s weight {k} is the exporter's, rescaled");
                }
            }
        });
    }

    [Test]
    public void ARigThatLoadedRepairedIsWrittenWithBoundsThatHold()
    {
        (string gltf, string spec) = ForeignCharacters.Dog().Write(_folder);
        JsonObject json = JsonNode.Parse(File.ReadAllText(gltf))!.AsObject();
        int position = json["meshes"]![0]!["primitives"]![0]!["attributes"]!["POSITION"]!.GetValue<int>();
        json["accessors"]![position]!["max"] = new JsonArray(0.01, 0.01, 0.01);
        File.WriteAllText(gltf, json.ToJsonString());

        CharacterModel model = CharacterSpecFile.Load(gltf, spec).Model;
        Assert.That(model.Source!.Model.Repaired, Does.Contain($"accessor {position}"), "loaded as repaired");
        byte[] glb = Animated(model);
        Keep(glb, "dog-stale-bounds-animated.glb");

        // SharpGLTF's strict validation (ParseGLB's default) refuses bounds that the data exceeds.
        Accessor written = ModelRoot.ParseGLB(glb).LogicalMeshes[0].Primitives[0].GetVertexAccessor("POSITION");
        Vector3[] points = [.. written.AsVector3Array()];
        (IReadOnlyList<double> min, IReadOnlyList<double> max) = written.Bounds;
        Vector3 high = points.Aggregate(Vector3.Max);
        Vector3 low = points.Aggregate(Vector3.Min);
        Assert.Multiple(() =>
        {
            Assert.That(max, Is.EqualTo(new double[] { high.X, high.Y, high.Z }));
            Assert.That(min, Is.EqualTo(new double[] { low.X, low.Y, low.Z }));
        });
    }

    /// <summary>The rig's animated GLB over two frames: at rest, then raised and turned with every angle at mid-range.</summary>
    private static byte[] Animated(CharacterModel model)
    {
        Rig rig = model.Rig;
        float[] middle = [.. rig.Dofs.Select(d => 0.5f * (d.Min + d.Max))];
        var frames = new List<AnimationFrame>
        {
            new(0f, new RootPose(new Vector3(0f, 0.5f, 0f), Quaternion.Identity), new float[rig.DofCount]),
            new(0.5f, new RootPose(new Vector3(1f, 0.8f, 0f), Quaternion.CreateFromAxisAngle(Vector3.UnitY, 0.4f)), middle),
        };
        return AnimatedGlbWriter.ToBytes(new JumpAnimation(model, Array.Empty<Move>(), [], frames, [], [], 0, 0), "jumps");
    }

    /// <summary>Keeps <paramref name="glb"/> where CI runs the Khronos validator on it (BALLISTIC_GLTF_OUT), when set.</summary>
    private static void Keep(byte[] glb, string name)
    {
        if (Environment.GetEnvironmentVariable("BALLISTIC_GLTF_OUT") is { Length: > 0 } validate)
        {
            Directory.CreateDirectory(validate);
            File.WriteAllBytes(Path.Combine(validate, name), glb);
        }
    }
}
