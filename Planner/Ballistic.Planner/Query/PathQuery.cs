using System.Diagnostics;
using System.Numerics;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;
using Ballistic.Planner.Steering;
using Ballistic.Planner.Walking;

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
    /// <summary>A* polls the termination condition, and pauses when run in steps, every this many expansions by default (<see cref="SliceExpansions"/>).</summary>
    private const int PollEvery = 1024;

    private readonly int _sliceExpansions = PollEvery;

    private readonly PlanningScene _scene;
    private readonly Roadmap _roadmap;
    private readonly ReachTest _reach;

    // Scratch of the search, valid for the current generation only (so nothing is cleared between requests).
    private readonly float[] _cost;
    private readonly (int Node, int Edge, int Kind)[] _cameFrom; // kind: FromJump (roadmap edge), FromWalk (roadmap walk), FromExtra (the request's)
    private readonly int[] _reached;
    private readonly int[] _closed;
    private readonly int[] _extraFirst;
    private readonly int[] _extraLast;
    private readonly int[] _extraStamp;
    private readonly List<int> _extraNext = [];
    private readonly List<Extra> _extra = [];
    private readonly PriorityQueue<int, float> _open = new();
    private readonly List<(float Distance, int Id)> _nearest = [];
    private readonly List<(int Node, float FlightTime)> _goalEntries = [];
    private readonly float[] _heuristic;
    private readonly int[] _heuristicStamp;

    /// <summary>Per roadmap jump slot (<see cref="Roadmap.OutgoingTargets"/>) and walk slot (<see cref="Roadmap.WalkTargets"/>), the generation whose search must not take it (a pair of the request's rejected set).</summary>
    private readonly int[] _rejectedJump;
    private readonly int[] _rejectedWalk;

    /// <summary>
    /// Per node id, the generation whose search takes no jump off (onto) it: the request's <see cref="QuerySettings.NoTakeoffs"/>
    /// (<see cref="QuerySettings.NoLandings"/>) marked once per search, a lookup per relaxed jump instead of one in each set.
    /// </summary>
    private readonly int[] _noTakeoffStamp;
    private readonly int[] _noLandingStamp;

    /// <summary>Per request edge (<see cref="_extra"/>), whether the current search must not take it.</summary>
    private readonly List<bool> _extraRejected = [];
    private int _generation;

    /// <summary>The generation of the heuristic values in <see cref="_heuristic"/>: one per request, whose searches all head for the same goal over the same edges (<see cref="NextHeuristics"/>).</summary>
    private int _heuristics;

    // The costs of the current request: a jump's flight time plus these efforts (0 without walking; QuerySettings.JumpCost); walks when allowed.
    private float _effort;
    private float _heightEffort;

    /// <summary>Whether this request walks, its jumps are not turned afterwards and faced ones are preferred (<see cref="QuerySettings.PreferFacedJumps"/>): jumps that do not face their way cost <see cref="UnfacedJumpCost"/> more.</summary>
    private bool _preferFaced;

    /// <summary>Whether this request walks and turns its jumps to face their way afterwards (<see cref="QuerySettings.FaceJumps"/>): a jump the facer could not turn costs <see cref="UnfacedJumpCost"/> more (<see cref="FacingCost"/>).</summary>
    private bool _facing;

    /// <summary>Per roadmap node: whether no turn is physical on it (<see cref="Unturnable"/>), found once.</summary>
    private readonly bool[] _unturnable;
    private bool _walking;
    private IReadOnlySet<int>? _noTakeoffs;
    private IReadOnlySet<int>? _noLandings;

    /// <summary>The ground this request no longer walks over (<see cref="QuerySettings.NoWalkSpots"/>), or <c>null</c>.</summary>
    private WalkBarrier? _barrier;
    private JumpTightener? _tightener;
    private (int From, int To)? _lostWalk;

    /// <summary>An edge of one request only (start or goal off the roadmap): a jump's arc or a walk, with its search cost in seconds.</summary>
    private readonly record struct Extra(int From, int To, float Cost, BallisticArc Arc, Walk? Walk);

    /// <summary>The level's surface costs, or <c>null</c> on a level without any (the plain costs, bit for bit).</summary>
    private readonly SurfaceCosts? _surfaces;

    /// <summary>Per roadmap walk, its cost with the surface costs (NaN until first needed); null without surface costs.</summary>
    private readonly float[]? _walkCosts;

    /// <summary>Per roadmap jump edge, the enter cost of its landing (NaN until first needed); null without surface costs.</summary>
    private readonly float[]? _landingCosts;

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
        _surfaces = SurfaceCosts.Of(scene);
        if (_surfaces is not null)
        {
            _walkCosts = new float[roadmap.Walks.Count];
            _landingCosts = new float[roadmap.Edges.Count];
            Array.Fill(_walkCosts, float.NaN);
            Array.Fill(_landingCosts, float.NaN);
        }

        _reach = new ReachTest(scene.Steering.Limits);
        int count = roadmap.Nodes.Count + 2;
        _cost = new float[count];
        _cameFrom = new (int, int, int)[count];
        _reached = new int[count];
        _closed = new int[count];
        _extraFirst = new int[count];
        _extraLast = new int[count];
        _extraStamp = new int[count];
        _heuristic = new float[count];
        _heuristicStamp = new int[count];
        _rejectedJump = new int[roadmap.OutgoingTargets.Length];
        _rejectedWalk = new int[roadmap.WalkTargets.Length];
        _noTakeoffStamp = new int[count];
        _noLandingStamp = new int[count];
        _unturnable = [.. roadmap.Nodes.Select(Unturnable)];
    }

    /// <summary>The roadmap searched.</summary>
    public Roadmap Roadmap => _roadmap;

    /// <summary>
    /// Prepares the roadmap's moves ahead of time (at a level's load), so that later queries over it recall most of
    /// what they would otherwise work out as they go. Every pair of nodes linked by a roadmap jump or walk is planned
    /// once as a request of its own (node to node, with <paramref name="settings"/>), and what those requests work out
    /// (stances turned to face a jump, the arcs linking them, walks traced) is kept in the scene for good, where its
    /// bounded memory of recent results forgets it once queries over a large roadmap have moved on. What is kept
    /// changes no path, only how soon it comes. Prepare with the settings of the queries to come (tolerance,
    /// locomotion, stance check, jump facing): what is kept is keyed by them. Costs seconds and tens of megabytes on a
    /// 1,000-node roadmap (the README gives figures); the scene keeps the memory while it lives.
    /// </summary>
    /// <param name="settings">The settings of the queries to prepare for; the defaults when <c>null</c>.</param>
    /// <param name="threads">Threads preparing at once, each with a query of its own; 1 prepares on this thread only.</param>
    /// <param name="termination">
    /// Stops the preparation early, polled between pairs (its clock and cancellation parts,
    /// <see cref="TerminationCondition.ShouldStopNow"/>); <c>null</c> for none. What was prepared stays kept.
    /// </param>
    /// <returns>How many node pairs were prepared: every pair linked by a roadmap jump or walk, fewer when stopped early.</returns>
    /// <exception cref="ArgumentException">The settings' jump costs are negative or not finite.</exception>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="threads"/> is below 1.</exception>
    public int Prepare(QuerySettings? settings = null, int threads = 1, TerminationCondition? termination = null)
    {
        settings = Checked(settings);
        ArgumentOutOfRangeException.ThrowIfLessThan(threads, 1);
        List<(int From, int To)> pairs = PairsToPrepare();
        var clock = Stopwatch.StartNew();
        int prepared = 0;

        // Each thread plans with a query of its own (a query is not thread-safe): this one, or one made for a worker.
        var queries = new System.Collections.Concurrent.ConcurrentBag<PathQuery> { this };
        RoadmapBaker.RunParallel(pairs.Count, threads, () => termination?.ShouldStopNow(clock.Elapsed, out _, out _) ?? false, i =>
        {
            PathQuery query = queries.TryTake(out PathQuery? idle) ? idle : new PathQuery(_scene, _roadmap);
            using (KeptResults.Keep())
            {
                query.Plan(_roadmap.Nodes[pairs[i].From], _roadmap.Nodes[pairs[i].To], settings);
            }

            queries.Add(query);
            Interlocked.Increment(ref prepared);
        });
        _scene.TrimKept();
        return prepared;
    }

    /// <summary>The node pairs a roadmap jump or walk links, each once, by takeoff node then landing node.</summary>
    private List<(int From, int To)> PairsToPrepare()
    {
        var pairs = new List<(int From, int To)>();
        var targets = new SortedSet<int>();
        for (int node = 0; node < _roadmap.Nodes.Count; node++)
        {
            targets.Clear();
            foreach (int edge in _roadmap.Outgoing(node))
            {
                targets.Add(_roadmap.EdgeTargets[edge]);
            }

            for (int entry = _roadmap.WalkOffsets[node]; entry < _roadmap.WalkOffsets[node + 1]; entry++)
            {
                targets.Add(_roadmap.WalkTargets[entry]);
            }

            foreach (int target in targets)
            {
                pairs.Add((node, target));
            }
        }

        return pairs;
    }

    /// <summary>A* expansions between two pauses of a search run in steps, where the termination condition is polled (<see cref="PollEvery"/> by default); positive.</summary>
    internal int SliceExpansions
    {
        get => _sliceExpansions;
        init => _sliceExpansions = value > 0 ? value : throw new ArgumentOutOfRangeException(nameof(value), value, "The slice must be positive.");
    }

    /// <summary>The request's settings (the defaults for <c>null</c>), refused with one line when their jump costs are negative or not finite.</summary>
    private static QuerySettings Checked(QuerySettings? settings)
    {
        settings ??= new QuerySettings();
        return settings.EffortProblem() is { } problem ? throw new ArgumentException(problem, nameof(settings)) : settings;
    }

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
    /// <exception cref="ArgumentException">The settings' jump costs are negative or not finite.</exception>
    public PlanResult Plan(Vector3 from, Vector3 to, QuerySettings? settings, IReadOnlySet<(int From, int To)>? rejected, TerminationCondition? termination = null) =>
        Stepwise.Last(PlanSteps(from, to, Checked(settings), rejected, termination));

    /// <summary>
    /// <see cref="Plan(Vector3, Vector3, QuerySettings?, IReadOnlySet{ValueTuple{int, int}}?, TerminationCondition?)"/>
    /// in steps, for a caller that spreads one request over several frames: <c>null</c> at each pause point (after
    /// each placement, each steering call, every <see cref="SliceExpansions"/> A* expansions and each stage of the path's
    /// post-processing), then the result, the same as the whole call gives. The query is the request's until the
    /// steps end or are disposed.
    /// </summary>
    internal IEnumerable<PlanResult?> PlanSteps(Vector3 from, Vector3 to, QuerySettings? settings, IReadOnlySet<(int From, int To)>? rejected, TerminationCondition? termination)
    {
        settings = Checked(settings);
        var clock = Stopwatch.StartNew();
        if (Stopped(termination, clock, null, null) is { } early)
        {
            yield return early;
            yield break;
        }

        EndpointPlacement startPlacement = Locate(from, settings, out RoadmapNode? reused);
        bool startReused = reused is not null;
        if (startPlacement.Pose is not { } startPose)
        {
            yield return Fail(PlannerStatus.InvalidStart, startPlacement.Failure("start", settings.Tolerance)!, null, null, clock) with { StartPlacement = startPlacement };
            yield break;
        }

        int n = _roadmap.Nodes.Count;
        RoadmapNode start = reused ?? Existing(startPose.Pose) ?? new RoadmapNode(n, startPose.Pose, startPose.Cone, startPose.Contacts);
        if (Stopped(termination, clock, start, null) is { } stopped)
        {
            yield return stopped with { StartPlacement = startPlacement };
            yield break;
        }

        yield return null;
        EndpointPlacement goalPlacement = Locate(to, settings, out reused);
        if (goalPlacement.Pose is not { } goalPose)
        {
            yield return Fail(PlannerStatus.InvalidGoal, goalPlacement.Failure("goal", settings.Tolerance)!, start, null, clock) with { StartPlacement = startPlacement, GoalPlacement = goalPlacement };
            yield break;
        }

        RoadmapNode goal = reused ?? Existing(goalPose.Pose) ?? (startPose.Pose == goalPose.Pose ? start : new RoadmapNode(n + 1, goalPose.Pose, goalPose.Cone, goalPose.Contacts));
        _goalPoint = reused is null ? to : null;
        _startPoint = startReused ? null : from;
        yield return null;
        foreach (PlanResult? step in ConnectSteps(start, goal, settings, rejected, termination, clock))
        {
            yield return step is null ? null : step with { StartPlacement = step.StartPlacement ?? startPlacement, GoalPlacement = step.GoalPlacement ?? goalPlacement };
        }
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
    /// <exception cref="ArgumentException">The settings' jump costs are negative or not finite.</exception>
    public PlanResult Plan(RoadmapNode start, Vector3 to, QuerySettings? settings = null, IReadOnlySet<(int From, int To)>? rejected = null, TerminationCondition? termination = null)
    {
        ArgumentNullException.ThrowIfNull(start);
        return Stepwise.Last(PlanSteps(start, to, Checked(settings), rejected, termination));
    }

    /// <summary>
    /// <see cref="Plan(RoadmapNode, Vector3, QuerySettings?, IReadOnlySet{ValueTuple{int, int}}?, TerminationCondition?)"/>
    /// in steps (see <see cref="PlanSteps(Vector3, Vector3, QuerySettings?, IReadOnlySet{ValueTuple{int, int}}?, TerminationCondition?)"/>).
    /// </summary>
    internal IEnumerable<PlanResult?> PlanSteps(RoadmapNode start, Vector3 to, QuerySettings? settings, IReadOnlySet<(int From, int To)>? rejected, TerminationCondition? termination)
    {
        ArgumentNullException.ThrowIfNull(start);
        settings = Checked(settings);
        var clock = Stopwatch.StartNew();
        int n = _roadmap.Nodes.Count;
        RoadmapNode from = Resolve(start, n);
        if (Stopped(termination, clock, from, null) is { } early)
        {
            yield return early;
            yield break;
        }

        EndpointPlacement goalPlacement = Locate(to, settings, out RoadmapNode? reused);
        if (goalPlacement.Pose is not { } goalPose)
        {
            yield return Fail(PlannerStatus.InvalidGoal, goalPlacement.Failure("goal", settings.Tolerance)!, from, null, clock) with { GoalPlacement = goalPlacement };
            yield break;
        }

        RoadmapNode goal = reused ?? Existing(goalPose.Pose) ?? (from.Pose == goalPose.Pose ? from : new RoadmapNode(n + 1, goalPose.Pose, goalPose.Cone, goalPose.Contacts));
        _goalPoint = reused is null ? to : null;
        _startPoint = null;
        yield return null;
        foreach (PlanResult? step in ConnectSteps(from, goal, settings, rejected, termination, clock))
        {
            yield return step is null ? null : step with { GoalPlacement = step.GoalPlacement ?? goalPlacement };
        }
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
    /// <exception cref="ArgumentException">The settings' jump costs are negative or not finite.</exception>
    public PlanResult Plan(RoadmapNode start, RoadmapNode goal, QuerySettings? settings = null, IReadOnlySet<(int From, int To)>? rejected = null, TerminationCondition? termination = null)
    {
        ArgumentNullException.ThrowIfNull(start);
        ArgumentNullException.ThrowIfNull(goal);
        return Stepwise.Last(PlanSteps(start, goal, Checked(settings), rejected, termination));
    }

    /// <summary>
    /// <see cref="Plan(RoadmapNode, RoadmapNode, QuerySettings?, IReadOnlySet{ValueTuple{int, int}}?, TerminationCondition?)"/>
    /// in steps (see <see cref="PlanSteps(Vector3, Vector3, QuerySettings?, IReadOnlySet{ValueTuple{int, int}}?, TerminationCondition?)"/>).
    /// </summary>
    internal IEnumerable<PlanResult?> PlanSteps(RoadmapNode start, RoadmapNode goal, QuerySettings? settings, IReadOnlySet<(int From, int To)>? rejected, TerminationCondition? termination)
    {
        ArgumentNullException.ThrowIfNull(start);
        ArgumentNullException.ThrowIfNull(goal);
        settings = Checked(settings);
        var clock = Stopwatch.StartNew();
        int n = _roadmap.Nodes.Count;
        RoadmapNode from = Resolve(start, n);
        RoadmapNode to = _roadmap.Holds(goal) ? goal
            : _roadmap.FindPose(goal.Pose) is int id ? _roadmap.Node(id)
            : from.Pose == goal.Pose ? from
            : goal.Id == n + 1 ? goal : goal with { Id = n + 1 };
        _goalPoint = null;
        _startPoint = null;
        return ConnectSteps(from, to, settings, rejected, termination, clock);
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
    private IEnumerable<PlanResult?> ConnectSteps(RoadmapNode start, RoadmapNode goal, QuerySettings settings, IReadOnlySet<(int From, int To)>? rejected, TerminationCondition? termination, Stopwatch clock)
    {
        if (Stopped(termination, clock, start, goal) is { } early)
        {
            yield return early;
            yield break;
        }

        if (goal.Id == start.Id)
        {
            yield return new PlanResult(PlannerStatus.Exact, "the start is the goal: no jump needed", start, goal, [], clock.Elapsed);
            yield break;
        }

        // The request's costs: walking allowed when asked and the character walks.
        _walking = settings.Locomotion == Locomotion.WalkAndJump && _scene.Walking.Limits.CanWalk;
        _noTakeoffs = settings.NoTakeoffs;
        _noLandings = settings.NoLandings;
        _barrier = _walking ? WalkBarrier.Of(settings.NoWalkSpots, _scene.Character) : null;
        _effort = _walking ? settings.JumpEffort : 0f;
        _heightEffort = _walking ? settings.JumpHeightEffort : 0f;
        _preferFaced = _walking && !settings.FaceJumps && settings.PreferFacedJumps;
        _facing = _walking && settings.FaceJumps;
        float walkDistance = settings.MaxWalkDistance ?? Planning.BakeSettings.DefaultMaxWalkDistance(_scene.Walking.Limits);

        // Extra edges of the request: start → roadmap, roadmap → goal, start → goal (a roadmap node has its own).
        int n = _roadmap.Nodes.Count;
        _extra.Clear();
        bool startIsNew = start.Id >= n;
        bool goalIsNew = goal.Id >= n;
        ParabolaSteering steering = _scene.Steering;
        if (startIsNew || goalIsNew)
        {
            if (rejected?.Contains((start.Id, goal.Id)) != true)
            {
                if (steering.Steer(start.Pose, start.Cone, goal.Pose, goal.Cone) is { Succeeded: true } direct)
                {
                    _extra.Add(new Extra(start.Id, goal.Id, JumpCost(start, goal, direct.Arc), direct.Arc, null));
                }

                yield return null;

                if (_walking && _scene.Walking.SteerRemembered(start, goal, settings.MaxDirectWalk).Walk is Walk walk && _barrier?.Bars(walk) != true)
                {
                    _extra.Add(new Extra(start.Id, goal.Id, WalkCost(walk), default, walk));
                }
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
                    yield return stopped;
                    yield break;
                }

                RoadmapNode node = _roadmap.Node(j);
                SteeringResult r = steering.Steer(start.Pose, start.Cone, node.Pose, node.Cone);
                yield return null;
                if (r.Succeeded)
                {
                    _extra.Add(new Extra(start.Id, j, JumpCost(start, node, r.Arc), r.Arc, null));
                    if (++connected >= settings.Connections)
                    {
                        break;
                    }
                }
            }

            if (_walking)
            {
                foreach (PlanResult? step in AddWalks(start, goal, walkDistance, settings, rejected, fromNode: true, termination, clock))
                {
                    yield return step;
                    if (step is not null)
                    {
                        yield break;
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
                    yield return stopped;
                    yield break;
                }

                RoadmapNode node = _roadmap.Node(j);
                SteeringResult r = steering.Steer(node.Pose, node.Cone, goal.Pose, goal.Cone);
                yield return null;
                if (r.Succeeded)
                {
                    _extra.Add(new Extra(j, goal.Id, JumpCost(node, goal, r.Arc), r.Arc, null));
                    if (++connected >= settings.Connections)
                    {
                        break;
                    }
                }
            }

            if (_walking)
            {
                foreach (PlanResult? step in AddWalks(goal, start, walkDistance, settings, rejected, fromNode: false, termination, clock))
                {
                    yield return step;
                    if (step is not null)
                    {
                        yield break;
                    }
                }
            }
        }

        _lostWalk = null;
        var search = new Search();
        int heuristics = NextHeuristics();
        foreach (bool _ in AStar(start, goal, rejected, heuristics, termination, clock, search))
        {
            yield return null;
        }

        List<Move>? path = search.Path;
        int expansions = search.Expansions;
        if (search.Cut is { } cut)
        {
            yield return cut with { Expansions = expansions };
            yield break;
        }

        if (_lostWalk is (int lostFrom, int lostTo))
        {
            yield return Fail(PlannerStatus.NoPath, $"the roadmap's walk from node {lostFrom} to node {lostTo} no longer finds its ground on this level: bake the roadmap again", start, goal, clock) with { Expansions = expansions };
            yield break;
        }

        float searched = path is null ? 0f : CostOf(path);
        var finished = new Finished();
        foreach (bool _ in Finish(path, start, goal, settings, rejected, termination, clock, finished))
        {
            yield return null;
        }

        (path, EndpointPlacement? startPlacement, EndpointPlacement? goalPlacement, IReadOnlyList<(int From, int To)> unturned) = (finished.Path, finished.Start, finished.Goal, finished.Unturned);
        if (path is not null && unturned.Count > 0)
        {
            // Jumps the facer could not turn to face their way (the takeoff or landing on ground too steep to turn
            // on, or their turns did not animate): searched again without them, while that costs little more.
            var avoided = new HashSet<(int From, int To)>(rejected ?? (IEnumerable<(int From, int To)>)[]);
            int fewest = unturned.Count;
            for (int again = 0; again < FacingSearches && unturned.Count > 0; again++)
            {
                avoided.UnionWith(unturned);
                _lostWalk = null;
                var research = new Search();
                foreach (bool _ in AStar(start, goal, avoided, heuristics, termination, clock, research))
                {
                    yield return null;
                }

                List<Move>? other = research.Path;
                expansions += research.Expansions;
                if (research.Cut is not null || _lostWalk is not null || other is null || CostOf(other) > FacingDetour * searched)
                {
                    break;
                }

                var refinished = new Finished();
                foreach (bool _ in Finish(other, start, goal, settings, avoided, termination, clock, refinished))
                {
                    yield return null;
                }

                (List<Move>? made, EndpointPlacement? madeStart, EndpointPlacement? madeGoal, IReadOnlyList<(int From, int To)> left) = (refinished.Path, refinished.Start, refinished.Goal, refinished.Unturned);
                if (made is not null && left.Count < fewest)
                {
                    (path, startPlacement, goalPlacement, fewest) = (made, madeStart, madeGoal, left.Count);
                }

                unturned = left;
            }
        }

        if (goalPlacement is not null && path is { Count: > 0 })
        {
            goal = path[^1].To; // placed again facing the last jump (same requested point and tolerance)
        }

        if (startPlacement is not null && path is { Count: > 0 })
        {
            start = path[0].From; // placed again facing the first jump
        }

        string moves = _walking ? "moves (jumps or walks)" : "jumps";
        string holds = _walking ? $"{n} nodes, {_roadmap.Edges.Count} jumps, {_roadmap.Walks.Count} walks" : $"{n} nodes, {_roadmap.Edges.Count} jumps";
        PlanResult result = path is null
            ? Fail(PlannerStatus.NoPath, $"the roadmap ({holds}) holds no sequence of {moves} from the start to the goal" + (rejected is { Count: > 0 } ? $" without the {Moves(rejected.Count)} set aside" : "")
                + NoPathGap.Describe(_scene, _roadmap, start, goal, [.. _extra.Select(e => (e.From, e.To))], _walking, rejected), start, goal, clock)
            : new PlanResult(PlannerStatus.Exact, $"{Describe(path)} found", start, goal, path, clock.Elapsed) { StartPlacement = startPlacement, GoalPlacement = goalPlacement, Cost = CostOf(path) };
        yield return result with { Expansions = expansions };
    }

    /// <summary>
    /// How many times at most a request searches again without the jumps it could not turn to face
    /// (<see cref="JumpFacer.Unturned"/>). Three since 2026-12-06: with two, a Rigify panda crossing the curved terrain
    /// kept a 2.3 m jump taking off 143° off its way that the third search goes round; a warm desert node-to-node
    /// request then expands 104 nodes on average instead of 88 (about a tenth more time).
    /// </summary>
    internal const int FacingSearches = 3;

    /// <summary>A path searched again without unturned jumps is taken only when it costs at most this times the first one searched.</summary>
    internal const float FacingDetour = 1.5f;

    /// <summary>
    /// The searched <paramref name="path"/> made ready to perform: shortcut, jumps cut down to walks, hops over
    /// ground the body could not walk, jumps turned to face their way (as <paramref name="settings"/> ask), walks
    /// joined; with the start and goal placements made for facing and the jumps left unturned.
    /// </summary>
    private IEnumerable<bool> Finish(List<Move>? path, RoadmapNode start, RoadmapNode goal, QuerySettings settings, IReadOnlySet<(int From, int To)>? rejected, TerminationCondition? termination, Stopwatch clock, Finished finished)
    {
        int nextId = _roadmap.Nodes.Count + 2;
        EndpointPlacement? startPlacement = null;
        EndpointPlacement? goalPlacement = null;
        IReadOnlyList<(int From, int To)> unturned = [];
        if (path is not null && _walking)
        {
            if (settings.Shortcut)
            {
                path = Shortcut(path, settings, rejected);
                yield return true;
            }

            if (settings.TightenJumps)
            {
                _tightener ??= new JumpTightener(_scene);
                _tightener.Barrier = _barrier;
                path = _tightener.Tighten(path, ref nextId, settings.MinCutWalk, rejected, settings.UncutJumps, settings.CanStand, () => Stopped(termination, clock, start, goal) is not null);
                yield return true;
                path = Shortcut(path, settings, rejected, walksOnly: true);
                yield return true;
            }

            if (settings.HopSpots is { Count: > 0 } spots)
            {
                _tightener ??= new JumpTightener(_scene);
                _tightener.Barrier = _barrier;
                path = _tightener.Hop(path, spots, ref nextId, 0.5f * settings.MinCutWalk, rejected, settings.CanStand, () => Stopped(termination, clock, start, goal) is not null);
                yield return true;
            }

            if (settings.FaceJumps)
            {
                path = Face(path, walking: true, ref nextId, start, goal, settings, rejected, termination, clock, out startPlacement, out goalPlacement, out unturned);
                yield return true;
            }

            path = JoinWalks(path, _scene.Walking);
        }
        else if (path is not null && settings.FaceJumps)
        {
            path = Face(path, walking: false, ref nextId, start, goal, settings, rejected, termination, clock, out startPlacement, out goalPlacement, out unturned);
            yield return true;
        }

        (finished.Path, finished.Start, finished.Goal, finished.Unturned) = (path, startPlacement, goalPlacement, unturned);
    }

    /// <summary>What <see cref="Finish"/> made of a searched path: the path ready to perform (<c>null</c> when none was found), the start and goal placed again for facing, the jumps left unturned.</summary>
    private sealed class Finished
    {
        public List<Move>? Path;
        public EndpointPlacement? Start;
        public EndpointPlacement? Goal;
        public IReadOnlyList<(int From, int To)> Unturned = [];
    }

    /// <summary>
    /// The path's jumps turned to face their way (<see cref="JumpFacer"/>). A start (goal) this request placed at a
    /// point (not a stance it was given or a roadmap node preferred; the bake's node of that very placement included)
    /// may be placed again at that point, within the same tolerance, facing the first (last) jump, as id n (n + 1):
    /// <paramref name="startPlacement"/> (<paramref name="goalPlacement"/>) is then that placement, otherwise <c>null</c>.
    /// </summary>
    private List<Move> Face(List<Move> path, bool walking, ref int nextId, RoadmapNode start, RoadmapNode goal, QuerySettings settings, IReadOnlySet<(int From, int To)>? rejected, TerminationCondition? termination, Stopwatch clock, out EndpointPlacement? startPlacement, out EndpointPlacement? goalPlacement, out IReadOnlyList<(int From, int To)> unturned)
    {
        int n = _roadmap.Nodes.Count;
        var startEnd = new PlacedEnd(this, _startPoint is Vector3 from && start.Id <= n ? from : null, start, n, settings);
        var goalEnd = new PlacedEnd(this, _goalPoint is Vector3 to && (goal.Id == n + 1 || goal.Id < n) ? to : null, goal, n + 1, settings);
        var facer = new JumpFacer(_scene, walking, settings.CanStand, settings.RefusedTurns, settings.CanPush, _barrier);
        List<Move> faced = facer.Face(path, ref nextId, rejected, settings.UncutJumps, settings.UnfacedJumps, startEnd.Place, goalEnd.Place, () => Stopped(termination, clock, null, null) is not null);
        unturned = [.. facer.Unturned];
        startPlacement = faced.Count > 0 ? startEnd.PlacementOf(faced[0].From) : null;
        goalPlacement = faced.Count > 0 ? goalEnd.PlacementOf(faced[^1].To) : null;
        return faced;
    }

    /// <summary>A start or goal that may be placed again at its requested point, facing a jump (<see cref="Face"/>).</summary>
    private sealed class PlacedEnd(PathQuery query, Vector3? point, RoadmapNode old, int id, QuerySettings settings)
    {
        /// <summary>Every stance placed, with its placement: the path keeps at most one of them.</summary>
        private readonly List<(RoadmapNode Node, EndpointPlacement Placement)> _placed = [];

        /// <summary>Places the end again facing the yaw (radians about +Y) within one of the offsets (radians), or <c>null</c> (none placed, or it must stay: then <see cref="Place"/> itself is <c>null</c>).</summary>
        public Func<float, float[], RoadmapNode?>? Place => point is Vector3 p ? (facing, yaws) => PlaceAt(p, facing, yaws) : null;

        /// <summary>The placement of <paramref name="node"/> when it is the end placed again, otherwise <c>null</c>.</summary>
        public EndpointPlacement? PlacementOf(RoadmapNode node) => _placed.Find(p => ReferenceEquals(p.Node, node)).Placement;

        private RoadmapNode? PlaceAt(Vector3 p, float facing, float[] yaws)
        {
            EndpointPlacement placed = query._scene.Sampler.PlaceFacingWithin(p, settings.Tolerance, facing, yaws, settings.CanStand, JumpFacer.Height(query._scene.Sampler, old));
            if (placed.Pose is not { } pose)
            {
                return null;
            }

            var node = new RoadmapNode(id, pose.Pose, pose.Cone, pose.Contacts);
            _placed.Add((node, placed));
            return node;
        }
    }

    /// <summary>
    /// A* over the roadmap plus the request's extra edges. Cost: time, a jump's flight time plus the request's jump
    /// effort (none in jump-only mode), a walk's duration. Heuristic: in jump-only mode the larger of two lower bounds
    /// on the remaining flight time, so the path found is of least total flight time: the horizontal distance to the
    /// goal divided by the fastest horizontal speed of any jump (every jump covers its horizontal distance at most
    /// that fast), and the roadmap's landmark bounds (<see cref="Landmarks"/>; for a goal off the roadmap, through the
    /// nodes jumping to it), which also prune nodes that cannot reach the goal. With walking, the distance bound alone,
    /// over the faster of the fastest jump and the walking speed (landmarks know jumps only).
    /// </summary>
    /// <remarks>
    /// In steps: a pause (<c>true</c>) every <see cref="SliceExpansions"/> expansions, where the termination condition is
    /// polled; the search's state stays in this query's scratch between them, so a search in steps expands the same
    /// nodes in the same order as one run whole. Its outcome goes in <paramref name="search"/>.
    /// </remarks>
    private IEnumerable<bool> AStar(RoadmapNode start, RoadmapNode goal, IReadOnlySet<(int From, int To)>? rejected, int heuristics, TerminationCondition? termination, Stopwatch clock, Search search)
    {
        int generation = NextGeneration();
        float fastest = _roadmap.MaxHorizontalSpeed;
        if (_walking)
        {
            fastest = MathF.Max(fastest, _scene.Walking.Limits.Speed);
        }

        int roadmapCount = _roadmap.Nodes.Count;
        Reject(rejected, generation);
        Bar(generation);
        Stamp(_noTakeoffs, _noTakeoffStamp, generation);
        Stamp(_noLandings, _noLandingStamp, generation);
        _extraNext.Clear();
        _extraRejected.Clear();
        _goalEntries.Clear();
        for (int e = 0; e < _extra.Count; e++)
        {
            Extra extra = _extra[e];
            _extraNext.Add(-1);
            _extraRejected.Add(rejected?.Contains((extra.From, extra.To)) == true);
            if (_extraStamp[extra.From] != generation)
            {
                _extraStamp[extra.From] = generation;
                _extraFirst[extra.From] = e;
            }
            else
            {
                _extraNext[_extraLast[extra.From]] = e;
            }

            _extraLast[extra.From] = e;
            if (extra.Walk is null)
            {
                fastest = MathF.Max(fastest, extra.Arc.HorizontalSpeed);
                if (extra.To == goal.Id && extra.From < roadmapCount)
                {
                    _goalEntries.Add((extra.From, extra.Arc.FlightTime));
                }
            }
        }

        float inverseSpeed = fastest > 0f ? 1f / fastest : 0f;
        _open.Clear();
        _cost[start.Id] = 0f;
        _reached[start.Id] = generation;
        _open.Enqueue(start.Id, 0f);
        int paused = -1;
        while (Expand(start, goal, generation, heuristics, inverseSpeed, ref paused, search))
        {
            if (Stopped(termination, clock, start, goal) is { } stopped)
            {
                search.Cut = stopped;
                yield break;
            }

            yield return true;
        }
    }

    /// <summary>
    /// Marks the node ids of <paramref name="nodes"/> in <paramref name="stamps"/> with <paramref name="generation"/>;
    /// ids outside the search's range (no node the search relaxes has them) are skipped.
    /// </summary>
    private static void Stamp(IReadOnlySet<int>? nodes, int[] stamps, int generation)
    {
        if (nodes is null)
        {
            return;
        }

        foreach (int node in nodes)
        {
            if (node >= 0 && node < stamps.Length)
            {
                stamps[node] = generation;
            }
        }
    }

    /// <summary>
    /// Marks the roadmap's jump and walk slots between the pairs of <paramref name="rejected"/> as not to be taken by
    /// the search of <paramref name="generation"/>: a lookup per slot instead of one in the set per relaxed edge.
    /// </summary>
    private void Reject(IReadOnlySet<(int From, int To)>? rejected, int generation)
    {
        if (rejected is null)
        {
            return;
        }

        ReadOnlySpan<int> offsets = _roadmap.OutgoingOffsets;
        ReadOnlySpan<int> targets = _roadmap.OutgoingTargets;
        ReadOnlySpan<int> walkOffsets = _roadmap.WalkOffsets;
        ReadOnlySpan<int> walkTargets = _roadmap.WalkTargets;
        int roadmapCount = _roadmap.Nodes.Count;
        foreach ((int from, int to) in rejected)
        {
            if (from < 0 || from >= roadmapCount)
            {
                continue;
            }

            for (int i = offsets[from], end = offsets[from + 1]; i < end; i++)
            {
                if (targets[i] == to)
                {
                    _rejectedJump[i] = generation;
                }
            }

            for (int i = walkOffsets[from], end = walkOffsets[from + 1]; i < end; i++)
            {
                if (walkTargets[i] == to)
                {
                    _rejectedWalk[i] = generation;
                }
            }
        }
    }

    /// <summary>
    /// Marks the roadmap's walk slots whose ground path passes the request's <see cref="_barrier"/> as not to be taken
    /// by the search of <paramref name="generation"/>. A walk runs straight, seen from above, between its stances'
    /// contact centres (<see cref="WalkSteering"/>), so the segment between them is its path's trace.
    /// </summary>
    private void Bar(int generation)
    {
        if (_barrier is not { } barrier)
        {
            return;
        }

        ReadOnlySpan<int> walkOffsets = _roadmap.WalkOffsets;
        ReadOnlySpan<int> walkTargets = _roadmap.WalkTargets;
        for (int from = 0; from < _roadmap.Nodes.Count; from++)
        {
            Vector3 a = _roadmap.Nodes[from].ContactCentre;
            for (int i = walkOffsets[from], end = walkOffsets[from + 1]; i < end; i++)
            {
                if (barrier.Bars(a, _roadmap.Nodes[walkTargets[i]].ContactCentre))
                {
                    _rejectedWalk[i] = generation;
                }
            }
        }
    }

    /// <summary>What <see cref="AStar"/> found: the path (<c>null</c> for none, or when stopped), the nodes expanded, the failure it was stopped with.</summary>
    private sealed class Search
    {
        public List<Move>? Path;
        public int Expansions;
        public PlanResult? Cut;
    }

    /// <summary>
    /// Expands <see cref="AStar"/>'s open nodes, first the one it paused before (<paramref name="paused"/>, or -1),
    /// until the goal is reached or the open list empties (false: <paramref name="search"/> holds the outcome), or until
    /// the next node would be the <see cref="SliceExpansions"/>-th expanded since the last pause (true, that node in
    /// <paramref name="paused"/>).
    /// </summary>
    private bool Expand(RoadmapNode start, RoadmapNode goal, int generation, int heuristics, float inverseSpeed, ref int paused, Search search)
    {
        var heuristic = new Heuristic(this, goal, inverseSpeed, heuristics, landmarks: !_walking);
        ReadOnlySpan<int> offsets = _roadmap.OutgoingOffsets;
        ReadOnlySpan<int> targets = _roadmap.OutgoingTargets;
        ReadOnlySpan<float> times = _roadmap.OutgoingFlightTimes;
        ReadOnlySpan<float> heights = _roadmap.OutgoingEnergyHeights;
        ReadOnlySpan<int> edges = _roadmap.OutgoingEdges;
        ReadOnlySpan<int> walkOffsets = _roadmap.WalkOffsets;
        ReadOnlySpan<int> walkTargets = _roadmap.WalkTargets;
        ReadOnlySpan<float> walkTimes = _roadmap.WalkDurations;
        ReadOnlySpan<int> walkEntries = _roadmap.WalkEntries;
        int roadmapCount = _roadmap.Nodes.Count;
        bool walks = _walking && _roadmap.Walks.Count > 0;
        float effort = _effort;
        float heightEffort = _heightEffort;
        bool preferFaced = _preferFaced;
        bool facing = _facing;
        bool[] unturnable = _unturnable;
        bool surfaces = _surfaces is not null;
        float[] cost = _cost;
        int[] reached = _reached;
        int[] closed = _closed;
        PriorityQueue<int, float> open = _open;
        int[] rejectedJump = _rejectedJump;
        int[] rejectedWalk = _rejectedWalk;
        int[] noTakeoff = _noTakeoffStamp;
        int[] noLanding = _noLandingStamp;
        int node = paused;
        paused = -1;
        while (true)
        {
            if (node < 0)
            {
                if (!open.TryDequeue(out node, out _))
                {
                    return false;
                }

                if (closed[node] == generation)
                {
                    node = -1;
                    continue;
                }

                closed[node] = generation;
                if (node == goal.Id)
                {
                    search.Expansions++;
                    search.Path = Reconstruct(start, goal);
                    return false;
                }

                if (++search.Expansions % _sliceExpansions == 0)
                {
                    paused = node;
                    return true;
                }
            }

            float here = cost[node];
            if (node < roadmapCount)
            {
                for (int i = offsets[node], end = offsets[node + 1]; i < end; i++)
                {
                    if (rejectedJump[i] == generation)
                    {
                        continue;
                    }

                    Relax(node, targets[i], here + times[i] + effort + (heightEffort * heights[i]) + (preferFaced || (facing && (unturnable[node] || unturnable[targets[i]])) ? FacingCost(edges[i]) : 0f) + (surfaces ? LandingCost(edges[i]) : 0f), edges[i], FromJump, ref heuristic);
                }

                if (walks)
                {
                    for (int i = walkOffsets[node], end = walkOffsets[node + 1]; i < end; i++)
                    {
                        if (rejectedWalk[i] == generation)
                        {
                            continue;
                        }

                        Relax(node, walkTargets[i], here + (surfaces ? RoadmapWalkCost(walkEntries[i]) : walkTimes[i]), walkEntries[i], FromWalk, ref heuristic);
                    }
                }
            }

            if (_extraStamp[node] == generation)
            {
                for (int e = _extraFirst[node]; e >= 0; e = _extraNext[e])
                {
                    if (_extraRejected[e])
                    {
                        continue;
                    }

                    Relax(node, _extra[e].To, here + _extra[e].Cost, e, FromExtra, ref heuristic);
                }
            }

            node = -1;
        }

        void Relax(int node, int next, float candidate, int edge, int kind, ref Heuristic h)
        {
            if (closed[next] != generation && (reached[next] != generation || candidate < cost[next])
                && (kind == FromWalk || (kind == FromExtra && _extra[edge].Walk is not null) || (noTakeoff[node] != generation && noLanding[next] != generation)))
            {
                float bound = h.At(next);
                if (bound < float.PositiveInfinity)
                {
                    cost[next] = candidate;
                    reached[next] = generation;
                    _cameFrom[next] = (node, edge, kind);
                    open.Enqueue(next, candidate + bound);
                }
            }
        }
    }

    /// <summary>Kinds of the edge a node was reached by (<see cref="_cameFrom"/>).</summary>
    private const int FromJump = 0;
    private const int FromWalk = 1;
    private const int FromExtra = 2;

    /// <summary>The A* heuristic of one request's searches, each node's value computed once (seconds; +∞: cannot reach the goal).</summary>
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

        public Heuristic(PathQuery query, RoadmapNode goal, float inverseSpeed, int generation, bool landmarks)
        {
            _query = query;
            _goal = goal.Id;
            _target = new Vector2(goal.Pose.Position.X, goal.Pose.Position.Z);
            _inverseSpeed = inverseSpeed;
            _generation = generation;
            _landmarks = landmarks ? query._roadmap.Landmarks : Landmarks.None;
            _goalOnRoadmap = goal.Id < query._roadmap.Nodes.Count;
            _goalFrom = _goalOnRoadmap && _landmarks.Count > 0 ? _landmarks.From(goal.Id) : [];
            _goalTo = _goalOnRoadmap && _landmarks.Count > 0 ? _landmarks.To(goal.Id) : [];
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
            Array.Clear(_rejectedJump);
            Array.Clear(_rejectedWalk);
            Array.Clear(_noTakeoffStamp);
            Array.Clear(_noLandingStamp);
            _generation = 0;
        }

        return ++_generation;
    }

    /// <summary>
    /// A fresh generation of heuristic values, for a request's searches: the first and those after facing (which set
    /// jumps aside but keep the goal, the request's edges and so every bound) share each node's value.
    /// </summary>
    private int NextHeuristics()
    {
        if (_heuristics == int.MaxValue)
        {
            Array.Clear(_heuristicStamp);
            _heuristics = 0;
        }

        return ++_heuristics;
    }

    /// <summary>The moves from the start to the goal by the search's back-pointers; <c>null</c> (with <see cref="_lostWalk"/> set) when a roadmap walk no longer traces.</summary>
    private List<Move>? Reconstruct(RoadmapNode start, RoadmapNode goal)
    {
        RoadmapNode NodeAt(int id) => id == start.Id ? start : id == goal.Id ? goal : _roadmap.Node(id);
        var moves = new List<Move>();
        for (int node = goal.Id; node != start.Id; node = _cameFrom[node].Node)
        {
            (int fromId, int edge, int kind) = _cameFrom[node];
            RoadmapNode from = NodeAt(fromId);
            RoadmapNode to = NodeAt(node);
            switch (kind)
            {
                case FromJump:
                    moves.Add(new Jump(from, to, _roadmap.Edge(edge).Arc));
                    break;
                case FromWalk:
                    // The roadmap keeps a walk's length; its ground path is traced again, exactly as the bake did.
                    if (_scene.Walking.SteerRemembered(from, to).Walk is not Walk walk)
                    {
                        _lostWalk = (fromId, node);
                        return null;
                    }

                    moves.Add(walk);
                    break;
                default:
                    Extra extra = _extra[edge];
                    moves.Add(extra.Walk is Walk w ? w : new Jump(from, to, extra.Arc));
                    break;
            }
        }

        moves.Reverse();
        return moves;
    }

    /// <summary>
    /// Links <paramref name="stance"/> (the start, <paramref name="fromNode"/> true, or the goal) by walks to (from)
    /// its nearest roadmap nodes within <paramref name="distance"/> metres, as the bake links nodes; in steps: <c>null</c>
    /// after each steering call, or the failure <paramref name="termination"/> stops the request with.
    /// </summary>
    private IEnumerable<PlanResult?> AddWalks(RoadmapNode stance, RoadmapNode other, float distance, QuerySettings settings, IReadOnlySet<(int From, int To)>? rejected, bool fromNode, TerminationCondition? termination, Stopwatch clock)
    {
        _roadmap.NearestWithin(stance.Pose.Position, distance, settings.MaxNeighbours, _nearest);
        int connected = 0;
        foreach ((_, int j) in _nearest)
        {
            (int a, int b) = fromNode ? (stance.Id, j) : (j, stance.Id);
            if (rejected?.Contains((a, b)) == true)
            {
                continue;
            }

            if (Stopped(termination, clock, fromNode ? stance : other, fromNode ? other : stance) is { } stopped)
            {
                yield return stopped;
                yield break;
            }

            RoadmapNode node = _roadmap.Node(j);
            Walk? steered = (fromNode ? _scene.Walking.SteerRemembered(stance, node, distance) : _scene.Walking.SteerRemembered(node, stance, distance)).Walk;
            yield return null;
            if (steered is Walk walk && _barrier?.Bars(walk) != true)
            {
                _extra.Add(new Extra(a, b, WalkCost(walk), default, walk));
                if (++connected >= settings.Connections * 2)
                {
                    break;
                }
            }
        }

    }

    /// <summary>A move's cost in the search, seconds: a walk's length over its speed, a jump's flight time plus the effort.</summary>
    /// <summary>What <paramref name="path"/> costs in this search, seconds (<see cref="CostOf(Move)"/> of each move).</summary>
    private float CostOf(List<Move> path)
    {
        float cost = 0f;
        foreach (Move move in path)
        {
            cost += CostOf(move);
        }

        return cost;
    }

    private float CostOf(Move move) => move is Jump jump ? JumpCost(jump.From, jump.To, jump.Arc) : WalkCost((Walk)move);

    /// <summary>A jump's cost in this search, seconds: its flight time, plus (walking allowed) the efforts of <see cref="QuerySettings.JumpCost(in BallisticArc, float, float)"/>.</summary>
    private float JumpCost(in BallisticArc arc) => QuerySettings.JumpCost(arc, _effort, _heightEffort);

    /// <summary><see cref="JumpCost(in BallisticArc)"/> of a jump from <paramref name="from"/> to <paramref name="to"/>, plus <see cref="UnfacedJumpCost"/> when it does not face its way and will not be turned to.</summary>
    private float JumpCost(RoadmapNode from, RoadmapNode to, in BallisticArc arc) =>
        JumpCost(arc) + (_preferFaced && !JumpFacer.Faces(from, to, arc) ? UnfacedJumpCost : 0f) + (_surfaces?.Jump(from, to) ?? 0f);

    /// <summary>The enter cost of roadmap edge <paramref name="edge"/>'s landing surface (<see cref="SurfaceCosts.Jump"/>), computed once per query object.</summary>
    private float LandingCost(int edge)
    {
        float known = _landingCosts![edge];
        if (float.IsNaN(known))
        {
            RoadmapEdge e = _roadmap.Edges[edge];
            known = _landingCosts[edge] = _surfaces!.Jump(_roadmap.Nodes[e.From], _roadmap.Nodes[e.To]);
        }

        return known;
    }

    /// <summary>
    /// Roadmap walk <paramref name="walk"/>'s cost with the surface costs (<see cref="SurfaceCosts.Walk"/>), computed
    /// once per query object: its duration, over the ground straight between its stances' contact centres.
    /// </summary>
    private float RoadmapWalkCost(int walk)
    {
        float known = _walkCosts![walk];
        if (float.IsNaN(known))
        {
            RoadmapWalk w = _roadmap.Walk(walk);
            RoadmapNode from = _roadmap.Nodes[w.From];
            known = _walkCosts[walk] = _surfaces!.Walk([from.ContactCentre, _roadmap.Nodes[w.To].ContactCentre], w.Duration, _surfaces.MaterialOf(from));
        }

        return known;
    }

    /// <summary>
    /// What roadmap edge <paramref name="edge"/> costs on top of its effort when it does not face its way
    /// (<see cref="UnfacedJumpCost"/>): in a search whose jumps are not turned afterwards, and in one whose jumps are
    /// turned for an edge taking off from or landing on a stance where no turn is physical (<see cref="Unturnable"/>),
    /// since the facer cannot turn it there either (a Rigify panda crossing the curved terrain landed on a dune face
    /// tilted 33°, its friction cone 26.6° wide, and took off from it 173° off its way: no turn walk there, and no hop,
    /// in place or 0.15–0.3 m any way, within the cones).
    /// </summary>
    private float FacingCost(int edge)
    {
        RoadmapEdge e = _roadmap.Edges[edge];
        return JumpFacer.Faces(_roadmap.Nodes[e.From], _roadmap.Nodes[e.To], e.Arc) ? 0f : UnfacedJumpCost;
    }

    /// <summary>
    /// Whether no turn is physical on <paramref name="node"/>: its friction cone's axis tilts further from vertical than
    /// the cone is wide (a hop in place, straight up, would slip) and than the character walks (no turn walk).
    /// </summary>
    private bool Unturnable(RoadmapNode node)
    {
        float tilt = MathF.Acos(Math.Clamp(Vector3.Normalize(node.Cone.Axis).Y, -1f, 1f));
        return tilt > node.Cone.HalfAngle && tilt > _scene.Walking.Limits.MaxSlopeDegrees * MathF.PI / 180f;
    }

    /// <summary>
    /// Seconds a jump travelling <see cref="JumpFacer.MinDistance"/> or more across costs on top of its effort when its
    /// stances do not face its way (<see cref="JumpFacer.Faces"/>) in a walking request whose jumps are not turned
    /// afterwards (the repair's last rounds, once turned jumps failed to animate: <see cref="QuerySettings.PreferFacedJumps"/>):
    /// such a search prefers the roadmap's jumps that already face their way wherever one costs at most
    /// this much more, so a character is not flown sideways or backwards where it need not be.
    /// </summary>
    internal const float UnfacedJumpCost = 8f;

    /// <summary>
    /// A walk's cost in the search: its length over its speed (the roadmap's walk durations), seconds, with the surface
    /// costs of the ground along its path; turning in place and speeding up are not counted.
    /// </summary>
    private float WalkCost(Walk walk) =>
        _surfaces is null ? walk.Length / walk.Speed : _surfaces.Walk(walk.Path, walk.Length / walk.Speed, _surfaces.MaterialOf(walk.From));

    /// <summary>
    /// Shortcutting: from each pose of the path, the farthest later pose reached by one direct walk, or failing that
    /// (two or more moves on) one direct jump, that takes less time than the moves it replaces (jump effort included)
    /// replaces them; a jump to the next pose may become a walk longer than the roadmap's walk edges. Greedy from the
    /// start; never uses a move set aside. With <paramref name="walksOnly"/>, stretches are replaced by a direct walk
    /// only, never a jump (after <see cref="JumpTightener"/>, whose walks a direct jump would undo; a cut jump whose
    /// ends turn out to be walkable, or walks in a row, become one walk).
    /// </summary>
    private List<Move> Shortcut(List<Move> path, QuerySettings settings, IReadOnlySet<(int From, int To)>? rejected, bool walksOnly = false)
    {
        if (path.Count < 2)
        {
            return path;
        }

        var poses = new List<RoadmapNode> { path[0].From };
        poses.AddRange(path.Select(m => m.To));
        var costs = new float[path.Count + 1];
        for (int k = 0; k < path.Count; k++)
        {
            costs[k + 1] = costs[k] + CostOf(path[k]);
        }

        var result = new List<Move>();
        int i = 0;
        while (i < path.Count)
        {
            Move? best = null;
            int bestEnd = i + 1;
            for (int j = path.Count; j >= i + 1 && best is null; j--)
            {
                // One move on: only a jump, replaced by a walk between the same stances (longer than a walk edge).
                RoadmapNode a = poses[i];
                RoadmapNode b = poses[j];
                if (a.Id == b.Id || rejected?.Contains((a.Id, b.Id)) == true || (j == i + 1 && path[i] is not Jump))
                {
                    continue;
                }

                float saving = costs[j] - costs[i] - 1e-3f;
                if (_scene.Walking.SteerRemembered(a, b, settings.MaxDirectWalk).Walk is Walk walk && WalkCost(walk) < saving && _barrier?.Bars(walk) != true)
                {
                    best = walksOnly ? walk with { CutFrom = CutFrom(path, i, j) } : walk;
                }
                else if (!walksOnly && j >= i + 2 && _reach.InReach(a.Pose.Position, b.Pose.Position) &&
                    _scene.Steering.SteerRemembered(a.Pose, a.Cone, b.Pose, b.Cone) is { Succeeded: true } jump && JumpCost(a, b, jump.Arc) < saving)
                {
                    best = new Jump(a, b, jump.Arc);
                }

                if (best is not null)
                {
                    bestEnd = j;
                }
            }

            result.Add(best ?? path[i]);
            i = bestEnd;
        }

        return result;
    }

    /// <summary>The jumps the moves from index <paramref name="from"/> up to (not including) <paramref name="to"/> were cut from, each once.</summary>
    private static IReadOnlyList<(int From, int To)> CutFrom(List<Move> path, int from, int to)
    {
        var cut = new List<(int From, int To)>();
        for (int k = from; k < to; k++)
        {
            foreach ((int, int) jump in path[k].CutFrom)
            {
                if (!cut.Contains(jump))
                {
                    cut.Add(jump);
                }
            }
        }

        return cut.Count == 0 ? [] : cut;
    }

    /// <summary>Sharpest corner (degrees) at which two walks are joined into one walked without stopping.</summary>
    private const float MaxJoinTurnDegrees = 30f;

    /// <summary>
    /// Joins consecutive walks into one walk through the stances between them (the character does not stop there)
    /// when the trunk stays clear along the joined walk (its trunk follows the joined path, not each part's) and the
    /// path turns by at most <see cref="MaxJoinTurnDegrees"/> there (a sharper corner is walked as two walks: the
    /// character stops and turns in place, which the legs can follow).
    /// </summary>
    private static List<Move> JoinWalks(List<Move> path, WalkSteering walking)
    {
        float cos = MathF.Cos(MaxJoinTurnDegrees * MathF.PI / 180f);
        var result = new List<Move>();
        foreach (Move move in path)
        {
            if (move is Walk next && result.Count > 0 && result[^1] is Walk previous &&
                Vector3.Dot(previous.HeadingAt(previous.Length), next.HeadingAt(0f)) >= cos &&
                Joined(previous, next) is Walk joined && walking.TrunkIsFree(joined))
            {
                result[^1] = joined;
            }
            else
            {
                result.Add(move);
            }
        }

        return result;
    }

    private static Walk Joined(Walk first, Walk second)
    {
        var points = new List<Vector3>(first.Path);
        int skip = points[^1] == second.Path[0] ? 1 : 0;
        points.AddRange(second.Path.Skip(skip));
        float[]? cross = first.CrossGrades.Count > 0 && second.CrossGrades.Count > 0 ? [.. first.CrossGrades, .. second.CrossGrades.Skip(skip)] : null;
        return new Walk(first.From, second.To, points, first.Speed, [.. first.Via, first.To, .. second.Via], first.TurnRate, first.MaxGrade, first.PitchSpan, cross)
        {
            CutFrom = CutFrom([first, second], 0, 2),
            HoppedFrom = first.HoppedFrom.Count == 0 ? second.HoppedFrom : [.. first.HoppedFrom.Union(second.HoppedFrom)],
        };
    }

    /// <summary>"3 jumps", "2 walks and 1 jump".</summary>
    private static string Describe(IReadOnlyList<Move> path)
    {
        int walks = path.Count(m => m is Walk);
        int jumps = path.Count - walks;
        return walks == 0 ? JumpRepair.Jumps(jumps)
            : jumps == 0 ? Plural(walks, "walk")
            : $"{Plural(walks, "walk")} and {JumpRepair.Jumps(jumps)}";
    }

    /// <summary>"1 move", "3 moves".</summary>
    private static string Moves(int count) => Plural(count, "move");

    private static string Plural(int count, string noun) => count == 1 ? $"1 {noun}" : $"{count} {noun}s";

    /// <summary>The requested goal point of the request being planned, when its goal was placed there (not a roadmap node given or preferred).</summary>
    private Vector3? _goalPoint;

    /// <summary>The requested start point of the request being planned, when its start was placed there (not a stance given or a roadmap node preferred).</summary>
    private Vector3? _startPoint;

    /// <summary>The failure to return when <paramref name="termination"/> says to stop now, otherwise <c>null</c>.</summary>
    private static PlanResult? Stopped(TerminationCondition? termination, Stopwatch clock, RoadmapNode? start, RoadmapNode? goal) =>
        termination is not null && termination.ShouldStopNow(clock.Elapsed, out PlannerStatus status, out string reason)
            ? Fail(status, reason, start, goal, clock)
            : null;

    private static PlanResult Fail(PlannerStatus status, string reason, RoadmapNode? start, RoadmapNode? goal, Stopwatch clock) =>
        new(status, reason, start, goal, [], clock.Elapsed);
}
