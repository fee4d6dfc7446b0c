namespace Ballistic.Planner.Animation;

/// <summary>Which stance of a jump a <see cref="JumpProblem"/> belongs to, when it is a problem of the stance and not of the jump.</summary>
internal enum ProblemStance
{
    /// <summary>A problem of the move itself.</summary>
    None,

    /// <summary>The body cannot crouch on the takeoff stance, or no limb reaches the level from it.</summary>
    Takeoff,

    /// <summary>The body cannot absorb a landing on the landing stance, or no limb reaches the level from it.</summary>
    Landing,
}
