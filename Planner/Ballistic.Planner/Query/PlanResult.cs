using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;

namespace Ballistic.Planner.Query;

/// <summary>The outcome of a path query.</summary>
/// <param name="Status"><see cref="PlannerStatus.Exact"/> when a path was found, otherwise why not.</param>
/// <param name="Reason">One sentence explaining the status.</param>
/// <param name="Start">The start node placed at the requested start point (a roadmap node when the roadmap holds that very pose), when one could be placed.</param>
/// <param name="Goal">The goal node placed at the requested goal point, when one could be placed.</param>
/// <param name="Moves">The moves (jumps and walks) from start to goal, in order; empty unless the status is exact.</param>
/// <param name="Elapsed">Wall-clock duration of the query.</param>
public sealed record PlanResult(PlannerStatus Status, string Reason, RoadmapNode? Start, RoadmapNode? Goal, IReadOnlyList<Move> Moves, TimeSpan Elapsed)
{
    // A cache of the jump moves, valid for the moves list it was made from ('with' copies it along).
    private (IReadOnlyList<Move>? Of, IReadOnlyList<Jump> Jumps) _jumps;

    /// <summary>Where the requested start put the start stance (distances included), when the query got that far.</summary>
    internal EndpointPlacement? StartPlacement { get; init; }

    /// <summary>Where the requested goal put the goal stance (distances included), when the query got that far.</summary>
    internal EndpointPlacement? GoalPlacement { get; init; }

    /// <summary>
    /// How many nodes the A* search expanded (0 when the request ended before searching): a measure of the search's
    /// work, for callers that budget many requests.
    /// </summary>
    public int Expansions { get; init; }

    /// <summary>
    /// The path's cost in the search that found it, seconds: walking time (times the surfaces' travel costs) plus each
    /// jump's flight time and efforts (<see cref="QuerySettings.JumpCost(in Steering.BallisticArc)"/>); 0 when no path was found.
    /// </summary>
    internal float Cost { get; init; }

    /// <summary>The jump moves of <see cref="Moves"/>, in order.</summary>
    public IReadOnlyList<Jump> Jumps
    {
        get
        {
            if (!ReferenceEquals(_jumps.Of, Moves))
            {
                _jumps = (Moves, Moves as IReadOnlyList<Jump> ?? [.. Moves.OfType<Jump>()]);
            }

            return _jumps.Jumps;
        }
    }

    /// <summary>The walk moves of <see cref="Moves"/>, in order.</summary>
    public IEnumerable<Walk> Walks => Moves.OfType<Walk>();

    /// <summary>Total flight time of the path's jumps, seconds.</summary>
    public float TotalFlightTime => Jumps.Sum(j => j.Arc.FlightTime);

    /// <summary>Total time of the path's moves (flights and walks), seconds.</summary>
    public float TotalDuration => Moves.Sum(m => m.Duration);
}
