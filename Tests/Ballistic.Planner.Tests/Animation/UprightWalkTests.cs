using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Animation;

/// <summary>A walk that meets trouble in one place is walked upright everywhere else.</summary>
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
        (Level level, (Vector3 From, Vector3 To)[] requests) = ForeignLevels.Get("holes-debris");
        string folder = Path.Combine(Path.GetTempPath(), $"ballistic-tailed-{Guid.NewGuid():N}");
        Sweep.Setup setup;
        try
        {
            (CharacterModel model, ReducedCharacter reduced) = ForeignCharacters.Named("tailed").Load(folder);
            setup = Sweep.Prepare("holes-debris", level, model, reduced);
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }

        AuditReport report = Sweep.Run(setup, requests[0].From, requests[0].To);
        Assert.That(report.Look, Is.Not.Null, report.ToString());
        AnimatorEye.Criterion upright = report.Look!.Upright;
        Assert.That(upright.Worst, Is.Not.Null, "a walk cruises over level ground");
        Assert.That(upright.Passes, Is.True, upright.ToString());
    }
}
