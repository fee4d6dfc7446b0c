namespace Ballistic.Planner.Sampling;

/// <summary>
/// How close a plan's first and last stance must come to the requested start and goal points: the centre of the
/// stance's contacts within <see cref="Across"/> metres horizontally and <see cref="UpDown"/> metres vertically
/// (world Y) of the point. The vertical bound keeps a goal on a step or a roof from ending on the floor beside it.
/// </summary>
/// <param name="Across">Largest horizontal distance, metres (default 0.5).</param>
/// <param name="UpDown">Largest vertical distance, metres (default 0.25).</param>
public readonly record struct EndpointTolerance(float Across = 0.5f, float UpDown = 0.25f)
{
    /// <summary>Creates the default tolerance: 0.5 m across, 0.25 m up or down.</summary>
    public EndpointTolerance()
        : this(0.5f, 0.25f)
    {
    }

    /// <summary>Checks both bounds.</summary>
    /// <exception cref="ArgumentException">A bound is not a finite positive number of metres.</exception>
    public void Validate()
    {
        if (!(Across > 0f && float.IsFinite(Across) && UpDown > 0f && float.IsFinite(UpDown)))
        {
            throw new ArgumentException($"The endpoint tolerance must be finite and positive, not {Across} m across and {UpDown} m up/down.");
        }
    }

    /// <inheritdoc />
    public override string ToString() => $"{Across:0.##} m across and {UpDown:0.##} m up/down";
}
