using System.Diagnostics;
using System.Numerics;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;
using Ballistic.Planner.Steering;

namespace Ballistic.Planner.Query;

/// <summary>
/// Online path request (paper §5): the start and goal points are turned into valid root poses nearby, linked to
/// the roadmap by the steering method, and A* finds the sequence of jumps of least total flight time. The baked
/// roadmap is not modified. Work is bounded by the roadmap's size.
/// </summary>
public sealed class PathQuery
{
    private readonly PlanningScene _scene;
    private readonly Roadmap _roadmap;

    /// <summary>Creates a query over a roadmap baked for the scene's level and character.</summary>
    /// <exception cref="ArgumentException">The roadmap was baked for another level or character.</exception>
    public PathQuery(PlanningScene scene, Roadmap roadmap)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(roadmap);
        if (roadmap.LevelFingerprint != scene.Level.Fingerprint)
        {
            throw new ArgumentException("The roadmap was baked on another level.", nameof(roadmap));
        }

        if (roadmap.CharacterFingerprint != scene.Character.Fingerprint)
        {
            throw new ArgumentException($"The roadmap was baked for another character ({roadmap.CharacterName}).", nameof(roadmap));
        }

        _scene = scene;
        _roadmap = roadmap;
    }

    /// <summary>Plans from the point <paramref name="from"/> to the point <paramref name="to"/> (world metres).</summary>
    public PlanResult Plan(Vector3 from, Vector3 to, QuerySettings? settings = null)
    {
        settings ??= new QuerySettings();
        var clock = Stopwatch.StartNew();
        PoseEvaluation? startPose = _scene.Sampler.SampleNear(SeedMixer.Create(settings.Seed, -11), from, settings.ProjectionRadius);
        if (startPose is null)
        {
            return Fail(PlannerStatus.InvalidStart, $"no valid root pose within {settings.ProjectionRadius:0.##} m of the start {Format(from)}", null, null, clock);
        }

        PoseEvaluation? goalPose = _scene.Sampler.SampleNear(SeedMixer.Create(settings.Seed, -12), to, settings.ProjectionRadius);
        int n = _roadmap.Nodes.Count;
        var start = new RoadmapNode(n, startPose.Pose, startPose.Cone, startPose.Contacts);
        if (goalPose is null)
        {
            return Fail(PlannerStatus.InvalidGoal, $"no valid root pose within {settings.ProjectionRadius:0.##} m of the goal {Format(to)}", start, null, clock);
        }

        var goal = new RoadmapNode(n + 1, goalPose.Pose, goalPose.Cone, goalPose.Contacts);

        // Extra edges of the query: start → roadmap, roadmap → goal, start → goal.
        var extra = new List<(int From, int To, BallisticArc Arc)>();
        SteeringResult direct = _scene.Steering.Steer(start.Pose, start.Cone, goal.Pose, goal.Cone);
        if (direct.Succeeded)
        {
            extra.Add((start.Id, goal.Id, direct.Arc));
        }

        foreach (int j in Nearest(start.Pose.Position, settings.MaxNeighbours))
        {
            RoadmapNode node = _roadmap.Nodes[j];
            SteeringResult r = _scene.Steering.Steer(start.Pose, start.Cone, node.Pose, node.Cone);
            if (r.Succeeded)
            {
                extra.Add((start.Id, j, r.Arc));
            }
        }

        foreach (int j in Nearest(goal.Pose.Position, settings.MaxNeighbours))
        {
            RoadmapNode node = _roadmap.Nodes[j];
            SteeringResult r = _scene.Steering.Steer(node.Pose, node.Cone, goal.Pose, goal.Cone);
            if (r.Succeeded)
            {
                extra.Add((j, goal.Id, r.Arc));
            }
        }

        List<Jump>? path = AStar(start, goal, extra);
        return path is null
            ? Fail(PlannerStatus.NoPath, $"the roadmap ({n} nodes, {_roadmap.Edges.Count} jumps) holds no sequence of jumps from the start to the goal", start, goal, clock)
            : new PlanResult(PlannerStatus.Exact, $"{path.Count} jumps found", start, goal, path, clock.Elapsed);
    }

    /// <summary>A* over the roadmap plus the query's extra edges; cost = flight time, heuristic = horizontal distance / top speed.</summary>
    private List<Jump>? AStar(RoadmapNode start, RoadmapNode goal, List<(int From, int To, BallisticArc Arc)> extra)
    {
        int count = _roadmap.Nodes.Count + 2;
        var extraOut = new List<int>[count];
        for (int e = 0; e < extra.Count; e++)
        {
            (extraOut[extra[e].From] ??= []).Add(e);
        }

        float topSpeed = _scene.Character.TakeoffSpeedMax;
        Vector3 target = goal.Pose.Position;
        float Heuristic(int node)
        {
            Vector3 p = node == start.Id ? start.Pose.Position : node == goal.Id ? target : _roadmap.Nodes[node].Pose.Position;
            return new Vector2(target.X - p.X, target.Z - p.Z).Length() / topSpeed;
        }

        var cost = new float[count];
        Array.Fill(cost, float.PositiveInfinity);
        var cameFrom = new (int Node, BallisticArc Arc)[count];
        var closed = new bool[count];
        var open = new PriorityQueue<int, (float F, int Id)>();
        cost[start.Id] = 0f;
        open.Enqueue(start.Id, (Heuristic(start.Id), start.Id));
        while (open.TryDequeue(out int node, out _))
        {
            if (closed[node])
            {
                continue;
            }

            closed[node] = true;
            if (node == goal.Id)
            {
                return Reconstruct(start, goal, cameFrom);
            }

            void Relax(int next, in BallisticArc arc)
            {
                float candidate = cost[node] + arc.FlightTime;
                if (!closed[next] && candidate < cost[next])
                {
                    cost[next] = candidate;
                    cameFrom[next] = (node, arc);
                    open.Enqueue(next, (candidate + Heuristic(next), next));
                }
            }

            if (node < _roadmap.Nodes.Count)
            {
                foreach (int e in _roadmap.Outgoing(node))
                {
                    RoadmapEdge edge = _roadmap.Edges[e];
                    Relax(edge.To, edge.Arc);
                }
            }

            if (extraOut[node] is { } list)
            {
                foreach (int e in list)
                {
                    Relax(extra[e].To, extra[e].Arc);
                }
            }
        }

        return null;
    }

    private List<Jump> Reconstruct(RoadmapNode start, RoadmapNode goal, (int Node, BallisticArc Arc)[] cameFrom)
    {
        RoadmapNode NodeAt(int id) => id == start.Id ? start : id == goal.Id ? goal : _roadmap.Nodes[id];
        var jumps = new List<Jump>();
        for (int node = goal.Id; node != start.Id; node = cameFrom[node].Node)
        {
            jumps.Add(new Jump(NodeAt(cameFrom[node].Node), NodeAt(node), cameFrom[node].Arc));
        }

        jumps.Reverse();
        return jumps;
    }

    /// <summary>Up to <paramref name="count"/> roadmap nodes nearest to <paramref name="point"/> within jump reach of it.</summary>
    private List<int> Nearest(Vector3 point, int count)
    {
        SteeringLimits limits = _scene.Steering.Limits;
        var candidates = new List<(float Distance, int Id)>();
        foreach (RoadmapNode node in _roadmap.Nodes)
        {
            Vector3 q = node.Pose.Position;
            float x = new Vector2(q.X - point.X, q.Z - point.Z).Length();
            if (x <= limits.MaxReach(point.Y - q.Y) || x <= limits.MaxReach(q.Y - point.Y))
            {
                candidates.Add((Vector3.Distance(point, q), node.Id));
            }
        }

        candidates.Sort();
        return [.. candidates.Take(count).Select(c => c.Id)];
    }

    private static PlanResult Fail(PlannerStatus status, string reason, RoadmapNode? start, RoadmapNode? goal, Stopwatch clock) =>
        new(status, reason, start, goal, [], clock.Elapsed);

    private static string Format(Vector3 p) => $"({p.X:0.###}, {p.Y:0.###}, {p.Z:0.###})";
}
