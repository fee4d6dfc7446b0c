using System.Numerics;
using Ballistic.Planner.Planning;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Paths;

namespace Ballistic.Runtime.Events;

/// <summary>
/// One thing that happened to an agent during a tick (<see cref="JumpWorld.Events"/>). Positions are the trunk
/// centre in world metres (Y up); times are world seconds (<see cref="JumpWorld.Time"/>).
/// </summary>
/// <param name="Kind">What happened.</param>
/// <param name="Agent">The agent.</param>
/// <param name="Tick">The tick during which it happened.</param>
/// <param name="Time">World time of the event, seconds: for a move, the exact time it starts or ends (it may fall between two ticks).</param>
/// <param name="Jump">
/// For move events (jump and walk events, and <see cref="JumpEventKind.TargetReached"/> at the end of a path), the
/// move's index among the current path's moves (jumps and walks counted together, <see cref="Paths.AgentPath.Moves"/>);
/// −1 otherwise. Also <see cref="Move"/>.
/// </param>
/// <param name="From">Takeoff trunk centre (jump events), the trunk centre where a walk starts (walk events), or the agent's trunk centre.</param>
/// <param name="To">Landing trunk centre (jump events), the trunk centre where a walk ends (walk events), or the target (path events).</param>
/// <param name="Velocity">Takeoff velocity of the trunk centre, m/s (jump events); zero otherwise.</param>
/// <param name="FlightTime">Flight time of the jump (jump events) or duration of the walk (walk events), seconds; zero otherwise. Also <see cref="Duration"/>.</param>
/// <param name="Status">For <see cref="JumpEventKind.PathFailed"/>, the planner's status; <see cref="PlannerStatus.Exact"/> otherwise.</param>
/// <param name="Reason">For failures and removals, one sentence saying why; <c>null</c> otherwise.</param>
/// <param name="Path">
/// For <see cref="JumpEventKind.PathFound"/>, the path found; for jump and walk events and a
/// <see cref="JumpEventKind.TargetReached"/> at the end of a path, the path they belong to (<see cref="Jump"/>
/// indexes its moves), kept so that a reader draining late still knows the move's stances after the agent has moved
/// on; <c>null</c> otherwise.
/// </param>
public readonly record struct JumpEvent(
    JumpEventKind Kind,
    AgentHandle Agent,
    long Tick,
    double Time,
    int Jump,
    Vector3 From,
    Vector3 To,
    Vector3 Velocity,
    float FlightTime,
    PlannerStatus Status,
    string? Reason,
    AgentPath? Path = null)
{
    /// <summary>The move's index on the current path (the same as <see cref="Jump"/>); −1 for events that are not of a move.</summary>
    public int Move => Jump;

    /// <summary>How long the move takes, seconds: a jump's flight time or a walk's duration (the same as <see cref="FlightTime"/>).</summary>
    public float Duration => FlightTime;

    /// <summary>True for the events of a walk (<see cref="JumpEventKind.WalkStarted"/>, <see cref="JumpEventKind.WalkFinished"/>).</summary>
    public bool IsWalk => Kind is JumpEventKind.WalkStarted or JumpEventKind.WalkFinished;
}
