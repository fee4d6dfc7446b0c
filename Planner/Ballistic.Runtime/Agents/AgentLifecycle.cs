namespace Ballistic.Runtime.Agents;

/// <summary>
/// Where an agent is in its life in a <see cref="JumpWorld"/>: only <see cref="Active"/> agents are simulated (and
/// selected by queries); the others keep their handle, kind, target and the point they stand at until they join.
/// </summary>
public enum AgentLifecycle
{
    /// <summary>On its kind's roadmap, moved by the systems.</summary>
    Active,

    /// <summary>Its kind has no roadmap (not given yet, or cleared): it joins where it stands when the roadmap comes, its target kept.</summary>
    Waiting,

    /// <summary>Its kind has a roadmap, but the character can stand nowhere near the agent's point (<see cref="JumpWorld.GetAgentReason"/> says why); a warp tries again.</summary>
    Unplaced,

    /// <summary>Its kind was removed: the agent is out of the simulation for good; its handle stays valid until it is removed.</summary>
    Detached,
}
