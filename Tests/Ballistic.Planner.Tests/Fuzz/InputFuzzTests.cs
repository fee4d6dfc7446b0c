using System.Numerics;
using System.Security.Cryptography;
using System.Text.Json;
using System.Text.Json.Nodes;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Gltf;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Tests.Fuzz;

/// <summary>
/// Seeded mutations of valid level, character, limb spec and roadmap files (tracker issue 8): whatever the bytes,
/// <see cref="GltfLevelLoader.Load"/>, <see cref="CharacterSpecFile.Load(string, string, GltfLoadOptions?)"/> and <see cref="RoadmapFile.Load(string, string, Ballistic.Planner.Characters.ReducedCharacter)"/> either
/// succeed or throw an input error with one plain sentence, within 2 s and 512 MiB a case (see
/// <see cref="FuzzHarness"/>). The seeds are fixed, so every run tries the same cases; a failure prints its seed and
/// mutations, and <c>BALLISTIC_FUZZ_REPLAY=format:seed</c> with <see cref="Replay"/> runs it alone.
/// </summary>
[Category("Fuzz")]
[NonParallelizable] // each case has a wall-clock limit
public sealed class InputFuzzTests
{
    /// <summary>Master seeds: case <c>i</c> of master seed <c>s</c> has the seed <c>s × 10,000 + i</c>.</summary>
    private static readonly int[] MasterSeeds = [11, 23, 37, 41, 59];

    /// <summary>Roadmap cases found by longer runs whose name length prefix throws a FormatException out of RoadmapFile.Load.</summary>
    private static readonly int[] FormatExceptionSeeds = [1030494, 1090361];

    private static readonly Lazy<JsonObject> LevelJson = new(() => FuzzInputs.SplitGlb(FuzzInputs.LevelGlb).Json);
    private static readonly Lazy<byte[]> LevelBin = new(() => FuzzInputs.SplitGlb(FuzzInputs.LevelGlb).Bin);
    private static readonly Lazy<JsonObject> FrogJson = new(() => FuzzInputs.SplitGlb(FuzzInputs.FrogGlb).Json);
    private static readonly Lazy<byte[]> FrogBin = new(() => FuzzInputs.SplitGlb(FuzzInputs.FrogGlb).Bin);

    private string _folder = "";

    [OneTimeSetUp]
    public void MakeFolder()
    {
        _folder = Path.Combine(Path.GetTempPath(), $"ballistic-fuzz-{Guid.NewGuid():N}");
        Directory.CreateDirectory(_folder);

        // A valid buffer one folder above every case: a .gltf that follows "../secret.bin" would load it.
        File.WriteAllBytes(Path.Combine(_folder, "secret.bin"), LevelBin.Value);
    }

    [OneTimeTearDown]
    public void RemoveFolder() => Directory.Delete(_folder, recursive: true);

    [Test]
    public void GlbLevels() => Fuzz("glb", 800);

    [Test]
    public void GltfLevelsWithExternalBuffers() => Fuzz("gltf", 400);

    [Test]
    public void Characters() => Fuzz("character", 300);

    [Test]
    public void LimbSpecs() => Fuzz("spec", 300);

    [Test]
    public void Roadmaps() => Fuzz("roadmap", 100);

    /// <summary>
    /// Roadmaps changed and given a checksum that matches again, so that their content is read: counts, floats
    /// (NaN, infinities, huge and negative values), node and limb indices and the name's length prefix. A roadmap that
    /// loads must hold finite poses and contacts, limbs of the character and positive flight times.
    /// </summary>
    [Test]
    public void RoadmapMutationsWithRecomputedChecksums() => Fuzz("roadmap-rehashed", 200, FormatExceptionSeeds);

    /// <summary>Master seed of the second lane when none is given: CI and a plain <c>dotnet test</c> try the same cases.</summary>
    private const int DeepDefaultSeed = 2026;

    /// <summary>Cases of each kind (level, limb spec, roadmap) the second lane runs per master seed.</summary>
    private const int DeepCases = 30;

