using System.Numerics;
using System.Text.Json;
using System.Text.Json.Nodes;
using Ballistic.Planner.Characters;
using Ballistic.Planner.IO;

namespace Ballistic.Planner.Rigs;

/// <summary>One limb of a limb spec as written: what the spec leaves out is <c>null</c> (derived later).</summary>
internal sealed record LimbSpec(string Name, string RootBone, string EffectorBone, Vector3? EffectorOffset, Vector3? ContactNormal, LimbKind Kind, NormalFilter? Filter);

/// <summary>A limb spec as written, checked for keys, types and ranges but not yet against a rig.</summary>
internal sealed record CharacterSpec(
    string Name,
    Vector3 UpAxis,
    Vector3 ForwardAxis,
    int? RequiredContacts,
    float? TakeoffSpeedMax,
    float? LandingSpeedMax,
    float? Friction,
    float? WalkSpeed,
    float? MaxSlope,
    float? MaxSlopeAlong,
    float? StepHeight,
    IReadOnlyList<string>? TrunkBones,
    IReadOnlyList<LimbSpec> Limbs,
    IReadOnlyDictionary<string, JointAxis[]> Joints,
    float? BoneRadius,
    IReadOnlyDictionary<string, float> BoneRadii,
    IReadOnlyDictionary<string, IReadOnlyList<(string Bone, float[] Degrees)>> Poses,
    string? Rig = null);

/// <summary>
/// Reads a <c>ballistic.character/1</c> limb spec strictly: unknown keys, wrong JSON types, unknown values and
/// out-of-range numbers are <see cref="RigException"/>s naming the file, the limb or bone and the key.
/// </summary>
internal sealed class CharacterSpecReader
{
    /// <summary>Axis names accepted by <c>upAxis</c> and <c>forwardAxis</c>, with their directions.</summary>
    internal static readonly IReadOnlyDictionary<string, Vector3> AxisNames = new Dictionary<string, Vector3>(StringComparer.Ordinal)
    {
        ["+X"] = Vector3.UnitX,
        ["-X"] = -Vector3.UnitX,
        ["+Y"] = Vector3.UnitY,
        ["-Y"] = -Vector3.UnitY,
        ["+Z"] = Vector3.UnitZ,
        ["-Z"] = -Vector3.UnitZ,
    };

    /// <summary>The largest magnitude of a length (metres), speed (m/s), friction or vector component a spec may give.</summary>
    internal const float MaxMagnitude = 1e3f;

    /// <summary>The most limbs a spec may name: a centipede's legs fit; a spec of thousands (a 3,000-limb one baked for 139 s) is refused.</summary>
    internal const int MaxLimbs = 128;

    /// <summary>The widest joint limit a spec may give, degrees either way.</summary>
    internal const float MaxDegrees = 360f;

    private static readonly string[] TopKeys = ["schema", "name", "upAxis", "forwardAxis", "requiredContacts", "takeoffSpeedMax", "landingSpeedMax", "friction", "walkSpeed", "maxSlope", "maxSlopeAlong", "stepHeight", "trunkBones", "limbs", "joints", "boneRadius", "boneRadii", "poses", "rig"];
    private static readonly string[] LimbKeys = ["rootBone", "effectorBone", "effectorOffset", "contactNormal", "contact", "normalFilter"];
    private static readonly string[] FilterKeys = ["direction", "minCosine"];
    private static readonly string[] JointKeys = ["axes"];
    private static readonly string[] AxisKeys = ["axis", "min", "max"];
    private static readonly string[] PoseNames = ["contact", "flexion", "extending"];

    private readonly string _file;

    private CharacterSpecReader(string file) => _file = file;

    /// <summary>Parses and checks the spec's bytes; <paramref name="file"/> names it in messages.</summary>
    /// <exception cref="RigException">The spec is not valid JSON or breaks the schema.</exception>
    public static CharacterSpec Read(byte[] bytes, string file)
    {
        var reader = new CharacterSpecReader(file);
        if (!System.Text.Unicode.Utf8.IsValid(bytes))
        {
            throw new RigException($"{file} is not valid JSON: it is not UTF-8 text.");
        }

        JsonNode? root;
        try
        {
            using (var document = JsonDocument.Parse(bytes))
            {
                reader.CheckUniqueKeys(document.RootElement, "");
            }

            root = JsonNode.Parse(bytes);
        }
        catch (JsonException e)
        {
            throw new RigException($"{file} is not valid JSON: {MessageText.Json(e)}.", e);
        }

        return reader.Read(root);
    }

