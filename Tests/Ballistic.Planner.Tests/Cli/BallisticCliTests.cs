using Ballistic.Cli;

namespace Ballistic.Planner.Tests.Cli;

public sealed class BallisticCliTests
{
    [Test]
    public void VersionPrintsTheAssemblyVersionAndSucceeds()
    {
        (int code, string output, _) = Run("--version");
        Assert.Multiple(() =>
        {
            Assert.That(code, Is.Zero);
            Assert.That(output.Trim(), Does.StartWith("0.1.0"));
        });
    }

    [Test]
    public void HelpDescribesTheToolAndItsConventions()
    {
        (int code, string output, _) = Run("--help");
        Assert.Multiple(() =>
        {
            Assert.That(code, Is.Zero);
            Assert.That(output, Does.Contain("ballistic jumps").And.Contain("Y up, metres, seconds"));
        });
    }

    [Test]
    public void AnUnknownCommandFailsAndNamesIt()
    {
        (int code, _, string error) = Run("fly-to-the-moon");
        Assert.Multiple(() =>
        {
            Assert.That(code, Is.Not.Zero);
            Assert.That(error, Does.Contain("fly-to-the-moon"));
        });
    }

    /// <summary>
    /// `bench` times the desert's queries one by one and prints each kind's median and 95th percentile: point to point
    /// and node to node, every request finding a path, the tail never under the median; then the same requests again
    /// (routes taken before, what the scene remembered reused), each kind finding as many paths as the first time; then
    /// the first requests again on a scene whose query was prepared, finding as many paths.
    /// </summary>
    [Test]
    public void BenchPrintsTheQueriesMedianAndTail()
    {
        (int code, string output, string error) = Run("bench", "--only", "desert", "--runs", "1");
        var lines = output.Split('\n').Where(l => l.StartsWith("query on a ", StringComparison.Ordinal) || l.StartsWith("node to node on it", StringComparison.Ordinal)).ToArray();
        Assert.Multiple(() =>
        {
            Assert.That(code, Is.Zero, error);
            Assert.That(lines, Has.Length.EqualTo(2), output);
            foreach (string line in lines)
            {
                System.Text.RegularExpressions.Match m = System.Text.RegularExpressions.Regex.Match(line, @"median ([0-9.]+) ms, p95 ([0-9.]+) ms over 100 queries after 100 warm-up queries \(100 found a path\)");
                Assert.That(m.Success, Is.True, line);
                double median = double.Parse(m.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture);
                double tail = double.Parse(m.Groups[2].Value, System.Globalization.CultureInfo.InvariantCulture);
                Assert.That(median, Is.GreaterThan(0d), line);
                Assert.That(tail, Is.GreaterThanOrEqualTo(median), line);
            }

            string again = output.Split('\n').Single(l => l.StartsWith("the same requests again", StringComparison.Ordinal));
            var kinds = System.Text.RegularExpressions.Regex.Matches(again, @"(point to point|node to node) median ([0-9.]+) ms, p95 ([0-9.]+) ms \(([0-9]+) found a path\)");
            Assert.That(kinds, Has.Count.EqualTo(2), again);
            foreach (System.Text.RegularExpressions.Match m in kinds)
            {
                double median = double.Parse(m.Groups[2].Value, System.Globalization.CultureInfo.InvariantCulture);
                Assert.That(median, Is.GreaterThan(0d), again);
                Assert.That(double.Parse(m.Groups[3].Value, System.Globalization.CultureInfo.InvariantCulture), Is.GreaterThanOrEqualTo(median), again);
                Assert.That(m.Groups[4].Value, Is.EqualTo("100"), $"{m.Groups[1].Value}: the same requests find the same number of paths again ({again})");
            }

            // The same new routes on a prepared query's scene: the node pairs prepared and what was kept, and as many paths.
            string prepared = output.Split('\n').Single(l => l.StartsWith("new routes after preparing the query", StringComparison.Ordinal));
            System.Text.RegularExpressions.Match counts = System.Text.RegularExpressions.Regex.Match(prepared, @"\(([0-9,]+) node pairs on [0-9]+ threads in [0-9.]+ s, ([0-9,]+) results kept, [0-9]+ MB\)");
            Assert.That(counts.Success, Is.True, prepared);
            Assert.That(int.Parse(counts.Groups[1].Value, System.Globalization.NumberStyles.AllowThousands, System.Globalization.CultureInfo.InvariantCulture), Is.GreaterThan(1_000), prepared);
            Assert.That(int.Parse(counts.Groups[2].Value, System.Globalization.NumberStyles.AllowThousands, System.Globalization.CultureInfo.InvariantCulture), Is.GreaterThan(1_000), prepared);
            var preparedKinds = System.Text.RegularExpressions.Regex.Matches(prepared, @"(point to point|node to node) median ([0-9.]+) ms, p95 ([0-9.]+) ms \(([0-9]+) found a path\)");
            Assert.That(preparedKinds, Has.Count.EqualTo(2), prepared);
            foreach (System.Text.RegularExpressions.Match m in preparedKinds)
            {
                Assert.That(m.Groups[4].Value, Is.EqualTo("100"), $"{m.Groups[1].Value}: the prepared query finds as many paths ({prepared})");
            }
        });
    }

    private static (int Code, string Output, string Error) Run(params string[] args)
    {
        using var output = new StringWriter();
        using var error = new StringWriter();
        int code = BallisticCli.Run(args, output, error);
        return (code, output.ToString(), error.ToString());
    }
}
