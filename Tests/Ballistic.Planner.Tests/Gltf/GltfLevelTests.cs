using System.Numerics;
using System.Text;
using System.Text.Json.Nodes;
using Ballistic.Authoring.Gltf;
using Ballistic.Authoring.Levels;
using Ballistic.Planner.Gltf;
using Ballistic.Planner.IO;
using Ballistic.Planner.Levels;
using SharpGLTF.Schema2;
using SharpGLTF.Transforms;

namespace Ballistic.Planner.Tests.Gltf;

public sealed class GltfLevelTests
{
    private static readonly LevelMesh Floor = new("Floor", [new(0f, 0f, 0f), new(4f, 0f, 0f), new(4f, 0f, 4f), new(0f, 0f, 4f)], [0, 2, 1, 0, 3, 2], new LevelMaterial("sand", null), new Vector4(0.8f, 0.7f, 0.5f, 1f));
    private static readonly LevelMesh Ice = new("Ice", [new(5f, 1f, 0f), new(6f, 1f, 0f), new(6f, 1f, 1f)], [0, 2, 1], new LevelMaterial("ice", 0.05f), new Vector4(0.8f, 0.9f, 1f, 1f));

    [Test]
    public void WrittenLevelsReadBackExactly()
    {
        string path = Temp(".glb");
        try
        {
            GltfLevelWriter.Save(path, [Floor, Ice]);
            Level level = GltfLevelLoader.Load(path);
            Assert.Multiple(() =>
            {
                Assert.That(level.Triangles, Has.Count.EqualTo(3));
                Assert.That(level.Triangles[0].A, Is.EqualTo(new Vector3(0f, 0f, 0f)));
                Assert.That(level.Triangles[0].B, Is.EqualTo(new Vector3(4f, 0f, 4f)));
                Assert.That(Vector3.Distance(level.Triangles[0].Normal, Vector3.UnitY), Is.LessThan(1e-6f));
                Assert.That(level.FrictionOf(0, 0.5f), Is.EqualTo(0.5f));
                Assert.That(level.FrictionOf(2, 0.5f), Is.EqualTo(0.05f));
                Assert.That(level.Materials.Select(m => m.Name), Is.EquivalentTo(new[] { "sand", "ice" }));
            });
        }
        finally
        {
            File.Delete(path);
        }
    }

    [Test]
    public void NodeHierarchyTransformsApplyParentFirst()
    {
        // Parent: translate (10, 0, 0) and turn 90° about Y; child: translate (1, 2, 0) holding the mesh.
        ModelRoot root = GltfWrite.Create();
        float s = MathF.Sqrt(0.5f);
        Node parent = root.UseScene(0).CreateNode("parent");
        parent.LocalTransform = new AffineTransform(null, new Quaternion(0f, s, 0f, s), new Vector3(10f, 0f, 0f));
        Node child = parent.CreateNode("child");
        child.LocalTransform = new AffineTransform(null, null, new Vector3(1f, 2f, 0f));
        child.Mesh = root.CreateMesh();
        child.Mesh.CreatePrimitive().SetVertexAccessor("POSITION", GltfWrite.Vectors(root, [new(0f, 0f, 0f), new(1f, 0f, 0f), new(0f, 0f, -1f)]));

        Level level = GltfLevelLoader.Build(GltfModel.Parse(GltfWrite.Glb(root), "t.glb", null), "t.glb");
        // The child's origin (1, 2, 0) turned 90° about Y is (0, 2, −1), then moved to (10, 2, −1).
        Assert.That(Vector3.Distance(level.Triangles[0].A, new Vector3(10f, 2f, -1f)), Is.LessThan(1e-5f));
        Assert.That(Vector3.Distance(level.Triangles[0].B, new Vector3(10f, 2f, -2f)), Is.LessThan(1e-5f));
    }

    [Test]
    public void MatrixNodesAndTextGltfWithDataUrisAreRead()
    {
        byte[] glb = GltfLevelWriter.ToBytes([Floor]);
        // Re-express as a .gltf text file: the binary chunk as a base64 data URI, the node moved by a matrix.
        (JsonObject root, byte[] bin) = Fuzz.FuzzInputs.SplitGlb(glb);
        root["buffers"] = new JsonArray(new JsonObject { ["byteLength"] = bin.Length, ["uri"] = "data:application/octet-stream;base64," + Convert.ToBase64String(bin) });
        ((JsonObject)((JsonArray)root["nodes"]!)[0]!)["matrix"] = new JsonArray(1f, 0f, 0f, 0f, 0f, 1f, 0f, 0f, 0f, 0f, 1f, 0f, 0f, 3f, 0f, 1f);
        Level level = GltfLevelLoader.Build(GltfModel.Parse(Encoding.UTF8.GetBytes(root.ToJsonString()), "f.gltf", null), "f.gltf");
        Assert.That(level.Bounds.Min.Y, Is.EqualTo(3f));
    }

    [Test]
    public void FrictionInTheMaterialNameIsRead()
    {
        var named = Floor with { Material = new LevelMaterial("Wet rock (mu=0.3)", null) };
        byte[] glb = GltfLevelWriter.ToBytes([named]);
        Level level = GltfLevelLoader.Build(GltfModel.Parse(glb, "n.glb", null), "n.glb");
        Assert.That(level.FrictionOf(0, 1f), Is.EqualTo(0.3f));
    }

