using System.Diagnostics;
using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime.Baking;

namespace Ballistic.Planner.Tests.Baking;

[NonParallelizable] // waits on background bakes with a patience limit
public sealed class BakeJobTests
{
    /// <summary>How long a test waits for a bake to reach a state before failing (a bound against hangs, not a timing assertion).</summary>
    private static readonly TimeSpan Patience = TimeSpan.FromSeconds(60);

    [Test]
    public void AJobBakeOfGodotStyleSourcesIsThePlannersBakeOfTheSameLevel()
    {
        BakeOutcome outcome = BakingLevels.Baked;
        Assert.That(outcome.Status, Is.EqualTo(BakeJobStatus.Succeeded), outcome.Reason);

        var scene = PlanningScene.Create(BakingLevels.Planner(), CharacterPresets.Skeleton());
        BakeResult planner = new RoadmapBaker(scene).Bake(BakingLevels.Settings);
        byte[] expected = RoadmapFile.ToBytes(planner.Roadmap);
        Assert.Multiple(() =>
        {
            Assert.That(outcome.Succeeded, Is.True);
            Assert.That(outcome.Reason, Is.EqualTo(planner.Reason));
            Assert.That(RoadmapFile.ToBytes(outcome.Roadmap!), Is.EqualTo(expected), "the job's roadmap is the planner's");
            Assert.That(outcome.Data!.RoadmapBytes, Is.EqualTo(expected));
            Assert.That(outcome.Data.NodeCount, Is.EqualTo(planner.Roadmap.Nodes.Count));
            Assert.That(outcome.Data.JumpCount, Is.EqualTo(planner.Roadmap.Edges.Count));
            Assert.That(outcome.ToString(), Does.StartWith($"baked 40 nodes and {planner.Roadmap.Edges.Count} jumps in "));
        });

        // The synchronous path, with another thread count, gives the same.
        BakeOutcome now = BakeJob.Run(BakingLevels.FromSources().Build(), CharacterPresets.Skeleton(), BakingLevels.Settings with { Threads = 1 });
        Assert.That(now.Data!.RoadmapBytes, Is.EqualTo(expected));
    }

    [Test]
    public void ProgressNeverGoesBackAndIsFullOnSuccess()
    {
        using BakeJob job = BakeJob.Start(BakingLevels.FromSources().Build(), CharacterPresets.Skeleton(), new BakeSettings { Seed = 8, MaxNodes = 60, Threads = 2 });
        var seen = new List<BakeProgress>();
        var clock = Stopwatch.StartNew();
        while (job.IsBaking && clock.Elapsed < Patience)
        {
            seen.Add(job.Progress);
            Thread.Sleep(1);
        }

        BakeOutcome outcome = job.Wait();
        seen.Add(job.Progress);
        Assert.That(outcome.Status, Is.EqualTo(BakeJobStatus.Succeeded), outcome.Reason);
        for (int i = 1; i < seen.Count; i++)
        {
            Assert.That(seen[i].Fraction, Is.GreaterThanOrEqualTo(seen[i - 1].Fraction), $"reading {i}");
            Assert.That(seen[i].Nodes, Is.GreaterThanOrEqualTo(seen[i - 1].Nodes), $"reading {i}");
            Assert.That(seen[i].Fraction, Is.InRange(0d, 1d));
            Assert.That(seen[i].NodeBudget, Is.EqualTo(60));
        }

        BakeProgress last = seen[^1];
        Assert.Multiple(() =>
        {
            Assert.That(last.Fraction, Is.EqualTo(1d));
            Assert.That(last.Nodes, Is.EqualTo(60));
            Assert.That(last.Jumps, Is.EqualTo(outcome.Data!.JumpCount));
            Assert.That(last.Text, Does.StartWith($"done: 60 nodes, {outcome.Data.JumpCount} jumps in "));
            Assert.That(job.Outcome, Is.SameAs(outcome));
            Assert.That(job.Completion.Result, Is.SameAs(outcome));
        });
    }

