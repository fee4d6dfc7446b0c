using System.Numerics;
using System.Text.Json.Nodes;
using Ballistic.Planner.Gltf;

namespace Ballistic.Planner.Rigs;

/// <summary>
/// The bones of a glTF skin as a rig skeleton in Ballistic's frame (Y up, +Z forward, metres), and the skin's
/// vertices grouped by the bone that carries most of their weight. A bone's rig parent is its nearest ancestor
/// node that is also a bone; the nodes in between (anchors, empties) and every ancestor's rotation and uniform scale
/// are folded into its rest offset and rotation. When the skin has several root bones, the one with the most limb
/// bones below it is the rig's root and the others hang from it rigidly.
/// </summary>
internal sealed class GltfSkeleton
{
    private GltfSkeleton(int[] nodes, string[] names, int[] parents, Vector3[] offsets, Quaternion[] restRotations, Vector3[] restPositions, Quaternion[] restWorldRotations, List<Vector3>[] points)
    {
        Nodes = nodes;
        Names = names;
        Parents = parents;
        Offsets = offsets;
        RestRotations = restRotations;
        RestPositions = restPositions;
        RestWorldRotations = restWorldRotations;
        Points = points;
    }

    /// <summary>The glTF node of each rig joint, parents before children, the root first.</summary>
    public int[] Nodes { get; }

    /// <summary>Bone names (unique).</summary>
    public string[] Names { get; }

    /// <summary>Rig parent of each joint (−1 for the root).</summary>
    public int[] Parents { get; }

    /// <summary>Rest offset of each joint in its parent's frame, metres (the root's is zero).</summary>
    public Vector3[] Offsets { get; }

    /// <summary>Rest rotation of each joint relative to its parent (the root's relative to Ballistic's world).</summary>
    public Quaternion[] RestRotations { get; }

    /// <summary>Each joint's rest position in Ballistic's frame (the glTF scene rotated by the up/forward axes), metres.</summary>
    public Vector3[] RestPositions { get; }

    /// <summary>Each joint's rest rotation in Ballistic's frame.</summary>
    public Quaternion[] RestWorldRotations { get; }

    /// <summary>For each joint, the skinned vertices whose largest weight is on it, in its rest frame, metres.</summary>
    public List<Vector3>[] Points { get; }

