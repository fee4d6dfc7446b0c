using Ballistic.Planner.Animation;

namespace Ballistic.Planner.Query;

/// <summary>The outcome of <see cref="AnimatedPlanner.Plan"/>: the path, its whole-body animation and the jumps set aside on the way.</summary>
/// <param name="Result">
/// The path: <see cref="Planning.PlannerStatus.Exact"/> only when it animates cleanly; otherwise the status says why
/// not (<see cref="Planning.PlannerStatus.AnimationFailed"/> when paths exist but none animates cleanly).
/// </param>
/// <param name="Animation">The clean whole-body animation of the path; <c>null</c> unless exact with at least one jump.</param>
/// <param name="Rejected">Jumps set aside because the whole body could not perform them, with the reasons, in the order found.</param>
/// <param name="Rounds">How many searches were made (1 when the first path animated cleanly).</param>
public sealed record AnimatedPlan(PlanResult Result, JumpAnimation? Animation, IReadOnlyList<RejectedJump> Rejected, int Rounds);
