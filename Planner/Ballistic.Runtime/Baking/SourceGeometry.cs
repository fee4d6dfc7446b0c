using System.Globalization;
using System.Numerics;
using Ballistic.Planner.Levels;
using Ballistic.Runtime.Core;

namespace Ballistic.Runtime.Baking;

/// <summary>
/// Collects a level's triangles from several sources, the way Godot's navigation mesh baking parses its source
/// geometry (mesh instances and static collision shapes, each with its global transform), and builds the planner's
/// <see cref="Level"/> from them. Sources: a triangle list (<see cref="AddFaces"/>, what <c>Mesh.GetFaces()</c> and
/// <c>ConcavePolygonShape3D.GetFaces()</c> return) and a centred box (<see cref="AddBox"/>, a <c>BoxShape3D</c>).
/// </summary>
/// <remarks>
/// <para>
/// Frames: every source gives its vertices in its own local frame (metres) and its local-to-world transform as a
/// <see cref="Matrix4x4"/> in System.Numerics' row-vector convention: a world point is
/// <c>Vector3.Transform(local, toWorld)</c> = local × M, so the first three rows are the images of the local X, Y
/// and Z axes and the fourth row is the translation. Build it from a Godot <c>Transform3D</c> with
/// <see cref="FromBasis"/> (its basis columns <c>Basis.X</c>, <c>Basis.Y</c>, <c>Basis.Z</c> and <c>Origin</c>). The
/// world is Y up, metres, as in Godot.
/// </para>
/// <para>
/// Winding: the planner's front faces are counter-clockwise (glTF), Godot's clockwise; each triangle source says
/// which it holds (<see cref="FaceWinding"/>) and is turned round as needed. A transform that mirrors (negative
/// determinant) also reverses the winding, and is compensated, so that a front face stays a front face, as Godot
/// renders it.
/// </para>
/// <para>
/// Order matters: the level's triangles, and so its <see cref="Level.Fingerprint"/>, follow the order of the calls;
/// add sources in a stable order (the scene tree's). A source that fails adds nothing.
/// </para>
/// </remarks>
public sealed class SourceGeometry
{
    /// <summary>The largest friction coefficient a source may give (what a roadmap file can hold).</summary>
    public const float MaxFriction = 1e3f;

    private static readonly LevelMaterial DefaultMaterial = new("default", null);

    // A box's corners and its 12 triangles, counter-clockwise seen from outside.
    private static readonly int[] BoxIndices =
    [
        0, 2, 1, 0, 3, 2, // −Z
        4, 5, 6, 4, 6, 7, // +Z
        0, 4, 7, 0, 7, 3, // −X
        1, 2, 6, 1, 6, 5, // +X
        3, 7, 6, 3, 6, 2, // +Y
        0, 1, 5, 0, 5, 4, // −Y
    ];

    private readonly LevelBuilder _builder;
    private Level? _level;

    /// <summary>Creates an empty collection.</summary>
    /// <param name="name">Names the level in messages and in <see cref="Level.Source"/> (e.g. the roadmap node's path).</param>
    public SourceGeometry(string name)
    {
        ArgumentNullException.ThrowIfNull(name);
        Name = OneLine.Of(name);
        _builder = new LevelBuilder(Name);
    }

    /// <summary>Names the level in messages.</summary>
    public string Name { get; }

    /// <summary>Sources added so far (those that failed not counted).</summary>
    public int SourceCount { get; private set; }

    /// <summary>Triangles added so far, zero-area ones excluded.</summary>
    public int TriangleCount => _builder.TriangleCount;

    /// <summary>
    /// The fingerprint of the level built from the sources so far (<see cref="Level.Fingerprint"/>): compare it with
    /// <see cref="RoadmapData.LevelFingerprint"/> to tell whether the level changed since the bake.
    /// </summary>
    /// <exception cref="LevelException">No source was added, or every triangle has zero area.</exception>
    public string Fingerprint => Build().Fingerprint;

    /// <summary>
    /// The row-vector <see cref="Matrix4x4"/> of an affine transform given as a basis and an origin, as Godot's
    /// <c>Transform3D</c> holds it: <paramref name="x"/>, <paramref name="y"/> and <paramref name="z"/> are the basis
    /// columns (<c>Basis.X</c>, <c>Basis.Y</c>, <c>Basis.Z</c>: where the local X, Y and Z axes go, scale included)
    /// and <paramref name="origin"/> the translation, metres. The result maps local p to
    /// p.X·x + p.Y·y + p.Z·z + origin, as Godot's <c>transform * p</c> does.
    /// </summary>
    public static Matrix4x4 FromBasis(Vector3 x, Vector3 y, Vector3 z, Vector3 origin) => new(
        x.X, x.Y, x.Z, 0f,
        y.X, y.Y, y.Z, 0f,
        z.X, z.Y, z.Z, 0f,
        origin.X, origin.Y, origin.Z, 1f);

