using System.Numerics;
using Ballistic.Planner.Gltf;

namespace Ballistic.Planner.Rigs;

/// <summary>
/// The rigged glTF a <see cref="CharacterModel"/> was loaded from, and which glTF node each of the rig's joints is.
/// The animated GLB writer uses it to write the user's own meshes, materials, textures, skin and node hierarchy
/// with the jump clip added, instead of the procedural bone boxes.
/// </summary>
internal sealed class CharacterSource
{
    /// <summary>Creates a source mapping.</summary>
    /// <param name="model">The glTF the rig was read from.</param>
    /// <param name="jointNodes">For each rig joint (rig order), the index of its glTF node.</param>
    /// <param name="upAxis">The spec's <c>upAxis</c> (e.g. "+Z"): the glTF scene's direction that is the character's up.</param>
    /// <param name="forwardAxis">The spec's <c>forwardAxis</c> (e.g. "-Y"): the glTF scene's direction the character faces.</param>
    /// <exception cref="RigException">A node index is out of range or repeats, or an axis name is unknown.</exception>
    public CharacterSource(GltfModel model, IReadOnlyList<int> jointNodes, string upAxis = "+Y", string forwardAxis = "+Z")
    {
        ArgumentNullException.ThrowIfNull(model);
        ArgumentNullException.ThrowIfNull(jointNodes);
        ArgumentNullException.ThrowIfNull(upAxis);
        ArgumentNullException.ThrowIfNull(forwardAxis);
        int nodes = model.Root.LogicalNodes.Count;
        if (jointNodes.Any(n => n < 0 || n >= nodes) || jointNodes.Distinct().Count() != jointNodes.Count)
        {
            throw new RigException($"{model.Name}: the joints' node indices must be distinct nodes of the file.");
        }

        if (!CharacterSpecReader.AxisNames.ContainsKey(upAxis) || !CharacterSpecReader.AxisNames.ContainsKey(forwardAxis))
        {
            throw new RigException($"Unknown axis name '{upAxis}' or '{forwardAxis}' (expected one of {string.Join(", ", CharacterSpecReader.AxisNames.Keys)}).");
        }

        Model = model;
        JointNodes = [.. jointNodes];
        UpAxis = upAxis;
        ForwardAxis = forwardAxis;
    }

    /// <summary>The glTF the rig was read from (SharpGLTF's schema).</summary>
    public GltfModel Model { get; }

    /// <summary>For each rig joint, the index of its glTF node.</summary>
    public IReadOnlyList<int> JointNodes { get; }

    /// <summary>The glTF scene's direction that is the character's up ("+Y" unless the spec said otherwise).</summary>
    public string UpAxis { get; }

    /// <summary>The glTF scene's direction the character faces ("+Z" unless the spec said otherwise).</summary>
    public string ForwardAxis { get; }

    /// <summary>
    /// For each joint, whether the bone from its rig parent to it is part of the character's body, to be kept out of
    /// the level: true when the parent carries skinned vertices (the bone is that body part) and the parent is the
    /// joint's ancestor in the file (not a root bone hung from the rig's root, such as an IK target). Empty: every bone.
    /// </summary>
    public IReadOnlyList<bool> BodyBones { get; init; } = [];

    /// <summary>
    /// For each joint, points of the skinned mesh around its bone, in the bone's rest frame (metres): of the vertices
    /// skinned mostly to it, the farthest along each of 14 directions (the bone frame's axes and diagonals). A limb
    /// bone's points are kept out of the level (<see cref="Animation.BodyCollision"/>): a toe or heel reaches beyond
    /// the segments between joints. Empty: none.
    /// </summary>
    internal IReadOnlyList<Vector3[]> SkinProbes { get; init; } = [];

    /// <summary>
    /// For each joint, points spread over the skinned mesh around its bone (<see cref="MeshDefaults.Spread"/>), in the
    /// bone's rest frame (metres): the skin of a bone that carries no limb (a head, a tail's tip) is kept out of the
    /// level by these as well as by <see cref="SkinProbes"/>, since a level's edge may enter its face between the
    /// extremes. Empty: none.
    /// </summary>
    internal IReadOnlyList<Vector3[]> SpreadProbes { get; init; } = [];

    /// <summary>
    /// For each joint, points of the skinned mesh weighted to it and to other bones (a knee's back, carried partly by
    /// the thigh), with each bone's share (<see cref="SkinBlend"/>): of the vertices skinned mostly to it with at most
    /// <see cref="GltfSkeleton.BlendedShare"/> of their weight, the farthest along the 14 directions of
    /// <see cref="SkinProbes"/> in each of <see cref="MeshDefaults.BlendSlices"/> slices along the bone. Posed, they lie where linear blend skinning puts them, not where the bone alone would
    /// (a deep knee bend folds them several centimetres off either bone). Empty: none.
    /// </summary>
    internal IReadOnlyList<SkinBlend[][]> BlendProbes { get; init; } = [];

    /// <summary>For each joint, whether its radius was derived from the skinned mesh (so a saved spec leaves it out and derives it again).</summary>
    internal IReadOnlyList<bool> DerivedRadii { get; init; } = [];
}
