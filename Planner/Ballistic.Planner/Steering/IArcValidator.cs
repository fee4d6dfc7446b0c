namespace Ballistic.Planner.Steering;

/// <summary>
/// Decides whether a candidate jump arc may be used (OMPL's <c>MotionValidator</c>): the steering method asks it about
/// every arc that already satisfies the friction cones, the speed limits and the apex bound. Implementations must be
/// thread-safe and deterministic: bakes call them from several threads and expect the same answer for the same arc.
/// </summary>
public interface IArcValidator
{
    /// <summary>True when the whole flight of <paramref name="arc"/> is acceptable.</summary>
    /// <param name="arc">The candidate arc (world frame, metres, seconds).</param>
    bool IsValid(in BallisticArc arc);
}
