using System.Numerics;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Runtime.Agents;

/// <summary>
/// One agent's request for a path: started on a tick within the budget, searched and animated in the background,
/// delivered on a fixed later tick. Pooled by the world's <see cref="PathQueue"/>: made ready for each use by
/// <see cref="Reset"/> and given back once delivered or dropped with its job ended, so that a crowd sent to new targets
/// allocates no request on the tick thread once the pool has grown. Each keeps its own <see cref="RequestJob"/>, reused
/// with it.
/// </summary>
internal sealed class PathRequest
{
    /// <summary>The agent that asked.</summary>
    public AgentHandle Agent { get; private set; }

    /// <summary>The point asked for, world metres.</summary>
    public Vector3 Target { get; private set; }

    /// <summary>The roadmap edge to perform as the whole path, with no search (<see cref="JumpWorld.PerformJump"/>); −1 to search. Only the job's first round performs it; once set aside, its later rounds search.</summary>
    public int ForcedEdge { get; set; } = -1;

    /// <summary>
    /// The moves to perform as the whole path, with no search (<see cref="JumpWorld.PerformMoves"/>); <c>null</c> to
    /// search. Only the job's first round performs them; once one is set aside, its later rounds search.
    /// </summary>
    public IReadOnlyList<Move>? ForcedMoves { get; set; }

    /// <summary>The stance searched from.</summary>
    public RoadmapNode? Start { get; set; }

    /// <summary>The kind whose roadmap was searched and whose animator animated (the agent's when the request started).</summary>
    public CharacterKind? Character { get; set; }

    /// <summary>The tick on which the path is delivered to its agent.</summary>
    public long DueTick { get; set; }

    /// <summary>The request's search and animation, run on a background thread or on the tick; reused with the request.</summary>
    public RequestJob Job { get; } = new();

    /// <summary>The outcome of the search and animation once read on the tick thread (run there, or its background job ended).</summary>
    public RequestOutcome? Outcome { get; set; }

    /// <summary>True once a tick stopped waiting for this request's animation (<see cref="Core.WorldSettings.MaxAnimationWait"/> spent): it is delivered at the first tick its animation is ready.</summary>
    public bool Late { get; set; }

    /// <summary>Makes the request ready for a new use: <paramref name="agent"/>'s, to <paramref name="target"/> (world metres), performing roadmap edge <paramref name="forcedEdge"/> (−1: searching).</summary>
    public void Reset(AgentHandle agent, Vector3 target, int forcedEdge)
    {
        Agent = agent;
        Target = target;
        ForcedEdge = forcedEdge;
        ForcedMoves = null;
        Start = null;
        Character = null;
        DueTick = 0;
        Outcome = null;
        Late = false;
    }
}
