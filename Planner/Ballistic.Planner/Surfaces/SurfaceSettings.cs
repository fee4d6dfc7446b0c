namespace Ballistic.Planner.Surfaces;

/// <summary>How triangles are grouped into contact surfaces (defaults after the original affordance extraction).</summary>
internal sealed record SurfaceSettings
{
    /// <summary>
    /// Largest squared distance |n_seed − n|² between a surface's first triangle's unit normal and another
    /// triangle's; 0.3 allows about 32°.
    /// </summary>
    public float MaxNormalDeviationSquared { get; init; } = 0.3f;

    /// <summary>Surfaces smaller than this (square metres) take no contacts; their triangles still collide.</summary>
    public float MinArea { get; init; } = 0.05f;

    /// <summary>Vertices closer than this (metres) count as shared when finding neighbouring triangles.</summary>
    public float WeldTolerance { get; init; } = 1e-4f;
}
