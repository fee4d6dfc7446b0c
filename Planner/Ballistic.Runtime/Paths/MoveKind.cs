namespace Ballistic.Runtime.Paths;

/// <summary>How a move of a path is performed.</summary>
public enum MoveKind
{
    /// <summary>A ballistic jump: the trunk centre flies on a parabola from one stance to the next.</summary>
    Jump,

    /// <summary>A walk: the trunk moves at a constant speed along a path on the ground while the legs step (<see cref="Planner.Roadmaps.Walk"/>).</summary>
    Walk,
}
