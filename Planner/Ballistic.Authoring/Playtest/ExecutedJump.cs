using Ballistic.Planner.Roadmaps;

namespace Ballistic.Authoring.Playtest;

/// <summary>A jump an agent took off for during a playtest: its takeoff and landing stances and the exact arc flown.</summary>
/// <param name="Agent">Index of the agent in the playtest.</param>
/// <param name="TakeoffTime">World time of takeoff, seconds.</param>
/// <param name="Jump">The jump (stances and arc), as a plan report lists it.</param>
public sealed record ExecutedJump(int Agent, double TakeoffTime, Jump Jump);
