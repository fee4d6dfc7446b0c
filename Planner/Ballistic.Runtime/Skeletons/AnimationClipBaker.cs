using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Geometry;
using Ballistic.Runtime.Paths;

namespace Ballistic.Runtime.Skeletons;

/// <summary>
/// Bakes a planned path's whole-body animation (its jumps and walks) into tracks for one skeleton, so that designers can scrub it in the
/// engine's animation editor: the animation is sampled at a fixed rate, each sample converted by a
/// <see cref="SkeletonBinding"/> (the same conversion the runtime animator makes every frame), and each track
/// thinned to the keys its interpolation cannot reproduce within an epsilon. Deterministic.
/// </summary>
public static class AnimationClipBaker
{
    /// <summary>The most samples a clip may take (duration × frame rate + 1).</summary>
    public const int MaxFrames = 1_000_000;

    /// <summary>Bakes an agent's path (its <see cref="AgentPath.Animation"/>; clip time = path time).</summary>
    /// <inheritdoc cref="Bake(JumpAnimation, SkeletonBinding, in BoneTransform, ClipBakeSettings?)"/>
    public static BakedClip Bake(AgentPath path, SkeletonBinding binding, in BoneTransform skeletonGlobal, ClipBakeSettings? settings = null)
    {
        ArgumentNullException.ThrowIfNull(path);
        return Bake(path.Animation, binding, skeletonGlobal, settings);
    }

    /// <summary>
    /// Bakes <paramref name="animation"/>, the whole clip over its moves (jumps, walks and the stances between them): a
    /// rotation track per driven bone and a position track per positioned bone (<see cref="SkeletonBinding.PositionedBones"/>),
    /// keyed from time 0 to the animation's duration.
    /// </summary>
    /// <param name="animation">The whole-body animation (of the binding's character).</param>
    /// <param name="binding">The binding of the character to the skeleton the clip is for.</param>
    /// <param name="skeletonGlobal">The skeleton node's world transform while the clip plays (the positions are relative to it).</param>
    /// <param name="settings">Rate, epsilons and skeleton path; defaults when <c>null</c>.</param>
    /// <exception cref="ArgumentException">The animation is of another character or has no frames or no moves, a setting is out of range, or the clip would exceed <see cref="MaxFrames"/> samples.</exception>
    public static BakedClip Bake(JumpAnimation animation, SkeletonBinding binding, in BoneTransform skeletonGlobal, ClipBakeSettings? settings = null)
    {
        ArgumentNullException.ThrowIfNull(animation);
        ArgumentNullException.ThrowIfNull(binding);
        settings ??= new ClipBakeSettings();
        if (settings.Problem() is { } problem)
        {
            throw new ArgumentException($"Clip bake settings: {problem}.", nameof(settings));
        }

        if (!ReferenceEquals(animation.Model.Rig, binding.Model.Rig))
        {
            throw new ArgumentException($"The animation is of '{animation.Model.Name}'; the binding is for '{binding.Model.Name}'.", nameof(animation));
        }

        if (animation.Frames.Count == 0 || animation.Moves.Count == 0)
        {
            throw new ArgumentException($"The animation has {animation.Frames.Count} frames and {animation.Moves.Count} moves; a clip needs at least one of each.", nameof(animation));
        }

        float duration = animation.Duration;
        double frames = Math.Ceiling((duration * (double)settings.FrameRate) - 1e-4) + 1.0;
        if (!(frames <= MaxFrames) || !float.IsFinite(duration) || duration < 0f)
        {
            throw new ArgumentException($"A {duration} s clip at {settings.FrameRate} frames per second exceeds {MaxFrames} samples.", nameof(settings));
        }

        int count = Math.Max(1, (int)frames);
        float[] times = new float[count];
        for (int k = 0; k < count; k++)
        {
            times[k] = k == count - 1 ? duration : (float)(k / (double)settings.FrameRate);
        }

        TargetSkeleton target = binding.Target;
        IReadOnlyList<int> driven = binding.DrivenBones;
        IReadOnlyList<int> positioned = binding.PositionedBones;
        var rotations = new Quaternion[driven.Count][];
        var positions = new Vector3[positioned.Count][];
        for (int i = 0; i < rotations.Length; i++)
        {
            rotations[i] = new Quaternion[count];
        }

        for (int i = 0; i < positions.Length; i++)
        {
            positions[i] = new Vector3[count];
        }

        float[] angles = new float[animation.Model.Rig.DofCount];
        var boneRotations = new Quaternion[target.BoneCount];
        var bonePositions = new Vector3[target.BoneCount];
        for (int k = 0; k < count; k++)
        {
            RootPose root = animation.Sample(times[k], angles);
            binding.ConvertAngles(root, angles, skeletonGlobal, boneRotations, bonePositions);
            for (int i = 0; i < rotations.Length; i++)
            {
                rotations[i][k] = boneRotations[driven[i]];
            }

            for (int i = 0; i < positions.Length; i++)
            {
                positions[i][k] = bonePositions[positioned[i]];
            }
        }

        // A position epsilon in world metres is, in the bone's parent space, that divided by the parent's scale.
        (_, _, float[] restScales) = target.RestInSkeleton();
        var rotationTracks = new BoneRotationTrack[rotations.Length];
        for (int i = 0; i < rotations.Length; i++)
        {
            int bone = driven[i];
            ShortestPaths(rotations[i]);
            (float[] t, Quaternion[] r) = Thin(times, rotations[i], settings.RotationEpsilon);
            rotationTracks[i] = new BoneRotationTrack(TrackPath(settings, target.Names[bone]), bone, target.Names[bone], t, r);
        }

        var positionTracks = new BonePositionTrack[positions.Length];
        for (int i = 0; i < positions.Length; i++)
        {
            int bone = positioned[i];
            int parent = target.Parents[bone];
            float parentScale = skeletonGlobal.Scale.X * (parent >= 0 ? restScales[parent] : 1f);
            (float[] t, Vector3[] p) = Thin(times, positions[i], settings.PositionEpsilon / parentScale);
            positionTracks[i] = new BonePositionTrack(TrackPath(settings, target.Names[bone]), bone, target.Names[bone], t, p);
        }

        return new BakedClip(duration, settings.FrameRate, rotationTracks, positionTracks);
    }

