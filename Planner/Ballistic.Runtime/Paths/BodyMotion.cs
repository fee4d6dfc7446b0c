using System.Numerics;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;

namespace Ballistic.Runtime.Paths;

/// <summary>
/// Where an agent's body point is along its path. The body point is the ground reference of a character (the
/// origin of its Godot body): on a stance, the centre of its contacts; in a jump, the trunk's arc shifted by an
/// offset that goes linearly in time from the takeoff stance's (trunk − contact centre) to the landing stance's, so
/// that it leaves the takeoff contact centre, lands on the landing one and flies a parabola under the same gravity;
/// in a walk, the point of the walk's ground path shifted by an offset that goes linearly along it from the first
/// stance's (contact centre − first path point) to the last's, so that it leaves the first stance's contact centre and
/// arrives on the last one's (the ground path itself when it runs between the contact centres, as planned walks do).
/// </summary>
internal static class BodyMotion
{
    /// <summary>The body point's takeoff velocity for the jump of <paramref name="move"/>, m/s: the trunk's minus the offset's rate of change.</summary>
    public static Vector3 BodyVelocity(in PathMove move) => BodyVelocity(move.From, move.To, move.Arc);

    /// <summary>The body point's takeoff velocity for a jump from <paramref name="from"/> to <paramref name="to"/> on <paramref name="arc"/>, m/s.</summary>
    public static Vector3 BodyVelocity(RoadmapNode from, RoadmapNode to, in BallisticArc arc)
    {
        Vector3 drift = (arc.End - to.ContactCentre) - (arc.Start - from.ContactCentre);
        return arc.TakeoffVelocity - (drift / arc.FlightTime);
    }

    /// <summary>
    /// The body point and its velocity <paramref name="t"/> seconds after the takeoff of <paramref name="move"/>: the
    /// parabola from the takeoff stance's contact centre at <see cref="BodyVelocity(in PathMove)"/> under the arc's
    /// gravity (the trunk's arc minus the offset interpolated linearly in time, written so as to be exact at takeoff).
    /// </summary>
    public static (Vector3 Position, Vector3 Velocity) InJump(in PathMove move, float t) =>
        InJump(move.From.ContactCentre, BodyVelocity(move), move.Arc.Gravity, t);

    /// <summary>
    /// The body point and its velocity <paramref name="t"/> seconds after leaving <paramref name="takeoff"/> (a
    /// contact centre) at <paramref name="velocity"/> under <paramref name="gravity"/> (m/s², down): the one formula
    /// of <see cref="InJump(in PathMove, float)"/> and of the paths' cached values (<see cref="AgentPath.BodyInJump"/>).
    /// </summary>
    public static (Vector3 Position, Vector3 Velocity) InJump(Vector3 takeoff, Vector3 velocity, float gravity, float t)
    {
        var g = new Vector3(0f, -gravity, 0f);
        return (takeoff + (velocity * t) + (0.5f * t * t * g), velocity + (g * t));
    }

    /// <summary>
    /// The body point and its velocity <paramref name="t"/> seconds after the start of the walk of
    /// <paramref name="move"/> (clamped to the walk): the walk's ground point <see cref="Walk.PointAt(float)"/> at
    /// <see cref="Walk.DistanceAt"/> plus the offset from the path's ends to the stances' contact centres,
    /// interpolated along the path; exactly the first stance's contact centre at 0 and the last one's at the end. The
    /// velocity is the walk's speed then (<see cref="Walk.SpeedAt"/>: zero while it turns in place, ramping up and
    /// down) along the path's direction there (zero before and after the walk).
    /// </summary>
    /// <exception cref="ArgumentException"><paramref name="move"/> is not a walk.</exception>
    public static (Vector3 Position, Vector3 Velocity) InWalk(in PathMove move, float t)
    {
        Walk walk = move.Walk ?? throw new ArgumentException($"Move {move.Index} is a jump, not a walk.", nameof(move));
        return InWalk(walk, WalkEnds.Of(move.From.ContactCentre, move.To.ContactCentre, walk), t);
    }

    /// <summary>
    /// <see cref="InWalk(in PathMove, float)"/> on <paramref name="walk"/> between the contact centres and offsets of
    /// <paramref name="ends"/> (computed once per path: <see cref="AgentPath.BodyInWalk"/>): the one formula.
    /// </summary>
    /// <param name="walk">The walk.</param>
    /// <param name="ends">Its contact centres and offsets.</param>
    /// <param name="t">Seconds since the walk's start.</param>
    /// <param name="segment">A path index of the walk near the point (a search hint: the same answer whatever it is).</param>
    internal static (Vector3 Position, Vector3 Velocity) InWalk(Walk walk, in WalkEnds ends, float t, int segment = -1)
    {
        (Vector3 fromCentre, Vector3 toCentre, Vector3 startShift, Vector3 endShift) = ends;
        float length = walk.Length;
        float d = walk.DistanceAt(t);
        Vector3 position = d <= 0f ? fromCentre
            : d >= length ? toCentre
            : walk.PointAt(d, ref segment) + Vector3.Lerp(startShift, endShift, d / length);
        if (!(t >= 0f && t <= walk.Duration) || length <= 0f)
        {
            return (position, Vector3.Zero);
        }

        // Direction of the path at d (averaged over a centimetre, which only matters at a corner).
        const float h = 0.005f;
        float a = MathF.Max(0f, d - h);
        float b = MathF.Min(length, d + h);
        int before = segment;
        Vector3 along = b > a ? (walk.PointAt(b, ref segment) - walk.PointAt(a, ref before)) / (b - a) : Vector3.Zero;
        Vector3 velocity = walk.SpeedAt(t) * (along + ((endShift - startShift) / length));
        return (position, velocity);
    }
}
