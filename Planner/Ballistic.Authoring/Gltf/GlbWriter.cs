using System.Buffers.Binary;
using System.Numerics;
using System.Text;
using System.Text.Json;
using System.Text.Json.Nodes;
using Ballistic.Planner.Gltf;
using Ballistic.Planner.IO;

namespace Ballistic.Authoring.Gltf;

/// <summary>
/// Builds a binary glTF 2.0 (<c>.glb</c>) file: one binary buffer, accessors appended to it, and the JSON objects
/// (meshes, nodes, materials, scenes…) added by the caller. Output is deterministic: the same calls give the same bytes.
/// </summary>
public sealed class GlbWriter
{
    private readonly MemoryStream _binary = new();
    private readonly JsonArray _bufferViews = [];
    private readonly JsonArray _accessors = [];

    /// <summary>The JSON root; <c>asset</c>, <c>buffers</c>, <c>bufferViews</c> and <c>accessors</c> are filled in by the writer.</summary>
    public JsonObject Root { get; } = new()
    {
        ["asset"] = new JsonObject { ["version"] = "2.0", ["generator"] = "Ballistic" },
    };

    /// <summary>
    /// A writer holding a copy of <paramref name="document"/>: its JSON (scenes, nodes, meshes, materials, textures,
    /// skins, animations…) with every buffer merged into the one binary buffer and every image embedded in it, so the
    /// result is a self-contained GLB. Accessor and buffer view indices are kept, so the copied JSON stays valid;
    /// further accessors and objects are appended after them.
    /// </summary>
    /// <exception cref="GltfException">A buffer or image cannot be read, or the file uses an extension whose data cannot be moved (EXT_meshopt_compression).</exception>
    internal static GlbWriter From(GltfDocument document)
    {
        ArgumentNullException.ThrowIfNull(document);
        if (document.Array("extensionsUsed").Any(e => e is JsonValue v && v.TryGetValue(out string? id) && id == "EXT_meshopt_compression"))
        {
            throw new GltfException($"{document.Name} uses EXT_meshopt_compression; export it without compression.");
        }

        var writer = new GlbWriter();
        foreach ((string key, JsonNode? value) in document.Root)
        {
            if (key is not ("buffers" or "bufferViews" or "accessors"))
            {
                writer.Root[key] = value?.DeepClone();
            }
        }

        if (writer.Root["asset"] is JsonObject asset)
        {
            asset["generator"] = "Ballistic";
        }

        long[] bases = new long[document.BufferCount];
        for (int b = 0; b < bases.Length; b++)
        {
            bases[b] = writer.Append(document.Buffer(b).Span);
        }

        for (int v = 0; v < document.Array("bufferViews").Count; v++)
        {
            if (document.Array("bufferViews")[v] is not JsonObject view || view["buffer"] is not JsonValue bv || !bv.TryGetValue(out int buffer) || buffer < 0 || buffer >= bases.Length)
            {
                throw new GltfException($"{document.Name}: buffer view {v} does not name an existing buffer.");
            }

            var copy = (JsonObject)view.DeepClone();
            copy["buffer"] = 0;
            copy["byteOffset"] = bases[buffer] + ((view["byteOffset"] as JsonValue)?.TryGetValue(out long o) == true ? o : 0L);
            writer._bufferViews.Add(copy);
        }

        foreach (JsonNode? accessor in document.Array("accessors"))
        {
            writer._accessors.Add(accessor?.DeepClone());
        }

        if (writer.Root["images"] is JsonArray images)
        {
            for (int i = 0; i < images.Count; i++)
            {
                if (images[i] is JsonObject image && image["uri"] is not null)
                {
                    (byte[] bytes, string mime) = document.ReadImage(i);
                    image.Remove("uri");
                    image["bufferView"] = writer.AddView(bytes, null);
                    image["mimeType"] = mime;
                }
            }
        }

        return writer;
    }

