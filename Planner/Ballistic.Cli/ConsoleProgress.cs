using Ballistic.Planner.Planning;

namespace Ballistic.Cli;

/// <summary>
/// The progress of a long bake: on an interactive terminal a one-line bar redrawn in place; otherwise (standard error
/// piped to a log, a CI job, a service) a plain line every <see cref="LogEvery"/>, the first only once the bake has run
/// that long, so that short bakes print nothing and long ones show they are alive.
/// </summary>
internal sealed class ConsoleProgress : IProgress<BakeState>
{
    /// <summary>Time between the plain lines written without a terminal.</summary>
    public static readonly TimeSpan LogEvery = TimeSpan.FromSeconds(10);

    private readonly TextWriter _writer;
    private readonly int? _targetNodes;
    private readonly bool _interactive;
    private readonly TimeSpan _every;
    private DateTime _last = DateTime.MinValue;
    private TimeSpan _logged;

    /// <summary>Progress on <paramref name="writer"/>, drawn as a bar (<paramref name="interactive"/>) or written as a line every <paramref name="every"/> of bake time.</summary>
    internal ConsoleProgress(TextWriter writer, int? targetNodes, bool interactive, TimeSpan every)
    {
        _writer = writer;
        _targetNodes = targetNodes;
        _interactive = interactive;
        _every = every;
    }

    /// <summary>The progress of a bake reported on <paramref name="writer"/>: a bar on a terminal, plain lines every <see cref="LogEvery"/> otherwise.</summary>
    public static ConsoleProgress For(TextWriter writer, int? targetNodes) => new(writer, targetNodes, IsInteractive(writer), LogEvery);

    /// <summary>True when progress should be drawn: standard error is a terminal and is the writer in use.</summary>
    public static bool IsInteractive(TextWriter writer) => ReferenceEquals(writer, Console.Error) && !Console.IsErrorRedirected;

    public void Report(BakeState value)
    {
        if (!_interactive)
        {
            if (value.Elapsed - _logged >= _every && value.Elapsed > TimeSpan.Zero)
            {
                _logged = value.Elapsed;
                string of = _targetNodes is int nodes ? $" of {nodes}" : "";
                _writer.WriteLine($"bake: {value.Nodes}{of} nodes, {value.Edges} jumps after {value.Elapsed.TotalSeconds:0} s");
                _writer.Flush();
            }

            return;
        }

        if (DateTime.UtcNow - _last < TimeSpan.FromMilliseconds(100))
        {
            return;
        }

        _last = DateTime.UtcNow;
        const int width = 30;
        string bar = _targetNodes is int target && target > 0
            ? new string('#', Math.Min(width, width * value.Nodes / target)).PadRight(width, '.')
            : new string('#', value.Batches % (width + 1)).PadRight(width, '.');
        _writer.Write($"\r[{bar}] {value.Nodes} nodes, {value.Edges} jumps, {value.Elapsed.TotalSeconds:0.0} s ");
        _writer.Flush();
    }

    /// <summary>Clears the bar's line (nothing to clear without a terminal).</summary>
    public void Finish()
    {
        if (_interactive)
        {
            _writer.Write("\r" + new string(' ', 78) + "\r");
            _writer.Flush();
        }
    }
}
