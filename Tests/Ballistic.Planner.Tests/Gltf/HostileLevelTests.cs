using System.Buffers.Binary;
using System.Diagnostics;
using System.Text;
using System.Text.Json.Nodes;
using Ballistic.Authoring.Levels;
using Ballistic.Planner.Gltf;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Gltf;

/// <summary>
/// Level files crafted the way an attacker would (tracker issue 8): each used to exhaust memory or time, read a file
/// it should not, or fail with a runtime error; each is now a <see cref="LevelException"/> naming the file, the
/// element and the problem, found quickly and without large allocations.
/// </summary>
[NonParallelizable] // loads have wall-clock limits
public sealed class HostileLevelTests
{
    private const long FewMegabytes = 32L << 20;
    private string _folder = "";

    [SetUp]
    public void MakeFolder()
    {
        _folder = Path.Combine(Path.GetTempPath(), $"ballistic-hostile-{Guid.NewGuid():N}");
        Directory.CreateDirectory(_folder);
    }

    [TearDown]
    public void RemoveFolder() => Directory.Delete(_folder, recursive: true);

    [Test]
    public void ANodeListingItsChildTwiceFortyDeepIsRefusedAtOnce()
    {
        // Each node lists the next one twice: walked path by path, the 40-node chain has 2^40 paths.
        JsonObject root = Triangle();
        var nodes = new JsonArray();
        for (int i = 0; i < 40; i++)
        {
            nodes.Add(new JsonObject { ["children"] = new JsonArray(i + 1, i + 1) });
        }

        nodes.Add(new JsonObject { ["mesh"] = 0 });
        root["nodes"] = nodes;
        root["scenes"] = new JsonArray(new JsonObject { ["nodes"] = new JsonArray(0) });
        string message = Refused(Write("doubled.gltf", root));
        Assert.That(message, Does.Contain("doubled.gltf").And.Contain("node 0 lists node 1 as a child twice"));
    }

    [Test]
    public void SecondParentsCyclesAndRepeatedRootsNameTheNode()
    {
        JsonObject diamond = Triangle();
        diamond["nodes"] = new JsonArray(new JsonObject { ["children"] = new JsonArray(2) }, new JsonObject { ["children"] = new JsonArray(2) }, new JsonObject { ["mesh"] = 0 });
        diamond["scenes"] = new JsonArray(new JsonObject { ["nodes"] = new JsonArray(0, 1) });
        JsonObject cycle = Triangle();
        cycle["nodes"] = new JsonArray(new JsonObject { ["mesh"] = 0 }, new JsonObject { ["children"] = new JsonArray(2) }, new JsonObject { ["children"] = new JsonArray(1) });
        JsonObject twice = Triangle();
        twice["scenes"] = new JsonArray(new JsonObject { ["nodes"] = new JsonArray(0, 0) });
        Assert.Multiple(() =>
        {
            Assert.That(Refused(Write("diamond.gltf", diamond)), Does.Contain("node 2 is a child of both node 0 and node 1"));
            Assert.That(Refused(Write("cycle.gltf", cycle)), Does.Contain("cycle through node"));
            Assert.That(Refused(Write("twice.gltf", twice)), Does.Contain("lists node 0 twice"));
        });
    }

