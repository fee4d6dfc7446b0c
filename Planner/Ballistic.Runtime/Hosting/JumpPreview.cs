using System.Numerics;
using Ballistic.Planner.Steering;

namespace Ballistic.Runtime.Hosting;

/// <summary>
/// A jump of an agent's path described for its node (<see cref="JumpAgentLogic.TryGetNextJump"/>): body points
/// (contact centres of the takeoff and landing stances) and the exact trunk arc. World metres, Y up; world seconds.
/// </summary>
/// <param name="Index">Index of the jump among the moves of the agent's path (jumps and walks counted together).</param>
/// <param name="TakeoffPoint">Centre of the takeoff stance's contacts, world metres.</param>
/// <param name="LandingPoint">Centre of the landing stance's contacts, world metres.</param>
/// <param name="TakeoffVelocity">Takeoff velocity of the body point, m/s: it flies a parabola under gravity from <paramref name="TakeoffPoint"/> to <paramref name="LandingPoint"/>.</param>
/// <param name="FlightTime">Flight time, seconds.</param>
/// <param name="TakeoffTime">World time of takeoff, seconds (in the past when <paramref name="InProgress"/>).</param>
/// <param name="LandingTime">World time of landing, seconds.</param>
/// <param name="InProgress">True when the agent is in this jump now.</param>
/// <param name="Arc">The trunk centre's exact arc (the runtime's <see cref="Paths.JumpInfo.Arc"/>).</param>
public readonly record struct JumpPreview(
    int Index,
    Vector3 TakeoffPoint,
    Vector3 LandingPoint,
    Vector3 TakeoffVelocity,
    float FlightTime,
    double TakeoffTime,
    double LandingTime,
    bool InProgress,
    BallisticArc Arc);
