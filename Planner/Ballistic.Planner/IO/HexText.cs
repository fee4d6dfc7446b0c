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
        return string.Create(bytes.Length * 2, bytes.ToArray(), static (chars, b) =>
        {
            const string Digits = "0123456789abcdef";
            for (int i = 0; i < b.Length; i++)
            {
                chars[2 * i] = Digits[b[i] >> 4];
                chars[(2 * i) + 1] = Digits[b[i] & 0xF];
            }
        });
#endif
    }
}
