using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Animation;

/// <summary>
/// A swinging leg's IK solve may turn a joint suddenly while staying under the gait's absolute bound
/// (<see cref="WalkGait.MaxJointTurn"/>, 15° a fine step): the skeleton turning in place at the start of its walk round
/// the block (a level in other tools' shape, the sweep's last request there), its ankle at its limit as the foot
/// left the ground, turned its hip's abduction onto its limit and its roll 18° in two fine steps, 23° in a displayed
/// frame between frames of 2°. A solve that turns a joint faster than 900°/s and three times as fast as the fine step
/// before is now passed over like one past the absolute bound, for the looser sole, then for the solve that holds.
/// Where only a solve past the absolute bound holds the curve (a leg reaching a joint's limit), the leg eases into it
/// over the displayed frame before (<see cref="WalkGait"/>'s swing).
/// </summary>
[Category("EndToEnd")]
public sealed class SwingSnapTests
{
    /// <summary>Where the foreign rig's files are written (removed when the fixture ends).</summary>
    private static readonly string RigFolder = RigFolders.For("swing-snap");

    [OneTimeTearDown]
    public void RemoveTheRigFiles() => RigFolders.Remove(RigFolder);

    [Test]
    public void ALegSwingingAsTheSkeletonTurnsInPlaceDoesNotSnap()
    {
        (Level level, (Vector3 From, Vector3 To)[] requests) = ForeignLevels.Get("block");

        // Swinging legs in its walks (before: 7 frames, every one a hip, 16–23° each).
        Sweep.AssertNoWalkSnaps(Sweep.Prepare("block", level, "skeleton"), requests[3].From, requests[3].To, "free");
    }

    /// <summary>
    /// The Rigify-style panda (a rig in another tool's shape, foot IK helpers, modelled mid-stride) walking through the
    /// doorway level's door (the sweep's request 1): its right hind leg reached a joint's limit along its swing, and
    /// the only solve holding the curve turned its thigh past the gait's 15° a fine step, 43.5° in a displayed frame
    /// between frames of 5.6°. The leg now changes solution over the frame before: no swinging limb of its walks snaps.
    /// </summary>
    /// <summary>
    /// A skeleton's leg reaching a joint's limit mid-swing goes over to another solution, 18–34° in a displayed frame
    /// between frames of 2–5° (the curved terrain's requests 0 and 2: a hip twice, a knee once). Easing that over the one
    /// frame before did not hide it from the eye; the jump is now blended over the steps around it (a tenth of a second
    /// for a 40° jump).
    /// </summary>
    [TestCase("curved", 0)]
    [TestCase("curved", 2)]
    public void ASkeletonsHipReachingItsLimitMidSwingDoesNotSnap(string levelName, int request)
    {
        (Level level, (Vector3 From, Vector3 To)[] requests) = ForeignLevels.Get(levelName);
        Sweep.AssertNoWalkSnaps(Sweep.Prepare(levelName, level, "skeleton"), requests[request].From, requests[request].To, "free");
    }

    /// <summary>
    /// Quadrupeds made elsewhere on the curved terrain (the sweep's requests there): the dog's right front paw turned
    /// 53° in a displayed frame between frames of 11° in its swing, the tailed quadruped's upper arm 28° between frames
    /// of 3°. Blended across, no swinging limb of their walks snaps.
    /// </summary>
    [TestCase("dog", 1)]
    [TestCase("tailed", 2)]
    public void AQuadrupedsSwingingLegDoesNotSnapOnTheDunes(string rig, int request)
    {
        (Sweep.Setup setup, (Vector3 From, Vector3 To)[] requests) = Sweep.PrepareForeign("curved", rig, RigFolder);
        Sweep.AssertNoWalkSnaps(setup, requests[request].From, requests[request].To, "free");
    }

    [Test]
    public void APandasLegReachingAJointLimitInItsSwingDoesNotSnap()
    {
        (Sweep.Setup setup, (Vector3 From, Vector3 To)[] requests) = Sweep.PrepareForeign("doorway", "panda", RigFolder);
        Sweep.AssertNoWalkSnaps(setup, requests[1].From, requests[1].To, "free");
    }
}
