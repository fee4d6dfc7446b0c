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

    /// <summary>
    /// A JSON syntax error for users: the parser's sentence without .NET's 0-based "LineNumber: 0 | BytePositionInLine: 11"
    /// (or "Path: …") suffix and its advice to programmers, followed by the 1-based place, "(line 1, column 12)", where
    /// the parser knows it.
    /// </summary>
    internal static string Json(System.Text.Json.JsonException e)
    {
        string text = e.Message;
        foreach (string marker in (string[])[" Path: ", " LineNumber: "])
        {
            int at = text.IndexOf(marker, StringComparison.Ordinal);
            if (at >= 0)
            {
                text = text[..at];
            }
        }

        // .NET's advice to programmers ("Change the reader options") means nothing to whoever wrote the file.
        text = text.Replace(" which is not supported in this mode", "", StringComparison.Ordinal).Replace(". Change the reader options", "", StringComparison.Ordinal);
        text = Printable(text.TrimEnd().TrimEnd('.', '|').TrimEnd());
        return e.LineNumber is long line
            ? string.Create(System.Globalization.CultureInfo.InvariantCulture, $"{text} (line {line + 1}, column {(e.BytePositionInLine ?? 0) + 1})")
            : text;
    }
}
