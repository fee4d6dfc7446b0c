using System.Buffers.Binary;
using System.Text.Json.Nodes;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Fuzz;

/// <summary>
/// The valid files the fuzz tests start from: the bundled gap-course level (as a GLB, and as a .gltf with its .bin
/// beside it), the frog and its limb spec, and a small roadmap baked on the gap course for the skeleton and saved
/// with <see cref="RoadmapFile.Save"/>.
/// </summary>
internal static class FuzzInputs
{
    private static readonly Lazy<byte[]> LevelGlbBytes = new(() => File.ReadAllBytes(RepositoryFiles.Level("gap-course")));
    private static readonly Lazy<byte[]> FrogGlbBytes = new(() => File.ReadAllBytes(Path.Combine(RepositoryFiles.Root, "Scenes", "characters", "frog.glb")));
    private static readonly Lazy<byte[]> FrogSpecBytes = new(() => File.ReadAllBytes(Path.Combine(RepositoryFiles.Root, "Scenes", "characters", "frog.limbs.json")));
    private static readonly Lazy<BakedRoadmap> Baked = new(Bake);

    /// <summary>Scenes/levels/gap-course.glb.</summary>
    public static byte[] LevelGlb => LevelGlbBytes.Value;

    /// <summary>Scenes/characters/frog.glb.</summary>
    public static byte[] FrogGlb => FrogGlbBytes.Value;

    /// <summary>Scenes/characters/frog.limbs.json.</summary>
    public static byte[] FrogSpec => FrogSpecBytes.Value;

    /// <summary>The roadmap file's bytes, and the level fingerprint and character it loads with.</summary>
    public static BakedRoadmap Roadmap => Baked.Value;

    /// <summary>The JSON and binary chunks of a GLB.</summary>
    public static (JsonObject Json, byte[] Bin) SplitGlb(byte[] glb)
    {
        int jsonLength = BinaryPrimitives.ReadInt32LittleEndian(glb.AsSpan(12));
        var json = JsonNode.Parse(glb.AsSpan(20, jsonLength))!.AsObject();
        int at = 20 + jsonLength;
        int binLength = BinaryPrimitives.ReadInt32LittleEndian(glb.AsSpan(at));
        return (json, glb[(at + 8)..(at + 8 + binLength)]);
    }

    /// <summary>A GLB of the given JSON text and binary chunk, every length right.</summary>
    public static byte[] JoinGlb(byte[] json, byte[] bin)
    {
        int jsonPadded = (json.Length + 3) & ~3;
        int binPadded = (bin.Length + 3) & ~3;
        byte[] file = new byte[12 + 8 + jsonPadded + 8 + binPadded];
        BinaryPrimitives.WriteUInt32LittleEndian(file, 0x46546C67);
        BinaryPrimitives.WriteUInt32LittleEndian(file.AsSpan(4), 2);
        BinaryPrimitives.WriteUInt32LittleEndian(file.AsSpan(8), (uint)file.Length);
        BinaryPrimitives.WriteUInt32LittleEndian(file.AsSpan(12), (uint)jsonPadded);
        BinaryPrimitives.WriteUInt32LittleEndian(file.AsSpan(16), 0x4E4F534A);
        json.CopyTo(file, 20);
        file.AsSpan(20 + json.Length, jsonPadded - json.Length).Fill((byte)' ');
        BinaryPrimitives.WriteUInt32LittleEndian(file.AsSpan(20 + jsonPadded), (uint)binPadded);
        BinaryPrimitives.WriteUInt32LittleEndian(file.AsSpan(24 + jsonPadded), 0x004E4942);
        bin.CopyTo(file, 28 + jsonPadded);
        return file;
    }

    /// <summary>The offsets of the chunk length fields of a GLB (the header's total length first).</summary>
    public static List<int> GlbLengthFields(byte[] glb)
    {
        var fields = new List<int> { 8 };
        long at = 12;
        while (at + 8 <= glb.Length)
        {
            fields.Add((int)at);
            at += 8 + (long)BinaryPrimitives.ReadUInt32LittleEndian(glb.AsSpan((int)at));
        }

        return fields;
    }

    private static BakedRoadmap Bake()
    {
        Level level = GltfLevelLoader.Load(RepositoryFiles.Level("gap-course"));
        ReducedCharacter character = CharacterPresets.Skeleton();
        Roadmap roadmap = new RoadmapBaker(PlanningScene.Create(level, character)).Bake(new BakeSettings { Seed = 8, MaxNodes = 12, Threads = 1 }).Roadmap;
        string path = Path.Combine(Path.GetTempPath(), $"ballistic-fuzz-{Guid.NewGuid():N}.roadmap");
        try
        {
            RoadmapFile.Save(roadmap, path);
            return new BakedRoadmap(File.ReadAllBytes(path), level.Fingerprint, character, roadmap.Nodes.Sum(n => n.Contacts.Count), roadmap.Edges.Count);
        }
        finally
        {
            File.Delete(path);
        }
    }
}
