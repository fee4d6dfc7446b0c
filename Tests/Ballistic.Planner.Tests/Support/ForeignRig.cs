using System.Buffers.Binary;
using System.Numerics;
using System.Text;
using System.Text.Json.Nodes;

namespace Ballistic.Planner.Tests.Support;

/// <summary>
/// Writes a rigged glTF the way other tools do, independently of the planner's writers: a node tree of bones and
/// non-bone nodes (armatures, anchors) with their own rotations and scales, a skin with inverse bind matrices, and a
/// textured mesh of boxes weighted to bones (some vertices shared between two bones). Boxes are given in the frame of
/// a chosen node, so a rig modelled in centimetres and Z up under a scaled, rotated armature is written as such.
/// </summary>
internal sealed class ForeignRig
{
    /// <summary>A 1×1 PNG.</summary>
    public static readonly byte[] Png = Convert.FromBase64String("iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8BQDwAEhQGAhKmMIQAAAABJRU5ErkJggg==");

    private readonly List<(string Name, int Parent, Vector3 T, Quaternion R, float S, bool Bone, bool AsMatrix)> _nodes = [];
    private readonly List<(Vector3 Position, int Bone, int Blend, float BlendWeight)> _vertices = [];
    private readonly List<int> _indices = [];

    /// <summary>Adds a node with a local translation, rotation and uniform scale; returns its index.</summary>
    public int Node(string name, int parent, Vector3 translation, Quaternion rotation, float scale = 1f, bool bone = false, bool asMatrix = false)
    {
        _nodes.Add((name, parent, translation, rotation, scale, bone, asMatrix));
        return _nodes.Count - 1;
    }

    /// <summary>
    /// Adds an unscaled bone (local scale 1, as exporters write bones) whose head is at <paramref name="position"/>
    /// with its +Y axis towards <paramref name="towards"/> and twisted about it, both in the frame of node <paramref name="frame"/>.
    /// </summary>
    public int BoneAt(string name, int parent, int frame, Vector3 position, Vector3 towards, float twist = 0f, bool asMatrix = false)
    {
        Quaternion rotation = Quaternion.Normalize(Quaternion.CreateFromAxisAngle(Vector3.Normalize(towards - position), twist) * FromTo(Vector3.UnitY, Vector3.Normalize(towards - position)));
        Matrix4x4 desired = Matrix4x4.CreateFromQuaternion(rotation) * Matrix4x4.CreateTranslation(position) * World(frame);
        Matrix4x4.Invert(World(parent), out Matrix4x4 inverseParent);
        Matrix4x4.Decompose(desired * inverseParent, out _, out Quaternion local, out Vector3 translation);
        return Node(name, parent, translation, Quaternion.Normalize(local), 1f, bone: true, asMatrix);
    }

    /// <summary>Marks <paramref name="node"/> as a bone (a skin joint).</summary>
    public void MakeBone(int node) => _nodes[node] = _nodes[node] with { Bone = true };

    /// <summary>The skin's joints in this order (default: bones in the order they were added).</summary>
    public List<int>? SkinOrder { get; set; }

    /// <summary>Node <paramref name="node"/>'s transform in the scene (−1: the identity).</summary>
    public Matrix4x4 World(int node)
    {
        if (node < 0)
        {
            return Matrix4x4.Identity;
        }

        (_, int parent, Vector3 t, Quaternion r, float s, _, _) = _nodes[node];
        return Matrix4x4.CreateScale(s) * Matrix4x4.CreateFromQuaternion(r) * Matrix4x4.CreateTranslation(t) * World(parent);
    }

    /// <summary>Index of the node called <paramref name="name"/>.</summary>
    public int this[string name] => _nodes.FindIndex(n => n.Name == name);

