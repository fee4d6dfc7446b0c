using Ballistic.Planner.Sampling;

namespace Ballistic.Planner.Query;

/// <summary>Parameters of a path query.</summary>
public sealed record QuerySettings
{
    /// <summary>How close the start and goal stances' contacts must come to the requested points (<see cref="TrunkSampler.Place"/>).</summary>
    public EndpointTolerance Tolerance { get; init; } = new();

    /// <summary>Start and goal are steered to and from at most this many nearest roadmap nodes within reach.</summary>
    public int MaxNeighbours { get; init; } = 32;

    /// <summary>Steering to (from) nearer nodes stops once the start (goal) has this many jumps into the roadmap.</summary>
    public int Connections { get; init; } = 4;

}
