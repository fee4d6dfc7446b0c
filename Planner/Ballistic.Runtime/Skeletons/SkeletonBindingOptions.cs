using System.Numerics;

namespace Ballistic.Runtime.Skeletons;

/// <summary>How <see cref="SkeletonBinding.Create"/> matches joints to bones and aligns their rests.</summary>
public sealed record SkeletonBindingOptions
{
    /// <summary>
    /// Explicit matches, runtime joint name → target bone name, tried before any other rule (for rigs whose names
    /// differ: "pelvis" → "Hips"). Every target named must be a bone of the skeleton; empty by default.
    /// </summary>
    public IReadOnlyDictionary<string, string> Renames { get; init; } = new Dictionary<string, string>();

    /// <summary>
    /// Match names that differ only in case and separators (<see cref="GodotBoneNames.LooseKey"/>) when no exact or
    /// sanitised name matches; a key shared by several bones matches none of them. On by default.
    /// </summary>
    public bool MatchLoosely { get; init; } = true;

    /// <summary>
    /// The rotation A taking the target skeleton's space to the rig's rest frame (the frame of the rig's rest pose
    /// with the root pose at the identity), so that a bone whose rest rotation in skeleton space is R is, at rest,
    /// A·R in the rig's frame. <c>null</c> (default): fitted to the rest positions of the matched bones relative to
    /// the root (Horn's least-squares rotation), which is exact when the skeleton is the rig's own file under any
    /// armature or axis-conversion node. Set it for skeletons whose bones all lie on one line.
    /// </summary>
    public Quaternion? RestAlignment { get; init; }
}