    /// <summary>
    /// Adds a triangle list: three vertices per triangle, in the source's local frame (metres), as
    /// <c>Mesh.GetFaces()</c> returns them.
    /// </summary>
    /// <param name="source">Names the source in messages (e.g. the node's path).</param>
    /// <param name="faces">Three vertices per triangle, local frame, metres.</param>
    /// <param name="toWorld">Local-to-world transform, row-vector convention (see <see cref="FromBasis"/>).</param>
    /// <param name="winding">Which way round the front faces run: <see cref="FaceWinding.Clockwise"/> for Godot's.</param>
    /// <param name="friction">Coulomb friction μ of these surfaces, or <c>null</c> for the character's default.</param>
    /// <param name="travelCost">What a second walked on these surfaces costs a path search, in seconds of plain walking (<see cref="LevelMaterial.TravelCost"/>; 1 for none extra).</param>
    /// <param name="enterCost">Seconds a path search adds for stepping or landing onto these surfaces from others (<see cref="LevelMaterial.EnterCost"/>; 0 for none).</param>
    /// <exception cref="LevelException">
    /// The vertex count is not a multiple of three, a vertex is not finite or lands beyond ±<see cref="LevelBuilder.MaxCoordinate"/>
    /// metres, the transform is not finite, not affine or flattens space, or the friction or a cost is out of range; the message names the source.
    /// </exception>
    public SourceGeometry AddFaces(string source, ReadOnlySpan<Vector3> faces, Matrix4x4 toWorld, FaceWinding winding, float? friction = null, float travelCost = 1f, float enterCost = 0f)
    {
        ArgumentNullException.ThrowIfNull(source);
        string name = SourceName(source);
        if (winding is not (FaceWinding.Clockwise or FaceWinding.CounterClockwise))
        {
            throw new LevelException($"Source '{name}' in {Name}: unknown face winding {(int)winding}.");
        }

        if (faces.Length % 3 != 0)
        {
            throw new LevelException($"Source '{name}' in {Name}: {faces.Length} vertices is not a whole number of triangles (three vertices per triangle).");
        }

        for (int i = 0; i < faces.Length; i++)
        {
            Vector3 p = faces[i];
            if (!float.IsFinite(p.X) || !float.IsFinite(p.Y) || !float.IsFinite(p.Z))
            {
                throw new LevelException($"Source '{name}' in {Name}: vertex {i} (triangle {i / 3}) is not finite ({Format(p)}).");
            }
        }

        LevelMaterial material = Material(name, friction, travelCost, enterCost);
        bool reverse = (winding == FaceWinding.Clockwise) ^ Mirrors(name, toWorld);
        int[] indices = new int[faces.Length];
        for (int i = 0; i < faces.Length; i += 3)
        {
            indices[i] = i;
            indices[i + 1] = reverse ? i + 2 : i + 1;
            indices[i + 2] = reverse ? i + 1 : i + 2;
        }

        return Add(name, faces, indices, toWorld, material);
    }

    /// <summary>
    /// Adds a closed box centred on its local origin (a <c>BoxShape3D</c>): 12 triangles facing out.
    /// </summary>
    /// <param name="source">Names the source in messages (e.g. the collision shape's path).</param>
    /// <param name="size">Full extents along the local X, Y and Z axes, metres (a <c>BoxShape3D</c>'s <c>Size</c>).</param>
    /// <param name="toWorld">Local-to-world transform, row-vector convention (see <see cref="FromBasis"/>).</param>
    /// <param name="friction">Coulomb friction μ of its faces, or <c>null</c> for the character's default.</param>
    /// <param name="travelCost">What a second walked on its faces costs a path search, in seconds of plain walking (<see cref="LevelMaterial.TravelCost"/>; 1 for none extra).</param>
    /// <param name="enterCost">Seconds a path search adds for stepping or landing onto its faces from others (<see cref="LevelMaterial.EnterCost"/>; 0 for none).</param>
    /// <exception cref="LevelException">The size is negative or not finite, the transform is not finite, not affine or flattens space, a corner lands too far, or the friction or a cost is out of range; the message names the source.</exception>
    public SourceGeometry AddBox(string source, Vector3 size, Matrix4x4 toWorld, float? friction = null, float travelCost = 1f, float enterCost = 0f)
    {
        ArgumentNullException.ThrowIfNull(source);
        string name = SourceName(source);
        if (!(size.X >= 0f && size.Y >= 0f && size.Z >= 0f) || !float.IsFinite(size.X) || !float.IsFinite(size.Y) || !float.IsFinite(size.Z))
        {
            throw new LevelException($"Source '{name}' in {Name}: the box size ({Format(size)}) must be finite and not negative.");
        }

        LevelMaterial material = Material(name, friction, travelCost, enterCost);
        bool reverse = Mirrors(name, toWorld);
        Vector3 h = size * 0.5f;
        Vector3[] corners =
        [
            new(-h.X, -h.Y, -h.Z), new(h.X, -h.Y, -h.Z), new(h.X, h.Y, -h.Z), new(-h.X, h.Y, -h.Z),
            new(-h.X, -h.Y, h.Z), new(h.X, -h.Y, h.Z), new(h.X, h.Y, h.Z), new(-h.X, h.Y, h.Z),
        ];
        int[] indices = [.. BoxIndices];
        if (reverse)
        {
            for (int i = 0; i < indices.Length; i += 3)
            {
                (indices[i + 1], indices[i + 2]) = (indices[i + 2], indices[i + 1]);
            }
        }

        return Add(name, corners, indices, toWorld, material);
    }

