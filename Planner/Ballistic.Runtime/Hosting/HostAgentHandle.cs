namespace Ballistic.Runtime.Hosting;

/// <summary>
/// Names one agent of a <see cref="JumpNavigationHost"/> (one <c>JumpAgent3D</c> node), like a navigation agent's RID.
/// Unlike the world's <see cref="Agents.AgentHandle"/>, it stays the same while the agent waits for its region, is
/// moved onto a rebaked roadmap or leaves the world: valid from <see cref="JumpNavigationHost.RegisterAgent"/> until
/// <see cref="JumpNavigationHost.UnregisterAgent"/>. The default handle names no agent.
/// </summary>
/// <param name="Index">Slot of the agent in the host.</param>
/// <param name="Generation">How many agents used the slot before, plus one; zero for the default handle.</param>
public readonly record struct HostAgentHandle(int Index, int Generation)
{
    /// <summary>True for a handle that was ever returned by <see cref="JumpNavigationHost.RegisterAgent"/> (not necessarily still valid).</summary>
    public bool IsAssigned => Generation > 0;

    /// <inheritdoc />
    public override string ToString() => IsAssigned ? $"hosted agent {Index}#{Generation}" : "no hosted agent";
}
