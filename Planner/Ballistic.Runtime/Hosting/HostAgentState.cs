namespace Ballistic.Runtime.Hosting;

/// <summary>Where a hosted agent is, as seen by the <see cref="JumpNavigationHost"/>.</summary>
public enum HostAgentState
{
    /// <summary>Its region has no roadmap yet (not registered, or cleared): it joins the world, where it stands, when the roadmap comes.</summary>
    Waiting,

    /// <summary>In the world: an agent of its region's character kind, moving by the runtime.</summary>
    Active,

    /// <summary>Its region has a roadmap but the character can stand nowhere near the agent's position (the reason says why); a warp tries again.</summary>
    Unplaced,

    /// <summary>Its region was freed: the agent is out of the world for good; only its last events remain to drain.</summary>
    Detached,
}
