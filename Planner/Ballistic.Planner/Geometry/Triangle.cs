using System.Numerics;

namespace Ballistic.Planner.Geometry;

/// <summary>
/// A triangle of the level in world space (metres, Y up). Its front face is the one from which
/// <see cref="A"/>, <see cref="B"/>, <see cref="C"/> appear counter-clockwise, as in glTF and Godot.
/// </summary>
/// <param name="A">First vertex, world metres.</param>
/// <param name="B">Second vertex, world metres.</param>
/// <param name="C">Third vertex, world metres.</param>
internal readonly record struct Triangle(Vector3 A, Vector3 B, Vector3 C)
{
    /// <summary>Twice the area times the unit normal: (B − A) × (C − A), in square metres.</summary>
    public Vector3 ScaledNormal => Vector3.Cross(B - A, C - A);

    /// <summary>Area in square metres.</summary>
    public float Area => ScaledNormal.Length() * 0.5f;

    /// <summary>Unit normal of the front face, or <see cref="Vector3.Zero"/> for a degenerate triangle.</summary>
    public Vector3 Normal
    {
        get
        {
            Vector3 n = ScaledNormal;
            float length = n.Length();
            return length > 0f ? n / length : Vector3.Zero;
        }
    }

    /// <summary>Centroid (mean of the three vertices), world metres.</summary>
    public Vector3 Centroid => (A + B + C) / 3f;

    /// <summary>Axis-aligned bounds of the three vertices.</summary>
    internal Aabb Bounds => new(Vector3.Min(Vector3.Min(A, B), C), Vector3.Max(Vector3.Max(A, B), C));

    /// <summary>True when every vertex coordinate is a finite number (no NaN, no infinity).</summary>
    public bool IsFinite =>
        float.IsFinite(A.X) && float.IsFinite(A.Y) && float.IsFinite(A.Z) &&
        float.IsFinite(B.X) && float.IsFinite(B.Y) && float.IsFinite(B.Z) &&
        float.IsFinite(C.X) && float.IsFinite(C.Y) && float.IsFinite(C.Z);

    /// <summary>
    /// The point of the triangle (interior or boundary) closest to <paramref name="p"/>, by Voronoi regions of the
    /// vertices, edges and face. Works for degenerate triangles too (it then returns a point of an edge).
    /// </summary>
    /// <param name="p">Query point, world metres.</param>
    public Vector3 ClosestPoint(Vector3 p)
    {
        Vector3 ab = B - A;
        Vector3 ac = C - A;
        Vector3 ap = p - A;
        float d1 = Vector3.Dot(ab, ap);
        float d2 = Vector3.Dot(ac, ap);
        if (d1 <= 0f && d2 <= 0f)
        {
            return A;
        }

        Vector3 bp = p - B;
        float d3 = Vector3.Dot(ab, bp);
        float d4 = Vector3.Dot(ac, bp);
        if (d3 >= 0f && d4 <= d3)
        {
            return B;
        }

        float vc = (d1 * d4) - (d3 * d2);
        if (vc <= 0f && d1 >= 0f && d3 <= 0f)
        {
            return A + (d1 / (d1 - d3) * ab);
        }

        Vector3 cp = p - C;
        float d5 = Vector3.Dot(ab, cp);
        float d6 = Vector3.Dot(ac, cp);
        if (d6 >= 0f && d5 <= d6)
        {
            return C;
        }

        float vb = (d5 * d2) - (d1 * d6);
        if (vb <= 0f && d2 >= 0f && d6 <= 0f)
        {
            return A + (d2 / (d2 - d6) * ac);
        }

        float va = (d3 * d6) - (d5 * d4);
        if (va <= 0f && (d4 - d3) >= 0f && (d5 - d6) >= 0f)
        {
            return B + ((d4 - d3) / ((d4 - d3) + (d5 - d6)) * (C - B));
        }

        float denominator = va + vb + vc;
        if (denominator <= 0f)
        {
            // Degenerate (collinear) triangle that fell through the edge tests: take the best of the three edges.
            return ClosestOnDegenerate(p);
        }

        float v = vb / denominator;
        float w = vc / denominator;
        return A + (ab * v) + (ac * w);
    }

    private Vector3 ClosestOnDegenerate(Vector3 p)
    {
        Vector3 best = ClosestOnSegment(A, B, p);
        Vector3 candidate = ClosestOnSegment(B, C, p);
        if (Vector3.DistanceSquared(candidate, p) < Vector3.DistanceSquared(best, p))
        {
            best = candidate;
        }

        candidate = ClosestOnSegment(C, A, p);
        return Vector3.DistanceSquared(candidate, p) < Vector3.DistanceSquared(best, p) ? candidate : best;
    }

    private static Vector3 ClosestOnSegment(Vector3 a, Vector3 b, Vector3 p)
    {
        Vector3 ab = b - a;
        float lengthSquared = ab.LengthSquared();
        if (lengthSquared <= 0f)
        {
            return a;
        }

        float t = Math.Clamp(Vector3.Dot(p - a, ab) / lengthSquared, 0f, 1f);
        return a + (ab * t);
    }
}
