using System.Numerics;
using Ballistic.Planner.Levels;

namespace Ballistic.Authoring.Levels;

/// <summary>
/// Deterministic procedural levels after the paper's scenarios: a dune desert (near the paper's 47,733 triangles),
/// a frog pond with lily pads and rocks (near 6,994), city rooftops (near 449,267) and a small gap course.
/// The same call always gives the same meshes, so the committed files never churn.
/// </summary>
public static class LevelGenerator
{
    /// <summary>The generated levels' names, in a stable order.</summary>
    public static IReadOnlyList<string> Names { get; } = ["desert", "pond", "rooftops", "gap-course"];

    private static readonly LevelMaterial Sand = new("sand", null);
    private static readonly LevelMaterial Rock = new("rock", null);
    private static readonly LevelMaterial Mud = new("mud", null);
    private static readonly LevelMaterial LilyPad = new("lily pad", null);
    private static readonly LevelMaterial Roof = new("roof", null);
    private static readonly LevelMaterial Wall = new("wall", null);
    private static readonly LevelMaterial Street = new("street", null);

    /// <summary>The meshes of the level called <paramref name="name"/>.</summary>
    /// <exception cref="ArgumentException">No generated level has that name.</exception>
    public static IReadOnlyList<LevelMesh> Generate(string name) => name switch
    {
        "desert" => Desert(),
        "pond" => Pond(),
        "rooftops" => Rooftops(),
        "gap-course" => GapCourse(),
        _ => throw new ArgumentException($"Unknown level '{name}'. Generated levels: {string.Join(", ", Names)}.", nameof(name)),
    };

    /// <summary>The level called <paramref name="name"/>, built in memory (the same triangles as its GLB file).</summary>
    /// <exception cref="ArgumentException">No generated level has that name.</exception>
    public static Level BuildLevel(string name)
    {
        var builder = new LevelBuilder($"{name} (generated)");
        foreach (LevelMesh mesh in Generate(name))
        {
            builder.AddMesh(mesh.Name, mesh.Positions, mesh.Indices, Matrix4x4.Identity, mesh.Material);
        }

        return builder.Build();
    }

    /// <summary>Height of the desert's dunes at (x, z), metres.</summary>
    public static float DuneHeight(float x, float z)
    {
        // Long parallel ridges, gently meandering, plus rolling swells.
        float ridge = MathF.Sin((0.55f * x) + (0.8f * MathF.Sin(0.21f * z)) + (0.15f * z));
        float swell = (Noise.Value(x * 0.18f, z * 0.18f, 7) - 0.5f) * 1.6f;
        float ripples = (Noise.Value(x * 0.9f, z * 0.9f, 11) - 0.5f) * 0.12f;
        return (0.75f * ridge * ridge) + swell + ripples;
    }

    /// <summary>A 22 m × 18 m dune field: 170 × 140 cells, 47,600 triangles, plus a few sandstone blocks.</summary>
    public static IReadOnlyList<LevelMesh> Desert()
    {
        const int nx = 170;
        const int nz = 140;
        const float minX = -11f;
        const float minZ = -9f;
        const float sizeX = 22f;
        const float sizeZ = 18f;
        var dunes = new MeshBuilder();
        for (int i = 0; i <= nx; i++)
        {
            for (int j = 0; j <= nz; j++)
            {
                float x = minX + (sizeX * i / nx);
                float z = minZ + (sizeZ * j / nz);
                dunes.Vertex(new Vector3(x, DuneHeight(x, z), z));
            }
        }

        for (int i = 0; i < nx; i++)
        {
            for (int j = 0; j < nz; j++)
            {
                int a = (i * (nz + 1)) + j;
                int b = a + 1;
                int c = a + nz + 1;
                int d = c + 1;
                dunes.Triangle(a, b, d);
                dunes.Triangle(a, d, c);
            }
        }

        var rocks = new MeshBuilder();
        foreach ((float x, float z, float w, float h) in new[] { (-4f, 2f, 1.2f, 1.4f), (2.5f, -4f, 1.6f, 1.1f), (5f, 4.5f, 1.0f, 1.8f) })
        {
            float ground = DuneHeight(x, z);
            rocks.Box(new Vector3(x - w, ground - 0.5f, z - w), new Vector3(x + w, ground + h, z + w));
        }

        return
        [
            dunes.ToMesh("Dunes", Sand, new Vector4(0.86f, 0.72f, 0.48f, 1f)),
            rocks.ToMesh("Sandstone", Rock, new Vector4(0.62f, 0.45f, 0.32f, 1f)),
        ];
    }

