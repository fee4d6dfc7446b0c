using System.Buffers.Binary;
using System.Numerics;
using System.Security.Cryptography;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.IO;

namespace Ballistic.Planner.Levels;

/// <summary>
/// A level as the planner sees it: a soup of world-space triangles (metres, Y up), each with a material. Load one from
/// a glTF file (<see cref="GltfLevelLoader"/>) or build one from mesh arrays (the runtime's <c>SourceGeometry</c>);
/// both check the input.
/// </summary>
public sealed class Level
{
    private string? _fingerprint;
    private TriangleBvh? _bvh;

    internal Level(Triangle[] triangles, int[] materialIndices, LevelMaterial[] materials, int droppedDegenerate, string source)
    {
        Triangles = triangles;
        MaterialIndices = materialIndices;
        Materials = materials;
        DroppedDegenerateTriangles = droppedDegenerate;
        Source = source;
        HasSurfaceCosts = Array.Exists(materials, m => m.HasCost);
        Bounds = Aabb.Empty;
        foreach (Triangle t in triangles)
        {
            Bounds = Aabb.Union(Bounds, t.Bounds);
        }
    }

    /// <summary>The triangles, world space; none is degenerate and every coordinate is finite.</summary>
    internal IReadOnlyList<Triangle> Triangles { get; }

    /// <summary>For each triangle, the index of its material in <see cref="Materials"/>.</summary>
    public IReadOnlyList<int> MaterialIndices { get; }

    /// <summary>The level's materials.</summary>
    public IReadOnlyList<LevelMaterial> Materials { get; }

    /// <summary>How many zero-area triangles the input held; they were dropped.</summary>
    public int DroppedDegenerateTriangles { get; }

    /// <summary>Where the level came from (a file path, or a name given by code).</summary>
    public string Source { get; }

    /// <summary>
    /// What was wrong with the level's glTF file and was repaired as it loaded (one line: stale accessor bounds, a
    /// rotation a little off unit length, as SharpGLTF's validation found them), or <c>null</c> when the file was
    /// valid as it was. Tools show it once; the level itself is right.
    /// </summary>
    public string? Repaired { get; internal set; }

    /// <summary>World bounds of all triangles.</summary>
    internal Aabb Bounds { get; }

    /// <summary>
    /// A hex SHA-256 of the triangles and their friction overrides: two levels with the same fingerprint plan the
    /// same. Roadmap files record it so that a roadmap is never used on another level.
    /// </summary>
    public string Fingerprint => _fingerprint ??= ComputeFingerprint();

    /// <summary>
    /// The bounding-volume hierarchy of <see cref="Triangles"/>, built on first use and shared by every scene and check
    /// on this level (the level never changes). Thread-safe: two threads asking at once may both build it; one is kept.
    /// </summary>
    internal TriangleBvh Bvh => LazyInitializer.EnsureInitialized(ref _bvh, () => new TriangleBvh(Triangles));

    /// <summary>
    /// The first triangle met by the segment <c>origin + t·direction</c>, <c>t ∈ [0, maxT]</c> (world metres; both faces
    /// count), as the planner sees the level: no physics bodies needed. Thread-safe.
    /// </summary>
    /// <param name="origin">Start of the segment, world metres.</param>
    /// <param name="direction">Direction of the segment (any length; <paramref name="maxT"/> is in units of it).</param>
    /// <param name="maxT">Largest ray parameter: 1 with <c>direction = to − origin</c> tests the segment to <c>to</c>.</param>
    /// <param name="hit">The hit, when there is one.</param>
    /// <returns>True when the segment meets the level.</returns>
    public bool Raycast(Vector3 origin, Vector3 direction, float maxT, out RayHit hit) => Bvh.Raycast(origin, direction, maxT, out hit);

    /// <summary>True when some material costs more than plain ground to cross or enter (<see cref="LevelMaterial.TravelCost"/>, <see cref="LevelMaterial.EnterCost"/>).</summary>
    internal bool HasSurfaceCosts { get; }

    /// <summary>The friction of triangle <paramref name="triangle"/>: its material's override, else <paramref name="defaultFriction"/>.</summary>
    public float FrictionOf(int triangle, float defaultFriction) =>
        Materials[MaterialIndices[triangle]].Friction ?? defaultFriction;

    private string ComputeFingerprint()
    {
        using var hash = IncrementalHash.CreateHash(HashAlgorithmName.SHA256);
        Span<byte> buffer = stackalloc byte[40];
        for (int i = 0; i < Triangles.Count; i++)
        {
            Triangle t = Triangles[i];
            float friction = Materials[MaterialIndices[i]].Friction ?? float.NaN;
            ReadOnlySpan<float> values = [t.A.X, t.A.Y, t.A.Z, t.B.X, t.B.Y, t.B.Z, t.C.X, t.C.Y, t.C.Z, friction];
            for (int k = 0; k < values.Length; k++)
            {
                BinaryPrimitives.WriteSingleLittleEndian(buffer[(k * 4)..], values[k]);
            }

            hash.AppendData(buffer);
        }

        return HexText.Lower(hash.GetHashAndReset());
    }
}
