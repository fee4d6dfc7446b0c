using System.Globalization;
using System.Numerics;
using System.Text.Json;
using System.Text.Json.Nodes;
using System.Text.RegularExpressions;
using Ballistic.Planner.Gltf;
using Ballistic.Planner.IO;
using SharpGLTF.Schema2;

namespace Ballistic.Planner.Levels;

/// <summary>
/// Reads a level from a glTF 2.0 file (<c>.glb</c> or <c>.gltf</c>): every triangle mesh of the default scene with
/// its node transforms applied. A material sets its surface friction with <c>"extras": {"friction": μ}</c>, or with
/// <c>mu=μ</c> or <c>friction=μ</c> in its name; otherwise the character's default applies. Its
/// <c>"extras": {"travelCost": c, "enterCost": s}</c> set what crossing it costs a search (<see cref="LevelMaterial.TravelCost"/>,
/// <see cref="LevelMaterial.EnterCost"/>). The file is read and
/// validated by SharpGLTF (<see cref="GltfModel"/>: what it repaired is <see cref="Level.Repaired"/>); the scene is
/// walked once (a node a scene reaches twice is an error naming it), and the vertices and triangles are counted
/// against <see cref="GltfLoadOptions"/> before they are read.
/// </summary>
public static partial class GltfLevelLoader
{
    /// <summary>Loads the level.</summary>
    /// <param name="path">The <c>.glb</c> or <c>.gltf</c> file.</param>
    /// <param name="options">Limits on bytes, vertices and triangles; <c>null</c> for <see cref="GltfLoadOptions.Default"/>.</param>
    /// <exception cref="LevelException">The file cannot be read, is not valid glTF, exceeds a limit, or holds no usable triangles; the message names the file and the element at fault.</exception>
    public static Level Load(string path, GltfLoadOptions? options = null)
    {
        ArgumentNullException.ThrowIfNull(path);
        try
        {
            return Build(GltfModel.Load(path, options), path);
        }
        catch (GltfException e)
        {
            throw new LevelException(MessageText.Printable(e.Message), e);
        }
        catch (LevelException e) when (e.Message.Any(char.IsControl))
        {
            // A mesh or material name from the file may hold a line break: the message stays one line.
            throw new LevelException(MessageText.Printable(e.Message), e);
        }
    }

    /// <summary>Builds a level from an already read model, within the model's <see cref="GltfModel.Options"/>.</summary>
    /// <param name="model">The glTF, read and validated.</param>
    /// <param name="source">Where the level comes from, for messages and <see cref="Level.Source"/>.</param>
    /// <exception cref="GltfException">The scene lists a node twice, a friction is not a finite number ≥ 0, a travel or enter cost is out of range, or the meshes exceed a limit.</exception>
    /// <exception cref="LevelException">A vertex is not finite or lies beyond <see cref="LevelBuilder.MaxCoordinate"/>, an index is out of range, or no triangle is left.</exception>
    internal static Level Build(GltfModel model, string source)
    {
        ArgumentNullException.ThrowIfNull(model);
        ArgumentNullException.ThrowIfNull(source);
        var builder = new LevelBuilder(source);
        ModelRoot root = model.Root;
        var materials = new LevelMaterial[root.LogicalMaterials.Count];
        for (int i = 0; i < materials.Length; i++)
        {
            materials[i] = Material(model, root.LogicalMaterials[i]);
        }

        var defaultMaterial = new LevelMaterial("default", null);
        var visited = new bool[root.LogicalNodes.Count];
        var counts = new Counts(model.Options);

        // The default scene's nodes (with no scene, every node that is nobody's child), depth first in the file's order.
        IEnumerable<Node> roots = root.DefaultScene is Scene scene ? scene.VisualChildren : root.LogicalNodes.Where(n => n.VisualParent is null);
        var stack = new Stack<(Node Node, Matrix4x4 Parent)>();
        foreach (Node node in roots.Reverse())
        {
            stack.Push((node, Matrix4x4.Identity));
        }

        while (stack.Count > 0)
        {
            (Node node, Matrix4x4 parent) = stack.Pop();
            if (visited[node.LogicalIndex])
            {
                throw new GltfException($"{model.Name}: the scene lists node {node.LogicalIndex} twice.");
            }

            visited[node.LogicalIndex] = true;
            Matrix4x4 world = model.LocalTransform(node) * parent;
            if (node.Mesh is Mesh mesh)
            {
                string meshName = !string.IsNullOrEmpty(mesh.Name) ? mesh.Name : !string.IsNullOrEmpty(node.Name) ? node.Name : $"mesh {mesh.LogicalIndex}";
                for (int p = 0; p < mesh.Primitives.Count; p++)
                {
                    string what = $"primitive {p} of mesh {mesh.LogicalIndex} ('{MessageText.Printable(meshName)}')";
                    AddPrimitive(builder, model, mesh.Primitives[p], what, $"{meshName}[{p}]", world, materials, defaultMaterial, counts);
                }
            }

            foreach (Node child in node.VisualChildren.Reverse())
            {
                stack.Push((child, world));
            }
        }

        Level level = builder.Build();
        level.Repaired = model.Repaired;
        return level;
    }

