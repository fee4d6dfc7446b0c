using System.Numerics;
using Ballistic.Planner.Levels;

namespace Ballistic.Planner.Tests.Support;

/// <summary>
/// Levels in the shapes other tools export, not ours: unwelded triangle soups placed by node transforms (some
/// modelled Z-up and turned, some scaled), single-sided planes, thin slabs, fine curved terrain, stairs, a block to
/// stand on, a floor with holes and rotated debris, a low cave, a wide open field, a maze, a two-storey house with
/// a front door and a staircase with a landing, and a cluttered floor at a rat's scale. Each comes with requests a user would make.
/// </summary>
internal static class ForeignLevels
{
    public static IReadOnlyList<string> Names { get; } = ["thin-slabs", "curved", "stairs", "block", "holes-debris", "cave", "field", "doorway", "beam", "maze", "house", "clutter"];

    /// <summary>A level and the start/goal pairs a user would try on it.</summary>
    public static (Level Level, (Vector3 From, Vector3 To)[] Requests) Get(string name) => name switch
    {
        "thin-slabs" => ThinSlabs(),
        "curved" => Curved(),
        "stairs" => Stairs(),
        "block" => Block(),
        "holes-debris" => HolesDebris(),
        "cave" => Cave(),
        "field" => Field(),
        "doorway" => Doorway(),
        "beam" => Beam(),
        "maze" => Maze(),
        "house" => House(),
        "clutter" => Clutter(),
        _ => throw new ArgumentException($"no foreign level '{name}'"),
    };

    /// <summary>
    /// Two rooms a 4 m wall apart, joined by an interior door 0.9 m wide and 2.1 m high (the wall, its two jambs and
    /// the lintel each a box, as a modeller cuts a door out of a wall), on a 20 cm thick floor slab: walked straight
    /// through, and from a corner of one room to the far corner of the other, the route bending through the door.
    /// </summary>
    internal static (Level Level, (Vector3 From, Vector3 To)[] Requests) Doorway() =>
        (DoorwayLevel(0.9f), [
            (new Vector3(-4f, 0f, 0f), new Vector3(4f, 0f, 0f)),
            (new Vector3(-3f, 0f, 2.5f), new Vector3(3f, 0f, 2.5f)),
            (new Vector3(2.5f, 0f, -3f), new Vector3(-2.5f, 0f, -1f)),
        ]);

    /// <summary>The doorway level (<see cref="Doorway"/>) with a door <paramref name="width"/> metres wide, centred on z = 0 in the wall at x = 0.</summary>
    internal static Level DoorwayLevel(float width)
    {
        float half = 0.5f * width;
        var b = new LevelBuilder($"doorway {width:0.##} m (foreign)");
        AddSoupBox(b, "floor", new Vector3(-6f, -0.2f, -4f), new Vector3(6f, 0f, 4f));
        AddSoupBox(b, "wall_left", new Vector3(-0.1f, 0f, -4f), new Vector3(0.1f, 4f, -half));
        AddSoupBox(b, "wall_right", new Vector3(-0.1f, 0f, half), new Vector3(0.1f, 4f, 4f));
        AddSoupBox(b, "lintel", new Vector3(-0.1f, 2.1f, -half), new Vector3(0.1f, 4f, half));
        return b.Build();
    }

