namespace Ballistic.Planner.Geometry;

/// <summary>Easing curves shared by the animation and the walks.</summary>
internal static class Easing
{
    /// <summary>The smoothstep 3x² − 2x³ of <paramref name="x"/> clamped to [0, 1]: 0 to 1 with zero slope at both ends.</summary>
    public static float Smooth(float x)
    {
        x = Math.Clamp(x, 0f, 1f);
        return x * x * (3f - (2f * x));
    }
}
