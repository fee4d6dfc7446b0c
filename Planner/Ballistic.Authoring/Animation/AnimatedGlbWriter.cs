using System.Numerics;
using Ballistic.Authoring.Gltf;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Gltf;
using Ballistic.Planner.IO;
using Ballistic.Planner.Rigs;
using SharpGLTF.Schema2;
using SharpGLTF.Transforms;

namespace Ballistic.Authoring.Animation;

/// <summary>
/// Writes a character and its animation (a path of moves: jumps and walks) as one animated, skinned glTF binary
/// (Godot and Blender import it), through SharpGLTF. A character loaded from a user's glTF (<see cref="CharacterModel.Source"/> set) is
/// written as that file, read again through the same checks: its scenes, node hierarchy, skinned meshes, materials,
/// textures and images (embedded), skins and clips, with one clip added, first in the list (the clip Blender makes the
/// armature's action), whose channels target the original bone nodes: the rotation of every bone
/// that moves, relative to its glTF parent (so anchor nodes between bones keep their place), and the translation and
/// rotation of every root bone, relative to its non-bone ancestors' transforms (an <c>Armature</c> rotated or scaled
/// stays as it is). A character built in code is written as an <c>Armature</c> node holding the joint hierarchy
/// (node names = joint names), a mesh of one box per bone skinned rigidly to it (the boxes of each effector bone and
/// the bones below it cut flat at the limb's contact point, a sole), and one clip whose channels are the
/// root joint's translation and rotation (its world placement on the jump arcs and walk paths) and every joint's
/// local rotation. Either way the clip is keyed at each of the animation's frames (flights, walks and the stances
/// between them alike) with linear interpolation; world frame Y up, metres, seconds. The same input gives the same bytes.
/// </summary>
public static class AnimatedGlbWriter
{
    /// <summary>The animation as GLB bytes, with clip name <paramref name="clip"/>.</summary>
    /// <exception cref="GltfException">The character's source glTF cannot be copied (an image or buffer is unreadable).</exception>
    public static byte[] ToBytes(JumpAnimation animation, string clip = "jumps")
    {
        ArgumentNullException.ThrowIfNull(animation);
        return Build(animation.Model, animation, clip);
    }

    /// <summary>
    /// The character alone as a skinned GLB without animation: for a character loaded from a glTF, that file made
    /// self-contained; otherwise the bone boxes in the rest pose (every angle 0).
    /// </summary>
    /// <exception cref="GltfException">The character's source glTF cannot be copied (an image or buffer is unreadable).</exception>
    public static byte[] ToBytes(CharacterModel model)
    {
        ArgumentNullException.ThrowIfNull(model);
        return Build(model, null, "");
    }

