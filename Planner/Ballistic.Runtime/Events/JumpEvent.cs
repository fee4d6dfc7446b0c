using System.Numerics;
using Ballistic.Planner.Planning;
using Ballistic.Runtime.Agents;

namespace Ballistic.Runtime.Events;

/// <summary>
/// One thing that happened to an agent during a tick (<see cref="JumpWorld.Events"/>). Positions are the trunk
/// centre in world metres (Y up); times are world seconds (<see cref="JumpWorld.Time"/>).
/// </summary>
/// <param name="Kind">What happened.</param>
/// <param name="Agent">The agent.</param>
/// <param name="Tick">The tick during which it happened.</param>
/// <param name="Time">World time of the event, seconds: for a jump, the exact takeoff or landing time (it may fall between two ticks).</param>
/// <param name="Jump">For jump events, the jump's index on the current path; −1 otherwise.</param>
/// <param name="From">Takeoff trunk centre (jump events), or the agent's trunk centre.</param>
/// <param name="To">Landing trunk centre (jump events), or the target (path events).</param>
/// <param name="Velocity">Takeoff velocity of the trunk centre, m/s (jump events); zero otherwise.</param>
/// <param name="FlightTime">Flight time of the jump, seconds (jump events); zero otherwise.</param>
/// <param name="Status">For <see cref="JumpEventKind.PathFailed"/>, the planner's status; <see cref="PlannerStatus.Exact"/> otherwise.</param>
/// <param name="Reason">For failures and removals, one sentence saying why; <c>null</c> otherwise.</param>
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
    string? Reason);