    /// <summary>
    /// An 8 m × 11 m pond: a muddy bank around an open water hole (nothing to stand on), lily pads floating at
    /// water level and rocks.
    /// </summary>
    public static IReadOnlyList<LevelMesh> Pond()
    {
        const float minX = -4.5f;
        const float minZ = -6.3f;
        const float sizeX = 8.1f;
        const float sizeZ = 11.2f;
        const int nx = 54;
        const int nz = 74;
        var bank = new MeshBuilder();
        var index = new int[nx + 1, nz + 1];
        for (int i = 0; i <= nx; i++)
        {
            for (int j = 0; j <= nz; j++)
            {
                float x = minX + (sizeX * i / nx);
                float z = minZ + (sizeZ * j / nz);
                float rim = PondShape(x, z);
                float y = 0.05f + (MathF.Max(0f, rim - 1f) * 0.35f) + ((Noise.Value(x * 0.8f, z * 0.8f, 3) - 0.5f) * 0.1f);
                index[i, j] = bank.Vertex(new Vector3(x, y, z));
            }
        }

        for (int i = 0; i < nx; i++)
        {
            for (int j = 0; j < nz; j++)
            {
                // Cells whose centre lies in the water are left open.
                float cx = minX + (sizeX * (i + 0.5f) / nx);
                float cz = minZ + (sizeZ * (j + 0.5f) / nz);
                if (PondShape(cx, cz) < 1f)
                {
                    continue;
                }

                bank.Triangle(index[i, j], index[i, j + 1], index[i + 1, j + 1]);
                bank.Triangle(index[i, j], index[i + 1, j + 1], index[i + 1, j]);
            }
        }

        var pads = new MeshBuilder();
        (float X, float Z, float R)[] padSpots =
        [
            (-1.6f, -3.6f, 0.42f), (-0.5f, -3.1f, 0.38f), (0.6f, -3.5f, 0.45f), (-1.1f, -2.0f, 0.40f), (0.2f, -1.8f, 0.36f),
            (1.3f, -2.3f, 0.40f), (-1.8f, -0.7f, 0.44f), (-0.6f, -0.5f, 0.38f), (0.7f, -0.6f, 0.42f), (1.7f, -0.9f, 0.35f),
            (-1.2f, 0.6f, 0.40f), (0.1f, 0.8f, 0.45f), (1.3f, 0.5f, 0.38f), (-0.5f, 1.9f, 0.42f), (0.8f, 2.0f, 0.40f),
            (-1.5f, 2.6f, 0.36f), (0.2f, 3.1f, 0.38f), (1.5f, 2.9f, 0.34f),
        ];
        foreach ((float x, float z, float r) in padSpots)
        {
            pads.Disc(new Vector3(x, 0.02f, z), r, 0.03f, 24);
        }

        var rocks = new MeshBuilder();
        foreach ((float x, float z, float r, float h) in new[] { (-2.2f, -2.4f, 0.35f, 0.25f), (2.1f, 1.6f, 0.4f, 0.3f), (-2.4f, 1.5f, 0.3f, 0.2f), (2.4f, -2.0f, 0.3f, 0.35f) })
        {
            Dome(rocks, new Vector3(x, -0.1f, z), r, h + 0.1f, 14, 5);
        }

        return
        [
            bank.ToMesh("Bank", Mud, new Vector4(0.35f, 0.3f, 0.2f, 1f)),
            pads.ToMesh("LilyPads", LilyPad, new Vector4(0.25f, 0.6f, 0.2f, 1f)),
            rocks.ToMesh("Rocks", Rock, new Vector4(0.5f, 0.5f, 0.48f, 1f)),
        ];
    }

