using System.Diagnostics;
using System.Runtime.InteropServices;
using System.Text.Json.Nodes;
using Ballistic.Planner.Gltf;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Rigs;

/// <summary>
/// Characters crafted to read other files, wait forever or exhaust memory (tracker issue 8): the glTF's buffers and
/// images stay in its folder, the spec and glTF must be regular files within the byte limit, skins and bones are
/// checked, and every problem is one <see cref="RigException"/> sentence.
/// </summary>
public sealed class HostileCharacterTests
{
    private string _folder = "";

    [SetUp]
    public void MakeFolder()
    {
        _folder = Path.Combine(Path.GetTempPath(), $"ballistic-hostile-rig-{Guid.NewGuid():N}");
        Directory.CreateDirectory(_folder);
    }

    [TearDown]
    public void RemoveFolder() => Directory.Delete(_folder, recursive: true);

    [Test]
    public void BuffersAndImagesOfACharacterStayInItsFolder()
    {
        ForeignCharacter dog = ForeignCharacters.Dog();
        string inner = Path.Combine(_folder, "dog");
        Directory.CreateDirectory(inner);
        string gltf = dog.Rig.WriteGltf(inner, "dog");
        string spec = Path.Combine(inner, "dog.limbs.json");
        File.WriteAllText(spec, dog.Spec);
        Assert.That(CharacterSpecFile.Load(gltf, spec).Model.Source, Is.Not.Null, "the character as written loads");

        // The same buffer and image, moved one folder up: following "../" would read them.
        File.Move(Path.Combine(inner, "dog.bin"), Path.Combine(_folder, "dog.bin"));
        File.Move(Path.Combine(inner, "dog.png"), Path.Combine(_folder, "dog.png"));
        JsonObject json = JsonNode.Parse(File.ReadAllText(gltf))!.AsObject();
        json["buffers"]![0]!["uri"] = "../dog.bin";
        File.WriteAllText(gltf, json.ToJsonString());
        string message = Assert.Throws<RigException>(() => CharacterSpecFile.Load(gltf, spec))!.Message;
        Assert.That(message, Does.Contain("dog.gltf: buffer 0's URI '../dog.bin' leads out of the glTF's folder"));

        File.Move(Path.Combine(_folder, "dog.bin"), Path.Combine(inner, "dog.bin"));
        json["buffers"]![0]!["uri"] = "dog.bin";
        json["images"]![0]!["uri"] = "../dog.png";
        File.WriteAllText(gltf, json.ToJsonString());
        // SharpGLTF reads every image as it reads the file, through the callback that confines them: the rig does not
        // load, so no animated GLB can embed it either.
        Assert.That(Assert.Throws<RigException>(() => CharacterSpecFile.Load(gltf, spec))!.Message, Does.Contain("dog.gltf: image 0's URI '../dog.png' leads out of the glTF's folder"));
    }

    [Test]
    public void SpecFilesMustBeRegularAndWithinTheByteLimit()
    {
        string glb = Path.Combine(RepositoryFiles.Root, "Scenes", "characters", "frog.glb");
        string spec = Path.Combine(RepositoryFiles.Root, "Scenes", "characters", "frog.limbs.json");
        long size = new FileInfo(spec).Length;
        Assert.Multiple(() =>
        {
            Assert.That(() => CharacterSpecFile.Load(glb, spec, new GltfLoadOptions { MaxBytes = 100 }),
                Throws.TypeOf<RigException>().With.Message.Contains($"Limb spec {spec} is {size} bytes, more than the 100 bytes allowed (GltfLoadOptions.MaxBytes)"));
            Assert.That(() => CharacterSpecFile.Load(glb, _folder), Throws.TypeOf<RigException>().With.Message.Contains("is a folder, not a file"));
            Assert.That(() => CharacterSpecFile.Load(glb, spec, new GltfLoadOptions { MaxVertices = 100 }),
                Throws.TypeOf<RigException>().With.Message.Contains("the character's skinned meshes read more than 100 vertices (GltfLoadOptions.MaxVertices)"));
        });

        if (OperatingSystem.IsLinux())
        {
            string pipe = Path.Combine(_folder, "frog.limbs.json");
            using (var mkfifo = Process.Start(new ProcessStartInfo("mkfifo", [pipe]) { UseShellExecute = false })!)
            {
                mkfifo.WaitForExit();
            }

            string zero = Path.Combine(_folder, "frog.glb");
            File.CreateSymbolicLink(zero, "/dev/zero");
            var load = Task.Run(() => Assert.Throws<RigException>(() => CharacterSpecFile.Load(glb, pipe))!.Message);
            Assert.That(load.Wait(TimeSpan.FromSeconds(10)), Is.True, "reading a named pipe waits for a writer");
            Assert.That(load.Result, Does.Contain("frog.limbs.json is a named pipe, not a regular file"));
            Assert.That(() => CharacterSpecFile.Load(zero, spec), Throws.TypeOf<RigException>().With.Message.Contains("frog.glb is a character device, not a regular file"));
        }
    }

