namespace Ballistic.Planner.IO;

/// <summary>Lower-case hexadecimal text of bytes (fingerprints and checksums), the same on every target framework.</summary>
internal static class HexText
{
    /// <summary><paramref name="bytes"/> as lower-case hexadecimal, two digits a byte.</summary>
    public static string Lower(ReadOnlySpan<byte> bytes)
    {
#if NET9_0_OR_GREATER
        return Convert.ToHexStringLower(bytes);
#else
        return Convert.ToHexString(bytes).ToLowerInvariant();
#endif
    }
}
