using Ballistic.Runtime.Agents;

namespace Ballistic.Runtime;

/// <summary>
/// The agents a <see cref="AgentQuery"/> selects in a <see cref="JumpWorld"/> (<see cref="JumpWorld.Query"/>), for
/// <c>foreach</c>: their handles in slot order (the order the world's systems use), read as the iteration reaches
/// each agent. Allocates nothing. An agent removed during the iteration is skipped if not reached yet; one added is
/// reached if its slot comes later.
/// </summary>
public readonly ref struct AgentQueryResult
{
    private readonly AgentStore _agents;
    private readonly AgentQuery _query;
    private readonly bool _empty;

    internal AgentQueryResult(AgentStore agents, AgentQuery query, bool empty)
    {
        _agents = agents;
        _query = query;
        _empty = empty;
    }

    /// <summary>Counts the agents selected now.</summary>
    public int Count()
    {
        int n = 0;
        foreach (AgentHandle _ in this)
        {
            n++;
        }

        return n;
    }

    /// <summary>The enumerator over the selected agents.</summary>
    public Enumerator GetEnumerator() => new(_agents, _query, _empty);

    /// <summary>Walks the world's slots, stopping at each selected live agent.</summary>
    public ref struct Enumerator
    {
        private readonly AgentStore _agents;
        private readonly AgentQuery _query;
        private readonly bool _empty;
        private int _slot;

        internal Enumerator(AgentStore agents, AgentQuery query, bool empty)
        {
            _agents = agents;
            _query = query;
            _empty = empty;
            _slot = -1;
        }

        /// <summary>The agent reached.</summary>
        public readonly AgentHandle Current => _agents.HandleOf(_slot);

        /// <summary>Moves to the next selected agent; false at the end.</summary>
        public bool MoveNext()
        {
            if (_empty)
            {
                return false;
            }

            while (++_slot < _agents.HighWater)
            {
                if (_agents.Alive[_slot] && _query.Selects(_slot, _agents.State[_slot], _agents.Kind[_slot]))
                {
                    return true;
                }
            }

            return false;
        }
    }
}
