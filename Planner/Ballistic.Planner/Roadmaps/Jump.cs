using Ballistic.Planner.Steering;

namespace Ballistic.Planner.Roadmaps;

/// <summary>One jump of a planned path: the takeoff and landing nodes and the arc between them.</summary>
/// <param name="Takeoff">The node jumped from (start, roadmap node or goal).</param>
/// <param name="Landing">The node landed on.</param>
/// <param name="Arc">The ballistic arc of the trunk centre.</param>
public sealed record Jump(RoadmapNode Takeoff, RoadmapNode Landing, BallisticArc Arc) : Move
{
    /// <summary>The takeoff node.</summary>
    public override RoadmapNode From => Takeoff;

    /// <summary>The landing node.</summary>
    public override RoadmapNode To => Landing;

    /// <summary>The flight time, seconds.</summary>
    public override float Duration => Arc.FlightTime;
}
