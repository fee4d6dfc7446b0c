using System.Globalization;
using System.Numerics;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;
using Ballistic.Planner.Walking;

namespace Ballistic.Planner.Query;

/// <summary>
/// Why a search found no path, in words a level designer acts on: how many stances the start reaches and how many
/// reach the goal (with how far they spread, so that a start closed in on every side shows as such), and the nearest
/// gap between those two sides: the least takeoff speed a jump across it needs when that is above the character's
/// limit (a ledge too high to jump onto), or else why the jump steering and the walking steering refuse it. The graph
/// is the search's own: the roadmap's jumps (and walks, for a request that walks) and the request's links to and from
/// its start and goal, without the moves set aside.
/// </summary>
internal static class NoPathGap
{
    /// <summary>
    /// The words (starting ": the start reaches …") that follow "holds no sequence of moves from the start to the goal";
    /// empty when the two sides are not apart (a path exists among moves the search may not take).
    /// </summary>
    /// <param name="scene">The level and character (steering, limits).</param>
    /// <param name="roadmap">The roadmap searched.</param>
    /// <param name="start">The request's start stance (a roadmap node or one placed, with an id past the roadmap's).</param>
    /// <param name="goal">The request's goal stance.</param>
    /// <param name="links">The request's own moves (from id, to id): start to roadmap, roadmap to goal, start to goal.</param>
    /// <param name="walking">Whether the request walks (the roadmap's walks count).</param>
    /// <param name="rejected">Moves (from id, to id) set aside, or <c>null</c>.</param>
    public static string Describe(PlanningScene scene, Roadmap roadmap, RoadmapNode start, RoadmapNode goal, IReadOnlyList<(int From, int To)> links, bool walking, IReadOnlySet<(int From, int To)>? rejected)
    {
        int n = roadmap.Nodes.Count;
        int count = Math.Max(n, Math.Max(start.Id, goal.Id) + 1);
        RoadmapNode NodeOf(int id) => id == start.Id ? start : id == goal.Id ? goal : roadmap.Nodes[id];

        // Every move of the search's graph (from id, to id): the request's links, the roadmap's jumps and, for a
        // request that walks, its walks; what the start reaches along them, and what reaches the goal.
        var moves = new List<(int From, int To)>(links);
        for (int node = 0; node < n; node++)
        {
            foreach (int next in roadmap.OutgoingTargets[roadmap.OutgoingOffsets[node]..roadmap.OutgoingOffsets[node + 1]])
            {
                moves.Add((node, next));
            }

            if (walking)
            {
                foreach (int next in roadmap.WalkTargets[roadmap.WalkOffsets[node]..roadmap.WalkOffsets[node + 1]])
                {
                    moves.Add((node, next));
                }
            }
        }

        bool[] forward = Reach(start.Id, moves, count, reversed: false, rejected);
        bool[] backward = Reach(goal.Id, moves, count, reversed: true, rejected);

        var starts = new List<int>();
        var goals = new List<int>();
        for (int id = 0; id < count; id++)
        {
            if (forward[id] && backward[id])
            {
                return "";
            }

            if (forward[id] && (id < n || id == start.Id))
            {
                starts.Add(id);
            }

            if (backward[id] && (id < n || id == goal.Id))
            {
                goals.Add(id);
            }
        }

        int reached = starts.Count(id => id < n && id != start.Id);
        int reaching = goals.Count(id => id < n && id != goal.Id);
        string text = $": the start reaches {Stances(reached)}{(reached > 0 ? Spread(starts, start, NodeOf) : "")} and {(reaching == 0 ? "none reaches the goal" : Stances(reaching) + Spread(goals, goal, NodeOf) + (reaching == 1 ? " reaches the goal" : " reach the goal"))}";

        // The easiest gap between the two sides: the pair a jump across needs the least takeoff speed for (a ballistic
        // jump of the trunk rising h over d across needs at least √(g (h + √(h² + d²)))), and what refuses a move there.
        float g0 = scene.Steering.Limits.Gravity;
        (float least, int a, int b) = Easiest([.. starts.Select(id => NodeOf(id).Pose.Position)], [.. goals.Select(id => NodeOf(id).Pose.Position)], g0);
        if (a < 0)
        {
            return text;
        }

        RoadmapNode near = NodeOf(starts[a]);
        RoadmapNode far = NodeOf(goals[b]);
        Vector3 step = far.ContactCentre - near.ContactCentre;
        float limit = scene.Character.TakeoffSpeedMax;
        string gap = string.Create(CultureInfo.InvariantCulture, $"; the easiest jump between them, from {Point(near.ContactCentre)} to {Point(far.ContactCentre)} ({new Vector2(step.X, step.Z).Length():0.0} m across, {MathF.Abs(step.Y):0.0} m {(step.Y >= 0f ? "up" : "down")}), needs a takeoff of at least {least:0.00} m/s");
        if (least > limit)
        {
            return text + gap + string.Create(CultureInfo.InvariantCulture, $", above the character's {limit:0.00} m/s");
        }

        SteeringResult jump = scene.Steering.Steer(near.Pose, near.Cone, far.Pose, far.Cone);
        string refused = string.Create(CultureInfo.InvariantCulture, $" (the character's limit: {limit:0.00} m/s), ") + (jump.Succeeded
            ? "and steers: the roadmap is too sparse there (bake more nodes)"
            : "and is refused: " + SteeringFailureText.Describe(jump.Failure));
        if (walking && scene.Walking.Limits.CanWalk)
        {
            WalkResult walk = scene.Walking.Steer(near, far);
            refused += walk.Walk is null ? "; a walk there: " + WalkRefusals.Reason(walk.Failure, scene.Walking.Limits) : "";
        }

        return text + gap + refused;
    }

