using System.Numerics;
using System.Runtime.InteropServices;
using System.Text.Json;
using System.Text.Json.Nodes;
using System.Text.RegularExpressions;
using Ballistic.Planner.IO;
using SharpGLTF.Schema2;
using SharpGLTF.Transforms;
using SharpGLTF.Validation;

namespace Ballistic.Planner.Gltf;

/// <summary>
/// A glTF 2.0 asset (<c>.glb</c> or <c>.gltf</c>, with embedded, data-URI or external buffers and images) read by
/// SharpGLTF, which parses the JSON into a typed schema and validates it on load: links between elements, accessors
/// against their buffer views, node hierarchies (one parent each, no cycle), transforms, skins. What the library does
/// not check we check around it: only regular files are read, within <see cref="GltfLoadOptions"/>' byte limit (the
/// file, then each external buffer and image against what is left); external files only from the glTF's own folder or
/// below (<see cref="ReferencedFile"/>, through the library's file-reader callback, through which every URI passes);
/// vertex and triangle counts before they are read (the callers). A file SharpGLTF refuses in its strict mode but
/// repairs in its <see cref="ValidationMode.TryFix"/> mode (weights summing to 0.999999, as assimp writes them, a
/// rotation a little off unit length) loads, and <see cref="Repaired"/> says what was wrong. Every problem is a
/// <see cref="GltfException"/> of one line naming the file and the element.
/// </summary>
internal sealed partial class GltfModel
{
    private GltfModel(ModelRoot root, string name, GltfLoadOptions options, string? repaired, byte[] bytes, string? directory)
    {
        Bytes = bytes;
        Directory = directory;
        Root = root;
        Name = name;
        Options = options;
        Repaired = repaired;
    }

    /// <summary>The file's bytes as read (the animated GLB writer copies the user's rig from them).</summary>
    internal byte[] Bytes { get; }

    /// <summary>The folder against which the file's URIs resolve, or <c>null</c> when they cannot.</summary>
    internal string? Directory { get; }

    /// <summary>The asset as SharpGLTF's typed schema.</summary>
    public ModelRoot Root { get; }

    /// <summary>The file name, for messages.</summary>
    public string Name { get; }

    /// <summary>The limits the asset was read with, which also bound what is read from it later (vertices, triangles).</summary>
    public GltfLoadOptions Options { get; }

    /// <summary>What SharpGLTF's strict validation refused and its repairing mode accepted (one line), or <c>null</c> when the file is valid as it is.</summary>
    public string? Repaired { get; }

    /// <summary>Reads a <c>.glb</c> or <c>.gltf</c> file.</summary>
    /// <param name="path">The file; a symbolic link to a regular file is followed.</param>
    /// <param name="options">Limits on the bytes read; <c>null</c> for <see cref="GltfLoadOptions.Default"/>.</param>
    /// <exception cref="GltfException">
    /// The file is missing, not a regular file, larger than <see cref="GltfLoadOptions.MaxBytes"/>, malformed, needs
    /// an unsupported extension, or refers to a buffer or image it may not read.
    /// </exception>
    public static GltfModel Load(string path, GltfLoadOptions? options = null)
    {
        ArgumentNullException.ThrowIfNull(path);
        options ??= GltfLoadOptions.Default;
        (byte[] bytes, string? directory) = ReadFile(path, options);
        return Parse(bytes, path, directory, options);
    }

    /// <summary>A glTF file's bytes (a regular file, within <see cref="GltfLoadOptions.MaxBytes"/>) and its folder, against which its URIs resolve.</summary>
    /// <exception cref="GltfException">The file is missing, not a regular file, too large, or its path cannot be resolved.</exception>
    internal static (byte[] Bytes, string? Directory) ReadFile(string path, GltfLoadOptions options)
    {
        byte[] bytes = InputFile.Read(path, options.MaxBytes, "GltfLoadOptions.MaxBytes", (problem, e) => new GltfException($"{MessageText.Printable(path)} {problem}.", e!));
        try
        {
            return (bytes, Path.GetDirectoryName(Path.GetFullPath(path)));
        }
        catch (Exception e) when (e is ArgumentException or IOException or NotSupportedException)
        {
            throw new GltfException($"{MessageText.Printable(path)} cannot be read: {MessageText.Printable(e.Message.TrimEnd('.'))}.", e);
        }
    }

    /// <summary>Parses glTF bytes (binary GLB or JSON).</summary>
    /// <param name="bytes">File content.</param>
    /// <param name="name">Name for messages.</param>
    /// <param name="directory">Folder against which external URIs resolve; <c>null</c> forbids them.</param>
    /// <param name="options">Limits; <c>null</c> for <see cref="GltfLoadOptions.Default"/>. The bytes given count towards <see cref="GltfLoadOptions.MaxBytes"/>.</param>
    /// <exception cref="GltfException">The bytes are not a usable glTF 2.0 asset; the message names the element at fault.</exception>
    public static GltfModel Parse(byte[] bytes, string name, string? directory, GltfLoadOptions? options = null)
    {
        ArgumentNullException.ThrowIfNull(bytes);
        ArgumentNullException.ThrowIfNull(name);
        options ??= GltfLoadOptions.Default;
        string printable = MessageText.Printable(name);
        try
        {
            return new GltfModel(Read(bytes, printable, directory, options, ValidationMode.Strict, repair: false), name, options, null, bytes, directory);
        }
        catch (ModelException strict)
        {
            try
            {
                ModelRoot repaired = Read(bytes, printable, directory, options, ValidationMode.TryFix, repair: true);
                return new GltfModel(repaired, name, options, Locate(Describe(strict), repaired), bytes, directory);
            }
            catch (ModelException e)
            {
                string described = Describe(e);
                throw new GltfException($"{printable}: {(Element().IsMatch(described) ? Locate(described, Unchecked(bytes, printable, directory, options)) : Pinpointed(bytes, described))}");
            }
        }
    }

