#nullable enable
using Godot;
using NumericsMatrix = System.Numerics.Matrix4x4;
using NumericsQuaternion = System.Numerics.Quaternion;
using NumericsVector3 = System.Numerics.Vector3;

namespace Ballistic.Addon;

/// <summary>
/// Converts between Godot's math types and System.Numerics, the planner's. Both are Y up, right-handed, metres;
/// Godot's <see cref="Transform3D"/> maps column vectors, System.Numerics matrices map row vectors (v' = v · M), so
/// the basis columns become the matrix rows and the origin its fourth row.
/// </summary>
internal static class GodotMath
{
    /// <summary>A Godot vector as a System.Numerics one.</summary>
    public static NumericsVector3 ToNumerics(this Vector3 v) => new(v.X, v.Y, v.Z);

    /// <summary>A System.Numerics vector as a Godot one.</summary>
    public static Vector3 ToGodot(this NumericsVector3 v) => new(v.X, v.Y, v.Z);

    /// <summary>A Godot quaternion as a System.Numerics one.</summary>
    public static NumericsQuaternion ToNumerics(this Quaternion q) => new(q.X, q.Y, q.Z, q.W);

    /// <summary>A System.Numerics quaternion as a Godot one, normalised (Godot refuses unnormalised rotations).</summary>
    public static Quaternion ToGodot(this NumericsQuaternion q)
    {
        NumericsQuaternion n = NumericsQuaternion.Normalize(q);
        return new Quaternion(n.X, n.Y, n.Z, n.W);
    }

    /// <summary>A Godot transform as a System.Numerics row-vector matrix.</summary>
    public static NumericsMatrix ToNumerics(this Transform3D t)
    {
        Vector3 x = t.Basis.Column0;
        Vector3 y = t.Basis.Column1;
        Vector3 z = t.Basis.Column2;
        return new NumericsMatrix(
            x.X, x.Y, x.Z, 0f,
            y.X, y.Y, y.Z, 0f,
            z.X, z.Y, z.Z, 0f,
            t.Origin.X, t.Origin.Y, t.Origin.Z, 1f);
    }

    /// <summary>An RGBA colour as Godot's.</summary>
    public static Color ToGodotColor(this System.Numerics.Vector4 rgba) => new(rgba.X, rgba.Y, rgba.Z, rgba.W);
}
