using System.Globalization;
using System.Numerics;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.IO;

namespace Ballistic.Planner.Levels;

/// <summary>
/// Assembles a <see cref="Level"/> from meshes given as raw arrays, checking them: a NaN or infinite vertex, or one
/// placed beyond ±<see cref="MaxCoordinate"/> metres, is an error naming its mesh and vertex; zero-area triangles are
/// dropped and counted; a level without triangles is an error.
/// </summary>
internal sealed class LevelBuilder
{
    /// <summary>How far from the origin, in metres along each axis, a level may reach: 1,000 km.</summary>
    public const float MaxCoordinate = 1e6f;

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
    /// <exception cref="LevelException">A vertex is NaN or infinite or lies beyond ±<see cref="MaxCoordinate"/>, an index is out of range, the index count is not a multiple of three, or the material's costs are out of range.</exception>
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
                throw new LevelException($"Mesh '{meshName}' in {Source}: vertex {i} is not finite ({Format(p)}).");
            }

            world[i] = Vector3.Transform(p, toWorld);
            CheckReach(world[i], $"Mesh '{meshName}' in {Source}: vertex {i}");
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
    /// <exception cref="LevelException">A vertex is NaN or infinite or lies beyond ±<see cref="MaxCoordinate"/>, or the material's costs are out of range.</exception>
    public LevelBuilder AddTriangle(Triangle triangle, LevelMaterial material)
    {
        ArgumentNullException.ThrowIfNull(material);
        if (!triangle.IsFinite)
        {
            throw new LevelException($"Triangle {TriangleCount + _dropped} in {Source} is not finite.");
        }

        CheckReach(triangle.A, $"Triangle {TriangleCount + _dropped} in {Source}: its first corner");
        CheckReach(triangle.B, $"Triangle {TriangleCount + _dropped} in {Source}: its second corner");
        CheckReach(triangle.C, $"Triangle {TriangleCount + _dropped} in {Source}: its third corner");

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
            if (LevelMaterial.CostProblem(material.TravelCost, material.EnterCost) is string problem)
            {
                throw new LevelException($"Material '{MessageText.Printable(material.Name)}' in {Source}: its {problem}.");
            }

            index = _materials.Count;
            _materials.Add(material);
            _materialIds.Add(material, index);
        }

        return index;
    }

    /// <summary>An error unless every coordinate of <paramref name="p"/> lies within ±<see cref="MaxCoordinate"/>.</summary>
    private static void CheckReach(Vector3 p, string what)
    {
        float worst = MathF.Max(MathF.Abs(p.X), MathF.Max(MathF.Abs(p.Y), MathF.Abs(p.Z)));
        if (!(worst <= MaxCoordinate))
        {
            float coordinate = MathF.Abs(p.X) == worst ? p.X : MathF.Abs(p.Y) == worst ? p.Y : p.Z;
            throw new LevelException(float.IsFinite(worst)
                ? $"{what} has a coordinate of {coordinate.ToString("G4", CultureInfo.InvariantCulture)} m, beyond the ±1e6 m a level may span."
                : $"{what} is taken by its node transforms to ({Format(p)}), beyond the ±1e6 m a level may span.");
        }
    }

    private static string Format(Vector3 p) => string.Create(CultureInfo.InvariantCulture, $"{p.X:G4}, {p.Y:G4}, {p.Z:G4}");

    private static bool IsFinite(Matrix4x4 m) =>
        float.IsFinite(m.M11) && float.IsFinite(m.M12) && float.IsFinite(m.M13) && float.IsFinite(m.M14) &&
        float.IsFinite(m.M21) && float.IsFinite(m.M22) && float.IsFinite(m.M23) && float.IsFinite(m.M24) &&
        float.IsFinite(m.M31) && float.IsFinite(m.M32) && float.IsFinite(m.M33) && float.IsFinite(m.M34) &&
        float.IsFinite(m.M41) && float.IsFinite(m.M42) && float.IsFinite(m.M43) && float.IsFinite(m.M44);
}
