namespace Ballistic.Runtime.Hosting;

/// <summary>
/// A signal of a <c>JumpAgent3D</c> node, as its <see cref="JumpAgentLogic"/> raises it: the node re-emits each as the
/// Godot signal of the same name (without the <c>Signal</c> suffix), in order. Positions are body points (ground
/// reference) in world metres, Y up.
/// </summary>
/// <param name="Time">World time at which it happened, seconds (<see cref="JumpWorld.Time"/>; a takeoff or landing may fall between two ticks).</param>
public abstract record AgentSignal(double Time);