    /// <summary>
    /// The file read again into a model of its own, to be changed and written (the animated GLB of a user's rig): its
    /// buffers and images read afresh through the same checks, and repaired as when it was loaded. With
    /// <paramref name="firstAnimation"/>, an animation of that name, with no channels yet, comes first in its list.
    /// </summary>
    /// <exception cref="GltfException">A file the glTF refers to can no longer be read, or has changed so that it no longer loads.</exception>
    internal ModelRoot ReadAgain(string? firstAnimation)
    {
        string printable = MessageText.Printable(Name);
        try
        {
            return Read(Bytes, printable, Directory, Options, Repaired is null ? ValidationMode.Strict : ValidationMode.TryFix, repair: Repaired is not null, firstAnimation);
        }
        catch (ModelException e)
        {
            throw new GltfException($"{printable}: {Describe(e)}");
        }
    }

    /// <summary>
    /// The local transform of <paramref name="node"/>, row-vector convention: its matrix, or scale · rotation ·
    /// translation with the rotation normalised in double precision (a quaternion an exporter wrote a little off unit
    /// length rotates, and does not scale).
    /// </summary>
    /// <exception cref="GltfException">The node's rotation is zero, or its transform holds a number that is not finite.</exception>
    public Matrix4x4 LocalTransform(Node node)
    {
        ArgumentNullException.ThrowIfNull(node);
        AffineTransform transform = node.LocalTransform;
        Matrix4x4 local;
        if (transform.IsMatrix)
        {
            local = transform.Matrix;
        }
        else
        {
            local = Trs(transform.Translation, transform.Rotation, transform.Scale)
                ?? throw new GltfException($"{MessageText.Printable(Name)}: node {node.LogicalIndex}{Named(node.Name)} has a zero rotation quaternion.");
        }

        for (int r = 0; r < 4; r++)
        {
            for (int c = 0; c < 4; c++)
            {
                if (!float.IsFinite(local[r, c]))
                {
                    throw new GltfException($"{MessageText.Printable(Name)}: node {node.LogicalIndex}{Named(node.Name)} has a transform that is not finite.");
                }
            }
        }

        return local;
    }

    /// <summary>The parent of every node (−1 for a root), by node index; the hierarchy was checked on load (one parent each, no cycle).</summary>
    public int[] NodeParents() => [.. Root.LogicalNodes.Select(n => n.VisualParent?.LogicalIndex ?? -1)];

    /// <summary>Every node's rest transform in the scene (its local transform times its ancestors'), row-vector convention, by node index.</summary>
    /// <exception cref="GltfException">A node's transform is not finite or has a zero rotation.</exception>
    public Matrix4x4[] WorldTransforms() => Compose(NodeParents(), n => LocalTransform(Root.LogicalNodes[n]));

    /// <summary>
    /// A node's local transform from glTF's translation, rotation and scale (row-vector convention: scale, then
    /// rotation, then translation), the rotation normalised in double precision; <c>null</c> for a zero rotation. Both
    /// glTF readers compose transforms through it, so that they agree to the bit.
    /// </summary>
    internal static Matrix4x4? Trs(Vector3 translation, Quaternion q, Vector3 scale)
    {
        double length = Math.Sqrt(((double)q.X * q.X) + ((double)q.Y * q.Y) + ((double)q.Z * q.Z) + ((double)q.W * q.W));
        if (!(length > 1e-6))
        {
            return null;
        }

        var rotation = new Quaternion((float)(q.X / length), (float)(q.Y / length), (float)(q.Z / length), (float)(q.W / length));
        return Matrix4x4.CreateScale(scale) * Matrix4x4.CreateFromQuaternion(rotation) * Matrix4x4.CreateTranslation(translation);
    }

    /// <summary>
    /// World transforms from each node's parent (−1 for a root; no cycle) and its local transform: every node once,
    /// its ancestors first, without recursion. Both glTF readers compose the scene through it.
    /// </summary>
    internal static Matrix4x4[] Compose(int[] parents, Func<int, Matrix4x4> local)
    {
        var world = new Matrix4x4[parents.Length];
        var done = new bool[parents.Length];
        var chain = new Stack<int>();
        for (int n = 0; n < parents.Length; n++)
        {
            for (int p = n; p >= 0 && !done[p]; p = parents[p])
            {
                chain.Push(p);
            }

            while (chain.Count > 0)
            {
                int node = chain.Pop();
                world[node] = parents[node] >= 0 ? local(node) * world[parents[node]] : local(node);
                done[node] = true;
            }
        }

        return world;
    }

    /// <summary>
    /// A VEC3 accessor's elements (decoded as the library decodes them: normalised or quantised integers, sparse
    /// substitutions). Tightly packed floats, what exporters write, are copied in one block instead of element by element.
    /// </summary>
    public static Vector3[] Vectors(Accessor accessor)
    {
        ArgumentNullException.ThrowIfNull(accessor);
        if (Packed(accessor, EncodingType.FLOAT, 12) is ArraySegment<byte> bytes)
        {
            return MemoryMarshal.Cast<byte, Vector3>(bytes.AsSpan()).ToArray();
        }

        return [.. accessor.AsVector3Array()];
    }

    /// <summary>
    /// An index accessor's values as <see cref="int"/>; a value above 2³¹ − 1 comes out negative, for the caller to
    /// refuse. Tightly packed 32-bit and 16-bit indices are read in one pass.
    /// </summary>
    public static int[] Indices(Accessor accessor)
    {
        ArgumentNullException.ThrowIfNull(accessor);
        if (Packed(accessor, EncodingType.UNSIGNED_INT, 4) is ArraySegment<byte> words)
        {
            return MemoryMarshal.Cast<byte, int>(words.AsSpan()).ToArray();
        }

        if (Packed(accessor, EncodingType.UNSIGNED_SHORT, 2) is ArraySegment<byte> halves)
        {
            ReadOnlySpan<ushort> values = MemoryMarshal.Cast<byte, ushort>(halves.AsSpan());
            int[] result = new int[values.Length];
            for (int i = 0; i < values.Length; i++)
            {
                result[i] = values[i];
            }

            return result;
        }

        IList<uint> all = accessor.AsIndicesArray();
        int[] indices = new int[all.Count];
        for (int i = 0; i < indices.Length; i++)
        {
            indices[i] = unchecked((int)all[i]);
        }

        return indices;
    }

