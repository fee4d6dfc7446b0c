namespace Ballistic.Planner.Tests.Support;

/// <summary>
/// Temporary folders for the rig files a fixture writes (<see cref="ForeignCharacter.Load(string)"/>): they stay until
/// the fixture ends, since writing an animated GLB reads a .gltf's images again.
/// </summary>
internal static class RigFolders
{
    /// <summary>The folder of fixture <paramref name="fixture"/> in this test process, under the system's temporary folder (not created).</summary>
    public static string For(string fixture) => Path.Combine(Path.GetTempPath(), $"ballistic-{fixture}-{Environment.ProcessId}");

    /// <summary>Removes <paramref name="folder"/> and everything in it, if it exists.</summary>
    public static void Remove(string folder)
    {
        if (Directory.Exists(folder))
        {
            Directory.Delete(folder, recursive: true);
        }
    }
}
