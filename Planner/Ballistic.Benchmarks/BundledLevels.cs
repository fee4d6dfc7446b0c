using Ballistic.Planner.Levels;

namespace Ballistic.Benchmarks;

/// <summary>The repository's bundled levels (<c>Scenes/levels/*.glb</c>), found upwards from the benchmark's folder.</summary>
internal static class BundledLevels
{
    /// <summary>Loads <c>Scenes/levels/<paramref name="name"/>.glb</c>.</summary>
    public static Level Load(string name) => GltfLevelLoader.Load(Path.Combine(RepositoryRoot(), "Scenes", "levels", name + ".glb"));

    /// <summary>The repository root: the folder holding Ballistic.slnx, above the benchmark's folder.</summary>
    public static string RepositoryRoot()
    {
        for (DirectoryInfo? dir = new(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            if (File.Exists(Path.Combine(dir.FullName, "Ballistic.slnx")))
            {
                return dir.FullName;
            }
        }

        throw new InvalidOperationException("Cannot find the repository root (Ballistic.slnx) above the benchmark's folder.");
    }
}
