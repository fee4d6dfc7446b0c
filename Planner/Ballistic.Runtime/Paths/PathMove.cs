using Ballistic.Planner.Geometry;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;

namespace Ballistic.Runtime.Paths;

/// <summary>
/// One move of an agent's path with its place on the path's clock (seconds from the moment the agent started
/// following the path). For a jump: the trunk centre leaves <see cref="From"/> at <see cref="Start"/>, flies exactly
/// on <see cref="Arc"/> and lands on <see cref="To"/> at <see cref="End"/>. For a walk: the trunk leaves
/// <see cref="From"/> at <see cref="Start"/> and moves exactly as <see cref="Walk"/>'s <see cref="Planner.Roadmaps.Walk.PoseAt(float)"/>
/// at the time since <see cref="Start"/>, reaching <see cref="To"/> at <see cref="End"/>. Either way the stance after
/// it lasts until <see cref="StanceEnd"/> while limbs re-step for the next move.
/// </summary>
/// <param name="Kind">How the move is performed.</param>
/// <param name="Index">Index of the move on its path, from zero (jumps and walks counted together).</param>
/// <param name="From">The stance the move leaves (a roadmap node, or the path's start stance).</param>
/// <param name="To">The stance the move reaches.</param>
/// <param name="Arc">The jump's arc of the trunk centre (world metres, seconds); the default arc for a walk.</param>
/// <param name="Start">Path time of takeoff (a jump) or of the first step (a walk), seconds.</param>
/// <param name="TakeoffEnd">For a jump, path time at which the last limb lets go of its takeoff contact, seconds (≥ <see cref="Start"/>); <see cref="Start"/> for a walk.</param>
/// <param name="LandingStart">For a jump, path time at which the first limb touches its landing contact, seconds (≤ <see cref="End"/>); <see cref="End"/> for a walk.</param>
/// <param name="End">Path time of landing (the end of the flight) or of the walk's arrival, seconds.</param>
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
    float StanceEnd)
{
    /// <summary>The walk (ground path, speed, trunk pose along it) when <see cref="Kind"/> is <see cref="MoveKind.Walk"/>; <c>null</c> for a jump.</summary>
    public Walk? Walk { get; init; }

    /// <summary>How long the move takes, seconds: the jump's flight time or the walk's length over its speed.</summary>
    public float Duration => Walk is { } walk ? walk.Duration : Arc.FlightTime;

    /// <summary>The trunk's pose when the move starts (world metres): the arc's takeoff pose, or <see cref="From"/>'s pose for a walk.</summary>
    public RootPose StartPose => Walk is null ? Arc.Takeoff : From.Pose;

    /// <summary>The trunk's pose when the move ends (world metres): the arc's landing pose, or <see cref="To"/>'s pose for a walk.</summary>
    public RootPose EndPose => Walk is null ? Arc.Landing : To.Pose;

    /// <summary>
    /// The trunk's pose <paramref name="t"/> seconds after <see cref="Start"/> (clamped to the move): exactly
    /// <see cref="BallisticArc.PoseAt"/> for a jump, <see cref="Planner.Roadmaps.Walk.PoseAt(float)"/> for a walk.
    /// </summary>
    public RootPose PoseAt(float t) => Walk is { } walk ? walk.PoseAt(t) : Arc.PoseAt(Math.Clamp(t, 0f, Arc.FlightTime));

    /// <summary>The planner's move this is: the walk, or a jump made of the stances and the arc.</summary>
    public Move ToMove() => Walk is { } walk ? walk : new Jump(From, To, Arc);
}