    /// <summary>
    /// The bytes of an accessor whose elements lie back to back in its buffer view (no stride beyond the element, no
    /// sparse substitution, not normalised, of <paramref name="encoding"/> with <paramref name="size"/>-byte
    /// elements), on a little-endian machine; <c>null</c> otherwise. The library has checked them against the view.
    /// </summary>
    private static ArraySegment<byte>? Packed(Accessor accessor, EncodingType encoding, int size)
    {
        if (!BitConverter.IsLittleEndian || accessor.IsSparse || accessor.Normalized || accessor.Encoding != encoding
            || accessor.Format.ByteSize != size || accessor.SourceBufferView is not BufferView view
            || (view.ByteStride != 0 && view.ByteStride != size))
        {
            return null;
        }

        long length = (long)accessor.Count * size;
        ArraySegment<byte> content = view.Content;
        if (accessor.ByteOffset < 0 || accessor.ByteOffset + length > content.Count)
        {
            return null;
        }

        return content.Slice(accessor.ByteOffset, (int)length);
    }

    /// <summary>" ('name')" for an element with a name, else nothing: for messages.</summary>
    public static string Named(string? name) => string.IsNullOrEmpty(name) ? "" : $" ('{MessageText.Printable(name)}')";

    /// <summary>
    /// Reads with SharpGLTF in <paramref name="mode"/>, the JSON first through <see cref="Prepare"/> (with
    /// <paramref name="repair"/>, without accessor bounds), external files through the callback that confines them to
    /// <paramref name="directory"/> and to what is left of the byte limit; every exception becomes a
    /// <see cref="GltfException"/> but the library's <see cref="ModelException"/>, left to the caller.
    /// </summary>
    private static ModelRoot Read(byte[] bytes, string name, string? directory, GltfLoadOptions options, ValidationMode mode, bool repair, string? firstAnimation = null)
    {
        long budget = options.MaxBytes - bytes.Length;
        GltfException? refused = null;
        var elements = new Dictionary<string, string>(StringComparer.Ordinal);
        ArraySegment<byte> External(string uri)
        {
            try
            {
                // The element that names the URI, as the file wrote it (the library may hand it over percent-decoded).
                string element = elements.TryGetValue(uri, out string? named) ? named
                    : elements.FirstOrDefault(e => Unescaped(e.Key) == uri).Value ?? "a file";
                string raw = elements.FirstOrDefault(e => e.Value == element && (e.Key == uri || Unescaped(e.Key) == uri)).Key ?? uri;
                if (directory is null)
                {
                    throw new GltfException($"{name}: {element} refers to the external file '{MessageText.Printable(raw)}', which cannot be resolved here.");
                }

                string path = ReferencedFile.Resolve(directory, raw, problem => new GltfException($"{name}: {element}'s URI '{MessageText.Printable(raw)}' {problem}."));
                byte[] data = InputFile.Read(path, Math.Max(budget, 0), $"what is left of the limit of {options.MaxBytes} with the glTF and its other files, GltfLoadOptions.MaxBytes", (problem, e) => new GltfException($"{name}: {element}'s file '{MessageText.Printable(raw)}' {problem}.", e!));
                budget -= data.Length;
                return data;
            }
            catch (GltfException e)
            {
                refused = e;
                throw;
            }
        }

        try
        {
            ReadContext context = ReadContext.Create(External);
            context.Validation = mode;
            context.JsonPreprocessor = json => Prepare(json, name, repair, elements, firstAnimation);
            using var stream = new MemoryStream(bytes, writable: false);
            return context.ReadSchema2(stream);
        }
        catch (ModelException) when (refused is null)
        {
            throw;
        }
        catch (GltfException)
        {
            throw;
        }
        catch (Exception e) when (e is not OutOfMemoryException and not StackOverflowException && !ThrownByUs(e))
        {
            // The library met something it does not expect (a malformed GLB header, JSON that is not glTF's shape,
            // an extension it cannot decode): the file is at fault, not the program, and it says so in one line.
            throw refused ?? new GltfException($"{name}: {Pinpointed(bytes, Describe(e))}");
        }
    }

    /// <summary>
    /// Whether <paramref name="e"/> came out of our own code (the JSON checks run inside the library's read): the first
    /// frame outside .NET's own libraries is ours. Such an exception is a bug of ours and is not dressed as an input
    /// error, so that the fuzz suite sees it.
    /// </summary>
    private static bool ThrownByUs(Exception e)
    {
        foreach (System.Diagnostics.StackFrame frame in new System.Diagnostics.StackTrace(e).GetFrames())
        {
            if (frame.GetMethod()?.DeclaringType?.Assembly is System.Reflection.Assembly assembly && assembly != typeof(object).Assembly
                && !(assembly.GetName().Name ?? "").StartsWith("System.", StringComparison.Ordinal))
            {
                return assembly == typeof(GltfModel).Assembly;
            }
        }

        return false;
    }

    /// <summary>The most documents <see cref="Pinpoint"/> reads to find where a failure lies.</summary>
    private const int MostProbes = 4000;

    /// <summary><paramref name="failure"/> with where in the JSON it lies in front ("accessors[3].componentType: …"), when <see cref="Pinpoint"/> finds it.</summary>
    private static string Pinpointed(byte[] bytes, string failure) =>
        failure.StartsWith("its JSON ", StringComparison.Ordinal) && Pinpoint(bytes, failure) is string where ? $"{where}: {failure}" : failure;

