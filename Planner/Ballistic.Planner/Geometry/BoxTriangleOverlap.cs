using System.Numerics;

namespace Ballistic.Planner.Geometry;

/// <summary>Separating-axis overlap test between an origin-centred axis-aligned box and a triangle.</summary>
internal static class BoxTriangleOverlap
{
    /// <summary>
    /// True when the box [−h, h] and the triangle (v0, v1, v2), all in the box's frame, share a point.
    /// Thirteen candidate axes: three box faces, the triangle normal, nine box-axis × triangle-edge products.
    /// </summary>
    public static bool CenteredBoxIntersects(Vector3 h, Vector3 v0, Vector3 v1, Vector3 v2)
    {
        if (BeyondAFace(h, v0, v1, v2))
        {
            return false;
        }

        Vector3 e0 = v1 - v0;
        Vector3 e1 = v2 - v1;
        Vector3 e2 = v0 - v2;

        // Triangle normal: the plane against the box.
        Vector3 n = Vector3.Cross(e0, e1);
        float planeDistance = Vector3.Dot(n, v0);
        float radius = (h.X * MathF.Abs(n.X)) + (h.Y * MathF.Abs(n.Y)) + (h.Z * MathF.Abs(n.Z));
        if (MathF.Abs(planeDistance) > radius)
        {
            return false;
        }

        return !SeparatedOnEdgeAxes(h, e0, v0, v1, v2) &&
               !SeparatedOnEdgeAxes(h, e1, v0, v1, v2) &&
               !SeparatedOnEdgeAxes(h, e2, v0, v1, v2);
    }

    /// <summary>
    /// The box face axes, the first of <see cref="CenteredBoxIntersects"/>'s tests: true when all three vertices (in
    /// the box's frame) lie beyond the same face of the box [−h, h].
    /// </summary>
    public static bool BeyondAFace(Vector3 h, Vector3 v0, Vector3 v1, Vector3 v2)
    {
        Vector3 min = Vector3.Min(Vector3.Min(v0, v1), v2);
        Vector3 max = Vector3.Max(Vector3.Max(v0, v1), v2);
        return min.X > h.X || max.X < -h.X || min.Y > h.Y || max.Y < -h.Y || min.Z > h.Z || max.Z < -h.Z;
    }

    /// <summary>Tests the three axes (unit x, y, z) × <paramref name="edge"/>.</summary>
    private static bool SeparatedOnEdgeAxes(Vector3 h, Vector3 edge, Vector3 v0, Vector3 v1, Vector3 v2) =>
        SeparatedOnAxis(h, new Vector3(0f, -edge.Z, edge.Y), v0, v1, v2) ||
        SeparatedOnAxis(h, new Vector3(edge.Z, 0f, -edge.X), v0, v1, v2) ||
        SeparatedOnAxis(h, new Vector3(-edge.Y, edge.X, 0f), v0, v1, v2);

    private static bool SeparatedOnAxis(Vector3 h, Vector3 axis, Vector3 v0, Vector3 v1, Vector3 v2)
    {
        float p0 = Vector3.Dot(axis, v0);
        float p1 = Vector3.Dot(axis, v1);
        float p2 = Vector3.Dot(axis, v2);
        float radius = (h.X * MathF.Abs(axis.X)) + (h.Y * MathF.Abs(axis.Y)) + (h.Z * MathF.Abs(axis.Z));
        return MathF.Min(p0, MathF.Min(p1, p2)) > radius || MathF.Max(p0, MathF.Max(p1, p2)) < -radius;
    }
}
