using System.Numerics;

namespace Ballistic.Runtime.Hosting;

/// <summary>
/// The agent took off. Its body point flies the parabola <c>From + Velocity·t + ½·g·t²</c> (g = (0, −9.81, 0))
/// and lands on <paramref name="To"/> after <paramref name="FlightTime"/>: a user moving their own body can set its
/// velocity to <paramref name="Velocity"/> and let gravity act.
/// </summary>
/// <param name="Time">World time of the takeoff, seconds.</param>
/// <param name="From">Takeoff point: the centre of the takeoff stance's contacts, world metres.</param>
/// <param name="To">Landing point: the centre of the landing stance's contacts, world metres.</param>
/// <param name="Velocity">Takeoff velocity of the body point, m/s (the trunk's own is in <see cref="JumpPreview.Arc"/>).</param>
/// <param name="FlightTime">Flight time, seconds.</param>
public sealed record JumpStartedSignal(double Time, Vector3 From, Vector3 To, Vector3 Velocity, float FlightTime) : AgentSignal(Time);
