using System.Buffers.Binary;
using System.Globalization;
using System.Numerics;
using System.Text.Json;
using System.Text.Json.Nodes;
using Ballistic.Planner.IO;

namespace Ballistic.Planner.Gltf;

/// <summary>
/// A glTF 2.0 asset read from a <c>.glb</c> or <c>.gltf</c> file (embedded, data-URI or external buffers): its JSON
/// and binary buffers, with typed access to accessors and node transforms. Levels and characters are read through
/// SharpGLTF (<see cref="GltfModel"/>); the animated GLB writer still copies a user's rig through this document,
/// parsed from the same bytes, until issue 25 moves the writer to SharpGLTF too.
/// Input is not trusted: only regular files are read, within <see cref="GltfLoadOptions"/>' limits; external
/// buffers and images only from the glTF's own folder or below; every count, offset and stride is checked against
/// the bytes it reads before anything is allocated; and every problem is a <see cref="GltfException"/> naming the
/// file, the element and what is wrong.
/// </summary>
internal sealed class GltfDocument
{
    private const uint GlbMagic = 0x46546C67;
    private const uint JsonChunk = 0x4E4F534A;
    private const uint BinChunk = 0x004E4942;

    private readonly List<ReadOnlyMemory<byte>> _buffers;
    private readonly long _bufferBytes;

    private GltfDocument(JsonObject root, List<ReadOnlyMemory<byte>> buffers, string name, string? directory, GltfLoadOptions options)
    {
        Root = root;
        _buffers = buffers;
        _bufferBytes = buffers.Sum(b => (long)b.Length);
        Name = name;
        Directory = directory;
        Options = options;
    }

    /// <summary>The glTF JSON.</summary>
    public JsonObject Root { get; }

    /// <summary>The file name, for messages.</summary>
    public string Name { get; }

    /// <summary>The folder against which external URIs (buffers, images) resolve, or <c>null</c> when they cannot.</summary>
    public string? Directory { get; }

    /// <summary>The limits the document was read with, which also bound what is read from it later (images, levels, skins).</summary>
    public GltfLoadOptions Options { get; }

    /// <summary>Number of binary buffers (the GLB binary chunk, data URIs and external files, in the file's order).</summary>
    public int BufferCount => _buffers.Count;

    /// <summary>Reads a <c>.glb</c> or <c>.gltf</c> file.</summary>
    /// <param name="path">The file; a symbolic link to a regular file is followed.</param>
    /// <param name="options">Limits on the bytes read; <c>null</c> for <see cref="GltfLoadOptions.Default"/>.</param>
    /// <exception cref="GltfException">
    /// The file is missing, not a regular file, larger than <see cref="GltfLoadOptions.MaxBytes"/>, malformed, needs
    /// an unsupported extension, or refers to a buffer it may not read.
    /// </exception>
    public static GltfDocument Load(string path, GltfLoadOptions? options = null)
    {
        ArgumentNullException.ThrowIfNull(path);
        options ??= GltfLoadOptions.Default;
        (byte[] bytes, string? directory) = GltfModel.ReadFile(path, options);
        return Parse(bytes, path, directory, options);
    }

    /// <summary>Parses glTF bytes (binary GLB or JSON).</summary>
    /// <param name="bytes">File content.</param>
    /// <param name="name">Name for messages.</param>
    /// <param name="directory">Folder against which external buffer URIs resolve; <c>null</c> forbids them.</param>
    /// <param name="options">Limits; <c>null</c> for <see cref="GltfLoadOptions.Default"/>. The bytes given count towards <see cref="GltfLoadOptions.MaxBytes"/>.</param>
    /// <exception cref="GltfException">The bytes are not a usable glTF 2.0 asset; the message names the element at fault.</exception>
    public static GltfDocument Parse(byte[] bytes, string name, string? directory, GltfLoadOptions? options = null)
    {
        ArgumentNullException.ThrowIfNull(bytes);
        ArgumentNullException.ThrowIfNull(name);
        options ??= GltfLoadOptions.Default;
        ReadOnlyMemory<byte>? binChunk = null;
        ReadOnlyMemory<byte> json;
        if (bytes.Length >= 4 && BinaryPrimitives.ReadUInt32LittleEndian(bytes) == GlbMagic)
        {
            (json, binChunk) = Chunks(bytes, name);
        }
        else
        {
            json = bytes;
        }

        JsonObject root = ParseJson(json, name);

        var buffers = new List<ReadOnlyMemory<byte>>();
        long budget = options.MaxBytes - bytes.Length;
        if (root["buffers"] is JsonNode bufferNode)
        {
            JsonArray bufferArray = bufferNode as JsonArray ?? throw new GltfException($"{name}: 'buffers' is {Describe(bufferNode)}, not a list.");
            for (int i = 0; i < bufferArray.Count; i++)
            {
                ReadOnlyMemory<byte> buffer = LoadBuffer(bufferArray[i], i, binChunk, name, directory, budget, options.MaxBytes);
                if (i != 0 || binChunk is null || bufferArray[i] is not JsonObject b || b["uri"] is not null)
                {
                    budget -= buffer.Length;
                }

                buffers.Add(buffer);
            }
        }

        return new GltfDocument(root, buffers, name, directory, options);
    }