    /// <summary>
    /// Adds a box, axis-aligned in node <paramref name="frame"/>'s frame from <paramref name="min"/> to
    /// <paramref name="max"/>, weighted to <paramref name="bone"/> (and <paramref name="blendWeight"/> of it to
    /// <paramref name="blend"/> when given). Each face is a 3 × 3 grid of vertices.
    /// </summary>
    public void Box(int bone, int frame, Vector3 min, Vector3 max, int blend = -1, float blendWeight = 0.3f)
    {
        Matrix4x4 toScene = World(frame);
        for (int axis = 0; axis < 3; axis++)
        {
            for (int side = 0; side < 2; side++)
            {
                int start = _vertices.Count;
                for (int a = 0; a < 3; a++)
                {
                    for (int b = 0; b < 3; b++)
                    {
                        float[] t = new float[3];
                        t[axis] = side;
                        t[(axis + 1) % 3] = a * 0.5f;
                        t[(axis + 2) % 3] = b * 0.5f;
                        Vector3 local = min + ((max - min) * new Vector3(t[0], t[1], t[2]));
                        _vertices.Add((Vector3.Transform(local, toScene), bone, blend, blend >= 0 ? blendWeight : 0f));
                    }
                }

                for (int a = 0; a < 2; a++)
                {
                    for (int b = 0; b < 2; b++)
                    {
                        int v = start + (a * 3) + b;
                        int[] quad = side == 0 ? [v, v + 1, v + 4, v, v + 4, v + 3] : [v, v + 4, v + 1, v, v + 3, v + 4];
                        _indices.AddRange(quad);
                    }
                }
            }
        }
    }

    /// <summary>A box along <paramref name="bone"/> (in its own frame: its +Y from its head, <paramref name="length"/> long, <paramref name="radius"/> either side), as <see cref="Box"/>.</summary>
    public void BoxAlong(int bone, float length, float radius, int blend = -1, float blendWeight = 0.3f) =>
        Box(bone, bone, new Vector3(-radius, 0f, -radius), new Vector3(radius, length, radius), blend, blendWeight);

    /// <summary>Scene positions of the vertices whose main bone is one of <paramref name="bones"/>.</summary>
    public Vector3[] VerticesOf(params int[] bones) => [.. _vertices.Where(v => bones.Contains(v.Bone)).Select(v => v.Position)];

    /// <summary>The rig as a binary glTF.</summary>
    /// <param name="byteWeights">Weights as normalised unsigned bytes and joints as bytes (else floats and unsigned shorts).</param>
    public byte[] ToGlb(bool byteWeights = false)
    {
        (JsonObject json, byte[] bin) = Build(byteWeights, externalImage: null);
        json["buffers"] = new JsonArray(new JsonObject { ["byteLength"] = bin.Length });
        return Fuzz.FuzzInputs.JoinGlb(Encoding.UTF8.GetBytes(json.ToJsonString()), bin);
    }

    /// <summary>Writes the rig as <c>NAME.gltf</c> with its buffer and texture as separate files beside it; returns the glTF's path.</summary>
    public string WriteGltf(string folder, string name)
    {
        (JsonObject json, byte[] bin) = Build(byteWeights: false, externalImage: name + ".png");
        json["buffers"] = new JsonArray(new JsonObject { ["byteLength"] = bin.Length, ["uri"] = name + ".bin" });
        File.WriteAllBytes(Path.Combine(folder, name + ".bin"), bin);
        File.WriteAllBytes(Path.Combine(folder, name + ".png"), Png);
        string path = Path.Combine(folder, name + ".gltf");
        File.WriteAllText(path, json.ToJsonString());
        return path;
    }

