using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;
using Ballistic.Planner.Steering;

namespace Ballistic.Planner.Planning;

/// <summary>The outcome of a bake: the roadmap (complete or as far as it got), how it ended and what it cost.</summary>
/// <param name="Roadmap">The roadmap; on <see cref="PlannerStatus.InvalidStart"/> or <see cref="PlannerStatus.InvalidGoal"/> it is empty.</param>
/// <param name="Status">How the bake ended.</param>
/// <param name="Reason">One sentence saying why it ended.</param>
/// <param name="Elapsed">Wall-clock duration of the bake.</param>
/// <param name="StartNode">Id of the start node, when a start was given and placed.</param>
/// <param name="GoalNode">Id of the goal node, when a goal was given and placed.</param>
/// <param name="SteeringCalls">How many times the steering method ran.</param>
/// <param name="SamplesDrawn">How many node samples were attempted (each of up to the sampler's attempts).</param>
public sealed record BakeResult(Roadmap Roadmap, PlannerStatus Status, string Reason, TimeSpan Elapsed, int? StartNode, int? GoalNode, long SteeringCalls, long SamplesDrawn)
{
    /// <summary>How many steering calls failed, by reason (the original planner's failure counters).</summary>
    public IReadOnlyDictionary<SteeringFailure, long> SteeringRejections { get; init; } = new Dictionary<SteeringFailure, long>();

    /// <summary>Where the requested start put the start node (or why it could not), when a start was given.</summary>
    internal EndpointPlacement? StartPlacement { get; init; }

    /// <summary>Where the requested goal put the goal node (or why it could not), when a goal was given.</summary>
    internal EndpointPlacement? GoalPlacement { get; init; }
}
