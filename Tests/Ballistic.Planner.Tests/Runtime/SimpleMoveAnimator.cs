using Ballistic.Planner.Animation;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>
/// A test double of the whole-body animator that animates walks as well as jumps, simply: a fixed stance between
/// moves, frames at the frame rate with the root exactly on the moves (<see cref="JumpAnimation.RootAt"/>: the arc in
/// flight, <see cref="Walk.PoseAt"/> while walking) and the character's contact pose angles; no problems. Standing
/// checks are the real animator's.
/// </summary>
internal sealed class SimpleMoveAnimator(JumpAnimator real, float stance = 0.2f) : IJumpAnimator
{
    /// <summary>Seconds of stance between two moves.</summary>
    public float Stance { get; } = stance;

    /// <summary>Paths animated so far.</summary>
    public int Calls { get; private set; }

    public JumpAnimation Animate(IReadOnlyList<Move> moves, float frameRate = 60f)
    {
        Calls++;
        float[] stances = [.. Enumerable.Repeat(Stance, Math.Max(0, moves.Count - 1))];
        var timing = new JumpAnimation(real.Model, moves, stances, [], [], [], 0, 0);
        int n = Math.Max(1, (int)MathF.Ceiling(timing.Duration * frameRate));
        var frames = new List<AnimationFrame>(n + 1);
        for (int k = 0; k <= n; k++)
        {
            float t = k == n ? timing.Duration : MathF.Min(k / frameRate, timing.Duration);
            frames.Add(new AnimationFrame(t, timing.RootAt(t), real.Model.ContactPose));
        }

        return new JumpAnimation(real.Model, moves, stances, frames, [], [], 0, 0);
    }

    public bool CanStand(PoseEvaluation pose) => real.CanStand(pose);
}
