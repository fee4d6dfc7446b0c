using System.Buffers.Binary;
using System.Numerics;
using System.Text;
using System.Text.Json;
using System.Text.Json.Nodes;

namespace Ballistic.Planner.Gltf;

/// <summary>
/// A glTF 2.0 asset read from a <c>.glb</c> or <c>.gltf</c> file (embedded, data-URI or external buffers): its JSON
/// and binary buffers, with typed access to accessors and node transforms. Written for this project because no
/// glTF library is available from the package registry it builds against; it reads what levels and characters
/// need (meshes, node hierarchies, materials, skins) and refuses compressed extensions with a clear message.
/// </summary>
public sealed class GltfDocument
{
    private static readonly HashSet<string> SupportedRequiredExtensions = ["KHR_mesh_quantization", "KHR_materials_emissive_strength"];

    private readonly List<byte[]> _buffers;

    private GltfDocument(JsonObject root, List<byte[]> buffers, string name, string? directory)
    {
        Root = root;
        _buffers = buffers;
        Name = name;
        Directory = directory;
    }

    /// <summary>The glTF JSON.</summary>
    public JsonObject Root { get; }

    /// <summary>The file name, for messages.</summary>
    public string Name { get; }

    /// <summary>The folder against which external URIs (buffers, images) resolve, or <c>null</c> when they cannot.</summary>
    public string? Directory { get; }

    /// <summary>Number of binary buffers (the GLB binary chunk, data URIs and external files, in the file's order).</summary>
    public int BufferCount => _buffers.Count;

    /// <summary>Reads a <c>.glb</c> or <c>.gltf</c> file.</summary>
    /// <exception cref="GltfException">The file is missing, malformed, or needs an unsupported extension.</exception>
    public static GltfDocument Load(string path)
    {
        ArgumentNullException.ThrowIfNull(path);
        byte[] bytes;
        try
        {
            bytes = File.ReadAllBytes(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new GltfException($"{path} cannot be read: {e.Message}", e);
        }

        return Parse(bytes, path, Path.GetDirectoryName(Path.GetFullPath(path)));
    }

    /// <summary>Parses glTF bytes (binary GLB or JSON).</summary>
    /// <param name="bytes">File content.</param>
    /// <param name="name">Name for messages.</param>
    /// <param name="directory">Folder against which external buffer URIs resolve; <c>null</c> forbids them.</param>
    public static GltfDocument Parse(byte[] bytes, string name, string? directory)
    {
        ArgumentNullException.ThrowIfNull(bytes);
        byte[]? binChunk = null;
        ReadOnlySpan<byte> json;
        if (bytes.Length >= 12 && BinaryPrimitives.ReadUInt32LittleEndian(bytes) == 0x46546C67)
        {
            uint version = BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan(4));
            if (version != 2)
            {
                throw new GltfException($"{name} is GLB version {version}; only glTF 2.0 is supported.");
            }

            int offset = 12;
            json = default;
            bool haveJson = false;
            while (offset + 8 <= bytes.Length)
            {
                int length = checked((int)BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan(offset)));
                uint type = BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan(offset + 4));
                if (length < 0 || offset + 8 + length > bytes.Length)
                {
                    throw new GltfException($"{name} is truncated: a GLB chunk runs past the end of the file.");
                }

                if (type == 0x4E4F534A && !haveJson)
                {
                    json = bytes.AsSpan(offset + 8, length);
                    haveJson = true;
                }
                else if (type == 0x004E4942 && binChunk is null)
                {
                    binChunk = bytes.AsSpan(offset + 8, length).ToArray();
                }

                offset += 8 + length;
            }

