using System.Diagnostics;
using System.Globalization;
using Ballistic.Planner.Planning;

namespace Ballistic.Runtime.Baking;

/// <summary>
/// Turns the baker's reports (<see cref="BakeState"/>, one per round, on the bake's thread) into
/// <see cref="BakeProgress"/> snapshots that any thread may read. The fraction never decreases and is 1 once
/// the bake has succeeded.
/// </summary>
internal sealed class ProgressTracker : IProgress<BakeState>
{
    private readonly int _budget;
    private readonly double _limitSeconds;
    private readonly Stopwatch _clock;
    private readonly IProgress<BakeState>? _also;
    private volatile BakeProgress _current;
    private volatile bool _finished;

    /// <summary>Creates a tracker for a bake of at most <paramref name="maxNodes"/> nodes and <paramref name="timeLimit"/>, timed by <paramref name="clock"/>, passing each report on to <paramref name="also"/> (a console line) when given.</summary>
    public ProgressTracker(int? maxNodes, TimeSpan? timeLimit, Stopwatch clock, IProgress<BakeState>? also = null)
    {
        _also = also;
        _budget = maxNodes is > 0 ? maxNodes.Value : 0;
        _limitSeconds = timeLimit is { } limit && limit > TimeSpan.Zero ? limit.TotalSeconds : 0d;
        _clock = clock;
        _current = new BakeProgress(0, 0, _budget, 0d, 0d, "preparing the level (collision and surfaces)");
    }

    /// <summary>The latest snapshot; while the bake runs, its elapsed time is read now.</summary>
    public BakeProgress Current
    {
        get
        {
            BakeProgress current = _current;
            return _finished ? current : current with { ElapsedSeconds = _clock.Elapsed.TotalSeconds };
        }
    }

    /// <summary>Takes the baker's state after a round.</summary>
    public void Report(BakeState value)
    {
        if (_finished)
        {
            return;
        }

        _also?.Report(value);

        BakeProgress previous = _current;
        double fraction = 0d;
        if (_budget > 0)
        {
            fraction = Math.Max(fraction, (double)value.Nodes / _budget);
        }

        if (_limitSeconds > 0d)
        {
            fraction = Math.Max(fraction, value.Elapsed.TotalSeconds / _limitSeconds);
        }

        fraction = Math.Clamp(Math.Max(fraction, previous.Fraction), 0d, 1d);
        string text = _budget > 0
            ? string.Create(CultureInfo.InvariantCulture, $"{value.Nodes} of {_budget} nodes, {value.Edges} jumps")
            : string.Create(CultureInfo.InvariantCulture, $"{value.Nodes} nodes, {value.Edges} jumps");
        _current = new BakeProgress(value.Nodes, value.Edges, _budget, fraction, _clock.Elapsed.TotalSeconds, text);
    }

    /// <summary>Freezes the snapshot at the outcome: full on success, as it was otherwise.</summary>
    public void Finish(BakeOutcome outcome)
    {
        BakeProgress last = _current;
        _current = outcome.Status switch
        {
            BakeJobStatus.Succeeded => new BakeProgress(outcome.Data!.NodeCount, outcome.Data.JumpCount, _budget, 1d, outcome.ElapsedSeconds,
                string.Create(CultureInfo.InvariantCulture, $"done: {outcome.Data.NodeCount} nodes, {outcome.Data.JumpCount} jumps in {outcome.ElapsedSeconds:0.0} s")),
            BakeJobStatus.Failed => last with { ElapsedSeconds = outcome.ElapsedSeconds, Text = "failed: " + outcome.Reason },
            _ => last with { ElapsedSeconds = outcome.ElapsedSeconds, Text = "cancelled" },
        };
        _finished = true;
    }
}