    /// <summary>
    /// Where in the file's JSON the library's reader fails with <paramref name="failure"/> (its reader does not say):
    /// found by reading, without validation, documents that hold the asset and one top-level property, then one item
    /// of that list, then that item without one of its keys, and seeing which still fail the same way. Only run for a
    /// file already refused; at most <see cref="MostProbes"/> reads. <c>null</c> when no single place is found.
    /// </summary>
    private static string? Pinpoint(byte[] bytes, string failure)
    {
        JsonObject root;
        try
        {
            using var stream = new MemoryStream(bytes, writable: false);
            if (JsonNode.Parse(ReadContext.ReadJson(stream).TrimStart('\uFEFF')) is not JsonObject parsed)
            {
                return null;
            }

            root = parsed;
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            return null; // not even JSON: the failure says so itself
        }

        int probes = 0;
        bool Fails(JsonObject probe)
        {
            if (++probes > MostProbes)
            {
                return false;
            }

            try
            {
                ReadContext context = ReadContext.Create(_ => throw new FileNotFoundException());
                context.Validation = ValidationMode.Skip;
                using var stream = new MemoryStream(System.Text.Encoding.UTF8.GetBytes(probe.ToJsonString()), writable: false);
                context.ReadSchema2(stream);
                return false;
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                return Describe(e) == failure;
            }
        }

        JsonNode? asset = root["asset"];
        JsonObject With(string key, JsonNode? value) => new() { ["asset"] = asset?.DeepClone(), [key] = value?.DeepClone() };
        foreach ((string key, JsonNode? value) in root.ToList())
        {
            if (key == "asset" || probes >= MostProbes || !Fails(With(key, value)))
            {
                continue;
            }

            // Narrowed from the outside in: in an object, the key without which the probe no longer fails; in a list,
            // the item that alone still fails.
            JsonObject probe = With(key, value);
            var path = new List<(string? Key, int Index)> { (key, 0) };
            JsonNode? node = probe[key];
            while (probes < MostProbes && node is JsonObject or JsonArray)
            {
                (string? Key, int Index)? found = null;
                if (Emptied(node))
                {
                    break; // the list or object fails as it is, empty: it is the value of the wrong type
                }

                if (node is JsonObject obj)
                {
                    foreach ((string property, JsonNode? _) in obj.ToList())
                    {
                        JsonNode? removed = obj[property];
                        obj.Remove(property);
                        bool stillFails = Fails(probe);
                        obj[property] = removed;
                        if (!stillFails)
                        {
                            found = (property, 0);
                            break;
                        }
                    }
                }
                else if (node is JsonArray array)
                {
                    JsonNode?[] items = [.. array];
                    array.Clear();
                    for (int i = 0; i < items.Length && found is null && probes < MostProbes; i++)
                    {
                        array.Add(items[i]);
                        if (Fails(probe))
                        {
                            found = (null, i);
                        }
                        else
                        {
                            array.Clear();
                        }
                    }

                    if (found is null)
                    {
                        array.Clear();
                        foreach (JsonNode? item in items)
                        {
                            array.Add(item);
                        }
                    }
                }

                if (found is not { } step)
                {
                    break;
                }

                path.Add(step);
                node = step.Key is string k ? ((JsonObject)node)[k] : ((JsonArray)node)[0];
            }

            return string.Concat(path.Select((p, i) => p.Key is null ? $"[{p.Index}]" : i == 0 ? p.Key : "." + p.Key));

            // Whether the probe still fails with this list or object emptied (it is then restored).
            bool Emptied(JsonNode container)
            {
                if (container is JsonArray list)
                {
                    JsonNode?[] items = [.. list];
                    list.Clear();
                    bool fails = Fails(probe);
                    foreach (JsonNode? item in items)
                    {
                        list.Add(item);
                    }

                    return fails;
                }

                var properties = ((JsonObject)container).ToList();
                ((JsonObject)container).Clear();
                bool still = Fails(probe);
                foreach ((string k, JsonNode? v) in properties)
                {
                    ((JsonObject)container)[k] = v;
                }

                return still;
            }
        }

        return null;
    }

    /// <summary>The asset read without validation, only to name the elements a message speaks of; <c>null</c> when even that fails.</summary>
    private static ModelRoot? Unchecked(byte[] bytes, string name, string? directory, GltfLoadOptions options)
    {
        try
        {
            return Read(bytes, name, directory, options, ValidationMode.Skip, repair: true);
        }
        catch (Exception e) when (e is ModelException or GltfException)
        {
            return null;
        }
    }

    /// <summary>
    /// A SharpGLTF message with its element (<c>Accessor[3]</c>, <c>Node[2]</c>…) in our words, and what uses it
    /// where <paramref name="model"/> says: "accessor 3 (POSITION of primitive 0 of mesh 1 ('Rock'))".
    /// </summary>
    private static string Locate(string message, ModelRoot? model)
    {
        Match match = Element().Match(message);
        if (!match.Success)
        {
            return message;
        }

        int index = int.Parse(match.Groups[2].Value, System.Globalization.CultureInfo.InvariantCulture);
        string kind = match.Groups[1].Value switch
        {
            "BufferView" => "buffer view",
            "MeshPrimitive" => "mesh primitive",
            string other => other.ToLowerInvariant(),
        };
        string? context = model is null ? null : Context(model, kind, index);
        return $"{kind} {index}{(context is null ? "" : $" ({context})")}: {match.Groups[3].Value.TrimStart().TrimStart(':').TrimStart()}";
    }

