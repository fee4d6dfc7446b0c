namespace Ballistic.Runtime.Events;

/// <summary>
/// The events of one tick, in order; grows by doubling (rarely), otherwise reused without allocation. On first asking
/// after a change it also sorts them by agent slot (stable, a counting sort into a second array), so that one agent's
/// events are one contiguous range (<see cref="Of"/>).
/// </summary>
internal sealed class EventBuffer
{
    private JumpEvent[] _events = new JumpEvent[256];
    private int _count;
    private JumpEvent[] _byAgent = [];
    private int[] _start = [];
    private int _slots;
    private bool _sorted;

    public ReadOnlySpan<JumpEvent> Events => _events.AsSpan(0, _count);

    /// <summary>Empties the buffer, letting go of the paths the events held (a finished path is not kept alive by an old event).</summary>
    public void Clear()
    {
        Array.Clear(_events, 0, _count);
        if (_sorted)
        {
            Array.Clear(_byAgent, 0, _count);
        }

        _count = 0;
        _sorted = false;
    }

    public void Add(in JumpEvent e)
    {
        if (_count == _events.Length)
        {
            Array.Resize(ref _events, _events.Length * 2);
        }

        _events[_count++] = e;
        _sorted = false;
    }

    /// <summary>
    /// The events of <paramref name="agent"/> (this generation of its slot), in order; empty when it has none. Sorts the
    /// buffer by slot on first use after a change (<paramref name="slots"/>: the world's slot count).
    /// </summary>
    public ReadOnlySpan<JumpEvent> Of(Agents.AgentHandle agent, int slots)
    {
        if (!agent.IsAssigned || (uint)agent.Index >= (uint)slots)
        {
            return [];
        }

        if (!_sorted || _slots != slots)
        {
            Sort(slots);
        }

        int from = _start[agent.Index];
        int to = _start[agent.Index + 1];

        // A slot removed and reused within the tick holds the old agent's events, then the new one's: take this one's run.
        while (from < to && _byAgent[from].Agent != agent)
        {
            from++;
        }

        int end = from;
        while (end < to && _byAgent[end].Agent == agent)
        {
            end++;
        }

        return _byAgent.AsSpan(from, end - from);
    }

    private void Sort(int slots)
    {
        if (_start.Length < slots + 2)
        {
            _start = new int[Math.Max(slots + 2, 2 * _start.Length)];
        }

        if (_byAgent.Length < _events.Length)
        {
            _byAgent = new JumpEvent[_events.Length];
        }

        Array.Clear(_start, 0, slots + 2);
        for (int i = 0; i < _count; i++)
        {
            int slot = _events[i].Agent.Index;
            if (_events[i].Agent.IsAssigned && (uint)slot < (uint)slots)
            {
                _start[slot + 2]++;
            }
        }

        // _start[s + 1] is where slot s begins once the counts are summed; it becomes where s ends as events are placed.
        for (int s = 2; s < slots + 2; s++)
        {
            _start[s] += _start[s - 1];
        }

        for (int i = 0; i < _count; i++)
        {
            int slot = _events[i].Agent.Index;
            if (_events[i].Agent.IsAssigned && (uint)slot < (uint)slots)
            {
                _byAgent[_start[slot + 1]++] = _events[i];
            }
        }

        _slots = slots;
        _sorted = true;
    }
}
