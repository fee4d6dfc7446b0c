using System.Numerics;
using System.Runtime.CompilerServices;

namespace Ballistic.Planner.Geometry;

/// <summary>
/// An axis-aligned bounding box in world space (metres, Y up), given by its minimum and maximum corners.
/// The empty box has <see cref="Min"/> at +∞ and <see cref="Max"/> at −∞, so that any union with it is the other box.
/// </summary>
/// <param name="Min">Smallest x, y and z of the box, in metres.</param>
/// <param name="Max">Largest x, y and z of the box, in metres.</param>
internal readonly record struct Aabb(Vector3 Min, Vector3 Max)
{
    /// <summary>The empty box: contains nothing, and is the identity of <see cref="Union(Aabb, Aabb)"/>.</summary>
    public static Aabb Empty => new(new Vector3(float.PositiveInfinity), new Vector3(float.NegativeInfinity));

    /// <summary>True when the box contains no point (some minimum coordinate exceeds its maximum).</summary>
    public bool IsEmpty => Min.X > Max.X || Min.Y > Max.Y || Min.Z > Max.Z;

    /// <summary>Centre of the box, in metres. Meaningless for the empty box.</summary>
    public Vector3 Center => (Min + Max) * 0.5f;

    /// <summary>Half the size of the box along each world axis, in metres. Meaningless for the empty box.</summary>
    public Vector3 HalfExtents => (Max - Min) * 0.5f;

    /// <summary>Surface area in square metres (0 for the empty box); the cost measure of a bounding-volume hierarchy.</summary>
    public float SurfaceArea
    {
        get
        {
            if (IsEmpty)
            {
                return 0f;
            }

            Vector3 d = Max - Min;
            return 2f * ((d.X * d.Y) + (d.Y * d.Z) + (d.Z * d.X));
        }
    }

    /// <summary>The smallest box holding every given point; the empty box when there are none.</summary>
    /// <param name="points">World points, in metres.</param>
    public static Aabb FromPoints(ReadOnlySpan<Vector3> points)
    {
        Vector3 min = new(float.PositiveInfinity);
        Vector3 max = new(float.NegativeInfinity);
        foreach (Vector3 p in points)
        {
            min = Vector3.Min(min, p);
            max = Vector3.Max(max, p);
        }

        return new Aabb(min, max);
    }

    /// <summary>The smallest box holding both boxes.</summary>
    public static Aabb Union(Aabb a, Aabb b) => new(Vector3.Min(a.Min, b.Min), Vector3.Max(a.Max, b.Max));

    /// <summary>The smallest box holding this box and the point <paramref name="p"/>.</summary>
    public Aabb Encapsulate(Vector3 p) => new(Vector3.Min(Min, p), Vector3.Max(Max, p));

    /// <summary>This box grown by <paramref name="margin"/> metres on every side (shrunk when negative).</summary>
    public Aabb Inflate(float margin) => new(Min - new Vector3(margin), Max + new Vector3(margin));

    /// <summary>True when <paramref name="p"/> lies inside the box or on its boundary.</summary>
    public bool Contains(Vector3 p) =>
        p.X >= Min.X && p.X <= Max.X &&
        p.Y >= Min.Y && p.Y <= Max.Y &&
        p.Z >= Min.Z && p.Z <= Max.Z;

    /// <summary>True when the two boxes share at least one point (touching counts).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public bool Intersects(in Aabb other) =>
        Min.X <= other.Max.X && Max.X >= other.Min.X &&
        Min.Y <= other.Max.Y && Max.Y >= other.Min.Y &&
        Min.Z <= other.Max.Z && Max.Z >= other.Min.Z;

    /// <summary>
    /// Slab test of the segment <c>origin + t·direction</c>, <c>t ∈ [tMin, tMax]</c>, against the box.
    /// Returns the entry parameter in <paramref name="tEnter"/> (clamped to <paramref name="tMin"/>) when they meet.
    /// </summary>
    /// <param name="origin">Start of the ray, world metres.</param>
    /// <param name="inverseDirection">Component-wise reciprocal of the ray direction (±∞ for zero components).</param>
    /// <param name="tMin">Smallest ray parameter considered.</param>
    /// <param name="tMax">Largest ray parameter considered.</param>
    /// <param name="tEnter">Parameter at which the ray enters the box, when it does.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public bool IntersectsRay(Vector3 origin, Vector3 inverseDirection, float tMin, float tMax, out float tEnter)
    {
        Vector3 t0 = (Min - origin) * inverseDirection;
        Vector3 t1 = (Max - origin) * inverseDirection;
        Vector3 near = Vector3.Min(t0, t1);
        Vector3 far = Vector3.Max(t0, t1);

        // NaN arises from 0 · ∞ when the origin lies on a slab plane of a zero direction component; treat as inside.
        float enter = MaxIgnoringNaN(MaxIgnoringNaN(MaxIgnoringNaN(tMin, near.X), near.Y), near.Z);
        float exit = MinIgnoringNaN(MinIgnoringNaN(MinIgnoringNaN(tMax, far.X), far.Y), far.Z);
        tEnter = enter;
        return enter <= exit;
    }

    private static float MaxIgnoringNaN(float a, float b) => float.IsNaN(b) || a >= b ? a : b;

    private static float MinIgnoringNaN(float a, float b) => float.IsNaN(b) || a <= b ? a : b;
}
