using System.Numerics;
using Ballistic.Planner.Collision;

namespace Ballistic.Planner.Tests.Support;

/// <summary>Points on bundled levels for end-to-end requests.</summary>
internal static class LevelPoints
{
    /// <summary>The highest surface point within 4 m of (x, z): a roof rather than the street below it.</summary>
    public static Vector3 Highest(TriangleBvh bvh, float x, float z)
    {
        Vector3 best = new(x, float.NegativeInfinity, z);
        for (float dx = -4f; dx <= 4f; dx += 1f)
        {
            for (float dz = -4f; dz <= 4f; dz += 1f)
            {
                if (Ground(bvh, x + dx, z + dz) is Vector3 p && p.Y > best.Y + 0.01f)
                {
                    best = p;
                }
            }
        }

        return best;
    }

    /// <summary>The highest surface point straight below (x, z), or null.</summary>
    public static Vector3? Ground(TriangleBvh bvh, float x, float z)
    {
        float top = bvh.Bounds.Max.Y + 1f;
        return bvh.Raycast(new Vector3(x, top, z), new Vector3(0f, -(top - bvh.Bounds.Min.Y + 1f), 0f), 1f, out RayHit hit) ? hit.Point : null;
    }
}