    [Test]
    public void AHundredThousandNodeChainIsRefusedAtOnceAndAThousandDeepLoads()
    {
        // SharpGLTF checks the hierarchy recursively (a 100,000-node chain overflowed the stack and took the process
        // down): ours, linear and without recursion, runs first and refuses more than GltfModel.MaxNodeDepth levels.
        string Chain(string file, int depth)
        {
            JsonObject root = Triangle();
            var nodes = new JsonArray();
            for (int i = 0; i < depth; i++)
            {
                nodes.Add(i + 1 < depth ? new JsonObject { ["children"] = new JsonArray(i + 1) } : new JsonObject { ["mesh"] = 0, ["translation"] = new JsonArray(0, 1, 0) });
            }

            root["nodes"] = nodes;
            return Write(file, root);
        }

        string deep = Chain("deep.gltf", 100_000);
        var clock = Stopwatch.StartNew();
        string message = Refused(deep);
        TimeSpan refused = clock.Elapsed;
        Level level = GltfLevelLoader.Load(Chain("thousand.gltf", GltfModel.MaxNodeDepth));
        Assert.Multiple(() =>
        {
            Assert.That(message, Does.Contain("deep.gltf: node 1000 lies 1001 deep in the node hierarchy; at most 1000 levels are read"));
            Assert.That(refused, Is.LessThan(TimeSpan.FromSeconds(10)));
            Assert.That(level.Triangles, Has.Count.EqualTo(1));
            Assert.That(level.Bounds.Min.Y, Is.EqualTo(1f));
        });
    }

    [Test]
    public void AnAccessorOfHundredsOfMillionsOfElementsWithoutDataIsRefusedBeforeAllocating()
    {
        JsonObject root = Triangle();
        root["accessors"]!.AsArray().Add(new JsonObject { ["componentType"] = 5126, ["count"] = 150_000_000, ["type"] = "VEC3" });
        root["meshes"]![0]!["primitives"]![0]!["attributes"]!["POSITION"] = 1;
        string message = Refused(Write("huge.gltf", root));
        Assert.That(message, Does.Contain("huge.gltf: with primitive 0 of mesh 0 ('Floor'), the level reads more than 60000000 vertices (GltfLoadOptions.MaxVertices)"));
    }

    [Test]
    public void CountsStridesAndOffsetsAreCheckedAgainstTheirViews()
    {
        JsonObject count = Triangle();
        count["accessors"]![0]!["count"] = 2_000_000_000;
        JsonObject offset = Triangle();
        offset["accessors"]![0]!["byteOffset"] = 2_147_483_000;
        JsonObject stride = Triangle();
        stride["bufferViews"]![0]!["byteStride"] = 4;
        JsonObject view = Triangle();
        view["bufferViews"]![0]!["byteOffset"] = 2_147_483_000;
        JsonObject negative = Triangle();
        negative["accessors"]![0]!["count"] = -3;
        Assert.Multiple(() =>
        {
            Assert.That(Refused(Write("count.gltf", count)), Does.Contain("count.gltf: accessor 0 (POSITION of primitive 0 of mesh 0 ('Floor')): BufferView[0]"));
            Assert.That(Refused(Write("offset.gltf", offset)), Does.Contain("offset.gltf: accessor 0 (POSITION of primitive 0 of mesh 0 ('Floor')): BufferView[0]: .2147483000+36 exceeds the number of available items (36)"));
            Assert.That(Refused(Write("stride.gltf", stride)), Does.Contain("stride.gltf: accessor 0 (POSITION of primitive 0 of mesh 0 ('Floor')): ElementByteSize: 4 must be greater or equal to 12"));
            Assert.That(Refused(Write("view.gltf", view)), Does.Contain("view.gltf: an offset or length runs past the end of the bytes it refers to"));
            Assert.That(Refused(Write("negative.gltf", negative)), Does.Contain("negative.gltf: accessor 0 (POSITION of primitive 0 of mesh 0 ('Floor')): _count: -3 must be greater or equal to 1"));
        });
    }

