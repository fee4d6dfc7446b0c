using System.Buffers.Binary;
using System.Globalization;
using System.Text;
using System.Text.Json;
using System.Text.Json.Nodes;

namespace Ballistic.Planner.Tests.Fuzz;

/// <summary>
/// Seeded mutations of input files, each written down so that a failure can be read and replayed: on bytes (bit
/// flips, byte runs, truncation, insertions, 32-bit fields rewritten with values at the edges of their range) and on
/// JSON (values swapped for other types, huge or edge numbers, small index shifts, removed or unknown keys, repeated
/// list items, repeated keys, deep nesting, hostile URIs). The same seed always gives the same mutations.
/// </summary>
internal sealed class Mutator(int seed)
{
    /// <summary>32-bit values at the edges: zero, one, sizes just off, signs, the overflow boundaries.</summary>
    public static readonly uint[] EdgeIntegers = [0, 1, 2, 3, 4, 7, 8, 12, 255, 256, 65535, 65536, 0x7FFFFFFF, 0x80000000, 0xFFFFFFF0, 0xFFFFFFFC, 0xFFFFFFFF, 150_000_000, 1_000_000];

    private static readonly double[] EdgeNumbers = [0, -0.0, 1, -1, 2, 3, 0.5, 1e-45, 1e-7, 1e30, -1e30, 1e38, 3.5e38, 1e300, -1e300, 2147483647, 2147483648, -2147483648, 4294967295, 4294967296, 9007199254740993, 150000000, 5126, 5125, 5123, 5121, 5120, 34962, 1e6, 1e7];

    private static readonly string[] EdgeStrings =
    [
        "", "x", "../../../../etc/passwd", "/etc/passwd", "%2e%2e/%2e%2e/etc/passwd", "..%2F..%2Fsecret.bin", "../secret.bin", "file:///etc/passwd",
        "http://example.com/a.bin", "a%00b.bin", "a\u0000b", "C:\\Windows\\win.ini", "\\\\server\\share\\x.bin", "data:application/octet-stream;base64,AAAA",
        "data:application/octet-stream;base64,!!!!", "data:,plain", "SCALAR", "VEC3", "MAT4", "VEC9", "2.0", "1.0", "KHR_draco_mesh_compression",
        "KHR_mesh_quantization", "foot", "hand", "paw", "+Z", "-Y", "up", "ballistic.character/1", "left_hip", "body", "image/png", "\uFFFF\uD800", "line\nbreak", "tab\there\r", new string('a', 5000),
    ];

    private readonly Random _random = new(seed);
    private readonly List<string> _log = [];
    private readonly List<(JsonObject Object, string Key)> _repeatedKeys = [];

    /// <summary>The seed the mutations come from.</summary>
    public int Seed { get; } = seed;

    /// <summary>What was done so far, in order.</summary>
    public string Description => _log.Count == 0 ? "(no mutation)" : string.Join("; ", _log);

    /// <summary>The random source, for callers choosing among strategies (and saying so with <see cref="Note"/>).</summary>
    public Random Random => _random;

    /// <summary>Writes <paramref name="text"/> into the description.</summary>
    public void Note(string text) => _log.Add(text);

    /// <summary><paramref name="rounds"/> byte-level mutations of a copy of <paramref name="input"/>.</summary>
    public byte[] Bytes(byte[] input, int rounds, string what)
    {
        var bytes = new List<byte>(input);
        for (int r = 0; r < rounds; r++)
        {
            int at = bytes.Count == 0 ? 0 : _random.Next(bytes.Count);
            switch (_random.Next(7))
            {
                case 0:
                case 1:
                    if (bytes.Count > 0)
                    {
                        int bit = _random.Next(8);
                        bytes[at] ^= (byte)(1 << bit);
                        _log.Add($"{what}: flip bit {bit} of byte {at}");
                    }

                    break;
                case 2:
                    {
                        int length = Math.Min(bytes.Count - at, 1 + _random.Next(64));
                        int fill = _random.Next(3);
                        for (int i = 0; i < length; i++)
                        {
                            bytes[at + i] = fill switch { 0 => 0, 1 => 0xFF, _ => (byte)_random.Next(256) };
                        }

                        _log.Add($"{what}: overwrite {length} bytes at {at} with {(fill == 0 ? "zeros" : fill == 1 ? "0xFF" : "random bytes")}");
                        break;
                    }

                case 3:
                    {
                        int keep = _random.Next(bytes.Count + 1);
                        bytes.RemoveRange(keep, bytes.Count - keep);
                        _log.Add($"{what}: truncate to {keep} bytes");
                        break;
                    }

                case 4:
                    {
                        int length = 1 + _random.Next(32);
                        byte[] insert = new byte[length];
                        _random.NextBytes(insert);
                        bytes.InsertRange(at, insert);
                        _log.Add($"{what}: insert {length} random bytes at {at}");
                        break;
                    }

                case 5:
                    {
                        int length = Math.Min(bytes.Count - at, 1 + _random.Next(32));
                        bytes.RemoveRange(at, length);
                        _log.Add($"{what}: delete {length} bytes at {at}");
                        break;
                    }

                default:
                    if (bytes.Count >= 4)
                    {
                        int aligned = Math.Min(at & ~3, bytes.Count - 4);
                        uint value = EdgeIntegers[_random.Next(EdgeIntegers.Length)];
                        byte[] array = [.. bytes];
                        BinaryPrimitives.WriteUInt32LittleEndian(array.AsSpan(aligned), value);
                        bytes = [.. array];
                        _log.Add($"{what}: write 0x{value:X8} at {aligned}");
                    }

                    break;
            }
        }

        return [.. bytes];
    }

