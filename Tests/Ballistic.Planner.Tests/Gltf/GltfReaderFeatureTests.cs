using System.Buffers.Binary;
using System.Numerics;
using System.Text;
using Ballistic.Planner.Gltf;
using Ballistic.Planner.Levels;

namespace Ballistic.Planner.Tests.Gltf;

/// <summary>
/// Files shaped the way other exporters write them: interleaved vertex buffers, 8-bit indices, triangle strips,
/// quantised positions, sparse accessors, external buffers.
/// </summary>
public sealed class GltfReaderFeatureTests
{
    [Test]
    public void InterleavedVerticesByteIndicesAndStrips()
    {
        // Four vertices, each position (12 bytes) followed by a normal (12 bytes): stride 24. A strip 0,1,2,3.
        var bin = new List<byte>();
        Vector3[] positions = [new(0f, 0f, 0f), new(0f, 0f, 1f), new(1f, 0f, 0f), new(1f, 0f, 1f)];
        foreach (Vector3 p in positions)
        {
            bin.AddRange(Floats(p.X, p.Y, p.Z, 0f, 1f, 0f));
        }

        bin.AddRange(new byte[] { 0, 1, 2, 3 });
        string json = $$"""
        {"asset":{"version":"2.0","generator":"hand-written exporter-style file"},
         "buffers":[{"byteLength":{{bin.Count}},"uri":"data:application/octet-stream;base64,{{Convert.ToBase64String([.. bin])}}"}],
         "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":96,"byteStride":24},{"buffer":0,"byteOffset":96,"byteLength":4}],
         "accessors":[{"bufferView":0,"byteOffset":0,"componentType":5126,"count":4,"type":"VEC3"},
                      {"bufferView":0,"byteOffset":12,"componentType":5126,"count":4,"type":"VEC3"},
                      {"bufferView":1,"componentType":5121,"count":4,"type":"SCALAR"}],
         "meshes":[{"name":"strip","primitives":[{"attributes":{"POSITION":0,"NORMAL":1},"indices":2,"mode":5}]}],
         "nodes":[{"mesh":0}],
         "scenes":[{"nodes":[0]}],"scene":0}
        """;
        Level level = GltfLevelLoader.Build(GltfModel.Parse(Encoding.UTF8.GetBytes(json), "strip.gltf", null), "strip.gltf");
        Assert.Multiple(() =>
        {
            Assert.That(level.Triangles, Has.Count.EqualTo(2));
            Assert.That(level.Triangles.All(t => Vector3.Distance(t.Normal, Vector3.UnitY) < 1e-6f), Is.True, "strip winding alternates so both triangles face up");
            Assert.That(level.Bounds.Max, Is.EqualTo(new Vector3(1f, 0f, 1f)));
        });
    }

    [Test]
    public void QuantisedPositionsSparseAccessorsAndExternalBuffers()
    {
        // KHR_mesh_quantization: normalised int16 positions scaled by the node. A sparse accessor lifts vertex 2.
        string folder = Path.Combine(Path.GetTempPath(), $"ballistic-gltf-{Guid.NewGuid():N}");
        Directory.CreateDirectory(folder);
        try
        {
            var bin = new List<byte>();
            short[] quantised = [0, 0, 0, 0, 0, 0, 32767, 0, 32767, 0, 0, 0]; // three vertices, each padded to 8 bytes (a vertex stride is a multiple of 4)
            foreach (short q in quantised)
            {
                bin.AddRange(BitConverter.GetBytes(q));
            }

            bin.AddRange(BitConverter.GetBytes((ushort)2)); // sparse index: vertex 2
            bin.AddRange(new byte[2]);
            bin.AddRange(BitConverter.GetBytes((short)32767)); // sparse value: (1, 0.5, 0)
            bin.AddRange(BitConverter.GetBytes((short)16384));
            bin.AddRange(BitConverter.GetBytes((short)0));
            File.WriteAllBytes(Path.Combine(folder, "level data.bin"), [.. bin]);
            string json = """
            {"asset":{"version":"2.0"},"extensionsUsed":["KHR_mesh_quantization"],"extensionsRequired":["KHR_mesh_quantization"],
             "buffers":[{"byteLength":BYTES,"uri":"level%20data.bin"}],
             "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":24,"byteStride":8},{"buffer":0,"byteOffset":24,"byteLength":2},{"buffer":0,"byteOffset":28,"byteLength":6}],
             "accessors":[{"bufferView":0,"componentType":5122,"normalized":true,"count":3,"type":"VEC3",
                           "sparse":{"count":1,"indices":{"bufferView":1,"componentType":5123},"values":{"bufferView":2}}}],
             "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
             "nodes":[{"mesh":0,"scale":[4,4,4]}],
             "scenes":[{"nodes":[0]}]}
            """;
            string path = Path.Combine(folder, "quantised.gltf");
            File.WriteAllText(path, json.Replace("BYTES", bin.Count.ToString(System.Globalization.CultureInfo.InvariantCulture), StringComparison.Ordinal));
            Level level = GltfLevelLoader.Load(path);
            Assert.That(level.Triangles, Has.Count.EqualTo(1));
            Assert.That(Vector3.Distance(level.Triangles[0].B, new Vector3(0f, 0f, 4f)), Is.LessThan(1e-3f));
            Assert.That(Vector3.Distance(level.Triangles[0].C, new Vector3(4f, 2f, 0f)), Is.LessThan(1e-3f), "the sparse value replaced vertex 2");
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    [Test]
    public void ReadingPastABufferIsAnError()
    {
        string json = """
        {"asset":{"version":"2.0"},"buffers":[{"byteLength":12,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAA"}],
         "bufferViews":[{"buffer":0,"byteLength":12}],
         "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],
         "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]}
        """;
        Assert.That(() => GltfLevelLoader.Build(GltfModel.Parse(Encoding.UTF8.GetBytes(json), "short.gltf", null), "short.gltf"),
            Throws.TypeOf<GltfException>().With.Message.Contains("short.gltf: accessor 0 (POSITION of primitive 0 of mesh 0): BufferView[0]").And.Message.Contains("exceeds the number of available items (12)"));
    }

    private static byte[] Floats(params float[] values)
    {
        byte[] bytes = new byte[values.Length * 4];
        for (int i = 0; i < values.Length; i++)
        {
            BinaryPrimitives.WriteSingleLittleEndian(bytes.AsSpan(4 * i), values[i]);
        }

        return bytes;
    }
}
