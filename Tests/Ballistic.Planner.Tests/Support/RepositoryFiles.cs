namespace Ballistic.Planner.Tests.Support;

/// <summary>Files of this repository (the bundled levels), found upwards from the test's folder.</summary>
internal static class RepositoryFiles
{
    public static string Root { get; } = FindRoot();

    public static string Level(string name) => Path.Combine(Root, "Scenes", "levels", name + ".glb");

    private static string FindRoot()
    {
        for (DirectoryInfo? dir = new(TestContext.CurrentContext.TestDirectory); dir is not null; dir = dir.Parent)
        {
            if (File.Exists(Path.Combine(dir.FullName, "Ballistic.slnx")))
            {
                return dir.FullName;
            }
        }

        throw new InvalidOperationException("Cannot find the repository root (Ballistic.slnx) above the test folder.");
    }
}
