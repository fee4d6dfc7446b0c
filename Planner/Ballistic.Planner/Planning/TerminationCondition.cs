namespace Ballistic.Planner.Planning;

/// <summary>
/// When a bake or a query stops, after OMPL's planner termination conditions, combined with <c>|</c> (stop when
/// any holds). Each condition says which status the work ends with and why. The one object carried from the
/// caller down to the parallel loops: a bake checks <see cref="ShouldStop"/> between sampling rounds and polls
/// <see cref="ShouldStopNow"/> between work items (samples, steering calls); a query polls
/// <see cref="ShouldStopNow"/> before its expensive steps. Conditions are immutable and thread-safe.
/// </summary>
public abstract class TerminationCondition
{
    /// <summary>Stop once the roadmap holds at least <paramref name="count"/> nodes (status <see cref="PlannerStatus.Exact"/>).</summary>
    public static TerminationCondition NodeCount(int count) =>
        count > 0
            ? new Predicate(s => s.Nodes >= count, PlannerStatus.Exact, $"reached {count} nodes")
            : throw new ArgumentOutOfRangeException(nameof(count), count, "The node count must be positive.");

    /// <summary>
    /// Stop once <paramref name="budget"/> has elapsed since the work began (status <see cref="PlannerStatus.Timeout"/>):
    /// each bake and each query measures from its own start. Also answers <see cref="ShouldStopNow"/>.
    /// </summary>
    public static TerminationCondition Timeout(TimeSpan budget) =>
        budget > TimeSpan.Zero
            ? new Deadline(budget)
            : throw new ArgumentOutOfRangeException(nameof(budget), budget, "The time budget must be positive.");

    /// <summary>Stop when the token is cancelled (status <see cref="PlannerStatus.Cancelled"/>). Also answers <see cref="ShouldStopNow"/>.</summary>
    public static TerminationCondition Cancellation(CancellationToken token) => new Cancelled(token);

    /// <summary>Stop once the start node reaches the goal node (status <see cref="PlannerStatus.Exact"/>).</summary>
    public static TerminationCondition StartGoalConnected() =>
        new Predicate(s => s.StartReachesGoal, PlannerStatus.Exact, "start and goal connected");

    /// <summary>Stop when <paramref name="stop"/> holds (checked between rounds only, never by <see cref="ShouldStopNow"/>).</summary>
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

    /// <summary>Whether to stop a bake in <paramref name="state"/>, and if so with which status and reason.</summary>
    public abstract bool ShouldStop(in BakeState state, out PlannerStatus status, out string reason);

    /// <summary>
    /// The cheap check polled between work items and by queries, which have no <see cref="BakeState"/>: whether to
    /// stop now, <paramref name="elapsed"/> after the work began. Only the parts that need nothing but the clock
    /// answer (<see cref="Timeout"/>, <see cref="Cancellation"/>); by default a condition never stops here.
    /// </summary>
    /// <param name="elapsed">Time since the bake or query began.</param>
    /// <param name="status">The status to end with, when stopping.</param>
    /// <param name="reason">Why, when stopping.</param>
    public virtual bool ShouldStopNow(TimeSpan elapsed, out PlannerStatus status, out string reason)
    {
        status = PlannerStatus.Exact;
        reason = "";
        return false;
    }

    private sealed class Predicate(Func<BakeState, bool> stop, PlannerStatus status, string reason) : TerminationCondition
    {
        public override bool ShouldStop(in BakeState state, out PlannerStatus outStatus, out string outReason)
        {
            outStatus = status;
            outReason = reason;
            return stop(state);
        }
    }

    private sealed class Deadline(TimeSpan budget) : TerminationCondition
    {
        private readonly string _reason = $"time budget of {budget.TotalSeconds:0.###} s spent";

        public override bool ShouldStop(in BakeState state, out PlannerStatus status, out string reason) =>
            ShouldStopNow(state.Elapsed, out status, out reason);

        public override bool ShouldStopNow(TimeSpan elapsed, out PlannerStatus status, out string reason)
        {
            status = PlannerStatus.Timeout;
            reason = _reason;
            return elapsed >= budget;
        }
    }

    private sealed class Cancelled(CancellationToken token) : TerminationCondition
    {
        public override bool ShouldStop(in BakeState state, out PlannerStatus status, out string reason) =>
            ShouldStopNow(state.Elapsed, out status, out reason);

        public override bool ShouldStopNow(TimeSpan elapsed, out PlannerStatus status, out string reason)
        {
            status = PlannerStatus.Cancelled;
            reason = "cancelled";
            return token.IsCancellationRequested;
        }
    }

    private sealed class Any(TerminationCondition left, TerminationCondition right) : TerminationCondition
    {
        public override bool ShouldStop(in BakeState state, out PlannerStatus status, out string reason) =>
            left.ShouldStop(state, out status, out reason) || right.ShouldStop(state, out status, out reason);

        public override bool ShouldStopNow(TimeSpan elapsed, out PlannerStatus status, out string reason) =>
            left.ShouldStopNow(elapsed, out status, out reason) || right.ShouldStopNow(elapsed, out status, out reason);
    }
}
