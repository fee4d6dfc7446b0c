using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Query;

/// <summary>A jump the planner set aside because the whole body could not perform it cleanly.</summary>
/// <param name="Takeoff">The node it jumps from.</param>
/// <param name="Landing">The node it lands on.</param>
/// <param name="Reason">Why: which pose, limb or bone, and what went wrong.</param>
public sealed record RejectedJump(RoadmapNode Takeoff, RoadmapNode Landing, string Reason);