    /// <summary>
    /// A hedge maze as a level designer blocks one out: a 12 × 10 m floor inside a wall, five walls 0.8 m high and
    /// 0.3 m thick across it, each open at one end in turn (2 m gaps), so that its 1.7 m corridors wind from west to
    /// east. Requests: into the next corridor round a wall's open end, through a gap straight ahead, and from the first
    /// corridor to the last.
    /// </summary>
    internal static (Level Level, (Vector3 From, Vector3 To)[] Requests) Maze()
    {
        var b = new LevelBuilder("maze (foreign)");
        AddSoupQuad(b, "floor", new Vector3(-6f, 0f, -5f), new Vector3(6f, 0f, -5f), new Vector3(6f, 0f, 5f), new Vector3(-6f, 0f, 5f), 6);
        AddSoupBox(b, "wall_west", new Vector3(-6.3f, 0f, -5.3f), new Vector3(-6f, 0.8f, 5.3f));
        AddSoupBox(b, "wall_east", new Vector3(6f, 0f, -5.3f), new Vector3(6.3f, 0.8f, 5.3f));
        AddSoupBox(b, "wall_south", new Vector3(-6f, 0f, -5.3f), new Vector3(6f, 0.8f, -5f));
        AddSoupBox(b, "wall_north", new Vector3(-6f, 0f, 5f), new Vector3(6f, 0.8f, 5.3f));
        for (int k = 0; k < 5; k++)
        {
            float x = -4f + (2f * k);
            (float from, float to) = k % 2 == 0 ? (-3f, 5f) : (-5f, 3f); // open to the south, then to the north
            AddSoupBox(b, $"hedge_{k}", new Vector3(x - 0.15f, 0f, from), new Vector3(x + 0.15f, 0.8f, to));
        }

        return (b.Build(), [
            (new Vector3(-5f, 0f, -1f), new Vector3(-3f, 0f, -1f)),
            (new Vector3(-1f, 0f, 4f), new Vector3(-3f, 0f, 4f)),
            (new Vector3(-5f, 0f, 4f), new Vector3(5f, 0f, -4f)),
        ]);
    }

    /// <summary>
    /// A two-storey house as an architect's export has one: 12 × 8 m inside 20 cm walls 6 m high under a roof slab, a front door 1.2 m
    /// wide and 2.1 m high in the west wall, a staircase along the north wall of two flights of 8 steps (17.6 cm
    /// risers, 28 cm treads, 1.2 m wide, each step a box) with a 1.2 m landing between them, up to a gallery 2.82 m up
    /// (a 20 cm slab on nothing, across the east end); the yard outside the door. Requests: in through the door, up
    /// both flights to the gallery, and from the gallery down and out.
    /// </summary>
    internal static (Level Level, (Vector3 From, Vector3 To)[] Requests) House()
    {
        const float rise = 0.176f;
        const float run = 0.28f;
        var b = new LevelBuilder("house (foreign)");
        AddSoupQuad(b, "ground", new Vector3(-11f, 0f, -6f), new Vector3(6.2f, 0f, -6f), new Vector3(6.2f, 0f, 6f), new Vector3(-11f, 0f, 6f), 6);
        AddSoupBox(b, "wall_front_south", new Vector3(-6.2f, 0f, -4.2f), new Vector3(-6f, 6f, -0.6f));
        AddSoupBox(b, "wall_front_north", new Vector3(-6.2f, 0f, 0.6f), new Vector3(-6f, 6f, 4.2f));
        AddSoupBox(b, "door_lintel", new Vector3(-6.2f, 2.1f, -0.6f), new Vector3(-6f, 6f, 0.6f));
        AddSoupBox(b, "wall_back", new Vector3(6f, 0f, -4.2f), new Vector3(6.2f, 6f, 4.2f));
        AddSoupBox(b, "wall_south", new Vector3(-6f, 0f, -4.2f), new Vector3(6f, 6f, -4f));
        AddSoupBox(b, "wall_north", new Vector3(-6f, 0f, 4f), new Vector3(6f, 6f, 4.2f));
        AddSoupBox(b, "roof", new Vector3(-6.2f, 6f, -4.2f), new Vector3(6.2f, 6.2f, 4.2f));
        for (int s = 0; s < 8; s++)
        {
            float x0 = -1f + (run * s);
            AddSoupBox(b, $"step_a{s}", new Vector3(x0, 0f, 2.8f), new Vector3(x0 + run, rise * (s + 1), 4f));
        }

        float landing = -1f + (8f * run);
        AddSoupBox(b, "landing", new Vector3(landing, 0f, 2.8f), new Vector3(landing + 1.2f, 8f * rise, 4f));
        for (int s = 0; s < 8; s++)
        {
            float x0 = landing + 1.2f + (run * s);
            AddSoupBox(b, $"step_b{s}", new Vector3(x0, 0f, 2.8f), new Vector3(x0 + run, rise * (s + 9), 4f));
        }

        float gallery = landing + 1.2f + (8f * run);
        AddSoupBox(b, "gallery", new Vector3(gallery, (16f * rise) - 0.2f, -4f), new Vector3(6f, 16f * rise, 4f));
        return (b.Build(), [
            (new Vector3(-9f, 0f, 0f), new Vector3(-3.5f, 0f, 0f)),
            (new Vector3(-3f, 0f, 2f), new Vector3(5.3f, 16f * rise, 0f)),
            (new Vector3(5.3f, 16f * rise, -2f), new Vector3(-9f, 0f, -2f)),
        ]);
    }