    /// <summary>Array <paramref name="key"/> of the root, or an empty array when the key is missing.</summary>
    /// <exception cref="GltfException">The key holds something other than a list.</exception>
    public JsonArray Array(string key) => Root[key] switch
    {
        null => [],
        JsonArray array => array,
        JsonNode other => throw new GltfException($"{Name}: '{key}' is {Describe(other)}, not a list."),
    };

    /// <summary>The bytes of buffer <paramref name="index"/>.</summary>
    /// <exception cref="GltfException">There is no such buffer.</exception>
    public ReadOnlyMemory<byte> Buffer(int index) => index >= 0 && index < _buffers.Count
        ? _buffers[index]
        : throw new GltfException($"{Name}: buffer {index} does not exist.");

    /// <summary>The local transform of node <paramref name="node"/> (matrix, or translation · rotation · scale).</summary>
    /// <exception cref="GltfException">The node's matrix, translation, rotation or scale is not a list of finite numbers of the right length, or its rotation is zero.</exception>
    public Matrix4x4 LocalTransform(JsonObject node)
    {
        ArgumentNullException.ThrowIfNull(node);
        if (node["matrix"] is JsonNode matrix)
        {
            // glTF matrices are column-major with column vectors; System.Numerics uses row vectors, so the
            // column-major list read row by row is the System.Numerics matrix.
            float[] v = Numbers(matrix, 16, node, "matrix");
            return new Matrix4x4(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11], v[12], v[13], v[14], v[15]);
        }

        Vector3 t = node["translation"] is JsonNode tn ? Vector(Numbers(tn, 3, node, "translation")) : Vector3.Zero;
        Quaternion r = node["rotation"] is JsonNode rn && Numbers(rn, 4, node, "rotation") is float[] q ? new Quaternion(q[0], q[1], q[2], q[3]) : Quaternion.Identity;
        Vector3 s = node["scale"] is JsonNode sn ? Vector(Numbers(sn, 3, node, "scale")) : Vector3.One;
        return GltfModel.Trs(t, r, s) ?? throw new GltfException($"{Name}: {NodeName(node)} has a zero rotation quaternion.");

