namespace Ballistic.Runtime.Skeletons;

/// <summary>Key lookup shared by the baked tracks.</summary>
internal static class KeyTimes
{
    /// <summary>
    /// The last key at or before <paramref name="time"/> (the first key before the track starts) and the weight of
    /// the next key, zero at or beyond the ends.
    /// </summary>
    public static int Before(float[] times, float time, out float weight)
    {
        weight = 0f;
        if (times.Length == 0)
        {
            throw new InvalidOperationException("A baked track has no keys.");
        }

        if (time <= times[0])
        {
            return 0;
        }

        if (time >= times[^1])
        {
            return times.Length - 1;
        }

        int lo = 0;
        int hi = times.Length - 1;
        while (hi - lo > 1)
        {
            int mid = (lo + hi) / 2;
            if (times[mid] <= time)
            {
                lo = mid;
            }
            else
            {
                hi = mid;
            }
        }

        float span = times[hi] - times[lo];
        weight = span > 0f ? Math.Clamp((time - times[lo]) / span, 0f, 1f) : 0f;
        return lo;
    }
}
