namespace Ballistic.Planner.Characters;

/// <summary>
/// The character's jump abilities and the steering method's tolerances. Speeds in metres per second, angles in
/// radians, heights in world metres (Y up).
/// </summary>
internal sealed record SteeringLimits
{
    /// <summary>Creates limits, checking every value.</summary>
    /// <param name="takeoffSpeedMax">Largest takeoff speed |ċ_t|, m/s, &gt; 0.</param>
    /// <param name="landingSpeedMax">Largest landing speed |ċ_l|, m/s, &gt; 0.</param>
    /// <param name="gravity">Magnitude of gravity, m/s², &gt; 0; it acts along −Y.</param>
    /// <exception cref="ArgumentOutOfRangeException">A value is not a finite positive number.</exception>
    public SteeringLimits(float takeoffSpeedMax, float landingSpeedMax, float gravity = StandardGravity)
    {
        TakeoffSpeedMax = Positive(takeoffSpeedMax, nameof(takeoffSpeedMax));
        LandingSpeedMax = Positive(landingSpeedMax, nameof(landingSpeedMax));
        Gravity = Positive(gravity, nameof(gravity));
    }

    /// <summary>Standard gravity, 9.81 m/s².</summary>
    public const float StandardGravity = 9.81f;

    /// <summary>Largest takeoff speed, m/s.</summary>
    public float TakeoffSpeedMax { get; }

    /// <summary>Largest landing speed, m/s.</summary>
    public float LandingSpeedMax { get; }

    /// <summary>Magnitude of gravity, m/s², acting along −Y.</summary>
    public float Gravity { get; }

    /// <summary>Highest world Y the trunk centre may reach at the apex; +∞ for no bound.</summary>
    public float MaxApexHeight { get; init; } = float.PositiveInfinity;

    /// <summary>Horizontal distances below this (metres) are rejected as <see cref="Steering.SteeringFailure.TooClose"/>.</summary>
    public float MinHorizontalDistance { get; init; } = 1e-3f;

    /// <summary>
    /// Smallest half-width (radians) of a cone's cut by the jump's vertical plane; narrower cuts are treated as
    /// missing the plane, since the velocity would have to graze the cone's boundary.
    /// </summary>
    public float MinConeCutHalfAngle { get; init; } = 0.01f;

    /// <summary>
    /// Distance (metres) within which the trunk may not pass the level during a flight: the resolution of the
    /// continuous collision check. Poses closer than this to the level cannot take off or land.
    /// </summary>
    public float CollisionTolerance { get; init; } = 1e-3f;

    /// <summary>Margin (radians) kept above the straight-line angle atan(Z/X), below which no parabola reaches the goal.</summary>
    public float AngleMargin { get; init; } = 1e-3f;

    /// <summary>
    /// The largest horizontal distance (metres) any jump can cover when the landing lies <paramref name="drop"/>
    /// metres below the takeoff (negative: above), from the takeoff and landing speed limits alone. A necessary
    /// condition used to prune candidate pairs; <c>0</c> when no jump of that height is possible.
    /// </summary>
    public float MaxReach(float drop)
    {
        double g = Gravity;
        double z = -drop;
        double v2 = (double)TakeoffSpeedMax * TakeoffSpeedMax;
        double w2 = ((double)LandingSpeedMax * LandingSpeedMax) + (2.0 * g * z);
        if (w2 <= 0.0)
        {
            return 0f;
        }

        // From the speed quadratics: a real root needs V⁴ ≥ g (g X² + 2 Z V²), i.e. X ≤ √(V² (V² − 2 g Z)) / g.
        double takeoff = (v2 * (v2 - (2.0 * g * z))) / (g * g);
        double landing = (w2 * (w2 - (2.0 * g * z))) / (g * g);
        double reach2 = Math.Min(takeoff, landing);
        return reach2 > 0.0 ? (float)Math.Sqrt(reach2) : 0f;
    }

    private static float Positive(float value, string name) =>
        value > 0f && float.IsFinite(value)
            ? value
            : throw new ArgumentOutOfRangeException(name, value, $"{name} must be a finite number greater than zero.");
}