        static Vector3 Vector(float[] a) => new(a[0], a[1], a[2]);
    }

    /// <summary>The parent of every node (−1 for a node no other node lists as a child). Linear in the number of nodes.</summary>
    /// <exception cref="GltfException">A node is not an object, a child index is out of range, a node has two parents, or the hierarchy has a cycle.</exception>
    public int[] NodeParents()
    {
        JsonArray nodes = Array("nodes");
        int[] parents = new int[nodes.Count];
        System.Array.Fill(parents, -1);
        for (int n = 0; n < nodes.Count; n++)
        {
            JsonObject node = Node(n);
            if (node["children"] is null)
            {
                continue;
            }

            if (node["children"] is not JsonArray children)
            {
                throw new GltfException($"{Name}: node {n}'s children are {Describe(node["children"])}, not a list.");
            }

            foreach (JsonNode? child in children)
            {
                int c = child is JsonValue value && value.GetValueKind() == JsonValueKind.Number && value.TryGetValue(out int i) ? i : -1;
                if (c < 0 || c >= nodes.Count)
                {
                    throw new GltfException($"{Name}: node {n} lists child {Describe(child)}, which is not a node (there are {nodes.Count}).");
                }

                if (c == n)
                {
                    throw new GltfException($"{Name}: node {n} lists itself as a child.");
                }

                if (parents[c] == n)
                {
                    throw new GltfException($"{Name}: node {n} lists node {c} as a child twice.");
                }

                if (parents[c] >= 0)
                {
                    throw new GltfException($"{Name}: node {c} is a child of both node {parents[c]} and node {n}; a glTF node has at most one parent.");
                }

                parents[c] = n;
            }
        }

        // With one parent each, following parents from any node ends at a root or loops; mark each node once.
        byte[] state = new byte[nodes.Count]; // 0 unseen, 1 on the current path, 2 leads to a root
        var path = new List<int>();
        for (int n = 0; n < nodes.Count; n++)
        {
            path.Clear();
            int p = n;
            while (p >= 0 && state[p] == 0)
            {
                state[p] = 1;
                path.Add(p);
                p = parents[p];
            }

            if (p >= 0 && state[p] == 1)
            {
                throw new GltfException($"{Name}: the node hierarchy has a cycle through node {p}.");
            }

            foreach (int q in path)
            {
                state[q] = 2;
            }
        }

        return parents;
    }

    /// <summary>Every node's rest transform in the scene (its local transform times its ancestors'), row-vector convention.</summary>
    /// <exception cref="GltfException">The hierarchy or a node's transform is malformed.</exception>
    public Matrix4x4[] WorldTransforms() => GltfModel.Compose(NodeParents(), n => LocalTransform(Node(n)));

    /// <summary>The encoded bytes of image <paramref name="index"/> (from a buffer view, a data URI or a file in the glTF's folder) and its MIME type.</summary>
    /// <exception cref="GltfException">The image is missing, cannot be read, or its URI leads out of the glTF's folder.</exception>
    public (byte[] Bytes, string MimeType) ReadImage(int index)
    {
        JsonArray images = Array("images");
        if (index < 0 || index >= images.Count || images[index] is not JsonObject image)
        {
            throw new GltfException($"{Name}: image {index} does not exist.");
        }

        string? mime = image["mimeType"] is null ? null : Text(image["mimeType"]) ?? throw new GltfException($"{Name}: image {index}'s mimeType is {Describe(image["mimeType"])}, not a string.");
        if (image["bufferView"] is not null)
        {
            int view = RequiredIndex(image, "bufferView", $"image {index}");
            (ReadOnlyMemory<byte> buffer, long offset, long length, _) = View(view);
            return (buffer.Span.Slice((int)offset, (int)length).ToArray(), mime ?? throw new GltfException($"{Name}: image {index} is in a buffer view but has no mimeType."));
        }

        string uri = image["uri"] is null
            ? throw new GltfException($"{Name}: image {index} has neither a uri nor a bufferView.")
            : Text(image["uri"]) ?? throw new GltfException($"{Name}: image {index}'s uri is {Describe(image["uri"])}, not a string.");
        if (uri.StartsWith("data:", StringComparison.OrdinalIgnoreCase))
        {
            byte[] data = DataUri(uri, Name, $"image {index}");
            return (data, mime ?? MimeOf(uri));
        }

        if (Directory is null)
        {
            throw new GltfException($"{Name}: image {index} refers to the external file '{uri}', which cannot be resolved here.");
        }

        string path = ReferencedFile.Resolve(Directory, uri, problem => new GltfException($"{Name}: image {index}'s URI '{MessageText.Printable(uri)}' {problem}."));
        mime ??= Path.GetExtension(path).ToLowerInvariant() switch
        {
            ".png" => "image/png",
            ".jpg" or ".jpeg" => "image/jpeg",
            ".webp" => "image/webp",
            ".ktx2" => "image/ktx2",
            _ => throw new GltfException($"{Name}: image {index} ('{MessageText.Printable(uri)}') has no mimeType and an unknown file extension."),
        };
        byte[] bytes = InputFile.Read(path, Options.MaxBytes, "GltfLoadOptions.MaxBytes", (problem, e) => new GltfException($"{Name}: image {index}'s file '{MessageText.Printable(uri)}' {problem}.", e!));
        return (bytes, mime);

        static string MimeOf(string uri)
        {
            int semicolon = uri.IndexOf(';', StringComparison.Ordinal);
            return semicolon > 5 ? uri[5..semicolon] : "application/octet-stream";
        }
    }

    /// <summary>Reads accessor <paramref name="index"/> as floats, <paramref name="components"/> per element.</summary>
    /// <exception cref="GltfException">The accessor is missing, of another shape, or runs past its buffer view or buffer.</exception>
    public float[] ReadFloats(int index, int components)
    {
        Layout layout = AccessorLayout(index);
        if (layout.Components != components)
        {
            throw new GltfException($"{Name}: accessor {index} has {layout.Components} components per element, expected {components}.");
        }

        float[] result = new float[layout.Count * components];
        int type = layout.ComponentType;
        bool normalized = layout.Normalized;
        Read(layout, index, (i, v) => result[i] = Convert(v, type, normalized));
        return result;
    }

    /// <summary>Reads accessor <paramref name="index"/> as unsigned integers (indices, joint ids).</summary>
    /// <exception cref="GltfException">The accessor is missing, holds no unsigned integers, holds a value above 2³¹ − 1, or runs past its buffer view or buffer.</exception>
    public int[] ReadIntegers(int index)
    {
        Layout layout = AccessorLayout(index);
        if (layout.ComponentType is not (5121 or 5123 or 5125))
        {
            throw new GltfException($"{Name}: accessor {index} holds component type {layout.ComponentType}, not unsigned integers.");
        }

        int[] result = new int[layout.Count * layout.Components];
        Read(layout, index, (i, v) => result[i] = v <= int.MaxValue
            ? (int)v
            : throw new GltfException(string.Create(CultureInfo.InvariantCulture, $"{Name}: accessor {index} holds the value {v} at element {i / layout.Components}, too large for an index.")));
        return result;
    }

    /// <summary>The number of elements accessor <paramref name="index"/> declares, checked against its data.</summary>
    /// <exception cref="GltfException">The accessor is missing or malformed.</exception>
    internal int ElementCount(int index) => AccessorLayout(index).Count;

    /// <summary>Node <paramref name="index"/> as an object.</summary>
    /// <exception cref="GltfException">The node does not exist or is not an object.</exception>
    internal JsonObject Node(int index)
    {
        JsonArray nodes = Array("nodes");
        return index < 0 || index >= nodes.Count
            ? throw new GltfException($"{Name}: node {index} does not exist (there are {nodes.Count}).")
            : nodes[index] as JsonObject ?? throw new GltfException($"{Name}: node {index} is {Describe(nodes[index])}, not an object.");
    }

    /// <summary>Integer <paramref name="key"/> of <paramref name="json"/>, 0 or more; an error naming <paramref name="what"/> when it is missing or not one.</summary>
    internal int RequiredIndex(JsonObject json, string key, string what) =>
        OptionalIndex(json, key, what) ?? throw new GltfException($"{Name}: {what} has no '{key}'.");

    /// <summary>Integer <paramref name="key"/> of <paramref name="json"/>, 0 or more, or <c>null</c> when missing; an error naming <paramref name="what"/> when it is something else.</summary>
    internal int? OptionalIndex(JsonObject json, string key, string what)
    {
        JsonNode? node = json[key];
        if (node is null)
        {
            return null;
        }

        return node is JsonValue value && value.GetValueKind() == JsonValueKind.Number && value.TryGetValue(out int i) && i >= 0
            ? i
            : throw new GltfException($"{Name}: {what} has '{key}' {Describe(node)}, not a whole number of at least 0.");
    }

    /// <summary>String <paramref name="key"/> of <paramref name="json"/>, or <c>null</c> when missing; an error naming <paramref name="what"/> when it is not a string.</summary>
    internal string? OptionalText(JsonObject json, string key, string what) => json[key] switch
    {
        null => null,
        JsonNode node => Text(node) ?? throw new GltfException($"{Name}: {what} has '{key}' {Describe(node)}, not a string."),
    };

    /// <summary>A short description of a JSON value for messages: "the string \"x\"", "the number 2.0", "a list of 3", "an object", "null".</summary>
    internal static string Describe(JsonNode? node)
    {
        static string Clip(string s) => s.Length > 40 ? s[..37] + "…" : s;
        return node switch
        {
            null => "null",
            JsonObject => "an object",
            JsonArray a => a.Count == 0 ? "an empty list" : $"a list of {a.Count}",
            JsonValue v => v.GetValueKind() switch
            {
                JsonValueKind.String => $"the string {Clip(MessageText.Printable(v.ToJsonString()))}",
                JsonValueKind.Number => $"the number {Clip(v.ToJsonString())}",
                _ => v.ToJsonString(),
            },
            _ => "an unknown value",
        };
    }

    private static (ReadOnlyMemory<byte> Json, ReadOnlyMemory<byte>? Bin) Chunks(byte[] bytes, string name)
    {
        if (bytes.Length < 12)
        {
            throw new GltfException($"{name} is truncated: a GLB file starts with a 12-byte header, but it holds {bytes.Length} bytes.");
        }

        uint version = BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan(4));
        if (version != 2)
        {
            throw new GltfException($"{name} is GLB version {version}; only glTF 2.0 is supported.");
        }

        uint declared = BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan(8));
        if (declared > (uint)bytes.Length)
        {
            throw new GltfException($"{name} is truncated: its GLB header declares {declared} bytes, but the file holds {bytes.Length}.");
        }

        long end = Math.Max(declared, 12u);
        long offset = 12;
        int chunk = 0;
        ReadOnlyMemory<byte>? json = null;
        ReadOnlyMemory<byte>? bin = null;
        while (offset + 8 <= end)
        {
            uint length = BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan((int)offset));
            uint type = BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan((int)offset + 4));
            if (length > end - offset - 8)
            {
                throw new GltfException($"{name} is truncated or corrupt: GLB chunk {chunk} at byte {offset} declares {length} bytes, but only {end - offset - 8} follow.");
            }

            var data = new ReadOnlyMemory<byte>(bytes, (int)offset + 8, (int)length);
            if (chunk == 0 && type != JsonChunk)
            {
                throw new GltfException($"{name} is not a valid GLB file: its first chunk is not JSON.");
            }

            if (type == JsonChunk && json is null)
            {
                json = data;
            }
            else if (type == BinChunk && bin is null)
            {
                bin = data;
            }

            offset += 8 + length;
            chunk++;
        }

        return json is ReadOnlyMemory<byte> j ? (j, bin) : throw new GltfException($"{name} is a GLB file without a JSON chunk.");
    }

    private static JsonObject ParseJson(ReadOnlyMemory<byte> json, string name)
    {
        if (json.Span.StartsWith("\uFEFF"u8))
        {
            json = json[3..]; // a byte order mark, which glTF forbids but some tools write
        }

        if (!System.Text.Unicode.Utf8.IsValid(json.Span))
        {
            throw new GltfException($"{name} is not a glTF file: its JSON is not valid UTF-8 text.");
        }

        // The same checks as a level's (SharpGLTF's reader): parses, an object, no key twice, a glTF 2.0 asset with
        // extensions we read, a node hierarchy one parent each, without cycles, at most GltfModel.MaxNodeDepth deep.
        GltfModel.CheckJson(System.Text.Encoding.UTF8.GetString(json.Span), name);
        return (JsonObject)JsonNode.Parse(json.Span)!;
    }

    private static ReadOnlyMemory<byte> LoadBuffer(JsonNode? node, int index, ReadOnlyMemory<byte>? binChunk, string name, string? directory, long budget, long maxBytes)
    {
        if (node is not JsonObject buffer)
        {
            throw new GltfException($"{name}: buffer {index} is {Describe(node)}, not an object.");
        }

        long length = buffer["byteLength"] is JsonValue lv && lv.GetValueKind() == JsonValueKind.Number && lv.TryGetValue(out long l) && l >= 0
            ? l
            : throw new GltfException($"{name}: buffer {index} has {(buffer["byteLength"] is null ? "no byteLength" : $"byteLength {Describe(buffer["byteLength"])}")}, not a whole number of bytes.");
        ReadOnlyMemory<byte> data;
        if (buffer["uri"] is null)
        {
            // The GLB's binary chunk: part of the file, already counted.
            data = index == 0 && binChunk is ReadOnlyMemory<byte> bin
                ? bin
                : throw new GltfException($"{name}: buffer {index} has no URI and there is no GLB binary chunk for it.");
        }
        else
        {
            if (length > budget)
            {
                throw new GltfException($"{name}: buffer {index} declares {length} bytes, more than the {Math.Max(budget, 0)} bytes left within the limit of {maxBytes} (GltfLoadOptions.MaxBytes).");
            }

            string uri = Text(buffer["uri"]) ?? throw new GltfException($"{name}: buffer {index}'s uri is {Describe(buffer["uri"])}, not a string.");
            if (uri.StartsWith("data:", StringComparison.OrdinalIgnoreCase))
            {
                data = DataUri(uri, name, $"buffer {index}");
                if (data.Length > budget)
                {
                    throw new GltfException($"{name}: buffer {index}'s data URI holds {data.Length} bytes, more than the {Math.Max(budget, 0)} bytes left within the limit of {maxBytes} (GltfLoadOptions.MaxBytes).");
                }
            }
            else
            {
                if (directory is null)
                {
                    throw new GltfException($"{name}: buffer {index} refers to the external file '{MessageText.Printable(uri)}', which cannot be resolved here.");
                }

                string path = ReferencedFile.Resolve(directory, uri, problem => new GltfException($"{name}: buffer {index}'s URI '{MessageText.Printable(uri)}' {problem}."));
                data = InputFile.Read(path, Math.Max(budget, 0), $"what is left of the limit of {maxBytes} with the glTF and its other buffers, GltfLoadOptions.MaxBytes", (problem, e) => new GltfException($"{name}: buffer {index}'s file '{MessageText.Printable(uri)}' {problem}.", e!));
            }
        }

        if (data.Length < length)
        {
            throw new GltfException($"{name}: buffer {index} holds {data.Length} bytes but declares {length} (the file is truncated).");
        }

        return data;
    }

    private static byte[] DataUri(string uri, string name, string what)
    {
        int comma = uri.IndexOf(',', StringComparison.Ordinal);
        if (comma < 0 || !uri[..comma].EndsWith(";base64", StringComparison.OrdinalIgnoreCase))
        {
            throw new GltfException($"{name}: {what} has a data URI that is not base64.");
        }

        try
        {
            return System.Convert.FromBase64String(uri[(comma + 1)..]);
        }
        catch (FormatException e)
        {
            throw new GltfException($"{name}: {what} has a malformed base64 data URI.", e);
        }
    }

    /// <summary>How accessor <paramref name="index"/> lies in its buffer, every number checked against the bytes it reads.</summary>
    private Layout AccessorLayout(int index)
    {
        JsonArray accessors = Array("accessors");
        if (index < 0 || index >= accessors.Count)
        {
            throw new GltfException($"{Name}: accessor {index} does not exist (there are {accessors.Count}).");
        }

        string what = $"accessor {index}";
        JsonObject accessor = accessors[index] as JsonObject ?? throw new GltfException($"{Name}: {what} is {Describe(accessors[index])}, not an object.");
        int count = RequiredIndex(accessor, "count", what);
        int componentType = RequiredIndex(accessor, "componentType", what);
        int size = ComponentSize(componentType) ?? throw new GltfException($"{Name}: {what} has the unknown componentType {componentType}.");
        string? type = OptionalText(accessor, "type", what);
        int components = ComponentsOf(type) ?? throw new GltfException($"{Name}: {what} has {(type is null ? "no type" : $"the unknown type '{MessageText.Printable(type)}'")}; expected SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3 or MAT4.");
        bool normalized = accessor["normalized"] switch
        {
            null => false,
            JsonValue v when v.GetValueKind() is JsonValueKind.True or JsonValueKind.False => v.GetValue<bool>(),
            JsonNode other => throw new GltfException($"{Name}: {what} has 'normalized' {Describe(other)}, not true or false."),
        };
        long elementSize = (long)size * components;
        var layout = new Layout(count, components, componentType, normalized, null, 0, 0);
        if (accessor["bufferView"] is not null)
        {
            int viewIndex = RequiredIndex(accessor, "bufferView", what);
            int offset = OptionalIndex(accessor, "byteOffset", what) ?? 0;
            (ReadOnlyMemory<byte> buffer, long viewOffset, long viewLength, int stride) = View(viewIndex);
            if (stride > 0 && stride < elementSize)
            {
                throw new GltfException($"{Name}: {what} has {elementSize}-byte elements, but buffer view {viewIndex}'s byteStride is {stride}.");
            }

            long step = stride > 0 ? stride : elementSize;
            if (count > 0 && offset + ((count - 1) * step) + elementSize > viewLength)
            {
                throw new GltfException($"{Name}: {what} reads past the end of buffer view {viewIndex}: {count} elements of {elementSize} bytes{(stride > 0 ? $" every {stride} bytes" : "")} from byte {offset} need {offset + ((count - 1) * step) + elementSize} bytes, but the view holds {viewLength}.");
            }

            layout = layout with { Buffer = buffer, Start = viewOffset + offset, Step = step };
        }
        else if (count * elementSize > _bufferBytes)
        {
            // Without a buffer view the elements are zeros (a sparse part may set some): no more than the file's data could describe.
            throw new GltfException($"{Name}: {what} declares {count} elements without a buffer view, more than the file's {_bufferBytes} bytes of buffers could give values to.");
        }

        if (count * elementSize > System.Array.MaxLength || (long)count * components * 4 > System.Array.MaxLength)
        {
            throw new GltfException($"{Name}: {what} declares {count} elements, too many to read.");
        }

        if (accessor["sparse"] is JsonNode sparseNode)
        {
            layout = layout with { Sparse = Sparse(sparseNode, index, count, elementSize) };
        }

        return layout;
    }

    private SparseLayout Sparse(JsonNode node, int index, int count, long elementSize)
    {
        string what = $"the sparse part of accessor {index}";
        JsonObject sparse = node as JsonObject ?? throw new GltfException($"{Name}: {what} is {Describe(node)}, not an object.");
        int sparseCount = RequiredIndex(sparse, "count", what);
        if (sparseCount > count)
        {
            throw new GltfException($"{Name}: {what} replaces {sparseCount} elements, but the accessor has {count}.");
        }

        JsonObject indices = sparse["indices"] as JsonObject ?? throw new GltfException($"{Name}: {what} has no indices object.");
        JsonObject values = sparse["values"] as JsonObject ?? throw new GltfException($"{Name}: {what} has no values object.");
        string iw = what + "'s indices";
        string vw = what + "'s values";
        int indexType = RequiredIndex(indices, "componentType", iw);
        if (indexType is not (5121 or 5123 or 5125))
        {
            throw new GltfException($"{Name}: {iw} have component type {indexType}, not unsigned integers.");
        }

        int indexSize = ComponentSize(indexType) ?? 4;
        int indexView = RequiredIndex(indices, "bufferView", iw);
        int valueView = RequiredIndex(values, "bufferView", vw);
        (ReadOnlyMemory<byte> ib, long io, long il, _) = View(indexView);
        (ReadOnlyMemory<byte> vb, long vo, long vl, _) = View(valueView);
        long indexOffset = OptionalIndex(indices, "byteOffset", iw) ?? 0;
        long valueOffset = OptionalIndex(values, "byteOffset", vw) ?? 0;
        if (indexOffset + ((long)sparseCount * indexSize) > il)
        {
            throw new GltfException($"{Name}: {iw} run past the end of buffer view {indexView}.");
        }

        if (valueOffset + (sparseCount * elementSize) > vl)
        {
            throw new GltfException($"{Name}: {vw} run past the end of buffer view {valueView}.");
        }

        return new SparseLayout(sparseCount, indexType, ib, io + indexOffset, vb, vo + valueOffset);
    }

    private void Read(Layout layout, int index, Action<int, double> store)
    {
        int size = ComponentSize(layout.ComponentType) ?? 4;
        int components = layout.Components;
        if (layout.Buffer is ReadOnlyMemory<byte> memory)
        {
            ReadOnlySpan<byte> buffer = memory.Span;
            for (int e = 0; e < layout.Count; e++)
            {
                int at = (int)(layout.Start + (e * layout.Step));
                for (int c = 0; c < components; c++)
                {
                    store((e * components) + c, ReadComponent(buffer, at + (c * size), layout.ComponentType));
                }
            }
        }

        if (layout.Sparse is SparseLayout sparse)
        {
            ReadOnlySpan<byte> indices = sparse.Indices.Span;
            ReadOnlySpan<byte> values = sparse.Values.Span;
            int indexSize = ComponentSize(sparse.IndexType) ?? 4;
            for (int k = 0; k < sparse.Count; k++)
            {
                double element = ReadComponent(indices, (int)(sparse.IndexStart + (k * indexSize)), sparse.IndexType);
                if (element >= layout.Count)
                {
                    throw new GltfException(string.Create(CultureInfo.InvariantCulture, $"{Name}: sparse index {k} of accessor {index} is {element}, but the accessor has {layout.Count} elements."));
                }

                for (int c = 0; c < components; c++)
                {
                    store(((int)element * components) + c, ReadComponent(values, (int)(sparse.ValueStart + (((k * components) + c) * size)), layout.ComponentType));
                }
            }
        }
    }

    private (ReadOnlyMemory<byte> Buffer, long Offset, long Length, int Stride) View(int viewIndex)
    {
        JsonArray views = Array("bufferViews");
        if (viewIndex < 0 || viewIndex >= views.Count)
        {
            throw new GltfException($"{Name}: buffer view {viewIndex} does not exist (there are {views.Count}).");
        }

        string what = $"buffer view {viewIndex}";
        JsonObject view = views[viewIndex] as JsonObject ?? throw new GltfException($"{Name}: {what} is {Describe(views[viewIndex])}, not an object.");
        int bufferIndex = RequiredIndex(view, "buffer", what);
        if (bufferIndex >= _buffers.Count)
        {
            throw new GltfException($"{Name}: {what} names buffer {bufferIndex}, which does not exist (there are {_buffers.Count}).");
        }

        ReadOnlyMemory<byte> buffer = _buffers[bufferIndex];
        long offset = OptionalIndex(view, "byteOffset", what) ?? 0;
        long length = RequiredIndex(view, "byteLength", what);
        if (offset + length > buffer.Length)
        {
            throw new GltfException($"{Name}: {what} runs past the end of buffer {bufferIndex}: bytes {offset} to {offset + length} of {buffer.Length} (the file may be truncated).");
        }

        int stride = OptionalIndex(view, "byteStride", what) ?? 0;
        return (buffer, offset, length, stride);
    }

    private float[] Numbers(JsonNode node, int count, JsonObject owner, string key)
    {
        if (node is JsonArray array && array.Count == count)
        {
            float[] values = new float[count];
            bool ok = true;
            for (int i = 0; i < count && ok; i++)
            {
                double d = 0;
                ok = array[i] is JsonValue v && v.GetValueKind() == JsonValueKind.Number && v.TryGetValue(out d) && float.IsFinite((float)d);
                values[i] = (float)d;
            }

            if (ok)
            {
                return values;
            }
        }

        throw new GltfException($"{Name}: {NodeName(owner)} has a malformed {key}: it must be a list of {count} finite numbers.");
    }

    /// <summary>"node 'hip'" for messages, or "node 3" when the node has no name.</summary>
    private string NodeName(JsonObject node)
    {
        if (Text(node["name"]) is string name)
        {
            return $"node '{MessageText.Printable(name)}'";
        }

        JsonArray nodes = Array("nodes");
        for (int i = 0; i < nodes.Count; i++)
        {
            if (ReferenceEquals(nodes[i], node))
            {
                return $"node {i}";
            }
        }

        return "a node";
    }

    private static double ReadComponent(ReadOnlySpan<byte> buffer, int at, int componentType) => componentType switch
    {
        5120 => (sbyte)buffer[at],
        5121 => buffer[at],
        5122 => BinaryPrimitives.ReadInt16LittleEndian(buffer[at..]),
        5123 => BinaryPrimitives.ReadUInt16LittleEndian(buffer[at..]),
        5125 => BinaryPrimitives.ReadUInt32LittleEndian(buffer[at..]),
        _ => BinaryPrimitives.ReadSingleLittleEndian(buffer[at..]),
    };

    private static float Convert(double value, int componentType, bool normalized) => !normalized ? (float)value : componentType switch
    {
        5120 => (float)Math.Max(value / 127.0, -1.0),
        5121 => (float)(value / 255.0),
        5122 => (float)Math.Max(value / 32767.0, -1.0),
        5123 => (float)(value / 65535.0),
        _ => (float)value,
    };

    private static int? ComponentSize(int componentType) => componentType switch
    {
        5120 or 5121 => 1,
        5122 or 5123 => 2,
        5125 or 5126 => 4,
        _ => null,
    };

    private static int? ComponentsOf(string? type) => type switch
    {
        "SCALAR" => 1,
        "VEC2" => 2,
        "VEC3" => 3,
        "VEC4" => 4,
        "MAT2" => 4,
        "MAT3" => 9,
        "MAT4" => 16,
        _ => null,
    };

    private static string? Text(JsonNode? node) => node is JsonValue value && value.GetValueKind() == JsonValueKind.String ? value.GetValue<string>() : null;

    private sealed record SparseLayout(int Count, int IndexType, ReadOnlyMemory<byte> Indices, long IndexStart, ReadOnlyMemory<byte> Values, long ValueStart);

    private sealed record Layout(int Count, int Components, int ComponentType, bool Normalized, ReadOnlyMemory<byte>? Buffer, long Start, long Step)
    {
        public SparseLayout? Sparse { get; init; }
    }
}
