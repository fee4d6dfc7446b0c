namespace Ballistic.Planner.Animation;

/// <summary>Why the whole body cannot perform one jump of a path cleanly.</summary>
/// <param name="Jump">Index of the jump in the path.</param>
/// <param name="Reason">One sentence: which pose, limb or bone, and what is wrong.</param>
public readonly record struct JumpProblem(int Jump, string Reason);
