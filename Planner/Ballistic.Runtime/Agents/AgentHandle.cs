namespace Ballistic.Runtime.Agents;

/// <summary>
/// Names one agent of a <see cref="JumpWorld"/>. Valid from <see cref="JumpWorld.AddAgent"/> until
/// <see cref="JumpWorld.RemoveAgent"/>; a removed agent's handle stays invalid even when its slot is reused (the
/// generation differs). The default handle names no agent.
/// </summary>
/// <param name="Index">Slot of the agent in the world's component arrays.</param>
/// <param name="Generation">How many agents used the slot before, plus one; zero for the default handle.</param>
public readonly record struct AgentHandle(int Index, int Generation)
{
    /// <summary>True for a handle that was ever returned by <see cref="JumpWorld.AddAgent"/> (not necessarily still valid).</summary>
    public bool IsAssigned => Generation > 0;

    /// <inheritdoc />
    public override string ToString() => IsAssigned ? $"agent {Index}#{Generation}" : "no agent";
}
