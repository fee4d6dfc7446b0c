using Ballistic.Planner.Animation;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Runtime;

namespace Ballistic.Planner.Tests.Query;

/// <summary>Animates like the inner double, with a problem (<paramref name="reason"/>, naming <paramref name="stance"/>) on every move <paramref name="refuses"/> picks.</summary>
internal sealed class RefusingAnimator(SimpleMoveAnimator inner, Func<Move, bool> refuses, string reason, ProblemStance stance = ProblemStance.None) : IJumpAnimator
{
    /// <summary>Paths animated with at least one move refused.</summary>
    public int PathsRefused { get; private set; }

    public JumpAnimation Animate(IReadOnlyList<Move> moves, float frameRate = 60f)
    {
        JumpAnimation a = inner.Animate(moves, frameRate);
        List<JumpProblem> problems = [.. Enumerable.Range(0, moves.Count).Where(m => refuses(moves[m])).Select(m => new JumpProblem(m, reason) { Stance = stance })];
        PathsRefused += problems.Count > 0 ? 1 : 0;
        return new JumpAnimation(a.Model, moves, [.. Enumerable.Range(0, Math.Max(0, moves.Count - 1)).Select(_ => inner.Stance)], a.Frames, a.ContactPhases, problems, 0, 0);
    }

    public bool CanStand(PoseEvaluation pose) => inner.CanStand(pose);
}
