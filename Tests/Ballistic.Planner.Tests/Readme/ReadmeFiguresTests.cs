using System.Globalization;
using System.Text.RegularExpressions;
using Ballistic.Cli;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Readme;

/// <summary>
/// The figures the README quotes are what the commands and the planner give: the demo's moves, and the side-by-side
/// table row by row. A mismatch prints the rows as they are now, to paste into the README.
/// </summary>
[Category("EndToEnd")]
public sealed partial class ReadmeFiguresTests
{
    private static string Readme => File.ReadAllText(Path.Combine(RepositoryFiles.Root, "README.md"));

    [Test]
    public void TheDemoFiguresAreWhatTheDemoPrints()
    {
        string folder = Path.Combine(Path.GetTempPath(), $"ballistic-demo-{Guid.NewGuid():N}");
        try
        {
            using var output = new StringWriter();
            using var error = new StringWriter();
            int code = BallisticCli.Run(["demo", "--out", folder], output, error);
            Assert.That(code, Is.Zero, error.ToString());
            string printed = output.ToString();
            Match path = PathLine().Match(printed);
            Assert.That(path.Success, Is.True, printed);
            int jumps = int.Parse(path.Groups["jumps"].Value, CultureInfo.InvariantCulture);
            int walks = int.Parse(path.Groups["walks"].Value, CultureInfo.InvariantCulture);
            string walked = path.Groups["walked"].Value;
            string sentence = $"plans and animates {walks} walks ({walked} m) and {jumps} jumps";
            TestContext.Out.WriteLine(printed);
            Assert.That(Readme.ReplaceLineEndings(" ").Replace("  ", " ", StringComparison.Ordinal), Does.Contain(sentence), "the README's demo sentence");

            // The clip's length where the README says how many frames Blender needs for it (24 frames a second).
            Match clip = ClipLine().Match(printed);
            Assert.That(clip.Success, Is.True, printed);
            double seconds = double.Parse(clip.Groups["seconds"].Value, CultureInfo.InvariantCulture);
            string frames = string.Create(CultureInfo.InvariantCulture, $"demo's {seconds:0.0} s are {Math.Ceiling(seconds * 24):0} frames at Blender's 24 fps");
            Assert.That(Readme.ReplaceLineEndings(" ").Replace("  ", " ", StringComparison.Ordinal), Does.Contain(frames), "the README's clip length");

            // The README's phase picture is the demo's, as the demo draws it now.
            string phases = Path.Combine(folder, "desert-skeleton-phases.svg");
            Assert.That(File.Exists(phases), Is.True, "the demo draws its longest jump's phases");
            Assert.That(File.ReadAllText(Path.Combine(RepositoryFiles.Root, "docs", "jump-phases.svg")), Is.EqualTo(File.ReadAllText(phases)), "docs/jump-phases.svg is not the demo's phase picture: copy out/desert-skeleton-phases.svg there");
            Assert.That(Readme, Does.Contain("![The demo's longest jump in five poses](docs/jump-phases.svg)"), "the README shows the phase picture");
        }
        finally
        {
            if (Directory.Exists(folder))
            {
                Directory.Delete(folder, recursive: true);
            }
        }
    }

    /// <summary>The table's levels but the rooftops, whose long bake has a fixture of its own (<see cref="RooftopsRowTests"/>).</summary>
    public static IEnumerable<TestCaseData> Levels() =>
        SideBySide.Levels.Where(l => l.Label != "rooftops").Select(l => new TestCaseData(l.Label).SetName($"README side by side: {l.Label}"));

    [TestCaseSource(nameof(Levels))]
    public void TheSideBySideRowsAreWhatThePlannerGives(string label) => CheckRows(label);

    /// <summary>The README's rows of <paramref name="label"/> are the planner's, as <see cref="SideBySide.Rows"/> makes them.</summary>
    public static void CheckRows(string label)
    {
        IReadOnlyList<string> rows = SideBySide.Rows(label);
        string[] inReadme = [.. Readme.Split('\n').Select(l => l.TrimEnd('\r')).Where(l => l.StartsWith($"| {label}, ", StringComparison.Ordinal))];
        TestContext.Out.WriteLine(string.Join('\n', rows));
        Assert.That(inReadme, Is.EqualTo(rows), "the README's side-by-side rows (the rows above are the current ones)");
    }

    [GeneratedRegex(@"path: (?<jumps>[0-9]+) jumps \([0-9.]+ s of flight, [0-9.]+ m of arcs\) and (?<walks>[0-9]+) walks \((?<walked>[0-9.]+) m")]
    private static partial Regex PathLine();

    [GeneratedRegex(@"^animation: (?<seconds>[0-9.]+) s ", RegexOptions.Multiline)]
    private static partial Regex ClipLine();
}
