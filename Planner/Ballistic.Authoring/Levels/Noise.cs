namespace Ballistic.Authoring.Levels;

/// <summary>Deterministic smooth value noise for the level generators (no dependence on the runtime's Random).</summary>
internal static class Noise
{
    /// <summary>A hash of an integer lattice point to [0, 1).</summary>
    public static float Hash(int x, int y, int seed)
    {
        uint h = unchecked((uint)((x * 374761393) + (y * 668265263) + (seed * 1442695041)));
        h = unchecked((h ^ (h >> 13)) * 1274126177u);
        h ^= h >> 16;
        return (h & 0xFFFFFF) / (float)0x1000000;
    }

    /// <summary>Smoothly interpolated lattice noise in [0, 1).</summary>
    public static float Value(float x, float y, int seed)
    {
        int x0 = (int)MathF.Floor(x);
        int y0 = (int)MathF.Floor(y);
        float fx = x - x0;
        float fy = y - y0;
        float sx = fx * fx * (3f - (2f * fx));
        float sy = fy * fy * (3f - (2f * fy));
        float a = Hash(x0, y0, seed);
        float b = Hash(x0 + 1, y0, seed);
        float c = Hash(x0, y0 + 1, seed);
        float d = Hash(x0 + 1, y0 + 1, seed);
        return float.Lerp(float.Lerp(a, b, sx), float.Lerp(c, d, sx), sy);
    }
}