    /// <summary>
    /// A kitchen floor at a rat's scale, 3 × 2 m of unwelded tiles: a book 3 cm thick, a board 6 cm high and an 8 cm
    /// box lying about, and a 12 cm gap between two floor boards over a 20 cm drop. Requests of 1 to 1.5 m: across the
    /// floor past the book, onto the box, and over the gap.
    /// </summary>
    internal static (Level Level, (Vector3 From, Vector3 To)[] Requests) Clutter()
    {
        var b = new LevelBuilder("clutter (foreign)");
        AddSoupQuad(b, "floor_west", new Vector3(-1.5f, 0f, -1f), new Vector3(0.6f, 0f, -1f), new Vector3(0.6f, 0f, 1f), new Vector3(-1.5f, 0f, 1f), 12);
        AddSoupQuad(b, "floor_east", new Vector3(0.72f, 0f, -1f), new Vector3(1.5f, 0f, -1f), new Vector3(1.5f, 0f, 1f), new Vector3(0.72f, 0f, 1f), 4);
        AddSoupQuad(b, "cellar", new Vector3(0.5f, -0.2f, -1f), new Vector3(0.8f, -0.2f, -1f), new Vector3(0.8f, -0.2f, 1f), new Vector3(0.5f, -0.2f, 1f), 1);
        Matrix4x4 turned = Matrix4x4.CreateRotationY(0.4f) * Matrix4x4.CreateTranslation(-0.6f, 0f, 0.3f);
        AddSoupBox(b, "book", new Vector3(-0.12f, 0f, -0.09f), new Vector3(0.12f, 0.03f, 0.09f), turned);
        AddSoupBox(b, "board", new Vector3(-0.2f, 0f, -0.7f), new Vector3(0.2f, 0.06f, -0.5f));
        AddSoupBox(b, "box", new Vector3(-1.2f, 0f, -0.8f), new Vector3(-0.9f, 0.08f, -0.5f));
        return (b.Build(), [
            (new Vector3(-1.2f, 0f, 0.5f), new Vector3(0.2f, 0f, 0.2f)),
            (new Vector3(-0.5f, 0f, -0.2f), new Vector3(-1.05f, 0.08f, -0.65f)),
            (new Vector3(0f, 0f, 0f), new Vector3(1.2f, 0f, 0f)),
        ]);
    }

