namespace Ballistic.Planner.Roadmaps;

/// <summary>
/// One move of a planned path, from one stance to the next: a <see cref="Jump"/> (a ballistic flight) or a
/// <see cref="Walk"/> (steps along the ground).
/// </summary>
public abstract record Move
{
    /// <summary>Prevents other move kinds outside the planner.</summary>
    private protected Move()
    {
    }

    /// <summary>The stance the move leaves (start, roadmap node or goal).</summary>
    public abstract RoadmapNode From { get; }

    /// <summary>The stance the move reaches.</summary>
    public abstract RoadmapNode To { get; }

    /// <summary>How long the move takes, seconds: a jump's flight time, a walk's length over the walking speed.</summary>
    public abstract float Duration { get; }

    /// <summary>
    /// The jumps of the searched path (takeoff id, landing id) this move stands in for part of, when the query cut
    /// them down to the ground they must cross (<see cref="Query.QuerySettings.TightenJumps"/>); empty for a move as
    /// searched. A walk joined from several may stand in for two. When such a move does not animate, the repair
    /// keeps those jumps whole (<see cref="Query.QuerySettings.UncutJumps"/>) instead of setting the move aside.
    /// </summary>
    public IReadOnlyList<(int From, int To)> CutFrom { get; init; } = [];

    /// <summary>
    /// The walks of the searched path (from id, to id) this move stands in for part of, when the query hopped over a
    /// spot of them the body could not walk (<see cref="Query.QuerySettings.HopSpots"/>); empty for a move as
    /// searched. When such a move does not animate either, the repair sets those walks aside.
    /// </summary>
    public IReadOnlyList<(int From, int To)> HoppedFrom { get; init; } = [];
}