    [Test]
    public void SurfaceCostsInTheMaterialsExtrasAreWrittenAndRead()
    {
        var mud = Floor with { Material = new LevelMaterial("mud", 0.4f) { TravelCost = 3f, EnterCost = 2.5f } };
        byte[] glb = GltfLevelWriter.ToBytes([mud, Ice]);
        Level level = GltfLevelLoader.Build(GltfModel.Parse(glb, "c.glb", null), "c.glb");
        LevelMaterial read = level.Materials[level.MaterialIndices[0]];
        LevelMaterial ice = level.Materials[level.MaterialIndices[2]];
        Assert.Multiple(() =>
        {
            Assert.That((read.Name, read.Friction, read.TravelCost, read.EnterCost), Is.EqualTo(("mud", (float?)0.4f, 3f, 2.5f)));
            Assert.That((ice.TravelCost, ice.EnterCost), Is.EqualTo((1f, 0f)), "no extras, no cost");
            Assert.That(level.Fingerprint, Is.EqualTo(GltfLevelLoader.Build(GltfModel.Parse(GltfLevelWriter.ToBytes([Floor with { Material = new LevelMaterial("mud", 0.4f) }, Ice]), "c.glb", null), "c.glb").Fingerprint),
                "costs change no roadmap: the fingerprint leaves them out");
        });
    }

    [TestCase("\"travelCost\": \"high\"", "c.glb: material 'sand' sets extras.travelCost to the string \"high\", not a number.")]
    [TestCase("\"travelCost\": 0.5", "c.glb: material 'sand': its travel cost 0.5 must be a number from 1 to 1000.")]
    [TestCase("\"enterCost\": -2", "c.glb: material 'sand': its enter cost -2 must be a number of seconds from 0 to 10000.")]
    public void SurfaceCostsThatAreNotNumbersInRangeAreRefusedInOneLine(string extra, string message)
    {
        (JsonObject root, byte[] bin) = Fuzz.FuzzInputs.SplitGlb(GltfLevelWriter.ToBytes([Floor]));
        root["buffers"] = new JsonArray(new JsonObject { ["byteLength"] = bin.Length, ["uri"] = "data:application/octet-stream;base64," + Convert.ToBase64String(bin) });
        ((JsonObject)((JsonArray)root["materials"]!)[0]!)["extras"] = JsonNode.Parse("{" + extra + "}");
        Assert.That(() => GltfLevelLoader.Build(GltfModel.Parse(Encoding.UTF8.GetBytes(root.ToJsonString()), "c.glb", null), "c.glb"),
            Throws.InstanceOf<BallisticInputException>().With.Message.EqualTo(message));
    }

    [Test]
    public void BadFilesGiveErrorsNamingTheFile()
    {
        string truncated = Temp(".glb");
        string text = Temp(".glb");
        string draco = Temp(".gltf");
        try
        {
            byte[] glb = GltfLevelWriter.ToBytes([Floor]);
            File.WriteAllBytes(truncated, glb[..(glb.Length - 20)]);
            File.WriteAllText(text, "this is not glTF");
            File.WriteAllText(draco, """{"asset":{"version":"2.0"},"extensionsRequired":["KHR_draco_mesh_compression"]}""");
            Assert.Multiple(() =>
            {
                Assert.That(() => GltfLevelLoader.Load(truncated), Throws.TypeOf<LevelException>().With.Message.Contains(truncated).And.Message.Contains("truncated"));
                Assert.That(() => GltfLevelLoader.Load(text), Throws.TypeOf<LevelException>().With.Message.Contains("not a glTF file"));
                Assert.That(() => GltfLevelLoader.Load(draco), Throws.TypeOf<LevelException>().With.Message.Contains("KHR_draco_mesh_compression"));
                Assert.That(() => GltfLevelLoader.Load(truncated + ".missing"), Throws.TypeOf<LevelException>().With.Message.Contains("cannot be read"));
            });
        }
        finally
        {
            File.Delete(truncated);
            File.Delete(text);
            File.Delete(draco);
        }
    }

    [Test]
    public void NonFiniteVerticesInAFileNameTheMesh()
    {
        // The writer refuses to write infinity; patch the first vertex's x in the binary chunk instead.
        var bad = Floor with { Name = "BrokenRock" };
        Assert.That(() => GltfLevelWriter.ToBytes([bad with { Positions = [new(float.PositiveInfinity, 0f, 0f), .. bad.Positions[1..]] }]), Throws.TypeOf<GltfException>().With.Message.Contains("finite"));
        byte[] glb = GltfLevelWriter.ToBytes([bad]);
        int binStart = 20 + BitConverter.ToInt32(glb, 12) + 8;
        BitConverter.GetBytes(float.PositiveInfinity).CopyTo(glb, binStart);
        Assert.That(() => GltfLevelLoader.Build(GltfModel.Parse(glb, "b.glb", null), "b.glb"), Throws.TypeOf<GltfException>().With.Message.EqualTo("b.glb: accessor 0 (POSITION of primitive 0 of mesh 0 ('BrokenRock')): POSITION[0]: Invalid Position."));
    }

    private static string Temp(string extension) => Path.Combine(Path.GetTempPath(), $"ballistic-{Guid.NewGuid():N}{extension}");
}