    /// <summary>Reads skin 0 of <paramref name="document"/>.</summary>
    /// <param name="document">The rigged glTF.</param>
    /// <param name="axes">Rotation from the glTF scene into Ballistic's frame (from the spec's up and forward axes).</param>
    /// <param name="limbBones">Names of the limbs' bones, to choose the root among several root bones.</param>
    /// <exception cref="RigException">There is no skin, a bone is scaled non-uniformly or mirrored, or bone names repeat.</exception>
    /// <exception cref="GltfException">The glTF's hierarchy, skin or meshes are malformed.</exception>
    public static GltfSkeleton Read(GltfDocument document, Quaternion axes, IReadOnlyCollection<string> limbBones)
    {
        string file = document.Name;
        JsonArray skins = document.Array("skins");
        if (skins.Count == 0)
        {
            throw new RigException($"{file} has no skin: a character needs a rigged (skinned) mesh.");
        }

        JsonArray nodes = document.Array("nodes");
        int[] skinJoints = SkinJoints(document, 0);
        if (skinJoints.Length == 0)
        {
            throw new RigException($"{file}: skin 0 has no joints.");
        }

        int[] parentNode = document.NodeParents();
        Matrix4x4[] world = document.WorldTransforms();
        var isJoint = new HashSet<int>(skinJoints);
        string NodeName(int node) => nodes[node]?["name"] is JsonValue v && v.TryGetValue(out string? s) && s.Length > 0 ? s : $"node {node}";
        int BoneAncestor(int node)
        {
            for (int p = parentNode[node]; p >= 0; p = parentNode[p])
            {
                if (isJoint.Contains(p))
                {
                    return p;
                }
            }

            return -1;
        }

        var byName = new Dictionary<string, int>(StringComparer.Ordinal);
        foreach (int j in skinJoints)
        {
            if (!byName.TryAdd(NodeName(j), j))
            {
                throw new RigException($"{file}: two bones are called '{NodeName(j)}' (nodes {byName[NodeName(j)]} and {j}); bone names must be unique.");
            }
        }

        // The root: among the skin's root bones, the one with the most limb bones below it, then the most bones.
        int[] roots = [.. skinJoints.Where(j => BoneAncestor(j) < 0)];
        int TopOf(int node)
        {
            while (BoneAncestor(node) >= 0)
            {
                node = BoneAncestor(node);
            }

            return node;
        }

        int main = roots
            .OrderByDescending(r => limbBones.Count(b => byName.TryGetValue(b, out int n) && TopOf(n) == r))
            .ThenByDescending(r => skinJoints.Count(j => TopOf(j) == r))
            .First();
        int RigParent(int node) => node == main ? -1 : BoneAncestor(node) is int a && a >= 0 ? a : main;

        // Parents before children: the skin's own order when it already is, else breadth-first from the root.
        var order = new List<int>();
        var placed = new HashSet<int>();
        bool parentFirst = skinJoints[0] == main;
        foreach (int j in skinJoints)
        {
            parentFirst &= j == main || placed.Contains(RigParent(j));
            placed.Add(j);
        }

        if (parentFirst)
        {
            order.AddRange(skinJoints);
        }
        else
        {
            var queue = new Queue<int>([main]);
            while (queue.Count > 0)
            {
                int node = queue.Dequeue();
                order.Add(node);
                foreach (int child in skinJoints.Where(c => c != main && RigParent(c) == node))
                {
                    queue.Enqueue(child);
                }
            }
        }

        // Rest frames in Ballistic's frame: rotation and position without the (uniform) scale.
        int count = order.Count;
        var positions = new Vector3[count];
        var rotations = new Quaternion[count];
        for (int i = 0; i < count; i++)
        {
            int node = order[i];
            CheckBoneScale(document, nodes, parentNode, isJoint, node, NodeName);
            if (!TryRigid(world[node], out _, out Quaternion rotation))
            {
                throw new RigException($"{file}: bone '{NodeName(node)}' with its parents is not a rotation with a uniform scale (sheared); apply the transforms before exporting.");
            }

            positions[i] = Vector3.Transform(world[node].Translation, axes);
            rotations[i] = Quaternion.Normalize(axes * rotation);
        }

        var index = new Dictionary<int, int>();
        for (int i = 0; i < count; i++)
        {
            index[order[i]] = i;
        }

        int[] parents = [.. order.Select(n => RigParent(n) is int p && p >= 0 ? index[p] : -1)];
        var offsets = new Vector3[count];
        var rests = new Quaternion[count];
        for (int i = 0; i < count; i++)
        {
            if (parents[i] < 0)
            {
                rests[i] = rotations[i];
                continue;
            }

            Quaternion inverse = Quaternion.Conjugate(rotations[parents[i]]);
            offsets[i] = Vector3.Transform(positions[i] - positions[parents[i]], inverse);
            rests[i] = Quaternion.Normalize(inverse * rotations[i]);
        }

        List<Vector3>[] points = SkinnedPoints(document, world, index, axes, positions, rotations);
        return new GltfSkeleton([.. order], [.. order.Select(NodeName)], parents, offsets, rests, positions, rotations, points);
    }

    /// <summary>
    /// Splits a transform into a uniform scale and a rotation (row-vector matrix); false when it is sheared,
    /// scaled non-uniformly, mirrored or degenerate.
    /// </summary>
    internal static bool TryRigid(Matrix4x4 m, out float scale, out Quaternion rotation)
    {
        var x = new Vector3(m.M11, m.M12, m.M13);
        var y = new Vector3(m.M21, m.M22, m.M23);
        var z = new Vector3(m.M31, m.M32, m.M33);
        scale = (x.Length() + y.Length() + z.Length()) / 3f;
        rotation = Quaternion.Identity;
        if (!(scale > 1e-8f) || !float.IsFinite(scale))
        {
            return false;
        }

        float tolerance = 1e-3f;
        if (MathF.Abs(x.Length() - scale) > tolerance * scale || MathF.Abs(y.Length() - scale) > tolerance * scale || MathF.Abs(z.Length() - scale) > tolerance * scale
            || MathF.Abs(Vector3.Dot(x, y)) > tolerance * scale * scale || MathF.Abs(Vector3.Dot(y, z)) > tolerance * scale * scale || MathF.Abs(Vector3.Dot(x, z)) > tolerance * scale * scale
            || Vector3.Dot(Vector3.Cross(x, y), z) <= 0f)
        {
            return false;
        }

        x /= scale;
        y /= scale;
        z /= scale;
        var pure = new Matrix4x4(x.X, x.Y, x.Z, 0f, y.X, y.Y, y.Z, 0f, z.X, z.Y, z.Z, 0f, 0f, 0f, 0f, 1f);
        rotation = Quaternion.Normalize(Quaternion.CreateFromRotationMatrix(pure));
        return true;
    }

