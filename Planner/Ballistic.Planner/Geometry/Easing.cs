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

    /// <summary>
    /// The share of what is left of the way to a target pose to move at step <paramref name="k"/> of
    /// <paramref name="count"/>, so that a pose moved by these shares alone follows a smoothstep from its start to the
    /// target (and one also moved otherwise between the steps, as an IK solve moves it, still ends on the target).
    /// </summary>
    public static float Pull(int k, int count)
    {
        if (k <= 0 || count <= 0)
        {
            return 0f;
        }

        float before = Smooth((k - 1) / (float)count);
        return before >= 1f - 1e-6f ? 1f : Math.Clamp((Smooth(k / (float)count) - before) / (1f - before), 0f, 1f);
    }
}
