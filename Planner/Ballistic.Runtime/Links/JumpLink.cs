using System.Numerics;

namespace Ballistic.Runtime.Links;

/// <summary>
/// One jump of a roadmap as a one-way navigation link for Godot's <c>NavigationServer3D</c> (<c>LinkCreate</c>, with
/// <c>LinkSetBidirectional(false)</c>): from the takeoff stance's contact centre to the landing stance's, both on the
/// ground, world metres. Godot charges a path through it <c>TravelCost × |End − Start| + EnterCost</c>.
/// </summary>
/// <param name="Edge">Index of the jump in the roadmap's <see cref="Planner.Roadmaps.Roadmap.Edges"/>: what <see cref="LinkTraversal"/> performs.</param>
/// <param name="From">Takeoff node id.</param>
/// <param name="To">Landing node id.</param>
/// <param name="Start">Link start: the takeoff node's contact centre, world metres.</param>
/// <param name="End">Link end: the landing node's contact centre, world metres.</param>
/// <param name="FlightTime">The jump's flight time, seconds.</param>
/// <param name="TravelCost">
/// Godot's <c>travel_cost</c>: FlightTime × reference speed ÷ |End − Start|, so that the link costs what walking
/// for the flight time at the reference speed costs (metres of navmesh path).
/// </param>
/// <param name="EnterCost">Godot's <c>enter_cost</c>, metres of path.</param>
public readonly record struct JumpLink(int Edge, int From, int To, Vector3 Start, Vector3 End, float FlightTime, float TravelCost, float EnterCost)
{
    /// <summary>Straight distance from start to end, metres.</summary>
    public float Length => Vector3.Distance(Start, End);

    /// <summary>What Godot's path search charges for the link: <c>TravelCost × Length + EnterCost</c>, metres.</summary>
    public float Cost => (TravelCost * Length) + EnterCost;
}
