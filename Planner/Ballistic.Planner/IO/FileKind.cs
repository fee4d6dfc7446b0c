using System.Runtime.InteropServices;

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
/// The kind of file at a path. .NET does not expose the file type bits, so on Linux (x64 and Arm64) they are read
/// with libc's <c>stat</c>; elsewhere every existing non-folder counts as regular.
/// </summary>
internal static partial class FileKind
{
    private const uint TypeMask = 0xF000;
    private const uint RegularBits = 0x8000;
    private const uint DirectoryBits = 0x4000;

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

        return Mode(path) is uint mode
            ? (mode & TypeMask) switch
            {
                RegularBits => FileKindValue.Regular,
                DirectoryBits => FileKindValue.Directory,
                _ => FileKindValue.Special,
            }
            : FileKindValue.Regular;
    }

    /// <summary>st_mode of <paramref name="path"/> (links followed), or <c>null</c> where it cannot be read here.</summary>
    private static uint? Mode(string path)
    {
        int offset = RuntimeInformation.ProcessArchitecture switch
        {
            Architecture.X64 => 24, // st_dev 8, st_ino 8, st_nlink 8, st_mode
            Architecture.Arm64 => 16, // st_dev 8, st_ino 8, st_mode
            _ => -1,
        };
        if (!OperatingSystem.IsLinux() || offset < 0)
        {
            return null;
        }

        byte[] buffer = new byte[256];
        try
        {
            return Stat(path, buffer) == 0 ? BitConverter.ToUInt32(buffer, offset) : null;
        }
        catch (Exception e) when (e is EntryPointNotFoundException or DllNotFoundException)
        {
            return null;
        }
    }

    [LibraryImport("libc", EntryPoint = "stat", StringMarshalling = StringMarshalling.Utf8)]
    private static partial int Stat(string path, [Out] byte[] buffer);
}
