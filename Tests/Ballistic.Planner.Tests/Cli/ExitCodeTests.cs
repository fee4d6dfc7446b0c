using System.Diagnostics;
using System.Text.Json;
using Ballistic.Cli;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Cli;

/// <summary>One error boundary: every failure is one line and an exit code by its class; Ctrl-C and SIGTERM cancel cleanly.</summary>
[NonParallelizable] // signals a real bake a fixed time after its start
public sealed class ExitCodeTests
{
    private string _folder = "";

    [SetUp]
    public void MakeFolder()
    {
        _folder = Path.Combine(Path.GetTempPath(), $"ballistic-exit-{Guid.NewGuid():N}");
        Directory.CreateDirectory(_folder);
    }

    [TearDown]
    public void RemoveFolder() => Directory.Delete(_folder, recursive: true);

    private static (int Code, string Output, string Error) Run(CancellationToken token, params string[] args)
    {
        using var output = new StringWriter();
        using var error = new StringWriter();
        int code = BallisticCli.Run(args, output, error, token);
        return (code, output.ToString(), error.ToString());
    }

    private static (int Code, string Output, string Error) Run(params string[] args) => Run(CancellationToken.None, args);

    [Test]
    public void EachClassOfFailureHasItsCodeAndOneLine()
    {
        string level = RepositoryFiles.Level("gap-course");
        string bad = Path.Combine(_folder, "bad.glb");
        File.WriteAllBytes(bad, [0x67, 0x6C, 0x54, 0x46, 2, 0, 0, 0, 0xF0, 0xFF, 0xFF, 0xFF]);
        string roadmap = Path.Combine(_folder, "r.roadmap");
        File.WriteAllText(roadmap, "not a roadmap");
        var cases = new (string[] Args, int Code, string Expected)[]
        {
            (["fly"], ExitCode.Usage, "fly"),
            (["bake", "--level", level, "--character", "skeleton", "--time-limit", "1e12", "--out", Path.Combine(_folder, "x")], ExitCode.Usage, "--time-limit takes 0.001 to 604800 seconds"),
            (["bake", "--level", level, "--character", "skeleton", "--time-limit", "1e-9", "--out", Path.Combine(_folder, "x")], ExitCode.Usage, "--time-limit takes 0.001 to 604800 seconds (a millisecond to a week), not 1E-09"),
            (["bake", "--level", level, "--character", "skeleton", "--time-limit", "1,5", "--out", Path.Combine(_folder, "x")], ExitCode.Usage, "--time-limit takes a number (a dot for decimals), not '1,5'"),
            (["playtest", "--level", level, "--character", "skeleton", "--seconds", "2,5", "--out", Path.Combine(_folder, "p")], ExitCode.Usage, "--seconds takes a number (a dot for decimals), not '2,5'"),
            (["bake", "--level", level, "--character", "skeleton", "--max-nodes", "abc", "--out", Path.Combine(_folder, "x")], ExitCode.Usage, "--max-nodes takes a whole number, not 'abc'"),
            (["bake", "--level", level, "--character", "skeleton", "--seed", "1.5", "--out", Path.Combine(_folder, "x")], ExitCode.Usage, "--seed takes a whole number, not '1.5'"),
            (["bake", "--level", _folder, "--character", "skeleton", "--out", Path.Combine(_folder, "x")], ExitCode.Input, "is a folder, not a file"),
            (["bake", "--level", level, "--character", "skeleton", "--time-limit", "NaN", "--out", Path.Combine(_folder, "x")], ExitCode.Usage, "--time-limit"),
            (["bake", "--level", level, "--character", "skeleton", "--max-nodes", "0", "--out", Path.Combine(_folder, "x")], ExitCode.Usage, "--max-nodes takes 1 to"),
            (["bake", "--level", level, "--character", "skeleton", "--threads", "100000", "--out", Path.Combine(_folder, "x")], ExitCode.Usage, "--threads takes 1 to 1024"),
            (["bench", "--runs", "0"], ExitCode.Usage, "--runs takes 1 to 1000"),
            (["bench", "--only", "moon"], ExitCode.Usage, "--only 'moon' matches no level or character"),
            (["bake", "--level", level, "--character", "skeleton"], ExitCode.Usage, "--out"),
            (["bake", "--level", Path.Combine(_folder, "missing.glb"), "--character", "skeleton", "--out", Path.Combine(_folder, "x")], ExitCode.Input, "does not exist"),
            (["bake", "--level", bad, "--character", "skeleton", "--out", Path.Combine(_folder, "x")], ExitCode.Input, "bad.glb"),
            (["plan", "--level", level, "--character", "skeleton", "--roadmap", roadmap, "--from", "-6,0,0", "--to", "11.5,1,0", "--report", Path.Combine(_folder, "r.json")], ExitCode.Input, "not a Ballistic roadmap"),
            (["bake", "--level", level, "--character", "skeleton", "--max-nodes", "5", "--out", _folder], ExitCode.Output, "it is a folder"),
            (["bake", "--level", level, "--character", "skeleton", "--max-nodes", "5", "--out", "a\0b.roadmap"], ExitCode.Output, "'a?b.roadmap': it is not a valid file path"),
            (["bake", "--level", "le\0vel.glb", "--character", "skeleton", "--out", Path.Combine(_folder, "x")], ExitCode.Input, "'le?vel.glb' is not a valid file path"),
            (["plan", "--level", level, "--character", "skeleton", "--from", "0,40,0", "--to", "11.5,1,0", "--report", Path.Combine(_folder, "r.json")], ExitCode.NotFound, "no valid pose"),
        };
        foreach ((string[] args, int code, string expected) in cases)
        {
            (int actual, _, string error) = Run(args);
            string context = string.Join(' ', args);
            Assert.That(actual, Is.EqualTo(code), $"{context}: {error}");
            if (code != ExitCode.NotFound)
            {
                Assert.That(error.TrimEnd().Split('\n'), Has.Length.EqualTo(1), $"{context}: one line, no stack trace: {error}");
                Assert.That(error, Does.StartWith("error: ").And.Contain(expected), context);
                Assert.That(error, Does.Not.Contain("System.").And.Not.Contain("TimeLimit").And.Not.Contain("`1"), $"{context}: no .NET names in a message for users");
            }
            else
            {
                Assert.That(error + (File.Exists(Path.Combine(_folder, "r.json")) ? File.ReadAllText(Path.Combine(_folder, "r.json")) : ""), Does.Contain(expected), context);
            }
        }

        if (OperatingSystem.IsLinux())
        {
            (int code, _, string error) = Run("bake", "--level", level, "--character", "skeleton", "--max-nodes", "5", "--out", "/dev/full");
            Assert.That(code, Is.EqualTo(ExitCode.Output));
            Assert.That(error.Trim(), Is.EqualTo("error: Refusing to replace /dev/full: it is not a regular file (a device, pipe or socket)."));
        }
    }

