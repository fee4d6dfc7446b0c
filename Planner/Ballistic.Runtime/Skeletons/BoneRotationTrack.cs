using System.Numerics;

namespace Ballistic.Runtime.Skeletons;

/// <summary>
/// A baked rotation track of one bone: key times and the bone's local pose rotation (in its parent bone's space,
/// as <c>Skeleton3D.SetBonePoseRotation</c> takes it) at each, interpolated by slerp. Godot: a
/// <c>Animation.TrackType.Rotation3D</c> track at <see cref="Path"/> with <c>RotationTrackInsertKey</c> per key.
/// </summary>
/// <param name="Path">The track path, "SkeletonPath:BoneName" (e.g. "Skeleton3D:Hips").</param>
/// <param name="Bone">The bone's index in the target skeleton.</param>
/// <param name="BoneName">The bone's name.</param>
/// <param name="Times">Key times, seconds, increasing (at least one).</param>
/// <param name="Rotations">The rotation at each key; consecutive keys lie in the same hemisphere.</param>
public sealed record BoneRotationTrack(string Path, int Bone, string BoneName, float[] Times, Quaternion[] Rotations)
{
    /// <summary>The rotation at <paramref name="time"/> (seconds): slerp between the keys around it, the first or last key outside them.</summary>
    public Quaternion Sample(float time)
    {
        int i = KeyTimes.Before(Times, time, out float w);
        return w <= 0f ? Rotations[i] : Quaternion.Normalize(Quaternion.Slerp(Rotations[i], Rotations[i + 1], w));
    }
}
