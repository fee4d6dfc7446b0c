using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Query;

/// <summary>A move (a jump, or a walk when <see cref="IsWalk"/>) the planner set aside because the whole body could not perform it cleanly.</summary>
/// <param name="Takeoff">The node it jumps (walks) from.</param>
/// <param name="Landing">The node it lands on (walks to).</param>
/// <param name="Reason">Why: which pose, limb or bone, and what went wrong (for a walk, the gait's problem and how far along its path, metres).</param>
public sealed record RejectedJump(RoadmapNode Takeoff, RoadmapNode Landing, string Reason)
{
    /// <summary>True when the move set aside is a walk (its gait could not be performed), false for a jump.</summary>
    public bool IsWalk { get; init; }
}