    /// <summary>Appends <paramref name="item"/> to root array <paramref name="key"/> (created when missing) and returns its index.</summary>
    public int Add(string key, JsonObject item)
    {
        if (Root[key] is not JsonArray array)
        {
            array = [];
            Root[key] = array;
        }

        array.Add(item);
        return array.Count - 1;
    }

    /// <summary>
    /// Puts <paramref name="item"/> first in root array <paramref name="key"/> (created when missing), the items
    /// already there after it in their order. Only for arrays nothing refers to by index (animations).
    /// </summary>
    public void AddFirst(string key, JsonObject item)
    {
        if (Root[key] is not JsonArray array)
        {
            array = [];
            Root[key] = array;
        }

        array.Insert(0, item);
    }

    /// <summary>Adds a VEC3 float accessor (with the min and max glTF requires for positions).</summary>
    public int AddVector3(ReadOnlySpan<Vector3> values, int? target = 34962)
    {
        float[] flat = new float[values.Length * 3];
        Vector3 min = new(float.PositiveInfinity);
        Vector3 max = new(float.NegativeInfinity);
        for (int i = 0; i < values.Length; i++)
        {
            flat[3 * i] = values[i].X;
            flat[(3 * i) + 1] = values[i].Y;
            flat[(3 * i) + 2] = values[i].Z;
            min = Vector3.Min(min, values[i]);
            max = Vector3.Max(max, values[i]);
        }

        int view = AddView(Floats(flat), target);
        var accessor = new JsonObject
        {
            ["bufferView"] = view,
            ["componentType"] = 5126,
            ["count"] = values.Length,
            ["type"] = "VEC3",
        };
        if (values.Length > 0)
        {
            accessor["min"] = new JsonArray(min.X, min.Y, min.Z);
            accessor["max"] = new JsonArray(max.X, max.Y, max.Z);
        }

        _accessors.Add(accessor);
        return _accessors.Count - 1;
    }

    /// <summary>Adds a float accessor of <paramref name="type"/> (SCALAR, VEC2, VEC4, MAT4…) with min and max.</summary>
    public int AddFloats(ReadOnlySpan<float> values, string type, int components, int? target = null)
    {
        int count = values.Length / components;
        var min = new JsonArray();
        var max = new JsonArray();
        for (int c = 0; c < components; c++)
        {
            float lo = float.PositiveInfinity;
            float hi = float.NegativeInfinity;
            for (int i = 0; i < count; i++)
            {
                lo = MathF.Min(lo, values[(i * components) + c]);
                hi = MathF.Max(hi, values[(i * components) + c]);
            }

            min.Add(lo);
            max.Add(hi);
        }

        int view = AddView(Floats(values), target);
        var accessor = new JsonObject { ["bufferView"] = view, ["componentType"] = 5126, ["count"] = count, ["type"] = type };
        if (count > 0)
        {
            accessor["min"] = min;
            accessor["max"] = max;
        }

        _accessors.Add(accessor);
        return _accessors.Count - 1;
    }

    /// <summary>Adds a triangle index accessor (16-bit when every index fits, else 32-bit).</summary>
    public int AddIndices(ReadOnlySpan<int> indices)
    {
        int largest = 0;
        foreach (int i in indices)
        {
            largest = Math.Max(largest, i);
        }

        bool small = largest < 65535;
        byte[] bytes = new byte[indices.Length * (small ? 2 : 4)];
        for (int i = 0; i < indices.Length; i++)
        {
            if (small)
            {
                BinaryPrimitives.WriteUInt16LittleEndian(bytes.AsSpan(2 * i), (ushort)indices[i]);
            }
            else
            {
                BinaryPrimitives.WriteUInt32LittleEndian(bytes.AsSpan(4 * i), (uint)indices[i]);
            }
        }

        int view = AddView(bytes, 34963);
        _accessors.Add(new JsonObject { ["bufferView"] = view, ["componentType"] = small ? 5123 : 5125, ["count"] = indices.Length, ["type"] = "SCALAR" });
        return _accessors.Count - 1;
    }

