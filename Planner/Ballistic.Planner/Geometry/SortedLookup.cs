namespace Ballistic.Planner.Geometry;

/// <summary>
/// Finds, in values sorted ascending (an animation's frame times, a walk's cumulative lengths), the first at or
/// above a given value, by equal slices of their span: each slice knows its first value at or above its start, and
/// the search steps over a value or two from there instead of halving through them all (it runs several times for
/// every moving agent every tick). The answer is exactly a search's: the index of the first value at or above the
/// one asked for.
/// </summary>
internal sealed class SortedLookup
{
    private readonly float[] _values;

    /// <summary>Per slice of <see cref="_width"/> from the first value: the first value at or above the slice's start.</summary>
    private readonly int[] _slices;

    /// <summary>The span each slice covers (0 when the values do not span any).</summary>
    private readonly float _width;

    /// <summary>Indexes <paramref name="values"/> (sorted ascending, finite, at least one; kept, not copied), as many slices as values.</summary>
    public SortedLookup(float[] values)
    {
        _values = values;
        float width = values.Length > 1 ? (values[^1] - values[0]) / values.Length : 0f;
        if (!(width > 0f))
        {
            _slices = [0];
            return;
        }

        _width = width;
        _slices = new int[values.Length];
        int i = 0;
        for (int s = 0; s < _slices.Length; s++)
        {
            float start = values[0] + (s * width);
            while (i < values.Length - 1 && values[i] < start)
            {
                i++;
            }

            _slices[s] = i;
        }
    }

    /// <summary>
    /// Index of the first value at or above <paramref name="value"/>: 0 for one at or below the first value (and for
    /// NaN), the last index for one above the last value.
    /// </summary>
    public int FirstAtOrAbove(float value)
    {
        int last = _values.Length - 1;
        if (last <= 0 || !(value > _values[0]))
        {
            return 0;
        }

        if (!(value <= _values[last]))
        {
            return last;
        }

        // Every value before the slice's first lies below the slice's start, so below value: step on from it (and
        // back, where rounding put value a hair below its slice's start).
        return StepTo(_slices[Math.Min(_slices.Length - 1, (int)((value - _values[0]) / _width))], value, int.MaxValue);
    }

    /// <summary>
    /// <see cref="FirstAtOrAbove(float)"/> searched from <paramref name="hint"/>, the answer for a nearby value (an
    /// agent's last tick), stepping a few values from it instead of finding the slice: the same answer whatever the
    /// hint (out of range, or more than a few values away, it searches as usual). Sets <paramref name="hint"/> to it.
    /// </summary>
    public int FirstAtOrAbove(float value, ref int hint)
    {
        int last = _values.Length - 1;
        if ((uint)hint <= (uint)last && last > 0 && value > _values[0] && value <= _values[last] && StepTo(hint, value, 4) is >= 0 and int near)
        {
            return hint = near;
        }

        return hint = FirstAtOrAbove(value);
    }

    /// <summary>
    /// The first index at or above <paramref name="value"/> (above the first value, at most the last), stepped to from
    /// <paramref name="i"/>: back while the value before is at or above, on while this one is below; −1 when that
    /// takes more than <paramref name="budget"/> steps.
    /// </summary>
    private int StepTo(int i, float value, int budget)
    {
        int steps = 0;
        while (i > 0 && _values[i - 1] >= value)
        {
            if (steps++ == budget)
            {
                return -1;
            }

            i--;
        }

        while (_values[i] < value)
        {
            if (steps++ == budget)
            {
                return -1;
            }

            i++;
        }

        return i;
    }
}
