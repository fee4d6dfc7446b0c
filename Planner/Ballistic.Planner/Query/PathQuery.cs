using System.Diagnostics;
using System.Numerics;
using Ballistic.Planner.Characters;
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
    private SearchGraph? _graph;

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
    public PlanResult Plan(Vector3 from, Vector3 to, QuerySettings? settings = null) => Plan(from, to, settings, rejected: null);

    /// <summary>
    /// Plans from the point <paramref name="from"/> to the point <paramref name="to"/> (world metres), never using a
    /// jump between the node pairs in <paramref name="rejected"/> (node ids as in <see cref="Jump"/>: roadmap ids, or
    /// the start's and goal's ids). Start and goal are placed by <see cref="TrunkSampler.Place"/>, deterministically:
    /// when the roadmap already holds that very pose (a bake given the same points), that node is used as is.
    /// </summary>
    public PlanResult Plan(Vector3 from, Vector3 to, QuerySettings? settings, IReadOnlySet<(int From, int To)>? rejected)
    {
        settings ??= new QuerySettings();
        var clock = Stopwatch.StartNew();
        EndpointPlacement startPlacement = _scene.Sampler.Place(from, settings.Tolerance, settings.CanStand);
        if (startPlacement.Pose is not { } startPose)
        {
            return Fail(PlannerStatus.InvalidStart, startPlacement.Failure("start", settings.Tolerance)!, null, null, clock) with { StartPlacement = startPlacement };
        }

        EndpointPlacement goalPlacement = _scene.Sampler.Place(to, settings.Tolerance, settings.CanStand);
        int n = _roadmap.Nodes.Count;
        RoadmapNode start = Existing(startPose) ?? new RoadmapNode(n, startPose.Pose, startPose.Cone, startPose.Contacts);
        if (goalPlacement.Pose is not { } goalPose)
        {
            return Fail(PlannerStatus.InvalidGoal, goalPlacement.Failure("goal", settings.Tolerance)!, start, null, clock) with { StartPlacement = startPlacement, GoalPlacement = goalPlacement };
        }

        RoadmapNode goal = Existing(goalPose) ?? (startPose.Pose == goalPose.Pose ? start : new RoadmapNode(n + 1, goalPose.Pose, goalPose.Cone, goalPose.Contacts));
        if (goal.Id == start.Id)
        {
            return new PlanResult(PlannerStatus.Exact, "the start is the goal: no jump needed", start, goal, [], clock.Elapsed) { StartPlacement = startPlacement, GoalPlacement = goalPlacement };
        }

        // Extra edges of the query: start → roadmap, roadmap → goal, start → goal (a roadmap node has its own).
        var extra = new List<(int From, int To, BallisticArc Arc)>();
        bool startIsNew = start.Id >= n;
        bool goalIsNew = goal.Id >= n;
        if ((startIsNew || goalIsNew) && rejected?.Contains((start.Id, goal.Id)) != true &&
            _scene.Steering.Steer(start.Pose, start.Cone, goal.Pose, goal.Cone) is { Succeeded: true } direct)
        {
            extra.Add((start.Id, goal.Id, direct.Arc));
        }

        if (startIsNew)
        {
            int connected = 0;
            foreach (int j in Nearest(start.Pose.Position, settings.MaxNeighbours))
            {
                RoadmapNode node = _roadmap.Nodes[j];
                SteeringResult r = _scene.Steering.Steer(start.Pose, start.Cone, node.Pose, node.Cone);
                if (r.Succeeded && rejected?.Contains((start.Id, j)) != true)
                {
                    extra.Add((start.Id, j, r.Arc));
                    if (++connected >= settings.Connections)
                    {
                        break;
                    }
                }
            }
        }

        if (goalIsNew)
        {
            int connected = 0;
            foreach (int j in Nearest(goal.Pose.Position, settings.MaxNeighbours))
            {
                RoadmapNode node = _roadmap.Nodes[j];
                SteeringResult r = _scene.Steering.Steer(node.Pose, node.Cone, goal.Pose, goal.Cone);
                if (r.Succeeded && rejected?.Contains((j, goal.Id)) != true)
                {
                    extra.Add((j, goal.Id, r.Arc));
                    if (++connected >= settings.Connections)
                    {
                        break;
                    }
                }
            }
        }

        List<Jump>? path = AStar(start, goal, extra, rejected);
        PlanResult result = path is null
            ? Fail(PlannerStatus.NoPath, $"the roadmap ({n} nodes, {_roadmap.Edges.Count} jumps) holds no sequence of jumps from the start to the goal" + (rejected is { Count: > 0 } ? $" without the {AnimatedPlanner.Jumps(rejected.Count)} set aside" : ""), start, goal, clock)
            : new PlanResult(PlannerStatus.Exact, $"{AnimatedPlanner.Jumps(path.Count)} found", start, goal, path, clock.Elapsed);
        return result with { StartPlacement = startPlacement, GoalPlacement = goalPlacement };
    }

    /// <summary>The roadmap node with exactly this pose (the bake placed the same point), or <c>null</c>.</summary>
    private RoadmapNode? Existing(PoseEvaluation pose)
    {
        foreach (RoadmapNode node in _roadmap.Nodes)
        {
            if (node.Pose == pose.Pose)
            {
                return node;
            }
        }

        return null;
    }

    /// <summary>
    /// A* over the roadmap plus the query's extra edges. Cost: flight time. Heuristic: horizontal distance to the
    /// goal divided by the fastest horizontal speed of any edge, a lower bound on the remaining flight time (every
    /// jump covers its horizontal distance at most that fast), so the path found is of least total flight time.
    /// </summary>
    private List<Jump>? AStar(RoadmapNode start, RoadmapNode goal, List<(int From, int To, BallisticArc Arc)> extra, IReadOnlySet<(int From, int To)>? rejected)
    {
        SearchGraph graph = Graph();
        int roadmapCount = graph.Positions.Length;
        int count = roadmapCount + 2;
        var extraOut = new List<int>?[count];
        float fastest = _roadmap.MaxHorizontalSpeed;
        for (int e = 0; e < extra.Count; e++)
        {
            (extraOut[extra[e].From] ??= []).Add(e);
            fastest = MathF.Max(fastest, extra[e].Arc.HorizontalSpeed);
        }

        float inverseSpeed = fastest > 0f ? 1f / fastest : 0f;
        Vector2 target = new(goal.Pose.Position.X, goal.Pose.Position.Z);
        var cost = new float[count];
        Array.Fill(cost, float.PositiveInfinity);
        var cameFrom = new (int Node, int Edge)[count]; // edge ≥ 0: roadmap edge; < 0: extra edge ~index
        var closed = new bool[count];
        var open = new PriorityQueue<int, float>();
        cost[start.Id] = 0f;
        open.Enqueue(start.Id, 0f);
        while (open.TryDequeue(out int node, out _))
        {
            if (closed[node])
            {
                continue;
            }

            closed[node] = true;
            if (node == goal.Id)
            {
                return Reconstruct(start, goal, cameFrom, extra);
            }

            float here = cost[node];
            if (node < roadmapCount)
            {
                for (int i = graph.Offsets[node]; i < graph.Offsets[node + 1]; i++)
                {
                    int next = graph.Targets[i];
                    float candidate = here + graph.Times[i];
                    if (!closed[next] && candidate < cost[next] && rejected?.Contains((node, next)) != true)
                    {
                        cost[next] = candidate;
                        cameFrom[next] = (node, graph.EdgeIndex[i]);
                        open.Enqueue(next, candidate + (Vector2.Distance(target, graph.Positions[next]) * inverseSpeed));
                    }
                }
            }

            if (extraOut[node] is { } list)
            {
                foreach (int e in list)
                {
                    int next = extra[e].To;
                    float candidate = here + extra[e].Arc.FlightTime;
                    if (!closed[next] && candidate < cost[next] && rejected?.Contains((node, next)) != true)
                    {
                        cost[next] = candidate;
                        cameFrom[next] = (node, ~e);
                        Vector2 p = next == goal.Id ? target : graph.Positions[next];
                        open.Enqueue(next, candidate + (Vector2.Distance(target, p) * inverseSpeed));
                    }
                }
            }
        }

        return null;
    }

    /// <summary>The roadmap in compressed rows for the search, rebuilt when the roadmap has grown.</summary>
    private SearchGraph Graph()
    {
        if (_graph is { } g && g.EdgeCount == _roadmap.Edges.Count && g.Positions.Length == _roadmap.Nodes.Count)
        {
            return g;
        }

        int n = _roadmap.Nodes.Count;
        var offsets = new int[n + 1];
        var positions = new Vector2[n];
        for (int i = 0; i < n; i++)
        {
            offsets[i + 1] = offsets[i] + _roadmap.Outgoing(i).Count;
            Vector3 p = _roadmap.Nodes[i].Pose.Position;
            positions[i] = new Vector2(p.X, p.Z);
        }

        var targets = new int[offsets[n]];
        var times = new float[offsets[n]];
        var edges = new int[offsets[n]];
        for (int i = 0; i < n; i++)
        {
            int k = offsets[i];
            foreach (int e in _roadmap.Outgoing(i))
            {
                targets[k] = _roadmap.EdgeTargets[e];
                times[k] = _roadmap.EdgeFlightTimes[e];
                edges[k++] = e;
            }
        }

        _graph = new SearchGraph(offsets, targets, times, edges, positions, _roadmap.Edges.Count);
        return _graph;
    }

    private sealed record SearchGraph(int[] Offsets, int[] Targets, float[] Times, int[] EdgeIndex, Vector2[] Positions, int EdgeCount);

    private List<Jump> Reconstruct(RoadmapNode start, RoadmapNode goal, (int Node, int Edge)[] cameFrom, List<(int From, int To, BallisticArc Arc)> extra)
    {
        RoadmapNode NodeAt(int id) => id == start.Id ? start : id == goal.Id ? goal : _roadmap.Nodes[id];
        var jumps = new List<Jump>();
        for (int node = goal.Id; node != start.Id; node = cameFrom[node].Node)
        {
            int edge = cameFrom[node].Edge;
            BallisticArc arc = edge >= 0 ? _roadmap.Edges[edge].Arc : extra[~edge].Arc;
            jumps.Add(new Jump(NodeAt(cameFrom[node].Node), NodeAt(node), arc));
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
}
