namespace Ballistic.Runtime.Agents;

/// <summary>What an agent is doing this tick.</summary>
public enum AgentState
{
    /// <summary>Standing with no path to follow (no target, target reached, or the path failed).</summary>
    Idle,

    /// <summary>Standing on a stance of its path: waiting for the path, or between two moves while limbs re-step.</summary>
    Stance,

    /// <summary>In a jump, the root on its parabola, while some limb still holds its takeoff contact.</summary>
    Takeoff,

    /// <summary>In a jump with no limb in contact.</summary>
    Flight,

    /// <summary>In a jump, the root on its parabola, from the moment the first limb touches its landing contact.</summary>
    Landing,

    /// <summary>Walking: the root moves along the walk's ground path at its speed (<see cref="Planner.Roadmaps.Walk.PoseAt(float)"/>) while the legs step.</summary>
    Walking,
}
