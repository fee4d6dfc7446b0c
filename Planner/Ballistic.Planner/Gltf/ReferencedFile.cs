using System.Text.RegularExpressions;

namespace Ballistic.Planner.Gltf;

/// <summary>
/// Where a <c>.gltf</c>'s buffer or image URI points: only into the glTF's own folder or below. The URI is
/// percent-decoded first; a NUL character, a scheme (other than <c>data:</c>, handled by the caller), an absolute
/// path, a <c>..</c> that leaves the folder, or a symbolic link on the way that leads out of it is refused, so a
/// level or character cannot make Ballistic read any other file on the machine.
/// </summary>
internal static partial class ReferencedFile
{
    private const int MaxLinks = 40;

    private static readonly StringComparison PathComparison = OperatingSystem.IsWindows() || OperatingSystem.IsMacOS()
        ? StringComparison.OrdinalIgnoreCase
        : StringComparison.Ordinal;

    /// <summary>The full path of the file <paramref name="uri"/> names, relative to <paramref name="directory"/>.</summary>
    /// <param name="directory">The glTF's folder (absolute).</param>
    /// <param name="uri">The URI as written in the glTF (not a data URI).</param>
    /// <param name="fail">Makes the exception from a phrase saying what is wrong with the URI.</param>
    public static string Resolve(string directory, string uri, Func<string, Exception> fail)
    {
        ArgumentNullException.ThrowIfNull(directory);
        ArgumentNullException.ThrowIfNull(uri);
        if (uri.Contains('\0', StringComparison.Ordinal))
        {
            throw fail("has a NUL character");
        }

        if (Scheme().IsMatch(uri))
        {
            throw fail("has a scheme; only data: URIs and relative paths to files in the glTF's folder can be read");
        }

        string path = Uri.UnescapeDataString(uri);
        if (path.Contains('\0', StringComparison.Ordinal))
        {
            throw fail("has a NUL character once percent-decoded");
        }

        if (path.Length == 0)
        {
            throw fail("is empty");
        }

        if (path[0] is '/' or '\\' || Path.IsPathRooted(path))
        {
            throw fail("is an absolute path; only files in the glTF's folder or below can be read");
        }

        int depth = 0;
        foreach (string segment in path.Split('/', '\\'))
        {
            depth += segment switch
            {
                "" or "." => 0,
                ".." => -1,
                _ => 1,
            };
            if (depth < 0)
            {
                throw fail("leads out of the glTF's folder (through '..'); only files in the folder or below can be read");
            }
        }

        string folder = Path.TrimEndingDirectorySeparator(Path.GetFullPath(directory));
        string full = Path.GetFullPath(Path.Combine(folder, path));
        if (!Inside(full, folder))
        {
            throw fail("leads out of the glTF's folder; only files in the folder or below can be read");
        }

        string? real = RealPath(full);
        string? realFolder = RealPath(folder);
        if (real is null || realFolder is null)
        {
            throw fail("goes through a loop of symbolic links");
        }

        if (!Inside(real, realFolder))
        {
            throw fail($"leads, through a symbolic link, to {real}, outside the glTF's folder");
        }

        return full;
    }

    private static bool Inside(string path, string folder) =>
        path.Length > folder.Length
        && path.StartsWith(folder, PathComparison)
        && (Path.EndsInDirectorySeparator(folder) || path[folder.Length] == Path.DirectorySeparatorChar || path[folder.Length] == Path.AltDirectorySeparatorChar);

    /// <summary>
    /// <paramref name="path"/> (absolute) with every symbolic link along it resolved, as far as its entries exist;
    /// <c>null</c> after more than 40 links (a loop).
    /// </summary>
    internal static string? RealPath(string path)
    {
        string root = Path.GetPathRoot(path) ?? "";
        var pending = new Stack<string>(Enumerable.Reverse(path[root.Length..].Split(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar)));
        string current = root;
        int links = 0;
        while (pending.Count > 0)
        {
            string part = pending.Pop();
            if (part is "" or ".")
            {
                continue;
            }

            if (part == "..")
            {
                current = Path.GetDirectoryName(current) ?? root;
                continue;
            }

            string next = Path.Combine(current, part);
            string? target;
            try
            {
                target = new FileInfo(next).LinkTarget;
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                target = null;
            }

            if (target is null)
            {
                current = next;
                continue;
            }

            if (++links > MaxLinks)
            {
                return null;
            }

            if (Path.IsPathRooted(target))
            {
                root = Path.GetPathRoot(target) ?? root;
                current = root;
                target = target[root.Length..];
            }

            foreach (string t in Enumerable.Reverse(target.Split(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar)))
            {
                pending.Push(t);
            }
        }

        return current;
    }

    [GeneratedRegex("^[A-Za-z][A-Za-z0-9+.-]*:", RegexOptions.CultureInvariant)]
    private static partial Regex Scheme();
}
