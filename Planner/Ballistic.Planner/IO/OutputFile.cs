using System.Diagnostics;
using System.Globalization;

namespace Ballistic.Planner.IO;

/// <summary>
/// Writes output files whole and safely. The bytes go to a temporary file created exclusively beside the target
/// (<c>.NAME.PID.RANDOM.tmp</c>), are flushed to disk, and the temporary file then replaces the target in one rename:
/// a failed or interrupted write never leaves a half-written file, and the previous file stays intact. Only regular
/// files are replaced: a device (<c>/dev/null</c>, <c>/dev/full</c>), a pipe, a socket or a folder is refused with an
/// error. A symbolic link is followed: the file it points to is written and the link stays a link. The temporary file
/// is removed on every exit path, and temporary files left by writers that were killed (their process is gone) are
/// removed by the next write to the same file.
/// </summary>
internal static class OutputFile
{
    /// <summary>Writes <paramref name="bytes"/> to <paramref name="path"/>, creating its folder.</summary>
    /// <exception cref="OutputFileException">The target is not a regular file, or it cannot be written; the message names <paramref name="path"/>.</exception>
    public static void Write(string path, ReadOnlySpan<byte> bytes)
    {
        ArgumentNullException.ThrowIfNull(path);
        Staged staged = Stage(path, bytes);
        try
        {
            staged.Replace();
        }
        finally
        {
            TryDelete(staged.Temporary);
        }
    }

    /// <summary>
    /// Checks, before long work, that <paramref name="path"/> can be written: it is (or will be) a regular file whose
    /// folder exists or can be made and takes a new file. Nothing is replaced (an empty temporary file is written
    /// and removed); the folder is created.
    /// </summary>
    /// <exception cref="OutputFileException">It could not be written; the message names <paramref name="path"/>.</exception>
    public static void Check(string path)
    {
        ArgumentNullException.ThrowIfNull(path);
        TryDelete(Stage(path, []).Temporary);
    }

    /// <summary>
    /// Writes several files that belong together (a report and the files it names), in order: every file is written
    /// whole to its temporary file first, and only when all of them are on disk do they replace their targets, one
    /// rename after another, the last named last. A failure writing any of them replaces none (the previous files all
    /// stay), and an interrupted run leaves at most the span of a few renames in which some are new and some old.
    /// </summary>
    /// <exception cref="OutputFileException">A target is not a regular file, or it cannot be written; the message names it.</exception>
    public static void WriteAll(IReadOnlyList<(string Path, byte[] Bytes)> files)
    {
        ArgumentNullException.ThrowIfNull(files);
        var staged = new List<Staged>(files.Count);
        try
        {
            foreach ((string path, byte[] bytes) in files)
            {
                ArgumentNullException.ThrowIfNull(path);
                staged.Add(Stage(path, bytes));
            }

            foreach (Staged file in staged)
            {
                file.Replace();
            }
        }
        finally
        {
            foreach (Staged file in staged)
            {
                TryDelete(file.Temporary);
            }
        }
    }

    /// <summary>
    /// Writes <paramref name="bytes"/> to a new temporary file beside <paramref name="path"/>'s target, flushed to
    /// disk; the caller replaces the target with it (<see cref="Staged.Replace"/>) and deletes it on every exit path.
    /// </summary>
    private static Staged Stage(string path, ReadOnlySpan<byte> bytes)
    {
        string target = Target(path);
        string directory = Path.GetDirectoryName(target) ?? ".";
        string name = Path.GetFileName(target);
        if (name.Length == 0)
        {
            throw new OutputFileException($"Cannot write {path}: it names a folder, not a file.");
        }

        string temporary = Path.Combine(directory, $".{name}.{Environment.ProcessId}.{Guid.NewGuid():N}.tmp");
        try
        {
            Directory.CreateDirectory(directory);
            RemoveStale(directory, name);
            using var stream = new FileStream(temporary, FileMode.CreateNew, FileAccess.Write, FileShare.None);
            stream.Write(bytes);
            stream.Flush(flushToDisk: true);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or NotSupportedException or ArgumentException)
        {
            TryDelete(temporary);
            throw new OutputFileException($"Cannot write {path}: {Reason(e)}", e);
        }

        return new Staged(path, target, temporary);
    }

    /// <summary>A file written whole to <see cref="Temporary"/>, waiting to replace <see cref="Target"/>.</summary>
    private sealed record Staged(string Path, string Target, string Temporary)
    {
        /// <summary>Replaces the target with the temporary file in one rename.</summary>
        public void Replace()
        {
            try
            {
                File.Move(Temporary, Target, overwrite: true);
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException or NotSupportedException or ArgumentException)
            {
                throw new OutputFileException($"Cannot write {Path}: {Reason(e)}", e);
            }
        }
    }

    /// <summary>The regular file to replace: <paramref name="path"/>, or the file a symbolic link at it points to.</summary>
    private static string Target(string path)
    {
        if (path.Contains('\0', StringComparison.Ordinal) || path.Length == 0)
        {
            throw new OutputFileException($"Cannot write '{Printable(path)}': it is not a valid file path (empty, or with a NUL character).");
        }

        string full;
        try
        {
            full = Path.GetFullPath(path);
        }
        catch (Exception e) when (e is ArgumentException or NotSupportedException or PathTooLongException)
        {
            throw new OutputFileException($"Cannot write '{Printable(path)}': it is not a valid file path.", e);
        }

        for (int hops = 0; hops < 32; hops++)
        {
            var info = new FileInfo(full);
            if (info.LinkTarget is string link)
            {
                full = Path.GetFullPath(link, Path.GetDirectoryName(full) ?? ".");
                continue;
            }

            switch (FileKind.Of(full))
            {
                case FileKindValue.Directory:
                    throw new OutputFileException($"Cannot write {path}: it is a folder.");
                case FileKindValue.Special:
                    throw new OutputFileException($"Refusing to replace {path}: it is not a regular file (a device, pipe or socket).");
                default:
                    return full;
            }
        }

        throw new OutputFileException($"Cannot write {path}: it is a chain of more than 32 symbolic links.");
    }

    /// <summary>Removes temporary files of earlier writes to <paramref name="name"/> whose process is gone.</summary>
    private static void RemoveStale(string directory, string name)
    {
        string prefix = $".{name}.";
        foreach (string file in Directory.EnumerateFiles(directory, $".{name}.*.tmp"))
        {
            string rest = Path.GetFileName(file)[prefix.Length..];
            int dot = rest.IndexOf('.', StringComparison.Ordinal);
            if (dot > 0 && int.TryParse(rest[..dot], NumberStyles.None, CultureInfo.InvariantCulture, out int pid) && pid != Environment.ProcessId && !Alive(pid))
            {
                TryDelete(file);
            }
        }
    }

    private static bool Alive(int pid)
    {
        try
        {
            using var process = Process.GetProcessById(pid);
            return !process.HasExited;
        }
        catch (Exception e) when (e is ArgumentException or InvalidOperationException)
        {
            return false;
        }
    }

    private static void TryDelete(string file)
    {
        try
        {
            File.Delete(file);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            // Nothing more can be done; the next write removes it once this process is gone.
        }
    }

    private static string Reason(Exception e) => e switch
    {
        UnauthorizedAccessException => "permission denied",
        DirectoryNotFoundException => "its folder cannot be created",
        PathTooLongException => "the path is too long",
        IOException io when io.HResult == 28 || io.Message.Contains("space", StringComparison.OrdinalIgnoreCase) => "no space left on the device",
        _ => e.Message,
    };

    private static string Printable(string path) => new([.. path.Select(c => char.IsControl(c) ? '?' : c)]);
}
