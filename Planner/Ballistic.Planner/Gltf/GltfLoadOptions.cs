namespace Ballistic.Planner.Gltf;

/// <summary>
/// Limits on what loading a glTF level or character may cost, so that a file made by a tool or a modder cannot use
/// up the machine: the bytes read from disk, and the vertices and triangles read from its meshes. Every limit is
/// checked before the work it bounds is done; a file beyond one is a <see cref="GltfException"/> (a level's a
/// <see cref="Levels.LevelException"/>, a character's a <see cref="Rigs.RigException"/>) naming the limit. The defaults
/// are generous: 2 GiB, 60 million vertices and 20 million triangles.
/// </summary>
public sealed record GltfLoadOptions
{
    /// <summary>The default <see cref="MaxBytes"/>: 2 GiB.</summary>
    public const long DefaultMaxBytes = 2L * 1024 * 1024 * 1024;

    /// <summary>The default <see cref="MaxVertices"/>: 60 million.</summary>
    public const int DefaultMaxVertices = 60_000_000;

    /// <summary>The default <see cref="MaxTriangles"/>: 20 million.</summary>
    public const int DefaultMaxTriangles = 20_000_000;

    private readonly long _maxBytes = DefaultMaxBytes;
    private readonly int _maxVertices = DefaultMaxVertices;
    private readonly int _maxTriangles = DefaultMaxTriangles;

    /// <summary>The default limits.</summary>
    public static GltfLoadOptions Default { get; } = new();

    /// <summary>
    /// The most bytes one load reads from disk: the <c>.glb</c> or <c>.gltf</c> file and its external buffers
    /// together, data URIs included (an image is read later, on its own, within the same limit). A file larger than
    /// what is left is refused before it is read. A limb spec is held to the same limit.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException">The value is not positive.</exception>
    public long MaxBytes
    {
        get => _maxBytes;
        init => _maxBytes = value > 0 ? value : throw new ArgumentOutOfRangeException(nameof(value), value, "MaxBytes must be positive.");
    }

    /// <summary>
    /// The most vertices a load reads from the file's meshes, each instance of a mesh counted (a level's meshes,
    /// or a character's skinned meshes). Checked from the accessors' declared counts before they are read.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException">The value is not positive.</exception>
    public int MaxVertices
    {
        get => _maxVertices;
        init => _maxVertices = value > 0 ? value : throw new ArgumentOutOfRangeException(nameof(value), value, "MaxVertices must be positive.");
    }

    /// <summary>
    /// The most triangles a level may hold, each instance of a mesh counted and zero-area triangles included.
    /// Checked from the accessors' declared counts before they are read.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException">The value is not positive.</exception>
    public int MaxTriangles
    {
        get => _maxTriangles;
        init => _maxTriangles = value > 0 ? value : throw new ArgumentOutOfRangeException(nameof(value), value, "MaxTriangles must be positive.");
    }
}