    /// <summary>
    /// The ids (below <paramref name="count"/>) reached from <paramref name="origin"/> along <paramref name="moves"/>
    /// not in <paramref name="rejected"/>: forward, or against the moves' direction (<paramref name="reversed"/>: the
    /// ids that reach <paramref name="origin"/>). The moves are laid out in compressed rows by the end walked from.
    /// </summary>
    private static bool[] Reach(int origin, List<(int From, int To)> moves, int count, bool reversed, IReadOnlySet<(int From, int To)>? rejected)
    {
        var offsets = new int[count + 1];
        foreach ((int from, int to) in moves)
        {
            offsets[(reversed ? to : from) + 1]++;
        }

        for (int i = 0; i < count; i++)
        {
            offsets[i + 1] += offsets[i];
        }

        var next = new int[count];
        Array.Copy(offsets, next, count);
        var ends = new int[moves.Count];
        foreach ((int from, int to) in moves)
        {
            ends[next[reversed ? to : from]++] = reversed ? from : to;
        }

        var reached = new bool[count];
        var stack = new Stack<int>();
        reached[origin] = true;
        stack.Push(origin);
        while (stack.TryPop(out int node))
        {
            for (int i = offsets[node]; i < offsets[node + 1]; i++)
            {
                int other = ends[i];
                if (!reached[other] && rejected?.Contains(reversed ? (other, node) : (node, other)) != true)
                {
                    reached[other] = true;
                    stack.Push(other);
                }
            }
        }

        return reached;
    }