    /// <summary>
    /// The second lane, past the loaders (<see cref="DeepFuzz"/>): mutated levels, limb specs and roadmaps that still
    /// load are baked and planned on, and every exact plan is audited. Its master seed is printed;
    /// <c>BALLISTIC_FUZZ_DEEP_SEED=N</c> runs master seed N and <c>BALLISTIC_FUZZ_DEEP_SEED=random</c> draws a new one
    /// each run (also printed, so any failure replays, as does the replay line of each failed case).
    /// </summary>
    [Test]
    public void DeepLane()
    {
        string? given = Environment.GetEnvironmentVariable("BALLISTIC_FUZZ_DEEP_SEED");
        int master = given is null ? DeepDefaultSeed
            : given == "random" ? Random.Shared.Next(1, 20_000_000)
            : int.Parse(given, System.Globalization.CultureInfo.InvariantCulture);
        TestContext.Out.WriteLine($"deep lane: master seed {master} (BALLISTIC_FUZZ_DEEP_SEED={master} runs it again)");
        var failures = new List<string>();
        foreach (string format in new[] { "deep-level", "deep-spec", "deep-roadmap" })
        {
            int[] seeds = [.. Enumerable.Range(0, DeepCases).Select(i => (master * 100) + i)];
            var clock = System.Diagnostics.Stopwatch.StartNew();
            (List<string> failed, int loaded) = FuzzHarness.Run(format, seeds, _folder, Maker(format), DeepFuzz.CaseTime);
            TestContext.Out.WriteLine($"{format}: {seeds.Length} cases in {clock.Elapsed.TotalSeconds:0.0} s: {loaded} loaded and planned, {seeds.Length - loaded - failed.Count} refused with an input error, {failed.Count} failed");
            failures.AddRange(failed);
        }

        TestContext.Out.WriteLine("plans of the cases that loaded: " + string.Join(", ", DeepFuzz.Outcomes.OrderBy(o => o.Key, StringComparer.Ordinal).Select(o => $"{o.Value} {o.Key}")));
        foreach (string failure in failures)
        {
            TestContext.Out.WriteLine(failure);
        }

        Assert.That(failures, Is.Empty, $"master seed {master}: {failures.Count} deep cases failed:\n{string.Join("\n", failures.Take(10))}");
    }

    /// <summary>Runs the one case named by <c>BALLISTIC_FUZZ_REPLAY=format:seed</c>, printing its mutations.</summary>
    [Test]
    [Explicit("replays one fuzz case: set BALLISTIC_FUZZ_REPLAY=format:seed")]
    public void Replay()
    {
        string? replay = Environment.GetEnvironmentVariable("BALLISTIC_FUZZ_REPLAY");
        Assume.That(replay, Is.Not.Null.And.Contains(":"), "set BALLISTIC_FUZZ_REPLAY=format:seed");
        string[] parts = replay!.Split(':');
        int seed = int.Parse(parts[1], System.Globalization.CultureInfo.InvariantCulture);
        string? failure = FuzzHarness.RunOne(parts[0], seed, _folder, Maker(parts[0]), out bool loaded, parts[0].StartsWith("deep-", StringComparison.Ordinal) ? DeepFuzz.CaseTime : null);
        TestContext.Out.WriteLine(failure ?? $"{replay}: passes ({(loaded ? "loads" : "refused with an input error")})");
        Assert.That(failure, Is.Null);
    }

    /// <summary>
    /// Runs <paramref name="casesPerSeed"/> cases for each master seed. For a longer search outside CI,
    /// <c>BALLISTIC_FUZZ_SEEDS=1,2,3</c> replaces the master seeds and <c>BALLISTIC_FUZZ_SCALE=10</c> multiplies the cases.
    /// </summary>
    private void Fuzz(string format, int casesPerSeed, int[]? extraSeeds = null)
    {
        int[] masters = Environment.GetEnvironmentVariable("BALLISTIC_FUZZ_SEEDS") is string list
            ? [.. list.Split(',').Select(t => int.Parse(t, System.Globalization.CultureInfo.InvariantCulture))]
            : MasterSeeds;
        int scale = Environment.GetEnvironmentVariable("BALLISTIC_FUZZ_SCALE") is string text ? int.Parse(text, System.Globalization.CultureInfo.InvariantCulture) : 1;
        casesPerSeed = Math.Min(casesPerSeed * scale, 9_999);
        int[] seeds = [.. masters.SelectMany(s => Enumerable.Range(0, casesPerSeed).Select(i => (s * 10_000) + i)), .. extraSeeds ?? []];
        var clock = System.Diagnostics.Stopwatch.StartNew();
        (List<string> failures, int loaded) = FuzzHarness.Run(format, seeds, _folder, Maker(format));
        TestContext.Out.WriteLine($"{format}: {seeds.Length} cases in {clock.Elapsed.TotalSeconds:0.0} s: {loaded} still loaded, {seeds.Length - loaded - failures.Count} refused with an input error, {failures.Count} failed");
        foreach (string failure in failures)
        {
            TestContext.Out.WriteLine(failure);
        }

        Assert.That(failures, Is.Empty, $"{failures.Count} of {seeds.Length} {format} cases failed:\n{string.Join("\n", failures.Take(20))}");
    }