    /// <summary>
    /// A wide open field, 120 m square, as a terrain exporter writes one (unwelded 5 m quads), with a few rocks and a
    /// 4 m wall, 12 m long and too high to jump, standing across the way of one request: requests of 12 to 40 m on a
    /// level a hundred times their route's area, one of them around the wall.
    /// </summary>
    internal static (Level Level, (Vector3 From, Vector3 To)[] Requests) Field()
    {
        var b = new LevelBuilder("field (foreign)");
        AddSoupQuad(b, "ground", new Vector3(-60f, 0f, -60f), new Vector3(60f, 0f, -60f), new Vector3(60f, 0f, 60f), new Vector3(-60f, 0f, 60f), 24);
        AddSoupBox(b, "wall", new Vector3(29.75f, 0f, -6f), new Vector3(30.25f, 4f, 6f));
        AddSoupBox(b, "rock_1", new Vector3(-30f, 0f, -31f), new Vector3(-29f, 0.5f, -30f));
        AddSoupBox(b, "rock_2", new Vector3(-22f, 0f, -27f), new Vector3(-20.5f, 0.4f, -25.5f));
        AddSoupBox(b, "rock_3", new Vector3(8f, 0f, 20f), new Vector3(9f, 0.6f, 21f));
        return (b.Build(), [
            (new Vector3(-45f, 0f, -40f), new Vector3(-10f, 0f, -20f)),
            (new Vector3(22f, 0f, 0f), new Vector3(38f, 0f, 0f)),
            (new Vector3(0f, 0f, 10f), new Vector3(12f, 0f, 14f)),
        ]);
    }

    /// <summary>
    /// A ground plane, slabs 2–10 cm thick floating at 0.5–1.2 m (boxes, as a modeller makes a shelf), a bare
    /// single-sided plane (no thickness) and a 20 cm wide bar 0.8 m up: goals on top of the slabs and the bar.
    /// </summary>
    private static (Level, (Vector3, Vector3)[]) ThinSlabs()
    {
        var b = new LevelBuilder("thin-slabs (foreign)");
        AddSoupQuad(b, "ground", new Vector3(-8f, 0f, -6f), new Vector3(8f, 0f, -6f), new Vector3(8f, 0f, 6f), new Vector3(-8f, 0f, 6f), 8);
        AddSoupBox(b, "slab_02", new Vector3(-4f, 0.6f, -1f), new Vector3(-2f, 0.62f, 1f));
        AddSoupBox(b, "slab_05", new Vector3(-0.5f, 0.9f, -1f), new Vector3(1.5f, 0.95f, 1f));
        AddSoupBox(b, "slab_10", new Vector3(3f, 1.1f, -1f), new Vector3(5f, 1.2f, 1f));
        AddSoupQuad(b, "plane", new Vector3(3f, 0.5f, 3f), new Vector3(5f, 0.5f, 3f), new Vector3(5f, 0.5f, 5f), new Vector3(3f, 0.5f, 5f), 1);
        AddSoupBox(b, "bar", new Vector3(-4f, 0.7f, 3.9f), new Vector3(-1f, 0.8f, 4.1f));
        return (b.Build(), [
            (new Vector3(-6f, 0f, 0f), new Vector3(-3f, 0.62f, 0f)),
            (new Vector3(-3f, 0.62f, 0f), new Vector3(0.5f, 0.95f, 0f)),
            (new Vector3(-6f, 0f, -3f), new Vector3(4f, 1.2f, 0f)),
            (new Vector3(6f, 0f, 4f), new Vector3(4f, 0.5f, 4f)),
            (new Vector3(-6f, 0f, 4f), new Vector3(-2.5f, 0.8f, 4f)),
        ]);
    }

    /// <summary>Rolling terrain modelled Z-up in centimetres (as a DCC tool exports) with a 0.25 m grid, turned and scaled into place.</summary>
    private static (Level, (Vector3, Vector3)[]) Curved()
    {
        const int n = 64;
        const float size = 1600f; // centimetres
        var positions = new List<Vector3>();
        var indices = new List<int>();
        for (int i = 0; i < n; i++)
        {
            for (int j = 0; j < n; j++)
            {
                // Unwelded: every quad its own four corners.
                Vector3 P(int a, int c)
                {
                    float x = (-size / 2f) + (size * a / n);
                    float y = (-size / 2f) + (size * c / n);
                    return new Vector3(x, y, CurvedHeight(x / 100f, -y / 100f) * 100f);
                }

                int s = positions.Count;
                positions.AddRange([P(i, j), P(i + 1, j), P(i + 1, j + 1), P(i, j + 1)]);
                indices.AddRange([s, s + 1, s + 2, s, s + 2, s + 3]);
            }
        }

        // Z-up centimetres → Y-up metres: rotate −90° about X, scale 0.01.
        Matrix4x4 toYUp = Matrix4x4.CreateScale(0.01f) * Matrix4x4.CreateRotationX(-MathF.PI / 2f);
        var b = new LevelBuilder("curved (foreign)");
        b.AddMesh("terrain", [.. positions], [.. indices], toYUp, TestLevels.Ground);
        Level level = b.Build();
        Vector3 At(float x, float z) => new(x, CurvedHeight(x, z), z);
        return (level, [
            (At(-6f, -6f), At(6f, 6f)),
            (At(-5f, 4f), At(5f, -4f)),
            (At(0f, -6f), At(0f, 6f)),
            (At(-6f, 0f), At(2.5f, 0.5f)),
        ]);
    }