    private static void AddPrimitive(LevelBuilder builder, GltfModel model, MeshPrimitive primitive, string what, string name, Matrix4x4 world, LevelMaterial[] materials, LevelMaterial fallback, Counts counts)
    {
        PrimitiveType mode = primitive.DrawPrimitiveType;
        if (mode is not (PrimitiveType.TRIANGLES or PrimitiveType.TRIANGLE_STRIP or PrimitiveType.TRIANGLE_FAN) || primitive.GetVertexAccessor("POSITION") is not Accessor positionAccessor)
        {
            return; // points and lines are not surfaces
        }

        Accessor? indexAccessor = primitive.IndexAccessor;

        // Count before reading: the accessors' declared sizes (checked against their data by the library) against the limits.
        int vertexCount = positionAccessor.Count;
        int indexCount = indexAccessor?.Count ?? vertexCount;
        long triangleCount = mode == PrimitiveType.TRIANGLES ? indexCount / 3 : Math.Max(0, indexCount - 2);
        counts.Add(model, what, vertexCount, triangleCount);

        if (positionAccessor.Dimensions != DimensionType.VEC3)
        {
            throw new GltfException($"{model.Name}: {what}'s POSITION accessor {positionAccessor.LogicalIndex} holds {positionAccessor.Dimensions}, not VEC3.");
        }

        Vector3[] positions = GltfModel.Vectors(positionAccessor);
        int[] indices = indexAccessor is null ? [.. Enumerable.Range(0, positions.Length)] : Indices(model, indexAccessor, what);
        int[] triangles = mode switch
        {
            PrimitiveType.TRIANGLE_STRIP => Strip(indices),
            PrimitiveType.TRIANGLE_FAN => Fan(indices),
            _ => indices.Length % 3 == 0 ? indices : indices[..(indices.Length - (indices.Length % 3))],
        };
        LevelMaterial material = primitive.Material is Material m ? materials[m.LogicalIndex] : fallback;
        builder.AddMesh(name, positions, triangles, world, material);
    }

    /// <summary>An index accessor's values, each a vertex index (the library has checked the encoding is unsigned).</summary>
    private static int[] Indices(GltfModel model, Accessor accessor, string what)
    {
        int[] indices = GltfModel.Indices(accessor);
        for (int i = 0; i < indices.Length; i++)
        {
            if (indices[i] < 0)
            {
                throw new GltfException(string.Create(CultureInfo.InvariantCulture, $"{model.Name}: {what}'s index accessor {accessor.LogicalIndex} holds the value {(uint)indices[i]} at element {i}, too large for an index."));
            }
        }

        return indices;
    }

