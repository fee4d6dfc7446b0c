namespace Ballistic.Runtime;

/// <summary>
/// One system of a <see cref="JumpWorld"/>, run once per tick in the order of <see cref="JumpWorld.Systems"/>, like a
/// Unity DOTS <c>ISystem</c>: it reads and writes the agents' components (the world's getters, its
/// <see cref="JumpWorld.Query"/> and the game's own <see cref="ComponentColumn{T}"/>s) and talks to the other systems
/// only through components and events, never by calling them. The world's own three are
/// <see cref="JumpWorld.PathRequestSystem"/>, <see cref="JumpWorld.LocomotionSystem"/> and
/// <see cref="JumpWorld.PoseSystem"/>; a game inserts its own between them (stamina, look-at, its own steering).
/// </summary>
/// <remarks>
/// Runs on the thread that calls <see cref="JumpWorld.Step()"/>. It may call the world's methods directly (their effects
/// are immediate, as between ticks) or record them in <see cref="JumpWorld.Commands"/> (played back at the start of
/// the next tick). An exception it throws does not escape the tick: the tick goes on with the next system and a
/// <see cref="Events.JumpEventKind.SystemFailed"/> event names the system and the exception.
/// </remarks>
public interface IJumpSystem
{
    /// <summary>Runs the system for one tick.</summary>
    /// <param name="tick">The tick being stepped: its number, world time and length.</param>
    /// <param name="world">The world stepping it.</param>
    void Update(in TickContext tick, JumpWorld world);
}