    /// <summary>Height (metres) of the curved terrain at (x, z) metres: hills about 1 m high, slopes up to ~35°.</summary>
    public static float CurvedHeight(float x, float z) =>
        (0.6f * MathF.Sin(x * 0.7f) * MathF.Cos(z * 0.6f)) + (0.3f * MathF.Sin((x + z) * 0.9f));

    /// <summary>A flight of 8 steps (17 cm rise, 30 cm run, 2 m wide) up to a landing, modelled as one mesh per step.</summary>
    private static (Level, (Vector3, Vector3)[]) Stairs()
    {
        var b = new LevelBuilder("stairs (foreign)");
        AddSoupQuad(b, "floor", new Vector3(-6f, 0f, -4f), new Vector3(2f, 0f, -4f), new Vector3(2f, 0f, 4f), new Vector3(-6f, 0f, 4f), 4);
        for (int s = 0; s < 8; s++)
        {
            float x0 = 2f + (0.3f * s);
            AddSoupBox(b, $"step_{s}", new Vector3(x0, 0f, -1f), new Vector3(x0 + 0.3f, 0.17f * (s + 1), 1f));
        }

        AddSoupBox(b, "landing", new Vector3(4.4f, 0f, -3f), new Vector3(8f, 1.36f, 3f));
        return (b.Build(), [
            (new Vector3(-4f, 0f, 0f), new Vector3(6.5f, 1.36f, 0f)),
            (new Vector3(-2f, 0f, 2f), new Vector3(3.35f, 0.68f, 0f)),
            (new Vector3(6.5f, 1.36f, 1.5f), new Vector3(-4f, 0f, -2f)),
            (new Vector3(0f, 0f, -2f), new Vector3(2.75f, 0.51f, 0.5f)),
        ]);
    }

    /// <summary>
    /// Two 1 m platforms 6 m apart joined by a 0.3 m beam whose top is level with theirs, the whole turned 20° about Y
    /// by a node transform, over open ground (a parkour course's beam): along the beam end to end, from platform to
    /// platform, and from the ground up onto the beam's middle.
    /// </summary>
    private static (Level, (Vector3, Vector3)[]) Beam()
    {
        var b = new LevelBuilder("beam (foreign)");
        AddSoupQuad(b, "ground", new Vector3(-10f, 0f, -10f), new Vector3(10f, 0f, -10f), new Vector3(10f, 0f, 10f), new Vector3(-10f, 0f, 10f), 2);
        Matrix4x4 place = Matrix4x4.CreateRotationY(20f * MathF.PI / 180f);
        AddSoupBox(b, "platform_west", new Vector3(-6f, 0f, -1.5f), new Vector3(-3f, 1f, 1.5f), place);
        AddSoupBox(b, "platform_east", new Vector3(3f, 0f, -1.5f), new Vector3(6f, 1f, 1.5f), place);
        AddSoupBox(b, "beam", new Vector3(-3f, 0.7f, -0.15f), new Vector3(3f, 1f, 0.15f), place);
        Vector3 At(float x, float y, float z) => Vector3.Transform(new Vector3(x, y, z), place);
        return (b.Build(), [
            (At(-2.8f, 1f, 0f), At(2.8f, 1f, 0f)),
            (At(-5f, 1f, 0.5f), At(5f, 1f, -0.5f)),
            (At(0f, 0f, 3f), At(0.5f, 1f, 0f)),
        ]);
    }