    [Test]
    public void ASparseIndexOutOfRangeIsNamed()
    {
        // Three vertices; the sparse part replaces "element 7".
        byte[] bin = [.. Floats(0, 0, 0, 1, 0, 0, 0, 0, 1), .. BitConverter.GetBytes((ushort)7), 0, 0, .. Floats(0, 5, 0)];
        JsonObject root = Triangle(bin);
        root["bufferViews"]!.AsArray().Add(new JsonObject { ["buffer"] = 0, ["byteOffset"] = 36, ["byteLength"] = 2 });
        root["bufferViews"]!.AsArray().Add(new JsonObject { ["buffer"] = 0, ["byteOffset"] = 40, ["byteLength"] = 12 });
        root["accessors"]![0]!["sparse"] = new JsonObject
        {
            ["count"] = 1,
            ["indices"] = new JsonObject { ["bufferView"] = 1, ["componentType"] = 5123 },
            ["values"] = new JsonObject { ["bufferView"] = 2 },
        };
        Assert.That(Refused(Write("sparse.gltf", root)), Does.Contain("sparse.gltf: an element refers to another that does not exist"));
    }

    [Test]
    public void AGlbChunkLengthNearFourGigabytesIsRefusedWithoutOverflow()
    {
        byte[] glb = GltfLevelWriter.ToBytes([new LevelMesh("Floor", [new(0f, 0f, 0f), new(1f, 0f, 0f), new(0f, 0f, 1f)], [0, 2, 1], new LevelMaterial("stone", null), System.Numerics.Vector4.One)]);
        BinaryPrimitives.WriteUInt32LittleEndian(glb.AsSpan(12), 0xFFFFFFF0);
        string path = Path.Combine(_folder, "chunk.glb");
        File.WriteAllBytes(path, glb);
        Assert.That(Refused(path), Does.Contain("chunk.glb: a GLB chunk declares 4294967280 bytes, more than the file holds (it is truncated or corrupt)"));
    }

    [Test]
    public void AssetVersionsAndRequiredExtensionsOfTheWrongTypeAreNamed()
    {
        string version = Path.Combine(_folder, "version.gltf");
        File.WriteAllText(version, """{"asset":{"version":2.0},"nodes":[]}""");
        string extensions = Path.Combine(_folder, "extensions.gltf");
        File.WriteAllText(extensions, """{"asset":{"version":"2.0"},"extensionsRequired":[5]}""");
        string extensionsText = Path.Combine(_folder, "extensions-text.gltf");
        File.WriteAllText(extensionsText, """{"asset":{"version":"2.0"},"extensionsRequired":"KHR_draco_mesh_compression"}""");
        Assert.Multiple(() =>
        {
            Assert.That(Refused(version), Does.Contain("asset.version is the number 2.0, not a string such as \"2.0\""));
            Assert.That(Refused(extensions), Does.Contain("extensionsRequired item 0 is the number 5, not an extension name"));
            Assert.That(Refused(extensionsText), Does.Contain("extensionsRequired is the string \"KHR_draco_mesh_compression\", not a list"));
        });
    }

    [Test]
    public void AValueOfTheWrongTypeIsNamedWithWhereItIs()
    {
        // SharpGLTF's JSON reader says what it met but not where; the loader finds where by reading parts of the file.
        JsonObject list = Triangle();
        list["accessors"]![0]!["componentType"] = new JsonArray(0, 1, 2);
        JsonObject text = Triangle();
        text["materials"] = new JsonArray(new JsonObject { ["pbrMetallicRoughness"] = new JsonObject { ["baseColorFactor"] = new JsonArray(1, "red", 1, 1) } });
        JsonObject target = Triangle();
        target["bufferViews"]![0]!["target"] = "vertices";
        Assert.Multiple(() =>
        {
            Assert.That(Refused(Write("target.gltf", target)), Does.EndWith("target.gltf: bufferViews[0].target: its JSON has the value 'vertices' where the glTF 2.0 schema allows only its own names."));
            Assert.That(Refused(Write("list.gltf", list)), Does.EndWith("list.gltf: accessors[0].componentType: its JSON has a value of a type the glTF 2.0 schema does not allow where it is."));
            Assert.That(Refused(Write("text.gltf", text)), Does.EndWith("text.gltf: materials[0].pbrMetallicRoughness.baseColorFactor[1]: its JSON has a string where the glTF 2.0 schema wants a number."));
        });
    }

