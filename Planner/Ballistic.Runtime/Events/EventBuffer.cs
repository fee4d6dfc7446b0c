namespace Ballistic.Runtime.Events;

/// <summary>The events of one tick, in order; grows by doubling (rarely), otherwise reused without allocation.</summary>
internal sealed class EventBuffer
{
    private JumpEvent[] _events = new JumpEvent[256];
    private int _count;

    public ReadOnlySpan<JumpEvent> Events => _events.AsSpan(0, _count);

    public void Clear() => _count = 0;

    public void Add(in JumpEvent e)
    {
        if (_count == _events.Length)
        {
            Array.Resize(ref _events, _events.Length * 2);
        }

        _events[_count++] = e;
    }
}
