namespace Ballistic.Runtime.Hosting;

/// <summary>
/// Which signal of a <c>JumpAgent3D</c> node an <see cref="AgentSignal"/> is: the node emits the Godot signal of the
/// same name (the names follow <c>NavigationAgent3D</c>'s where it has one).
/// </summary>
public enum AgentSignalKind
{
    /// <summary>A new path was found and the agent starts following it (<see cref="JumpAgentLogic.GetCurrentPath"/> has it), like <c>NavigationAgent3D.path_changed</c>.</summary>
    PathChanged,

    /// <summary>
    /// The agent took off. Its body point flies the parabola <c>From + Velocity·t + ½·g·t²</c> (g = (0, −9.81, 0))
    /// and lands on <see cref="AgentSignal.To"/> after <see cref="AgentSignal.Duration"/> (the flight time): a user
    /// moving their own body can set its velocity to <see cref="AgentSignal.Velocity"/> and let gravity act.
    /// </summary>
    JumpStarted,

    /// <summary>The agent landed on <see cref="AgentSignal.To"/>, the centre of the landing stance's contacts.</summary>
    Landed,

    /// <summary>
    /// The agent started a walk: its body point moves along the ground from <see cref="AgentSignal.From"/> to
    /// <see cref="AgentSignal.To"/> at <see cref="AgentSignal.Speed"/>, arriving after <see cref="AgentSignal.Duration"/>
    /// (<see cref="JumpAgentLogic.BodyPosition"/> and <see cref="JumpAgentLogic.BodyVelocity"/> follow it each tick; the
    /// path's points are in <see cref="JumpAgentLogic.GetCurrentPath"/>).
    /// </summary>
    WalkStarted,

    /// <summary>The agent finished a walk, standing on its last stance (<see cref="AgentSignal.To"/>).</summary>
    WalkFinished,

    /// <summary>The agent stands at its target (on the last stance of its path, or already within <see cref="JumpAgentLogic.TargetDesiredDistance"/>), like <c>NavigationAgent3D.target_reached</c>.</summary>
    TargetReached,

    /// <summary>
    /// Navigation toward the target ended, like <c>NavigationAgent3D.navigation_finished</c>: after
    /// <see cref="TargetReached"/>, and also after <see cref="PathFailed"/> so that nobody waits for it forever. Once per target.
    /// </summary>
    NavigationFinished,

    /// <summary>No path to the target (or the agent left its roadmap while heading there): <see cref="AgentSignal.Reason"/> says why in one sentence.</summary>
    PathFailed,
}
