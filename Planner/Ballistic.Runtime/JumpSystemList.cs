using System.Collections;
using Ballistic.Runtime.Core;

namespace Ballistic.Runtime;

/// <summary>
/// The ordered systems a <see cref="JumpWorld"/> runs each tick (<see cref="JumpWorld.Systems"/>), like an
/// Arch.Extended <c>Group</c> or a DOTS system group: by default the path-request, locomotion and pose systems, in
/// that order. A game inserts its own before or after any of them, removes one (the pose system, for a world whose
/// poses nobody reads) and puts it back. Changes are refused while the world steps (record them for later) and
/// after it is disposed; a refused change leaves the list as it was.
/// </summary>
public sealed class JumpSystemList : IReadOnlyList<IJumpSystem>
{
    private readonly JumpWorld _world;
    private readonly List<IJumpSystem> _systems = [];

    internal JumpSystemList(JumpWorld world, IEnumerable<IJumpSystem> systems)
    {
        _world = world;
        _systems.AddRange(systems);
    }

    /// <summary>Systems in the list.</summary>
    public int Count => _systems.Count;

    /// <summary>The system run <paramref name="index"/>th in a tick (from 0).</summary>
    public IJumpSystem this[int index] => _systems[index];

    /// <summary>The position of <paramref name="system"/> in the list, or −1.</summary>
    public int IndexOf(IJumpSystem system) => _systems.IndexOf(system);

    /// <summary>Appends <paramref name="system"/>: it runs last in each tick.</summary>
    public RuntimeResult Add(IJumpSystem system) => Insert(_systems.Count, system);

    /// <summary>Inserts <paramref name="system"/> to run just before <paramref name="anchor"/>.</summary>
    public RuntimeResult InsertBefore(IJumpSystem anchor, IJumpSystem system) =>
        Anchor(anchor, out int at) is { } refused ? refused : Insert(at, system);

    /// <summary>Inserts <paramref name="system"/> to run just after <paramref name="anchor"/>.</summary>
    public RuntimeResult InsertAfter(IJumpSystem anchor, IJumpSystem system) =>
        Anchor(anchor, out int at) is { } refused ? refused : Insert(at + 1, system);

    /// <summary>Takes <paramref name="system"/> out of the list: it no longer runs (a world's own system can be put back).</summary>
    public RuntimeResult Remove(IJumpSystem system)
    {
        if (Unchangeable() is { } refused)
        {
            return refused;
        }

        int at = system is null ? -1 : _systems.IndexOf(system);
        if (at < 0)
        {
            return new RuntimeResult(RuntimeStatus.InvalidArgument, $"{Describe(system)} is not in the world's system list");
        }

        _systems.RemoveAt(at);
        return RuntimeResult.Success;
    }

    /// <summary>Runs every system once, in order (<see cref="JumpWorld.Step()"/>); a game system's exception is reported, not thrown.</summary>
    internal void Run(in TickContext tick, Action<IJumpSystem, Exception> failed)
    {
        foreach (IJumpSystem system in _systems)
        {
            if (system is BuiltInSystem)
            {
                system.Update(in tick, _world); // catches its own agents' failures
                continue;
            }

            try
            {
                system.Update(in tick, _world);
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                failed(system, e);
            }
        }
    }

    /// <summary>How a system is named in messages: its own text for the world's, its type's name for a game's.</summary>
    internal static string Describe(IJumpSystem? system) => system switch
    {
        null => "the system (null)",
        BuiltInSystem b => $"the {b}",
        _ => $"system {system.GetType().Name}",
    };

    /// <inheritdoc />
    public IEnumerator<IJumpSystem> GetEnumerator() => _systems.GetEnumerator();

    IEnumerator IEnumerable.GetEnumerator() => GetEnumerator();

    private RuntimeResult Insert(int at, IJumpSystem system)
    {
        if (Unchangeable() is { } refused)
        {
            return refused;
        }

        if (system is null)
        {
            return new RuntimeResult(RuntimeStatus.InvalidArgument, "the system is null");
        }

        if (_systems.Contains(system))
        {
            return new RuntimeResult(RuntimeStatus.InvalidArgument, $"{Describe(system)} is in the world's system list already (at {_systems.IndexOf(system)})");
        }

        if (system is BuiltInSystem b && !ReferenceEquals(b.Owner, _world))
        {
            return new RuntimeResult(RuntimeStatus.InvalidArgument, $"{Describe(system)} belongs to another world");
        }

        _systems.Insert(at, system);
        return RuntimeResult.Success;
    }

    private RuntimeResult? Anchor(IJumpSystem anchor, out int at)
    {
        at = anchor is null ? -1 : _systems.IndexOf(anchor);
        return at >= 0 ? null : new RuntimeResult(RuntimeStatus.InvalidArgument, $"{Describe(anchor)} to insert next to is not in the world's system list");
    }

    private RuntimeResult? Unchangeable() =>
        _world.IsDisposed ? new RuntimeResult(RuntimeStatus.Disposed, "the world was disposed: nothing was done")
        : _world.IsStepping ? new RuntimeResult(RuntimeStatus.Busy, "the world is stepping: its system list changes only between ticks")
        : null;
}
