namespace Ballistic.Runtime.Hosting;

/// <summary>
/// The fixed-tick clock of a game loop: each frame's delta accumulates, and the world steps once per whole tick
/// accumulated, at most <see cref="MaxTicksPerFrame"/> times a frame, so that a long hitch does not freeze the game
/// catching up (the ticks beyond are dropped). A delta that is not finite or is negative (a corrupted or rewound
/// frame) adds nothing, so one bad frame never stops the clock. The Godot server node steps its host by it.
/// </summary>
public sealed class FixedTickClock
{
    private double _accumulated;

    /// <summary>Creates a clock ticking every <paramref name="tickSeconds"/> seconds.</summary>
    /// <param name="tickSeconds">Seconds per tick (positive and finite), e.g. <see cref="Core.WorldSettings.TickSeconds"/>.</param>
    /// <param name="maxTicksPerFrame">Most ticks one frame may step (at least 1).</param>
    /// <exception cref="ArgumentOutOfRangeException">A tick that is not positive and finite, or fewer than one tick per frame.</exception>
    public FixedTickClock(double tickSeconds, int maxTicksPerFrame = 4)
    {
        if (!(double.IsFinite(tickSeconds) && tickSeconds > 0.0))
        {
            throw new ArgumentOutOfRangeException(nameof(tickSeconds), tickSeconds, "A tick must last a positive, finite number of seconds.");
        }

        ArgumentOutOfRangeException.ThrowIfLessThan(maxTicksPerFrame, 1);
        TickSeconds = tickSeconds;
        MaxTicksPerFrame = maxTicksPerFrame;
    }

    /// <summary>Seconds per tick.</summary>
    public double TickSeconds { get; }

    /// <summary>Most ticks one frame steps.</summary>
    public int MaxTicksPerFrame { get; }

    /// <summary>Seconds accumulated toward the next tick (from zero to just under <see cref="TickSeconds"/> after each frame).</summary>
    public double Accumulated => _accumulated;

    /// <summary>
    /// Adds a frame of <paramref name="delta"/> seconds and returns how many ticks to step now (0 to
    /// <see cref="MaxTicksPerFrame"/>). A tick within a thousandth of its length counts as whole, so that frames of
    /// exactly one tick never skip one to rounding.
    /// </summary>
    public int Advance(double delta)
    {
        if (double.IsFinite(delta) && delta > 0.0)
        {
            _accumulated = Math.Min(_accumulated + delta, MaxTicksPerFrame * TickSeconds);
        }

        int ticks = 0;
        while (_accumulated >= TickSeconds * 0.999)
        {
            _accumulated = Math.Max(0.0, _accumulated - TickSeconds);
            ticks++;
        }

        return ticks;
    }
}