    /// <summary>The skin's joint nodes.</summary>
    internal static int[] SkinJoints(GltfDocument document, int skin)
    {
        int nodeCount = document.Array("nodes").Count;
        if (document.Array("skins")[skin] is not JsonObject json || json["joints"] is not JsonArray joints)
        {
            throw new GltfException($"{document.Name}: skin {skin} has no list of joints.");
        }

        return
        [
            .. joints.Select(j => j is JsonValue v && v.TryGetValue(out int n) && n >= 0 && n < nodeCount
                ? n
                : throw new GltfException($"{document.Name}: skin {skin} lists joint {j?.ToJsonString() ?? "null"}, which is not a node.")),
        ];
    }

    private static void CheckBoneScale(GltfDocument document, JsonArray nodes, int[] parentNode, HashSet<int> isJoint, int bone, Func<int, string> name)
    {
        // The bone itself, then its ancestors up to the scene root: each must be a rotation with a uniform scale.
        for (int node = bone; node >= 0; node = parentNode[node])
        {
            Matrix4x4 local = document.LocalTransform((JsonObject)nodes[node]!);
            if (TryRigid(local, out _, out _))
            {
                continue;
            }

            var scale = new Vector3(new Vector3(local.M11, local.M12, local.M13).Length(), new Vector3(local.M21, local.M22, local.M23).Length(), new Vector3(local.M31, local.M32, local.M33).Length());
            string what = node == bone ? $"bone '{name(node)}'" : $"{(isJoint.Contains(node) ? "bone" : "node")} '{name(node)}' (above bone '{name(bone)}')";
            string problem = Vector3.Dot(Vector3.Cross(new Vector3(local.M11, local.M12, local.M13), new Vector3(local.M21, local.M22, local.M23)), new Vector3(local.M31, local.M32, local.M33)) <= 0f
                ? "is mirrored or collapsed (a negative or zero scale)"
                : $"is scaled non-uniformly ({scale.X:0.###}, {scale.Y:0.###}, {scale.Z:0.###})";
            throw new RigException($"{document.Name}: {what} {problem}; apply the scale before exporting.");
        }
    }

