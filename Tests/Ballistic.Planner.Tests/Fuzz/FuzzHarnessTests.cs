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
        // Work until the thread's CPU time shows 50 ms of it, however long a loaded machine (a CI runner sharing its
        // cores) takes to give the thread that much: a CPU time that does not count work never gets there.
        TimeSpan worked = TimeSpan.Zero;
        var spin = Stopwatch.StartNew();
        double sink = 0;
        while (worked < TimeSpan.FromMilliseconds(50) && spin.Elapsed < TimeSpan.FromSeconds(30))
        {
            for (int i = 0; i < 10_000; i++)
            {
                sink += Math.Sqrt(sink + 1.0);
            }

            worked = FuzzHarness.ThreadCpuTime() - before - slept;
        }

        Assert.That(slept, Is.LessThan(TimeSpan.FromMilliseconds(100)), "300 ms asleep");
        Assert.That(worked, Is.GreaterThanOrEqualTo(TimeSpan.FromMilliseconds(50)), $"{spin.Elapsed.TotalSeconds:0.0} s of work ({sink:0})");
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
