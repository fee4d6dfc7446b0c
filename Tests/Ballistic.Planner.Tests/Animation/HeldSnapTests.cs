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
}
