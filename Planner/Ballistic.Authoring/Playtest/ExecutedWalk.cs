using Ballistic.Planner.Roadmaps;

namespace Ballistic.Authoring.Playtest;

/// <summary>A walk an agent started during a playtest: its stances, ground path and speed.</summary>
/// <param name="Agent">Index of the agent in the playtest.</param>
/// <param name="StartTime">World time of the first step, seconds.</param>
/// <param name="Walk">The walk (stances, ground path in world metres, speed in m/s).</param>
public sealed record ExecutedWalk(int Agent, double StartTime, Walk Walk);
