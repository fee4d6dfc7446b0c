using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;

namespace Ballistic.Runtime;

/// <summary>
/// A game's own component (<see cref="JumpWorld.AddComponentColumn{T}"/>): one value of <typeparamref name="T"/> per
/// agent that has it, stored in a column beside the world's components, indexed by the agent's slot, like a DOTS
/// <c>IComponentData</c>. Values of a removed agent are forgotten with it, so a reused slot starts without one. Read
/// and written on the world's thread (a system's or the game loop's), like the world itself.
/// </summary>
/// <typeparam name="T">The component: a struct of plain data (stamina, a look-at point, a team).</typeparam>
public sealed class ComponentColumn<T> : IComponentColumn
    where T : struct
{
    private readonly AgentStore _agents;
    private T[] _values = [];
    private bool[] _has = [];

    internal ComponentColumn(JumpWorld world, AgentStore agents, string name)
    {
        World = world;
        _agents = agents;
        Name = name;
    }

    /// <summary>The column's name, for messages.</summary>
    public string Name { get; }

    /// <summary>The world whose agents the column holds values for.</summary>
    public JumpWorld World { get; }

    /// <summary>True when <paramref name="agent"/> is a live agent of the world with a value in this column.</summary>
    public bool Has(AgentHandle agent) => _agents.IsValid(agent) && HasSlot(agent.Index);

    /// <summary>The agent's value, when it has one.</summary>
    public bool TryGet(AgentHandle agent, out T value)
    {
        bool has = Has(agent);
        value = has ? _values[agent.Index] : default;
        return has;
    }

    /// <summary>Gives <paramref name="agent"/> the value <paramref name="value"/>, adding the component or replacing its value.</summary>
    public RuntimeResult Set(AgentHandle agent, in T value)
    {
        if (World.IsDisposed)
        {
            return new RuntimeResult(RuntimeStatus.Disposed, "the world was disposed: nothing was done");
        }

        if (!_agents.IsValid(agent))
        {
            return new RuntimeResult(RuntimeStatus.UnknownAgent, $"{agent} is not an agent of this world (never added, or removed): column '{Name}' unchanged");
        }

        int slot = agent.Index;
        if (slot >= _has.Length)
        {
            int capacity = Math.Max(Math.Max(16, _agents.HighWater), 2 * _has.Length);
            Array.Resize(ref _values, capacity);
            Array.Resize(ref _has, capacity);
        }

        _values[slot] = value;
        _has[slot] = true;
        return RuntimeResult.Success;
    }

    /// <summary>Takes the component off <paramref name="agent"/> (nothing to do when it has none).</summary>
    public RuntimeResult Remove(AgentHandle agent)
    {
        if (World.IsDisposed)
        {
            return new RuntimeResult(RuntimeStatus.Disposed, "the world was disposed: nothing was done");
        }

        if (!_agents.IsValid(agent))
        {
            return new RuntimeResult(RuntimeStatus.UnknownAgent, $"{agent} is not an agent of this world (never added, or removed): column '{Name}' unchanged");
        }

        Clear(agent.Index);
        return RuntimeResult.Success;
    }

    /// <summary>
    /// The agent's value, to read and write in place (an agent a query <see cref="AgentQuery.With{T}"/> this column
    /// selected always has one). Valid until the column grows (a value set for a new slot).
    /// </summary>
    /// <exception cref="InvalidOperationException">The agent has no value in this column (or is not a live agent of the world).</exception>
    public ref T GetRef(AgentHandle agent)
    {
        if (!Has(agent))
        {
            throw new InvalidOperationException($"{agent} has no value in column '{Name}': set one first, or query With this column");
        }

        return ref _values[agent.Index];
    }

    /// <inheritdoc />
    /// <summary>
    /// The column's values as one span indexed by <see cref="AgentHandle.Index"/> (the agent's slot), read and written
    /// in place as a DOTS system reads a component array: <c>column.Values[agent.Index]</c> for an agent a query
    /// <see cref="AgentQuery.With{T}"/> this column selected. A slot without a value holds <c>default</c> (writing it
    /// gives the agent no value: use <see cref="Set"/>); the span may be shorter than the world's slots and is valid
    /// until the next <see cref="Set"/>.
    /// </summary>
    public Span<T> Values => _values;

    bool IComponentColumn.HasSlot(int slot) => HasSlot(slot);

    /// <inheritdoc />
    void IComponentColumn.Clear(int slot) => Clear(slot);

    private bool HasSlot(int slot) => (uint)slot < (uint)_has.Length && _has[slot];

    private void Clear(int slot)
    {
        if ((uint)slot < (uint)_has.Length)
        {
            _has[slot] = false;
            _values[slot] = default;
        }
    }

    /// <inheritdoc />
    public override string ToString() => $"column '{Name}' of {typeof(T).Name}";
}
