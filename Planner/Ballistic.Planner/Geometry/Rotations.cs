using System.Numerics;

namespace Ballistic.Planner.Geometry;

/// <summary>Rotations built from directions (Y up).</summary>
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
}
