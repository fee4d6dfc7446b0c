using System.Numerics;
using Ballistic.Planner.Planning;

namespace Ballistic.Authoring.Playtest;

/// <summary>One target an agent was sent to during a playtest, and how it ended.</summary>
/// <param name="Target">The point asked for (a roadmap stance's contact centre), world metres.</param>
/// <param name="From">Where the agent's trunk centre stood when sent, world metres.</param>
/// <param name="SetAt">World time the target was set, seconds.</param>
public sealed record PlaytestTarget(Vector3 Target, Vector3 From, double SetAt)
{
    /// <summary>World time the agent arrived, seconds; <c>null</c> unless reached.</summary>
    public double? ReachedAt { get; set; }

    /// <summary>The planner's status when the path failed; <c>null</c> unless failed.</summary>
    public PlannerStatus? FailureStatus { get; set; }

    /// <summary>Why the path failed; <c>null</c> unless failed.</summary>
    public string? FailureReason { get; set; }

    /// <summary>World time of the failure, seconds.</summary>
    public double? FailedAt { get; set; }

    /// <summary>True when reached.</summary>
    public bool Reached => ReachedAt is not null;

    /// <summary>True when the path failed.</summary>
    public bool Failed => FailureStatus is not null;
}
