using System.Numerics;

namespace Ballistic.Planner.Geometry;

/// <summary>Rotations built from directions (Y up) and taken out of transforms.</summary>
internal static class Rotations
{
    /// <summary>The shortest rotation taking +Y to <paramref name="up"/>.</summary>
    internal static Quaternion AlignUp(Vector3 up)
    {
        float dot = Math.Clamp(up.Y, -1f, 1f);
        if (dot > 0.999999f)
        {
            return Quaternion.Identity;
        }

        if (dot < -0.999999f)
        {
            return Quaternion.CreateFromAxisAngle(Vector3.UnitX, MathF.PI);
        }

        Vector3 axis = Vector3.Normalize(Vector3.Cross(Vector3.UnitY, up));
        return Quaternion.CreateFromAxisAngle(axis, MathF.Acos(dot));
    }

    /// <summary>
    /// The angle (radians, 0 to π) of the rotation taking <paramref name="a"/> to <paramref name="b"/> (unit
    /// quaternions; q and −q alike): from the relative rotation's sine and cosine, exact near 0, where the cosine of
    /// the two's dot product alone rounds (two headings 10⁻⁷ apart read 3·10⁻⁴ rad, a 0.4 s turn in place).
    /// </summary>
    internal static float AngleBetween(Quaternion a, Quaternion b)
    {
        Quaternion r = Quaternion.Conjugate(a) * b;
        return 2f * MathF.Atan2(new Vector3(r.X, r.Y, r.Z).Length(), MathF.Abs(r.W));
    }

    /// <summary>
    /// Splits a transform into a uniform scale and a rotation (row-vector matrix); false when it is sheared,
    /// scaled non-uniformly, mirrored or degenerate.
    /// </summary>
    public static bool TryRigid(Matrix4x4 m, out float scale, out Quaternion rotation)
    {
        var x = new Vector3(m.M11, m.M12, m.M13);
        var y = new Vector3(m.M21, m.M22, m.M23);
        var z = new Vector3(m.M31, m.M32, m.M33);
        scale = (x.Length() + y.Length() + z.Length()) / 3f;
        rotation = Quaternion.Identity;
        if (!(scale > 1e-8f) || !float.IsFinite(scale))
        {
            return false;
        }

        float tolerance = 1e-3f;
        if (MathF.Abs(x.Length() - scale) > tolerance * scale || MathF.Abs(y.Length() - scale) > tolerance * scale || MathF.Abs(z.Length() - scale) > tolerance * scale
            || MathF.Abs(Vector3.Dot(x, y)) > tolerance * scale * scale || MathF.Abs(Vector3.Dot(y, z)) > tolerance * scale * scale || MathF.Abs(Vector3.Dot(x, z)) > tolerance * scale * scale
            || Vector3.Dot(Vector3.Cross(x, y), z) <= 0f)
        {
            return false;
        }

        x /= scale;
        y /= scale;
        z /= scale;
        var pure = new Matrix4x4(x.X, x.Y, x.Z, 0f, y.X, y.Y, y.Z, 0f, z.X, z.Y, z.Z, 0f, 0f, 0f, 0f, 1f);
        rotation = Quaternion.Normalize(Quaternion.CreateFromRotationMatrix(pure));
        return true;
    }
}
