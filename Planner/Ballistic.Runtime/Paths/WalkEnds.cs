using System.Numerics;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Runtime.Paths;

/// <summary>
/// What the body point of a walk is measured from (<see cref="BodyMotion.InWalk(in PathMove, float)"/>): the contact
/// centres of the stances at either end (world metres) and their offsets from the walk's first and last path points.
/// </summary>
/// <param name="FromCentre">The first stance's contact centre.</param>
/// <param name="ToCentre">The last stance's contact centre.</param>
/// <param name="StartShift"><paramref name="FromCentre"/> minus the walk's first path point.</param>
/// <param name="EndShift"><paramref name="ToCentre"/> minus the walk's last path point.</param>
internal readonly record struct WalkEnds(Vector3 FromCentre, Vector3 ToCentre, Vector3 StartShift, Vector3 EndShift)
{
    /// <summary>The ends of <paramref name="walk"/> between stances whose contact centres are <paramref name="fromCentre"/> and <paramref name="toCentre"/>.</summary>
    public static WalkEnds Of(Vector3 fromCentre, Vector3 toCentre, Walk walk)
    {
        IReadOnlyList<Vector3> path = walk.Path;
        return new WalkEnds(fromCentre, toCentre, fromCentre - path[0], toCentre - path[^1]);
    }
}
