namespace Ballistic.Runtime.DebugDraw;

/// <summary>Sizes, caps and colours of <see cref="DebugLines"/>' drawings. Metres, Y up.</summary>
public sealed record DebugDrawSettings
{
    /// <summary>Half the size of the cross drawn at a node's contact centre, metres (three axis-aligned strokes); 0.15 m by default.</summary>
    public float CrossHalfSize { get; init; } = 0.15f;

    /// <summary>The most roadmap nodes drawn; when a roadmap has more, this many evenly spaced by id are drawn. 5,000 by default.</summary>
    public int MaxNodes { get; init; } = 5_000;

    /// <summary>The most roadmap jumps drawn; when a roadmap has more, this many evenly spaced by edge index are drawn. 2,000 by default.</summary>
    public int MaxArcs { get; init; } = 2_000;

    /// <summary>The most segments an arc's polyline has; 16 by default.</summary>
    public int MaxSegmentsPerArc { get; init; } = 16;

    /// <summary>The length an arc segment aims at, metres (fewer segments for short arcs, never more than <see cref="MaxSegmentsPerArc"/>); 0.25 m by default.</summary>
    public float SegmentLength { get; init; } = 0.25f;

    /// <summary>
    /// Length of the dashes a walk is drawn with, metres, with gaps as long between them (a walk reads as dashed
    /// beside the solid arcs); 0 draws walks as solid polylines of <see cref="SegmentLength"/> segments. 0.15 m by default.
    /// </summary>
    public float WalkDashLength { get; init; } = 0.15f;

    /// <summary>The most segments (dashes) a walk is drawn with; a longer walk gets longer dashes. 512 by default.</summary>
    public int MaxSegmentsPerWalk { get; init; } = 512;

    /// <summary>Length of a friction cone's rays, metres; 0.6 m by default.</summary>
    public float ConeLength { get; init; } = 0.6f;

    /// <summary>Number of rays in a friction cone's fan (3 to 256); 12 by default.</summary>
    public int ConeRays { get; init; } = 12;

    /// <summary>The colours; Godot's navigation debug defaults by default.</summary>
    public DebugPalette Colors { get; init; } = DebugPalette.GodotDefaults;

    /// <summary>The first problem with these settings, or <c>null</c>.</summary>
    public string? Problem() =>
        !(CrossHalfSize > 0f && float.IsFinite(CrossHalfSize)) ? $"the cross half size must be positive and finite, not {CrossHalfSize}"
        : MaxNodes < 0 ? $"the node cap must not be negative, not {MaxNodes}"
        : MaxArcs < 0 ? $"the arc cap must not be negative, not {MaxArcs}"
        : MaxSegmentsPerArc is < 1 or > 1024 ? $"the segments per arc must lie in [1, 1024], not {MaxSegmentsPerArc}"
        : !(SegmentLength > 0f && float.IsFinite(SegmentLength)) ? $"the segment length must be positive and finite, not {SegmentLength}"
        : !(ConeLength > 0f && float.IsFinite(ConeLength)) ? $"the cone length must be positive and finite, not {ConeLength}"
        : ConeRays is < 3 or > 256 ? $"the cone rays must lie in [3, 256], not {ConeRays}"
        : !(WalkDashLength >= 0f && float.IsFinite(WalkDashLength)) ? $"the walk dash length must be finite and not negative, not {WalkDashLength}"
        : MaxSegmentsPerWalk is < 1 or > 65_536 ? $"the segments per walk must lie in [1, 65536], not {MaxSegmentsPerWalk}"
        : Colors is null ? "the palette is missing"
        : null;
}
