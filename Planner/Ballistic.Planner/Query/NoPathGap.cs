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
        (float least, int a, int b) = (float.PositiveInfinity, -1, -1);
        foreach (int f in starts)
        {
            Vector3 p = NodeOf(f).Pose.Position;
            foreach (int g in goals)
            {
                float speed = LeastSpeed(NodeOf(g).Pose.Position - p, g0);
                if (speed < least)
                {
                    (least, a, b) = (speed, f, g);
                }
            }
        }

        if (a < 0)
        {
            return text;
        }

        RoadmapNode near = NodeOf(a);
        RoadmapNode far = NodeOf(b);
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
