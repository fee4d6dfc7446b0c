using System.Diagnostics;

namespace Ballistic.Planner.Tests.Fuzz;

/// <summary>The fuzz harness's limit is CPU time: a case on a loaded machine (waiting, not working) does not fail for the wall clock.</summary>
public sealed class FuzzHarnessTests
{
    private string _folder = "";

    [SetUp]
    public void MakeFolder()
    {
        _folder = Path.Combine(Path.GetTempPath(), $"ballistic-harness-{Guid.NewGuid():N}");
        Directory.CreateDirectory(_folder);
    }

    [TearDown]
    public void RemoveFolder() => Directory.Delete(_folder, recursive: true);

    [Test]
    public void TheThreadsCpuTimeCountsWorkNotWaiting()
    {
        Assume.That(File.Exists("/proc/thread-self/schedstat"), Is.True, "Linux reports a thread's CPU time");
        TimeSpan before = FuzzHarness.ThreadCpuTime();
        Thread.Sleep(300);
        TimeSpan slept = FuzzHarness.ThreadCpuTime() - before;
        var spin = Stopwatch.StartNew();
        double sink = 0;
        while (spin.ElapsedMilliseconds < 150)
        {
            sink += Math.Sqrt(sink + 1.0);
        }

        TimeSpan worked = FuzzHarness.ThreadCpuTime() - before - slept;
        Assert.That(slept, Is.LessThan(TimeSpan.FromMilliseconds(100)), "300 ms asleep");
        Assert.That(worked, Is.GreaterThan(TimeSpan.FromMilliseconds(20)), $"150 ms of work ({sink:0})");
    }

    [Test]
    public void ACaseThatWaitsLongerThanTheLimitButWorksLittlePasses()
    {
        Assume.That(File.Exists("/proc/thread-self/schedstat"), Is.True, "Linux reports a thread's CPU time");
        string? failure = FuzzHarness.RunOne("waiting", 1, _folder, (_, _) => () => Thread.Sleep(FuzzHarness.CaseTime + TimeSpan.FromMilliseconds(400)), out bool loaded);
        Assert.That(failure, Is.Null, "a case slowed by the machine, not by its own work");
        Assert.That(loaded, Is.True);
    }
}