    [Test]
    public void SkinsListingABoneTwiceAndBonesFarAwayAreNamed()
    {
        var dog = new BrokenDog(_folder);
        JsonObject pristine = dog.Pristine;
        string Broken(Action<JsonObject> change) => dog.Load(change);

        Assert.Multiple(() =>
        {
            int first = pristine["skins"]![0]!["joints"]![0]!.GetValue<int>();
            Assert.That(Broken(j => j["skins"]![0]!["joints"]!.AsArray().Add(first)), Does.Contain($"skin 0 lists node {first} as a joint twice"));
            Assert.That(Broken(j => j["nodes"]![first]!["translation"] = new JsonArray(1e30f, 0, 0)), Does.Contain("bone 'pelvis' has a scale or translation beyond ±1e6"));
            Assert.That(Broken(j => j["nodes"]![first]!["scale"] = new JsonArray(1e30f, 1e30f, 1e30f)), Does.Contain("bone 'pelvis' has a scale or translation beyond ±1e6"));
            Assert.That(Broken(j => j["accessors"]![0]!["count"] = 150_000_000), Does.Contain("dog.gltf: accessor 0 (POSITION of primitive 0 of mesh 0 ('Body')): BufferView[0]"));
            Assert.That(Broken(j => j["nodes"]![first]!["children"]!.AsArray().Add(first)), Does.Contain("lists itself as a child"));
        });
    }

    [Test]
    public void SingularInverseBindMatricesAndBadSkinWeightsAreNamed()
    {
        // Before, an all-zero inverse bind matrix folded the skinned mesh onto a point and NaN or negative weights
        // were skipped: both loaded and were written back into the animated GLB.
        var dog = new BrokenDog(_folder);
        JsonObject pristine = dog.Pristine;
        int inverseBind = pristine["skins"]![0]!["inverseBindMatrices"]!.GetValue<int>();
        int joint = pristine["skins"]![0]!["joints"]![1]!.GetValue<int>();
        int weights = pristine["meshes"]![0]!["primitives"]![0]!["attributes"]!["WEIGHTS_0"]!.GetValue<int>();

        // Matrix 1 (glTF's column-major floats 16 to 31) changed by change(floats).
        string Matrix(Action<float[]> change) => dog.LoadPatched((json, bin) =>
        {
            Span<float> floats = MemoryMarshal.Cast<byte, float>(BrokenDog.Bytes(json, bin, inverseBind).Bytes.Span)[16..32];
            float[] matrix = floats.ToArray();
            change(matrix);
            matrix.CopyTo(floats);
        });

        string Weight(float w) => dog.LoadPatched((json, bin) =>
        {
            (Memory<byte> bytes, int type) = BrokenDog.Bytes(json, bin, weights);
            Assert.That(type, Is.EqualTo(5126), "the dog's weights are floats");
            MemoryMarshal.Cast<byte, float>(bytes.Span)[0] = w;
        });

        Assert.Multiple(() =>
        {
            Assert.That(Matrix(m => Array.Clear(m)), Does.Contain($"dog.gltf: accessor {inverseBind} (the inverse bind matrices of skin 0").And.Contain("Invalid Matrix"));
            Assert.That(Matrix(m => Array.Clear(m, 0, 11)), Does.Contain($"accessor {inverseBind} (the inverse bind matrices of skin 0").And.Contain("Invalid Matrix"));
            Assert.That(Matrix(m => m[5] = float.NaN), Does.Contain($"accessor {inverseBind} (the inverse bind matrices of skin 0").And.Contain("Invalid Matrix"));
            Assert.That(Weight(float.NaN), Does.Contain("dog.gltf: mesh primitive 0: weights0: Weight Sum invalid at Index 0"));
            Assert.That(Weight(-0.5f), Does.Contain("dog.gltf: mesh primitive 0: weights0: Weight Sum invalid at Index 0"));
        });
    }
}