    [Test]
    public void TheTrackerTakesTheLargerOfNodeAndTimeShares()
    {
        var tracker = new ProgressTracker(100, TimeSpan.FromSeconds(10), Stopwatch.StartNew());
        Assert.That(tracker.Current.Fraction, Is.Zero);
        Assert.That(tracker.Current.Text, Does.StartWith("preparing"));
        tracker.Report(new BakeState(20, 50, TimeSpan.FromSeconds(1), false, 2));
        Assert.That(tracker.Current.Fraction, Is.EqualTo(0.2).Within(1e-12), "nodes lead");
        tracker.Report(new BakeState(25, 60, TimeSpan.FromSeconds(5), false, 3));
        Assert.That(tracker.Current.Fraction, Is.EqualTo(0.5).Within(1e-12), "time leads");
        Assert.That(tracker.Current.Text, Is.EqualTo("25 of 100 nodes, 60 jumps"));
        tracker.Report(new BakeState(25, 60, TimeSpan.FromSeconds(4), false, 3));
        Assert.That(tracker.Current.Fraction, Is.EqualTo(0.5).Within(1e-12), "never back");
        tracker.Report(new BakeState(30, 70, TimeSpan.FromSeconds(60), false, 4));
        Assert.That(tracker.Current.Fraction, Is.EqualTo(1d), "capped at 1");

        var open = new ProgressTracker(null, TimeSpan.FromSeconds(4), Stopwatch.StartNew());
        open.Report(new BakeState(7, 9, TimeSpan.FromSeconds(1), false, 1));
        Assert.Multiple(() =>
        {
            Assert.That(open.Current.Fraction, Is.EqualTo(0.25).Within(1e-12));
            Assert.That(open.Current.NodeBudget, Is.Zero);
            Assert.That(open.Current.Text, Is.EqualTo("7 nodes, 9 jumps"));
        });
    }

    [Test]
    public void CancellingDuringABakeGivesCancelledAndNoData()
    {
        using BakeJob job = BakeJob.Start(BakingLevels.FromSources().Build(), CharacterPresets.Skeleton(), new BakeSettings { Seed = 2, MaxNodes = 1_000_000, Threads = 2 });
        var clock = Stopwatch.StartNew();
        while (job.Progress.Nodes == 0 && job.IsBaking && clock.Elapsed < Patience)
        {
            Thread.Sleep(5);
        }

        Assert.That(job.Progress.Nodes, Is.GreaterThan(0), "the bake got under way");
        job.Cancel();
        Assert.That(job.Completion.Wait(Patience), Is.True, "the bake noticed the cancellation");
        BakeOutcome outcome = job.Outcome!;
        Assert.Multiple(() =>
        {
            Assert.That(outcome.Status, Is.EqualTo(BakeJobStatus.Cancelled));
            Assert.That(outcome.Succeeded, Is.False);
            Assert.That(outcome.Data, Is.Null, "no partial data");
            Assert.That(outcome.Roadmap, Is.Null);
            Assert.That(outcome.Reason, Is.EqualTo("cancelled"));
            Assert.That(job.IsBaking, Is.False);
            Assert.That(job.Progress.Text, Is.EqualTo("cancelled"));
            Assert.That(job.Progress.Fraction, Is.LessThan(1d));
        });
    }

    [Test]
    public void CancelBeforeTheOutcomeAlwaysWins()
    {
        // A bake far too long to end on its own before Cancel: cancelled even before its first round.
        using BakeJob job = BakeJob.Start(BakingLevels.FromSources().Build(), CharacterPresets.Skeleton(), new BakeSettings { Seed = 2, MaxNodes = 1_000_000, Threads = 1 });
        job.Cancel();
        Assert.That(job.Wait().Status, Is.EqualTo(BakeJobStatus.Cancelled));

        using var token = new CancellationTokenSource();
        token.Cancel();
        BakeOutcome now = BakeJob.Run(BakingLevels.FromSources().Build(), CharacterPresets.Skeleton(), new BakeSettings { Seed = 2, MaxNodes = 5, Threads = 1 }, token.Token);
        Assert.That(now.Status, Is.EqualTo(BakeJobStatus.Cancelled));
        Assert.That(now.Data, Is.Null);
    }

    [Test]
    public void DisposingCancelsAndWaits()
    {
        BakeJob job = BakeJob.Start(BakingLevels.FromSources().Build(), CharacterPresets.Skeleton(), new BakeSettings { Seed = 2, MaxNodes = 1_000_000, Threads = 2 });
        job.Dispose();
        Assert.Multiple(() =>
        {
            Assert.That(job.IsBaking, Is.False, "Dispose returned after the thread ended");
            Assert.That(job.Outcome!.Status, Is.EqualTo(BakeJobStatus.Cancelled));
            Assert.That(job.Outcome.Data, Is.Null);
        });
        job.Dispose();
        job.Cancel();
    }

