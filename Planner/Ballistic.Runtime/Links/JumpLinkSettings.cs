namespace Ballistic.Runtime.Links;

/// <summary>
/// Which jumps of a roadmap become navigation links, and at what cost (<see cref="JumpLinkSet.Build"/>). Roadmaps
/// hold thousands of jumps; most are hops a navmesh agent walks anyway. The defaults keep every jump between two
/// stances on walkable ground (no merging, no cap).
/// </summary>
public sealed record JumpLinkSettings
{
    /// <summary>
    /// The speed a link's flight time is priced at, m/s: pass the <c>NavigationAgent3D.MaxSpeed</c> of the agents
    /// that walk the navmesh (10 m/s by default in Godot), so that a jump costs as much as walking for its flight time.
    /// </summary>
    public float ReferenceSpeed { get; init; } = 10f;

    /// <summary>Godot's <c>enter_cost</c> of every link, metres of path (added when a path enters the link). Default 0.</summary>
    public float EnterCost { get; init; }

    /// <summary>A jump whose ends are farther apart than this horizontally (metres) is kept (or else by <see cref="MinHeightChange"/>). Default 0.</summary>
    public float MinHorizontalDistance { get; init; }

    /// <summary>A jump whose ends differ in height by more than this (metres, a step) is kept (or else by <see cref="MinHorizontalDistance"/>). Default 0.</summary>
    public float MinHeightChange { get; init; }

    /// <summary>
    /// Both stances must stand on ground no steeper than this, degrees: the angle between +Y and the stance's friction
    /// cone axis (the normalised sum of its contact normals). Jumps from or to walls and ceilings have no navmesh to
    /// connect to. Default 45° (Godot's <c>NavigationMesh.agent_max_slope</c>).
    /// </summary>
    public float MaxSlopeDegrees { get; init; } = 45f;

    /// <summary>
    /// A jump whose start and end lie within this distance (metres, each) of the start and end of a link already kept
    /// is merged into it (dropped). Jumps are taken cheapest first (flight time, then edge index), so that of near
    /// duplicates the quickest jump is kept. 0 (default): no merging.
    /// </summary>
    public float MergeRadius { get; init; }

    /// <summary>At most this many links are kept, the first in the order above. Default: no cap.</summary>
    public int MaxLinks { get; init; } = int.MaxValue;

    /// <summary>The first invalid setting as one sentence, or <c>null</c>.</summary>
    public string? Problem()
    {
        if (!float.IsFinite(ReferenceSpeed) || !(ReferenceSpeed > 0f))
        {
            return $"ReferenceSpeed must be finite and positive, not {ReferenceSpeed} m/s";
        }

        foreach ((string name, float value) in new[] { (nameof(EnterCost), EnterCost), (nameof(MinHorizontalDistance), MinHorizontalDistance), (nameof(MinHeightChange), MinHeightChange), (nameof(MergeRadius), MergeRadius) })
        {
            if (!float.IsFinite(value) || value < 0f)
            {
                return $"{name} must be finite and not negative, not {value}";
            }
        }

        if (!(MaxSlopeDegrees >= 0f && MaxSlopeDegrees <= 180f))
        {
            return $"MaxSlopeDegrees must be 0–180, not {MaxSlopeDegrees}";
        }

        return MaxLinks < 0 ? $"MaxLinks must not be negative, not {MaxLinks}" : null;
    }
}
