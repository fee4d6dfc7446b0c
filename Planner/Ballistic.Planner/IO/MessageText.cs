using System.Text;

namespace Ballistic.Planner.IO;

/// <summary>Text from files and the system, made safe to put in error messages.</summary>
internal static class MessageText
{
    /// <summary>The text with control characters escaped, for messages.</summary>
    internal static string Printable(string text)
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
}
