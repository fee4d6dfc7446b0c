using Ballistic.Planner.IO;

namespace Ballistic.Runtime.Core;

/// <summary>Text made safe for a one-line message: control characters (line breaks, tabs) escaped.</summary>
internal static class OneLine
{
    /// <summary>The text with every control character written as <c>\uXXXX</c> (the planner's one escape for messages).</summary>
    public static string Of(string text) => MessageText.Printable(text);

    /// <summary>The first characters of a fingerprint, for messages.</summary>
    public static string Short(string fingerprint) => fingerprint.Length <= 12 ? fingerprint : fingerprint[..12] + "…";
}