    private static LevelMaterial Material(GltfModel model, Material material)
    {
        string name = !string.IsNullOrEmpty(material.Name) ? material.Name : $"material {material.LogicalIndex}";
        float? friction = null;
        if (material.Extras is JsonObject extras && extras["friction"] is JsonNode extra)
        {
            friction = extra is JsonValue v && v.GetValueKind() == JsonValueKind.Number
                ? (float)v.GetValue<double>()
                : throw new GltfException($"{model.Name}: material '{MessageText.Printable(name)}' sets extras.friction to {Describe(extra)}, not a number.");
        }
        else if (FrictionInName().Match(name) is { Success: true } match)
        {
            friction = float.Parse(match.Groups[1].Value, CultureInfo.InvariantCulture);
        }

        if (friction is float f && (!(f >= 0f) || !float.IsFinite(f)))
        {
            throw new GltfException($"{model.Name}: material '{MessageText.Printable(name)}' sets friction {f.ToString(CultureInfo.InvariantCulture)}; friction must be a finite number ≥ 0.");
        }

        float travelCost = ExtraNumber(model, material, name, "travelCost") ?? 1f;
        float enterCost = ExtraNumber(model, material, name, "enterCost") ?? 0f;
        if (LevelMaterial.CostProblem(travelCost, enterCost) is string problem)
        {
            throw new GltfException($"{model.Name}: material '{MessageText.Printable(name)}': its {problem}.");
        }

        return new LevelMaterial(name, friction) { TravelCost = travelCost, EnterCost = enterCost };
    }

    /// <summary>The number a material's <c>extras</c> give under <paramref name="key"/>, or null when they give none; anything but a number is refused in one line.</summary>
    private static float? ExtraNumber(GltfModel model, Material material, string name, string key) =>
        material.Extras is JsonObject extras && extras[key] is JsonNode extra
            ? extra is JsonValue v && v.GetValueKind() == JsonValueKind.Number
                ? (float)v.GetValue<double>()
                : throw new GltfException($"{model.Name}: material '{MessageText.Printable(name)}' sets extras.{key} to {Describe(extra)}, not a number.")
            : null;

    /// <summary>A short description of a JSON value for messages: "the string \"x\"", "the number 2.0", "a list of 3", "an object", "null".</summary>
    private static string Describe(JsonNode node)
    {
        static string Clip(string s) => s.Length > 40 ? s[..37] + "…" : s;
        return node switch
        {
            JsonObject => "an object",
            JsonArray a => a.Count == 0 ? "an empty list" : $"a list of {a.Count}",
            JsonValue v when v.GetValueKind() == JsonValueKind.String => $"the string {Clip(MessageText.Printable(v.ToJsonString()))}",
            _ => Clip(MessageText.Printable(node.ToJsonString())),
        };
    }

    private static int[] Strip(int[] s)
    {
        int[] list = new int[Math.Max(0, s.Length - 2) * 3];
        for (int i = 0; i + 2 < s.Length; i++)
        {
            (list[3 * i], list[(3 * i) + 1], list[(3 * i) + 2]) = i % 2 == 0 ? (s[i], s[i + 1], s[i + 2]) : (s[i + 1], s[i], s[i + 2]);
        }

        return list;
    }

    private static int[] Fan(int[] s)
    {
        int[] list = new int[Math.Max(0, s.Length - 2) * 3];
        for (int i = 1; i + 1 < s.Length; i++)
        {
            (list[3 * (i - 1)], list[(3 * (i - 1)) + 1], list[(3 * (i - 1)) + 2]) = (s[0], s[i], s[i + 1]);
        }

        return list;
    }

    [GeneratedRegex(@"(?:\bmu|\bfriction)\s*=\s*([0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)", RegexOptions.IgnoreCase | RegexOptions.CultureInvariant)]
    private static partial Regex FrictionInName();

    /// <summary>Vertices and triangles read so far, every mesh instance counted, against the limits.</summary>
    private sealed class Counts(GltfLoadOptions options)
    {
        private long _vertices;
        private long _triangles;

        public void Add(GltfModel model, string what, long vertices, long triangles)
        {
            _vertices += vertices;
            _triangles += triangles;
            if (_vertices > options.MaxVertices)
            {
                throw new GltfException($"{model.Name}: with {what}, the level reads more than {options.MaxVertices} vertices (GltfLoadOptions.MaxVertices).");
            }

            if (_triangles > options.MaxTriangles)
            {
                throw new GltfException($"{model.Name}: with {what}, the level holds more than {options.MaxTriangles} triangles (GltfLoadOptions.MaxTriangles).");
            }
        }
    }
}