    /// <summary>What element <paramref name="index"/> of <paramref name="kind"/> is, by its name or its first user; <c>null</c> when unknown.</summary>
    private static string? Context(ModelRoot model, string kind, int index)
    {
        string? Of(Accessor accessor)
        {
            foreach (Mesh mesh in model.LogicalMeshes)
            {
                foreach (MeshPrimitive primitive in mesh.Primitives)
                {
                    string where = $"primitive {primitive.LogicalIndex} of mesh {mesh.LogicalIndex}{Named(mesh.Name)}";
                    if (primitive.IndexAccessor == accessor)
                    {
                        return "indices of " + where;
                    }

                    foreach (KeyValuePair<string, Accessor> attribute in primitive.VertexAccessors)
                    {
                        if (attribute.Value == accessor)
                        {
                            return $"{MessageText.Printable(attribute.Key)} of {where}";
                        }
                    }
                }
            }

            foreach (Skin skin in model.LogicalSkins)
            {
                if (skin.GetInverseBindMatricesAccessor() == accessor)
                {
                    return $"the inverse bind matrices of skin {skin.LogicalIndex}{Named(skin.Name)}";
                }
            }

            return string.IsNullOrEmpty(accessor.Name) ? null : $"'{MessageText.Printable(accessor.Name)}'";
        }

        try
        {
            return kind switch
            {
                "accessor" when index < model.LogicalAccessors.Count => Of(model.LogicalAccessors[index]),
                "buffer view" when index < model.LogicalBufferViews.Count => model.LogicalAccessors.FirstOrDefault(a => a.SourceBufferView?.LogicalIndex == index) is Accessor user
                    ? $"read by accessor {user.LogicalIndex}{(Of(user) is string of ? $", {of}" : "")}"
                    : null,
                "node" when index < model.LogicalNodes.Count => NameOnly(model.LogicalNodes[index].Name),
                "mesh" when index < model.LogicalMeshes.Count => NameOnly(model.LogicalMeshes[index].Name),
                "material" when index < model.LogicalMaterials.Count => NameOnly(model.LogicalMaterials[index].Name),
                "skin" when index < model.LogicalSkins.Count => NameOnly(model.LogicalSkins[index].Name),
                _ => null,
            };
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            return null; // an unvalidated model's links may be broken: the message goes without its context
        }

        static string? NameOnly(string? name) => string.IsNullOrEmpty(name) ? null : $"'{MessageText.Printable(name)}'";
    }

    /// <summary>The deepest node hierarchy read (a node under 999 ancestors); rigs and levels nest a few dozen deep.</summary>
    public const int MaxNodeDepth = 1000;

    /// <summary>
    /// What we do to the JSON before SharpGLTF parses it (its <see cref="ReadSettings.JsonPreprocessor"/> hook):
    /// a byte-order mark some exporters write is dropped; JSON that does not parse, is not an object or repeats a key
    /// is refused with where (<see cref="CheckUniqueKeys"/>); the node hierarchy is checked (<see cref="CheckNodes"/>),
    /// which the library checks recursively, so that a deep or looping hierarchy cannot overflow the stack or take
    /// quadratic time; and with <paramref name="repair"/> every accessor's <c>min</c> and <c>max</c> are dropped.
    /// Stale bounds (a vertex moved after they were written, a rounding in the exporter) are the commonest defect
    /// the library's strict and repairing modes both refuse; Godot and Blender import such files, and nothing here
    /// reads the bounds. With <paramref name="firstAnimation"/> (a file read again to be written, <see cref="ReadAgain"/>),
    /// an animation of that name and nothing else is put first in its list of animations: SharpGLTF appends the
    /// animations it creates and cannot reorder them, and its reader refuses empty channel and sampler lists but not
    /// missing ones.
    /// </summary>
    private static string Prepare(string json, string name, bool repair, Dictionary<string, string> elements, string? firstAnimation)
    {
        json = json.TrimStart('\uFEFF');
        if (json.Contains('\uFFFD', StringComparison.Ordinal))
        {
            // The library decodes the bytes with replacement characters: text that was not UTF-8 shows as U+FFFD.
            throw new GltfException($"{name} is not a glTF file: its JSON is not valid UTF-8 text.");
        }

        CheckJson(json, name, elements);
        if ((!repair && firstAnimation is null) || JsonNode.Parse(json) is not JsonObject prepared)
        {
            return json;
        }

        if (repair && prepared["accessors"] is JsonArray accessors)
        {
            foreach (JsonObject accessor in accessors.OfType<JsonObject>())
            {
                accessor.Remove("min");
                accessor.Remove("max");
            }
        }

        if (firstAnimation is not null)
        {
            // An animation of its own, first in the list, for the writer to fill with channels (nothing in glTF
            // refers to an animation by its index, so the user's clips move up one without a reference to mend).
            if (prepared["animations"] is not JsonArray animations)
            {
                animations = [];
                prepared["animations"] = animations;
            }

            animations.Insert(0, new JsonObject { ["name"] = firstAnimation });
        }

        return prepared.ToJsonString();
    }

    /// <summary>
    /// The checks made on a glTF's JSON text before it is read: it parses, is an object, repeats no key
    /// (<see cref="CheckUniqueKeys"/>), has a glTF 2.0 asset and only extensions we can read (<see cref="CheckAsset"/>), and
    /// a node hierarchy within bounds (<see cref="CheckNodes"/>). The URIs of buffers and images go into
    /// <paramref name="elements"/> (the URI as written, and the element, "buffer 2"), when given.
    /// </summary>
    /// <exception cref="GltfException">One of the checks fails; the message names the file and where.</exception>
    internal static void CheckJson(string json, string name, Dictionary<string, string>? elements = null)
    {
        JsonDocument document;
        try
        {
            document = JsonDocument.Parse(json);
        }
        catch (JsonException e)
        {
            throw new GltfException($"{name} is not a glTF file: {MessageText.Json(e)}.");
        }

        using (document)
        {
            JsonElement root = document.RootElement;
            if (root.ValueKind != JsonValueKind.Object)
            {
                string kind = root.ValueKind switch
                {
                    JsonValueKind.Array => "a list",
                    JsonValueKind.String => "a string",
                    JsonValueKind.Number => "a number",
                    _ => root.GetRawText(),
                };
                throw new GltfException($"{name} is not a glTF file: its JSON is {kind}, not an object.");
            }

            CheckUniqueKeys(root, name, []);
            CheckAsset(root, name);
            if (root.TryGetProperty("nodes", out JsonElement nodes) && nodes.ValueKind == JsonValueKind.Array)
            {
                CheckNodes(nodes, name);
            }

            if (root.TryGetProperty("skins", out JsonElement skins) && skins.ValueKind == JsonValueKind.Array)
            {
                CheckSkinJoints(skins, name);
            }

            foreach ((string list, string kind) in new[] { ("buffers", "buffer"), ("images", "image") })
            {
                if (elements is not null && root.TryGetProperty(list, out JsonElement items) && items.ValueKind == JsonValueKind.Array)
                {
                    int i = 0;
                    foreach (JsonElement item in items.EnumerateArray())
                    {
                        if (item.ValueKind == JsonValueKind.Object && item.TryGetProperty("uri", out JsonElement uri) && uri.ValueKind == JsonValueKind.String && uri.GetString() is string text)
                        {
                            elements.TryAdd(text, $"{kind} {i}");
                        }

                        i++;
                    }
                }
            }
        }
    }

