using Ballistic.Planner.Steering;

namespace Ballistic.Planner.Roadmaps;

/// <summary>A directed edge of the roadmap: a valid jump from one node to another.</summary>
/// <param name="From">Takeoff node id.</param>
/// <param name="To">Landing node id.</param>
/// <param name="Arc">The jump: takeoff and landing velocities, flight time, arc length.</param>
internal readonly record struct RoadmapEdge(int From, int To, BallisticArc Arc);
