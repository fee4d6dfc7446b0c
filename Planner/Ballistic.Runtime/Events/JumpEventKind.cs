namespace Ballistic.Runtime.Events;

/// <summary>What happened to an agent. Within a tick, events come in order: those of the calls and commands made before it (removals, refused commands), then in system order (path requests, then locomotion, by default) and, within a system, in agent slot order.</summary>
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

    /// <summary>
    /// A command recorded in <see cref="JumpWorld.Commands"/> was refused when played back at the start of this tick
    /// (its agent removed meanwhile, a point nobody stands on…): <see cref="JumpEvent.Reason"/> names the command and
    /// why; <see cref="JumpEvent.Agent"/> is the command's agent.
    /// </summary>
    CommandRefused,

    /// <summary>
    /// A game system of <see cref="JumpWorld.Systems"/> threw during this tick: <see cref="JumpEvent.Reason"/> names the
    /// system and the exception; <see cref="JumpEvent.Agent"/> is the default handle. The tick went on with the next system.
    /// </summary>
    SystemFailed,

    /// <summary>
    /// An agent recorded with <see cref="JumpCommandBuffer.AddAgent"/> was added when the commands were played:
    /// <see cref="JumpEvent.Agent"/> is its handle, <see cref="JumpEvent.From"/> the position asked; a
    /// <see cref="JumpEvent.Reason"/> says why it waits out of the simulation (its kind has no roadmap yet, or it
    /// cannot stand there: <see cref="Agents.AgentLifecycle"/>).
    /// </summary>
    Added,
}