    /// <summary>
    /// A repeated key is an error naming the key and where it repeats (readers differ in which of the two they keep,
    /// so the level baked could differ from the one the engine shows); so is a string or key that is not valid text
    /// (an escaped lone surrogate such as <c>\uD800</c>, which the JSON reader accepts but cannot turn into a string).
    /// Recursive within the JSON reader's nesting limit of 64.
    /// </summary>
    private static void CheckUniqueKeys(JsonElement element, string name, List<(string? Key, int Index)> path)
    {
        string At() => string.Concat(path.Select((p, i) => p.Key is null ? $"[{p.Index}]" : i == 0 ? p.Key : "." + p.Key));
        string Where() => path.Count == 0 ? "the top-level object" : $"the object at {At()}";
        GltfException NotUnicode() => new($"{name}: {(path.Count == 0 ? "the top-level JSON" : $"the JSON at {At()}")} holds text that is not valid Unicode (an escaped lone surrogate).");
        string Valid(JsonProperty property)
        {
            try
            {
                return property.Name;
            }
            catch (InvalidOperationException)
            {
                throw NotUnicode();
            }
        }

        if (element.ValueKind == JsonValueKind.Object)
        {
            // Most objects have a few keys: each compared with those before it, a set only past the first eight.
            HashSet<string>? seen = null;
            int k = 0;
            foreach (JsonProperty property in element.EnumerateObject())
            {
                string key = Valid(property);
                bool repeated = false;
                if (k < 8)
                {
                    int j = 0;
                    foreach (JsonProperty before in element.EnumerateObject())
                    {
                        if (j++ == k)
                        {
                            break;
                        }

                        repeated |= before.NameEquals(key);
                    }
                }
                else
                {
                    seen ??= [.. element.EnumerateObject().Take(k).Select(p => p.Name)];
                    repeated = !seen.Add(key);
                }

                if (repeated)
                {
                    throw new GltfException($"{name}: the key '{MessageText.Printable(key)}' appears twice in {Where()}.");
                }

                k++;
                if (property.Value.ValueKind is JsonValueKind.Object or JsonValueKind.Array or JsonValueKind.String)
                {
                    path.Add((key, 0));
                    CheckUniqueKeys(property.Value, name, path);
                    path.RemoveAt(path.Count - 1);
                }
            }
        }
        else if (element.ValueKind == JsonValueKind.Array)
        {
            int i = 0;
            foreach (JsonElement item in element.EnumerateArray())
            {
                if (item.ValueKind is JsonValueKind.Object or JsonValueKind.Array or JsonValueKind.String)
                {
                    path.Add((null, i));
                    CheckUniqueKeys(item, name, path);
                    path.RemoveAt(path.Count - 1);
                }

                i++;
            }
        }
        else if (element.ValueKind == JsonValueKind.String)
        {
            try
            {
                _ = element.GetString();
            }
            catch (InvalidOperationException)
            {
                throw NotUnicode();
            }
        }
    }

    /// <summary>
    /// A node's <c>translation</c>, <c>rotation</c>, <c>scale</c> and <c>matrix</c> are lists of exactly 3, 4, 3 and 16
    /// numbers: the library reads the first numbers of a longer list and fills a shorter one, so that a rotation written
    /// with an extra number would turn the bone silently.
    /// </summary>
    /// <exception cref="GltfException">One of them is not such a list.</exception>
    private static void CheckTransform(JsonElement node, int index, string name)
    {
        if (node.ValueKind != JsonValueKind.Object)
        {
            return;
        }

        foreach ((string key, int length) in Transforms)
        {
            if (node.TryGetProperty(key, out JsonElement value)
                && (value.ValueKind != JsonValueKind.Array || value.GetArrayLength() != length || value.EnumerateArray().Any(v => v.ValueKind != JsonValueKind.Number)))
            {
                string named = node.TryGetProperty("name", out JsonElement n) && n.ValueKind == JsonValueKind.String && n.GetString() is { Length: > 0 } text ? $" ('{MessageText.Printable(text)}')" : "";
                string seen = value.ValueKind == JsonValueKind.Array && value.GetArrayLength() == length
                    ? $"item {value.EnumerateArray().TakeWhile(v => v.ValueKind == JsonValueKind.Number).Count()} is {Describe(value.EnumerateArray().First(v => v.ValueKind != JsonValueKind.Number))}"
                    : $"not {Describe(value)}";
                throw new GltfException($"{name}: node {index}{named} has a malformed {key}: it must be a list of {length} numbers; {seen}.");
            }
        }
    }

    private static readonly (string Key, int Length)[] Transforms = [("translation", 3), ("rotation", 4), ("scale", 3), ("matrix", 16)];

