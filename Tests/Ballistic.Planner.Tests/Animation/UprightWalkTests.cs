using System.Numerics;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Animation;

/// <summary>Walks cruise upright: over the ground they cross, and everywhere but where they meet trouble.</summary>
public sealed class UprightWalkTests
{
    /// <summary>
    /// The tailed quadruped's walk between the holes meets a foothold its legs cannot hold with the hips cruising,
    /// and shorter steps there do not clear it: the hips come down to the stances' height a step either side of that
    /// place only, and the walk still cruises upright (at least 0.88 L) over the level ground (before: the whole walk
    /// was walked at the stances' height, 0.84 L).
    /// </summary>
    [Test]
    public void AWalkLowersItsHipsOnlyWhereItMeetsTrouble()
    {
        string folder = Path.Combine(Path.GetTempPath(), $"ballistic-tailed-{Guid.NewGuid():N}");
        AuditReport report;
        try
        {
            (Sweep.Setup setup, (Vector3 From, Vector3 To)[] requests) = Sweep.PrepareForeign("holes-debris", "tailed", folder);
            report = Sweep.Run(setup, requests[0].From, requests[0].To);
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }

        AssertUpright(report);
    }

    /// <summary>
    /// On the curved terrain the skeleton's first walk starts from a stance whose own feet, on the curve, hold its
    /// hips at their height; between the stances the feet step on the ground the walk crosses and the hips stand
    /// upright above it (at least 0.88 L), not at the height the start stance's footing allowed (before: 0.87 L all
    /// the way, the cruise interpolated between what each stance's feet held).
    /// </summary>
    [Test]
    public void AWalkCruisesUprightAboveTheGroundItCrossesNotItsStancesHeight()
    {
        (Level level, (Vector3 From, Vector3 To)[] requests) = ForeignLevels.Get("curved");
        Sweep.Setup setup = Sweep.Prepare("curved", level, "skeleton");
        AuditReport report = Sweep.Run(setup, requests[1].From, requests[1].To);

        AssertUpright(report);
    }

    /// <summary>The plan animates, some walk cruises over level ground, and every such walk's hips stand upright.</summary>
    private static void AssertUpright(AuditReport report)
    {
        Assert.That(report.Look, Is.Not.Null, report.ToString());
        AnimatorEye.Criterion upright = report.Look!.Upright;
        Assert.That(upright.Worst, Is.Not.Null, "a walk cruises over level ground");
        Assert.That(upright.Passes, Is.True, upright.ToString());
    }
}