    [Test]
    public void ATransformListOfTheWrongLengthIsRefused()
    {
        // SharpGLTF reads the first four numbers of a five-number rotation (and fills a short list): the node would be
        // turned by a rotation its file does not say.
        JsonObject rotation = Triangle();
        rotation["nodes"]![0]!["rotation"] = new JsonArray(0, 0.7071068, 0, 0.7071068, 0);
        JsonObject translation = Triangle();
        translation["nodes"]![0]!["translation"] = new JsonArray(1, 2);
        Assert.Multiple(() =>
        {
            Assert.That(Refused(Write("rotation.gltf", rotation)), Does.EndWith("rotation.gltf: node 0 has a malformed rotation: it must be a list of 4 numbers; not a list of 5."));
            Assert.That(Refused(Write("translation.gltf", translation)), Does.EndWith("translation.gltf: node 0 has a malformed translation: it must be a list of 3 numbers; not a list of 2."));
        });
    }

    [Test]
    public void RepeatedKeysAreNamedWithWhereTheyRepeat()
    {
        string path = Path.Combine(_folder, "keys.gltf");
        File.WriteAllText(path, """{"asset":{"version":"2.0"},"nodes":[{"mesh":0,"mesh":1}]}""");
        Assert.That(Refused(path), Does.Contain("keys.gltf: the key 'mesh' appears twice in the object at nodes[0]"));
    }

    [Test]
    public void TextThatIsNotUnicodeAndNamesWithLineBreaksGiveOneLine()
    {
        string bytes = Path.Combine(_folder, "latin1.gltf");
        File.WriteAllBytes(bytes, [.. Encoding.UTF8.GetBytes("""{"asset":{"version":"2.0","generator":"caf"""), 0xE9, .. Encoding.UTF8.GetBytes("\"}}")]);
        string surrogate = Path.Combine(_folder, "surrogate.gltf");
        File.WriteAllText(surrogate, """{"asset":{"version":"2.0"},"nodes":[{"name":"\uD800"}]}""");
        JsonObject broken = Triangle(Floats(0, 0, 0, 1e30f, 0, 0, 0, 0, 1));
        broken["meshes"]![0]!["name"] = "Floor\nsecond line";
        Assert.Multiple(() =>
        {
            Assert.That(Refused(bytes), Does.Contain("latin1.gltf is not a glTF file: its JSON is not valid UTF-8 text"));
            Assert.That(Refused(surrogate), Does.Contain("surrogate.gltf: the JSON at nodes[0].name holds text that is not valid Unicode"));
            Assert.That(Refused(Write("named.gltf", broken)), Does.Contain("Mesh 'Floor\\u000asecond line[0]'"));
        });
    }

    [Test]
    public void CoordinatesBeyondAMillionMetresNameTheVertex()
    {
        byte[] bin = Floats(0, 0, 0, 1e30f, 0, 0, 0, 0, 1);
        JsonObject far = Triangle(bin);
        JsonObject scaled = Triangle();
        scaled["nodes"]![0]!["scale"] = new JsonArray(1e30f, 1e30f, 1e30f);
        JsonObject nan = Triangle(Floats(0, 0, 0, float.NaN, 0, 0, 0, 0, 1));
        Assert.Multiple(() =>
        {
            Assert.That(Refused(Write("far.gltf", far)), Does.Contain("vertex 1 has a coordinate of 1E+30 m, beyond the ±1e6 m a level may span"));
            Assert.That(Refused(Write("scaled.gltf", scaled)), Does.Contain("vertex 1 has a coordinate of 1E+30 m, beyond the ±1e6 m"));
            Assert.That(Refused(Write("nan.gltf", nan)), Does.Contain("nan.gltf: accessor 0 (POSITION of primitive 0 of mesh 0 ('Floor')): POSITION[1]: Invalid Position"));
        });
    }