    /// <summary>A skin that lists a node as its joint twice (the library reads it, and the bone would be two bones).</summary>
    /// <exception cref="GltfException">A skin lists a node twice.</exception>
    private static void CheckSkinJoints(JsonElement skins, string name)
    {
        int s = 0;
        foreach (JsonElement skin in skins.EnumerateArray())
        {
            if (skin.ValueKind == JsonValueKind.Object && skin.TryGetProperty("joints", out JsonElement joints) && joints.ValueKind == JsonValueKind.Array)
            {
                var seen = new HashSet<int>();
                foreach (JsonElement joint in joints.EnumerateArray())
                {
                    if (joint.ValueKind == JsonValueKind.Number && joint.TryGetInt32(out int node) && !seen.Add(node))
                    {
                        throw new GltfException($"{name}: skin {s} lists node {node} as a joint twice.");
                    }
                }
            }

            s++;
        }
    }

    /// <summary>The glTF extensions a file may require: those whose data the library decodes for us.</summary>
    private static readonly HashSet<string> SupportedRequiredExtensions = ["KHR_mesh_quantization", "KHR_materials_emissive_strength"];

    /// <summary>
    /// The asset's version and required extensions, which the library reads with misleading messages when they are
    /// of the wrong type ("Empty array found" for a version written as a number) or not checked at all.
    /// </summary>
    private static void CheckAsset(JsonElement root, string name)
    {
        if (!root.TryGetProperty("asset", out JsonElement asset) || asset.ValueKind != JsonValueKind.Object)
        {
            throw new GltfException($"{name} is not a glTF 2.0 asset: it has {(root.TryGetProperty("asset", out JsonElement other) ? $"'asset' {Describe(other)}" : "no 'asset'")}, not an object with a version.");
        }

        if (!asset.TryGetProperty("version", out JsonElement version) || version.ValueKind != JsonValueKind.String)
        {
            throw new GltfException($"{name} is not a glTF 2.0 asset: asset.version is {(asset.TryGetProperty("version", out JsonElement v) ? Describe(v) : "missing")}, not a string such as \"2.0\".");
        }

        if (!(version.GetString() ?? "").StartsWith("2.", StringComparison.Ordinal))
        {
            throw new GltfException($"{name} is not a glTF 2.0 asset (asset.version is '{MessageText.Printable(version.GetString() ?? "")}').");
        }

        if (root.TryGetProperty("extensionsRequired", out JsonElement required))
        {
            if (required.ValueKind != JsonValueKind.Array)
            {
                throw new GltfException($"{name}: extensionsRequired is {Describe(required)}, not a list of extension names.");
            }

            int i = 0;
            foreach (JsonElement item in required.EnumerateArray())
            {
                string id = item.ValueKind == JsonValueKind.String ? item.GetString() ?? "" : throw new GltfException($"{name}: extensionsRequired item {i} is {Describe(item)}, not an extension name.");
                if (!SupportedRequiredExtensions.Contains(id))
                {
                    throw new GltfException($"{name} requires the glTF extension {MessageText.Printable(id)}, which Ballistic cannot read; export it without compression.");
                }

                i++;
            }
        }
    }

    /// <summary>A short description of a JSON value for messages: "the string \"x\"", "the number 2.0", "a list of 3", "an object", "null".</summary>
    private static string Describe(JsonElement element)
    {
        static string Clip(string s) => s.Length > 40 ? s[..37] + "…" : s;
        return element.ValueKind switch
        {
            JsonValueKind.Object => "an object",
            JsonValueKind.Array => element.GetArrayLength() == 0 ? "an empty list" : $"a list of {element.GetArrayLength()}",
            JsonValueKind.String => $"the string {Clip(MessageText.Printable(element.GetRawText()))}",
            JsonValueKind.Number => $"the number {Clip(element.GetRawText())}",
            _ => element.GetRawText(),
        };
    }

    /// <summary>A URI percent-decoded, or as it is when it does not decode.</summary>
    private static string Unescaped(string uri)
    {
        try
        {
            return Uri.UnescapeDataString(uri);
        }
        catch (UriFormatException)
        {
            return uri;
        }
    }

    /// <summary>
    /// The node hierarchy, linear in the nodes: each child listed by one parent, once, not itself; no cycle; at most
    /// <see cref="MaxNodeDepth"/> deep. Children that are not node indices are left to the library.
    /// </summary>
    /// <exception cref="GltfException">A node has two parents, lists a child twice or itself, the hierarchy loops, or is deeper than allowed.</exception>
    private static void CheckNodes(JsonElement nodes, string name)
    {
        int count = nodes.GetArrayLength();
        int[] parents = new int[count];
        Array.Fill(parents, -1);
        int n = 0;
        foreach (JsonElement node in nodes.EnumerateArray())
        {
            CheckTransform(node, n, name);
            if (node.ValueKind == JsonValueKind.Object && node.TryGetProperty("children", out JsonElement children) && children.ValueKind == JsonValueKind.Array)
            {
                foreach (JsonElement child in children.EnumerateArray())
                {
                    if (child.ValueKind != JsonValueKind.Number || !child.TryGetInt32(out int c) || c < 0 || c >= count)
                    {
                        continue;
                    }

                    if (c == n)
                    {
                        throw new GltfException($"{name}: node {n} lists itself as a child.");
                    }

                    if (parents[c] == n)
                    {
                        throw new GltfException($"{name}: node {n} lists node {c} as a child twice.");
                    }

                    if (parents[c] >= 0)
                    {
                        throw new GltfException($"{name}: node {c} is a child of both node {parents[c]} and node {n}; a glTF node has at most one parent.");
                    }

                    parents[c] = n;
                }
            }

            n++;
        }

        // With one parent each, following parents from any node ends at a root or loops; each node is measured once.
        int[] depth = new int[count]; // 0 unmeasured, -1 on the current path, else its depth (a root is 1)
        var path = new List<int>();
        for (int start = 0; start < count; start++)
        {
            path.Clear();
            int p = start;
            while (p >= 0 && depth[p] == 0)
            {
                depth[p] = -1;
                path.Add(p);
                p = parents[p];
            }

            if (p >= 0 && depth[p] < 0)
            {
                throw new GltfException($"{name}: the node hierarchy has a cycle through node {p}.");
            }

            int below = p >= 0 ? depth[p] : 0;
            for (int i = path.Count - 1; i >= 0; i--)
            {
                depth[path[i]] = ++below;
                if (below > MaxNodeDepth)
                {
                    throw new GltfException($"{name}: node {path[i]} lies {below} deep in the node hierarchy; at most {MaxNodeDepth} levels are read (GltfModel.MaxNodeDepth).");
                }
            }
        }
    }

