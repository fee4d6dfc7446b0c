using Ballistic.Planner.Animation;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>
/// A test double of the whole-body animator that animates walks as well as jumps, simply: a fixed stance between
/// moves, frames at the frame rate with the root exactly on the moves (<see cref="JumpAnimation.RootAt(float)"/>: the arc in
/// flight, <see cref="Walk.PoseAt(float)"/> while walking) and the character's contact pose angles; no problems. Standing
/// checks are the real animator's. With a <c>lift</c>, walking frames have their root that far above the walk's path
/// halfway through each walk, rising and falling as a sine of the walk's time (an upright walk's lift, simply).
/// </summary>
internal sealed class SimpleMoveAnimator(JumpAnimator real, float stance = 0.2f, float lift = 0f) : IJumpAnimator
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
            RootPose root = timing.RootAt(t);
            int m = timing.MoveIndex(t);
            float since = t - timing.MoveStart(m);
            if (lift != 0f && moves[m] is Walk walk && since > 0f && since < walk.Duration)
            {
                root = JumpAnimation.Lifted(root, lift * MathF.Sin(MathF.PI * since / walk.Duration));
            }

            frames.Add(new AnimationFrame(t, root, real.Model.ContactPose));
        }

        return new JumpAnimation(real.Model, moves, stances, frames, [], [], 0, 0);
    }

    public bool CanStand(PoseEvaluation pose) => real.CanStand(pose);
}
