namespace Ballistic.Planner.Planning;

/// <summary>
/// When a bake stops, after OMPL's planner termination conditions: checked between sampling rounds, combined with
/// <c>|</c> (stop when any holds). Each condition says which status the bake ends with and why.
/// </summary>
public abstract class TerminationCondition
{
    /// <summary>Stop once the roadmap holds at least <paramref name="count"/> nodes (status <see cref="PlannerStatus.Exact"/>).</summary>
    public static TerminationCondition NodeCount(int count) =>
        count > 0
            ? new Predicate(s => s.Nodes >= count, PlannerStatus.Exact, $"reached {count} nodes")
            : throw new ArgumentOutOfRangeException(nameof(count), count, "The node count must be positive.");

    /// <summary>Stop once <paramref name="budget"/> has elapsed (status <see cref="PlannerStatus.Timeout"/>).</summary>
    public static TerminationCondition Timeout(TimeSpan budget) =>
        budget > TimeSpan.Zero
            ? new Predicate(s => s.Elapsed >= budget, PlannerStatus.Timeout, $"time budget of {budget.TotalSeconds:0.###} s spent")
            : throw new ArgumentOutOfRangeException(nameof(budget), budget, "The time budget must be positive.");

    /// <summary>Stop when the token is cancelled (status <see cref="PlannerStatus.Cancelled"/>).</summary>
    public static TerminationCondition Cancellation(CancellationToken token) =>
        new Predicate(_ => token.IsCancellationRequested, PlannerStatus.Cancelled, "cancelled");

    /// <summary>Stop once the start node reaches the goal node (status <see cref="PlannerStatus.Exact"/>).</summary>
    public static TerminationCondition StartGoalConnected() =>
        new Predicate(s => s.StartReachesGoal, PlannerStatus.Exact, "start and goal connected");

    /// <summary>Stop when <paramref name="stop"/> holds.</summary>
    public static TerminationCondition When(Func<BakeState, bool> stop, PlannerStatus status, string reason)
    {
        ArgumentNullException.ThrowIfNull(stop);
        ArgumentNullException.ThrowIfNull(reason);
        return new Predicate(stop, status, reason);
    }

    /// <summary>Stops when either condition holds; the left one's verdict wins when both do.</summary>
    public static TerminationCondition operator |(TerminationCondition left, TerminationCondition right)
    {
        ArgumentNullException.ThrowIfNull(left);
        ArgumentNullException.ThrowIfNull(right);
        return new Any(left, right);
    }

    /// <summary>Stops when either condition holds (same as <c>|</c>).</summary>
    public static TerminationCondition BitwiseOr(TerminationCondition left, TerminationCondition right) => left | right;

    /// <summary>Whether to stop in <paramref name="state"/>, and if so with which status and reason.</summary>
    public abstract bool ShouldStop(in BakeState state, out PlannerStatus status, out string reason);

    private sealed class Predicate(Func<BakeState, bool> stop, PlannerStatus status, string reason) : TerminationCondition
    {
        public override bool ShouldStop(in BakeState state, out PlannerStatus outStatus, out string outReason)
        {
            outStatus = status;
            outReason = reason;
            return stop(state);
        }
    }

    private sealed class Any(TerminationCondition left, TerminationCondition right) : TerminationCondition
    {
        public override bool ShouldStop(in BakeState state, out PlannerStatus status, out string reason) =>
            left.ShouldStop(state, out status, out reason) || right.ShouldStop(state, out status, out reason);
    }
}
