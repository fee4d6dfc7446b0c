using System.Numerics;

namespace Ballistic.Runtime.Hosting;

/// <summary>
/// The agent started a walk: its body point moves along the ground from <paramref name="From"/> to
/// <paramref name="To"/> at <paramref name="Speed"/> along the walk's ground path, arriving after
/// <paramref name="Duration"/> (<see cref="JumpAgentLogic.BodyPosition"/> and <see cref="JumpAgentLogic.BodyVelocity"/>
/// follow it each tick; the path's points are in <see cref="JumpAgentLogic.GetCurrentPath"/>).
/// </summary>
/// <param name="Time">World time of the first step, seconds.</param>
/// <param name="From">Start point: the centre of the first stance's contacts, world metres.</param>
/// <param name="To">End point: the centre of the last stance's contacts, world metres.</param>
/// <param name="Duration">How long the walk takes, seconds.</param>
/// <param name="Speed">Walking speed along the ground path, m/s.</param>
/// <param name="Index">Index of the walk among the moves of the agent's path (jumps and walks counted together).</param>
public sealed record WalkStartedSignal(double Time, Vector3 From, Vector3 To, float Duration, float Speed, int Index) : AgentSignal(Time);
