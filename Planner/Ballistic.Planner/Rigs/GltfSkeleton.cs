using System.Globalization;
using System.Numerics;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Gltf;
using SharpGLTF.Schema2;

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
    /// <summary>How far from the origin, in metres along each axis, a bone or skinned vertex may lie.</summary>
    public const float MaxCoordinate = 1e6f;

    private GltfSkeleton(int[] nodes, string[] names, int[] parents, Vector3[] offsets, Quaternion[] restRotations, Vector3[] restPositions, Quaternion[] restWorldRotations, List<Vector3>[] points, List<SkinBlend[]>[] blends)
    {
        Blends = blends;
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

    /// <summary>
    /// For each joint, the vertices among <see cref="Points"/> (same order) weighted to several bones, at most
    /// <see cref="BlendedShare"/> of their weight on it (a knee's skin, carried partly by the thigh): each bone's share.
    /// </summary>
    public List<SkinBlend[]>[] Blends { get; }

    /// <summary>Largest share of its weight a vertex's own bone may carry for the vertex to count as blended.</summary>
    public const float BlendedShare = 0.95f;

    /// <summary>Reads skin 0 of <paramref name="model"/>.</summary>
    /// <param name="model">The rigged glTF, read and validated.</param>
    /// <param name="axes">Rotation from the glTF scene into Ballistic's frame (from the spec's up and forward axes).</param>
    /// <param name="limbBones">Names of the limbs' bones, to choose the root among several root bones.</param>
    /// <exception cref="RigException">There is no skin, a bone is scaled non-uniformly or mirrored, or bone names repeat.</exception>
    /// <exception cref="GltfException">The glTF's hierarchy, skin or meshes are malformed.</exception>
    public static GltfSkeleton Read(GltfModel model, Quaternion axes, IReadOnlyCollection<string> limbBones)
    {
        string file = model.Name;
        if (model.Root.LogicalSkins.Count == 0)
        {
            throw new RigException($"{file} has no skin: a character needs a rigged (skinned) mesh.");
        }

        IReadOnlyList<Node> nodes = model.Root.LogicalNodes;
        int[] skinJoints = SkinJoints(model, 0);
        if (skinJoints.Length == 0)
        {
            throw new RigException($"{file}: skin 0 has no joints.");
        }

        int[] parentNode = model.NodeParents();
        Matrix4x4[] world = model.WorldTransforms();
        var isJoint = new HashSet<int>(skinJoints);
        string NodeName(int node) => nodes[node].Name is { Length: > 0 } s ? s : $"node {node}";

        var byName = new Dictionary<string, int>(StringComparer.Ordinal);
        foreach (int j in skinJoints)
        {
            if (!byName.TryAdd(NodeName(j), j))
            {
                throw new RigException($"{file}: two bones are called '{NodeName(j)}' (nodes {byName[NodeName(j)]} and {j}); bone names must be unique.");
            }
        }

        // Each node's nearest ancestor that is a bone, and each bone's topmost bone ancestor: parents first, once each.
        int[] topological = ParentsFirst(parentNode);
        int[] boneAncestor = new int[parentNode.Length];
        int[] top = new int[parentNode.Length];
        foreach (int n in topological)
        {
            int p = parentNode[n];
            boneAncestor[n] = p < 0 ? -1 : isJoint.Contains(p) ? p : boneAncestor[p];
            top[n] = boneAncestor[n] < 0 ? n : top[boneAncestor[n]];
        }

        // The root: among the skin's root bones, the one with the most limb bones below it, then the most bones.
        int[] roots = [.. skinJoints.Where(j => boneAncestor[j] < 0)];
        var limbBonesBelow = new Dictionary<int, int>();
        foreach (string bone in limbBones)
        {
            if (byName.TryGetValue(bone, out int n))
            {
                limbBonesBelow[top[n]] = limbBonesBelow.GetValueOrDefault(top[n]) + 1;
            }
        }

        var bonesBelow = new Dictionary<int, int>();
        foreach (int j in skinJoints)
        {
            bonesBelow[top[j]] = bonesBelow.GetValueOrDefault(top[j]) + 1;
        }

        int main = roots
            .OrderByDescending(r => limbBonesBelow.GetValueOrDefault(r))
            .ThenByDescending(r => bonesBelow.GetValueOrDefault(r))
            .First();
        int RigParent(int node) => node == main ? -1 : boneAncestor[node] is int a && a >= 0 ? a : main;

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
            var children = skinJoints.Where(c => c != main).ToLookup(RigParent);
            var queue = new Queue<int>([main]);
            while (queue.Count > 0)
            {
                int node = queue.Dequeue();
                order.Add(node);
                foreach (int child in children[node])
                {
                    queue.Enqueue(child);
                }
            }
        }

        // Rest frames in Ballistic's frame: rotation and position without the (uniform) scale.
        int count = order.Count;
        var positions = new Vector3[count];
        var rotations = new Quaternion[count];
        var rigid = new HashSet<int>();
        for (int i = 0; i < count; i++)
        {
            int node = order[i];
            CheckBoneScale(model, parentNode, isJoint, node, NodeName, rigid);
            if (!IsFinite(world[node]))
            {
                throw new RigException($"{file}: bone '{NodeName(node)}' with its parents' transforms is not finite (a translation or scale too large); apply the transforms before exporting.");
            }

            if (!Rotations.TryRigid(world[node], out _, out Quaternion rotation))
            {
                throw new RigException($"{file}: bone '{NodeName(node)}' with its parents is not a rotation with a uniform scale (sheared); apply the transforms before exporting.");
            }

            positions[i] = Vector3.Transform(world[node].Translation, axes);
            rotations[i] = Quaternion.Normalize(axes * rotation);
            if (!Within(positions[i]))
            {
                throw new RigException($"{file}: bone '{NodeName(node)}' lies at ({positions[i].X:G4}, {positions[i].Y:G4}, {positions[i].Z:G4}), beyond the ±1e6 m a character may span.");
            }
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

        (List<Vector3>[] points, List<SkinBlend[]>[] blends) = SkinnedPoints(model, world, index, axes, positions, rotations);
        return new GltfSkeleton([.. order], [.. order.Select(NodeName)], parents, offsets, rests, positions, rotations, points, blends);
    }

    /// <summary>The skin's joint nodes, by node index (each once: <see cref="GltfModel.CheckJson"/> refuses a skin listing a node twice).</summary>
    internal static int[] SkinJoints(GltfModel model, int skin) => [.. model.Root.LogicalSkins[skin].Joints.Select(n => n.LogicalIndex)];

    /// <summary>Every node once, each after its parent (parents from <see cref="GltfModel.NodeParents"/>, which has no cycle).</summary>
    private static int[] ParentsFirst(int[] parents)
    {
        var children = new List<int>?[parents.Length];
        var order = new List<int>(parents.Length);
        for (int n = 0; n < parents.Length; n++)
        {
            if (parents[n] < 0)
            {
                order.Add(n);
            }
            else
            {
                (children[parents[n]] ??= []).Add(n);
            }
        }

        for (int i = 0; i < order.Count; i++)
        {
            if (children[order[i]] is List<int> list)
            {
                order.AddRange(list);
            }
        }

        return [.. order];
    }

    private static bool Within(Vector3 p) => MathF.Abs(p.X) <= MaxCoordinate && MathF.Abs(p.Y) <= MaxCoordinate && MathF.Abs(p.Z) <= MaxCoordinate;

    private static bool IsFinite(Matrix4x4 m) =>
        float.IsFinite(m.M11) && float.IsFinite(m.M12) && float.IsFinite(m.M13) && float.IsFinite(m.M14) &&
        float.IsFinite(m.M21) && float.IsFinite(m.M22) && float.IsFinite(m.M23) && float.IsFinite(m.M24) &&
        float.IsFinite(m.M31) && float.IsFinite(m.M32) && float.IsFinite(m.M33) && float.IsFinite(m.M34) &&
        float.IsFinite(m.M41) && float.IsFinite(m.M42) && float.IsFinite(m.M43) && float.IsFinite(m.M44);

    private static void CheckBoneScale(GltfModel model, int[] parentNode, HashSet<int> isJoint, int bone, Func<int, string> name, HashSet<int> rigid)
    {
        // The bone itself, then its ancestors up to the scene root: each must be a rotation with a uniform scale
        // (a node found rigid before, for another bone, has had its ancestors checked too).
        for (int node = bone; node >= 0 && !rigid.Contains(node); node = parentNode[node])
        {
            Matrix4x4 local = model.LocalTransform(model.Root.LogicalNodes[node]);
            string Which() => node == bone ? $"bone '{name(node)}'" : $"{(isJoint.Contains(node) ? "bone" : "node")} '{name(node)}' (above bone '{name(bone)}')";
            float largest = 0f;
            for (int k = 0; k < 16; k++)
            {
                largest = MathF.Max(largest, MathF.Abs(local[k / 4, k % 4]));
            }

            if (!(largest <= MaxCoordinate))
            {
                throw new RigException($"{model.Name}: {Which()} has a scale or translation beyond ±1e6; apply the transforms before exporting.");
            }

            if (Rotations.TryRigid(local, out _, out _))
            {
                continue;
            }

            var scale = new Vector3(new Vector3(local.M11, local.M12, local.M13).Length(), new Vector3(local.M21, local.M22, local.M23).Length(), new Vector3(local.M31, local.M32, local.M33).Length());
            string what = Which();
            string problem = Vector3.Dot(Vector3.Cross(new Vector3(local.M11, local.M12, local.M13), new Vector3(local.M21, local.M22, local.M23)), new Vector3(local.M31, local.M32, local.M33)) <= 0f
                ? "is mirrored or collapsed (a negative or zero scale)"
                : $"is scaled non-uniformly ({scale.X:0.###}, {scale.Y:0.###}, {scale.Z:0.###})";
            throw new RigException($"{model.Name}: {what} {problem}; apply the scale before exporting.");
        }

        int checkedNode = bone;
        while (checkedNode >= 0 && rigid.Add(checkedNode))
        {
            checkedNode = parentNode[checkedNode];
        }
    }

    /// <summary>Every skinned vertex in the rest pose, assigned to its dominant bone and expressed in that bone's rest frame; and those weighted to several bones, with each bone's share (<see cref="Blends"/>).</summary>
    /// <exception cref="GltfException">A skinned mesh, its skin or its accessors are malformed, or the vertices read exceed <see cref="GltfLoadOptions.MaxVertices"/>.</exception>
    /// <exception cref="RigException">A skinned vertex is not finite or lies beyond <see cref="MaxCoordinate"/>.</exception>
    private static (List<Vector3>[] Points, List<SkinBlend[]>[] Blends) SkinnedPoints(GltfModel model, Matrix4x4[] world, Dictionary<int, int> jointIndex, Quaternion axes, Vector3[] positions, Quaternion[] rotations)
    {
        var points = new List<Vector3>[positions.Length];
        var blends = new List<SkinBlend[]>[positions.Length];
        for (int j = 0; j < points.Length; j++)
        {
            points[j] = [];
            blends[j] = [];
        }

        string file = model.Name;
        long verticesRead = 0;
        var weightOfJoint = new Dictionary<int, float>();
        Span<float> read = stackalloc float[16];
        foreach (Node node in model.Root.LogicalNodes)
        {
            if (node.Mesh is not Mesh mesh || node.Skin is not Skin skinOfNode)
            {
                continue;
            }

            int meshIndex = mesh.LogicalIndex;
            int skin = skinOfNode.LogicalIndex;
            int[] joints = SkinJoints(model, skin);
            var skinMatrices = new Matrix4x4[joints.Length];
            IReadOnlyList<Matrix4x4>? inverseBind = skinOfNode.GetInverseBindMatricesAccessor() is Accessor ibAccessor ? [.. ibAccessor.AsMatrix4x4Array()] : null;
            if (inverseBind is not null && inverseBind.Count < joints.Length)
            {
                throw new GltfException($"{file}: skin {skin} has fewer inverse bind matrices than joints.");
            }

            for (int i = 0; i < joints.Length; i++)
            {
                Matrix4x4 ibm = Matrix4x4.Identity;
                if (inverseBind is not null)
                {
                    ibm = inverseBind[i];
                    for (int k = 0; k < 16; k++)
                    {
                        read[k] = ibm[k / 4, k % 4];
                    }

                    if (InverseBindProblem(read, ibm) is { } problem)
                    {
                        throw new GltfException($"{file}: skin {skin}'s inverse bind matrix {i} (of joint node {joints[i]}) {problem}.");
                    }
                }

                skinMatrices[i] = ibm * world[joints[i]];
            }

            for (int pi = 0; pi < mesh.Primitives.Count; pi++)
            {
                MeshPrimitive primitive = mesh.Primitives[pi];
                if (primitive.GetVertexAccessor("POSITION") is not Accessor positionAccessor)
                {
                    continue;
                }

                string what = $"primitive {pi} of mesh {meshIndex}";
                int sets = 0;
                while (primitive.GetVertexAccessor($"JOINTS_{sets}") is not null && primitive.GetVertexAccessor($"WEIGHTS_{sets}") is not null)
                {
                    sets++;
                }

                long vertexCount = positionAccessor.Count;
                verticesRead += vertexCount * (1 + sets);
                if (verticesRead > model.Options.MaxVertices)
                {
                    throw new GltfException($"{file}: with {what}, the character's skinned meshes read more than {model.Options.MaxVertices} vertices (GltfLoadOptions.MaxVertices).");
                }

                float[] vertices = System.Runtime.InteropServices.MemoryMarshal.Cast<Vector3, float>(GltfModel.Vectors(positionAccessor)).ToArray();
                var influences = new List<(int[] Joints, float[] Weights)>();
                for (int set = 0; set < sets; set++)
                {
                    IList<Vector4> jointSets = primitive.GetVertexAccessor($"JOINTS_{set}").AsVector4Array();
                    IList<Vector4> weightSets = primitive.GetVertexAccessor($"WEIGHTS_{set}").AsVector4Array();
                    if (jointSets.Count < vertexCount || weightSets.Count < vertexCount)
                    {
                        throw new GltfException($"{file}: {what}'s JOINTS_{set} or WEIGHTS_{set} has fewer elements than POSITION.");
                    }

                    int[] js = new int[4 * vertexCount];
                    float[] ws = new float[4 * vertexCount];
                    for (int v = 0; v < vertexCount; v++)
                    {
                        (Vector4 jv, Vector4 wv) = (jointSets[v], weightSets[v]);
                        (js[4 * v], js[(4 * v) + 1], js[(4 * v) + 2], js[(4 * v) + 3]) = ((int)jv.X, (int)jv.Y, (int)jv.Z, (int)jv.W);
                        (ws[4 * v], ws[(4 * v) + 1], ws[(4 * v) + 2], ws[(4 * v) + 3]) = (wv.X, wv.Y, wv.Z, wv.W);
                    }

                    influences.Add((js, ws));
                }

                for (int v = 0; v < vertices.Length / 3; v++)
                {
                    var p = new Vector3(vertices[3 * v], vertices[(3 * v) + 1], vertices[(3 * v) + 2]);
                    Vector3 skinned = Vector3.Zero;
                    float total = 0f;
                    weightOfJoint.Clear();
                    foreach ((int[] js, float[] ws) in influences)
                    {
                        for (int k = 0; k < 4; k++)
                        {
                            float w = ws[(4 * v) + k];
                            int joint = js[(4 * v) + k];
                            if (!float.IsFinite(w) || w < 0f)
                            {
                                throw new GltfException($"{file}: {what}, vertex {v} has a skin weight of {w.ToString(CultureInfo.InvariantCulture)}: weights must be finite and not negative.");
                            }

                            if (!(w > 0f))
                            {
                                continue;
                            }

                            if (joint >= joints.Length)
                            {
                                throw new GltfException($"{file}: {what}, vertex {v} is weighted to joint {joint}, but skin {skin} has {joints.Length} joints.");
                            }

                            skinned += Vector3.Transform(p, skinMatrices[joint]) * w;
                            total += w;
                            weightOfJoint[joint] = weightOfJoint.GetValueOrDefault(joint) + w;
                        }
                    }

                    if (!(total > 0f))
                    {
                        continue;
                    }

                    // The dominant bone: the most weight summed over the sets, the first listed on a tie.
                    int dominant = -1;
                    float best = 0f;
                    foreach ((int[] js, float[] ws) in influences)
                    {
                        for (int k = 0; k < 4; k++)
                        {
                            if (ws[(4 * v) + k] > 0f && weightOfJoint[js[(4 * v) + k]] > best)
                            {
                                best = weightOfJoint[js[(4 * v) + k]];
                                dominant = joints[js[(4 * v) + k]];
                            }
                        }
                    }

                    Vector3 inFrame = Vector3.Transform(skinned / total, axes);
                    if (!Within(inFrame))
                    {
                        throw new RigException($"{file}: vertex {v} of {what} lies at ({inFrame.X:G4}, {inFrame.Y:G4}, {inFrame.Z:G4}) in the rest pose, {(float.IsFinite(inFrame.X + inFrame.Y + inFrame.Z) ? "beyond the ±1e6 m a character may span" : "which is not finite")}.");
                    }

                    if (jointIndex.TryGetValue(dominant, out int bone))
                    {
                        points[bone].Add(Vector3.Transform(inFrame - positions[bone], Quaternion.Conjugate(rotations[bone])));

                        // Weighted to several of the rig's bones: each one's share, the vertex in its rest frame.
                        float onRig = 0f;
                        foreach ((int joint, float w) in weightOfJoint)
                        {
                            onRig += jointIndex.ContainsKey(joints[joint]) ? w : 0f;
                        }

                        if (onRig > 0f && best / onRig <= BlendedShare)
                        {
                            var parts = new List<SkinBlend>();
                            foreach ((int joint, float w) in weightOfJoint.OrderBy(e => e.Key))
                            {
                                if (jointIndex.TryGetValue(joints[joint], out int j))
                                {
                                    parts.Add(new SkinBlend(j, w / onRig, Vector3.Transform(inFrame - positions[j], Quaternion.Conjugate(rotations[j]))));
                                }
                            }

                            blends[bone].Add([.. parts]);
                        }
                        else
                        {
                            blends[bone].Add([]);
                        }
                    }
                }
            }
        }

        return (points, blends);
    }

    /// <summary>
    /// Why <paramref name="ibm"/> (an inverse bind matrix read from the floats <paramref name="read"/>, row-vector
    /// convention) cannot be one, or <c>null</c>: a number that is not finite, a fourth row other than (0, 0, 0, 1)
    /// (glTF's are affine), or a transform that does not invert (an all-zero matrix among them), which would fold the
    /// skinned mesh onto a point or a plane.
    /// </summary>
    private static string? InverseBindProblem(ReadOnlySpan<float> read, in Matrix4x4 ibm)
    {
        foreach (float x in read)
        {
            if (!float.IsFinite(x))
            {
                return "has a number that is not finite";
            }
        }

        const float Rounding = 1e-5f;
        if (MathF.Abs(ibm.M14) > Rounding || MathF.Abs(ibm.M24) > Rounding || MathF.Abs(ibm.M34) > Rounding || MathF.Abs(ibm.M44 - 1f) > Rounding)
        {
            return "is not affine (its fourth row must be 0, 0, 0, 1)";
        }

        // Affine: the determinant is its 3×3 part's, judged against the cube of its largest row (its scale).
        float scale = MathF.Max(MathF.Max(new Vector3(ibm.M11, ibm.M12, ibm.M13).Length(), new Vector3(ibm.M21, ibm.M22, ibm.M23).Length()), new Vector3(ibm.M31, ibm.M32, ibm.M33).Length());
        return scale > 0f && MathF.Abs(ibm.GetDeterminant()) > 1e-9f * scale * scale * scale ? null : "does not invert (its rotation and scale part is singular)";
    }
}