    /// <summary>
    /// A 260 m × 145 m district of flat-roofed houses in blocks, 4 to 22 m tall, separated by 1.5–4 m alleys and
    /// 12 m streets, roofs tessellated like the paper's detailed city model.
    /// </summary>
    public static IReadOnlyList<LevelMesh> Rooftops()
    {
        var roofs = new MeshBuilder();
        var walls = new MeshBuilder();
        var street = new MeshBuilder();
        const float minX = -140f;
        const float minZ = -80f;
        street.Quad(new Vector3(minX, 0f, minZ), new Vector3(minX, 0f, 65f), new Vector3(120f, 0f, 65f), new Vector3(120f, 0f, minZ), 26, 52);

        int seed = 0;
        for (float bx = minX + 6f; bx + 30f <= 120f; bx += 42f)
        {
            for (float bz = minZ + 6f; bz + 20f <= 65f; bz += 34f)
            {
                // A block of houses in a 3 × 2 grid with alleys between them.
                for (int i = 0; i < 3; i++)
                {
                    for (int k = 0; k < 2; k++)
                    {
                        seed++;
                        float alleyX = 1.5f + (2.5f * Noise.Hash(seed, 1, 5));
                        float alleyZ = 1.5f + (2.5f * Noise.Hash(seed, 2, 5));
                        float width = 10f - alleyX;
                        float depth = 11f - alleyZ;
                        float height = 4f + MathF.Round(18f * Noise.Hash(seed, 3, 5) * Noise.Hash(seed, 4, 5) * 2f) / 2f;
                        height = MathF.Min(height, 22f);
                        float x0 = bx + (i * 10f);
                        float z0 = bz + (k * 11f);
                        var min = new Vector3(x0, 0f, z0);
                        var max = new Vector3(x0 + width, height, z0 + depth);
                        House(roofs, walls, min, max, seed);
                    }
                }
            }
        }

        return
        [
            street.ToMesh("Streets", Street, new Vector4(0.3f, 0.3f, 0.32f, 1f)),
            walls.ToMesh("Walls", Wall, new Vector4(0.7f, 0.62f, 0.55f, 1f)),
            roofs.ToMesh("Roofs", Roof, new Vector4(0.55f, 0.3f, 0.25f, 1f)),
        ];
    }

    /// <summary>Four platforms with gaps, a low wall and a raised last platform: a quick check of a character.</summary>
    public static IReadOnlyList<LevelMesh> GapCourse()
    {
        var platforms = new MeshBuilder();
        platforms.Box(new Vector3(-8f, -1f, -2f), new Vector3(-3f, 0f, 2f), 1f);
        platforms.Box(new Vector3(-1.5f, -1f, -2f), new Vector3(1.5f, 0f, 2f), 1f);
        platforms.Box(new Vector3(3f, -1f, -2f), new Vector3(8f, 0f, 2f), 1f);
        platforms.Box(new Vector3(9.5f, -1f, -2f), new Vector3(13f, 1f, 2f), 1f);
        var wall = new MeshBuilder();
        wall.Box(new Vector3(5.4f, 0f, -2f), new Vector3(5.5f, 0.5f, 2f), 1f);
        return
        [
            platforms.ToMesh("Platforms", Rock, new Vector4(0.55f, 0.55f, 0.6f, 1f)),
            wall.ToMesh("Wall", Wall, new Vector4(0.8f, 0.4f, 0.3f, 1f)),
        ];
    }