    /// <summary>The error for <paramref name="where"/> (e.g. "limb 'left_foot', key 'contact'").</summary>
    public RigException Error(string where, string problem) => new($"{_file}: {where}: {problem}");

    private CharacterSpec Read(JsonNode? node)
    {
        if (node is not JsonObject root)
        {
            throw new RigException($"{_file} is not a Ballistic limb spec: its JSON is {Describe(node)}, not an object.");
        }

        string schema = root["schema"] is JsonNode s ? Text(s, "key 'schema'") : "";
        if (schema != CharacterSpecFile.Schema)
        {
            throw new RigException($"{_file} is not a Ballistic limb spec (schema '{schema}', expected '{CharacterSpecFile.Schema}').");
        }

        Keys(root, "the spec", TopKeys);
        string name = root["name"] is JsonNode n ? Text(n, "key 'name'") : Path.GetFileNameWithoutExtension(_file).Replace(".limbs", "", StringComparison.Ordinal);
        if (string.IsNullOrWhiteSpace(name))
        {
            throw Error("key 'name'", "must not be empty.");
        }

        Vector3 up = Axis(root, "upAxis", Vector3.UnitY);
        Vector3 forward = Axis(root, "forwardAxis", Vector3.UnitZ);
        if (MathF.Abs(Vector3.Dot(up, forward)) > 0.5f)
        {
            throw Error("keys 'upAxis' and 'forwardAxis'", $"must name perpendicular axes, not both along {AxisName(up)[1..]}.");
        }

        JsonObject limbsJson = root["limbs"] is JsonNode l ? Object(l, "key 'limbs'") : throw Error("key 'limbs'", "is missing: a character needs at least one limb.");
        if (limbsJson.Count == 0)
        {
            throw Error("key 'limbs'", "is empty: a character needs at least one limb.");
        }

        if (limbsJson.Count > MaxLimbs)
        {
            throw Error("key 'limbs'", $"names {limbsJson.Count} limbs, more than the {MaxLimbs} a character may have (every stance estimates a contact per limb: a bake's cost grows with them).");
        }

        var limbs = new List<LimbSpec>();
        foreach ((string limbName, JsonNode? limbNode) in limbsJson)
        {
            limbs.Add(Limb(limbName, limbNode));
        }

        int? required = root["requiredContacts"] is JsonNode rc ? Integer(rc, "key 'requiredContacts'") : null;
        if (required is int r && (r < 1 || r > limbs.Count))
        {
            throw Error("key 'requiredContacts'", $"{r} required contacts, but the spec has {limbs.Count} limb{(limbs.Count == 1 ? "" : "s")} (need 1 to {limbs.Count}).");
        }

        return new CharacterSpec(
            name,
            up,
            forward,
            required,
            Positive(root, "takeoffSpeedMax", "key 'takeoffSpeedMax'", "m/s"),
            Positive(root, "landingSpeedMax", "key 'landingSpeedMax'", "m/s"),
            root["friction"] is JsonNode f ? Between(Number(f, "key 'friction'"), 0f, MaxMagnitude, "key 'friction'") : null,
            root["walkSpeed"] is JsonNode ws ? Between(Number(ws, "key 'walkSpeed'"), 0f, 100f, "key 'walkSpeed' (m/s; 0: the character does not walk)") : null,
            root["maxSlope"] is JsonNode ms ? Between(Number(ms, "key 'maxSlope'"), 0f, 80f, "key 'maxSlope' (degrees)") : null,
            root["maxSlopeAlong"] is JsonNode ma ? Between(Number(ma, "key 'maxSlopeAlong'"), 0f, 80f, "key 'maxSlopeAlong' (degrees)") : null,
            root["stepHeight"] is JsonNode sh ? Between(Number(sh, "key 'stepHeight'"), 0f, 100f, "key 'stepHeight' (metres)") : null,
            root["trunkBones"] is JsonNode tb ? [.. Array(tb, "key 'trunkBones'").Select((b, i) => Text(b, $"key 'trunkBones', item {i}"))] : null,
            limbs,
            Joints(root["joints"]),
            Positive(root, "boneRadius", "key 'boneRadius'", "metres"),
            BoneRadii(root["boneRadii"]),
            Poses(root["poses"]),
            root["rig"] is JsonNode rig ? RigFile(Text(rig, "key 'rig'")) : null);
    }

