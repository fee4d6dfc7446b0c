namespace Ballistic.Planner.Sampling;

/// <summary>Derives independent, reproducible random streams from a user seed and a stream index (SplitMix64).</summary>
internal static class SeedMixer
{
    /// <summary>A seed for <see cref="Random"/> that depends only on (<paramref name="seed"/>, <paramref name="stream"/>, <paramref name="salt"/>).</summary>
    public static int Mix(int seed, long stream, ulong salt = 0)
    {
        ulong z = unchecked(((ulong)(uint)seed << 32) ^ (ulong)stream ^ (salt * 0xD1B54A32D192ED03UL));
        z = unchecked(z + 0x9E3779B97F4A7C15UL);
        z = unchecked((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL);
        z = unchecked((z ^ (z >> 27)) * 0x94D049BB133111EBUL);
        z ^= z >> 31;
        return (int)(z & 0x7FFFFFFF);
    }

    /// <summary>A <see cref="Random"/> for the stream.</summary>
    public static Random Create(int seed, long stream, ulong salt = 0) => new(Mix(seed, stream, salt));
}
