namespace Ballistic.Runtime.Hosting;

/// <summary>The agent stands at its target (on the last stance of its path, or already within <see cref="JumpAgentLogic.TargetDesiredDistance"/>), like <c>NavigationAgent3D.target_reached</c>.</summary>
/// <param name="Time">World time, seconds.</param>
public sealed record TargetReachedSignal(double Time) : AgentSignal(Time);