    [Test]
    public void ACancelledBakeWritesNothingAndKeepsThePreviousFile()
    {
        string path = Path.Combine(_folder, "course.roadmap");
        File.WriteAllText(path, "previous");
        using var cancelled = new CancellationTokenSource();
        cancelled.Cancel();
        (int code, _, string error) = Run(cancelled.Token, "bake", "--level", RepositoryFiles.Level("gap-course"), "--character", "skeleton", "--max-nodes", "50", "--out", path);
        Assert.Multiple(() =>
        {
            Assert.That(code, Is.EqualTo(ExitCode.Cancelled));
            Assert.That(error, Does.Contain("cancelled").And.Contain("unchanged"));
            Assert.That(File.ReadAllText(path), Is.EqualTo("previous"));
            Assert.That(Directory.GetFiles(_folder, "*.tmp"), Is.Empty);
        });

        string report = Path.Combine(_folder, "plan.json");
        (int planCode, _, _) = Run(cancelled.Token, "plan", "--level", RepositoryFiles.Level("gap-course"), "--character", "skeleton", "--from", "-6,0,0", "--to", "11.5,1,0", "--report", report);
        Assert.That(planCode, Is.EqualTo(ExitCode.Cancelled));
        Assert.That(File.Exists(report), Is.False);
    }

