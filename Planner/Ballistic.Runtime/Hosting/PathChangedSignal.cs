namespace Ballistic.Runtime.Hosting;

/// <summary>A new path was found and the agent starts following it (<see cref="JumpAgentLogic.GetCurrentPath"/> has it), like <c>NavigationAgent3D.path_changed</c>.</summary>
/// <param name="Time">World time, seconds.</param>
public sealed record PathChangedSignal(double Time) : AgentSignal(Time);
