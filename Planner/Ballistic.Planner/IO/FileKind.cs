namespace Ballistic.Planner.IO;

/// <summary>What a path names on disk, following symbolic links: a regular file, a folder, something else (device, pipe, socket) or nothing.</summary>
internal enum FileKindValue
{
    Missing,
    Regular,
    Directory,
    Special,
}

/// <summary>
/// The kind of file at a path, never opening it. .NET does not expose the file type bits, so on Linux they come from
/// <c>statx</c> (<see cref="InputFile.StatxProblem"/>); elsewhere every existing non-folder counts as regular.
/// </summary>
internal static class FileKind
{
    /// <summary>The kind of <paramref name="path"/>.</summary>
    public static FileKindValue Of(string path)
    {
        if (Directory.Exists(path))
        {
            return FileKindValue.Directory;
        }

        if (!File.Exists(path))
        {
            return FileKindValue.Missing;
        }

        if (!OperatingSystem.IsLinux())
        {
            return FileKindValue.Regular;
        }

        try
        {
            return InputFile.StatxProblem(path) switch
            {
                null => FileKindValue.Regular,
                "cannot be read: it does not exist" => FileKindValue.Missing,
                "is a folder, not a file" => FileKindValue.Directory,
                _ => FileKindValue.Special,
            };
        }
        catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
        {
            return FileKindValue.Regular;
        }
    }
}
