namespace Ballistic.Runtime.Events;

/// <summary>What happened to an agent. Within a tick, events come in system order (path requests, then locomotion) and, within a system, in agent slot order.</summary>
public enum JumpEventKind
{
    /// <summary>A path to the target was found and animated; the agent starts following it this tick.</summary>
    PathFound,

    /// <summary>No path: <see cref="JumpEvent.Reason"/> says why (target off the level, no sequence of moves, an animation that could not be performed…).</summary>
    PathFailed,

    /// <summary>A jump took off: takeoff and landing points, takeoff velocity and flight time are in the event.</summary>
    JumpStarted,

    /// <summary>A jump's flight ended on its landing stance.</summary>
    Landed,

    /// <summary>The agent stands on the last stance of its path, within tolerance of its target.</summary>
    TargetReached,

    /// <summary>The agent was removed; <see cref="JumpEvent.Reason"/> says in which state (e.g. in mid-flight).</summary>
    Removed,

    /// <summary>A walk started: its index on the path, the trunk centres at its start and end and its duration are in the event.</summary>
    WalkStarted,

    /// <summary>A walk ended on its last stance.</summary>
    WalkFinished,
}
