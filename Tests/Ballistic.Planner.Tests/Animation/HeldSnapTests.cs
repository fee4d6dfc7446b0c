using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Animation;

/// <summary>
/// A held foot's IK solve may go over to another solution holding the same foothold between two fine steps: the
/// user's human rig (90° rest rotations, a rig in another tool's shape) walking round the block level (the sweep's last
/// request there) twisted a hip 35–45° in a displayed frame between frames of 2–11°, at nearly every step, its foot
/// planted. The leg now changes solution over the displayed frame before, its foot still held flat
/// (<see cref="WalkGait"/>'s holds).
/// </summary>
[Category("EndToEnd")]
public sealed class HeldSnapTests
{
    /// <summary>Where the foreign rig's files are written (removed when the fixture ends).</summary>
    private static readonly string RigFolder = RigFolders.For("held-snap");

    [OneTimeTearDown]
    public void RemoveTheRigFiles() => RigFolders.Remove(RigFolder);

    [Test]
    public void AHumansPlantedLegDoesNotSnapAsItWalksRoundTheBlock()
    {
        (Sweep.Setup setup, (Vector3 From, Vector3 To)[] requests) = Sweep.PrepareForeign("block", "human", RigFolder);

        // Held legs in its walks (before: 19 frames).
        Sweep.AssertNoWalkSnaps(setup, requests[3].From, requests[3].To, "held");
    }

    /// <summary>
    /// Eased into over one displayed frame, a planted leg that jumps 27–38° still turns that far in one frame: the
    /// human rig's right hip and foot on its first walk round the block (the sweep's request 0: three snapping frames),
    /// the skeleton's right hip as it turns in place there (request 3: 38.3° between frames of 1.3°). The leg now
    /// changes solution over as many frames as keep each joint under 10° a frame where the hold began early enough,
    /// the foot still held flat.
    /// </summary>
    [Test]
    public void APlantedLegGoesOverToAnotherSolutionOverSeveralFrames()
    {
        (Sweep.Setup human, (Vector3 From, Vector3 To)[] requests) = Sweep.PrepareForeign("block", "human", RigFolder);
        Sweep.AssertNoWalkSnaps(human, requests[0].From, requests[0].To, "held");
        Sweep.AssertNoWalkSnaps(Sweep.Prepare("block", ForeignLevels.Get("block").Level, "skeleton"), requests[3].From, requests[3].To, "held");
    }
}
