using System.Numerics;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Animation;

/// <summary>
/// Animates a path of moves (jumps and walks) with the whole body and says what it could not do cleanly (the motion validator of
/// the plan use case, after OMPL's one-method validity interfaces). <see cref="JumpAnimator"/> is the implementation.
/// </summary>
public interface IJumpAnimator
{
    /// <summary>Animates the moves at <paramref name="frameRate"/> frames per second; problems go in <see cref="JumpAnimation.Problems"/>, never hidden.</summary>
    JumpAnimation Animate(IReadOnlyList<Move> moves, float frameRate = 60f);

    /// <summary>True when the whole body can stand at <paramref name="pose"/>: as many limbs as the character needs reach the level by IK with no bone through it.</summary>
    bool CanStand(PoseEvaluation pose);

    /// <summary>
    /// True when the whole body, its root at <paramref name="root"/>, can push off with <paramref name="velocity"/>
    /// (m/s, world frame; a landing's velocity reversed, to absorb it) on the contacts the plan reports,
    /// <paramref name="contacts"/>: the contact pose the animation would take off (land) on holds them and its cone
    /// contains the velocity. True unless an implementation says otherwise.
    /// </summary>
    bool CanPush(RootPose root, IReadOnlyList<Contact> contacts, Vector3 velocity) => true;
}
