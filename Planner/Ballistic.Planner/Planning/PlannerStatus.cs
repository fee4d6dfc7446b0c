namespace Ballistic.Planner.Planning;

/// <summary>How a bake or a query ended (after OMPL's planner status).</summary>
public enum PlannerStatus
{
    /// <summary>Done as asked: the roadmap reached its target, or a path was found.</summary>
    Exact,

    /// <summary>The time budget ran out first.</summary>
    Timeout,

    /// <summary>No valid root pose could be placed at the start.</summary>
    InvalidStart,

    /// <summary>No valid root pose could be placed at the goal.</summary>
    InvalidGoal,

    /// <summary>Cancelled: a <see cref="TerminationCondition.Cancellation"/> condition saw its token cancelled.</summary>
    Cancelled,

    /// <summary>The roadmap holds no sequence of jumps from start to goal.</summary>
    NoPath,

    /// <summary>
    /// Paths exist, but none that the whole body can perform cleanly (contact poses passing the no-slip test, no
    /// bone through the level, contacts held): every jump set aside is reported with its reason.
    /// </summary>
    AnimationFailed,
}
