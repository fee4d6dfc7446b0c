namespace Ballistic.Planner.Query;

/// <summary>Parameters of a path query.</summary>
public sealed record QuerySettings
{
    /// <summary>Radius (metres) around the start and goal points searched for a valid root pose.</summary>
    public float ProjectionRadius { get; init; } = 1.5f;

    /// <summary>Start and goal are steered to and from at most this many nearest roadmap nodes within reach.</summary>
    public int MaxNeighbours { get; init; } = 48;

    /// <summary>Seed of the start and goal pose sampling.</summary>
    public int Seed { get; init; } = 1;
}
