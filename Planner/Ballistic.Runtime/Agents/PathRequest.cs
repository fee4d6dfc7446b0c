using System.Numerics;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Runtime.Agents;

/// <summary>One agent's request for a path: started on a tick within the budget, searched and animated in the background, delivered on a fixed later tick.</summary>
internal sealed class PathRequest(AgentHandle agent, Vector3 target, long sequence)
{
    public AgentHandle Agent { get; } = agent;

    public Vector3 Target { get; } = target;

    /// <summary>The roadmap edge to perform as the whole path, with no search (<see cref="JumpWorld.PerformJump"/>); −1 to search (also once that edge was set aside).</summary>
    public int ForcedEdge { get; set; } = -1;

    /// <summary>
    /// The moves to perform as the whole path, with no search (<see cref="JumpWorld.PerformMoves"/>); <c>null</c> to
    /// search (also once one of them was set aside).
    /// </summary>
    public IReadOnlyList<Move>? ForcedMoves { get; set; }

    /// <summary>Order of the request: in-flight requests are delivered in this order.</summary>
    public long Sequence { get; } = sequence;

    /// <summary>Moves set aside because the body could not perform them, with why.</summary>
    public JumpRepair Repair { get; } = new();

    /// <summary>Searches made so far.</summary>
    public int Rounds { get; set; }

    /// <summary>The stance searched from.</summary>
    public RoadmapNode? Start { get; set; }

    /// <summary>The moves (jumps and walks) found by the last search.</summary>
    public IReadOnlyList<Move> Moves { get; set; } = [];

    /// <summary>The tick on which the path is delivered to its agent.</summary>
    public long DueTick { get; set; }

    /// <summary>The request's search and animation running in the background (null when run on the tick).</summary>
    public Task<RequestOutcome>? Job { get; set; }

    /// <summary>The outcome of the search and animation run on the tick.</summary>
    public RequestOutcome? Outcome { get; set; }
}
