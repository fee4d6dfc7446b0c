using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Hosting;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Runtime.Links;

/// <summary>
/// Takes a navmesh agent across a published jump link: when Godot's <c>NavigationAgent3D</c> reaches link k
/// (<c>link_reached</c>; the node finds k from the link's RID, or with <see cref="JumpLinkSet.FindLink"/> from its
/// ends), the <see cref="JumpAgentLogic"/> beside it performs exactly that jump: it stands on the takeoff stance at
/// once (warped there from wherever the navmesh agent was), jumps along the roadmap's edge and lands on the link's
/// end; its signals say when (<see cref="AgentSignalKind.Landed"/>, then <see cref="AgentSignalKind.TargetReached"/> and
/// <see cref="AgentSignalKind.NavigationFinished"/>), after which the navmesh agent walks on.
/// </summary>
/// <param name="links">The links published, made from the agents' region's current roadmap.</param>
public sealed class LinkTraversal(JumpLinkSet links)
{
    /// <summary>The links traversed.</summary>
    public JumpLinkSet Links { get; } = links ?? throw new ArgumentNullException(nameof(links));

    /// <summary>
    /// Performs link <paramref name="link"/> with <paramref name="agent"/> (<see cref="JumpAgentLogic.PerformJump"/> on
    /// the link's edge). Fails, leaving the agent as it was, for a link index out of range, an agent that is not on a
    /// roadmap, or links made from another roadmap than the agent's region has now (rebaked since: build and publish
    /// them again).
    /// </summary>
    public RuntimeResult Traverse(JumpAgentLogic agent, int link)
    {
        ArgumentNullException.ThrowIfNull(agent);
        if ((uint)link >= (uint)Links.Count)
        {
            return new RuntimeResult(RuntimeStatus.InvalidArgument, $"link {link} is not one of the {Links.Count} links");
        }

        JumpWorld world = agent.World;
        if (world.GetKindCharacter(world.GetKind(agent.Agent)) is not CharacterKind kind || agent.Lifecycle != AgentLifecycle.Active)
        {
            return new RuntimeResult(RuntimeStatus.InvalidPosition, $"the agent is not on a roadmap ({agent.StateReason ?? "not registered"})");
        }

        if (!ReferenceEquals(kind.Roadmap, Links.Roadmap))
        {
            return new RuntimeResult(RuntimeStatus.Mismatch, "the links were made from another roadmap than the one the agent's region has now (rebaked since?): make and publish them again");
        }

        return agent.PerformJump(Links.Links[link].Edge);
    }
}
