using System.Numerics;

namespace Ballistic.Runtime.Hosting;

/// <summary>The agent finished a walk, standing on its last stance.</summary>
/// <param name="Time">World time of arrival, seconds.</param>
/// <param name="Position">End point: the centre of the last stance's contacts, world metres.</param>
/// <param name="Index">Index of the walk among the moves of the agent's path (jumps and walks counted together).</param>
public sealed record WalkFinishedSignal(double Time, Vector3 Position, int Index) : AgentSignal(Time);