    [Test]
    public void ALevelWithNowhereToStandFailsWithAReason()
    {
        // Only a ceiling, facing down: no foot can stand on it.
        Level ceiling = new SourceGeometry("Cave/JumpRoadmap3D")
            .AddFaces("Cave/Ceiling", [new(-4f, 3f, -4f), new(-4f, 3f, 4f), new(4f, 3f, 4f), new(-4f, 3f, -4f), new(4f, 3f, 4f), new(4f, 3f, -4f)], Matrix4x4.Identity, FaceWinding.Clockwise)
            .Build();
        Assert.That(ceiling.Triangles.Select(t => t.Normal.Y), Is.All.EqualTo(-1f).Within(1e-6f), "clockwise seen from below");
        using BakeJob job = BakeJob.Start(ceiling, CharacterPresets.Skeleton(), new BakeSettings { Seed = 1, MaxNodes = 50, Threads = 2 });
        BakeOutcome outcome = job.Wait();
        Assert.Multiple(() =>
        {
            Assert.That(outcome.Status, Is.EqualTo(BakeJobStatus.Failed));
            Assert.That(outcome.Data, Is.Null);
            Assert.That(outcome.Roadmap, Is.Null);
            Assert.That(outcome.Reason, Does.StartWith("skeleton can stand nowhere on the level Cave/JumpRoadmap3D: no valid pose in "));
            Assert.That(outcome.Reason, Does.Not.Contain('\n'));
            Assert.That(job.Progress.Text, Is.EqualTo("failed: " + outcome.Reason));
            Assert.That(job.Progress.Fraction, Is.LessThan(1d));
        });
    }

    [Test]
    public void InvalidSettingsFailInsteadOfThrowing()
    {
        Level level = BakingLevels.FromSources().Build();
        using BakeJob threads = BakeJob.Start(level, CharacterPresets.Skeleton(), new BakeSettings { Threads = 0 });
        using BakeJob endless = BakeJob.Start(level, CharacterPresets.Skeleton(), new BakeSettings { MaxNodes = null, Threads = 1 });
        Assert.Multiple(() =>
        {
            Assert.That(threads.Wait().Status, Is.EqualTo(BakeJobStatus.Failed));
            Assert.That(threads.Wait().Reason, Is.EqualTo("Threads must be at least 1, not 0."));
            Assert.That(endless.Wait().Reason, Is.EqualTo("Nothing would stop this bake: give a node budget, a time limit or both."), "not a bake that runs until cancelled");
            Assert.That(endless.Wait().Data, Is.Null);
        });
    }

    [Test]
    public void SettingsFromExportedPrimitives()
    {
        BakeSettings nodes = BakeJob.Settings(seed: 7, maxNodes: 300, timeLimitSeconds: 0d, threads: 3);
        BakeSettings time = BakeJob.Settings(seed: 7, maxNodes: 0, timeLimitSeconds: 12.5d);
        Assert.Multiple(() =>
        {
            Assert.That((nodes.Seed, nodes.MaxNodes, nodes.TimeLimit, nodes.Threads), Is.EqualTo((7, (int?)300, (TimeSpan?)null, 3)));
            Assert.That((time.MaxNodes, time.TimeLimit), Is.EqualTo(((int?)null, (TimeSpan?)TimeSpan.FromSeconds(12.5))));
            Assert.That(time.Threads, Is.EqualTo(Math.Max(1, Environment.ProcessorCount - 1)));
            Assert.That(Assert.Throws<ArgumentException>(() => BakeJob.Settings(1, 0, 0d))!.Message, Is.EqualTo("Nothing would stop this bake: give a node budget, a time limit or both."));
            Assert.That(Assert.Throws<ArgumentException>(() => BakeJob.Settings(1, -5, 0d))!.Message, Does.Contain("not -5"));
            Assert.That(Assert.Throws<ArgumentException>(() => BakeJob.Settings(1, 10, double.NaN))!.Message, Does.Contain("not NaN"));
            Assert.That(Assert.Throws<ArgumentException>(() => BakeJob.Settings(1, 10, -1d))!.Message, Does.Contain("not -1"));
            Assert.That(Assert.Throws<ArgumentException>(() => BakeJob.Settings(1, 10, 0d, threads: -1))!.Message, Does.Contain("not -1"));
        });
    }
}