    /// <summary>Every skinned vertex in the rest pose, assigned to its dominant bone and expressed in that bone's rest frame.</summary>
    private static List<Vector3>[] SkinnedPoints(GltfDocument document, Matrix4x4[] world, Dictionary<int, int> jointIndex, Quaternion axes, Vector3[] positions, Quaternion[] rotations)
    {
        var points = new List<Vector3>[positions.Length];
        for (int j = 0; j < points.Length; j++)
        {
            points[j] = [];
        }

        JsonArray nodes = document.Array("nodes");
        JsonArray meshes = document.Array("meshes");
        for (int n = 0; n < nodes.Count; n++)
        {
            if (nodes[n] is not JsonObject node || node["mesh"] is not JsonValue meshValue || node["skin"] is not JsonValue skinValue)
            {
                continue;
            }

            if (!meshValue.TryGetValue(out int meshIndex) || meshIndex < 0 || meshIndex >= meshes.Count || meshes[meshIndex] is not JsonObject mesh
                || !skinValue.TryGetValue(out int skin) || skin < 0 || skin >= document.Array("skins").Count)
            {
                throw new GltfException($"{document.Name}: node {n} names a mesh or skin that does not exist.");
            }

            int[] joints = SkinJoints(document, skin);
            var skinMatrices = new Matrix4x4[joints.Length];
            float[]? inverseBind = document.Array("skins")[skin]!["inverseBindMatrices"] is JsonValue ib && ib.TryGetValue(out int ibAccessor) ? document.ReadFloats(ibAccessor, 16) : null;
            if (inverseBind is not null && inverseBind.Length < 16 * joints.Length)
            {
                throw new GltfException($"{document.Name}: skin {skin} has fewer inverse bind matrices than joints.");
            }

            for (int i = 0; i < joints.Length; i++)
            {
                Matrix4x4 ibm = Matrix4x4.Identity;
                if (inverseBind is not null)
                {
                    ReadOnlySpan<float> v = inverseBind.AsSpan(16 * i, 16);
                    ibm = new Matrix4x4(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11], v[12], v[13], v[14], v[15]);
                }

                skinMatrices[i] = ibm * world[joints[i]];
            }

            foreach (JsonNode? primitiveNode in mesh["primitives"] as JsonArray ?? [])
            {
                if (primitiveNode?["attributes"] is not JsonObject attributes || attributes["POSITION"] is not JsonValue pv || !pv.TryGetValue(out int positionAccessor))
                {
                    continue;
                }

                float[] vertices = document.ReadFloats(positionAccessor, 3);
                var sets = new List<(int[] Joints, float[] Weights)>();
                for (int set = 0; attributes[$"JOINTS_{set}"] is JsonValue jv && attributes[$"WEIGHTS_{set}"] is JsonValue wv; set++)
                {
                    int[] js = jv.TryGetValue(out int ja) ? document.ReadIntegers(ja) : throw new GltfException($"{document.Name}: mesh {meshIndex} has a malformed JOINTS_{set}.");
                    float[] ws = wv.TryGetValue(out int wa) ? document.ReadFloats(wa, 4) : throw new GltfException($"{document.Name}: mesh {meshIndex} has a malformed WEIGHTS_{set}.");
                    if (js.Length < vertices.Length / 3 * 4 || ws.Length < vertices.Length / 3 * 4)
                    {
                        throw new GltfException($"{document.Name}: mesh {meshIndex}'s JOINTS_{set} or WEIGHTS_{set} has fewer elements than POSITION.");
                    }

                    sets.Add((js, ws));
                }

                for (int v = 0; v < vertices.Length / 3; v++)
                {
                    var p = new Vector3(vertices[3 * v], vertices[(3 * v) + 1], vertices[(3 * v) + 2]);
                    Vector3 skinned = Vector3.Zero;
                    float total = 0f;
                    int dominant = -1;
                    float best = 0f;
                    foreach ((int[] js, float[] ws) in sets)
                    {
                        for (int k = 0; k < 4; k++)
                        {
                            float w = ws[(4 * v) + k];
                            int joint = js[(4 * v) + k];
                            if (!(w > 0f))
                            {
                                continue;
                            }

                            if (joint >= joints.Length)
                            {
                                throw new GltfException($"{document.Name}: mesh {meshIndex}, vertex {v} is weighted to joint {joint}, but skin {skin} has {joints.Length} joints.");
                            }

                            skinned += Vector3.Transform(p, skinMatrices[joint]) * w;
                            total += w;
                            float onBone = w;
                            foreach ((int[] js2, float[] ws2) in sets)
                            {
                                for (int k2 = 0; k2 < 4; k2++)
                                {
                                    if (!ReferenceEquals(js2, js) || k2 != k)
                                    {
                                        onBone += js2[(4 * v) + k2] == joint && ws2[(4 * v) + k2] > 0f ? ws2[(4 * v) + k2] : 0f;
                                    }
                                }
                            }

                            if (onBone > best)
                            {
                                best = onBone;
                                dominant = joints[joint];
                            }
                        }
                    }

                    if (total <= 0f || !jointIndex.TryGetValue(dominant, out int bone))
                    {
                        continue;
                    }

                    Vector3 inFrame = Vector3.Transform(skinned / total, axes);
                    points[bone].Add(Vector3.Transform(inFrame - positions[bone], Quaternion.Conjugate(rotations[bone])));
                }
            }
        }

        return points;
    }
}
