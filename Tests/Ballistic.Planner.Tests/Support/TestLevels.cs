using System.Numerics;
using Ballistic.Planner.Levels;

namespace Ballistic.Planner.Tests.Support;

/// <summary>Small hand-made levels for tests.</summary>
internal static class TestLevels
{
    public static readonly LevelMaterial Ground = new("ground", null);

    /// <summary>Adds an axis-aligned horizontal rectangle at height y, split into n × n quads, facing up (then placed by <paramref name="toWorld"/>, if given: a ramp).</summary>
    public static LevelBuilder AddFloor(this LevelBuilder builder, float minX, float minZ, float maxX, float maxZ, float y, int n = 4, LevelMaterial? material = null, Matrix4x4? toWorld = null)
    {
        var positions = new List<Vector3>();
        var indices = new List<int>();
        for (int i = 0; i <= n; i++)
        {
            for (int j = 0; j <= n; j++)
            {
                positions.Add(new Vector3(minX + ((maxX - minX) * i / n), y, minZ + ((maxZ - minZ) * j / n)));
            }
        }

        for (int i = 0; i < n; i++)
        {
            for (int j = 0; j < n; j++)
            {
                int a = (i * (n + 1)) + j;
                int b = a + 1;
                int c = a + n + 1;
                int d = c + 1;
                indices.AddRange([a, b, d, a, d, c]);
            }
        }

        return builder.AddMesh("floor", positions.ToArray(), indices.ToArray(), toWorld ?? Matrix4x4.Identity, material ?? Ground);
    }

    /// <summary>Adds a closed axis-aligned box (outward faces), e.g. a platform or a wall.</summary>
    public static LevelBuilder AddBox(this LevelBuilder builder, Vector3 min, Vector3 max, LevelMaterial? material = null)
    {
        Vector3[] p =
        [
            new(min.X, min.Y, min.Z), new(max.X, min.Y, min.Z), new(max.X, max.Y, min.Z), new(min.X, max.Y, min.Z),
            new(min.X, min.Y, max.Z), new(max.X, min.Y, max.Z), new(max.X, max.Y, max.Z), new(min.X, max.Y, max.Z),
        ];
        int[] indices =
        [
            0, 2, 1, 0, 3, 2, // −Z
            4, 5, 6, 4, 6, 7, // +Z
            0, 4, 7, 0, 7, 3, // −X
            1, 2, 6, 1, 6, 5, // +X
            3, 7, 6, 3, 6, 2, // +Y
            0, 1, 5, 0, 5, 4, // −Y
        ];
        return builder.AddMesh("box", p, indices, Matrix4x4.Identity, material ?? Ground);
    }
}