    internal static Func<Mutator, string, Action> Maker(string format) => format switch
    {
        "glb" => GlbLevel,
        "gltf" => GltfLevel,
        "character" => Character,
        "spec" => Spec,
        "roadmap" => (m, folder) => Roadmap(m, folder, rehash: false),
        "roadmap-rehashed" => (m, folder) => Roadmap(m, folder, rehash: true),
        "deep-level" => (m, folder) => DeepFuzz.Level(m, folder, GlbLevel),
        "deep-spec" => (m, folder) => DeepFuzz.Spec(m, folder, Spec),
        "deep-roadmap" => (m, folder) => DeepFuzz.Roadmap(m, folder, (mm, f) => Roadmap(mm, f, rehash: true)),
        _ => throw new ArgumentException($"Unknown fuzz format '{format}'.", nameof(format)),
    };

    private static Action GlbLevel(Mutator m, string folder)
    {
        string path = Path.Combine(folder, "level.glb");
        File.WriteAllBytes(path, MutatedGlb(m, FuzzInputs.LevelGlb, LevelJson.Value, LevelBin.Value));
        return () => GltfLevelLoader.Load(path);
    }

    private static Action GltfLevel(Mutator m, string folder)
    {
        var json = (JsonObject)LevelJson.Value.DeepClone();
        json["buffers"]![0]!["uri"] = "level.bin";
        byte[] bin = LevelBin.Value;
        byte[] text;
        switch (m.Random.Next(10))
        {
            case < 6:
                m.Json(json, 1 + m.Random.Next(3));
                text = m.Serialize(json);
                break;
            case < 8:
                text = m.Serialize(json);
                bin = m.Bytes(bin, 1 + m.Random.Next(3), "level.bin");
                break;
            default:
                text = m.Bytes(m.Serialize(json), 1 + m.Random.Next(4), "level.gltf");
                break;
        }

        string path = Path.Combine(folder, "level.gltf");
        File.WriteAllBytes(path, text);
        File.WriteAllBytes(Path.Combine(folder, "level.bin"), bin);
        return () =>
        {
            GltfLevelLoader.Load(path);
            CheckNothingOutsideWasRead(text, folder);
        };
    }

    private static Action Character(Mutator m, string folder)
    {
        byte[] glb = FuzzInputs.FrogGlb;
        byte[] spec = FuzzInputs.FrogSpec;
        if (m.Random.Next(2) == 0)
        {
            glb = MutatedGlb(m, glb, FrogJson.Value, FrogBin.Value);
        }
        else
        {
            spec = MutatedSpec(m, spec);
        }

        string gltfPath = Path.Combine(folder, "frog.glb");
        string specPath = Path.Combine(folder, "frog.limbs.json");
        File.WriteAllBytes(gltfPath, glb);
        File.WriteAllBytes(specPath, spec);
        return () => CharacterSpecFile.Load(gltfPath, specPath);
    }

    private static Action Spec(Mutator m, string folder)
    {
        string gltfPath = Path.Combine(folder, "frog.glb");
        string specPath = Path.Combine(folder, "frog.limbs.json");
        File.WriteAllBytes(gltfPath, FuzzInputs.FrogGlb);
        File.WriteAllBytes(specPath, MutatedSpec(m, FuzzInputs.FrogSpec));
        return () => CharacterSpecFile.Load(gltfPath, specPath);
    }

    private static Action Roadmap(Mutator m, string folder, bool rehash)
    {
        BakedRoadmap baked = FuzzInputs.Roadmap;
        RoadmapFields fields = baked.Fields();
        byte[] bytes = (byte[])baked.Bytes.Clone();
        int choice = m.Random.Next(10);
        if (rehash)
        {
            bytes = bytes[..fields.PayloadLength];
        }

        switch (choice)
        {
            case < 2:
                m.Field(bytes, fields.Counts[m.Random.Next(fields.Counts.Count)], "count");
                break;
            case < 5:
                for (int i = 1 + m.Random.Next(3); i > 0; i--)
                {
                    m.Float(bytes, fields.Floats[m.Random.Next(fields.Floats.Count)], "float");
                }

                break;
            case < 7:
                m.Field(bytes, fields.Indices[m.Random.Next(fields.Indices.Count)], "index");
                break;
            case 7:
                bytes[fields.NameLength] = (byte)m.Random.Next(256);
                m.Note($"name length prefix (byte {fields.NameLength}) ← {bytes[fields.NameLength]}");
                break;
            default:
                bytes = m.Bytes(bytes, 1 + m.Random.Next(3), "roadmap");
                break;
        }

        if (rehash)
        {
            bytes = [.. bytes, .. SHA256.HashData(bytes)];
            m.Note("checksum recomputed");
        }

        string path = Path.Combine(folder, "level.roadmap");
        File.WriteAllBytes(path, bytes);
        return () =>
        {
            Roadmap roadmap = RoadmapFile.Load(path, baked.LevelFingerprint, baked.Character);
            if (rehash && Invalid(roadmap, baked.Character.Limbs.Count) is string problem)
            {
                throw new InvalidDataException($"The roadmap loaded with {problem}.");
            }
        };
    }