    /// <summary>The spec's <c>rig</c>: a <c>.glb</c> or <c>.gltf</c> named relative to the spec's own folder (checked for escapes when it is opened).</summary>
    private string RigFile(string rig)
    {
        string extension = Path.GetExtension(rig);
        if (!extension.Equals(".glb", StringComparison.OrdinalIgnoreCase) && !extension.Equals(".gltf", StringComparison.OrdinalIgnoreCase))
        {
            throw Error("key 'rig'", $"names '{rig}', which is not a .glb or .gltf file: give the rigged glTF's path relative to the spec's folder, e.g. \"hero.glb\".");
        }

        return rig;
    }

    private LimbSpec Limb(string name, JsonNode? node)
    {
        string where = $"limb '{name}'";
        JsonObject limb = Object(node, where);
        Keys(limb, where, LimbKeys);
        string rootBone = limb["rootBone"] is JsonNode rb ? Text(rb, $"{where}, key 'rootBone'") : throw Error(where, "has no rootBone (the first bone of the limb's chain, e.g. the hip).");
        string effectorBone = limb["effectorBone"] is JsonNode eb ? Text(eb, $"{where}, key 'effectorBone'") : throw Error(where, "has no effectorBone (the bone that touches, e.g. the foot).");
        LimbKind kind = LimbKind.Foot;
        if (limb["contact"] is JsonNode c)
        {
            kind = Text(c, $"{where}, key 'contact'") switch
            {
                "foot" => LimbKind.Foot,
                "hand" => LimbKind.Hand,
                string other => throw Error($"{where}, key 'contact'", $"must be \"foot\" or \"hand\", not \"{other}\"."),
            };
        }

        NormalFilter? filter = null;
        if (limb["normalFilter"] is JsonNode fn)
        {
            string fw = $"{where}, key 'normalFilter'";
            JsonObject f = Object(fn, fw);
            Keys(f, fw, FilterKeys);
            Vector3 direction = f["direction"] is JsonNode d ? Vector(d, $"{where}, key 'normalFilter.direction'", nonZero: true) : throw Error(fw, "has no direction (a world vector, usually [0, 1, 0]).");
            float minCosine = f["minCosine"] is JsonNode m ? Number(m, $"{where}, key 'normalFilter.minCosine'") : throw Error(fw, "has no minCosine (−1 accepts every surface, 0.5 those within 60° of the direction).");
            if (minCosine is < -1f or > 1f)
            {
                throw Error($"{where}, key 'normalFilter.minCosine'", $"must lie in [−1, 1], not {minCosine}.");
            }

            filter = new NormalFilter(Vector3.Normalize(direction), minCosine);
        }

        return new LimbSpec(
            name,
            rootBone,
            effectorBone,
            limb["effectorOffset"] is JsonNode eo ? Vector(eo, $"{where}, key 'effectorOffset'", nonZero: false) : null,
            limb["contactNormal"] is JsonNode cn ? Vector(cn, $"{where}, key 'contactNormal'", nonZero: true) : null,
            kind,
            filter);
    }

