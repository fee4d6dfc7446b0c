using Ballistic.Runtime.Core;

namespace Ballistic.Runtime.Hosting;

/// <summary>
/// The outcome of <see cref="JumpNavigationHost.RegisterAgent"/>. The handle is assigned whenever the region handle
/// and the position were usable, even when the agent could not stand there yet (<see cref="HostAgentState.Unplaced"/>,
/// the result saying why; warp it to try elsewhere) or waits for its region's roadmap (<see cref="HostAgentState.Waiting"/>).
/// </summary>
/// <param name="Result">Status and reason: <see cref="RuntimeStatus.Ok"/> when the agent is on the roadmap or waits for it.</param>
/// <param name="Agent">The new agent; the default handle when the region or the position was refused.</param>
public readonly record struct HostAgentResult(RuntimeResult Result, HostAgentHandle Agent)
{
    /// <summary>True when the agent stands on its region's roadmap or waits for the region to get one.</summary>
    public bool Ok => Result.Ok;
}