    /// <summary>A 1.2 m block and a 0.5 m crate on open ground: goals on top of them, and back down.</summary>
    private static (Level, (Vector3, Vector3)[]) Block()
    {
        var b = new LevelBuilder("block (foreign)");
        AddSoupQuad(b, "ground", new Vector3(-8f, 0f, -8f), new Vector3(8f, 0f, -8f), new Vector3(8f, 0f, 8f), new Vector3(-8f, 0f, 8f), 2);

        // The block modelled around its own origin and placed by a node transform (turned 30° about Y).
        Matrix4x4 place = Matrix4x4.CreateRotationY(MathF.PI / 6f) * Matrix4x4.CreateTranslation(2f, 0f, 1f);
        AddSoupBox(b, "block", new Vector3(-1f, 0f, -1f), new Vector3(1f, 1.2f, 1f), place);
        AddSoupBox(b, "crate", new Vector3(-5.4f, 0f, -3.4f), new Vector3(-4.6f, 0.5f, -2.6f));
        return (b.Build(), [
            (new Vector3(-4f, 0f, 3f), new Vector3(2f, 1.2f, 1f)),
            (new Vector3(2f, 1.2f, 1f), new Vector3(-5f, 0.5f, -3f)),
            (new Vector3(-5f, 0.5f, -3f), new Vector3(5f, 0f, -5f)),
            (new Vector3(6f, 0f, 6f), new Vector3(-6f, 0f, -6f)),
        ]);
    }

    /// <summary>A floor of 1 m tiles with tiles missing (holes to fall through) and rotated crates and planks lying about.</summary>
    private static (Level, (Vector3, Vector3)[]) HolesDebris()
    {
        var b = new LevelBuilder("holes-debris (foreign)");
        for (int i = -6; i < 6; i++)
        {
            for (int j = -4; j < 4; j++)
            {
                bool hole = (i is -2 or -1 && j is -1 or 0 or 1) || (i == 2 && j is >= -4 and < 2) || (i == 3 && j is >= -4 and < 2);
                if (!hole)
                {
                    AddSoupQuad(b, $"tile_{i}_{j}", new Vector3(i, 0f, j), new Vector3(i + 1, 0f, j), new Vector3(i + 1, 0f, j + 1), new Vector3(i, 0f, j + 1), 1);
                }
            }
        }

        var random = new Random(7);
        for (int k = 0; k < 10; k++)
        {
            float x = -5.5f + (11f * (float)random.NextDouble());
            float z = -3.5f + (7f * (float)random.NextDouble());
            Vector3 half = new(0.1f + (0.3f * (float)random.NextDouble()), 0.05f + (0.2f * (float)random.NextDouble()), 0.1f + (0.3f * (float)random.NextDouble()));
            Matrix4x4 place = Matrix4x4.CreateRotationZ(0.3f * ((float)random.NextDouble() - 0.5f)) * Matrix4x4.CreateRotationY(6.28f * (float)random.NextDouble()) * Matrix4x4.CreateTranslation(x, half.Y * 0.8f, z);
            AddSoupBox(b, $"debris_{k}", -half, half, place);
        }

        return (b.Build(), [
            (new Vector3(-5f, 0f, 0f), new Vector3(5f, 0f, 0f)),
            (new Vector3(-5f, 0f, -3f), new Vector3(0.5f, 0f, 3f)),
            (new Vector3(5f, 0f, -3f), new Vector3(-4f, 0f, 3f)),
        ]);
    }

