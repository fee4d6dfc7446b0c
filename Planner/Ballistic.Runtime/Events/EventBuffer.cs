namespace Ballistic.Runtime.Events;

/// <summary>The events of one tick, in order; grows by doubling (rarely), otherwise reused without allocation.</summary>
internal sealed class EventBuffer
{
    private JumpEvent[] _events = new JumpEvent[256];
    private int _count;

    public ReadOnlySpan<JumpEvent> Events => _events.AsSpan(0, _count);

    /// <summary>Empties the buffer, letting go of the paths the events held (a finished path is not kept alive by an old event).</summary>
    public void Clear()
    {
        Array.Clear(_events, 0, _count);
        _count = 0;
    }

    public void Add(in JumpEvent e)
    {
        if (_count == _events.Length)
        {
            Array.Resize(ref _events, _events.Length * 2);
        }

        _events[_count++] = e;
    }
}