    /// <summary>What a loaded roadmap should not hold (the checks roadmap validation is to make), or <c>null</c>.</summary>
    private static string? Invalid(Roadmap roadmap, int limbs)
    {
        static bool Finite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);
        foreach (RoadmapNode node in roadmap.Nodes)
        {
            Quaternion q = node.Pose.Rotation;
            if (!Finite(node.Pose.Position) || !float.IsFinite(q.X + q.Y + q.Z + q.W))
            {
                return $"node {node.Id} at a position or rotation that is not finite";
            }

            foreach (Contact contact in node.Contacts)
            {
                if (!Finite(contact.Position) || !Finite(contact.Normal) || contact.Limb < 0 || contact.Limb >= limbs)
                {
                    return $"a contact of node {node.Id} that is not finite or names limb {contact.Limb} of {limbs}";
                }
            }
        }

        foreach (RoadmapEdge edge in roadmap.Edges)
        {
            if (!(edge.Arc.FlightTime > 0f) || !float.IsFinite(edge.Arc.FlightTime) || !Finite(edge.Arc.TakeoffVelocity))
            {
                return $"the jump {edge.From}→{edge.To} taking {edge.Arc.FlightTime} s at a velocity of {edge.Arc.TakeoffVelocity}";
            }
        }

        return null;
    }

    /// <summary>A GLB mutated as bytes, in its length fields, or in its JSON (and then perhaps its binary chunk), rebuilt with the right lengths.</summary>
    private static byte[] MutatedGlb(Mutator m, byte[] glb, JsonObject baseJson, byte[] baseBin)
    {
        switch (m.Random.Next(10))
        {
            case < 3:
                return m.Bytes(glb, 1 + m.Random.Next(4), "glb");
            case < 5:
                {
                    byte[] bytes = (byte[])glb.Clone();
                    List<int> lengths = FuzzInputs.GlbLengthFields(bytes);
                    m.Field(bytes, lengths[m.Random.Next(lengths.Count)], "GLB length field");
                    return bytes;
                }

            default:
                {
                    var json = (JsonObject)baseJson.DeepClone();
                    m.Json(json, 1 + m.Random.Next(3));
                    byte[] bin = m.Random.Next(4) == 0 ? m.Bytes(baseBin, 1 + m.Random.Next(3), "bin chunk") : baseBin;
                    return FuzzInputs.JoinGlb(m.Serialize(json), bin);
                }
        }
    }

    private static byte[] MutatedSpec(Mutator m, byte[] spec)
    {
        if (m.Random.Next(4) == 0)
        {
            return m.Bytes(spec, 1 + m.Random.Next(4), "spec");
        }

        JsonNode json = JsonNode.Parse(spec)!;
        m.Json(json, 1 + m.Random.Next(3));
        return m.Serialize(json);
    }

    /// <summary>
    /// After a successful load, every URI the .gltf names (its buffers' and images', under any key it repeats: a
    /// reader may take either of two duplicate keys) must have been a data URI or a file in its folder.
    /// </summary>
    private static void CheckNothingOutsideWasRead(byte[] text, string folder)
    {
        JsonDocument document;
        try
        {
            document = JsonDocument.Parse(text);
        }
        catch (JsonException)
        {
            return;
        }

        string inside = Path.GetFullPath(folder) + Path.DirectorySeparatorChar;
        using (document)
        {
            var pending = new Stack<JsonElement>([document.RootElement]);
            while (pending.Count > 0)
            {
                JsonElement element = pending.Pop();
                if (element.ValueKind == JsonValueKind.Array)
                {
                    foreach (JsonElement item in element.EnumerateArray())
                    {
                        pending.Push(item);
                    }
                }
                else if (element.ValueKind == JsonValueKind.Object)
                {
                    foreach (JsonProperty property in element.EnumerateObject())
                    {
                        if (property.Name == "uri" && property.Value.ValueKind == JsonValueKind.String && property.Value.GetString() is string uri
                            && !uri.StartsWith("data:", StringComparison.OrdinalIgnoreCase)
                            && !Path.GetFullPath(Path.Combine(folder, Uri.UnescapeDataString(uri))).StartsWith(inside, StringComparison.Ordinal))
                        {
                            throw new InvalidOperationException($"The level loaded, naming the file '{uri}', outside its folder.");
                        }

                        pending.Push(property.Value);
                    }
                }
            }
        }
    }
}
