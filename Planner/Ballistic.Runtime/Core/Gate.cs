namespace Ballistic.Runtime.Core;

/// <summary>
/// A runtime object (world, host) entered by one thread until disposed, after <see cref="Enter"/> or
/// <see cref="Wait"/>; nothing is held for a refused entry. The thread that holds it may enter again (a system's
/// call during the tick).
/// </summary>
internal readonly ref struct Gate
{
    private readonly object? _held;

    private Gate(object held) => _held = held;

    /// <summary>
    /// Enters <paramref name="gate"/> for a change from this thread; refused (<paramref name="busy"/> says why,
    /// nothing entered) while another thread steps or changes <paramref name="what"/>: it belongs to one thread, and a
    /// racing call would corrupt it.
    /// </summary>
    public static Gate Enter(object gate, string what, out RuntimeResult? busy)
    {
        if (Monitor.TryEnter(gate))
        {
            busy = null;
            return new Gate(gate);
        }

        busy = new RuntimeResult(RuntimeStatus.Busy,
            $"refused: another thread is stepping or changing the {what} right now (this call came from thread {Environment.CurrentManagedThreadId}); the {what} belongs to one thread: record changes from others in world.Commands");
        return default;
    }

    /// <summary>Enters <paramref name="gate"/>, waiting for another thread's call or tick to end.</summary>
    public static Gate Wait(object gate)
    {
        Monitor.Enter(gate);
        return new Gate(gate);
    }

    /// <summary>Leaves the gate when it was entered.</summary>
    public void Dispose()
    {
        if (_held is not null)
        {
            Monitor.Exit(_held);
        }
    }
}
