namespace Ballistic.Planner.Characters;

/// <summary>A closed range of heights, metres.</summary>
/// <param name="Min">Lowest height, metres.</param>
/// <param name="Max">Highest height, metres (≥ <paramref name="Min"/>).</param>
internal readonly record struct HeightRange(float Min, float Max)
{
    /// <summary>The height at fraction <paramref name="t"/> (0 = <see cref="Min"/>, 1 = <see cref="Max"/>).</summary>
    public float Lerp(float t) => Min + ((Max - Min) * t);

    /// <summary>True when both ends are finite, positive and in order.</summary>
    public bool IsValid => float.IsFinite(Min) && float.IsFinite(Max) && Min > 0f && Min <= Max;
}