    private Dictionary<string, JointAxis[]> Joints(JsonNode? node)
    {
        var joints = new Dictionary<string, JointAxis[]>(StringComparer.Ordinal);
        if (node is null)
        {
            return joints;
        }

        foreach ((string bone, JsonNode? jointNode) in Object(node, "key 'joints'"))
        {
            string where = $"joints, bone '{bone}'";
            JsonObject joint = Object(jointNode, where);
            Keys(joint, where, JointKeys);
            JsonArray axes = joint["axes"] is JsonNode a ? Array(a, $"{where}, key 'axes'") : throw Error(where, "has no axes (a list of {\"axis\": [x, y, z], \"min\": degrees, \"max\": degrees}).");
            var list = new List<JointAxis>();
            for (int i = 0; i < axes.Count; i++)
            {
                string aw = $"{where}, axis {i}";
                JsonObject axis = Object(axes[i], aw);
                Keys(axis, aw, AxisKeys);
                Vector3 direction = axis["axis"] is JsonNode d ? Vector(d, $"{aw}, key 'axis'", nonZero: true) : throw Error(aw, "has no axis (a vector in the bone's frame).");
                float min = axis["min"] is JsonNode mn ? Between(Number(mn, $"{aw}, key 'min'"), -MaxDegrees, MaxDegrees, $"{aw}, key 'min'") : throw Error(aw, "has no min (degrees).");
                float max = axis["max"] is JsonNode mx ? Between(Number(mx, $"{aw}, key 'max'"), -MaxDegrees, MaxDegrees, $"{aw}, key 'max'") : throw Error(aw, "has no max (degrees).");
                if (min > max)
                {
                    throw Error(aw, $"min {min}° is above max {max}°.");
                }

                list.Add(new JointAxis(Vector3.Normalize(direction), min * MathF.PI / 180f, max * MathF.PI / 180f));
            }

            joints[bone] = [.. list];
        }

        return joints;
    }

    private Dictionary<string, float> BoneRadii(JsonNode? node)
    {
        var radii = new Dictionary<string, float>(StringComparer.Ordinal);
        if (node is not null)
        {
            foreach ((string bone, JsonNode? value) in Object(node, "key 'boneRadii'"))
            {
                string where = $"boneRadii, bone '{bone}'";
                float radius = Number(value, where);
                radii[bone] = radius is > 0f and <= MaxMagnitude ? radius : throw Error(where, $"must be a positive radius in metres of at most {MaxMagnitude:0}, not {radius}.");
            }
        }

        return radii;
    }

    private Dictionary<string, IReadOnlyList<(string Bone, float[] Degrees)>> Poses(JsonNode? node)
    {
        var poses = new Dictionary<string, IReadOnlyList<(string, float[])>>(StringComparer.Ordinal);
        if (node is null)
        {
            return poses;
        }

        JsonObject json = Object(node, "key 'poses'");
        Keys(json, "key 'poses'", PoseNames);
        foreach ((string poseName, JsonNode? poseNode) in json)
        {
            var bones = new List<(string, float[])>();
            foreach ((string bone, JsonNode? values) in Object(poseNode, $"pose '{poseName}'"))
            {
                string where = $"pose '{poseName}', bone '{bone}'";
                JsonArray list = Array(values, where);
                bones.Add((bone, [.. list.Select((v, i) => Number(v, $"{where}, angle {i}"))]));
            }

            poses[poseName] = bones;
        }

        return poses;
    }

