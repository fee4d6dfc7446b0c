using Ballistic.Planner.Levels;
using Ballistic.Planner.Rigs;
using BenchmarkDotNet.Attributes;

namespace Ballistic.Benchmarks;

/// <summary>
/// Reading the bundled glTF files as a game or the editor does: each level (<c>Scenes/levels/*.glb</c>, 15 KB to
/// 11 MB) into a <see cref="Level"/>, and each bundled character (<c>Scenes/characters/*.glb</c> with its limb spec)
/// into a rig. Issue 25 compares these before and after reading through SharpGLTF (allocated bytes stand in for peak
/// memory: every byte a load allocates is live until it returns).
/// </summary>
[MemoryDiagnoser]
[MedianColumn]
public class GltfLoadBenchmarks
{
    /// <summary>A level's or a character's file name without its extension, as "level/name" or "character/name".</summary>
    [Params("level/desert", "level/gap-course", "level/pond", "level/rooftops", "character/skeleton", "character/frog")]
    public string File { get; set; } = "";

    /// <summary>One load; the level's triangles or the rig's joints.</summary>
    [Benchmark]
    public int Load()
    {
        string[] parts = File.Split('/');
        if (parts[0] == "level")
        {
            return BundledLevels.Load(parts[1]).Triangles.Count;
        }

        string folder = Path.Combine(BundledLevels.RepositoryRoot(), "Scenes", "characters");
        return CharacterSpecFile.Load(Path.Combine(folder, parts[1] + ".glb"), Path.Combine(folder, parts[1] + ".limbs.json")).Model.Rig.Joints.Count;
    }
}
