using System.Numerics;

namespace Ballistic.Planner.Steering;

/// <summary>
/// The admissible takeoff angles of a jump, in the vertical plane through both poses.
/// </summary>
/// <param name="Min">Smallest admissible takeoff angle α above the horizontal, radians.</param>
/// <param name="Max">Largest admissible takeoff angle, radians.</param>
/// <param name="X">Horizontal distance between the poses, metres.</param>
/// <param name="Z">Rise from takeoff to landing (landing Y − takeoff Y), metres.</param>
/// <param name="Heading">Unit horizontal direction from takeoff to landing (world XZ plane).</param>
internal readonly record struct AngleInterval(double Min, double Max, double X, double Z, Vector3 Heading);