    private Vector3 Axis(JsonObject root, string key, Vector3 fallback)
    {
        if (root[key] is not JsonNode node)
        {
            return fallback;
        }

        string text = Text(node, $"key '{key}'");
        return AxisNames.TryGetValue(text, out Vector3 axis)
            ? axis
            : throw Error($"key '{key}'", $"must be one of {string.Join(", ", AxisNames.Keys.Select(k => $"\"{k}\""))}, not \"{text}\".");
    }

    private static string AxisName(Vector3 axis) => CharacterSpecReader.AxisNames.First(a => a.Value == axis).Key;

    private float? Positive(JsonObject json, string key, string where, string unit)
    {
        if (json[key] is not JsonNode node)
        {
            return null;
        }

        float value = Number(node, where);
        return value is > 0f and <= MaxMagnitude ? value : throw Error(where, $"must be positive and at most {MaxMagnitude:0} ({unit}), not {value}.");
    }

    private float Between(float value, float min, float max, string where) => value >= min && value <= max ? value : throw Error(where, $"must lie between {min} and {max}, not {value}.");

    private void Keys(JsonObject json, string where, string[] known)
    {
        foreach ((string key, JsonNode? value) in json)
        {
            if (!known.Contains(key))
            {
                throw Error(where, $"unknown key '{key}' (known keys: {string.Join(", ", known)}).");
            }

            if (value is null)
            {
                throw Error(where.StartsWith("the spec", StringComparison.Ordinal) ? $"key '{key}'" : $"{where}, key '{key}'", "is null, not a value; leave the key out to use its default.");
            }
        }
    }

    private JsonObject Object(JsonNode? node, string where) => node as JsonObject ?? throw Error(where, $"must be an object, not {Describe(node)}.");

    private JsonArray Array(JsonNode? node, string where) => node as JsonArray ?? throw Error(where, $"must be a list, not {Describe(node)}.");

    private string Text(JsonNode? node, string where) =>
        node is JsonValue v && v.GetValueKind() == JsonValueKind.String ? v.GetValue<string>() : throw Error(where, $"must be a string, not {Describe(node)}.");

    private float Number(JsonNode? node, string where)
    {
        if (node is JsonValue v && v.GetValueKind() == JsonValueKind.Number)
        {
            float value = (float)v.GetValue<double>();
            return float.IsFinite(value) ? value : throw Error(where, $"must be a finite number, not {v.ToJsonString()}.");
        }

        throw Error(where, $"must be a number, not {Describe(node)}.");
    }

    private int Integer(JsonNode? node, string where) =>
        node is JsonValue v && v.GetValueKind() == JsonValueKind.Number && v.TryGetValue(out int i) ? i : throw Error(where, $"must be a whole number, not {Describe(node)}.");

    private Vector3 Vector(JsonNode? node, string where, bool nonZero)
    {
        if (node is not JsonArray a || a.Count != 3)
        {
            throw Error(where, $"must be a list of 3 numbers [x, y, z], not {Describe(node)}.");
        }

        var v = new Vector3(Number(a[0], where), Number(a[1], where), Number(a[2], where));
        if (MathF.Max(MathF.Abs(v.X), MathF.Max(MathF.Abs(v.Y), MathF.Abs(v.Z))) > MaxMagnitude)
        {
            throw Error(where, $"must have components within ±{MaxMagnitude:0}, not [{v.X}, {v.Y}, {v.Z}].");
        }

        return !nonZero || v.LengthSquared() > 1e-12f ? v : throw Error(where, "must not be the zero vector.");
    }

    private void CheckUniqueKeys(JsonElement element, string path)
    {
        string Valid(Func<string?> read)
        {
            try
            {
                return read() ?? "";
            }
            catch (InvalidOperationException e)
            {
                throw new RigException($"{_file}: {(path.Length == 0 ? "the spec" : $"object '{path}'")}: holds text that is not valid Unicode (an escaped lone surrogate).", e);
            }
        }

        if (element.ValueKind == JsonValueKind.Object)
        {
            var seen = new HashSet<string>(StringComparer.Ordinal);
            foreach (JsonProperty property in element.EnumerateObject())
            {
                string key = Valid(() => property.Name);
                if (!seen.Add(key))
                {
                    throw Error(path.Length == 0 ? "the spec" : $"object '{path}'", $"the key '{key}' appears twice.");
                }

                CheckUniqueKeys(property.Value, path.Length == 0 ? key : $"{path}.{key}");
            }
        }
        else if (element.ValueKind == JsonValueKind.Array)
        {
            int i = 0;
            foreach (JsonElement item in element.EnumerateArray())
            {
                CheckUniqueKeys(item, $"{path}[{i++}]");
            }
        }
        else if (element.ValueKind == JsonValueKind.String)
        {
            Valid(element.GetString);
        }
    }

    private static string Describe(JsonNode? node) => node switch
    {
        null => "null",
        JsonObject => "an object",
        JsonArray a => a.Count == 0 ? "an empty list" : $"a list of {a.Count}",
        JsonValue v => v.GetValueKind() switch
        {
            JsonValueKind.String => $"the string {v.ToJsonString()}",
            JsonValueKind.Number => $"the number {v.ToJsonString()}",
            JsonValueKind.True or JsonValueKind.False => v.ToJsonString(),
            _ => v.ToJsonString(),
        },
        _ => node.ToJsonString(),
    };
}
