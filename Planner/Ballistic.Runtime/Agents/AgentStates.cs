namespace Ballistic.Runtime.Agents;

/// <summary>A set of <see cref="AgentState"/>s, to select agents by what they do (<see cref="AgentQuery.InStates"/>).</summary>
[Flags]
public enum AgentStates
{
    /// <summary>No state: a query that selects nobody.</summary>
    None = 0,

    /// <summary><see cref="AgentState.Idle"/>.</summary>
    Idle = 1 << (int)AgentState.Idle,

    /// <summary><see cref="AgentState.Stance"/>.</summary>
    Stance = 1 << (int)AgentState.Stance,

    /// <summary><see cref="AgentState.Takeoff"/>.</summary>
    Takeoff = 1 << (int)AgentState.Takeoff,

    /// <summary><see cref="AgentState.Flight"/>.</summary>
    Flight = 1 << (int)AgentState.Flight,

    /// <summary><see cref="AgentState.Landing"/>.</summary>
    Landing = 1 << (int)AgentState.Landing,

    /// <summary><see cref="AgentState.Walking"/>.</summary>
    Walking = 1 << (int)AgentState.Walking,

    /// <summary>In a jump: takeoff, flight or landing.</summary>
    Jumping = Takeoff | Flight | Landing,

    /// <summary>Standing: idle or on a stance of its path.</summary>
    Standing = Idle | Stance,

    /// <summary>Every state.</summary>
    All = Idle | Stance | Takeoff | Flight | Landing | Walking,
}
