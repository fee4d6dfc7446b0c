using System.Text;

namespace Ballistic.Runtime.Core;

/// <summary>Text made safe for a one-line message: control characters (line breaks, tabs) escaped.</summary>
internal static class OneLine
{
    /// <summary>The text with every control character written as <c>\uXXXX</c>.</summary>
    public static string Of(string text)
    {
        if (!text.Any(char.IsControl))
        {
            return text;
        }

        var builder = new StringBuilder(text.Length + 8);
        foreach (char c in text)
        {
            builder.Append(char.IsControl(c) ? $"\\u{(int)c:x4}" : c);
        }

        return builder.ToString();
    }

    /// <summary>The first characters of a fingerprint, for messages.</summary>
    public static string Short(string fingerprint) => fingerprint.Length <= 12 ? fingerprint : fingerprint[..12] + "…";
}
