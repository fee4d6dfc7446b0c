namespace Ballistic.Planner.Query;

/// <summary>Parameters of a path query.</summary>
public sealed record QuerySettings
{
    /// <summary>Radius (metres) around the start and goal points searched for a valid root pose: the pose stands on a surface point within this distance of the requested point.</summary>
    public float ProjectionRadius { get; init; } = 1.5f;

    /// <summary>Start and goal are steered to and from at most this many nearest roadmap nodes within reach.</summary>
    public int MaxNeighbours { get; init; } = 32;

    /// <summary>Steering to (from) nearer nodes stops once the start (goal) has this many jumps into the roadmap.</summary>
    public int Connections { get; init; } = 4;

    /// <summary>Seed of the start and goal pose sampling.</summary>
    public int Seed { get; init; } = 1;
}