    /// <summary>The track path of a bone: "SkeletonPath:BoneName".</summary>
    public static string TrackPath(ClipBakeSettings settings, string boneName)
    {
        ArgumentNullException.ThrowIfNull(settings);
        return $"{settings.SkeletonPath}:{boneName}";
    }

    /// <summary>
    /// The angle between two unit rotations, radians, accurate for tiny angles (4 asin(|a − b| / 2) with b taken in
    /// a's hemisphere) where 2 acos(a·b) is not.
    /// </summary>
    internal static double Angle(Quaternion a, Quaternion b)
    {
        double sign = Quaternion.Dot(a, b) < 0f ? -1.0 : 1.0;
        double dx = a.X - (sign * b.X);
        double dy = a.Y - (sign * b.Y);
        double dz = a.Z - (sign * b.Z);
        double dw = a.W - (sign * b.W);
        double chord = Math.Sqrt((dx * dx) + (dy * dy) + (dz * dz) + (dw * dw));
        return 4.0 * Math.Asin(Math.Min(1.0, chord / 2.0));
    }

    /// <summary>Flips keys into the previous key's hemisphere, so that every interpolation takes the short way.</summary>
    private static void ShortestPaths(Quaternion[] keys)
    {
        for (int k = 1; k < keys.Length; k++)
        {
            if (Quaternion.Dot(keys[k], keys[k - 1]) < 0f)
            {
                keys[k] = -keys[k];
            }
        }
    }

    /// <summary>
    /// The keys to keep: the first, the last, and each key that slerp between the last key kept and a later key
    /// cannot reproduce within <paramref name="epsilon"/> radians at every key in between (greedy). A track that
    /// never leaves <paramref name="epsilon"/> of its first key keeps only that key.
    /// </summary>
    private static (float[] Times, Quaternion[] Values) Thin(float[] times, Quaternion[] values, float epsilon)
    {
        int n = values.Length;
        bool constant = true;
        for (int i = 1; i < n && constant; i++)
        {
            constant = Angle(values[i], values[0]) <= epsilon;
        }

        if (constant)
        {
            return ([times[0]], [values[0]]);
        }

        var kept = new List<int> { 0 };
        int anchor = 0;
        for (int j = 1; j < n - 1; j++)
        {
            int next = j + 1;
            bool covered = true;
            for (int i = anchor + 1; i <= j && covered; i++)
            {
                float w = (times[i] - times[anchor]) / (times[next] - times[anchor]);
                covered = Angle(Quaternion.Normalize(Quaternion.Slerp(values[anchor], values[next], w)), values[i]) <= epsilon;
            }

            if (!covered)
            {
                kept.Add(j);
                anchor = j;
            }
        }

        kept.Add(n - 1);
        return ([.. kept.Select(k => times[k])], [.. kept.Select(k => values[k])]);
    }

    /// <summary>As the rotation <see cref="Thin(float[], Quaternion[], float)"/>, for positions interpolated linearly, within <paramref name="epsilon"/> (the track's units).</summary>
    private static (float[] Times, Vector3[] Values) Thin(float[] times, Vector3[] values, float epsilon)
    {
        int n = values.Length;
        bool constant = true;
        for (int i = 1; i < n && constant; i++)
        {
            constant = Vector3.Distance(values[i], values[0]) <= epsilon;
        }

        if (constant)
        {
            return ([times[0]], [values[0]]);
        }

        var kept = new List<int> { 0 };
        int anchor = 0;
        for (int j = 1; j < n - 1; j++)
        {
            int next = j + 1;
            bool covered = true;
            for (int i = anchor + 1; i <= j && covered; i++)
            {
                float w = (times[i] - times[anchor]) / (times[next] - times[anchor]);
                covered = Vector3.Distance(Vector3.Lerp(values[anchor], values[next], w), values[i]) <= epsilon;
            }

            if (!covered)
            {
                kept.Add(j);
                anchor = j;
            }
        }

        kept.Add(n - 1);
        return ([.. kept.Select(k => times[k])], [.. kept.Select(k => values[k])]);
    }
}
