using System.Globalization;
using System.Numerics;
using System.Runtime.InteropServices;
using System.Text.Json;
using System.Text.Json.Nodes;
using System.Text.RegularExpressions;
using Ballistic.Planner.Gltf;
using Ballistic.Planner.IO;

namespace Ballistic.Planner.Levels;

/// <summary>
/// Reads a level from a glTF 2.0 file (<c>.glb</c> or <c>.gltf</c>): every triangle mesh of the default scene with
/// its node transforms applied. A material sets its surface friction with <c>"extras": {"friction": μ}</c>, or with
/// <c>mu=μ</c> or <c>friction=μ</c> in its name; otherwise the character's default applies. The node hierarchy is
/// walked once (a node with two parents, a cycle, or a node a scene reaches twice is an error naming it), and the
/// vertices and triangles are counted against <see cref="GltfLoadOptions"/> before they are read.
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
            return Build(GltfDocument.Load(path, options), path);
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

    /// <summary>Builds a level from an already parsed document, within the document's <see cref="GltfDocument.Options"/>.</summary>
    /// <param name="document">The parsed glTF.</param>
    /// <param name="source">Where the level comes from, for messages and <see cref="Level.Source"/>.</param>
    /// <exception cref="GltfException">The document's scene, nodes, meshes or accessors are malformed, or exceed a limit.</exception>
    /// <exception cref="LevelException">A vertex is not finite or lies beyond <see cref="LevelBuilder.MaxCoordinate"/>, an index is out of range, or no triangle is left.</exception>
    internal static Level Build(GltfDocument document, string source)
    {
        ArgumentNullException.ThrowIfNull(document);
        ArgumentNullException.ThrowIfNull(source);
        var builder = new LevelBuilder(source);
        JsonArray meshes = document.Array("meshes");
        JsonArray materialArray = document.Array("materials");
        var materials = new LevelMaterial[materialArray.Count];
        for (int i = 0; i < materials.Length; i++)
        {
            materials[i] = Material(document, materialArray[i], i);
        }

        var defaultMaterial = new LevelMaterial("default", null);
        int[] parents = document.NodeParents();
        var visited = new bool[parents.Length];
        var counts = new Counts(document.Options);

        var stack = new Stack<(int Node, Matrix4x4 Parent)>();
        List<int> roots = SceneRoots(document, parents);
        for (int r = roots.Count - 1; r >= 0; r--)
        {
            stack.Push((roots[r], Matrix4x4.Identity));
        }

        while (stack.Count > 0)
        {
            (int index, Matrix4x4 parent) = stack.Pop();
            if (visited[index])
            {
                throw new GltfException($"{document.Name}: the scene lists node {index} twice.");
            }

            visited[index] = true;
            JsonObject node = document.Node(index);
            Matrix4x4 world = document.LocalTransform(node) * parent;
            if (document.OptionalIndex(node, "mesh", $"node {index}") is int m)
            {
                if (m >= meshes.Count || meshes[m] is not JsonObject mesh)
                {
                    throw new GltfException($"{document.Name}: node {index} names mesh {m}, which does not exist (there are {meshes.Count}).");
                }

                string meshName = document.OptionalText(mesh, "name", $"mesh {m}") ?? document.OptionalText(node, "name", $"node {index}") ?? $"mesh {m}";
                JsonArray primitives = mesh["primitives"] switch
                {
                    JsonArray list => list,
                    null => throw new GltfException($"{document.Name}: mesh {m} ('{MessageText.Printable(meshName)}') has no primitives."),
                    JsonNode other => throw new GltfException($"{document.Name}: mesh {m} ('{MessageText.Printable(meshName)}') has primitives {GltfDocument.Describe(other)}, not a list."),
                };
                for (int p = 0; p < primitives.Count; p++)
                {
                    string what = $"primitive {p} of mesh {m} ('{MessageText.Printable(meshName)}')";
                    JsonObject primitive = primitives[p] as JsonObject ?? throw new GltfException($"{document.Name}: {what} is {GltfDocument.Describe(primitives[p])}, not an object.");
                    AddPrimitive(builder, document, primitive, what, $"{meshName}[{p}]", world, materials, defaultMaterial, counts);
                }
            }

            if (node["children"] is JsonArray children)
            {
                // NodeParents checked every child index and that each node has one parent.
                for (int c = children.Count - 1; c >= 0; c--)
                {
                    stack.Push((children[c]!.GetValue<int>(), world));
                }
            }
        }

        return builder.Build();
    }

    private static void AddPrimitive(LevelBuilder builder, GltfDocument document, JsonObject primitive, string what, string name, Matrix4x4 world, LevelMaterial[] materials, LevelMaterial fallback, Counts counts)
    {
        int mode = document.OptionalIndex(primitive, "mode", what) ?? 4;
        if (mode > 6)
        {
            throw new GltfException($"{document.Name}: {what} has the unknown mode {mode}.");
        }

        JsonObject attributes = primitive["attributes"] as JsonObject ?? throw new GltfException($"{document.Name}: {what} has {(primitive["attributes"] is null ? "no attributes" : $"attributes {GltfDocument.Describe(primitive["attributes"])}")}, not an object.");
        if (mode is not (4 or 5 or 6) || attributes["POSITION"] is null)
        {
            return; // points and lines are not surfaces
        }

        int positionAccessor = document.RequiredIndex(attributes, "POSITION", what + "'s attributes");
        int? indexAccessor = document.OptionalIndex(primitive, "indices", what);
        int material = document.OptionalIndex(primitive, "material", what) ?? -1;
        if (material >= materials.Length)
        {
            throw new GltfException($"{document.Name}: {what} names material {material}, which does not exist (there are {materials.Length}).");
        }

        // Count before reading: the accessors' declared sizes, checked against their data and the limits.
        int vertexCount = document.ElementCount(positionAccessor);
        int indexCount = indexAccessor is int ia ? document.ElementCount(ia) : vertexCount;
        long triangleCount = mode == 4 ? indexCount / 3 : Math.Max(0, indexCount - 2);
        counts.Add(document, what, vertexCount, triangleCount);

        float[] flat = document.ReadFloats(positionAccessor, 3);
        ReadOnlySpan<Vector3> positions = MemoryMarshal.Cast<float, Vector3>(flat.AsSpan());
        int[] indices = indexAccessor is int i ? document.ReadIntegers(i) : [.. Enumerable.Range(0, positions.Length)];
        int[] triangles = mode switch
        {
            5 => Strip(indices),
            6 => Fan(indices),
            _ => indices.Length % 3 == 0 ? indices : indices[..(indices.Length - (indices.Length % 3))],
        };
        builder.AddMesh(name, positions, triangles, world, material >= 0 ? materials[material] : fallback);
    }

    private static List<int> SceneRoots(GltfDocument document, int[] parents)
    {
        JsonArray scenes = document.Array("scenes");
        if (scenes.Count == 0)
        {
            // No scenes: every node that is nobody's child.
            return [.. Enumerable.Range(0, parents.Length).Where(n => parents[n] < 0)];
        }

        int scene = document.OptionalIndex(document.Root, "scene", "the file") ?? 0;
        if (scene >= scenes.Count)
        {
            throw new GltfException($"{document.Name}: the default scene {scene} does not exist (there are {scenes.Count}).");
        }

        JsonObject sceneJson = scenes[scene] as JsonObject ?? throw new GltfException($"{document.Name}: scene {scene} is {GltfDocument.Describe(scenes[scene])}, not an object.");
        JsonArray nodes = sceneJson["nodes"] switch
        {
            null => [],
            JsonArray list => list,
            JsonNode other => throw new GltfException($"{document.Name}: scene {scene}'s nodes are {GltfDocument.Describe(other)}, not a list."),
        };
        var roots = new List<int>(nodes.Count);
        for (int i = 0; i < nodes.Count; i++)
        {
            int n = nodes[i] is JsonValue v && v.GetValueKind() == JsonValueKind.Number && v.TryGetValue(out int k) && k >= 0 && k < parents.Length
                ? k
                : throw new GltfException($"{document.Name}: scene {scene} lists node {GltfDocument.Describe(nodes[i])}, which is not a node (there are {parents.Length}).");
            if (parents[n] >= 0)
            {
                throw new GltfException($"{document.Name}: scene {scene} lists node {n}, which is a child of node {parents[n]}; a scene lists only root nodes.");
            }

            roots.Add(n);
        }

        return roots;
    }

    private static LevelMaterial Material(GltfDocument document, JsonNode? node, int index)
    {
        string what = $"material {index}";
        JsonObject material = node as JsonObject ?? throw new GltfException($"{document.Name}: {what} is {GltfDocument.Describe(node)}, not an object.");
        string name = document.OptionalText(material, "name", what) ?? what;
        float? friction = null;
        if (material["extras"] is JsonObject extras && extras["friction"] is JsonNode extra)
        {
            friction = extra is JsonValue v && v.GetValueKind() == JsonValueKind.Number
                ? (float)v.GetValue<double>()
                : throw new GltfException($"{document.Name}: material '{MessageText.Printable(name)}' sets extras.friction to {GltfDocument.Describe(extra)}, not a number.");
        }
        else if (FrictionInName().Match(name) is { Success: true } match)
        {
            friction = float.Parse(match.Groups[1].Value, CultureInfo.InvariantCulture);
        }

        if (friction is float f && (!(f >= 0f) || !float.IsFinite(f)))
        {
            throw new GltfException($"{document.Name}: material '{MessageText.Printable(name)}' sets friction {f.ToString(CultureInfo.InvariantCulture)}; friction must be a finite number ≥ 0.");
        }

        return new LevelMaterial(name, friction);
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

        public void Add(GltfDocument document, string what, long vertices, long triangles)
        {
            _vertices += vertices;
            _triangles += triangles;
            if (_vertices > options.MaxVertices)
            {
                throw new GltfException($"{document.Name}: with {what}, the level reads more than {options.MaxVertices} vertices (GltfLoadOptions.MaxVertices).");
            }

            if (_triangles > options.MaxTriangles)
            {
                throw new GltfException($"{document.Name}: with {what}, the level holds more than {options.MaxTriangles} triangles (GltfLoadOptions.MaxTriangles).");
            }
        }
    }
}
