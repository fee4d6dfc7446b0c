using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Runtime;

/// <summary>
/// Which agents a system or game code iterates (<see cref="JumpWorld.Query"/>), like a DOTS <c>EntityQuery</c>: by
/// what they do (<see cref="InStates"/>), their kind (<see cref="OfKind"/>), and the game components they have
/// (<see cref="With{T}"/>) or lack (<see cref="Without{T}"/>). Build it once and keep it: building allocates,
/// iterating does not. The default query selects every active agent (agents waiting for a roadmap, unplaced or
/// detached are out of the simulation: <see cref="AgentLifecycle"/>).
/// </summary>
public readonly struct AgentQuery
{
    private readonly AgentStates _states;
    private readonly int _kind;
    private readonly IComponentColumn[]? _with;
    private readonly IComponentColumn[]? _without;

    private AgentQuery(AgentStates states, int kind, IComponentColumn[]? with, IComponentColumn[]? without)
    {
        // Stored inverted so that the default query (all zeros) selects every state and every kind.
        _states = ~states & AgentStates.All;
        _kind = kind + 1;
        _with = with;
        _without = without;
    }

    /// <summary>The states selected.</summary>
    public AgentStates States => ~_states & AgentStates.All;

    /// <summary>Agents doing any of <paramref name="states"/> (replacing the states selected before).</summary>
    public AgentQuery InStates(AgentStates states) => new(states, Kind, _with, _without);

    /// <summary>Agents of <paramref name="kind"/> only; the default handle selects every kind again.</summary>
    public AgentQuery OfKind(KindHandle kind) => new(States, kind.Assigned ? kind.Index : -1, _with, _without);

    /// <summary>Agents that have a value in <paramref name="column"/> (as well as in the columns asked for before).</summary>
    public AgentQuery With<T>(ComponentColumn<T> column)
        where T : struct
    {
        ArgumentNullException.ThrowIfNull(column);
        return new(States, Kind, [.. _with ?? [], column], _without);
    }

    /// <summary>Agents that have no value in <paramref name="column"/>.</summary>
    public AgentQuery Without<T>(ComponentColumn<T> column)
        where T : struct
    {
        ArgumentNullException.ThrowIfNull(column);
        return new(States, Kind, _with, [.. _without ?? [], column]);
    }

    /// <summary>The kind index selected, or −1 for every kind.</summary>
    private int Kind => _kind - 1;

    /// <summary>True when the columns asked for are all of <paramref name="world"/> (a query naming another world's column selects nobody).</summary>
    internal bool IsOf(JumpWorld world)
    {
        foreach (IComponentColumn column in _with ?? [])
        {
            if (!ReferenceEquals(column.World, world))
            {
                return false;
            }
        }

        foreach (IComponentColumn column in _without ?? [])
        {
            if (!ReferenceEquals(column.World, world))
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>True when the live agent in <paramref name="slot"/>, doing <paramref name="state"/>, of kind <paramref name="kind"/>, is selected.</summary>
    internal bool Selects(int slot, AgentState state, int kind)
    {
        if ((States & (AgentStates)(1 << (int)state)) == 0 || (Kind >= 0 && kind != Kind))
        {
            return false;
        }

        foreach (IComponentColumn column in _with ?? [])
        {
            if (!column.HasSlot(slot))
            {
                return false;
            }
        }

        foreach (IComponentColumn column in _without ?? [])
        {
            if (column.HasSlot(slot))
            {
                return false;
            }
        }

        return true;
    }
}
