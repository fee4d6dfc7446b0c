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
        AssertPasses(RunForeignRig("holes-debris", "tailed", 0), look => look.Upright, "a walk cruises over level ground");
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
        AssertPasses(RunForeignLevel("curved", "skeleton", 1), look => look.Upright, "a walk cruises over level ground");
    }

    /// <summary>
    /// The desert skeleton's fourth walk of the sweep's first request crosses 0.7 s of level sand just before a steep
    /// dune face: its steps shorten for the face only within half a metre of it (<see cref="Ballistic.Planner.Animation.WalkGait.StepAveraging"/>),
    /// and its hips stand upright there (at least 0.88 L; before: 0.879 L, the steps shortening over the metre around
    /// the steepening).
    /// </summary>
    [Test]
    public void AWalkStaysUprightOnLevelSandUpToADuneFace()
    {
        Sweep.Setup setup = Sweep.PrepareBundled("desert", "skeleton");
        (Vector3 From, Vector3 To)[] requests = Sweep.RandomPairs(setup.Scene, 6, seed: 42, 25f);
        AssertPasses(Sweep.Run(setup, requests[0].From, requests[0].To), look => look.Upright, "a walk cruises over level ground");
    }

    /// <summary>
    /// The user's human rig walking down the foreign staircase meets the same trouble again with its steps shortened
    /// once (a foot cannot swing down two treads clear of the nosing): the steps there shorten further, down to
    /// 0.45 of the upright step, and the walk stays upright at its natural cadence on the level ground before and
    /// after the stairs (before: the whole walk fell back to short steps, 3.2 steps a second at 0.52 L).
    /// </summary>
    [Test]
    public void StepsShortenFurtherWhereTheSameTroubleComesBack()
    {
        AssertPasses(RunForeignRig("stairs", "human", 2), look => look.Cadence, "a walk cruises over level ground");
    }

    /// <summary>
    /// A short walk on the staircase's landing (1.6 m, a long turn in place first) swings the skeleton's arms fully
    /// while it cruises: the swing fades in and out over the whole stepping, not only between its first and last
    /// steps (before: 18° of swing, the arms still fading in when the walk slowed).
    /// </summary>
    [Test]
    public void AShortWalkSwingsItsArmsWhileItCruises()
    {
        AssertPasses(RunForeignLevel("stairs", "skeleton", 2), look => look.ArmSwing, "an arm swings where the walk cruises over level ground");
    }

    /// <summary>The audited plan of foreign level <paramref name="level"/>'s request <paramref name="request"/> (0-based) for foreign rig <paramref name="rig"/>, its files written to a folder removed afterwards.</summary>
    private static AuditReport RunForeignRig(string level, string rig, int request)
    {
        string folder = Path.Combine(Path.GetTempPath(), $"ballistic-{rig}-{Guid.NewGuid():N}");
        try
        {
            (Sweep.Setup setup, (Vector3 From, Vector3 To)[] requests) = Sweep.PrepareForeign(level, rig, folder);
            return Sweep.Run(setup, requests[request].From, requests[request].To);
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    /// <summary>The audited plan of foreign level <paramref name="level"/>'s request <paramref name="request"/> (0-based) for our <paramref name="character"/>.</summary>
    private static AuditReport RunForeignLevel(string level, string character, int request)
    {
        (Level built, (Vector3 From, Vector3 To)[] requests) = ForeignLevels.Get(level);
        return Sweep.Run(Sweep.Prepare(level, built, character), requests[request].From, requests[request].To);
    }

    /// <summary>The plan animates, the criterion <paramref name="criterion"/> picks saw something to measure (<paramref name="measured"/>), and it passes.</summary>
    private static void AssertPasses(AuditReport report, Func<AnimatorEye.Look, AnimatorEye.Criterion> criterion, string measured)
    {
        Assert.That(report.Look, Is.Not.Null, report.ToString());
        AnimatorEye.Criterion seen = criterion(report.Look!);
        Assert.That(seen.Worst, Is.Not.Null, measured);
        Assert.That(seen.Passes, Is.True, seen.ToString());
    }
}
