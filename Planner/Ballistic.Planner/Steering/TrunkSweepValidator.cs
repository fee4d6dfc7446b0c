using System.Numerics;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Steering;

/// <summary>
/// The built-in arc check: the trunk box W0, carried along the arc (position on the parabola, rotation interpolated
/// from takeoff to landing), never touches the level. Thread-safe when the collision world is.
/// </summary>
/// <remarks>
/// Conservative and continuous: the flight is cut into intervals over which no point of the trunk moves more than its
/// smallest half extent (translation at the arc's top speed plus rotation of its farthest corner). Over an interval
/// every trunk position lies inside the mid-interval trunk grown by the largest distance a point can travel in half
/// the interval, so that grown box being free proves the whole interval free. Where it is not, the interval is halved,
/// down to a growth of the collision tolerance. A thin obstacle can therefore never be stepped over, and the trunk's
/// corners cannot clip one between samples.
/// </remarks>
internal sealed class TrunkSweepValidator : IArcValidator
{
    private readonly ICollisionWorld _world;

    /// <summary>Creates the check.</summary>
    /// <param name="world">The level's collision geometry.</param>
    /// <param name="trunkHalfExtents">Half extents (metres) of the trunk box W0, in the trunk frame; positive.</param>
    /// <param name="collisionTolerance">Growth (metres) below which a touching interval counts as a collision; not negative.</param>
    public TrunkSweepValidator(ICollisionWorld world, Vector3 trunkHalfExtents, float collisionTolerance)
    {
        ArgumentNullException.ThrowIfNull(world);
        if (!(MathF.Min(trunkHalfExtents.X, MathF.Min(trunkHalfExtents.Y, trunkHalfExtents.Z)) > 0f))
        {
            throw new ArgumentOutOfRangeException(nameof(trunkHalfExtents), trunkHalfExtents, "Trunk half extents must be positive.");
        }

        if (!(collisionTolerance >= 0f))
        {
            throw new ArgumentOutOfRangeException(nameof(collisionTolerance), collisionTolerance, "The collision tolerance must not be negative.");
        }

        _world = world;
        TrunkHalfExtents = trunkHalfExtents;
        CollisionTolerance = collisionTolerance;
    }

    /// <summary>Half extents of the trunk box W0, metres.</summary>
    public Vector3 TrunkHalfExtents { get; }

    /// <summary>Smallest growth (metres) to which a touching interval is refined before it counts as a collision.</summary>
    public float CollisionTolerance { get; }

    /// <inheritdoc/>
    public bool IsValid(in BallisticArc arc)
    {
        float spacing = MathF.Min(TrunkHalfExtents.X, MathF.Min(TrunkHalfExtents.Y, TrunkHalfExtents.Z));
        float speed = MathF.Max(arc.TakeoffVelocity.Length(), arc.LandingVelocity.Length());
        float dot = MathF.Min(1f, MathF.Abs(Quaternion.Dot(arc.StartRotation, arc.EndRotation)));
        float turn = 2f * MathF.Acos(dot);
        float cornerSpeed = arc.FlightTime > 0f ? turn / arc.FlightTime * TrunkHalfExtents.Length() : 0f;
        float pointSpeed = speed + cornerSpeed;
        int steps = Math.Max(1, (int)MathF.Ceiling(arc.FlightTime * pointSpeed / spacing));
        for (int i = 0; i < steps; i++)
        {
            if (!IntervalIsFree(arc, arc.FlightTime * i / steps, arc.FlightTime * (i + 1) / steps, pointSpeed, depth: 0))
            {
                return false;
            }
        }

        return true;
    }

    private bool IntervalIsFree(in BallisticArc arc, float t0, float t1, float pointSpeed, int depth)
    {
        float mid = 0.5f * (t0 + t1);
        float growth = pointSpeed * 0.5f * (t1 - t0);
        RootPose pose = arc.PoseAt(mid);
        if (!_world.Overlaps(new OrientedBox(pose.Position, TrunkHalfExtents + new Vector3(growth), pose.Rotation)))
        {
            return true;
        }

        if (growth <= CollisionTolerance || depth >= 24)
        {
            return false;
        }

        return IntervalIsFree(arc, t0, mid, pointSpeed, depth + 1) && IntervalIsFree(arc, mid, t1, pointSpeed, depth + 1);
    }
}
