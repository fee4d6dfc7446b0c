using Ballistic.Planner.Planning;

namespace Ballistic.Cli;

/// <summary>A one-line progress bar for long bakes, drawn on an interactive terminal only.</summary>
internal sealed class ConsoleProgress(TextWriter writer, int? targetNodes) : IProgress<BakeState>
{
    private DateTime _last = DateTime.MinValue;

    /// <summary>True when progress should be drawn: standard error is a terminal and is the writer in use.</summary>
    public static bool IsInteractive(TextWriter writer) => ReferenceEquals(writer, Console.Error) && !Console.IsErrorRedirected;

    public void Report(BakeState value)
    {
        if (DateTime.UtcNow - _last < TimeSpan.FromMilliseconds(100))
        {
            return;
        }

        _last = DateTime.UtcNow;
        const int width = 30;
        string bar = targetNodes is int target && target > 0
            ? new string('#', Math.Min(width, width * value.Nodes / target)).PadRight(width, '.')
            : new string('#', value.Batches % (width + 1)).PadRight(width, '.');
        writer.Write($"\r[{bar}] {value.Nodes} nodes, {value.Edges} jumps, {value.Elapsed.TotalSeconds:0.0} s ");
        writer.Flush();
    }

    /// <summary>Clears the line.</summary>
    public void Finish()
    {
        writer.Write("\r" + new string(' ', 78) + "\r");
        writer.Flush();
    }
}