    [Test]
    public void ACancelledPlanOnASavedRoadmapWritesNothing()
    {
        string path = Path.Combine(_folder, "course.roadmap");
        (int bakeCode, _, string bakeError) = Run("bake", "--level", RepositoryFiles.Level("gap-course"), "--character", "skeleton", "--max-nodes", "60", "--out", path);
        Assert.That(bakeCode, Is.Zero, bakeError);
        using var cancelled = new CancellationTokenSource();
        cancelled.Cancel();
        string report = Path.Combine(_folder, "plan.json");
        (int code, _, string error) = Run(cancelled.Token, "plan", "--level", RepositoryFiles.Level("gap-course"), "--character", "skeleton", "--roadmap", path, "--from", "-6,0,0", "--to", "11.5,1,0", "--report", report);
        Assert.Multiple(() =>
        {
            Assert.That(code, Is.EqualTo(ExitCode.Cancelled), error);
            Assert.That(error, Does.Contain("cancelled"));
            Assert.That(File.Exists(report), Is.False);
        });
    }

    [Test]
    public void SigtermCancelsARealBakeCleanly()
    {
        if (!OperatingSystem.IsLinux())
        {
            Assert.Ignore("POSIX signals: Linux only here.");
        }

        string tool = typeof(BallisticCli).Assembly.Location;
        string path = Path.Combine(_folder, "desert.roadmap");
        File.WriteAllText(path, "previous");
        var start = new ProcessStartInfo("dotnet") { RedirectStandardError = true, RedirectStandardOutput = true, UseShellExecute = false };
        foreach (string a in new[] { tool, "bake", "--level", RepositoryFiles.Level("desert"), "--character", "skeleton", "--max-nodes", "10000000", "--threads", "1", "--out", path })
        {
            start.ArgumentList.Add(a);
        }

        using Process process = Process.Start(start)!;
        Task<string> stderr = process.StandardError.ReadToEndAsync();
        Task<string> stdout = process.StandardOutput.ReadToEndAsync();
        Thread.Sleep(4000); // loading and baking under way
        using (Process kill = Process.Start("kill", ["-TERM", process.Id.ToString(System.Globalization.CultureInfo.InvariantCulture)])!)
        {
            kill.WaitForExit();
        }

        Assert.That(process.WaitForExit(60_000), Is.True, "the bake stops soon after SIGTERM");
        Assert.Multiple(() =>
        {
            Assert.That(process.ExitCode, Is.EqualTo(ExitCode.Cancelled), stderr.Result + stdout.Result);
            Assert.That(stdout.Result, Does.Contain("bake: cancelled"));
            Assert.That(File.ReadAllText(path), Is.EqualTo("previous"), "the previous file is intact");
            Assert.That(Directory.GetFiles(_folder, "*.tmp"), Is.Empty, "no temporary file");
        });
    }

    [Test]
    public void TheSameStartAndGoalIsAPlanOfNoJumps()
    {
        string report = Path.Combine(_folder, "still.json");
        (int code, string output, string error) = Run("plan", "--level", RepositoryFiles.Level("gap-course"), "--character", "skeleton", "--from", "-6,0,0", "--to", "-6,0,0", "--report", report, "--animate");
        Assert.That(code, Is.EqualTo(ExitCode.Success), error);
        Assert.That(output, Does.Contain("status: exact"));
        using JsonDocument json = JsonDocument.Parse(File.ReadAllBytes(report));
        Assert.That(json.RootElement.GetProperty("jumps").GetArrayLength(), Is.Zero);
        Assert.That(json.RootElement.GetProperty("roadmap").GetProperty("nodes").GetInt32(), Is.EqualTo(1), "the bake stops at once: start and goal are one stance");
    }
}