    [Test]
    public void BufferUrisCannotLeaveTheGltfsFolder()
    {
        // A real buffer outside the level's folder, with the level's own bytes: following the URI would load it.
        string inner = Path.Combine(_folder, "level");
        Directory.CreateDirectory(inner);
        byte[] bin = Floats(0, 0, 0, 1, 0, 0, 0, 0, 1);
        File.WriteAllBytes(Path.Combine(_folder, "outside.bin"), bin);
        File.WriteAllBytes(Path.Combine(inner, "inside.bin"), bin);
        File.CreateSymbolicLink(Path.Combine(inner, "link.bin"), Path.Combine(_folder, "outside.bin"));
        Directory.CreateSymbolicLink(Path.Combine(inner, "up"), _folder);
        string Level(string uri)
        {
            JsonObject root = Triangle();
            root["buffers"]![0]!["uri"] = uri;
            string path = Path.Combine(inner, "level.gltf");
            File.WriteAllText(path, root.ToJsonString());
            return path;
        }

        Assert.Multiple(() =>
        {
            Assert.That(GltfLevelLoader.Load(Level("inside.bin")).Triangles, Has.Count.EqualTo(1), "a file beside the glTF is read");
            Assert.That(GltfLevelLoader.Load(Level("./sub/../inside.bin")).Triangles, Has.Count.EqualTo(1), "'..' that stays inside is fine");
            Assert.That(Refused(Level("../outside.bin")), Does.Contain("buffer 0's URI '../outside.bin' leads out of the glTF's folder"));
            Assert.That(Refused(Level("../../../../etc/passwd")), Does.Contain("'../../../../etc/passwd' leads out of the glTF's folder"));
            Assert.That(Refused(Level("%2e%2e/outside.bin")), Does.Contain("'%2e%2e/outside.bin' leads out of the glTF's folder"));
            Assert.That(Refused(Level("sub/..%5c..%5coutside.bin")), Does.Contain("leads out of the glTF's folder"));
            Assert.That(Refused(Level(Path.Combine(_folder, "outside.bin"))), Does.Contain("is an absolute path"));
            Assert.That(Refused(Level("%2Fetc%2Fpasswd")), Does.Contain("is an absolute path"));
            Assert.That(Refused(Level("file:///etc/passwd")), Does.Contain("'file:///etc/passwd' has a scheme"));
            Assert.That(Refused(Level("inside.bin%00.png")), Does.Contain("'inside.bin\\u0000.png'").Or.Contain("NUL character"));
            Assert.That(Refused(Level("link.bin")), Does.Contain("'link.bin' leads, through a symbolic link, to").And.Contain("outside the glTF's folder"));
            Assert.That(Refused(Level("up/outside.bin")), Does.Contain("'up/outside.bin' leads, through a symbolic link"));
        });
    }

    [Test]
    public void OnlyRegularFilesAreRead()
    {
        Assume.That(OperatingSystem.IsLinux(), "named pipes and /dev/zero are made the Linux way");
        string zero = Path.Combine(_folder, "zero.glb");
        File.CreateSymbolicLink(zero, "/dev/zero");
        string pipe = Path.Combine(_folder, "pipe.glb");
        using (var mkfifo = Process.Start(new ProcessStartInfo("mkfifo", [pipe]) { UseShellExecute = false })!)
        {
            mkfifo.WaitForExit();
            Assert.That(mkfifo.ExitCode, Is.Zero, "mkfifo");
        }

        string regular = Path.Combine(_folder, "floor.gltf");
        File.WriteAllText(regular, Triangle().ToJsonString());
        string link = Path.Combine(_folder, "floor-link.gltf");
        File.CreateSymbolicLink(link, regular);
        Assert.Multiple(() =>
        {
            Assert.That(Refused(zero), Does.Contain("zero.glb is a character device, not a regular file"));
            Assert.That(Refused(pipe), Does.Contain("pipe.glb is a named pipe, not a regular file"));
            Assert.That(Refused(_folder), Does.Contain("is a folder, not a file"));
            Assert.That(Refused(Path.Combine(_folder, "missing.glb")), Does.Contain("missing.glb cannot be read: it does not exist"));
            Assert.That(Refused(Path.Combine(_folder, "nul\0.glb")), Does.Contain("NUL character"));
            Assert.That(GltfLevelLoader.Load(link).Triangles, Has.Count.EqualTo(1), "a symbolic link to a regular file is followed");
        });
    }