    /// <summary>
    /// The pair (index into <paramref name="from"/>, index into <paramref name="to"/>; world positions) a jump between
    /// needs the least takeoff speed for (<see cref="LeastSpeed"/>), and that speed: the first such pair scanning
    /// <paramref name="from"/> in order and, for each, <paramref name="to"/> in order (<see cref="EasiestByEveryPair"/>
    /// gives the same). (∞, −1, −1) when either side is empty. Two large sides (two islands of a big roadmap, thousands
    /// of stances each) are not scanned pair by pair: <paramref name="to"/> is put in a grid across, and from each
    /// point of <paramref name="from"/> the grid's cells are visited ring by ring outward, a cell only when the least
    /// speed any point in it could need (the cell's lowest point, at its nearest across) is below the best so far, and
    /// the rings only while one could be.
    /// </summary>
    internal static (float Least, int From, int To) Easiest(IReadOnlyList<Vector3> from, IReadOnlyList<Vector3> to, float g)
    {
        if ((long)from.Count * to.Count <= PairsScanned)
        {
            return EasiestByEveryPair(from, to, g);
        }

        // The grid: about four points a cell, over the bounds of `to` across (x, z); each cell's points in list order and its lowest height.
        float minX = float.PositiveInfinity, minZ = float.PositiveInfinity, maxX = float.NegativeInfinity, maxZ = float.NegativeInfinity, lowest = float.PositiveInfinity;
        foreach (Vector3 q in to)
        {
            (minX, maxX, minZ, maxZ, lowest) = (MathF.Min(minX, q.X), MathF.Max(maxX, q.X), MathF.Min(minZ, q.Z), MathF.Max(maxZ, q.Z), MathF.Min(lowest, q.Y));
        }

        float size = MathF.Max(MathF.Max(maxX - minX, maxZ - minZ) / MathF.Sqrt(to.Count / 4f), 1e-3f);
        int columns = Math.Min(1024, (int)((maxX - minX) / size) + 1);
        int rows = Math.Min(1024, (int)((maxZ - minZ) / size) + 1);
        size = MathF.Max((maxX - minX) / columns, (maxZ - minZ) / rows) * (1f + 1e-6f) + 1e-6f;
        var cells = new List<int>[columns * rows];
        var cellLow = new float[columns * rows];
        Array.Fill(cellLow, float.PositiveInfinity);
        for (int i = 0; i < to.Count; i++)
        {
            int cell = Cell(to[i].X, minX, columns) + (columns * Cell(to[i].Z, minZ, rows));
            (cells[cell] ??= []).Add(i);
            cellLow[cell] = MathF.Min(cellLow[cell], to[i].Y);
        }

        // Distances across to a cell are taken this much short (metres): a point rounded into a cell may lie a few ulps outside it.
        float slack = (1e-5f * (MathF.Abs(minX) + MathF.Abs(minZ) + (columns * size) + (rows * size))) + 1e-5f;
        (float least, int a, int b) = (float.PositiveInfinity, -1, -1);
        for (int f = 0; f < from.Count; f++)
        {
            Vector3 p = from[f];
            int cx = Cell(p.X, minX, columns);
            int cz = Cell(p.Z, minZ, rows);
            int rings = Math.Max(Math.Max(cx, columns - 1 - cx), Math.Max(cz, rows - 1 - cz));
            for (int ring = 0; ring <= rings; ring++)
            {
                // Every cell of this ring and beyond lies at least (ring − 1) cells across from p.
                if (Pruned(Bound(lowest - p.Y, MathF.Max(0f, ((ring - 1) * size) - slack), g), least))
                {
                    break;
                }

                // The ring's cells only, not the square inside it: its bottom and top rows, then its two sides between.
                for (int x = cx - ring; x <= cx + ring; x++)
                {
                    Open(x, cz - ring);
                    if (ring > 0)
                    {
                        Open(x, cz + ring);
                    }
                }

                for (int z = cz - ring + 1; z <= cz + ring - 1; z++)
                {
                    Open(cx - ring, z);
                    Open(cx + ring, z);
                }
            }

            // Cell (x, z)'s points from p, unless the cell is outside the grid, empty, or too far across or too high to hold a better pair.
            void Open(int x, int z)
            {
                if (x < 0 || z < 0 || x >= columns || z >= rows || cells[x + (columns * z)] is not List<int> points)
                {
                    return;
                }

                float dx = MathF.Max(0f, MathF.Max(minX + (x * size) - p.X, p.X - (minX + ((x + 1) * size))));
                float dz = MathF.Max(0f, MathF.Max(minZ + (z * size) - p.Z, p.Z - (minZ + ((z + 1) * size))));
                if (Pruned(Bound(cellLow[x + (columns * z)] - p.Y, MathF.Max(0f, MathF.Sqrt((dx * dx) + (dz * dz)) - slack), g), least))
                {
                    return;
                }

                foreach (int t in points)
                {
                    // As the scan pair by pair would: a lower speed, or for this same point an equal one further up the list.
                    float speed = LeastSpeed(to[t] - p, g);
                    if (speed < least || (speed == least && a == f && t < b))
                    {
                        (least, a, b) = (speed, f, t);
                    }
                }
            }
        }

        return (least, a, b);

        int Cell(float v, float min, int count) => Math.Clamp((int)((v - min) / size), 0, count - 1);
    }

