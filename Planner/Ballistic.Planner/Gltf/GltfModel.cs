using System.Numerics;
using System.Text.Json;
using System.Text.Json.Nodes;
using System.Text.RegularExpressions;
using Ballistic.Planner.IO;
using SharpGLTF.Schema2;
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
    private GltfModel(ModelRoot root, string name, GltfLoadOptions options, string? repaired)
    {
        Root = root;
        Name = name;
        Options = options;
        Repaired = repaired;
    }

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
        byte[] bytes = InputFile.Read(path, options.MaxBytes, "GltfLoadOptions.MaxBytes", (problem, e) => new GltfException($"{MessageText.Printable(path)} {problem}.", e!));
        string? directory;
        try
        {
            directory = Path.GetDirectoryName(Path.GetFullPath(path));
        }
        catch (Exception e) when (e is ArgumentException or IOException or NotSupportedException)
        {
            throw new GltfException($"{MessageText.Printable(path)} cannot be read: {MessageText.Printable(e.Message.TrimEnd('.'))}.", e);
        }

        return Parse(bytes, path, directory, options);
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
            return new GltfModel(Read(bytes, printable, directory, options, ValidationMode.Strict, null), name, options, null);
        }
        catch (ModelException strict)
        {
            try
            {
                return new GltfModel(Read(bytes, printable, directory, options, ValidationMode.TryFix, WithoutBounds), name, options, Describe(strict));
            }
            catch (ModelException e)
            {
                throw new GltfException($"{printable}: {Describe(e)}");
            }
        }
    }

    /// <summary>The local transform of <paramref name="node"/> (its matrix, or translation · rotation · scale), row-vector convention, checked finite.</summary>
    /// <exception cref="GltfException">The node's matrix holds a number that is not finite.</exception>
    public Matrix4x4 LocalTransform(Node node)
    {
        Matrix4x4 local = node.LocalMatrix;
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

    /// <summary>" ('name')" for an element with a name, else nothing: for messages.</summary>
    public static string Named(string? name) => string.IsNullOrEmpty(name) ? "" : $" ('{MessageText.Printable(name)}')";

    /// <summary>
    /// Reads with SharpGLTF in <paramref name="mode"/>, external files through the callback that confines them to
    /// <paramref name="directory"/> and to what is left of the byte limit; every exception becomes a
    /// <see cref="GltfException"/> but the library's <see cref="ModelException"/>, left to the caller.
    /// </summary>
    private static ModelRoot Read(byte[] bytes, string name, string? directory, GltfLoadOptions options, ValidationMode mode, JsonFilterCallback? filter)
    {
        long budget = options.MaxBytes - bytes.Length;
        GltfException? refused = null;
        ArraySegment<byte> External(string uri)
        {
            try
            {
                if (directory is null)
                {
                    throw new GltfException($"{name}: it refers to the external file '{MessageText.Printable(uri)}', which cannot be resolved here.");
                }

                string path = ReferencedFile.Resolve(directory, uri, problem => new GltfException($"{name}: the URI '{MessageText.Printable(uri)}' {problem}."));
                byte[] data = InputFile.Read(path, Math.Max(budget, 0), $"what is left of the limit of {options.MaxBytes} with the glTF and its other files, GltfLoadOptions.MaxBytes", (problem, e) => new GltfException($"{name}: the file '{MessageText.Printable(uri)}' {problem}.", e!));
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
            context.JsonPreprocessor = filter;
            using var stream = new MemoryStream(bytes, writable: false);
            return context.ReadSchema2(stream);
        }
        catch (ModelException) when (refused is null)
        {
            throw;
        }
        catch (Exception e) when (e is not OutOfMemoryException and not StackOverflowException)
        {
            // The library met something it does not expect (a malformed GLB header, JSON that is not glTF's shape,
            // an extension it cannot decode): the file is at fault, not the program, and it says so in one line.
            throw refused ?? new GltfException($"{name}: {Describe(e)}");
        }
    }

    /// <summary>
    /// The repair pass's filter on the JSON: every accessor's <c>min</c> and <c>max</c> dropped. Stale bounds (a
    /// vertex moved after they were written, a rounding in the exporter) are the commonest defect SharpGLTF's strict
    /// and repairing modes both refuse; Godot and Blender import such files, and nothing here reads the bounds.
    /// </summary>
    private static string WithoutBounds(string json)
    {
        try
        {
            if (JsonNode.Parse(json) is JsonObject root && root["accessors"] is JsonArray accessors)
            {
                foreach (JsonObject accessor in accessors.OfType<JsonObject>())
                {
                    accessor.Remove("min");
                    accessor.Remove("max");
                }

                return root.ToJsonString();
            }
        }
        catch (Exception e) when (e is JsonException or ArgumentException or InvalidOperationException)
        {
            // Malformed, or a key twice in one object: left as it is, for the library to say what is wrong with it.
        }

        return json;
    }

    /// <summary>
    /// One line from a SharpGLTF exception: its message without the library's advice to run the validator and its
    /// parameter names, and in place of a .NET message that names a failed argument check (an index out of range in a
    /// link the library did not validate), what it means for the file.
    /// </summary>
    private static string Describe(Exception e)
    {
        string message = e switch
        {
            JsonException => "the JSON is malformed" + (e.Message.Length > 0 ? ": " + e.Message : ""),
            EndOfStreamException => "the file ends before its content does (truncated)",
            _ => e.Message,
        };
        int advice = message.IndexOf("Model generated by", StringComparison.Ordinal);
        message = advice >= 0 ? message[..advice] : message;
        message = ParameterName().Replace(message, "");
        if (DuplicateKey().Match(message) is { Success: true } duplicate)
        {
            message = $"the JSON names '{duplicate.Groups[1].Value.TrimEnd('.')}' twice in one object";
        }
        else if (RuntimeWords.Any(w => message.Contains(w, StringComparison.Ordinal)))
        {
            string where = message.Split(' ', 2)[0];
            message = $"{where}: an element refers to another that does not exist (an index past the end of its list)";
        }

        string line = MessageText.Printable(message.ReplaceLineEndings(" ").Trim());
        return line.Length == 0 ? $"SharpGLTF cannot read it ({e.GetType().Name})" : line.TrimEnd('.') + ".";
    }

    /// <summary>.NET's own phrases for a failed argument check, which say nothing to the file's author.</summary>
    private static readonly string[] RuntimeWords = ["Index was out of range", "Specified argument was out of the range", "Object reference not set", "Value cannot be null"];

    [GeneratedRegex(@"An item with the same key has already been added\. Key: (\S+)")]
    private static partial Regex DuplicateKey();

    [GeneratedRegex(@"\s*\(Parameter '[^']*'\)")]
    private static partial Regex ParameterName();
}