    private (JsonObject Json, byte[] Bin) Build(bool byteWeights, string? externalImage)
    {
        List<int> joints = SkinOrder ?? [.. Enumerable.Range(0, _nodes.Count).Where(n => _nodes[n].Bone)];
        var bin = new MemoryStream();
        var views = new JsonArray();
        var accessors = new JsonArray();
        int View(byte[] bytes, int? target)
        {
            while (bin.Length % 4 != 0)
            {
                bin.WriteByte(0);
            }

            var view = new JsonObject { ["buffer"] = 0, ["byteOffset"] = bin.Length, ["byteLength"] = bytes.Length };
            if (target is int t)
            {
                view["target"] = t;
            }

            bin.Write(bytes);
            views.Add(view);
            return views.Count - 1;
        }

        int Accessor(byte[] bytes, int componentType, int count, string type, bool normalized = false, JsonArray? min = null, JsonArray? max = null, int? target = 34962)
        {
            var accessor = new JsonObject { ["bufferView"] = View(bytes, target), ["componentType"] = componentType, ["count"] = count, ["type"] = type };
            if (normalized)
            {
                accessor["normalized"] = true;
            }

            if (min is not null)
            {
                accessor["min"] = min;
                accessor["max"] = max;
            }

            accessors.Add(accessor);
            return accessors.Count - 1;
        }

        // Vertex attributes.
        int n = _vertices.Count;
        byte[] positions = new byte[n * 12];
        byte[] uvs = new byte[n * 8];
        byte[] jointBytes = new byte[n * (byteWeights ? 4 : 8)];
        byte[] weightBytes = new byte[n * (byteWeights ? 4 : 16)];
        Vector3 lo = new(float.MaxValue);
        Vector3 hi = new(float.MinValue);
        for (int v = 0; v < n; v++)
        {
            (Vector3 p, int bone, int blend, float blendWeight) = _vertices[v];
            lo = Vector3.Min(lo, p);
            hi = Vector3.Max(hi, p);
            BinaryPrimitives.WriteSingleLittleEndian(positions.AsSpan(12 * v), p.X);
            BinaryPrimitives.WriteSingleLittleEndian(positions.AsSpan((12 * v) + 4), p.Y);
            BinaryPrimitives.WriteSingleLittleEndian(positions.AsSpan((12 * v) + 8), p.Z);
            BinaryPrimitives.WriteSingleLittleEndian(uvs.AsSpan(8 * v), (v % 7) / 7f);
            BinaryPrimitives.WriteSingleLittleEndian(uvs.AsSpan((8 * v) + 4), (v % 5) / 5f);
            int j0 = joints.IndexOf(bone);
            int j1 = blend >= 0 ? joints.IndexOf(blend) : 0;
            if (byteWeights)
            {
                jointBytes[4 * v] = (byte)j0;
                jointBytes[(4 * v) + 1] = (byte)j1;
                byte second = (byte)MathF.Round(blendWeight * 255f);
                weightBytes[4 * v] = (byte)(255 - second);
                weightBytes[(4 * v) + 1] = second;
            }
            else
            {
                BinaryPrimitives.WriteUInt16LittleEndian(jointBytes.AsSpan(8 * v), (ushort)j0);
                BinaryPrimitives.WriteUInt16LittleEndian(jointBytes.AsSpan((8 * v) + 2), (ushort)j1);
                BinaryPrimitives.WriteSingleLittleEndian(weightBytes.AsSpan(16 * v), 1f - blendWeight);
                BinaryPrimitives.WriteSingleLittleEndian(weightBytes.AsSpan((16 * v) + 4), blendWeight);
            }
        }

        byte[] indexBytes = new byte[_indices.Count * 2];
        for (int i = 0; i < _indices.Count; i++)
        {
            BinaryPrimitives.WriteUInt16LittleEndian(indexBytes.AsSpan(2 * i), (ushort)_indices[i]);
        }

        var attributes = new JsonObject
        {
            ["POSITION"] = Accessor(positions, 5126, n, "VEC3", min: [lo.X, lo.Y, lo.Z], max: [hi.X, hi.Y, hi.Z]),
            ["TEXCOORD_0"] = Accessor(uvs, 5126, n, "VEC2"),
            ["JOINTS_0"] = Accessor(jointBytes, byteWeights ? 5121 : 5123, n, "VEC4"),
            ["WEIGHTS_0"] = Accessor(weightBytes, byteWeights ? 5121 : 5126, n, "VEC4", normalized: byteWeights),
        };
        int indices = Accessor(indexBytes, 5123, _indices.Count, "SCALAR", target: 34963);

        // Inverse bind matrices: the bones' rest transforms inverted, with an exact affine row.
        byte[] ibm = new byte[joints.Count * 64];
        for (int j = 0; j < joints.Count; j++)
        {
            Matrix4x4.Invert(World(joints[j]), out Matrix4x4 m);
            float[] values = [m.M11, m.M12, m.M13, 0f, m.M21, m.M22, m.M23, 0f, m.M31, m.M32, m.M33, 0f, m.M41, m.M42, m.M43, 1f];
            for (int k = 0; k < 16; k++)
            {
                BinaryPrimitives.WriteSingleLittleEndian(ibm.AsSpan((64 * j) + (4 * k)), values[k]);
            }
        }

        int inverseBind = Accessor(ibm, 5126, joints.Count, "MAT4", target: null);
        var image = new JsonObject { ["name"] = "skin texture" };
        if (externalImage is null)
        {
            image["bufferView"] = View(Png, null);
            image["mimeType"] = "image/png";
        }
        else
        {
            image["uri"] = externalImage;
        }

        var nodes = new JsonArray();
        for (int i = 0; i < _nodes.Count; i++)
        {
            (string name, _, Vector3 t, Quaternion r, float s, _, bool asMatrix) = _nodes[i];
            var node = new JsonObject { ["name"] = name };
            if (asMatrix)
            {
                Matrix4x4 m = Matrix4x4.CreateScale(s) * Matrix4x4.CreateFromQuaternion(r) * Matrix4x4.CreateTranslation(t);
                node["matrix"] = new JsonArray(m.M11, m.M12, m.M13, m.M14, m.M21, m.M22, m.M23, m.M24, m.M31, m.M32, m.M33, m.M34, m.M41, m.M42, m.M43, m.M44);
            }
            else
            {
                node["translation"] = new JsonArray(t.X, t.Y, t.Z);
                node["rotation"] = new JsonArray(r.X, r.Y, r.Z, r.W);
                if (s != 1f)
                {
                    node["scale"] = new JsonArray(s, s, s);
                }
            }

            int[] children = [.. Enumerable.Range(0, _nodes.Count).Where(c => _nodes[c].Parent == i)];
            if (children.Length > 0)
            {
                node["children"] = new JsonArray([.. children.Select(c => (JsonNode)c)]);
            }

            nodes.Add(node);
        }

        nodes.Add(new JsonObject { ["name"] = "Body", ["mesh"] = 0, ["skin"] = 0 });
        int[] sceneRoots = [.. Enumerable.Range(0, _nodes.Count).Where(i => _nodes[i].Parent < 0), _nodes.Count];
        var json = new JsonObject
        {
            ["asset"] = new JsonObject { ["version"] = "2.0", ["generator"] = "ForeignRig test exporter" },
            ["scene"] = 0,
            ["scenes"] = new JsonArray(new JsonObject { ["nodes"] = new JsonArray([.. sceneRoots.Select(i => (JsonNode)i)]) }),
            ["nodes"] = nodes,
            ["meshes"] = new JsonArray(new JsonObject
            {
                ["name"] = "Body",
                ["primitives"] = new JsonArray(new JsonObject { ["attributes"] = attributes, ["indices"] = indices, ["material"] = 0 }),
            }),
            ["materials"] = new JsonArray(new JsonObject
            {
                ["name"] = "Skin",
                ["pbrMetallicRoughness"] = new JsonObject { ["baseColorTexture"] = new JsonObject { ["index"] = 0 }, ["metallicFactor"] = 0f },
            }),
            ["textures"] = new JsonArray(new JsonObject { ["source"] = 0, ["sampler"] = 0 }),
            ["samplers"] = new JsonArray(new JsonObject { ["magFilter"] = 9729, ["minFilter"] = 9987 }),
            ["images"] = new JsonArray(image),
            ["skins"] = new JsonArray(new JsonObject { ["name"] = "Rig", ["joints"] = new JsonArray([.. joints.Select(j => (JsonNode)j)]), ["inverseBindMatrices"] = inverseBind }),
            ["bufferViews"] = views,
            ["accessors"] = accessors,
        };
        return (json, bin.ToArray());
    }

    private static Quaternion FromTo(Vector3 from, Vector3 to)
    {
        float dot = Vector3.Dot(from, to);
        if (dot < -0.9999f)
        {
            return Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI);
        }

        Vector3 axis = Vector3.Cross(from, to);
        return Quaternion.Normalize(new Quaternion(axis, 1f + dot));
    }
}
