namespace Ballistic.Runtime.Skeletons;

/// <summary>How <see cref="AnimationClipBaker"/> samples and thins a clip.</summary>
public sealed record ClipBakeSettings
{
    /// <summary>Samples per second (0 &lt; rate ≤ 1000); 30 by default. The last sample falls exactly on the end.</summary>
    public float FrameRate { get; init; } = 30f;

    /// <summary>
    /// A rotation key is dropped when the track, interpolated between the keys kept around it (slerp, as Godot's
    /// linear rotation tracks do), stays within this angle (radians) of it; 1e-4 rad by default. Zero keeps every
    /// key that differs at all.
    /// </summary>
    public float RotationEpsilon { get; init; } = 1e-4f;

    /// <summary>
    /// A position key is dropped when the track, interpolated linearly between the keys kept around it, stays within
    /// this distance (world metres, whatever the skeleton's units) of it; 1e-4 m by default.
    /// </summary>
    public float PositionEpsilon { get; init; } = 1e-4f;

    /// <summary>
    /// The path of the <c>Skeleton3D</c> node from the animation player's root node (Godot's <c>AnimationMixer.RootNode</c>),
    /// the part before ':' in each track path ("Skeleton3D:Hips"); "Skeleton3D" by default.
    /// </summary>
    public string SkeletonPath { get; init; } = "Skeleton3D";

    /// <summary>The first problem with these settings, or <c>null</c>.</summary>
    public string? Problem() =>
        !(FrameRate > 0f && FrameRate <= 1000f) ? $"the frame rate must lie in (0, 1000] per second, not {FrameRate}"
        : !(RotationEpsilon >= 0f && float.IsFinite(RotationEpsilon)) ? $"the rotation epsilon must be finite and not negative, not {RotationEpsilon}"
        : !(PositionEpsilon >= 0f && float.IsFinite(PositionEpsilon)) ? $"the position epsilon must be finite and not negative, not {PositionEpsilon}"
        : string.IsNullOrEmpty(SkeletonPath) || SkeletonPath.Contains(':', StringComparison.Ordinal) ? $"the skeleton path must be a node path without ':', not '{SkeletonPath}'"
        : null;
}