    private static void House(MeshBuilder roofs, MeshBuilder walls, Vector3 min, Vector3 max, int seed)
    {
        const float cell = 0.5f;
        Vector3 s = max - min;
        int nx = Math.Max(1, (int)MathF.Ceiling(s.X / cell));
        int nz = Math.Max(1, (int)MathF.Ceiling(s.Z / cell));
        int ny = Math.Max(1, (int)MathF.Ceiling(s.Y / 1f));
        roofs.Quad(new Vector3(min.X, max.Y, min.Z), new Vector3(min.X, max.Y, max.Z), new Vector3(max.X, max.Y, max.Z), new Vector3(max.X, max.Y, min.Z), nx, nz);
        walls.Quad(new Vector3(min.X, min.Y, max.Z), new Vector3(max.X, min.Y, max.Z), new Vector3(max.X, max.Y, max.Z), new Vector3(min.X, max.Y, max.Z), ny, nx * 2);
        walls.Quad(new Vector3(max.X, min.Y, min.Z), new Vector3(min.X, min.Y, min.Z), new Vector3(min.X, max.Y, min.Z), new Vector3(max.X, max.Y, min.Z), ny, nx * 2);
        walls.Quad(new Vector3(max.X, min.Y, max.Z), new Vector3(max.X, min.Y, min.Z), new Vector3(max.X, max.Y, min.Z), new Vector3(max.X, max.Y, max.Z), ny, nz * 2);
        walls.Quad(new Vector3(min.X, min.Y, min.Z), new Vector3(min.X, min.Y, max.Z), new Vector3(min.X, max.Y, max.Z), new Vector3(min.X, max.Y, min.Z), ny, nz * 2);

        // A roof-top box (stairwell or machine room) on some houses.
        if (Noise.Hash(seed, 9, 5) < 0.5f && s.X > 4f && s.Z > 4f)
        {
            float w = 1.2f + (Noise.Hash(seed, 10, 5) * 1.2f);
            float cx = min.X + (s.X * (0.3f + (0.4f * Noise.Hash(seed, 11, 5))));
            float cz = min.Z + (s.Z * (0.3f + (0.4f * Noise.Hash(seed, 12, 5))));
            walls.Box(new Vector3(cx - w, max.Y, cz - w), new Vector3(cx + w, max.Y + 2.2f, cz + w), 0.5f);
        }
    }

    /// <summary>0 at the pond's centre, 1 on its shore, more outside (an ellipse with a wobbly edge).</summary>
    private static float PondShape(float x, float z)
    {
        float wobble = 1f + (0.08f * MathF.Sin(3f * MathF.Atan2(z, x)));
        return MathF.Sqrt((x * x / (2.6f * 2.6f)) + ((z + 0.2f) * (z + 0.2f) / (4.6f * 4.6f))) / wobble;
    }

    private static void Dome(MeshBuilder mesh, Vector3 center, float radius, float height, int segments, int rings)
    {
        int apex = mesh.Vertex(center + new Vector3(0f, height, 0f));
        int first = mesh.Positions.Count;
        for (int r = 1; r <= rings; r++)
        {
            float t = r / (float)rings;
            float ringRadius = radius * MathF.Sin(t * MathF.PI / 2f);
            float y = height * MathF.Cos(t * MathF.PI / 2f);
            for (int k = 0; k < segments; k++)
            {
                float a = 2f * MathF.PI * k / segments;
                mesh.Vertex(center + new Vector3(ringRadius * MathF.Cos(a), y, ringRadius * MathF.Sin(a)));
            }
        }

        for (int k = 0; k < segments; k++)
        {
            mesh.Triangle(apex, first + ((k + 1) % segments), first + k);
        }

        for (int r = 0; r + 1 < rings; r++)
        {
            int a0 = first + (r * segments);
            int b0 = a0 + segments;
            for (int k = 0; k < segments; k++)
            {
                int k1 = (k + 1) % segments;
                mesh.Triangle(a0 + k, a0 + k1, b0 + k1);
                mesh.Triangle(a0 + k, b0 + k1, b0 + k);
            }
        }
    }
}