    [Test]
    public void AnExternalBufferThatIsAPipeOrDeviceIsRefused()
    {
        Assume.That(OperatingSystem.IsLinux(), "named pipes and /dev/zero are made the Linux way");
        File.CreateSymbolicLink(Path.Combine(_folder, "zero.bin"), "/dev/zero");
        using (var mkfifo = Process.Start(new ProcessStartInfo("mkfifo", [Path.Combine(_folder, "pipe.bin")]) { UseShellExecute = false })!)
        {
            mkfifo.WaitForExit();
        }

        JsonObject zero = Triangle();
        zero["buffers"]![0]!["uri"] = "zero.bin";
        JsonObject pipe = Triangle();
        pipe["buffers"]![0]!["uri"] = "pipe.bin";
        Assert.Multiple(() =>
        {
            Assert.That(Refused(Write("zero.gltf", zero)), Does.Contain("buffer 0's URI 'zero.bin' leads, through a symbolic link, to /dev/zero"));
            Assert.That(Refused(Write("pipe.gltf", pipe)), Does.Contain("buffer 0's file 'pipe.bin' is a named pipe, not a regular file"));
        });
    }

    [Test]
    public void AByteOrderMarkBeforeTheJsonIsTolerated()
    {
        string path = Path.Combine(_folder, "bom.gltf");
        File.WriteAllText(path, Triangle().ToJsonString(), new UTF8Encoding(encoderShouldEmitUTF8Identifier: true));
        Assert.That(File.ReadAllBytes(path)[..3], Is.EqualTo(new byte[] { 0xEF, 0xBB, 0xBF }));
        Assert.That(GltfLevelLoader.Load(path).Triangles, Has.Count.EqualTo(1));
    }

    [Test]
    public void TheLimitsAreCheckedBeforeReading()
    {
        string level = RepositoryFiles.Level("gap-course");
        long size = new FileInfo(level).Length;
        Assert.Multiple(() =>
        {
            Assert.That(Refused(level, new GltfLoadOptions { MaxBytes = 1000 }), Does.Contain($"gap-course.glb is {size} bytes, more than the 1000 bytes allowed (GltfLoadOptions.MaxBytes)"));
            Assert.That(Refused(level, new GltfLoadOptions { MaxTriangles = 10 }), Does.Contain("the level holds more than 10 triangles (GltfLoadOptions.MaxTriangles)"));
            Assert.That(Refused(level, new GltfLoadOptions { MaxVertices = 10 }), Does.Contain("the level reads more than 10 vertices (GltfLoadOptions.MaxVertices)"));
            Assert.That(GltfLevelLoader.Load(level, new GltfLoadOptions { MaxBytes = size }).Triangles, Is.Not.Empty, "a file of exactly the limit is read");
            Assert.That(() => new GltfLoadOptions { MaxTriangles = 0 }, Throws.TypeOf<ArgumentOutOfRangeException>());
        });

        // An external buffer counts with the glTF towards the byte limit.
        JsonObject root = Triangle();
        File.WriteAllBytes(Path.Combine(_folder, "floor.bin"), Floats(0, 0, 0, 1, 0, 0, 0, 0, 1));
        root["buffers"]![0]!["uri"] = "floor.bin";
        string gltf = Write("floor.gltf", root);
        long json = new FileInfo(gltf).Length;
        Assert.That(Refused(gltf, new GltfLoadOptions { MaxBytes = json + 30 }), Does.Contain("buffer 0's file 'floor.bin' is 36 bytes, more than the 30 bytes allowed (what is left of the limit of"));
        Assert.That(GltfLevelLoader.Load(gltf, new GltfLoadOptions { MaxBytes = json + 36 }).Triangles, Has.Count.EqualTo(1));
    }

