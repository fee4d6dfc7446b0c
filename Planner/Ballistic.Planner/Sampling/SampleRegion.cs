using System.Numerics;

namespace Ballistic.Planner.Sampling;

/// <summary>
/// The part of a level's surfaces a bake samples while it focuses on a request (<see cref="TrunkSampler"/>): every
/// surface point within <see cref="Radius"/> metres, horizontally, of the segment from the start to the goal (a
/// corridor with round ends, at any height). Holds the candidate triangles that may reach into it, with their areas
/// summed in order: a point drawn on one of them by area and kept only when it lies in the corridor is drawn
/// uniformly over the corridor's surface.
/// </summary>
internal sealed class SampleRegion
{
    private readonly Vector2 _from;
    private readonly Vector2 _to;

    /// <summary>Creates the region of <paramref name="candidates"/> (triangle indices, with <paramref name="cumulative"/> their areas summed in order) within <paramref name="radius"/> of the segment from <paramref name="from"/> to <paramref name="to"/> (world metres, horizontally).</summary>
    public SampleRegion(Vector3 from, Vector3 to, float radius, int[] candidates, double[] cumulative, double share)
    {
        _from = new Vector2(from.X, from.Z);
        _to = new Vector2(to.X, to.Z);
        Radius = radius;
        Candidates = candidates;
        Cumulative = cumulative;
        Share = share;
    }

    /// <summary>Metres, horizontally, from the start-to-goal segment within which the region's points lie.</summary>
    public float Radius { get; }

    /// <summary>Candidate triangles (level indices) that may reach into the region.</summary>
    public int[] Candidates { get; }

    /// <summary>The areas of <see cref="Candidates"/> summed in order (square metres).</summary>
    public double[] Cumulative { get; }

    /// <summary>The share of the level's candidate area on <see cref="Candidates"/> (0 to 1): near 1, the region is most of the level.</summary>
    public double Share { get; }

    /// <summary>True when <paramref name="point"/> (world metres) lies within <see cref="Radius"/> of the segment, horizontally.</summary>
    public bool Contains(Vector3 point) => Distance(new Vector2(point.X, point.Z), _from, _to) <= Radius;

    /// <summary>True when the horizontal box from <paramref name="min"/> to <paramref name="max"/> comes within <paramref name="radius"/> of the segment from <paramref name="from"/> to <paramref name="to"/>.</summary>
    public static bool Reaches(Vector2 min, Vector2 max, Vector2 from, Vector2 to, float radius)
    {
        // Two convex shapes that do not overlap are nearest at a vertex of one: the segment's ends against the box, the
        // box's corners against the segment; a segment crossing the box is at distance 0.
        if (BoxDistance(from, min, max) <= radius || BoxDistance(to, min, max) <= radius)
        {
            return true;
        }

        Vector2[] corners = [min, new(max.X, min.Y), max, new(min.X, max.Y)];
        foreach (Vector2 corner in corners)
        {
            if (Distance(corner, from, to) <= radius)
            {
                return true;
            }
        }

        for (int i = 0; i < 4; i++)
        {
            if (Crosses(from, to, corners[i], corners[(i + 1) % 4]))
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>Distance from <paramref name="p"/> to the segment from <paramref name="a"/> to <paramref name="b"/>.</summary>
    private static float Distance(Vector2 p, Vector2 a, Vector2 b)
    {
        Vector2 ab = b - a;
        float length = ab.LengthSquared();
        float t = length > 0f ? Math.Clamp(Vector2.Dot(p - a, ab) / length, 0f, 1f) : 0f;
        return Vector2.Distance(p, a + (t * ab));
    }

    private static float BoxDistance(Vector2 p, Vector2 min, Vector2 max) => Vector2.Max(Vector2.Max(min - p, p - max), Vector2.Zero).Length();

    private static bool Crosses(Vector2 a, Vector2 b, Vector2 c, Vector2 d)
    {
        static float Cross(Vector2 u, Vector2 v) => (u.X * v.Y) - (u.Y * v.X);
        float d1 = Cross(b - a, c - a);
        float d2 = Cross(b - a, d - a);
        float d3 = Cross(d - c, a - c);
        float d4 = Cross(d - c, b - c);
        return ((d1 > 0f && d2 < 0f) || (d1 < 0f && d2 > 0f)) && ((d3 > 0f && d4 < 0f) || (d3 < 0f && d4 > 0f));
    }
}
