using System.Numerics;
using System.Text.RegularExpressions;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Animation;

/// <summary>
/// A limb leaving the ground carries on at the speed it left with and eases into its way to the flight's apex pose
/// over a tenth of a second (<see cref="JumpAnimator"/>'s flight). Before, it went from the drive up's speed to the
/// flight's slow way to its apex pose at once: a frog's wrists and ankles extending 15–16° in the last frame of its
/// drive up, its shoulders 23–29°, then 2–9° a frame, which the eye sees snap at every takeoff of its hops across a
/// wide field and over thin slabs (levels in other tools' shapes; 16 snapping frames over the sweep).
/// </summary>
[Category("EndToEnd")]
public sealed partial class TakeoffKickTests
{
    [TestCase("field", 2)]
    [TestCase("thin-slabs", 1)]
    public void AFrogsLimbsDoNotStopDeadAtTakeoff(string levelName, int request)
    {
        (Level level, (Vector3 From, Vector3 To)[] requests) = ForeignLevels.Get(levelName);
        Sweep.Planned planned = Sweep.Plan(Sweep.Prepare(levelName, level, "frog"), requests[request].From, requests[request].To);
        Assert.That(planned.Report.FullyRight, Is.True, planned.Report.ToString());
        Assert.That(planned.Plan.Animation!.Arcs, Has.Count.GreaterThan(1), "a plan of hops");

        // No snapping frame of a limb joint around a takeoff (the frame before it, or the flight's first).
        string[] atTakeoff = [.. planned.Report.Look!.Snaps.Seen.Where(s => s.Score > 1f && AtTakeoff().IsMatch(s.Seen)).Select(s => s.Seen)];
        Assert.That(atTakeoff, Is.Empty, string.Join(Environment.NewLine, atTakeoff));
    }

    [GeneratedRegex(@"\(0\.0\d s before jump \d+'s takeoff|flight, 0\.0\d s after takeoff", RegexOptions.CultureInvariant)]
    private static partial Regex AtTakeoff();
}