    /// <summary>Rewrites the little-endian 32-bit field at <paramref name="offset"/> with an edge value or a nearby one.</summary>
    public void Field(byte[] bytes, int offset, string what)
    {
        uint old = BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan(offset));
        uint value = _random.Next(3) switch
        {
            0 => old + (uint)_random.Next(1, 5),
            1 => old - (uint)_random.Next(1, 5),
            _ => EdgeIntegers[_random.Next(EdgeIntegers.Length)],
        };
        BinaryPrimitives.WriteUInt32LittleEndian(bytes.AsSpan(offset), value);
        _log.Add($"{what} (byte {offset}): {old} → {value}");
    }

    /// <summary>Rewrites the little-endian float at <paramref name="offset"/> with NaN, an infinity, a huge, tiny or negative value.</summary>
    public void Float(byte[] bytes, int offset, string what)
    {
        float[] values = [float.NaN, float.PositiveInfinity, float.NegativeInfinity, 1e30f, -1e30f, 3.4e38f, 0f, -0f, -1f, 1e-45f, 1e7f, -1e7f];
        float value = values[_random.Next(values.Length)];
        float old = BinaryPrimitives.ReadSingleLittleEndian(bytes.AsSpan(offset));
        BinaryPrimitives.WriteSingleLittleEndian(bytes.AsSpan(offset), value);
        _log.Add(string.Create(CultureInfo.InvariantCulture, $"{what} (byte {offset}): {old} → {value}"));
    }

    /// <summary><paramref name="rounds"/> JSON mutations of <paramref name="root"/> (changed in place); serialise with <see cref="Serialize"/>.</summary>
    public void Json(JsonNode root, int rounds)
    {
        for (int r = 0; r < rounds; r++)
        {
            List<Slot> slots = Slots(root);
            if (slots.Count == 0)
            {
                return;
            }

            Slot slot = slots[_random.Next(slots.Count)];
            JsonNode? current = slot.Get();
            int choice = _random.Next(10);
            switch (choice)
            {
                case 0:
                    slot.Set(Other(slots));
                    _log.Add($"json: {slot.Path} ← {Show(slot.Get())}");
                    break;
                case 1:
                    slot.Set(JsonValue.Create(EdgeNumbers[_random.Next(EdgeNumbers.Length)]));
                    _log.Add($"json: {slot.Path} ← {Show(slot.Get())}");
                    break;
                case 2:
                    slot.Set(JsonValue.Create(EdgeStrings[_random.Next(EdgeStrings.Length)]));
                    _log.Add($"json: {slot.Path} ← {Show(slot.Get())}");
                    break;
                case 3 when current is JsonValue value && value.GetValueKind() == JsonValueKind.Number:
                    {
                        double d = double.Parse(value.ToJsonString(), CultureInfo.InvariantCulture);
                        double shifted = _random.Next(5) switch
                        {
                            0 => d + 1,
                            1 => d - 1,
                            2 => d * 2,
                            3 => -d,
                            _ => _random.Next((int)Math.Min(Math.Abs(d) * 2, 1000) + 3),
                        };
                        slot.Set(JsonValue.Create(shifted));
                        _log.Add(string.Create(CultureInfo.InvariantCulture, $"json: {slot.Path} {d} → {shifted}"));
                        break;
                    }

                case 4:
                    slot.Remove();
                    _log.Add($"json: remove {slot.Path}");
                    break;
                case 5 when slot.Parent is JsonArray array:
                    array.Insert(_random.Next(array.Count + 1), current?.DeepClone());
                    _log.Add($"json: repeat the item {slot.Path}");
                    break;
                case 6 when slot.Parent is JsonObject parent:
                    _repeatedKeys.Add((parent, slot.Key!));
                    _log.Add($"json: write the key {slot.Path} twice");
                    break;
                case 7:
                    {
                        int depth = 10 + _random.Next(300);
                        bool arrays = _random.Next(2) == 0;
                        JsonNode? nested = current?.DeepClone();
                        for (int i = 0; i < depth; i++)
                        {
                            nested = arrays ? new JsonArray(nested) : new JsonObject { ["n"] = nested };
                        }

                        slot.Set(nested);
                        _log.Add($"json: nest {slot.Path} {depth} {(arrays ? "lists" : "objects")} deep");
                        break;
                    }

                case 8 when current is JsonObject obj:
                    obj[(_random.Next(3) == 0 ? "unknown\nkey" : "unknownKey") + _random.Next(100)] = _random.Next(2) == 0 ? 1 : "x";
                    _log.Add($"json: add an unknown key to {slot.Path}");
                    break;
                case 8 when current is JsonArray list && list.Count > 1:
                    {
                        int a = _random.Next(list.Count);
                        int b = _random.Next(list.Count);
                        JsonNode? first = list[a]?.DeepClone();
                        list[a] = list[b]?.DeepClone();
                        list[b] = first;
                        _log.Add($"json: swap items {a} and {b} of {slot.Path}");
                        break;
                    }

                default:
                    {
                        JsonNode? replacement = _random.Next(6) switch
                        {
                            0 => null,
                            1 => JsonValue.Create(true),
                            2 => new JsonObject(),
                            3 => new JsonArray(),
                            4 => new JsonArray(0, 1, 2),
                            _ => new JsonArray([.. Enumerable.Range(0, 5000).Select(_ => (JsonNode?)JsonValue.Create(0))]),
                        };
                        slot.Set(replacement);
                        _log.Add($"json: {slot.Path} ← {Show(replacement)}");
                        break;
                    }
            }
        }
    }

    /// <summary><paramref name="root"/> as UTF-8 JSON, with the keys marked by <see cref="Json"/> written twice.</summary>
    public byte[] Serialize(JsonNode root)
    {
        using var stream = new MemoryStream();
        using (var writer = new Utf8JsonWriter(stream, new JsonWriterOptions { SkipValidation = true, MaxDepth = 4096 }))
        {
            Write(writer, root);
        }

        return stream.ToArray();
    }

    private void Write(Utf8JsonWriter writer, JsonNode? node)
    {
        switch (node)
        {
            case null:
                writer.WriteNullValue();
                break;
            case JsonObject obj:
                writer.WriteStartObject();
                foreach ((string key, JsonNode? value) in obj)
                {
                    int times = _repeatedKeys.Any(r => ReferenceEquals(r.Object, obj) && r.Key == key) ? 2 : 1;
                    for (int t = 0; t < times; t++)
                    {
                        writer.WritePropertyName(key);
                        Write(writer, value);
                    }
                }

                writer.WriteEndObject();
                break;
            case JsonArray array:
                writer.WriteStartArray();
                foreach (JsonNode? item in array)
                {
                    Write(writer, item);
                }

                writer.WriteEndArray();
                break;
            default:
                node.WriteTo(writer);
                break;
        }
    }

    private JsonNode? Other(List<Slot> slots) => slots[_random.Next(slots.Count)].Get()?.DeepClone();

    private static string Show(JsonNode? node)
    {
        string text = node?.ToJsonString() ?? "null";
        return text.Length > 60 ? text[..57] + "…" : text;
    }

    /// <summary>Every value of the tree with where it sits (the root itself excluded).</summary>
    private static List<Slot> Slots(JsonNode root)
    {
        var slots = new List<Slot>();
        var stack = new Stack<(JsonNode Node, string Path, int Depth)>();
        stack.Push((root, "$", 0));
        while (stack.Count > 0)
        {
            (JsonNode node, string path, int depth) = stack.Pop();
            if (depth > 40)
            {
                continue;
            }

            if (node is JsonObject obj)
            {
                foreach ((string key, JsonNode? value) in obj)
                {
                    slots.Add(new Slot(obj, key, -1, $"{path}.{key}"));
                    if (value is not null)
                    {
                        stack.Push((value, $"{path}.{key}", depth + 1));
                    }
                }
            }
            else if (node is JsonArray array)
            {
                for (int i = 0; i < array.Count; i++)
                {
                    slots.Add(new Slot(array, null, i, $"{path}[{i}]"));
                    if (array[i] is JsonNode item)
                    {
                        stack.Push((item, $"{path}[{i}]", depth + 1));
                    }
                }
            }
        }

        return slots;
    }

    /// <summary>A place in the tree: a key of an object or an index of a list.</summary>
    private sealed record Slot(JsonNode Parent, string? Key, int Index, string Path)
    {
        public JsonNode? Get() => Parent is JsonObject o ? o[Key!] : ((JsonArray)Parent)[Index];

        public void Set(JsonNode? value)
        {
            if (Parent is JsonObject o)
            {
                o[Key!] = value;
            }
            else
            {
                ((JsonArray)Parent)[Index] = value;
            }
        }

        public void Remove()
        {
            if (Parent is JsonObject o)
            {
                o.Remove(Key!);
            }
            else
            {
                ((JsonArray)Parent).RemoveAt(Index);
            }
        }
    }

    /// <summary>Encodes text as UTF-8 without a byte order mark.</summary>
    public static byte[] Utf8(string text) => new UTF8Encoding(false).GetBytes(text);
}
