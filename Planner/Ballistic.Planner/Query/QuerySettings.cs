using Ballistic.Planner.Sampling;

namespace Ballistic.Planner.Query;

/// <summary>Parameters of a path query.</summary>
public sealed record QuerySettings
{
    /// <summary>How close the start and goal stances' contacts must come to the requested points (<see cref="TrunkSampler.Place"/>).</summary>
    public EndpointTolerance Tolerance { get; init; } = new();

    /// <summary>
    /// An extra check the start and goal stances must pass (the whole body can stand there), or <c>null</c>.
    /// <see cref="Query.AnimatedPlanner"/> sets it to its animator's <see cref="Animation.IJumpAnimator.CanStand"/>, for
    /// the bake and the query alike, so that both place the same stances.
    /// </summary>
    public Func<Contacts.PoseEvaluation, bool>? CanStand { get; init; }

    /// <summary>Start and goal are steered to and from at most this many nearest roadmap nodes within reach.</summary>
    public int MaxNeighbours { get; init; } = 32;

    /// <summary>Steering to (from) nearer nodes stops once the start (goal) has this many jumps into the roadmap.</summary>
    public int Connections { get; init; } = 4;

    /// <summary>
    /// When true, a requested point with a roadmap node standing within <see cref="ReuseShare"/> of the tolerance
    /// (its contact centre within that share of <see cref="EndpointTolerance.Across"/> horizontally and of
    /// <see cref="EndpointTolerance.UpDown"/> vertically, the nearest such, <see cref="Roadmaps.Roadmap.FindNode"/>)
    /// that passes <see cref="CanStand"/> is served by that node: no placement, no steering, a tenth of the work.
    /// Off by default, because the stance then depends on the roadmap: a query given the points a bake was given
    /// may then start or end on another node than the bake placed there.
    /// </summary>
    public bool PreferRoadmapNodes { get; init; }

    /// <summary>Share of the tolerance within which <see cref="PreferRoadmapNodes"/> takes a roadmap node (0.35, as close as <see cref="TrunkSampler.Place"/> takes a stance at once).</summary>
    public const float ReuseShare = 0.35f;
}
