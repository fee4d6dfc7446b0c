using System.Numerics;

namespace Ballistic.Runtime.Hosting;

/// <summary>The agent landed.</summary>
/// <param name="Time">World time of the landing, seconds.</param>
/// <param name="Position">Landing point: the centre of the landing stance's contacts, world metres.</param>
public sealed record LandedSignal(double Time, Vector3 Position) : AgentSignal(Time);
