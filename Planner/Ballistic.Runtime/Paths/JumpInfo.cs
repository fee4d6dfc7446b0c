using System.Numerics;
using Ballistic.Planner.Steering;

namespace Ballistic.Runtime.Paths;

/// <summary>
/// A jump of an agent's path: the one it is in (<see cref="JumpWorld.TryGetCurrentJump"/>) or the next one, known
/// before it happens (<see cref="JumpWorld.TryGetNextJump"/>): where it takes off and lands, how fast and when. Positions are the trunk centre in world metres; times are world
/// seconds (<see cref="JumpWorld.Time"/>).
/// </summary>
/// <param name="Index">Index of the jump among the moves of the agent's path (jumps and walks counted together).</param>
/// <param name="Arc">The arc the trunk centre will fly on (exactly).</param>
/// <param name="TakeoffTime">World time of takeoff, seconds (in the past when the agent is already in the air).</param>
/// <param name="LandingTime">World time of landing, seconds.</param>
/// <param name="InProgress">True when the agent is already in this jump.</param>
/// <param name="TakeoffPoint">The body point at takeoff: the centre of the takeoff stance's contacts, world metres (the character's ground reference, where a <c>JumpAgent3D</c> puts its body).</param>
/// <param name="LandingPoint">The body point at landing: the centre of the landing stance's contacts, world metres.</param>
/// <param name="BodyVelocity">The body point's takeoff velocity, m/s: it flies a parabola under the arc's gravity from <paramref name="TakeoffPoint"/> to <paramref name="LandingPoint"/> in the flight time (the trunk's own is <see cref="Velocity"/>).</param>
public readonly record struct JumpInfo(int Index, BallisticArc Arc, double TakeoffTime, double LandingTime, bool InProgress, Vector3 TakeoffPoint, Vector3 LandingPoint, Vector3 BodyVelocity)
{
    /// <summary>Takeoff trunk centre, world metres.</summary>
    public Vector3 From => Arc.Start;

    /// <summary>Landing trunk centre, world metres.</summary>
    public Vector3 To => Arc.End;

    /// <summary>Takeoff velocity of the trunk centre, m/s.</summary>
    public Vector3 Velocity => Arc.TakeoffVelocity;

    /// <summary>Flight time, seconds.</summary>
    public float FlightTime => Arc.FlightTime;
}
