using System.Diagnostics;
using System.Numerics;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;
using Ballistic.Planner.Steering;

namespace Ballistic.Planner.Query;

/// <summary>
/// Online path request (paper §5): the start and goal are turned into valid root poses nearby (or given as
/// stances already evaluated), linked to the roadmap by the steering method, and A* finds the sequence of jumps of
/// least total flight time. The baked roadmap is not modified. Work is bounded by the roadmap's size.
/// </summary>
/// <remarks>
/// A query owns scratch memory reused from one request to the next (search costs, back-pointers, the open list),
/// so that a request between two roadmap nodes allocates little more than its result. It is therefore not
/// thread-safe: use one <see cref="PathQuery"/> per thread. The <see cref="Roadmap"/> and the
/// <see cref="PlanningScene"/> are thread-safe and may be shared by any number of queries on any threads.
/// </remarks>
public sealed class PathQuery
{
    /// <summary>A* polls the termination condition every this many expansions.</summary>
    private const int PollEvery = 1024;

    private readonly PlanningScene _scene;
    private readonly Roadmap _roadmap;
    private readonly ReachTest _reach;

    // Scratch of the search, valid for the current generation only (so nothing is cleared between requests).
    private readonly float[] _cost;
    private readonly (int Node, int Edge)[] _cameFrom; // edge ≥ 0: roadmap edge; < 0: extra edge ~index
    private readonly int[] _reached;
    private readonly int[] _closed;
    private readonly int[] _extraFirst;
    private readonly int[] _extraLast;
    private readonly int[] _extraStamp;
    private readonly List<int> _extraNext = [];
    private readonly List<(int From, int To, BallisticArc Arc)> _extra = [];
    private readonly PriorityQueue<int, float> _open = new();
    private readonly List<(float Distance, int Id)> _nearest = [];
    private readonly List<(int Node, float FlightTime)> _goalEntries = [];
    private readonly float[] _heuristic;
    private readonly int[] _heuristicStamp;
    private int _generation;

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
        _reach = new ReachTest(scene.Steering.Limits);
        int count = roadmap.Nodes.Count + 2;
        _cost = new float[count];
        _cameFrom = new (int, int)[count];
        _reached = new int[count];
        _closed = new int[count];
        _extraFirst = new int[count];
        _extraLast = new int[count];
        _extraStamp = new int[count];
        _heuristic = new float[count];
        _heuristicStamp = new int[count];
    }

    /// <summary>The roadmap searched.</summary>
    public Roadmap Roadmap => _roadmap;

    /// <summary>Plans from the point <paramref name="from"/> to the point <paramref name="to"/> (world metres).</summary>
    public PlanResult Plan(Vector3 from, Vector3 to, QuerySettings? settings = null) => Plan(from, to, settings, rejected: null);

    /// <summary>
    /// Plans from the point <paramref name="from"/> to the point <paramref name="to"/> (world metres), never using a
    /// jump between the node pairs in <paramref name="rejected"/> (node ids as in <see cref="Jump"/>: roadmap ids, or
    /// the start's and goal's ids). Start and goal are placed by <see cref="TrunkSampler.Place"/>, deterministically:
    /// when the roadmap already holds that very pose (a bake given the same points), that node is used as is;
    /// otherwise the start gets id n and the goal id n + 1 (n the roadmap's node count). With
    /// <see cref="QuerySettings.PreferRoadmapNodes"/>, a roadmap node standing within the tolerance of a point
    /// (<see cref="Roadmap.FindNode"/>) is taken instead of placing a stance there.
    /// </summary>
    /// <param name="from">Requested start point, world metres.</param>
    /// <param name="to">Requested goal point, world metres.</param>
    /// <param name="settings">Endpoint tolerance, stance check and connections; defaults when <c>null</c>.</param>
    /// <param name="rejected">Jumps (takeoff id, landing id) not to use, or <c>null</c>.</param>
    /// <param name="termination">
    /// Stops the request early (its time and cancellation parts, <see cref="TerminationCondition.ShouldStopNow"/>,
    /// polled before each placement, between steering calls and during the search, the time measured from the
    /// request's start): the result then has that condition's status (<see cref="PlannerStatus.Timeout"/>,
    /// <see cref="PlannerStatus.Cancelled"/>) and reason. <c>null</c> for none.
    /// </param>
    public PlanResult Plan(Vector3 from, Vector3 to, QuerySettings? settings, IReadOnlySet<(int From, int To)>? rejected, TerminationCondition? termination = null)
    {
        settings ??= new QuerySettings();
        var clock = Stopwatch.StartNew();
        if (Stopped(termination, clock, null, null) is { } early)
        {
            return early;
        }

        EndpointPlacement startPlacement = Locate(from, settings, out RoadmapNode? reused);
        if (startPlacement.Pose is not { } startPose)
        {
            return Fail(PlannerStatus.InvalidStart, startPlacement.Failure("start", settings.Tolerance)!, null, null, clock) with { StartPlacement = startPlacement };
        }

        int n = _roadmap.Nodes.Count;
        RoadmapNode start = reused ?? Existing(startPose.Pose) ?? new RoadmapNode(n, startPose.Pose, startPose.Cone, startPose.Contacts);
        if (Stopped(termination, clock, start, null) is { } stopped)
        {
            return stopped with { StartPlacement = startPlacement };
        }

        EndpointPlacement goalPlacement = Locate(to, settings, out reused);
        if (goalPlacement.Pose is not { } goalPose)
        {
            return Fail(PlannerStatus.InvalidGoal, goalPlacement.Failure("goal", settings.Tolerance)!, start, null, clock) with { StartPlacement = startPlacement, GoalPlacement = goalPlacement };
        }

        RoadmapNode goal = reused ?? Existing(goalPose.Pose) ?? (startPose.Pose == goalPose.Pose ? start : new RoadmapNode(n + 1, goalPose.Pose, goalPose.Cone, goalPose.Contacts));
        return Connect(start, goal, settings, rejected, termination, clock) with { StartPlacement = startPlacement, GoalPlacement = goalPlacement };
    }

    /// <summary>
    /// Plans from an already evaluated stance <paramref name="start"/> (an agent standing on the roadmap, or where
    /// a previous plan left it) to the point <paramref name="to"/> (world metres). A roadmap node (same
    /// <see cref="RoadmapNode.Id"/> and equal pose as the roadmap's node of that id) is used directly: no sampling,
    /// no steering. Any other stance, such as the goal node of a previous query, is steered into the roadmap like a
    /// placed start, as id n (n the roadmap's node count; the roadmap's own node when it holds that very pose). The
    /// goal is placed as by <see cref="Plan(Vector3, Vector3, QuerySettings?, IReadOnlySet{ValueTuple{int, int}}?, TerminationCondition?)"/>.
    /// </summary>
    /// <param name="start">The stance the path starts from: root pose, friction cone and contacts, world frame.</param>
    /// <param name="to">Requested goal point, world metres.</param>
    /// <param name="settings">Endpoint tolerance, stance check and connections; defaults when <c>null</c>.</param>
    /// <param name="rejected">Jumps (takeoff id, landing id, as in the result) not to use, or <c>null</c>.</param>
    /// <param name="termination">Stops the request early (see the point-to-point overload); <c>null</c> for none.</param>
    public PlanResult Plan(RoadmapNode start, Vector3 to, QuerySettings? settings = null, IReadOnlySet<(int From, int To)>? rejected = null, TerminationCondition? termination = null)
    {
        ArgumentNullException.ThrowIfNull(start);
        settings ??= new QuerySettings();
        var clock = Stopwatch.StartNew();
        int n = _roadmap.Nodes.Count;
        RoadmapNode from = Resolve(start, n);
        if (Stopped(termination, clock, from, null) is { } early)
        {
            return early;
        }

        EndpointPlacement goalPlacement = Locate(to, settings, out RoadmapNode? reused);
        if (goalPlacement.Pose is not { } goalPose)
        {
            return Fail(PlannerStatus.InvalidGoal, goalPlacement.Failure("goal", settings.Tolerance)!, from, null, clock) with { GoalPlacement = goalPlacement };
        }

        RoadmapNode goal = reused ?? Existing(goalPose.Pose) ?? (from.Pose == goalPose.Pose ? from : new RoadmapNode(n + 1, goalPose.Pose, goalPose.Cone, goalPose.Contacts));
        return Connect(from, goal, settings, rejected, termination, clock) with { GoalPlacement = goalPlacement };
    }

    /// <summary>
    /// Plans between two already evaluated stances. Roadmap nodes (same id and equal pose as the roadmap's) are used
    /// directly, with no sampling or steering: between two of them the request is an A* search over the roadmap
    /// alone. Other stances are steered into the roadmap, the start as id n and the goal as id n + 1 (n the
    /// roadmap's node count), unless the roadmap holds that very pose.
    /// </summary>
    /// <param name="start">The stance the path starts from, world frame.</param>
    /// <param name="goal">The stance the path ends on, world frame.</param>
    /// <param name="settings">Connections for stances off the roadmap; defaults when <c>null</c> (the tolerance and stance check are not used).</param>
    /// <param name="rejected">Jumps (takeoff id, landing id, as in the result) not to use, or <c>null</c>.</param>
    /// <param name="termination">Stops the request early (see the point-to-point overload); <c>null</c> for none.</param>
    public PlanResult Plan(RoadmapNode start, RoadmapNode goal, QuerySettings? settings = null, IReadOnlySet<(int From, int To)>? rejected = null, TerminationCondition? termination = null)
    {
        ArgumentNullException.ThrowIfNull(start);
        ArgumentNullException.ThrowIfNull(goal);
        settings ??= new QuerySettings();
        var clock = Stopwatch.StartNew();
        int n = _roadmap.Nodes.Count;
        RoadmapNode from = Resolve(start, n);
        RoadmapNode to = _roadmap.Holds(goal) ? goal
            : _roadmap.FindPose(goal.Pose) is int id ? _roadmap.Node(id)
            : from.Pose == goal.Pose ? from
            : goal.Id == n + 1 ? goal : goal with { Id = n + 1 };
        return Connect(from, to, settings, rejected, termination, clock);
    }

    /// <summary>
    /// Where a requested point puts a stance: a roadmap node when <see cref="QuerySettings.PreferRoadmapNodes"/> finds
    /// one within the tolerance that can stand there (<paramref name="node"/>), otherwise <see cref="TrunkSampler.Place"/>.
    /// </summary>
    private EndpointPlacement Locate(Vector3 point, QuerySettings settings, out RoadmapNode? node)
    {
        node = null;
        if (settings.PreferRoadmapNodes)
        {
            if (_roadmap.FindNode(point, settings.Tolerance) is int id)
            {
                RoadmapNode found = _roadmap.Node(id);
                var stance = new PoseEvaluation(found.Pose, PoseValidity.Valid, found.Contacts, found.Cone);
                if (settings.CanStand?.Invoke(stance) != false)
                {
                    node = found;
                    Vector3 centre = _roadmap.ContactCentres[id];
                    return new EndpointPlacement(point, stance, centre, new Vector2(centre.X - point.X, centre.Z - point.Z).Length(), MathF.Abs(centre.Y - point.Y), null);
                }
            }
        }

        return _scene.Sampler.Place(point, settings.Tolerance, settings.CanStand);
    }

    /// <summary>A stance as the search sees it: the roadmap's node when it is one (or holds its pose), otherwise the stance as id <paramref name="outsideId"/>.</summary>
    private RoadmapNode Resolve(RoadmapNode node, int outsideId) =>
        _roadmap.Holds(node) ? node
        : _roadmap.FindPose(node.Pose) is int id ? _roadmap.Node(id)
        : node.Id == outsideId ? node : node with { Id = outsideId };

    /// <summary>The roadmap node with exactly this pose (the bake placed the same point), or <c>null</c>.</summary>
    private RoadmapNode? Existing(in Geometry.RootPose pose) => _roadmap.FindPose(pose) is int id ? _roadmap.Node(id) : null;

    /// <summary>Links the start and goal to the roadmap (those not in it) and searches.</summary>
    private PlanResult Connect(RoadmapNode start, RoadmapNode goal, QuerySettings settings, IReadOnlySet<(int From, int To)>? rejected, TerminationCondition? termination, Stopwatch clock)
    {
        if (Stopped(termination, clock, start, goal) is { } early)
        {
            return early;
        }

        if (goal.Id == start.Id)
        {
            return new PlanResult(PlannerStatus.Exact, "the start is the goal: no jump needed", start, goal, [], clock.Elapsed);
        }

        // Extra edges of the request: start → roadmap, roadmap → goal, start → goal (a roadmap node has its own).
        int n = _roadmap.Nodes.Count;
        _extra.Clear();
        bool startIsNew = start.Id >= n;
        bool goalIsNew = goal.Id >= n;
        ParabolaSteering steering = _scene.Steering;
        if (startIsNew || goalIsNew)
        {
            if (rejected?.Contains((start.Id, goal.Id)) != true &&
                steering.Steer(start.Pose, start.Cone, goal.Pose, goal.Cone) is { Succeeded: true } direct)
            {
                _extra.Add((start.Id, goal.Id, direct.Arc));
            }
        }

        if (startIsNew)
        {
            int connected = 0;
            _roadmap.Nearest(start.Pose.Position, _reach, settings.MaxNeighbours, _nearest);
            foreach ((_, int j) in _nearest)
            {
                if (rejected?.Contains((start.Id, j)) == true)
                {
                    continue;
                }

                if (Stopped(termination, clock, start, goal) is { } stopped)
                {
                    return stopped;
                }

                RoadmapNode node = _roadmap.Node(j);
                SteeringResult r = steering.Steer(start.Pose, start.Cone, node.Pose, node.Cone);
                if (r.Succeeded)
                {
                    _extra.Add((start.Id, j, r.Arc));
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
            _roadmap.Nearest(goal.Pose.Position, _reach, settings.MaxNeighbours, _nearest);
            foreach ((_, int j) in _nearest)
            {
                if (rejected?.Contains((j, goal.Id)) == true)
                {
                    continue;
                }

                if (Stopped(termination, clock, start, goal) is { } stopped)
                {
                    return stopped;
                }

                RoadmapNode node = _roadmap.Node(j);
                SteeringResult r = steering.Steer(node.Pose, node.Cone, goal.Pose, goal.Cone);
                if (r.Succeeded)
                {
                    _extra.Add((j, goal.Id, r.Arc));
                    if (++connected >= settings.Connections)
                    {
                        break;
                    }
                }
            }
        }

        List<Jump>? path = AStar(start, goal, rejected, termination, clock, out int expansions, out PlanResult? cut);
        if (cut is not null)
        {
            return cut with { Expansions = expansions };
        }

        PlanResult result = path is null
            ? Fail(PlannerStatus.NoPath, $"the roadmap ({n} nodes, {_roadmap.Edges.Count} jumps) holds no sequence of jumps from the start to the goal" + (rejected is { Count: > 0 } ? $" without the {JumpRepair.Jumps(rejected.Count)} set aside" : ""), start, goal, clock)
            : new PlanResult(PlannerStatus.Exact, $"{JumpRepair.Jumps(path.Count)} found", start, goal, path, clock.Elapsed);
        return result with { Expansions = expansions };
    }

    /// <summary>
    /// A* over the roadmap plus the request's extra edges. Cost: flight time. Heuristic: the larger of two lower
    /// bounds on the remaining flight time, so the path found is of least total flight time: the horizontal distance
    /// to the goal divided by the fastest horizontal speed of any jump (every jump covers its horizontal distance at
    /// most that fast), and the roadmap's landmark bounds (<see cref="Landmarks"/>; for a goal off the roadmap, through
    /// the nodes jumping to it), which also prune nodes that cannot reach the goal.
    /// </summary>
    private List<Jump>? AStar(RoadmapNode start, RoadmapNode goal, IReadOnlySet<(int From, int To)>? rejected, TerminationCondition? termination, Stopwatch clock, out int expansions, out PlanResult? cut)
    {
        int generation = NextGeneration();
        expansions = 0;
        cut = null;
        float fastest = _roadmap.MaxHorizontalSpeed;
        int roadmapCount = _roadmap.Nodes.Count;
        _extraNext.Clear();
        _goalEntries.Clear();
        for (int e = 0; e < _extra.Count; e++)
        {
            (int from, int to, BallisticArc arc) = _extra[e];
            _extraNext.Add(-1);
            if (_extraStamp[from] != generation)
            {
                _extraStamp[from] = generation;
                _extraFirst[from] = e;
            }
            else
            {
                _extraNext[_extraLast[from]] = e;
            }

            _extraLast[from] = e;
            fastest = MathF.Max(fastest, arc.HorizontalSpeed);
            if (to == goal.Id && from < roadmapCount)
            {
                _goalEntries.Add((from, arc.FlightTime));
            }
        }

        var heuristic = new Heuristic(this, goal, fastest > 0f ? 1f / fastest : 0f, generation);
        ReadOnlySpan<int> offsets = _roadmap.OutgoingOffsets;
        ReadOnlySpan<int> targets = _roadmap.OutgoingTargets;
        ReadOnlySpan<float> times = _roadmap.OutgoingFlightTimes;
        ReadOnlySpan<int> edges = _roadmap.OutgoingEdges;
        float[] cost = _cost;
        int[] reached = _reached;
        int[] closed = _closed;
        PriorityQueue<int, float> open = _open;
        open.Clear();
        cost[start.Id] = 0f;
        reached[start.Id] = generation;
        open.Enqueue(start.Id, 0f);
        while (open.TryDequeue(out int node, out _))
        {
            if (closed[node] == generation)
            {
                continue;
            }

            closed[node] = generation;
            if (node == goal.Id)
            {
                expansions++;
                return Reconstruct(start, goal);
            }

            if (++expansions % PollEvery == 0 && Stopped(termination, clock, start, goal) is { } stopped)
            {
                cut = stopped;
                return null;
            }

            float here = cost[node];
            if (node < roadmapCount)
            {
                for (int i = offsets[node], end = offsets[node + 1]; i < end; i++)
                {
                    int next = targets[i];
                    float candidate = here + times[i];
                    if (closed[next] != generation && (reached[next] != generation || candidate < cost[next]) && rejected?.Contains((node, next)) != true)
                    {
                        float h = heuristic.At(next);
                        if (h < float.PositiveInfinity)
                        {
                            cost[next] = candidate;
                            reached[next] = generation;
                            _cameFrom[next] = (node, edges[i]);
                            open.Enqueue(next, candidate + h);
                        }
                    }
                }
            }

            if (_extraStamp[node] == generation)
            {
                for (int e = _extraFirst[node]; e >= 0; e = _extraNext[e])
                {
                    int next = _extra[e].To;
                    float candidate = here + _extra[e].Arc.FlightTime;
                    if (closed[next] != generation && (reached[next] != generation || candidate < cost[next]) && rejected?.Contains((node, next)) != true)
                    {
                        float h = heuristic.At(next);
                        if (h < float.PositiveInfinity)
                        {
                            cost[next] = candidate;
                            reached[next] = generation;
                            _cameFrom[next] = (node, ~e);
                            open.Enqueue(next, candidate + h);
                        }
                    }
                }
            }
        }

        return null;
    }

    /// <summary>The A* heuristic of one search, each node's value computed once (seconds; +∞: cannot reach the goal).</summary>
    private readonly ref struct Heuristic
    {
        private readonly PathQuery _query;
        private readonly int _goal;
        private readonly bool _goalOnRoadmap;
        private readonly Vector2 _target;
        private readonly float _inverseSpeed;
        private readonly int _generation;
        private readonly Landmarks _landmarks;
        private readonly ReadOnlySpan<float> _goalFrom;
        private readonly ReadOnlySpan<float> _goalTo;

        public Heuristic(PathQuery query, RoadmapNode goal, float inverseSpeed, int generation)
        {
            _query = query;
            _goal = goal.Id;
            _target = new Vector2(goal.Pose.Position.X, goal.Pose.Position.Z);
            _inverseSpeed = inverseSpeed;
            _generation = generation;
            _landmarks = query._roadmap.Landmarks;
            _goalOnRoadmap = goal.Id < query._roadmap.Nodes.Count;
            _goalFrom = _goalOnRoadmap ? _landmarks.From(goal.Id) : [];
            _goalTo = _goalOnRoadmap ? _landmarks.To(goal.Id) : [];
        }

        public float At(int node)
        {
            if (node == _goal)
            {
                return 0f;
            }

            if (_query._heuristicStamp[node] == _generation)
            {
                return _query._heuristic[node];
            }

            float h = Vector2.Distance(_target, _query._roadmap.Horizontal[node]) * _inverseSpeed;
            if (_landmarks.Count > 0)
            {
                ReadOnlySpan<float> from = _landmarks.From(node);
                ReadOnlySpan<float> to = _landmarks.To(node);
                float bound;
                if (_goalOnRoadmap)
                {
                    bound = Landmarks.LowerBound(from, to, _goalFrom, _goalTo);
                }
                else
                {
                    // Off the roadmap, the goal is entered only by the request's jumps to it.
                    bound = float.PositiveInfinity;
                    foreach ((int entry, float time) in _query._goalEntries)
                    {
                        bound = MathF.Min(bound, Landmarks.LowerBound(from, to, _landmarks.From(entry), _landmarks.To(entry)) + time);
                    }
                }

                h = MathF.Max(h, bound);
            }

            _query._heuristic[node] = h;
            _query._heuristicStamp[node] = _generation;
            return h;
        }
    }

    /// <summary>A fresh generation of the scratch arrays (cleared only when the counter wraps).</summary>
    private int NextGeneration()
    {
        if (_generation == int.MaxValue)
        {
            Array.Clear(_reached);
            Array.Clear(_closed);
            Array.Clear(_extraStamp);
            Array.Clear(_heuristicStamp);
            _generation = 0;
        }

        return ++_generation;
    }

    private List<Jump> Reconstruct(RoadmapNode start, RoadmapNode goal)
    {
        RoadmapNode NodeAt(int id) => id == start.Id ? start : id == goal.Id ? goal : _roadmap.Node(id);
        var jumps = new List<Jump>();
        for (int node = goal.Id; node != start.Id; node = _cameFrom[node].Node)
        {
            int edge = _cameFrom[node].Edge;
            BallisticArc arc = edge >= 0 ? _roadmap.Edge(edge).Arc : _extra[~edge].Arc;
            jumps.Add(new Jump(NodeAt(_cameFrom[node].Node), NodeAt(node), arc));
        }

        jumps.Reverse();
        return jumps;
    }

    /// <summary>The failure to return when <paramref name="termination"/> says to stop now, otherwise <c>null</c>.</summary>
    private static PlanResult? Stopped(TerminationCondition? termination, Stopwatch clock, RoadmapNode? start, RoadmapNode? goal) =>
        termination is not null && termination.ShouldStopNow(clock.Elapsed, out PlannerStatus status, out string reason)
            ? Fail(status, reason, start, goal, clock)
            : null;

    private static PlanResult Fail(PlannerStatus status, string reason, RoadmapNode? start, RoadmapNode? goal, Stopwatch clock) =>
        new(status, reason, start, goal, [], clock.Elapsed);
}
