namespace Ballistic.Planner.Sampling;

/// <summary>How root poses are drawn near the level's surfaces.</summary>
internal sealed record SamplerSettings
{
    /// <summary>Attempts (draw, repair, check) before one sample is given up.</summary>
    public int MaxAttempts { get; init; } = 1_000;

    /// <summary>Out-of-collision repair steps per attempt.</summary>
    public int RepairSteps { get; init; } = 8;

    /// <summary>Distance (metres) the trunk is pushed out of the level at each repair step.</summary>
    public float RepairStep { get; init; } = 0.05f;
}