    /// <summary>A tunnel 2.6 m high (floor, walls, ceiling as one inward-facing mesh) with a raised ledge inside.</summary>
    private static (Level, (Vector3, Vector3)[]) Cave()
    {
        var b = new LevelBuilder("cave (foreign)");
        AddSoupQuad(b, "floor", new Vector3(-8f, 0f, -2f), new Vector3(8f, 0f, -2f), new Vector3(8f, 0f, 2f), new Vector3(-8f, 0f, 2f), 8);
        AddSoupQuad(b, "ceiling", new Vector3(-8f, 2.6f, 2f), new Vector3(8f, 2.6f, 2f), new Vector3(8f, 2.6f, -2f), new Vector3(-8f, 2.6f, -2f), 8);
        AddSoupQuad(b, "wall_n", new Vector3(-8f, 0f, 2f), new Vector3(8f, 0f, 2f), new Vector3(8f, 2.6f, 2f), new Vector3(-8f, 2.6f, 2f), 4);
        AddSoupQuad(b, "wall_s", new Vector3(-8f, 2.6f, -2f), new Vector3(8f, 2.6f, -2f), new Vector3(8f, 0f, -2f), new Vector3(-8f, 0f, -2f), 4);
        AddSoupBox(b, "ledge", new Vector3(1f, 0f, -2f), new Vector3(3f, 0.4f, 2f));
        return (b.Build(), [
            (new Vector3(-6f, 0f, 0f), new Vector3(6f, 0f, 0f)),
            (new Vector3(-6f, 0f, 1f), new Vector3(2f, 0.4f, 0f)),
        ]);
    }

    /// <summary>A quad split into n × n cells, every triangle with its own vertices (no index sharing).</summary>
    private static void AddSoupQuad(LevelBuilder b, string name, Vector3 p00, Vector3 p10, Vector3 p11, Vector3 p01, int n)
    {
        var positions = new List<Vector3>();
        for (int i = 0; i < n; i++)
        {
            for (int j = 0; j < n; j++)
            {
                Vector3 P(float u, float v) => Vector3.Lerp(Vector3.Lerp(p00, p10, u), Vector3.Lerp(p01, p11, u), v);
                float u0 = i / (float)n, u1 = (i + 1) / (float)n, v0 = j / (float)n, v1 = (j + 1) / (float)n;
                positions.AddRange([P(u0, v0), P(u1, v1), P(u1, v0), P(u0, v0), P(u0, v1), P(u1, v1)]);
            }
        }

        // Winding: normal = (p01 − p00) × (p10 − p00) must face "out"; flip each triangle when it does not.
        Vector3 wanted = Vector3.Cross(p01 - p00, p10 - p00);
        for (int t = 0; t < positions.Count; t += 3)
        {
            Vector3 n0 = Vector3.Cross(positions[t + 1] - positions[t], positions[t + 2] - positions[t]);
            if (Vector3.Dot(n0, wanted) < 0f)
            {
                (positions[t + 1], positions[t + 2]) = (positions[t + 2], positions[t + 1]);
            }
        }

        b.AddMesh(name, [.. positions], [.. Enumerable.Range(0, positions.Count)], Matrix4x4.Identity, TestLevels.Ground);
    }

    /// <summary>A closed box as a triangle soup (outward faces), optionally placed by a transform.</summary>
    internal static void AddSoupBox(LevelBuilder b, string name, Vector3 min, Vector3 max, Matrix4x4? place = null)
    {
        var corners = new Vector3[]
        {
            new(min.X, min.Y, min.Z), new(max.X, min.Y, min.Z), new(max.X, max.Y, min.Z), new(min.X, max.Y, min.Z),
            new(min.X, min.Y, max.Z), new(max.X, min.Y, max.Z), new(max.X, max.Y, max.Z), new(min.X, max.Y, max.Z),
        };
        int[] faces = [0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5, 3, 7, 6, 3, 6, 2, 0, 1, 5, 0, 5, 4];
        Vector3[] soup = [.. faces.Select(i => corners[i])];
        b.AddMesh(name, soup, [.. Enumerable.Range(0, soup.Length)], place ?? Matrix4x4.Identity, TestLevels.Ground);
    }
}
