using System.Numerics;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Sampling;

namespace Ballistic.Authoring.Reports;

/// <summary>Everything a plan report holds: the request, the roadmap it used and the result (its moves: jumps and walks).</summary>
/// <param name="LevelPath">The level file, as given.</param>
/// <param name="Scene">The planning scene (level and character).</param>
/// <param name="From">Requested start point, world metres.</param>
/// <param name="To">Requested goal point, world metres.</param>
/// <param name="RoadmapNodes">Nodes of the roadmap used.</param>
/// <param name="RoadmapEdges">Edges of the roadmap used.</param>
/// <param name="Seed">Seed of the bake.</param>
/// <param name="BakeSeconds">Duration of the bake (0 when loaded from a file).</param>
/// <param name="Result">The query result.</param>
/// <param name="Timings">Named durations in seconds (load, bake, query…).</param>
public sealed record PlanReport(string LevelPath, PlanningScene Scene, Vector3 From, Vector3 To, int RoadmapNodes, int RoadmapEdges, int Seed, double BakeSeconds, PlanResult Result, IReadOnlyDictionary<string, double> Timings)
{
    /// <summary>The whole-body animation of the path, when one was made.</summary>
    public AnimationReport? Animation { get; init; }

    /// <summary>The endpoint tolerance of the request.</summary>
    public EndpointTolerance Tolerance { get; init; } = new();

    /// <summary>
    /// The moves the query allowed (<see cref="QuerySettings.Locomotion"/>), written as the request's
    /// <c>locomotion</c> (<c>walk+jump</c> or <c>jump</c>); <c>null</c> leaves it out.
    /// </summary>
    public Locomotion? Locomotion { get; init; }

    /// <summary>Jumps set aside because the whole body could not perform them, with the reasons.</summary>
    public IReadOnlyList<RejectedJump> Rejected { get; init; } = [];
}
