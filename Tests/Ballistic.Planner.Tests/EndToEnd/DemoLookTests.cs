using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.EndToEnd;

/// <summary>
/// The README's main job, the skeleton crossing the bundled desert (`ballistic demo`: the same level, character,
/// request, seed and node budget), is what a user sees first: its plan passes the independent audit and its animated
/// GLB, read back as an importer reads it, every criterion of the animator's eye.
/// </summary>
[Category("EndToEnd")]
public sealed class DemoLookTests
{
    [Test]
    public void TheDemoIsFullyRightAndReadsAsJumpsAndWalks()
    {
        Sweep.Setup setup = Sweep.PrepareBundled("desert", "skeleton");
        // Start and goal on the highest surface straight below, as the CLI places them.
        AuditReport report = Sweep.Run(setup, LevelPoints.Ground(setup.Scene.Bvh, -9.5f, -7.5f)!.Value, LevelPoints.Ground(setup.Scene.Bvh, 9.5f, 7.5f)!.Value, seed: 1, maxNodes: 600);
        TestContext.Out.WriteLine(report.Look is { } seen ? string.Join("; ", seen.All.Select(c => $"{c.Name}: {c.Criterion}")) : "not animated");

        // Its longest walk (9.8 s across the flat between the dunes) met a trouble further on each time its steps
        // were shortened where the last one did: given up after two such walks, it fell back on the gait's
        // short-stepped crouch, whose left sole went into the level (12.16 s).
        Assert.That(report.FullyRight, Is.True, report.ToString());
        Assert.That(report.Look, Is.Not.Null);
        Assert.That(report.Look!.Upright.Seen, Is.Not.Empty, "the demo's walks cruise on level ground");

        // Its fifth walk crosses a dune's crest: the hips follow the crest up (before they were lifted about the
        // walk's bend, they were held 0.74-0.87 L over the one foot down there, 0.860 L in the median).
        (float score, string crest) = report.Look.Upright.Seen.Single(s => s.Seen.StartsWith("walk 4's", StringComparison.Ordinal));
        Assert.That(score, Is.GreaterThanOrEqualTo(1f), crest);

        // Every criterion passes. The last to pass was upright: the last walk cruised 0.868 L over its held feet (0.88
        // asked) on dune sand of 5-7°, where the hips were lowered as on a slope; they now stay up to 7°
        // (WalkGait.HipsLevelGrade), and where that keeps a foot from its foothold the walk slows and shortens its steps.
        foreach ((string name, AnimatorEye.Criterion criterion) in report.Look.All)
        {
            Assert.That(criterion.Passes, Is.True, $"{name}: {criterion}");
        }
    }
}
