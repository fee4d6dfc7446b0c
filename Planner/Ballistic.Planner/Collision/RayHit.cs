using System.Numerics;

namespace Ballistic.Planner.Collision;

/// <summary>Where a ray or segment first meets the level.</summary>
/// <param name="Triangle">Index of the triangle hit, in the level's triangle list.</param>
/// <param name="Distance">Ray parameter of the hit: distance along the ray in units of its direction's length.</param>
/// <param name="Point">World point of the hit, metres.</param>
/// <param name="Normal">Unit front-face normal of the triangle hit.</param>
public readonly record struct RayHit(int Triangle, float Distance, Vector3 Point, Vector3 Normal);
