namespace Ballistic.Runtime.Agents;

/// <summary>
/// Where an agent's navigation toward its target stands (<see cref="JumpWorld.GetNavigationStatus"/>), like
/// <c>NavigationAgent3D</c>'s finished and reachable flags in one component: set by <see cref="JumpWorld.SetTarget"/>
/// and the systems, read by handle or for many agents at once (<see cref="JumpWorld.NavigationStatuses"/>) instead of
/// by following events.
/// </summary>
public enum NavigationStatus
{
    /// <summary>No target: never given one, cleared, or the agent was placed again (warped, rebaked, joined) without one.</summary>
    Idle,

    /// <summary>A path toward the target is asked for: queued, searched or animated.</summary>
    Planning,

    /// <summary>Following a path (toward its target, or, after a new target, to the stance where it replans).</summary>
    Following,

    /// <summary>It stands at its last target (<see cref="Events.JumpEventKind.TargetReached"/>).</summary>
    Reached,

    /// <summary>No path to its target (<see cref="JumpWorld.GetNavigationFailure"/> says why); it stands where it was.</summary>
    Failed,
}
