using System.Numerics;

namespace Ballistic.Planner.Geometry;

/// <summary>
/// Clips a triangle by an oriented box (Sutherland–Hodgman against its six face planes) and measures the part
/// inside: the area and centroid of the intersection, used to estimate where a limb's workspace meets a surface.
/// </summary>
internal static class BoxClipper
{
    /// <summary>A triangle clipped by six planes has at most 9 vertices.</summary>
    private const int MaxVertices = 12;

    /// <summary>
    /// The area (square metres) and centroid (world metres) of the part of <paramref name="triangle"/> inside
    /// <paramref name="box"/>. Area 0 when they do not overlap in a region of positive area.
    /// </summary>
    public static (float Area, Vector3 Centroid) ClipArea(in OrientedBox box, in Triangle triangle)
    {
        return ClipLocal(box, triangle, box.ToLocal(triangle.A), box.ToLocal(triangle.B), box.ToLocal(triangle.C));
    }

    /// <summary>
    /// <see cref="ClipLocal"/>, but area 0 (centroid the box's centre) wherever the separating-axis test
    /// (<see cref="BoxTriangleOverlap.CenteredBoxIntersects"/>) finds the box and the triangle apart. That test is
    /// needed only where the clipped area is below <see cref="GrazeArea"/>: a larger piece is a true overlap, not a
    /// rounding of the clip along a face the triangle grazes.
    /// </summary>
    public static (float Area, Vector3 Centroid) OverlapArea(in OrientedBox box, in Triangle triangle, Vector3 v0, Vector3 v1, Vector3 v2)
    {
        Vector3 h = box.HalfExtents;
        if (BoxTriangleOverlap.BeyondAFace(h, v0, v1, v2))
        {
            return (0f, box.Center);
        }

        (float Area, Vector3 Centroid) clipped = ClipLocal(box, triangle, v0, v1, v2);
        return clipped.Area > 0f && clipped.Area < GrazeArea && !BoxTriangleOverlap.CenteredBoxIntersects(h, v0, v1, v2)
            ? (0f, box.Center)
            : clipped;
    }

    /// <summary>Clipped areas (square metres, a square millimetre) below which <see cref="OverlapArea"/> asks the separating-axis test.</summary>
    public const float GrazeArea = 1e-6f;

    /// <summary>
    /// <see cref="ClipArea"/> of <paramref name="triangle"/> given its vertices in the box's frame
    /// (<see cref="OrientedBox.ToLocal"/> of A, B and C), computed once by the caller.
    /// </summary>
    public static (float Area, Vector3 Centroid) ClipLocal(in OrientedBox box, in Triangle triangle, Vector3 v0, Vector3 v1, Vector3 v2)
    {
        Vector3 h = box.HalfExtents;
        if (Inside(v0, h) && Inside(v1, h) && Inside(v2, h))
        {
            // Wholly inside: nothing to clip.
            return (triangle.Area, triangle.Centroid);
        }

        Span<Vector3> a = stackalloc Vector3[MaxVertices];
        Span<Vector3> b = stackalloc Vector3[MaxVertices];
        a[0] = v0;
        a[1] = v1;
        a[2] = v2;
        int count = 3;

        for (int axis = 0; axis < 3 && count > 0; axis++)
        {
            float limit = axis == 0 ? h.X : axis == 1 ? h.Y : h.Z;
            if (Within(a[..count], axis, limit))
            {
                continue; // clipping by this axis's two planes would give the polygon back as it is
            }

            count = ClipPlane(a[..count], b, axis, limit, sign: 1f);
            count = ClipPlane(b[..count], a, axis, limit, sign: -1f);
        }

        if (count < 3)
        {
            return (0f, box.Center);
        }

        // Fan triangulation from the first vertex: area-weighted centroid.
        Vector3 origin = a[0];
        float twiceArea = 0f;
        Vector3 weighted = Vector3.Zero;
        for (int i = 1; i + 1 < count; i++)
        {
            float part = Vector3.Cross(a[i] - origin, a[i + 1] - origin).Length();
            twiceArea += part;
            weighted += (origin + a[i] + a[i + 1]) * (part / 3f);
        }

        if (!(twiceArea > 0f))
        {
            return (0f, box.Center);
        }

        return (twiceArea * 0.5f, box.ToWorld(weighted / twiceArea));
    }

    /// <summary>Keeps the part of the polygon where sign · coordinate ≤ limit.</summary>
    private static int ClipPlane(ReadOnlySpan<Vector3> input, Span<Vector3> output, int axis, float limit, float sign)
    {
        int count = 0;
        for (int i = 0; i < input.Length; i++)
        {
            Vector3 current = input[i];
            Vector3 next = input[(i + 1) % input.Length];
            float dc = (sign * Component(current, axis)) - limit;
            float dn = (sign * Component(next, axis)) - limit;
            if (dc <= 0f)
            {
                output[count++] = current;
            }

            if ((dc < 0f && dn > 0f) || (dc > 0f && dn < 0f))
            {
                output[count++] = current + ((next - current) * (dc / (dc - dn)));
            }
        }

        return count;
    }

    /// <summary>Whether every vertex lies within both planes ±<paramref name="limit"/> of <paramref name="axis"/>, boundary included (<see cref="ClipPlane"/> keeps it whole).</summary>
    private static bool Within(ReadOnlySpan<Vector3> polygon, int axis, float limit)
    {
        foreach (Vector3 v in polygon)
        {
            if (!(MathF.Abs(Component(v, axis)) <= limit))
            {
                return false;
            }
        }

        return true;
    }

    private static bool Inside(Vector3 p, Vector3 h) => MathF.Abs(p.X) <= h.X && MathF.Abs(p.Y) <= h.Y && MathF.Abs(p.Z) <= h.Z;

    private static float Component(Vector3 v, int axis) => axis == 0 ? v.X : axis == 1 ? v.Y : v.Z;
}