    /// <summary>Adds an unsigned-byte VEC4 accessor (skin joint indices).</summary>
    public int AddJoints(ReadOnlySpan<byte> joints)
    {
        int view = AddView(joints.ToArray(), 34962);
        _accessors.Add(new JsonObject { ["bufferView"] = view, ["componentType"] = 5121, ["count"] = joints.Length / 4, ["type"] = "VEC4" });
        return _accessors.Count - 1;
    }

    /// <summary>The finished file.</summary>
    public byte[] ToBytes()
    {
        byte[] bin = _binary.ToArray();
        Root["buffers"] = new JsonArray(new JsonObject { ["byteLength"] = bin.Length });
        Root["bufferViews"] = _bufferViews.DeepClone();
        Root["accessors"] = _accessors.DeepClone();
        byte[] json = Utf8(Root.ToJsonString(new JsonSerializerOptions { WriteIndented = false }));
        int jsonPadded = Pad4(json.Length);
        int binPadded = Pad4(bin.Length);
        int total = 12 + 8 + jsonPadded + (bin.Length > 0 ? 8 + binPadded : 0);
        byte[] file = new byte[total];
        BinaryPrimitives.WriteUInt32LittleEndian(file, 0x46546C67);
        BinaryPrimitives.WriteUInt32LittleEndian(file.AsSpan(4), 2);
        BinaryPrimitives.WriteUInt32LittleEndian(file.AsSpan(8), (uint)total);
        BinaryPrimitives.WriteUInt32LittleEndian(file.AsSpan(12), (uint)jsonPadded);
        BinaryPrimitives.WriteUInt32LittleEndian(file.AsSpan(16), 0x4E4F534A);
        json.CopyTo(file, 20);
        file.AsSpan(20 + json.Length, jsonPadded - json.Length).Fill((byte)' ');
        if (bin.Length > 0)
        {
            int at = 20 + jsonPadded;
            BinaryPrimitives.WriteUInt32LittleEndian(file.AsSpan(at), (uint)binPadded);
            BinaryPrimitives.WriteUInt32LittleEndian(file.AsSpan(at + 4), 0x004E4942);
            bin.CopyTo(file, at + 8);
        }

        return file;
    }

    /// <summary>Writes the file to <paramref name="path"/>, creating its folder.</summary>
    public void Save(string path)
    {
        ArgumentNullException.ThrowIfNull(path);
        OutputFile.Write(path, ToBytes());
    }

    private long Append(ReadOnlySpan<byte> bytes)
    {
        while (_binary.Length % 4 != 0)
        {
            _binary.WriteByte(0);
        }

        long at = _binary.Length;
        _binary.Write(bytes);
        return at;
    }

    private int AddView(byte[] bytes, int? target)
    {
        while (_binary.Length % 4 != 0)
        {
            _binary.WriteByte(0);
        }

        var view = new JsonObject { ["buffer"] = 0, ["byteOffset"] = _binary.Length, ["byteLength"] = bytes.Length };
        if (target is int t)
        {
            view["target"] = t;
        }

        _binary.Write(bytes);
        _bufferViews.Add(view);
        return _bufferViews.Count - 1;
    }

    private static byte[] Floats(ReadOnlySpan<float> values)
    {
        byte[] bytes = new byte[values.Length * 4];
        for (int i = 0; i < values.Length; i++)
        {
            if (!float.IsFinite(values[i]))
            {
                throw new GltfException($"Cannot write value {values[i]} (element {i}) to glTF: every number must be finite.");
            }

            BinaryPrimitives.WriteSingleLittleEndian(bytes.AsSpan(4 * i), values[i]);
        }

        return bytes;
    }

    /// <summary>Encodes <paramref name="text"/> as UTF-8 without a byte order mark (for GLB JSON chunks).</summary>
    private static byte[] Utf8(string text) => new UTF8Encoding(false).GetBytes(text);

    private static int Pad4(int n) => (n + 3) & ~3;
}
