using System.Numerics;
using Ballistic.Planner.Levels;

namespace Ballistic.Planner.Surfaces;

/// <summary>
/// The level's triangles grouped into contact surfaces by region growing: triangles sharing a vertex, with the
/// same material and a normal close to the region's first triangle, form one surface. Deterministic.
/// </summary>
internal sealed class SurfaceSet
{
    private readonly int[] _surfaceOfTriangle;
    private readonly ContactSurface[] _surfaces;
    private readonly Vector3[] _normals;

    private SurfaceSet(int[] surfaceOfTriangle, ContactSurface[] surfaces, Vector3[] normals)
    {
        _surfaceOfTriangle = surfaceOfTriangle;
        _surfaces = surfaces;
        _normals = normals;
    }

    /// <summary>The surfaces, indexed by <see cref="ContactSurface.Id"/>.</summary>
    public IReadOnlyList<ContactSurface> Surfaces => _surfaces;

    /// <summary>The surface of triangle <paramref name="triangle"/>, or −1 when it lies in a surface too small for contacts.</summary>
    public int SurfaceOf(int triangle) => _surfaceOfTriangle[triangle];

    /// <summary>The unit normal of triangle <paramref name="triangle"/> (<see cref="Geometry.Triangle.Normal"/>), worked out once when the set is built.</summary>
    public Vector3 NormalOf(int triangle) => _normals[triangle];

    /// <summary>Groups the level's triangles.</summary>
    public static SurfaceSet Build(Level level, SurfaceSettings? settings = null)
    {
        ArgumentNullException.ThrowIfNull(level);
        settings ??= new SurfaceSettings();
        int n = level.Triangles.Count;
        int[] corners = WeldCorners(level, settings.WeldTolerance, out int vertexCount);

        // Vertex → triangles, compressed rows.
        int[] start = new int[vertexCount + 1];
        foreach (int v in corners)
        {
            start[v + 1]++;
        }

        for (int v = 0; v < vertexCount; v++)
        {
            start[v + 1] += start[v];
        }

        int[] fill = (int[])start.Clone();
        int[] incident = new int[corners.Length];
        for (int c = 0; c < corners.Length; c++)
        {
            incident[fill[corners[c]]++] = c / 3;
        }

        var normals = new Vector3[n];
        var areas = new float[n];
        for (int t = 0; t < n; t++)
        {
            normals[t] = level.Triangles[t].Normal;
            areas[t] = level.Triangles[t].Area;
        }

        int[] region = new int[n];
        Array.Fill(region, -1);
        var surfaceOf = new int[n];
        var surfaces = new List<ContactSurface>();
        var members = new List<int>();
        var queue = new Queue<int>();
        int regionCount = 0;
        for (int seed = 0; seed < n; seed++)
        {
            if (region[seed] >= 0)
            {
                continue;
            }

            int material = level.MaterialIndices[seed];
            Vector3 seedNormal = normals[seed];
            members.Clear();
            region[seed] = regionCount;
            queue.Enqueue(seed);
            while (queue.Count > 0)
            {
                int t = queue.Dequeue();
                members.Add(t);
                for (int k = 0; k < 3; k++)
                {
                    int v = corners[(3 * t) + k];
                    for (int i = start[v]; i < start[v + 1]; i++)
                    {
                        int other = incident[i];
                        if (region[other] < 0 && level.MaterialIndices[other] == material &&
                            Vector3.DistanceSquared(normals[other], seedNormal) < settings.MaxNormalDeviationSquared)
                        {
                            region[other] = regionCount;
                            queue.Enqueue(other);
                        }
                    }
                }
            }

            regionCount++;
            float area = 0f;
            Vector3 weighted = Vector3.Zero;
            foreach (int t in members)
            {
                area += areas[t];
                weighted += normals[t] * areas[t];
            }

            int id = -1;
            if (area >= settings.MinArea && weighted.LengthSquared() > 0f)
            {
                id = surfaces.Count;
                surfaces.Add(new ContactSurface(id, Vector3.Normalize(weighted), area, material, members.Count));
            }

            foreach (int t in members)
            {
                surfaceOf[t] = id;
            }
        }

        return new SurfaceSet(surfaceOf, [.. surfaces], normals);
    }

    /// <summary>Maps each triangle corner to a welded vertex id (positions quantised to the tolerance).</summary>
    private static int[] WeldCorners(Level level, float tolerance, out int vertexCount)
    {
        float inverse = 1f / MathF.Max(tolerance, 1e-9f);
        var ids = new Dictionary<(long, long, long), int>();
        int[] corners = new int[level.Triangles.Count * 3];
        for (int t = 0; t < level.Triangles.Count; t++)
        {
            var tri = level.Triangles[t];
            corners[3 * t] = Id(tri.A);
            corners[(3 * t) + 1] = Id(tri.B);
            corners[(3 * t) + 2] = Id(tri.C);
        }

        vertexCount = ids.Count;
        return corners;

        int Id(Vector3 p)
        {
            var key = ((long)MathF.Round(p.X * inverse), (long)MathF.Round(p.Y * inverse), (long)MathF.Round(p.Z * inverse));
            if (!ids.TryGetValue(key, out int id))
            {
                id = ids.Count;
                ids.Add(key, id);
            }

            return id;
        }
    }
}
