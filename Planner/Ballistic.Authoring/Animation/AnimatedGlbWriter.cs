using System.Numerics;
using System.Text.Json.Nodes;
using Ballistic.Authoring.Gltf;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Gltf;
using Ballistic.Planner.IO;
using Ballistic.Planner.Rigs;

namespace Ballistic.Authoring.Animation;

/// <summary>
/// Writes a character and its animation (a path of moves: jumps and walks) as one animated, skinned glTF binary
/// (Godot and Blender import it). A character loaded from a user's glTF (<see cref="CharacterModel.Source"/> set) is
/// written as that file: its scenes, node hierarchy, skinned meshes, materials, textures and images (embedded),
/// skins and clips, with one clip added whose channels target the original bone nodes: the rotation of every bone
/// that moves, relative to its glTF parent (so anchor nodes between bones keep their place), and the translation and
/// rotation of every root bone, relative to its non-bone ancestors' transforms (an <c>Armature</c> rotated or scaled
/// stays as it is). A character built in code is written as an <c>Armature</c> node holding the joint hierarchy
/// (node names = joint names), a mesh of one box per bone skinned rigidly to it (the boxes of each effector bone and
/// the bones below it cut flat at the limb's contact point, a sole), and one clip whose channels are the
/// root joint's translation and rotation (its world placement on the jump arcs and walk paths) and every joint's
/// local rotation. Either way the clip is keyed at each of the animation's frames (flights, walks and the stances
/// between them alike) with linear interpolation; world frame Y up, metres, seconds.
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
        var writer = new GlbWriter();

        // Nodes: Armature, then one node per joint (node index = joint index + 1), then the skinned mesh node.
        var bindPositions = new Vector3[jointCount];
        var bindRotations = new Quaternion[jointCount];
        // Bind pose = rest pose (every angle 0), so that a reader applying the limb spec's angles gets this rig back.
        float[] rest = new float[rig.DofCount];
        rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), rest, bindPositions, bindRotations);
        var armatureChildren = new JsonArray();
        writer.Add("nodes", new JsonObject { ["name"] = "Armature", ["children"] = armatureChildren });
        for (int j = 0; j < jointCount; j++)
        {
            Joint joint = rig.Joints[j];
            Vector3 translation = j == 0 ? bindPositions[0] : joint.Offset;
            Quaternion rotation = j == 0 ? bindRotations[0] : rig.LocalRotation(j, rest);
            var node = new JsonObject
            {
                ["name"] = joint.Name,
                ["translation"] = Array(translation),
                ["rotation"] = Array(rotation),
            };
            var children = new JsonArray();
            for (int c = 0; c < jointCount; c++)
            {
                if (rig.Joints[c].Parent == j)
                {
                    children.Add(c + 1);
                }
            }

            if (children.Count > 0)
            {
                node["children"] = children;
            }

            writer.Add("nodes", node);
            if (j == 0)
            {
                armatureChildren.Add(1);
            }
        }

        // Skinned mesh: the bone boxes (BoneBoxes: the body the animator checks against the level), each vertex bound to one joint.
        BoneBoxes boxes = BoneBoxes.Of(model);
        Vector3[] positions = [.. boxes.Positions];
        var joints = new List<byte>();
        foreach (int joint in boxes.Joints)
        {
            joints.AddRange([(byte)joint, 0, 0, 0]);
        }

        int[] indices = [.. boxes.Indices];

        int material = writer.Add("materials", new JsonObject
        {
            ["name"] = $"{model.Name} bones",
            ["pbrMetallicRoughness"] = new JsonObject { ["baseColorFactor"] = new JsonArray(0.85f, 0.82f, 0.74f, 1f), ["metallicFactor"] = 0f, ["roughnessFactor"] = 0.7f },
            ["doubleSided"] = true,
        });
        float[] weights = new float[positions.Length * 4];
        for (int v = 0; v < positions.Length; v++)
        {
            weights[4 * v] = 1f;
        }

        int positionAccessor = writer.AddVector3(positions);
        int jointAccessor = writer.AddJoints([.. joints]);
        int weightAccessor = writer.AddFloats(weights, "VEC4", 4, 34962);
        int indexAccessor = writer.AddIndices(indices);
        int mesh = writer.Add("meshes", new JsonObject
        {
            ["name"] = model.Name,
            ["primitives"] = new JsonArray(new JsonObject
            {
                ["attributes"] = new JsonObject { ["POSITION"] = positionAccessor, ["JOINTS_0"] = jointAccessor, ["WEIGHTS_0"] = weightAccessor },
                ["indices"] = indexAccessor,
                ["material"] = material,
            }),
        });

        float[] inverseBind = new float[jointCount * 16];
        for (int j = 0; j < jointCount; j++)
        {
            Matrix4x4 world = Matrix4x4.CreateFromQuaternion(bindRotations[j]) * Matrix4x4.CreateTranslation(bindPositions[j]);
            Matrix4x4.Invert(world, out Matrix4x4 inverse);

            // glTF requires the affine row of an inverse bind matrix to be exactly (0, 0, 0, 1).
            inverse.M14 = 0f;
            inverse.M24 = 0f;
            inverse.M34 = 0f;
            inverse.M44 = 1f;
            Write(inverseBind.AsSpan(16 * j), inverse);
        }

        int inverseBindAccessor = writer.AddFloats(inverseBind, "MAT4", 16);
        var skinJoints = new JsonArray();
        for (int j = 0; j < jointCount; j++)
        {
            skinJoints.Add(j + 1);
        }

        int skin = writer.Add("skins", new JsonObject { ["name"] = model.Name, ["joints"] = skinJoints, ["inverseBindMatrices"] = inverseBindAccessor, ["skeleton"] = 1 });
        int meshNode = writer.Add("nodes", new JsonObject { ["name"] = $"{model.Name}_mesh", ["mesh"] = mesh, ["skin"] = skin });

        writer.Root["scene"] = writer.Add("scenes", new JsonObject { ["name"] = model.Name, ["nodes"] = new JsonArray(0, meshNode) });
        if (animation is null)
        {
            return writer.ToBytes();
        }

        // The clip.
        int frames = animation.Frames.Count;
        float[] times = new float[frames];
        var rootTranslations = new Vector3[frames];
        var rotations = new float[jointCount][];
        for (int j = 0; j < jointCount; j++)
        {
            rotations[j] = new float[frames * 4];
        }

        for (int f = 0; f < frames; f++)
        {
            AnimationFrame frame = animation.Frames[f];
            times[f] = frame.Time;
            rootTranslations[f] = frame.Root.ToWorld(rig.RootOffset + rig.Joints[0].Offset);
            for (int j = 0; j < jointCount; j++)
            {
                Quaternion r = j == 0 ? Quaternion.Normalize(frame.Root.Rotation * rig.LocalRotation(0, frame.Angles)) : rig.LocalRotation(j, frame.Angles);
                rotations[j][4 * f] = r.X;
                rotations[j][(4 * f) + 1] = r.Y;
                rotations[j][(4 * f) + 2] = r.Z;
                rotations[j][(4 * f) + 3] = r.W;
            }
        }

        EnsureShortestPaths(rotations, frames);
        int input = writer.AddFloats(times, "SCALAR", 1);
        var samplers = new JsonArray();
        var channels = new JsonArray();
        samplers.Add(new JsonObject { ["input"] = input, ["output"] = writer.AddVector3(rootTranslations, target: null), ["interpolation"] = "LINEAR" });
        channels.Add(new JsonObject { ["sampler"] = 0, ["target"] = new JsonObject { ["node"] = 1, ["path"] = "translation" } });
        for (int j = 0; j < jointCount; j++)
        {
            if (j > 0 && rig.DofsOf(j) == 0)
            {
                continue;
            }

            samplers.Add(new JsonObject { ["input"] = input, ["output"] = writer.AddFloats(rotations[j], "VEC4", 4), ["interpolation"] = "LINEAR" });
            channels.Add(new JsonObject { ["sampler"] = samplers.Count - 1, ["target"] = new JsonObject { ["node"] = j + 1, ["path"] = "rotation" } });
        }

        writer.AddFirst("animations", new JsonObject { ["name"] = clip, ["samplers"] = samplers, ["channels"] = channels }); // first: the clip importers pick (Blender's action)
        return writer.ToBytes();
    }

    /// <summary>The user's glTF with the clip added: channels on the original bone nodes.</summary>
    private static byte[] BuildFromSource(CharacterModel model, CharacterSource source, JumpAnimation? animation, string clip)
    {
        GlbWriter writer = GlbWriter.From(source.Document);
        if (animation is null)
        {
            return writer.ToBytes();
        }

        Rig rig = model.Rig;
        int jointCount = rig.Joints.Count;
        GltfDocument document = source.Document;
        int[] parentNode = document.NodeParents();
        Matrix4x4[] world = document.WorldTransforms();
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
        JsonArray nodes = (JsonArray)writer.Root["nodes"]!;
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
                throw new GltfException($"{document.Name}: the parent of bone '{rig.Joints[j].Name}' is not a rotation with a uniform scale.");
            }

            parentPosition[j] = parentWorld.Translation;
            if (!isRoot[j])
            {
                Rigid(world[boneAbove], out _, out Quaternion above);
                between[j] = Quaternion.Normalize(Quaternion.Conjugate(above) * parentRotation[j]);
            }

            // Animated nodes must carry translation, rotation and scale rather than a matrix.
            if (nodes[node] is JsonObject json && json["matrix"] is not null && (isRoot[j] || rig.DofsOf(j) > 0))
            {
                Matrix4x4 local = document.LocalTransform(json);
                Rigid(local, out float scale, out Quaternion rotation);
                json.Remove("matrix");
                json["translation"] = Array(local.Translation);
                json["rotation"] = Array(rotation);
                json["scale"] = new JsonArray(scale, scale, scale);
            }
        }

        int frames = animation.Frames.Count;
        float[] times = new float[frames];
        var translations = new Vector3[jointCount][];
        var rotations = new float[jointCount][];
        for (int j = 0; j < jointCount; j++)
        {
            translations[j] = new Vector3[frames];
            rotations[j] = new float[frames * 4];
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

                local = Quaternion.Normalize(local);
                rotations[j][4 * f] = local.X;
                rotations[j][(4 * f) + 1] = local.Y;
                rotations[j][(4 * f) + 2] = local.Z;
                rotations[j][(4 * f) + 3] = local.W;
            }
        }

        EnsureShortestPaths(rotations, frames);
        int input = writer.AddFloats(times, "SCALAR", 1);
        var samplers = new JsonArray();
        var channels = new JsonArray();
        for (int j = 0; j < jointCount; j++)
        {
            int node = source.JointNodes[j];
            if (isRoot[j])
            {
                samplers.Add(new JsonObject { ["input"] = input, ["output"] = writer.AddVector3(translations[j], target: null), ["interpolation"] = "LINEAR" });
                channels.Add(new JsonObject { ["sampler"] = samplers.Count - 1, ["target"] = new JsonObject { ["node"] = node, ["path"] = "translation" } });
            }

            if (isRoot[j] || rig.DofsOf(j) > 0)
            {
                samplers.Add(new JsonObject { ["input"] = input, ["output"] = writer.AddFloats(rotations[j], "VEC4", 4), ["interpolation"] = "LINEAR" });
                channels.Add(new JsonObject { ["sampler"] = samplers.Count - 1, ["target"] = new JsonObject { ["node"] = node, ["path"] = "rotation" } });
            }
        }

        writer.AddFirst("animations", new JsonObject { ["name"] = clip, ["samplers"] = samplers, ["channels"] = channels }); // first: the clip importers pick (Blender's action)
        return writer.ToBytes();
    }

    /// <summary>Splits a row-vector transform into a uniform scale and a rotation; false when it is neither.</summary>
    private static bool Rigid(Matrix4x4 m, out float scale, out Quaternion rotation) => Rotations.TryRigid(m, out scale, out rotation);

    /// <summary>Writes the animation to <paramref name="path"/>.</summary>
    /// <exception cref="GltfException">The character's source glTF cannot be copied (an image or buffer is unreadable).</exception>
    public static void Save(JumpAnimation animation, string path, string clip = "jumps") => OutputFile.Write(path, ToBytes(animation, clip));

    /// <summary>Flips quaternion keys whose dot product with the previous key is negative, so slerp takes the short way.</summary>
    private static void EnsureShortestPaths(float[][] rotations, int frames)
    {
        foreach (float[] keys in rotations)
        {
            for (int f = 1; f < frames; f++)
            {
                float dot = (keys[4 * f] * keys[4 * (f - 1)]) + (keys[(4 * f) + 1] * keys[(4 * (f - 1)) + 1]) + (keys[(4 * f) + 2] * keys[(4 * (f - 1)) + 2]) + (keys[(4 * f) + 3] * keys[(4 * (f - 1)) + 3]);
                if (dot < 0f)
                {
                    for (int k = 0; k < 4; k++)
                    {
                        keys[(4 * f) + k] = -keys[(4 * f) + k];
                    }
                }
            }
        }
    }

    private static JsonArray Array(Vector3 v) => new(v.X, v.Y, v.Z);

    private static JsonArray Array(Quaternion q) => new(q.X, q.Y, q.Z, q.W);

    private static void Write(Span<float> target, Matrix4x4 m)
    {
        // System.Numerics (row vectors) written row by row is glTF's column-major order.
        float[] values = [m.M11, m.M12, m.M13, m.M14, m.M21, m.M22, m.M23, m.M24, m.M31, m.M32, m.M33, m.M34, m.M41, m.M42, m.M43, m.M44];
        values.CopyTo(target);
    }
}