    /// <summary>
    /// One line from a SharpGLTF exception: its message without the library's advice to run the validator and its
    /// parameter names. Where the library's validation speaks of an element (<c>Accessor[3] …</c>), <see cref="Locate"/>
    /// names it further. Where its JSON reader or a failed argument check speaks in .NET's words (which name no
    /// element: the reader does not say where it was), the message says what that means for the file.
    /// </summary>
    private static string Describe(Exception e)
    {
        string message = e switch
        {
            // SharpGLTF's JSON reader throws these for a token of a kind it does not expect at a schema field (its
            // _JSonSerializationExtensions.AsEnum on "target": true throws NotImplementedException): the file is at
            // fault, and Pinpointed adds where (304 of the fuzz suite's refusals read this way).
            NotImplementedException or NotSupportedException => "its JSON has a value of a type the glTF 2.0 schema does not allow where it is",
            NotFiniteNumberException => "a vertex attribute holds a number that is not finite (NaN or infinity), which the library's repair cannot mend",
            EndOfStreamException => "the file ends before its content does (truncated)",
            _ => e.Message,
        };
        int advice = message.IndexOf("Model generated by", StringComparison.Ordinal);
        message = advice >= 0 ? message[..advice] : message;
        message = ParameterName().Replace(message, "").Trim();
        string where = message.Split(' ', 2)[0].TrimEnd(':');
        string? plain = GlbLength().Match(message) is { Success: true } length
            ? $"its GLB header gives {length.Groups[1].Value} bytes but the file holds {length.Groups[2].Value}{(long.Parse(length.Groups[2].Value, System.Globalization.CultureInfo.InvariantCulture) < long.Parse(length.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture) ? " (it is truncated)" : "")}"
            : Capacity().Match(message) is { Success: true } capacity
                ? $"a GLB chunk declares {capacity.Groups[1].Value} bytes, more than the file holds (it is truncated or corrupt)"
                : TokenAsNumber().Match(message) is { Success: true } token
                    ? $"its JSON has {Token(token.Groups[1].Value)} where the glTF 2.0 schema wants a number"
                    : UnexpectedToken().Match(message) is { Success: true } unexpected
                        ? $"its JSON has {Token(unexpected.Groups[1].Value)} where the glTF 2.0 schema wants another kind of value"
                        : EnumValue().Match(message) is { Success: true } enumValue
                            ? $"its JSON has the value '{enumValue.Groups[1].Value}' where the glTF 2.0 schema allows only its own names"
                        : message.Contains("Empty array found", StringComparison.Ordinal) ? "its JSON has an empty list where the glTF 2.0 schema wants a value or a list with items"
                        : message.Contains("is out of bounds for an Int", StringComparison.Ordinal) ? "its JSON has a number where the glTF 2.0 schema wants a whole number within range"
                        : message.Contains("System.Text.Json.JsonException", StringComparison.Ordinal) ? "its JSON does not follow the glTF 2.0 schema"
                        : message.Contains("Offset and length were out of bounds", StringComparison.Ordinal) ? "an offset or length runs past the end of the bytes it refers to (a buffer view past its buffer, or an accessor past its view)"
                        : RuntimeWords.Any(w => message.Contains(w, StringComparison.Ordinal)) ? "an element refers to another that does not exist (an index past the end of its list)"
                        : null;
        if (plain is not null)
        {
            message = Element().IsMatch(where) ? $"{where} {plain}" : plain;
        }
        else if (where == "ModelRoot")
        {
            message = message["ModelRoot".Length..].Trim();
        }

        string line = MessageText.Printable(message.ReplaceLineEndings(" ").Trim());
        return line.Length == 0 ? $"SharpGLTF cannot read it ({e.GetType().Name})" : line.TrimEnd('.') + ".";

        static string Token(string kind) => kind switch
        {
            "StartArray" => "a list",
            "StartObject" => "an object",
            "String" => "a string",
            "Number" => "a number",
            "True" or "False" => "true or false",
            "Null" => "null",
            _ => "a value",
        };
    }

    [GeneratedRegex(@"Cannot get the value of a token type '(\w+)' as a number")]
    private static partial Regex TokenAsNumber();

    [GeneratedRegex(@"(?s)Value '(.*)' not found in 'SharpGLTF\.[\w.]+'")]
    private static partial Regex EnumValue();

    [GeneratedRegex(@"Unexpected token (\w+)")]
    private static partial Regex UnexpectedToken();

    /// <summary>.NET's own phrases for a failed argument check, which say nothing to the file's author.</summary>
    private static readonly string[] RuntimeWords = ["Index was out of range", "Specified argument was out of the range", "Object reference not set", "Value cannot be null"];

    [GeneratedRegex(@"^(Accessor|BufferView|Buffer|Node|Mesh|MeshPrimitive|Material|Skin|Texture|Image|Sampler|Scene|Camera|Animation)\[(\d+)\](.*)$")]
    private static partial Regex Element();

    [GeneratedRegex(@"specified length of the file \((\d+)\) is not equal to the actual length of the file \((\d+)\)")]
    private static partial Regex GlbLength();

    [GeneratedRegex(@"(\d+) bytes to read exceeds maximum capacity")]
    private static partial Regex Capacity();

    [GeneratedRegex(@"\s*\(Parameter '[^']*'\)")]
    private static partial Regex ParameterName();
}