    [Test]
    public void AMeshInstancedByManyNodesCountsEachInstanceAgainstTheTriangleLimit()
    {
        JsonObject root = Triangle();
        var nodes = new JsonArray();
        for (int i = 0; i < 50; i++)
        {
            nodes.Add(new JsonObject { ["mesh"] = 0, ["translation"] = new JsonArray(i * 2, 0, 0) });
        }

        root["nodes"] = nodes;
        root["scenes"] = new JsonArray(new JsonObject { ["nodes"] = new JsonArray([.. Enumerable.Range(0, 50).Select(i => (JsonNode)i)]) });
        string path = Write("instances.gltf", root);
        Assert.That(GltfLevelLoader.Load(path).Triangles, Has.Count.EqualTo(50));
        Assert.That(Refused(path, new GltfLoadOptions { MaxTriangles = 49 }), Does.Contain("more than 49 triangles"));
    }

    /// <summary>The level's error message; fails when loading takes long, allocates much, or throws anything else.</summary>
    private static string Refused(string path, GltfLoadOptions? options = null)
    {
        LevelException? error = null;
        long allocated = 0;
        var run = Task.Run(() =>
        {
            long before = GC.GetAllocatedBytesForCurrentThread();
            try
            {
                GltfLevelLoader.Load(path, options);
            }
            catch (LevelException e)
            {
                error = e;
            }

            allocated = GC.GetAllocatedBytesForCurrentThread() - before;
        });
        Assert.That(run.Wait(TimeSpan.FromSeconds(10)), Is.True, $"{path} took more than 10 s");
        Assert.That(error, Is.Not.Null, $"{path} loaded");
        Assert.That(allocated, Is.LessThan(FewMegabytes), $"{path} allocated {allocated} bytes before failing");
        TestContext.Out.WriteLine(error!.Message);
        Assert.That(error.Message, Does.Not.Contain("\n").And.Not.Contain("Specified argument").And.Not.Contain("Index was out").And.Not.Contain("An item with the same key"));
        return error.Message;
    }

    private string Write(string name, JsonObject root)
    {
        string path = Path.Combine(_folder, name);
        File.WriteAllText(path, root.ToJsonString());
        return path;
    }

    /// <summary>A one-triangle level: positions (3 floats each) in a data-URI buffer, one node, one scene.</summary>
    private static JsonObject Triangle(byte[]? bin = null)
    {
        bin ??= Floats(0, 0, 0, 1, 0, 0, 0, 0, 1);
        return new JsonObject
        {
            ["asset"] = new JsonObject { ["version"] = "2.0" },
            ["buffers"] = new JsonArray(new JsonObject { ["byteLength"] = bin.Length, ["uri"] = "data:application/octet-stream;base64," + Convert.ToBase64String(bin) }),
            ["bufferViews"] = new JsonArray(new JsonObject { ["buffer"] = 0, ["byteOffset"] = 0, ["byteLength"] = 36 }),
            ["accessors"] = new JsonArray(new JsonObject { ["bufferView"] = 0, ["componentType"] = 5126, ["count"] = 3, ["type"] = "VEC3" }),
            ["meshes"] = new JsonArray(new JsonObject { ["name"] = "Floor", ["primitives"] = new JsonArray(new JsonObject { ["attributes"] = new JsonObject { ["POSITION"] = 0 } }) }),
            ["nodes"] = new JsonArray(new JsonObject { ["mesh"] = 0 }),
            ["scenes"] = new JsonArray(new JsonObject { ["nodes"] = new JsonArray(0) }),
        };
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
