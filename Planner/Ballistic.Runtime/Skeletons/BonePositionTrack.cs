using System.Numerics;

namespace Ballistic.Runtime.Skeletons;

/// <summary>
/// A baked position track of one bone: key times and the bone's local pose position (in its parent's space, the
/// skeleton's units, as <c>Skeleton3D.SetBonePosePosition</c> takes it), interpolated linearly. Godot: a
/// <c>Animation.TrackType.Position3D</c> track at <see cref="Path"/> with <c>PositionTrackInsertKey</c> per key.
/// </summary>
/// <param name="Path">The track path, "SkeletonPath:BoneName" (e.g. "Skeleton3D:Hips").</param>
/// <param name="Bone">The bone's index in the target skeleton.</param>
/// <param name="BoneName">The bone's name.</param>
/// <param name="Times">Key times, seconds, increasing (at least one).</param>
/// <param name="Positions">The position at each key.</param>
public sealed record BonePositionTrack(string Path, int Bone, string BoneName, float[] Times, Vector3[] Positions)
{
    /// <summary>The position at <paramref name="time"/> (seconds): linear between the keys around it, the first or last key outside them.</summary>
    public Vector3 Sample(float time)
    {
        int i = KeyTimes.Before(Times, time, out float w);
        return w <= 0f ? Positions[i] : Vector3.Lerp(Positions[i], Positions[i + 1], w);
    }
}
