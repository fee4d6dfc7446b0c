namespace Ballistic.Runtime.Hosting;

/// <summary>
/// Navigation toward the target ended, like <c>NavigationAgent3D.navigation_finished</c>: after
/// <see cref="TargetReachedSignal"/>, and also after <see cref="PathFailedSignal"/> so that nobody waits for it forever.
/// Once per target.
/// </summary>
/// <param name="Time">World time, seconds.</param>
public sealed record NavigationFinishedSignal(double Time) : AgentSignal(Time);