    /// <summary>
    /// The level of every source added so far. The same instance comes back until another source is added.
    /// </summary>
    /// <exception cref="LevelException">No source was added, or every triangle has zero area.</exception>
    public Level Build()
    {
        if (SourceCount == 0)
        {
            throw new LevelException($"The level {Name} has no source geometry: no mesh or collision shape was given to bake on.");
        }

        return _level ??= _builder.Build();
    }

    private SourceGeometry Add(string name, ReadOnlySpan<Vector3> positions, int[] indices, Matrix4x4 toWorld, LevelMaterial material)
    {
        _builder.AddMesh(name, positions, indices, toWorld, material);
        _level = null;
        SourceCount++;
        return this;
    }

    /// <summary>
    /// Whether <paramref name="m"/> mirrors (negative determinant), after checking that it is finite, affine
    /// and does not flatten space.
    /// </summary>
    private bool Mirrors(string name, Matrix4x4 m)
    {
        ReadOnlySpan<float> all = [m.M11, m.M12, m.M13, m.M14, m.M21, m.M22, m.M23, m.M24, m.M31, m.M32, m.M33, m.M34, m.M41, m.M42, m.M43, m.M44];
        foreach (float v in all)
        {
            if (!float.IsFinite(v))
            {
                throw new LevelException($"Source '{name}' in {Name}: its transform holds NaN or infinite values.");
            }
        }

        if (m.M14 != 0f || m.M24 != 0f || m.M34 != 0f || m.M44 != 1f)
        {
            throw new LevelException($"Source '{name}' in {Name}: its transform is not affine (its last column must be 0, 0, 0, 1 in row-vector form).");
        }

        var x = new Vector3(m.M11, m.M12, m.M13);
        var y = new Vector3(m.M21, m.M22, m.M23);
        var z = new Vector3(m.M31, m.M32, m.M33);
        double determinant = Vector3.Dot(x, Vector3.Cross(y, z));
        double scale = (double)x.Length() * y.Length() * z.Length();
        if (!(Math.Abs(determinant) > 1e-6 * scale) || !(scale > 0d))
        {
            throw new LevelException($"Source '{name}' in {Name}: its transform flattens it (a scale of zero along some axis, basis determinant {determinant.ToString("G3", CultureInfo.InvariantCulture)}).");
        }

        return determinant < 0d;
    }

    private LevelMaterial Material(string name, float? friction, float travelCost, float enterCost)
    {
        if (LevelMaterial.CostProblem(travelCost, enterCost) is string problem)
        {
            throw new LevelException($"Source '{name}' in {Name}: its {problem}.");
        }

        bool costed = (DefaultMaterial with { TravelCost = travelCost, EnterCost = enterCost }).HasCost;
        string costs = costed ? string.Create(CultureInfo.InvariantCulture, $", travel cost {travelCost:R}, enter cost {enterCost:R}") : "";
        if (friction is not float mu)
        {
            return costed ? new LevelMaterial("default" + costs, null) { TravelCost = travelCost, EnterCost = enterCost } : DefaultMaterial;
        }

        if (!(mu >= 0f && mu <= MaxFriction))
        {
            throw new LevelException($"Source '{name}' in {Name}: friction {mu.ToString(CultureInfo.InvariantCulture)} must be finite and between 0 and {MaxFriction.ToString(CultureInfo.InvariantCulture)}.");
        }

        return new LevelMaterial(string.Create(CultureInfo.InvariantCulture, $"friction {mu:R}") + costs, mu) { TravelCost = travelCost, EnterCost = enterCost };
    }

    private static string SourceName(string source) => source.Length == 0 ? "(unnamed)" : OneLine.Of(source);

    private static string Format(Vector3 p) => string.Create(CultureInfo.InvariantCulture, $"{p.X:G4}, {p.Y:G4}, {p.Z:G4}");
}
