using System.Text;

namespace Ballistic.Cli;

/// <summary>
/// Names read from files (a limb spec's or a rig's <c>name</c>, a level's file name) made safe as part of an output
/// file's name: data, never a path. A mod's spec named <c>../../x/evil</c> must not choose where the tool writes.
/// </summary>
internal static class OutputName
{
    /// <summary>Longest slug, in characters.</summary>
    public const int MaxLength = 64;

    /// <summary>
    /// <paramref name="name"/> with every character but ASCII letters, digits, '-', '_' and '.' replaced by '_', without
    /// leading or trailing dots and underscores (no hidden file, no "..") and cut to <see cref="MaxLength"/>;
    /// <paramref name="fallback"/> when nothing is left.
    /// </summary>
    public static string Slug(string name, string fallback)
    {
        var text = new StringBuilder(Math.Min(name.Length, 4 * MaxLength));
        foreach (char c in name.AsSpan(0, Math.Min(name.Length, 4 * MaxLength)))
        {
            text.Append(char.IsAsciiLetterOrDigit(c) || c is '-' or '_' or '.' ? c : '_');
        }

        string slug = text.ToString().Trim('.', '_');
        slug = slug.Length > MaxLength ? slug[..MaxLength].TrimEnd('.', '_') : slug;
        return slug.Length == 0 ? fallback : slug;
    }
}
