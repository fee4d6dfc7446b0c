namespace Ballistic.Runtime.Hosting;

/// <summary>No path to the target (or the agent left its roadmap while heading there): <paramref name="Reason"/> says why in one sentence.</summary>
/// <param name="Time">World time, seconds.</param>
/// <param name="Reason">Why: the planner's reason (target off the level, no sequence of jumps…) or the host's (region freed…).</param>
public sealed record PathFailedSignal(double Time, string Reason) : AgentSignal(Time);