            if (!haveJson)
            {
                throw new GltfException($"{name} is a GLB file without a JSON chunk.");
            }
        }
        else
        {
            json = bytes;
        }

        JsonObject root;
        try
        {
            root = JsonNode.Parse(json) as JsonObject ?? throw new GltfException($"{name} is not a glTF file: its JSON is not an object.");
        }
        catch (JsonException e)
        {
            throw new GltfException($"{name} is not a glTF file: {e.Message}", e);
        }

        CheckUniqueKeys(root, name);

        string? assetVersion = Text((root["asset"] as JsonObject)?["version"]);
        if (assetVersion is null || !assetVersion.StartsWith("2.", StringComparison.Ordinal))
        {
            throw new GltfException($"{name} is not a glTF 2.0 asset (asset.version is '{assetVersion ?? "missing"}').");
        }

        if (root["extensionsRequired"] is JsonArray required)
        {
            foreach (JsonNode? extension in required)
            {
                string id = Text(extension) ?? "";
                if (!SupportedRequiredExtensions.Contains(id))
                {
                    throw new GltfException($"{name} requires the glTF extension {id}, which Ballistic cannot read; export it without compression.");
                }
            }
        }

        var buffers = new List<byte[]>();
        if (root["buffers"] is JsonArray bufferArray)
        {
            for (int i = 0; i < bufferArray.Count; i++)
            {
                buffers.Add(LoadBuffer(bufferArray[i] as JsonObject, i, binChunk, name, directory));
            }
        }

        return new GltfDocument(root, buffers, name, directory);
    }

    /// <summary>Array <paramref name="key"/> of the root, or an empty array.</summary>
    public JsonArray Array(string key) => Root[key] as JsonArray ?? [];

    /// <summary>The bytes of buffer <paramref name="index"/>.</summary>
    public ReadOnlyMemory<byte> Buffer(int index) => index >= 0 && index < _buffers.Count
        ? _buffers[index]
        : throw new GltfException($"{Name}: buffer {index} does not exist.");

    /// <summary>The local transform of node <paramref name="node"/> (matrix, or translation · rotation · scale).</summary>
    /// <exception cref="GltfException">The node's matrix, translation, rotation or scale is not a list of numbers of the right length.</exception>
    public Matrix4x4 LocalTransform(JsonObject node)
    {
        ArgumentNullException.ThrowIfNull(node);
        string what = Text(node["name"]) is string name ? $"node '{name}'" : "a node";
        if (node["matrix"] is JsonNode matrix)
        {
            // glTF matrices are column-major with column vectors; System.Numerics uses row vectors, so the
            // column-major list read row by row is the System.Numerics matrix.
            float[] v = Numbers(matrix, 16, what, "matrix");
            return new Matrix4x4(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11], v[12], v[13], v[14], v[15]);
        }

        Vector3 t = node["translation"] is JsonNode tn ? Vector(Numbers(tn, 3, what, "translation")) : Vector3.Zero;
        Quaternion r = Quaternion.Identity;
        if (node["rotation"] is JsonNode rn)
        {
            float[] q = Numbers(rn, 4, what, "rotation");
            r = new Quaternion(q[0], q[1], q[2], q[3]);
            if (!(r.Length() > 1e-6f))
            {
                throw new GltfException($"{Name}: {what} has a zero rotation quaternion.");
            }

            r = Quaternion.Normalize(r);
        }

        Vector3 s = node["scale"] is JsonNode sn ? Vector(Numbers(sn, 3, what, "scale")) : Vector3.One;
        return Matrix4x4.CreateScale(s) * Matrix4x4.CreateFromQuaternion(r) * Matrix4x4.CreateTranslation(t);

        static Vector3 Vector(float[] a) => new(a[0], a[1], a[2]);
    }

    /// <summary>The parent of every node (−1 for a node no other node lists as a child).</summary>
    /// <exception cref="GltfException">A child index is out of range, a node has two parents, or the hierarchy has a cycle.</exception>
    public int[] NodeParents()
    {
        JsonArray nodes = Array("nodes");
        int[] parents = new int[nodes.Count];
        System.Array.Fill(parents, -1);
        for (int n = 0; n < nodes.Count; n++)
        {
            if (nodes[n] is not JsonObject node)
            {
                throw new GltfException($"{Name}: node {n} is not an object.");
            }

            if (node["children"] is null)
            {
                continue;
            }

            if (node["children"] is not JsonArray children)
            {
                throw new GltfException($"{Name}: node {n}'s children are not a list.");
            }

            foreach (JsonNode? child in children)
            {
                int c = child is JsonValue value && value.TryGetValue(out int i) ? i : -1;
                if (c < 0 || c >= nodes.Count)
                {
                    throw new GltfException($"{Name}: node {n} lists child {child?.ToJsonString() ?? "null"}, which is not a node.");
                }

                if (c == n)
                {
                    throw new GltfException($"{Name}: node {n} lists itself as a child.");
                }

                if (parents[c] >= 0)
                {
                    throw new GltfException($"{Name}: node {c} has more than one parent.");
                }

                parents[c] = n;
            }
        }

        for (int n = 0; n < nodes.Count; n++)
        {
            int steps = 0;
            for (int p = parents[n]; p >= 0; p = parents[p])
            {
                if (++steps > nodes.Count)
                {
                    throw new GltfException($"{Name}: the node hierarchy has a cycle through node {n}.");
                }
            }
        }

        return parents;
    }

    /// <summary>Every node's rest transform in the scene (its local transform times its ancestors'), row-vector convention.</summary>
    public Matrix4x4[] WorldTransforms()
    {
        int[] parents = NodeParents();
        JsonArray nodes = Array("nodes");
        var world = new Matrix4x4[nodes.Count];
        var done = new bool[nodes.Count];
        for (int n = 0; n < nodes.Count; n++)
        {
            Resolve(n);
        }

        return world;

        void Resolve(int n)
        {
            if (done[n])
            {
                return;
            }

            Matrix4x4 local = LocalTransform((JsonObject)nodes[n]!);
            if (parents[n] >= 0)
            {
                Resolve(parents[n]);
                local *= world[parents[n]];
            }

            world[n] = local;
            done[n] = true;
        }
    }

    /// <summary>The encoded bytes of image <paramref name="index"/> (from a buffer view, a data URI or a file beside the glTF) and its MIME type.</summary>
    /// <exception cref="GltfException">The image is missing or cannot be read.</exception>
    public (byte[] Bytes, string MimeType) ReadImage(int index)
    {
        JsonArray images = Array("images");
        if (index < 0 || index >= images.Count || images[index] is not JsonObject image)
        {
            throw new GltfException($"{Name}: image {index} does not exist.");
        }

        string? mime = Text(image["mimeType"]);
        if (image["bufferView"] is JsonNode viewNode)
        {
            int view = viewNode is JsonValue v && v.TryGetValue(out int i) ? i : throw new GltfException($"{Name}: image {index} has a malformed bufferView.");
            (byte[] buffer, int offset, int length, _) = View(view);
            return (buffer.AsSpan(offset, length).ToArray(), mime ?? throw new GltfException($"{Name}: image {index} is in a buffer view but has no mimeType."));
        }

        string uri = Text(image["uri"]) ?? throw new GltfException($"{Name}: image {index} has neither a uri nor a bufferView.");
        if (uri.StartsWith("data:", StringComparison.Ordinal))
        {
            int comma = uri.IndexOf(',', StringComparison.Ordinal);
            if (comma < 0 || !uri[..comma].EndsWith(";base64", StringComparison.Ordinal))
            {
                throw new GltfException($"{Name}: image {index} has a data URI that is not base64.");
            }

            try
            {
                return (System.Convert.FromBase64String(uri[(comma + 1)..]), mime ?? uri[5..uri.IndexOf(';', StringComparison.Ordinal)]);
            }
            catch (FormatException e)
            {
                throw new GltfException($"{Name}: image {index} has a malformed base64 data URI.", e);
            }
        }

        if (Directory is null)
        {
            throw new GltfException($"{Name}: image {index} refers to the external file '{uri}', which cannot be resolved here.");
        }

        string extension = Path.GetExtension(uri).ToLowerInvariant();
        mime ??= extension switch
        {
            ".png" => "image/png",
            ".jpg" or ".jpeg" => "image/jpeg",
            ".webp" => "image/webp",
            ".ktx2" => "image/ktx2",
            _ => throw new GltfException($"{Name}: image {index} ('{uri}') has no mimeType and an unknown file extension."),
        };
        try
        {
            return (File.ReadAllBytes(Path.Combine(Directory, Uri.UnescapeDataString(uri))), mime);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new GltfException($"{Name}: image {index} file '{uri}' cannot be read: {e.Message}", e);
        }
    }

    /// <summary>Reads accessor <paramref name="index"/> as floats, <paramref name="components"/> per element.</summary>
    /// <exception cref="GltfException">The accessor is missing, of another shape, or runs past its buffer.</exception>
    public float[] ReadFloats(int index, int components)
    {
        JsonObject accessor = Accessor(index);
        int count = Int(accessor, "count", $"accessor {index}");
        int actual = ComponentsOf(Text(accessor["type"]));
        if (actual != components)
        {
            throw new GltfException($"{Name}: accessor {index} has {actual} components per element, expected {components}.");
        }

        int componentType = Int(accessor, "componentType", $"accessor {index}");
        bool normalized = (accessor["normalized"] as JsonValue)?.TryGetValue(out bool n) == true && n;
        float[] result = new float[count * components];
        if (accessor["bufferView"] is not null)
        {
            ReadComponents(accessor, index, count, components, componentType, (i, v) => result[i] = Convert(v, componentType, normalized));
        }

        ApplySparse(accessor, index, components, componentType, (i, v) => result[i] = Convert(v, componentType, normalized));
        return result;
    }

    /// <summary>Reads accessor <paramref name="index"/> as unsigned integers (indices, joint ids).</summary>
    public int[] ReadIntegers(int index)
    {
        JsonObject accessor = Accessor(index);
        int count = Int(accessor, "count", $"accessor {index}");
        int components = ComponentsOf(Text(accessor["type"]));
        int componentType = Int(accessor, "componentType", $"accessor {index}");
        if (componentType is not (5121 or 5123 or 5125))
        {
            throw new GltfException($"{Name}: accessor {index} holds component type {componentType}, not unsigned integers.");
        }

        int[] result = new int[count * components];
        if (accessor["bufferView"] is not null)
        {
            ReadComponents(accessor, index, count, components, componentType, (i, v) => result[i] = checked((int)v));
        }

        ApplySparse(accessor, index, components, componentType, (i, v) => result[i] = checked((int)v));
        return result;
    }

    private JsonObject Accessor(int index)
    {
        JsonArray accessors = Array("accessors");
        return index >= 0 && index < accessors.Count && accessors[index] is JsonObject a
            ? a
            : throw new GltfException($"{Name}: accessor {index} does not exist.");
    }

    private void ReadComponents(JsonObject accessor, int index, int count, int components, int componentType, Action<int, double> store)
    {
        int viewIndex = Int(accessor, "bufferView", $"accessor {index}");
        int accessorOffset = accessor["byteOffset"] is null ? 0 : Int(accessor, "byteOffset", $"accessor {index}");
        (byte[] buffer, int viewOffset, int viewLength, int stride) = View(viewIndex);
        int size = ComponentSize(componentType);
        int elementSize = size * components;
        int step = stride > 0 ? stride : elementSize;
        if (count > 0 && accessorOffset + ((long)(count - 1) * step) + elementSize > viewLength)
        {
            throw new GltfException($"{Name}: accessor {index} reads past the end of buffer view {viewIndex}.");
        }

        for (int e = 0; e < count; e++)
        {
            int at = viewOffset + accessorOffset + (e * step);
            for (int c = 0; c < components; c++)
            {
                store((e * components) + c, ReadComponent(buffer, at + (c * size), componentType));
            }
        }
    }

    private void ApplySparse(JsonObject accessor, int index, int components, int componentType, Action<int, double> store)
    {
        if (accessor["sparse"] is not JsonObject sparse)
        {
            return;
        }

        string what = $"the sparse part of accessor {index}";
        int count = Int(sparse, "count", what);
        JsonObject indices = sparse["indices"] as JsonObject ?? throw new GltfException($"{Name}: {what} has no indices.");
        JsonObject values = sparse["values"] as JsonObject ?? throw new GltfException($"{Name}: {what} has no values.");
        (byte[] ib, int io, int il, _) = View(Int(indices, "bufferView", what + "'s indices"));
        (byte[] vb, int vo, int vl, _) = View(Int(values, "bufferView", what + "'s values"));
        int indexType = Int(indices, "componentType", what + "'s indices");
        io += indices["byteOffset"] is null ? 0 : Int(indices, "byteOffset", what + "'s indices");
        vo += values["byteOffset"] is null ? 0 : Int(values, "byteOffset", what + "'s values");
        int size = ComponentSize(componentType);
        if ((long)count * ComponentSize(indexType) > il || (long)count * components * size > vl)
        {
            throw new GltfException($"{Name}: the sparse part of accessor {index} runs past its buffer view.");
        }

        for (int k = 0; k < count; k++)
        {
            int element = checked((int)ReadComponent(ib, io + (k * ComponentSize(indexType)), indexType));
            for (int c = 0; c < components; c++)
            {
                store((element * components) + c, ReadComponent(vb, vo + (((k * components) + c) * size), componentType));
            }
        }
    }

    private (byte[] Buffer, int Offset, int Length, int Stride) View(int viewIndex)
    {
        JsonArray views = Array("bufferViews");
        if (viewIndex < 0 || viewIndex >= views.Count || views[viewIndex] is not JsonObject view)
        {
            throw new GltfException($"{Name}: buffer view {viewIndex} does not exist.");
        }

        int bufferIndex = Int(view, "buffer", $"buffer view {viewIndex}");
        if (bufferIndex < 0 || bufferIndex >= _buffers.Count)
        {
            throw new GltfException($"{Name}: buffer view {viewIndex} names buffer {bufferIndex}, which does not exist.");
        }

        byte[] buffer = _buffers[bufferIndex];
        int offset = view["byteOffset"] is null ? 0 : Int(view, "byteOffset", $"buffer view {viewIndex}");
        int length = Int(view, "byteLength", $"buffer view {viewIndex}");
        if (offset < 0 || length < 0 || (long)offset + length > buffer.Length)
        {
            throw new GltfException($"{Name}: buffer view {viewIndex} runs past the end of buffer {bufferIndex} (the file may be truncated).");
        }

        return (buffer, offset, length, view["byteStride"] is null ? 0 : Int(view, "byteStride", $"buffer view {viewIndex}"));
    }

    private int Int(JsonObject json, string key, string what) =>
        json[key] is JsonValue value && value.TryGetValue(out int i)
            ? i
            : throw new GltfException($"{Name}: {what} has {(json[key] is null ? "no" : "a malformed")} '{key}'.");

    private float[] Numbers(JsonNode node, int count, string what, string key)
    {
        if (node is JsonArray array && array.Count == count)
        {
            float[] values = new float[count];
            for (int i = 0; i < count; i++)
            {
                if (array[i] is not JsonValue v || !v.TryGetValue(out float f) || !float.IsFinite(f))
                {
                    break;
                }

                values[i] = f;
                if (i == count - 1)
                {
                    return values;
                }
            }
        }

        throw new GltfException($"{Name}: {what} has a malformed {key}: it must be a list of {count} finite numbers.");
    }

    private static double ReadComponent(byte[] buffer, int at, int componentType) => componentType switch
    {
        5120 => (sbyte)buffer[at],
        5121 => buffer[at],
        5122 => BinaryPrimitives.ReadInt16LittleEndian(buffer.AsSpan(at)),
        5123 => BinaryPrimitives.ReadUInt16LittleEndian(buffer.AsSpan(at)),
        5125 => BinaryPrimitives.ReadUInt32LittleEndian(buffer.AsSpan(at)),
        5126 => BinaryPrimitives.ReadSingleLittleEndian(buffer.AsSpan(at)),
        _ => throw new GltfException($"Unknown glTF component type {componentType}."),
    };

    private static float Convert(double value, int componentType, bool normalized) => !normalized ? (float)value : componentType switch
    {
        5120 => (float)Math.Max(value / 127.0, -1.0),
        5121 => (float)(value / 255.0),
        5122 => (float)Math.Max(value / 32767.0, -1.0),
        5123 => (float)(value / 65535.0),
        _ => (float)value,
    };

    private static int ComponentSize(int componentType) => componentType switch
    {
        5120 or 5121 => 1,
        5122 or 5123 => 2,
        5125 or 5126 => 4,
        _ => throw new GltfException($"Unknown glTF component type {componentType}."),
    };

    private static int ComponentsOf(string? type) => type switch
    {
        "SCALAR" => 1,
        "VEC2" => 2,
        "VEC3" => 3,
        "VEC4" => 4,
        "MAT2" => 4,
        "MAT3" => 9,
        "MAT4" => 16,
        _ => throw new GltfException($"Unknown glTF accessor type '{type}'."),
    };

    private static byte[] LoadBuffer(JsonObject? buffer, int index, byte[]? binChunk, string name, string? directory)
    {
        if (buffer is null)
        {
            throw new GltfException($"{name}: buffer {index} is not an object.");
        }

        int length = (buffer["byteLength"] as JsonValue)?.TryGetValue(out int l) == true ? l : 0;
        string? uri = Text(buffer["uri"]);
        byte[] data;
        if (uri is null)
        {
            data = index == 0 && binChunk is not null
                ? binChunk
                : throw new GltfException($"{name}: buffer {index} has no URI and there is no GLB binary chunk for it.");
        }
        else if (uri.StartsWith("data:", StringComparison.Ordinal))
        {
            int comma = uri.IndexOf(',', StringComparison.Ordinal);
            if (comma < 0 || !uri[..comma].EndsWith(";base64", StringComparison.Ordinal))
            {
                throw new GltfException($"{name}: buffer {index} has a data URI that is not base64.");
            }

            try
            {
                data = System.Convert.FromBase64String(uri[(comma + 1)..]);
            }
            catch (FormatException e)
            {
                throw new GltfException($"{name}: buffer {index} has a malformed base64 data URI.", e);
            }
        }
        else
        {
            if (directory is null)
            {
                throw new GltfException($"{name}: buffer {index} refers to the external file '{uri}', which cannot be resolved here.");
            }

            string path = Path.Combine(directory, Uri.UnescapeDataString(uri));
            try
            {
                data = File.ReadAllBytes(path);
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                throw new GltfException($"{name}: buffer {index} file '{uri}' cannot be read: {e.Message}", e);
            }
        }

        if (data.Length < length)
        {
            throw new GltfException($"{name}: buffer {index} holds {data.Length} bytes but declares {length} (the file is truncated).");
        }

        return data;
    }

    /// <summary>Reads every object of the tree so that a repeated key fails here, with the file's name, rather than later.</summary>
    private static void CheckUniqueKeys(JsonNode? node, string name)
    {
        switch (node)
        {
            case JsonObject o:
                try
                {
                    foreach (KeyValuePair<string, JsonNode?> property in o)
                    {
                        CheckUniqueKeys(property.Value, name);
                    }
                }
                catch (ArgumentException e) when (e is not ArgumentNullException)
                {
                    throw new GltfException($"{name}: an object at {o.GetPath()} repeats a key ({e.Message}).", e);
                }

                break;
            case JsonArray a:
                foreach (JsonNode? item in a)
                {
                    CheckUniqueKeys(item, name);
                }

                break;
        }
    }

    private static string? Text(JsonNode? node) => node is JsonValue value && value.TryGetValue(out string? text) ? text : null;

    /// <summary>Encodes <paramref name="text"/> as UTF-8 without a byte order mark (for GLB JSON chunks).</summary>
    internal static byte[] Utf8(string text) => new UTF8Encoding(false).GetBytes(text);
}
