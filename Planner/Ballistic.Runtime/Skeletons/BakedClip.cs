namespace Ballistic.Runtime.Skeletons;

/// <summary>
/// A planned path's whole-body animation baked for one skeleton: what a Godot <c>Animation</c> is built from (set
/// <c>Length</c>, add a <c>Rotation3D</c> track per <see cref="RotationTracks"/> entry and a <c>Position3D</c>
/// track per <see cref="PositionTracks"/> entry, linear interpolation), e.g. to put in an <c>AnimationLibrary</c>.
/// </summary>
/// <param name="Length">Duration of the clip, seconds: the animation's duration.</param>
/// <param name="FrameRate">Samples per second it was baked at.</param>
/// <param name="RotationTracks">One track per driven bone, in bone order.</param>
/// <param name="PositionTracks">One track per positioned bone (the root bone and any other top driven bone), in bone order.</param>
public sealed record BakedClip(float Length, float FrameRate, IReadOnlyList<BoneRotationTrack> RotationTracks, IReadOnlyList<BonePositionTrack> PositionTracks)
{
    /// <summary>Total number of keys over every track.</summary>
    public int KeyCount => RotationTracks.Sum(t => t.Times.Length) + PositionTracks.Sum(t => t.Times.Length);
}
