using System.Globalization;
using System.Runtime.InteropServices;
using System.Text;

namespace Ballistic.Planner.IO;

/// <summary>
/// Reads input files (glTF, GLB, their buffers and images, limb specs) safely: only regular files, following
/// symbolic links; a named pipe, device, socket or directory is refused without being opened (opening a pipe would
/// wait forever, a device would never end), and a file larger than the byte limit is refused before it is read.
/// Problems come back as a phrase ("is a named pipe, not a regular file") that the caller puts after the file's name.
/// </summary>
internal static class InputFile
{
    private const int StatxModeOffset = 28;
    private const int StatxBufferSize = 256;
    private const int AtFdCwd = -100;
    private const uint StatxType = 0x1;
    private const int Enoent = 2;
    private const int Enotdir = 20;

    private static bool s_statxMissing;

    /// <summary>The whole content of the regular file at <paramref name="path"/>.</summary>
    /// <param name="path">The file.</param>
    /// <param name="maxBytes">The most bytes it may hold.</param>
    /// <param name="limit">What sets <paramref name="maxBytes"/>, for the message (e.g. "GltfLoadOptions.MaxBytes").</param>
    /// <param name="fail">Makes the exception from a phrase saying what is wrong and the error behind it, if any.</param>
    public static byte[] Read(string path, long maxBytes, string limit, Func<string, Exception?, Exception> fail)
    {
        ArgumentNullException.ThrowIfNull(path);
        if (path.Contains('\0', StringComparison.Ordinal))
        {
            throw fail("has a NUL character in its name", null);
        }

        if (path.Length == 0)
        {
            throw fail("cannot be read: the path is empty", null);
        }

        if (Problem(path) is string problem)
        {
            throw fail(problem, null);
        }

        try
        {
            using var stream = new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.Read, bufferSize: 1, FileOptions.SequentialScan);
            long length = stream.Length;
            if (length > maxBytes)
            {
                throw fail(string.Create(CultureInfo.InvariantCulture, $"is {length} bytes, more than the {maxBytes} bytes allowed ({limit})"), null);
            }

            if (length > Array.MaxLength)
            {
                throw fail(string.Create(CultureInfo.InvariantCulture, $"is {length} bytes, more than one file can hold in memory"), null);
            }

            byte[] bytes = new byte[length];
            stream.ReadExactly(bytes);
            return bytes;
        }
        catch (EndOfStreamException e)
        {
            throw fail("became shorter while it was being read", e);
        }
        catch (FileNotFoundException e)
        {
            throw fail("cannot be read: it does not exist", e);
        }
        catch (DirectoryNotFoundException e)
        {
            throw fail("cannot be read: its folder does not exist", e);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or NotSupportedException or ArgumentException)
        {
            throw fail($"cannot be read: {MessageText.Printable(e.Message.TrimEnd('.'))}", e);
        }
    }

    /// <summary>
    /// Why <paramref name="path"/> cannot be read as a regular file, or <c>null</c> when it is one (or when opening
    /// it will say what is wrong, such as a missing permission).
    /// </summary>
    internal static string? Problem(string path)
    {
        if (OperatingSystem.IsLinux() && !s_statxMissing)
        {
            try
            {
                return StatxProblem(path);
            }
            catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
            {
                s_statxMissing = true;
            }
        }

        return PortableProblem(path);
    }

    /// <summary>The file type from <c>statx</c> (Linux), which follows symbolic links and never opens the file.</summary>
    internal static string? StatxProblem(string path)
    {
        byte[] name = Encoding.UTF8.GetBytes(path + "\0");
        byte[] buffer = new byte[StatxBufferSize];
        if (NativeMethods.Statx(AtFdCwd, name, 0, StatxType, buffer) != 0)
        {
            int error = Marshal.GetLastPInvokeError();
            return error is Enoent or Enotdir ? "cannot be read: it does not exist" : null;
        }

        int type = BitConverter.ToUInt16(buffer, StatxModeOffset) & 0xF000;
        return type switch
        {
            0x8000 => null,
            0x4000 => "is a folder, not a file",
            0x1000 => "is a named pipe, not a regular file",
            0x2000 => "is a character device, not a regular file",
            0x6000 => "is a block device, not a regular file",
            0xC000 => "is a socket, not a regular file",
            _ => "is not a regular file",
        };
    }

    /// <summary>
    /// Without <c>statx</c>, .NET cannot tell a regular file from a pipe or device, but those report no size: an
    /// entry of zero bytes is refused unopened, and a file is read up to the size it reports, never further.
    /// </summary>
    internal static string? PortableProblem(string path)
    {
        if (Directory.Exists(path))
        {
            return "is a folder, not a file";
        }

        try
        {
            var info = new FileInfo(path);
            FileSystemInfo target = info.LinkTarget is null ? info : info.ResolveLinkTarget(returnFinalTarget: true) ?? info;
            if (!target.Exists)
            {
                return Directory.Exists(target.FullName) ? "is a folder, not a file" : "cannot be read: it does not exist";
            }

            return target is FileInfo file && file.Length == 0 ? "is empty, or not a regular file (a named pipe or device)" : null;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return null;
        }
    }

    private static class NativeMethods
    {
        [DllImport("libc", EntryPoint = "statx", SetLastError = true)]
        [DefaultDllImportSearchPaths(DllImportSearchPath.SafeDirectories)]
        public static extern int Statx(int directory, byte[] path, int flags, uint mask, byte[] buffer);
    }
}
