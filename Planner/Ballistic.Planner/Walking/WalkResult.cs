using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Walking;

/// <summary>The outcome of <see cref="WalkSteering.Steer"/>: the walk, or why there is none.</summary>
/// <param name="Walk">The walk when valid, otherwise <c>null</c>.</param>
/// <param name="Failure"><see cref="WalkFailure.None"/> when valid, otherwise the first check that failed.</param>
internal readonly record struct WalkResult(Walk? Walk, WalkFailure Failure)
{
    /// <summary>True when a valid walk was found.</summary>
    public bool Succeeded => Walk is not null;
}