    /// <summary>Sides whose pairs number at most this are scanned pair by pair (<see cref="EasiestByEveryPair"/>).</summary>
    internal const int PairsScanned = 16_384;

    /// <summary><see cref="Easiest"/> by every pair, in order: the reference.</summary>
    internal static (float Least, int From, int To) EasiestByEveryPair(IReadOnlyList<Vector3> from, IReadOnlyList<Vector3> to, float g)
    {
        (float least, int a, int b) = (float.PositiveInfinity, -1, -1);
        for (int f = 0; f < from.Count; f++)
        {
            for (int t = 0; t < to.Count; t++)
            {
                float speed = LeastSpeed(to[t] - from[f], g);
                if (speed < least)
                {
                    (least, a, b) = (speed, f, t);
                }
            }
        }

        return (least, a, b);
    }

    /// <summary>
    /// <see cref="LeastSpeed"/> of a jump rising <paramref name="rise"/> over <paramref name="across"/> metres: a
    /// lower bound of it for any jump rising more or travelling farther across.
    /// </summary>
    private static float Bound(float rise, float across, float g) => MathF.Sqrt(g * (rise + MathF.Sqrt((rise * rise) + (across * across))));

    /// <summary>Whether a cell (or a ring of cells) whose jumps need at least <paramref name="bound"/> can hold none below <paramref name="least"/>, with room for rounding; never for a bound that is not a number.</summary>
    private static bool Pruned(float bound, float least) => bound > (least * (1f + 1e-4f)) + 1e-6f;

    /// <summary>The least takeoff speed (m/s) of a ballistic jump displaced by <paramref name="d"/> (world metres) under gravity <paramref name="g"/> (m/s²).</summary>
    internal static float LeastSpeed(Vector3 d, float g)
    {
        float across = new Vector2(d.X, d.Z).Length();
        return MathF.Sqrt(g * (d.Y + MathF.Sqrt((d.Y * d.Y) + (across * across))));
    }

    private static string Stances(int count) => count switch
    {
        0 => "no stance of the roadmap",
        1 => "1 stance",
        _ => string.Create(CultureInfo.InvariantCulture, $"{count} stances"),
    };

    /// <summary>" (all within X m of it)" when the stances lie within 10 m of <paramref name="end"/> (a side closed in), else empty.</summary>
    private static string Spread(List<int> side, RoadmapNode end, Func<int, RoadmapNode> nodeOf)
    {
        float farthest = side.Count == 0 ? 0f : side.Max(id => Vector3.Distance(nodeOf(id).ContactCentre, end.ContactCentre));
        return farthest <= 10f ? string.Create(CultureInfo.InvariantCulture, $" (all within {farthest:0.0} m of it)") : "";
    }

    private static string Point(Vector3 p) => string.Create(CultureInfo.InvariantCulture, $"({p.X:0.0}, {p.Y:0.0}, {p.Z:0.0})");
}
