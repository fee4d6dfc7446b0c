using Ballistic.Runtime.Core;

namespace Ballistic.Runtime.Agents;

/// <summary>The outcome of <see cref="JumpWorld.AddAgent"/>: the new agent's handle, or why none was added.</summary>
/// <param name="Result">Status and reason.</param>
/// <param name="Agent">The new agent; the default handle when the status is not <see cref="RuntimeStatus.Ok"/>.</param>
public readonly record struct AddAgentResult(RuntimeResult Result, AgentHandle Agent)
{
    /// <summary>True when the agent was added.</summary>
    public bool Ok => Result.Ok;
}
