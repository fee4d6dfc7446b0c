namespace Ballistic.Planner.Steering;

/// <summary>Why the parabola steering method found no jump between two root poses.</summary>
public enum SteeringFailure
{
    /// <summary>No failure: a valid jump was found.</summary>
    None = 0,

    /// <summary>The two poses are (almost) vertically aligned: horizontal distance X ≈ 0 has no parabola.</summary>
    TooClose,

    /// <summary>The vertical plane through both poses misses the takeoff friction cone, or only grazes it.</summary>
    TakeoffConeMissesPlane,

    /// <summary>The vertical plane through both poses misses the landing friction cone, or only grazes it.</summary>
    LandingConeMissesPlane,

    /// <summary>No takeoff angle keeps the takeoff speed under the character's limit.</summary>
    TakeoffSpeed,

    /// <summary>No takeoff angle keeps the landing speed under the character's limit.</summary>
    LandingSpeed,

    /// <summary>No forward-moving landing velocity has its reverse inside the landing cone.</summary>
    LandingCone,

    /// <summary>Each constraint alone admits takeoff angles, but no angle satisfies them all.</summary>
    EmptyAngleInterval,

    /// <summary>Every admissible parabola rises above the height bound.</summary>
    ApexTooHigh,

    /// <summary>
    /// Every tried parabola is refused by the arc validator: the trunk collides with the level, or an extra
    /// <see cref="IArcValidator"/> given to the planning scene refuses it.
    /// </summary>
    Collision,
}
