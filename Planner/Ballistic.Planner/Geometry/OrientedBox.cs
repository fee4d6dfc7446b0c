using System.Numerics;

namespace Ballistic.Planner.Geometry;

/// <summary>
/// A box with any orientation in world space (metres, Y up): the trunk shape W0 of a character and the limb
/// workspaces Wk are such boxes. Its local frame is centred on <see cref="Center"/> and rotated by
/// <see cref="Rotation"/> (local to world); in that frame the box is [−<see cref="HalfExtents"/>, +<see cref="HalfExtents"/>].
/// </summary>
internal readonly struct OrientedBox : IEquatable<OrientedBox>
{
    /// <summary>Creates a box.</summary>
    /// <param name="center">Centre of the box, world metres.</param>
    /// <param name="halfExtents">Half the size along each local axis, metres; every component must be ≥ 0 and finite.</param>
    /// <param name="rotation">Local-to-world rotation; normalised here.</param>
    /// <exception cref="ArgumentOutOfRangeException">A half extent is negative, NaN or infinite, or the rotation is zero or not finite.</exception>
    public OrientedBox(Vector3 center, Vector3 halfExtents, Quaternion rotation)
    {
        if (!(halfExtents.X >= 0f && halfExtents.Y >= 0f && halfExtents.Z >= 0f) ||
            !float.IsFinite(halfExtents.X) || !float.IsFinite(halfExtents.Y) || !float.IsFinite(halfExtents.Z))
        {
            throw new ArgumentOutOfRangeException(nameof(halfExtents), halfExtents, "Box half extents must be finite and not negative.");
        }

        float length = rotation.Length();
        if (!(length > 1e-6f) || !float.IsFinite(length))
        {
            throw new ArgumentOutOfRangeException(nameof(rotation), rotation, "Box rotation must be a finite, non-zero quaternion.");
        }

        Center = center;
        HalfExtents = halfExtents;
        Rotation = rotation * (1f / length);
    }

    /// <summary>Centre of the box, world metres.</summary>
    public Vector3 Center { get; }

    /// <summary>Half the size of the box along its local x, y and z axes, metres.</summary>
    public Vector3 HalfExtents { get; }

    /// <summary>Unit local-to-world rotation.</summary>
    public Quaternion Rotation { get; }

    /// <summary>The box's local x axis in world space (unit).</summary>
    public Vector3 AxisX => Vector3.Transform(Vector3.UnitX, Rotation);

    /// <summary>The box's local y axis in world space (unit).</summary>
    public Vector3 AxisY => Vector3.Transform(Vector3.UnitY, Rotation);

    /// <summary>The box's local z axis in world space (unit).</summary>
    public Vector3 AxisZ => Vector3.Transform(Vector3.UnitZ, Rotation);

    /// <summary>The smallest axis-aligned box holding this box.</summary>
    public Aabb Bounds
    {
        get
        {
            Matrix4x4 m = Matrix4x4.CreateFromQuaternion(Rotation);
            // World half size along each world axis = |R| · h (row i of |R| dotted with h).
            Vector3 extent = new(
                (MathF.Abs(m.M11) * HalfExtents.X) + (MathF.Abs(m.M21) * HalfExtents.Y) + (MathF.Abs(m.M31) * HalfExtents.Z),
                (MathF.Abs(m.M12) * HalfExtents.X) + (MathF.Abs(m.M22) * HalfExtents.Y) + (MathF.Abs(m.M32) * HalfExtents.Z),
                (MathF.Abs(m.M13) * HalfExtents.X) + (MathF.Abs(m.M23) * HalfExtents.Y) + (MathF.Abs(m.M33) * HalfExtents.Z));
            return new Aabb(Center - extent, Center + extent);
        }
    }

    /// <summary>Expresses a world point in the box's local frame (origin at the centre, box axes).</summary>
    public Vector3 ToLocal(Vector3 worldPoint) => Vector3.Transform(worldPoint - Center, Quaternion.Conjugate(Rotation));

    /// <summary>Expresses a point of the box's local frame in world space.</summary>
    public Vector3 ToWorld(Vector3 localPoint) => Center + Vector3.Transform(localPoint, Rotation);

    /// <summary>True when the world point lies inside the box or on its boundary.</summary>
    public bool Contains(Vector3 worldPoint)
    {
        Vector3 local = Vector3.Abs(ToLocal(worldPoint));
        return local.X <= HalfExtents.X && local.Y <= HalfExtents.Y && local.Z <= HalfExtents.Z;
    }

    /// <summary>Writes the eight corners, world metres, into <paramref name="corners"/> (length ≥ 8).</summary>
    /// <exception cref="ArgumentException">The span holds fewer than eight elements.</exception>
    public void GetCorners(Span<Vector3> corners)
    {
        if (corners.Length < 8)
        {
            throw new ArgumentException("A box has eight corners; the span is too short.", nameof(corners));
        }

        for (int i = 0; i < 8; i++)
        {
            Vector3 local = new(
                (i & 1) == 0 ? -HalfExtents.X : HalfExtents.X,
                (i & 2) == 0 ? -HalfExtents.Y : HalfExtents.Y,
                (i & 4) == 0 ? -HalfExtents.Z : HalfExtents.Z);
            corners[i] = ToWorld(local);
        }
    }

    /// <summary>
    /// Exact box–triangle overlap by the separating axis theorem (the box's three face normals, the triangle normal
    /// and the nine edge-cross-product axes). Touching counts as overlap.
    /// </summary>
    /// <param name="triangle">Triangle in world space.</param>
    public bool Intersects(in Triangle triangle)
    {
        Quaternion inverse = Quaternion.Conjugate(Rotation);
        Vector3 v0 = Vector3.Transform(triangle.A - Center, inverse);
        Vector3 v1 = Vector3.Transform(triangle.B - Center, inverse);
        Vector3 v2 = Vector3.Transform(triangle.C - Center, inverse);
        return BoxTriangleOverlap.CenteredBoxIntersects(HalfExtents, v0, v1, v2);
    }

    /// <inheritdoc />
    public bool Equals(OrientedBox other) =>
        Center == other.Center && HalfExtents == other.HalfExtents && Rotation == other.Rotation;

    /// <inheritdoc />
    public override bool Equals(object? obj) => obj is OrientedBox other && Equals(other);

    /// <inheritdoc />
    public override int GetHashCode() => HashCode.Combine(Center, HalfExtents, Rotation);

    /// <summary>Compares two boxes component by component.</summary>
    public static bool operator ==(OrientedBox left, OrientedBox right) => left.Equals(right);

    /// <summary>Compares two boxes component by component.</summary>
    public static bool operator !=(OrientedBox left, OrientedBox right) => !left.Equals(right);

    /// <inheritdoc />
    public override string ToString() => $"OrientedBox(center {Center}, half extents {HalfExtents}, rotation {Rotation})";
}
