namespace Ballistic.Planner.Walking;

/// <summary>Why two stances are not linked by a walk.</summary>
internal enum WalkFailure
{
    /// <summary>The walk is valid.</summary>
    None,

    /// <summary>The character does not walk (<see cref="Characters.WalkingLimits.CanWalk"/> is false).</summary>
    NotWalking,

    /// <summary>The stances are farther apart than the walk's limit.</summary>
    TooFar,

    /// <summary>The ground is missing under the path, or drops by more than the step height.</summary>
    Gap,

    /// <summary>The ground rises by more than the step height, or something stands between the ground and the trunk.</summary>
    StepTooHigh,

    /// <summary>The ground is steeper than the character's steepest slope.</summary>
    TooSteep,

    /// <summary>The trunk box at walking height touches the level along the way.</summary>
    TrunkCollides,
}
