namespace Ballistic.Authoring.Playtest;

/// <summary>
/// What a playtest's ticks cost, as a game's frame would feel them: the wall time of each <c>JumpWorld.Step</c> on
/// the tick thread (waiting for late path animations included), the CPU time of the whole process (background
/// searches and animations included) and what the tick thread allocated inside the steps. Machine-dependent: not
/// part of the playtest's report file, which stays the same on any machine.
/// </summary>
/// <param name="MedianMilliseconds">Median wall time of one tick on the tick thread, milliseconds.</param>
/// <param name="P95Milliseconds">95th percentile of the same, milliseconds.</param>
/// <param name="WorstMilliseconds">The longest tick, milliseconds.</param>
/// <param name="CpuMillisecondsPerTick">CPU time of the whole process over the ticks, on all threads, per tick, milliseconds.</param>
/// <param name="BytesAllocatedPerTick">Bytes the tick thread allocated inside the steps, per tick (the requests it solved while waiting for late ones included).</param>
/// <param name="OverFrame">Ticks longer than a 60 Hz frame (<see cref="FrameMilliseconds"/>): hitches a player would see.</param>
public sealed record PlaytestTickTimes(double MedianMilliseconds, double P95Milliseconds, double WorstMilliseconds, double CpuMillisecondsPerTick, double BytesAllocatedPerTick, int OverFrame)
{
    /// <summary>One frame at 60 Hz, milliseconds.</summary>
    public const double FrameMilliseconds = 1000.0 / 60.0;

    /// <summary>The figures of ticks that took <paramref name="tickMilliseconds"/> each, <paramref name="cpu"/> of process CPU time and <paramref name="allocated"/> bytes on the tick thread in all; <c>null</c> for no tick.</summary>
    public static PlaytestTickTimes? From(IReadOnlyList<double> tickMilliseconds, TimeSpan cpu, long allocated)
    {
        ArgumentNullException.ThrowIfNull(tickMilliseconds);
        if (tickMilliseconds.Count == 0)
        {
            return null;
        }

        double[] sorted = [.. tickMilliseconds.Order()];
        int n = sorted.Length;
        return new PlaytestTickTimes(sorted[n / 2], sorted[Math.Min(n - 1, (int)Math.Ceiling(0.95 * n) - 1)], sorted[^1], cpu.TotalMilliseconds / n, (double)allocated / n, sorted.Count(t => t > FrameMilliseconds));
    }
}
