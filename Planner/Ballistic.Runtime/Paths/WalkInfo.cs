using System.Numerics;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Runtime.Paths;

/// <summary>
/// A walk of an agent's path: the one it is walking now (<see cref="JumpWorld.TryGetCurrentWalk"/>) or the next one,
/// known before it starts (<see cref="JumpWorld.TryGetNextWalk"/>). While walking, the agent's root is exactly
/// <c>Walk.PoseAt((float)(Time − StartTime))</c> raised by the path animation's
/// <see cref="Planner.Animation.JumpAnimation.WalkLift(float)"/> (the trunk of an upright walk above its ground path). Positions are the trunk centre in world metres; times are world
/// seconds (<see cref="JumpWorld.Time"/>).
/// </summary>
/// <param name="Index">Index of the walk among the moves of the agent's path (jumps and walks counted together).</param>
/// <param name="Walk">The walk: ground path (world metres), speed (m/s) and the trunk pose along it.</param>
/// <param name="StartTime">World time of the first step, seconds (in the past when the agent is already walking it).</param>
/// <param name="EndTime">World time of arrival on the walk's last stance, seconds.</param>
/// <param name="InProgress">True when the agent is walking it now.</param>
public readonly record struct WalkInfo(int Index, Walk Walk, double StartTime, double EndTime, bool InProgress)
{
    /// <summary>Trunk centre at the start (the first stance's), world metres.</summary>
    public Vector3 From => Walk.From.Pose.Position;

    /// <summary>Trunk centre at the end (the last stance's), world metres.</summary>
    public Vector3 To => Walk.To.Pose.Position;

    /// <summary>How long the walk takes, seconds.</summary>
    public float Duration => Walk.Duration;

    /// <summary>Walking speed along the ground path, m/s.</summary>
    public float Speed => Walk.Speed;

    /// <summary>Length of the ground path, metres.</summary>
    public float Length => Walk.Length;
}
