namespace Ballistic.Planner.Animation;

/// <summary>Why the whole body cannot perform one move (jump or walk) of a path cleanly.</summary>
/// <param name="Jump">Index of the move in the path.</param>
/// <param name="Reason">One sentence: which pose, limb or bone, and what is wrong.</param>
/// <param name="Along">
/// For a walk's problem, where it first shows: metres along the walk's ground path (<see cref="Roadmaps.Walk.PointAt(float)"/>);
/// <see cref="float.NaN"/> when it has no place on the path (a jump's problem, or a walk's stance that cannot be stood in).
/// </param>
internal readonly record struct JumpProblem(int Jump, string Reason, float Along = float.NaN)
{
    /// <summary>True when the problem has a place along a walk (<see cref="Along"/> is a number).</summary>
    public bool IsLocated => !float.IsNaN(Along);

    /// <summary>
    /// The stance the problem belongs to rather than the jump: the body cannot crouch on the jump's takeoff stance, or
    /// absorb its landing on the landing stance, or no limb reaches the level from it, whichever jump it makes there (every jump from or to that stance has
    /// the same contact pose there).
    /// </summary>
    internal ProblemStance Stance { get; init; }

    /// <summary>
    /// For a problem of the move, the stance it shows next to: a limb that hits the level in the first (last)
    /// <see cref="NearShare"/> of the flight, when it has just left (is about to reach) its takeoff (landing) stance.
    /// Other jumps from (to) that stance may pass, so a roadmap stance is not set aside for it; a stance placed to turn
    /// or cut a jump is placed again elsewhere (<see cref="Query.JumpRepair.RefusedTurns"/>).
    /// </summary>
    internal ProblemStance Near { get; init; }

    /// <summary>Share of a flight, from either end, within which a limb's hit is <see cref="Near"/> that end's stance.</summary>
    internal const float NearShare = 0.1f;
}
