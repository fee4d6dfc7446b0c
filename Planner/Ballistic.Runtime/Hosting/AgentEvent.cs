using Ballistic.Runtime.Events;
using Ballistic.Runtime.Paths;

namespace Ballistic.Runtime.Hosting;

/// <summary>
/// One event of one hosted agent, as <see cref="JumpNavigationHost.TryDequeueEvent"/> delivers it: the world's event
/// (or, for <see cref="JumpEventKind.Removed"/>, the host's: the region was freed or lost its roadmap, or the agent
/// could not stand on a new roadmap) with the path it belongs to, kept so that a node draining late still knows the
/// move's stances after the world has moved on.
/// </summary>
/// <param name="Event">What happened; positions are trunk centres in world metres, times world seconds.</param>
/// <param name="Path">
/// For <see cref="JumpEventKind.PathFound"/>, the path found; for jump and walk events and <see cref="JumpEventKind.TargetReached"/>,
/// the path they belong to (<see cref="JumpEvent.Jump"/> indexes its moves); otherwise <c>null</c>.
/// </param>
public readonly record struct AgentEvent(JumpEvent Event, AgentPath? Path);