    private static byte[] Build(CharacterModel model, JumpAnimation? animation, string clip)
    {
        if (model.Source is CharacterSource source)
        {
            return BuildFromSource(model, source, animation, clip);
        }

        Rig rig = model.Rig;
        int jointCount = rig.Joints.Count;
        ModelRoot root = GltfWrite.Create();
        Scene scene = root.UseScene(model.Name);

        // Nodes: Armature, then one node per joint (node index = joint index + 1), then the skinned mesh node.
        var bindPositions = new Vector3[jointCount];
        var bindRotations = new Quaternion[jointCount];
        // Bind pose = rest pose (every angle 0), so that a reader applying the limb spec's angles gets this rig back.
        float[] rest = new float[rig.DofCount];
        rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), rest, bindPositions, bindRotations);
        Node armature = scene.CreateNode("Armature");
        var nodes = new Node[jointCount];
        for (int j = 0; j < jointCount; j++)
        {
            Joint joint = rig.Joints[j];
            nodes[j] = (j == 0 ? armature : nodes[joint.Parent]).CreateNode(joint.Name);
            nodes[j].LocalTransform = new AffineTransform(null, j == 0 ? bindRotations[0] : rig.LocalRotation(j, rest), j == 0 ? bindPositions[0] : joint.Offset);
        }

        // Skinned mesh: the bone boxes (BoneBoxes: the body the animator checks against the level), each vertex bound to one joint.
        BoneBoxes boxes = BoneBoxes.Of(model);
        Vector3[] positions = [.. boxes.Positions];
        byte[] joints = new byte[positions.Length * 4];
        float[] weights = new float[positions.Length * 4];
        for (int v = 0; v < positions.Length; v++)
        {
            joints[4 * v] = (byte)boxes.Joints[v];
            weights[4 * v] = 1f;
        }

        Material material = GltfWrite.Material(root, $"{model.Name} bones", new Vector4(0.85f, 0.82f, 0.74f, 1f), roughness: 0.7f, doubleSided: true);

        Mesh mesh = root.CreateMesh(model.Name);
        MeshPrimitive primitive = mesh.CreatePrimitive();
        primitive.SetVertexAccessor("POSITION", GltfWrite.Vectors(root, positions));
        primitive.SetVertexAccessor("JOINTS_0", GltfWrite.Joints(root, joints));
        primitive.SetVertexAccessor("WEIGHTS_0", GltfWrite.Floats(root, weights, DimensionType.VEC4, vertex: true));
        primitive.SetIndexAccessor(GltfWrite.Indices(root, [.. boxes.Indices]));
        primitive.Material = material;

        var bound = new (Node Joint, Matrix4x4 InverseBind)[jointCount];
        for (int j = 0; j < jointCount; j++)
        {
            Matrix4x4 world = Matrix4x4.CreateFromQuaternion(bindRotations[j]) * Matrix4x4.CreateTranslation(bindPositions[j]);
            Matrix4x4.Invert(world, out Matrix4x4 inverse);

            // glTF requires the affine row of an inverse bind matrix to be exactly (0, 0, 0, 1).
            (inverse.M14, inverse.M24, inverse.M34, inverse.M44) = (0f, 0f, 0f, 1f);
            bound[j] = (nodes[j], inverse);
        }

        Skin skin = root.CreateSkin(model.Name);
        skin.BindJoints(bound);
        skin.Skeleton = nodes[0];
        Node meshNode = scene.CreateNode($"{model.Name}_mesh");
        meshNode.Mesh = mesh;
        meshNode.Skin = skin;
        if (animation is null)
        {
            return GltfWrite.Glb(root);
        }

        // The clip.
        int frames = animation.Frames.Count;
        float[] times = new float[frames];
        var rootTranslations = new Vector3[frames];
        var rotations = new Quaternion[jointCount][];
        for (int j = 0; j < jointCount; j++)
        {
            rotations[j] = new Quaternion[frames];
        }

        for (int f = 0; f < frames; f++)
        {
            AnimationFrame frame = animation.Frames[f];
            times[f] = frame.Time;
            rootTranslations[f] = frame.Root.ToWorld(rig.RootOffset + rig.Joints[0].Offset);
            for (int j = 0; j < jointCount; j++)
            {
                rotations[j][f] = j == 0 ? Quaternion.Normalize(frame.Root.Rotation * rig.LocalRotation(0, frame.Angles)) : rig.LocalRotation(j, frame.Angles);
            }
        }

        EnsureShortestPaths(rotations);
        SharpGLTF.Schema2.Animation written = root.CreateAnimation(clip);
        written.CreateTranslationChannel(nodes[0], Keys(times, rootTranslations), true);
        for (int j = 0; j < jointCount; j++)
        {
            if (j == 0 || rig.DofsOf(j) > 0)
            {
                written.CreateRotationChannel(nodes[j], Keys(times, rotations[j]), true);
            }
        }

        return GltfWrite.Glb(root);
    }

    /// <summary>
    /// The user's glTF with the clip added first in its list of animations: channels on the original bone nodes; the
    /// file made self-contained (buffers merged, images embedded) and the generator named beside the original's. A rig
    /// that loaded repaired is read again as repaired: SharpGLTF's repairing mode rescales skin weights that do not sum
    /// to one (assimp writes 0.999999), and the accessors get bounds that hold.
    /// </summary>
    private static byte[] BuildFromSource(CharacterModel model, CharacterSource source, JumpAnimation? animation, string clip)
    {
        GltfModel original = source.Model;
        ModelRoot root = original.ReadAgain(animation is null ? null : clip);
        if (root.ExtensionsUsed.Contains("EXT_meshopt_compression"))
        {
            throw new GltfException($"{MessageText.Printable(original.Name)} uses EXT_meshopt_compression; export it without compression.");
        }

        string? generator = root.Asset.Generator;
        root.Asset.Generator = string.IsNullOrWhiteSpace(generator) || generator == GltfWrite.Generator ? GltfWrite.Generator : $"{GltfWrite.Generator} (from {generator})";
        if (original.Repaired is not null)
        {
            // Read as repaired, without the accessors' stale bounds: written with bounds that hold.
            foreach (Accessor accessor in root.LogicalAccessors)
            {
                accessor.UpdateBounds();
            }
        }

        if (animation is null)
        {
            return GltfWrite.Glb(root);
        }

        Rig rig = model.Rig;
        int jointCount = rig.Joints.Count;
        int[] parentNode = original.NodeParents();
        Matrix4x4[] world = original.WorldTransforms();
        var jointOfNode = new Dictionary<int, int>();
        for (int j = 0; j < jointCount; j++)
        {
            jointOfNode[source.JointNodes[j]] = j;
        }

        // Per joint: a root bone (no bone above it in the file) gets translation and rotation relative to its
        // parent node's fixed world transform; any other bone a rotation relative to its parent node, whose world
        // rotation is its rig parent's times the fixed rotation of the nodes in between (anchors).
        var isRoot = new bool[jointCount];
        var between = new Quaternion[jointCount];
        var parentRotation = new Quaternion[jointCount];
        var parentPosition = new Vector3[jointCount];
        var parentScale = new float[jointCount];
        for (int j = 0; j < jointCount; j++)
        {
            int node = source.JointNodes[j];
            int parent = parentNode[node];
            int boneAbove = parent;
            while (boneAbove >= 0 && !jointOfNode.ContainsKey(boneAbove))
            {
                boneAbove = parentNode[boneAbove];
            }

            isRoot[j] = boneAbove < 0;
            Matrix4x4 parentWorld = parent >= 0 ? world[parent] : Matrix4x4.Identity;
            if (!Rigid(parentWorld, out parentScale[j], out parentRotation[j]))
            {
                throw new GltfException($"{MessageText.Printable(original.Name)}: the parent of bone '{rig.Joints[j].Name}' is not a rotation with a uniform scale.");
            }

            parentPosition[j] = parentWorld.Translation;
            if (!isRoot[j])
            {
                Rigid(world[boneAbove], out _, out Quaternion above);
                between[j] = Quaternion.Normalize(Quaternion.Conjugate(above) * parentRotation[j]);
            }

            // Animated nodes must carry translation, rotation and scale rather than a matrix.
            Node written = root.LogicalNodes[node];
            if (written.LocalTransform.IsMatrix && (isRoot[j] || rig.DofsOf(j) > 0))
            {
                Matrix4x4 local = original.LocalTransform(original.Root.LogicalNodes[node]);
                Rigid(local, out float scale, out Quaternion rotation);
                written.LocalTransform = new AffineTransform(new Vector3(scale), rotation, local.Translation);
            }
        }

        int frames = animation.Frames.Count;
        float[] times = new float[frames];
        var translations = new Vector3[jointCount][];
        var rotations = new Quaternion[jointCount][];
        for (int j = 0; j < jointCount; j++)
        {
            translations[j] = new Vector3[frames];
            rotations[j] = new Quaternion[frames];
        }

        var positions = new Vector3[jointCount];
        var worldRotations = new Quaternion[jointCount];
        for (int f = 0; f < frames; f++)
        {
            AnimationFrame frame = animation.Frames[f];
            times[f] = frame.Time;
            rig.Solve(frame.Root, frame.Angles, positions, worldRotations);
            for (int j = 0; j < jointCount; j++)
            {
                Quaternion local;
                if (isRoot[j])
                {
                    Quaternion inverse = Quaternion.Conjugate(parentRotation[j]);
                    translations[j][f] = Vector3.Transform(positions[j] - parentPosition[j], inverse) / parentScale[j];
                    local = inverse * worldRotations[j];
                }
                else
                {
                    local = Quaternion.Conjugate(worldRotations[rig.Joints[j].Parent] * between[j]) * worldRotations[j];
                }

                rotations[j][f] = Quaternion.Normalize(local);
            }
        }

        EnsureShortestPaths(rotations);
        SharpGLTF.Schema2.Animation ours = root.LogicalAnimations[0]; // the one ReadAgain put first: the clip importers pick (Blender's action)
        for (int j = 0; j < jointCount; j++)
        {
            Node node = root.LogicalNodes[source.JointNodes[j]];
            if (isRoot[j])
            {
                ours.CreateTranslationChannel(node, Keys(times, translations[j]), true);
            }

            if (isRoot[j] || rig.DofsOf(j) > 0)
            {
                ours.CreateRotationChannel(node, Keys(times, rotations[j]), true);
            }
        }

        return GltfWrite.Glb(root);
    }

    /// <summary>The keyframes (time, value) of a channel.</summary>
    /// <exception cref="GltfException">The frame times do not increase.</exception>
    private static Dictionary<float, T> Keys<T>(float[] times, T[] values)
    {
        var keys = new Dictionary<float, T>(times.Length);
        for (int f = 0; f < times.Length; f++)
        {
            if (f > 0 && !(times[f] > times[f - 1]))
            {
                throw new GltfException($"Cannot write the clip: frame {f}'s time {times[f]} s does not follow frame {f - 1}'s ({times[f - 1]} s).");
            }

            keys.Add(times[f], values[f]);
        }

        return keys;
    }

    /// <summary>Splits a row-vector transform into a uniform scale and a rotation; false when it is neither.</summary>
    private static bool Rigid(Matrix4x4 m, out float scale, out Quaternion rotation) => Rotations.TryRigid(m, out scale, out rotation);

    /// <summary>Writes the animation to <paramref name="path"/>.</summary>
    /// <exception cref="GltfException">The character's source glTF cannot be copied (an image or buffer is unreadable).</exception>
    public static void Save(JumpAnimation animation, string path, string clip = "jumps") => OutputFile.Write(path, ToBytes(animation, clip));

    /// <summary>Flips quaternion keys whose dot product with the previous key is negative, so slerp takes the short way.</summary>
    private static void EnsureShortestPaths(Quaternion[][] rotations)
    {
        foreach (Quaternion[] keys in rotations)
        {
            for (int f = 1; f < keys.Length; f++)
            {
                if (Quaternion.Dot(keys[f], keys[f - 1]) < 0f)
                {
                    keys[f] = -keys[f];
                }
            }
        }
    }
}
