using System.Numerics;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Runtime.Agents;

/// <summary>One agent's request for a path: started on a tick within the budget, searched and animated in the background, delivered on a fixed later tick.</summary>
internal sealed class PathRequest(AgentHandle agent, Vector3 target)
{
    public AgentHandle Agent { get; } = agent;

    public Vector3 Target { get; } = target;

    /// <summary>The roadmap edge to perform as the whole path, with no search (<see cref="JumpWorld.PerformJump"/>); −1 to search. Only the job's first round performs it; once set aside, its later rounds search.</summary>
    public int ForcedEdge { get; set; } = -1;

    /// <summary>
    /// The moves to perform as the whole path, with no search (<see cref="JumpWorld.PerformMoves"/>); <c>null</c> to
    /// search. Only the job's first round performs them; once one is set aside, its later rounds search.
    /// </summary>
    public IReadOnlyList<Move>? ForcedMoves { get; set; }

    /// <summary>Moves set aside because the body could not perform them, with why.</summary>
    public JumpRepair Repair { get; } = new();

    /// <summary>The stance searched from.</summary>
    public RoadmapNode? Start { get; set; }

    /// <summary>The kind whose roadmap was searched and whose animator animated (the agent's when the request started).</summary>
    public CharacterKind? Character { get; set; }

    /// <summary>The tick on which the path is delivered to its agent.</summary>
    public long DueTick { get; set; }

    /// <summary>
    /// The request's search and animation queued or running in the background (null when run on the tick): its result
    /// is null when the tick thread claimed and ran the work itself (<see cref="Outcome"/> then holds it).
    /// </summary>
    public Task<RequestOutcome?>? Job { get; set; }

    /// <summary>
    /// Runs the work <see cref="Job"/> runs, here and now, unless a thread has already started it (then null): the
    /// tick thread waiting for the request runs it itself while no background thread has.
    /// </summary>
    public Func<RequestOutcome?>? RunHere { get; set; }

    /// <summary>The outcome of the search and animation run on the tick thread.</summary>
    public RequestOutcome? Outcome { get; set; }

    /// <summary>True once a tick stopped waiting for this request's animation (<see cref="Core.WorldSettings.MaxAnimationWait"/> spent): it is delivered at the first tick its animation is ready.</summary>
    public bool Late { get; set; }
}
