using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;

namespace Ballistic.Runtime.Paths;

/// <summary>
/// One move of an agent's path with its place on the path's clock (seconds from the moment the agent started
/// following the path). For a jump: the trunk centre leaves <see cref="From"/> at <see cref="Start"/>, flies exactly
/// on <see cref="Arc"/> and lands on <see cref="To"/> at <see cref="End"/>; the stance after it lasts until
/// <see cref="StanceEnd"/> while limbs re-step for the next move.
/// </summary>
/// <param name="Kind">How the move is performed.</param>
/// <param name="Index">Index of the move on its path, from zero.</param>
/// <param name="From">The stance the move leaves (a roadmap node, or the path's start stance).</param>
/// <param name="To">The stance the move reaches.</param>
/// <param name="Arc">The jump's arc of the trunk centre (world metres, seconds).</param>
/// <param name="Start">Path time of takeoff, seconds.</param>
/// <param name="TakeoffEnd">Path time at which the last limb lets go of its takeoff contact, seconds (≥ <see cref="Start"/>).</param>
/// <param name="LandingStart">Path time at which the first limb touches its landing contact, seconds (≤ <see cref="End"/>).</param>
/// <param name="End">Path time of landing (the end of the flight), seconds.</param>
/// <param name="StanceEnd">Path time at which the next move starts (the end of the path for the last move), seconds.</param>
public readonly record struct PathMove(
    MoveKind Kind,
    int Index,
    RoadmapNode From,
    RoadmapNode To,
    BallisticArc Arc,
    float Start,
    float TakeoffEnd,
    float LandingStart,
    float End,
    float StanceEnd);
