using Ballistic.Cli;
using Ballistic.Planner.Planning;

namespace Ballistic.Planner.Tests.Cli;

/// <summary>A long bake shows it is alive without a terminal too: a plain line every ten seconds of bake time, none for a short bake.</summary>
public sealed class ConsoleProgressTests
{
    private static BakeState At(double seconds, int nodes) => new(nodes, nodes * 30, TimeSpan.FromSeconds(seconds), false, nodes / 16);

    [Test]
    public void WithoutATerminalABakeWritesAPlainLineEveryTenSeconds()
    {
        using var log = new StringWriter();
        var progress = new ConsoleProgress(log, 5000, interactive: false, ConsoleProgress.LogEvery);
        foreach ((double seconds, int nodes) in new[] { (0.5, 16), (4.0, 400), (10.2, 1000), (15.0, 1500), (20.4, 2000), (29.9, 2900) })
        {
            progress.Report(At(seconds, nodes));
        }

        progress.Finish();
        Assert.That(log.ToString(), Does.Not.Contain("\r"), "no bar redrawn in a log");
        Assert.That(log.ToString().Split('\n', StringSplitOptions.RemoveEmptyEntries), Is.EqualTo(new[]
        {
            "bake: 1000 of 5000 nodes, 30000 jumps after 10 s",
            "bake: 2000 of 5000 nodes, 60000 jumps after 20 s",
        }));
    }

    [Test]
    public void AShortBakeWritesNothingWithoutATerminal()
    {
        using var log = new StringWriter();
        var progress = new ConsoleProgress(log, null, interactive: false, ConsoleProgress.LogEvery);
        progress.Report(At(0.2, 16));
        progress.Report(At(3.0, 200));
        progress.Finish();
        Assert.That(log.ToString(), Is.Empty);
    }
}
