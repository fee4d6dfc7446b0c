namespace Ballistic.Planner.Steering;

/// <summary>The outcome of one call of the parabola steering method.</summary>
/// <param name="Failure"><see cref="SteeringFailure.None"/> on success, otherwise why no jump exists.</param>
/// <param name="Arc">The jump found; meaningful only on success.</param>
internal readonly record struct SteeringResult(SteeringFailure Failure, BallisticArc Arc)
{
    /// <summary>True when a valid jump was found.</summary>
    public bool Succeeded => Failure == SteeringFailure.None;

    /// <summary>A failed result.</summary>
    public static SteeringResult Fail(SteeringFailure failure) => new(failure, default);
}
