using System.Numerics;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Levels;

/// <summary>
/// Assembles a <see cref="Level"/> from meshes given as raw arrays, checking them: a NaN or infinite vertex is an
/// error naming its mesh; zero-area triangles are dropped and counted; a level without triangles is an error.
/// </summary>
public sealed class LevelBuilder
{
    private readonly List<Triangle> _triangles = [];
    private readonly List<int> _materialIndices = [];
    private readonly List<LevelMaterial> _materials = [];
    private readonly Dictionary<LevelMaterial, int> _materialIds = [];
    private int _dropped;

    /// <summary>Creates a builder.</summary>
    /// <param name="source">Where the level comes from, used in error messages (a file path or a name).</param>
    public LevelBuilder(string source)
    {
        Source = source;
    }

    /// <summary>Where the level comes from.</summary>
    public string Source { get; }

    /// <summary>Triangles added so far (degenerate ones excluded).</summary>
    public int TriangleCount => _triangles.Count;

    /// <summary>
    /// Adds an indexed triangle mesh.
    /// </summary>
    /// <param name="meshName">Name used in error messages.</param>
    /// <param name="positions">Vertex positions in the mesh's local frame, metres.</param>
    /// <param name="indices">Three vertex indices per triangle, counter-clockwise seen from the front.</param>
    /// <param name="toWorld">Local-to-world transform (System.Numerics row-vector convention).</param>
    /// <param name="material">Material of every triangle of the mesh.</param>
    /// <exception cref="LevelException">A vertex is NaN or infinite, an index is out of range, or the index count is not a multiple of three.</exception>
    public LevelBuilder AddMesh(string meshName, ReadOnlySpan<Vector3> positions, ReadOnlySpan<int> indices, Matrix4x4 toWorld, LevelMaterial material)
    {
        ArgumentNullException.ThrowIfNull(material);
        if (indices.Length % 3 != 0)
        {
            throw new LevelException($"Mesh '{meshName}' in {Source}: {indices.Length} indices is not a whole number of triangles.");
        }

        if (!IsFinite(toWorld))
        {
            throw new LevelException($"Mesh '{meshName}' in {Source}: its transform holds NaN or infinite values.");
        }

        var world = new Vector3[positions.Length];
        for (int i = 0; i < positions.Length; i++)
        {
            Vector3 p = positions[i];
            if (!float.IsFinite(p.X) || !float.IsFinite(p.Y) || !float.IsFinite(p.Z))
            {
                throw new LevelException($"Mesh '{meshName}' in {Source}: vertex {i} is not finite ({p.X}, {p.Y}, {p.Z}).");
            }

            world[i] = Vector3.Transform(p, toWorld);
        }

        int materialIndex = MaterialIndex(material);
        for (int i = 0; i < indices.Length; i += 3)
        {
            int a = indices[i];
            int b = indices[i + 1];
            int c = indices[i + 2];
            if ((uint)a >= (uint)world.Length || (uint)b >= (uint)world.Length || (uint)c >= (uint)world.Length)
            {
                throw new LevelException($"Mesh '{meshName}' in {Source}: triangle {i / 3} uses a vertex index out of range (mesh has {world.Length} vertices).");
            }

            AddChecked(new Triangle(world[a], world[b], world[c]), materialIndex);
        }

        return this;
    }

    /// <summary>Adds one world-space triangle.</summary>
    /// <exception cref="LevelException">A vertex is NaN or infinite.</exception>
    public LevelBuilder AddTriangle(Triangle triangle, LevelMaterial material)
    {
        ArgumentNullException.ThrowIfNull(material);
        if (!triangle.IsFinite)
        {
            throw new LevelException($"Triangle {TriangleCount + _dropped} in {Source} is not finite.");
        }

        AddChecked(triangle, MaterialIndex(material));
        return this;
    }

    /// <summary>Finishes the level.</summary>
    /// <exception cref="LevelException">The level has no (non-degenerate) triangle.</exception>
    public Level Build()
    {
        if (_triangles.Count == 0)
        {
            throw new LevelException(_dropped > 0
                ? $"The level {Source} is empty: all {_dropped} of its triangles have zero area."
                : $"The level {Source} is empty: it has no triangles.");
        }

        return new Level([.. _triangles], [.. _materialIndices], [.. _materials], _dropped, Source);
    }

    private void AddChecked(Triangle triangle, int materialIndex)
    {
        // Zero area relative to the triangle's size: the cross product vanishes or is lost in rounding.
        float scale = MathF.Max(Vector3.DistanceSquared(triangle.A, triangle.B), MathF.Max(Vector3.DistanceSquared(triangle.B, triangle.C), Vector3.DistanceSquared(triangle.C, triangle.A)));
        float twiceArea = triangle.ScaledNormal.Length();
        if (!(twiceArea > 1e-7f * scale) || !(twiceArea > 1e-12f))
        {
            _dropped++;
            return;
        }

        _triangles.Add(triangle);
        _materialIndices.Add(materialIndex);
    }

    private int MaterialIndex(LevelMaterial material)
    {
        if (!_materialIds.TryGetValue(material, out int index))
        {
            index = _materials.Count;
            _materials.Add(material);
            _materialIds.Add(material, index);
        }

        return index;
    }

    private static bool IsFinite(Matrix4x4 m) =>
        float.IsFinite(m.M11) && float.IsFinite(m.M12) && float.IsFinite(m.M13) && float.IsFinite(m.M14) &&
        float.IsFinite(m.M21) && float.IsFinite(m.M22) && float.IsFinite(m.M23) && float.IsFinite(m.M24) &&
        float.IsFinite(m.M31) && float.IsFinite(m.M32) && float.IsFinite(m.M33) && float.IsFinite(m.M34) &&
        float.IsFinite(m.M41) && float.IsFinite(m.M42) && float.IsFinite(m.M43) && float.IsFinite(m.M44);
}
