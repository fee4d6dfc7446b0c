using System.Numerics;

namespace Ballistic.Runtime.Hosting;

/// <summary>
/// A signal of a <c>JumpAgent3D</c> node, as its <see cref="JumpAgentLogic"/> raises it: the node re-emits each as the
/// Godot signal named by <see cref="Kind"/>, in order. A small struct: raising signals allocates nothing. Positions are
/// body points (the character's ground reference: the centre of a stance's contacts) in world metres, Y up; times
/// are world seconds (<see cref="JumpWorld.Time"/>).
/// </summary>
/// <param name="Kind">Which signal.</param>
/// <param name="Time">World time at which it happened, seconds (a takeoff or landing may fall between two ticks).</param>
/// <param name="Move">For jump and walk signals, the move's index among the moves of the agent's path (jumps and walks counted together); −1 otherwise.</param>
/// <param name="From">For jump and walk signals, where the move starts: the centre of its first stance's contacts, world metres; zero otherwise.</param>
/// <param name="To">For jump and walk signals, where the move ends: the centre of its last stance's contacts (the landing point), world metres; zero otherwise.</param>
/// <param name="Velocity">For <see cref="AgentSignalKind.JumpStarted"/>, the body point's takeoff velocity, m/s (the trunk's own is in <see cref="Paths.JumpInfo.Arc"/>); zero otherwise.</param>
/// <param name="Duration">For jump signals the flight time, for walk signals the walk's duration, seconds; zero otherwise.</param>
/// <param name="Speed">For walk signals, the walking speed along the ground path, m/s; zero otherwise.</param>
/// <param name="Reason">For <see cref="AgentSignalKind.PathFailed"/>, why in one sentence: the planner's reason (target off the level, no sequence of jumps…) or the world's (the agent's kind removed or its roadmap cleared…); <c>null</c> otherwise.</param>
public readonly record struct AgentSignal(
    AgentSignalKind Kind,
    double Time,
    int Move,
    Vector3 From,
    Vector3 To,
    Vector3 Velocity,
    float Duration,
    float Speed,
    string? Reason)
{
    /// <summary>A signal that is not of a move (<see cref="AgentSignalKind.PathChanged"/>, <see cref="AgentSignalKind.TargetReached"/>, <see cref="AgentSignalKind.NavigationFinished"/>).</summary>
    internal static AgentSignal Of(AgentSignalKind kind, double time) => new(kind, time, -1, default, default, default, 0f, 0f, null);

    /// <summary>A <see cref="AgentSignalKind.PathFailed"/> signal.</summary>
    internal static AgentSignal Failed(double time, string reason) => new(AgentSignalKind.PathFailed, time, -1, default, default, default, 0f, 0f, reason);
}
