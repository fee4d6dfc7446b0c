using System.Globalization;
using System.Numerics;
using System.Text.Json.Nodes;
using System.Text.RegularExpressions;
using Ballistic.Planner.Gltf;

namespace Ballistic.Planner.Levels;

/// <summary>
/// Reads a level from a glTF 2.0 file (<c>.glb</c> or <c>.gltf</c>): every triangle mesh of the default scene with
/// its node transforms applied. A material sets its surface friction with <c>"extras": {"friction": μ}</c>, or with
/// <c>mu=μ</c> or <c>friction=μ</c> in its name; otherwise the character's default applies.
/// </summary>
public static partial class GltfLevelLoader
{
    /// <summary>Loads the level.</summary>
    /// <exception cref="LevelException">The file cannot be read, is not valid glTF, or holds no usable triangles.</exception>
    public static Level Load(string path)
    {
        ArgumentNullException.ThrowIfNull(path);
        GltfDocument document;
        try
        {
            document = GltfDocument.Load(path);
        }
        catch (GltfException e)
        {
            throw new LevelException(e.Message, e);
        }

        try
        {
            return Build(document, path);
        }
        catch (GltfException e)
        {
            throw new LevelException(e.Message, e);
        }
        catch (Exception e) when (e is InvalidOperationException or FormatException or OverflowException or KeyNotFoundException or NullReferenceException or InvalidCastException)
        {
            throw new LevelException($"{path} is not a valid glTF file ({e.Message}).", e);
        }
    }

    /// <summary>Builds a level from an already parsed document.</summary>
    public static Level Build(GltfDocument document, string source)
    {
        ArgumentNullException.ThrowIfNull(document);
        var builder = new LevelBuilder(source);
        JsonArray nodes = document.Array("nodes");
        JsonArray meshes = document.Array("meshes");
        LevelMaterial[] materials = [.. document.Array("materials").Select((m, i) => Material(m as JsonObject, i))];
        var defaultMaterial = new LevelMaterial("default", null);

        var stack = new Stack<(int Node, Matrix4x4 Parent, int Depth)>();
        foreach (int root in SceneRoots(document).Reverse())
        {
            stack.Push((root, Matrix4x4.Identity, 0));
        }

        while (stack.Count > 0)
        {
            (int index, Matrix4x4 parent, int depth) = stack.Pop();
            if (index < 0 || index >= nodes.Count || nodes[index] is not JsonObject node)
            {
                throw new GltfException($"{source}: node {index} does not exist.");
            }

            if (depth > 256)
            {
                throw new GltfException($"{source}: the node hierarchy is deeper than 256 levels or has a cycle.");
            }

            Matrix4x4 world = document.LocalTransform(node) * parent;
            if (node["mesh"] is JsonNode meshIndex)
            {
                int m = meshIndex.GetValue<int>();
                if (m < 0 || m >= meshes.Count || meshes[m] is not JsonObject mesh)
                {
                    throw new GltfException($"{source}: node {index} names mesh {m}, which does not exist.");
                }

                string meshName = mesh["name"]?.GetValue<string>() ?? node["name"]?.GetValue<string>() ?? $"mesh {m}";
                JsonArray primitives = mesh["primitives"] as JsonArray ?? [];
                for (int p = 0; p < primitives.Count; p++)
                {
                    AddPrimitive(builder, document, primitives[p] as JsonObject, $"{meshName}[{p}]", world, materials, defaultMaterial);
                }
            }

            if (node["children"] is JsonArray children)
            {
                for (int c = children.Count - 1; c >= 0; c--)
                {
                    stack.Push((children[c]!.GetValue<int>(), world, depth + 1));
                }
            }
        }

        return builder.Build();
    }

    private static void AddPrimitive(LevelBuilder builder, GltfDocument document, JsonObject? primitive, string name, Matrix4x4 world, LevelMaterial[] materials, LevelMaterial fallback)
    {
        if (primitive is null)
        {
            return;
        }

        int mode = primitive["mode"]?.GetValue<int>() ?? 4;
        if (mode is not (4 or 5 or 6) || primitive["attributes"]?["POSITION"] is not JsonNode positionAccessor)
        {
            return; // points and lines are not surfaces
        }

        float[] flat = document.ReadFloats(positionAccessor.GetValue<int>(), 3);
        var positions = new Vector3[flat.Length / 3];
        for (int i = 0; i < positions.Length; i++)
        {
            positions[i] = new Vector3(flat[3 * i], flat[(3 * i) + 1], flat[(3 * i) + 2]);
        }

        int[] indices = primitive["indices"] is JsonNode indexAccessor
            ? document.ReadIntegers(indexAccessor.GetValue<int>())
            : [.. Enumerable.Range(0, positions.Length)];
        int[] triangles = mode switch
        {
            5 => Strip(indices),
            6 => Fan(indices),
            _ => indices.Length % 3 == 0 ? indices : indices[..(indices.Length - (indices.Length % 3))],
        };
        int material = primitive["material"]?.GetValue<int>() ?? -1;
        LevelMaterial levelMaterial = material >= 0 && material < materials.Length ? materials[material] : fallback;
        builder.AddMesh(name, positions, triangles, world, levelMaterial);
    }

    private static IEnumerable<int> SceneRoots(GltfDocument document)
    {
        JsonArray scenes = document.Array("scenes");
        if (scenes.Count > 0)
        {
            int scene = document.Root["scene"]?.GetValue<int>() ?? 0;
            if (scene < 0 || scene >= scenes.Count)
            {
                throw new GltfException($"{document.Name}: the default scene {scene} does not exist.");
            }

            return (scenes[scene]?["nodes"] as JsonArray ?? []).Select(n => n!.GetValue<int>()).ToList();
        }

        // No scenes: every node that is nobody's child.
        JsonArray nodes = document.Array("nodes");
        var children = new HashSet<int>(nodes.SelectMany(n => (n?["children"] as JsonArray ?? []).Select(c => c!.GetValue<int>())));
        return Enumerable.Range(0, nodes.Count).Where(i => !children.Contains(i)).ToList();
    }

    private static LevelMaterial Material(JsonObject? material, int index)
    {
        string name = material?["name"]?.GetValue<string>() ?? $"material {index}";
        float? friction = null;
        if (material?["extras"]?["friction"] is JsonNode extra)
        {
            friction = extra.GetValue<float>();
        }
        else if (FrictionInName().Match(name) is { Success: true } match)
        {
            friction = float.Parse(match.Groups[1].Value, CultureInfo.InvariantCulture);
        }

        if (friction is float f && (!(f >= 0f) || !float.IsFinite(f)))
        {
            throw new GltfException($"Material '{name}' sets friction {f}; friction must be a finite number ≥ 0.");
        }

        return new LevelMaterial(name, friction);
    }

    private static int[] Strip(int[] s)
    {
        var list = new List<int>();
        for (int i = 0; i + 2 < s.Length; i++)
        {
            list.AddRange(i % 2 == 0 ? [s[i], s[i + 1], s[i + 2]] : [s[i + 1], s[i], s[i + 2]]);
        }

        return [.. list];
    }

    private static int[] Fan(int[] s)
    {
        var list = new List<int>();
        for (int i = 1; i + 1 < s.Length; i++)
        {
            list.AddRange([s[0], s[i], s[i + 1]]);
        }

        return [.. list];
    }

    [GeneratedRegex(@"(?:\bmu|\bfriction)\s*=\s*([0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)", RegexOptions.IgnoreCase | RegexOptions.CultureInvariant)]
    private static partial Regex FrictionInName();
}
