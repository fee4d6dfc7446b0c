using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Animation;

/// <summary>
/// An animator whose <see cref="IJumpAnimator.Animate"/> can be spread over several frames: the same animation in
/// steps, <c>null</c> at each pause point (after each jump's contact poses and flight, after each walk's gait), then the
/// animation. A path request advanced under a per-tick budget uses it; other animators animate in one step.
/// </summary>
internal interface IStepwiseAnimator
{
    /// <summary><see cref="IJumpAnimator.Animate"/> in steps; the last step gives the same animation the whole call does.</summary>
    IEnumerable<JumpAnimation?> AnimateSteps(IReadOnlyList<Move> moves, float frameRate);
}
