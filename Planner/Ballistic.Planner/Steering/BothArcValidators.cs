namespace Ballistic.Planner.Steering;

/// <summary>An arc is valid when the first validator accepts it and then the second does.</summary>
internal sealed class BothArcValidators(IArcValidator first, IArcValidator second) : IArcValidator
{
    /// <summary>The validator asked first (the cheaper or built-in one).</summary>
    public IArcValidator First { get; } = first;

    /// <summary>The validator asked second.</summary>
    public IArcValidator Second { get; } = second;

    /// <inheritdoc/>
    public bool IsValid(in BallisticArc arc) => First.IsValid(arc) && Second.IsValid(arc);
}
