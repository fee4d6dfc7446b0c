using System.Diagnostics;
using System.Numerics;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;
using Ballistic.Planner.Steering;
using Ballistic.Planner.Walking;

namespace Ballistic.Planner.Planning;

/// <summary>
/// Bakes a roadmap (Algorithm 1 of the paper): rounds of valid root samples, each new node steered to and from its
/// nearest neighbours within jump reach, until a termination condition holds.
/// </summary>
/// <remarks>
/// Deterministic whatever the thread count: sample k draws from its own random stream (seed, k); nodes enter the
/// roadmap in sample order; every pair's jumps are computed in parallel but inserted in pair order. A round cut
/// short by the time budget or cancellation is discarded whole, so the roadmap is always a prefix of rounds. Each
/// new node's neighbour candidates come from a spatial index of the nodes (<see cref="NodeIndex"/>): the same set,
/// in the same (distance, id) order, as a scan over every node would give.
/// </remarks>
public sealed class RoadmapBaker
{
    /// <summary>Rounds in a row without a single valid sample after which the bake gives up.</summary>
    public const int MaxEmptyRounds = 8;

    private readonly PlanningScene _scene;

    /// <summary>Creates a baker for a scene.</summary>
    public RoadmapBaker(PlanningScene scene)
    {
        ArgumentNullException.ThrowIfNull(scene);
        _scene = scene;
    }

    /// <summary>Bakes a roadmap.</summary>
    /// <param name="settings">Seed, limits and optional start and goal.</param>
    /// <param name="termination">
    /// An extra termination condition (cancellation: <see cref="TerminationCondition.Cancellation"/>; a time budget;
    /// any predicate), combined with those of <paramref name="settings"/> and checking first. Its time and
    /// cancellation parts are also polled between work items, so that a round is cut short as soon as they hold.
    /// </param>
    /// <param name="progress">Receives the state after every round.</param>
    /// <exception cref="ArgumentException">The settings are invalid or nothing would ever stop the bake.</exception>
    public BakeResult Bake(BakeSettings settings, TerminationCondition? termination = null, IProgress<BakeState>? progress = null)
    {
        ArgumentNullException.ThrowIfNull(settings);
        settings.Validate();
        TerminationCondition stop = BuildTermination(settings, termination);
        var clock = Stopwatch.StartNew();
        var roadmap = new RoadmapBuilder(_scene.Level.Fingerprint, _scene.Character.Fingerprint, _scene.Character.Name, settings.Seed);
        var index = new NodeIndex(NodeIndex.CellSizeFor(_scene.Steering.Limits));
        var reach = new ReachTest(_scene.Steering.Limits);
        var counters = new Counters();

        // Work is cut short between items when the clock or cancellation says so; the start and goal only by cancellation.
        (PlannerStatus Status, string Reason)? cut = null;
        var gate = new object();
        bool StopNow()
        {
            if (stop.ShouldStopNow(clock.Elapsed, out PlannerStatus status, out string reason))
            {
                lock (gate)
                {
                    cut ??= (status, reason);
                }

                return true;
            }

            return false;
        }

        bool CancelledNow() => stop.ShouldStopNow(clock.Elapsed, out PlannerStatus status, out _) && status == PlannerStatus.Cancelled;

        int? startNode = null;
        int? goalNode = null;
        EndpointPlacement? startPlacement = null;
        EndpointPlacement? goalPlacement = null;
        if (settings.Start is Vector3 start)
        {
            startPlacement = _scene.Sampler.Place(start, settings.Tolerance, settings.CanStand);
            if (startPlacement.Pose is not { } pose)
            {
                return new BakeResult(roadmap.Freeze(), PlannerStatus.InvalidStart, startPlacement.Failure("start", settings.Tolerance)!, clock.Elapsed, null, null, 0, 0) { StartPlacement = startPlacement };
            }

            startNode = Insert(roadmap, index, reach, [pose], settings, counters, CancelledNow)?[0];
        }

        if (settings.Goal is Vector3 goal)
        {
            goalPlacement = _scene.Sampler.Place(goal, settings.Tolerance, settings.CanStand);
            if (goalPlacement.Pose is not { } pose)
            {
                return new BakeResult(new RoadmapBuilder(roadmap.LevelFingerprint, roadmap.CharacterFingerprint, roadmap.CharacterName, settings.Seed).Freeze(),
                    PlannerStatus.InvalidGoal, goalPlacement.Failure("goal", settings.Tolerance)!, clock.Elapsed, null, null, counters.Steering, 0)
                { StartPlacement = startPlacement, GoalPlacement = goalPlacement };
            }

            // The same stance as the start (start equal to goal) is the start node itself: a plan of no jumps.
            goalNode = startPlacement?.Pose is { } startPose && startPose.Pose == pose.Pose && startNode is int same
                ? same
                : Insert(roadmap, index, reach, [pose], settings, counters, CancelledNow)?[0];
        }

        // A request on a level much larger than its route samples around the route first.
        RequestFocus? focus = settings.FocusOnRequest && startPlacement?.Pose is { } from && goalPlacement?.Pose is { } to
            ? RequestFocus.For(_scene.Sampler, _scene.Steering.Limits, from.Pose.Position, to.Pose.Position, roadmap.Nodes.Count)
            : null;
        long nextSample = 0;
        int rounds = 0;
        int emptyRounds = 0;
        bool lined = false;
        bool approached = false;

        // Stances placed on purpose (not sampled) join the roadmap within the node budget; true when some did.
        bool AddedOnce(PoseEvaluation[] stances)
        {
            if (settings.MaxNodes is int most)
            {
                stances = stances[..Math.Min(stances.Length, Math.Max(0, most - roadmap.Nodes.Count))];
            }

            return stances.Length > 0 && Insert(roadmap, index, reach, stances, settings, counters, CancelledNow) is not null;
        }

        while (true)
        {
            var state = new BakeState(roadmap.Nodes.Count, roadmap.Edges.Count, clock.Elapsed, Connected(roadmap, startNode, goalNode), rounds);
            progress?.Report(state);
            if (settings.ApproachRaisedEnds && !approached && state.StartReachesGoal && startPlacement?.Pose is { } low && goalPlacement?.Pose is { } high)
            {
                // Connected while baking on for a wandering route: the ground within a hop of a raised end joins once.
                approached = true;
                if (AddedOnce(ApproachStances(low, high, settings)))
                {
                    continue;
                }
            }

            bool stopping = stop.ShouldStop(state, out PlannerStatus status, out string reason);
            if (!stopping && cut is { } verdict)
            {
                // Cut short by a condition that answers only between work items: end with its verdict.
                (stopping, status, reason) = (true, verdict.Status, verdict.Reason);
            }

            if (stopping && !lined && status == PlannerStatus.Exact && settings.StopWhenConnected && settings.FocusOnRequest && state.StartReachesGoal
                && startPlacement?.Pose is { } leaving && goalPlacement?.Pose is { } arriving)
            {
                // Connected: before stopping, the straight route's stances (LineStances: where the line runs on open
                // ground) and those along narrow surfaces that run the request's way (NarrowStances) join the roadmap
                // once, so the query can take them when they cost less than the route the random samples connected
                // (a beam's hops, not the floor below). Added after the connection, not
                // before, so the roadmap holds every node it held before: the route found costs no more than before
                // (tried first: stances added at the start, and on any ground, connected the desert demo sooner, on a poorer
                // roadmap: 12 jumps and no walk).
                lined = true;
                if (AddedOnce([.. LineStances(leaving, arriving, settings), .. NarrowStances(leaving, arriving, settings)]))
                {
                    continue;
                }
            }

            if (stopping)
            {
                if (status == PlannerStatus.Exact && settings.StopWhenConnected && !state.StartReachesGoal)
                {
                    status = PlannerStatus.NoPath;
                    reason += "; the start does not reach the goal yet";
                }

                return new BakeResult(roadmap.Freeze(), status, reason, clock.Elapsed, startNode, goalNode, counters.Steering, nextSample)
                { SteeringRejections = counters.Rejections, StartPlacement = startPlacement, GoalPlacement = goalPlacement };
            }

            if (emptyRounds >= MaxEmptyRounds)
            {
                long drawn = (long)MaxEmptyRounds * settings.BatchSize;
                return new BakeResult(roadmap.Freeze(), PlannerStatus.NoPath,
                    $"no valid root pose found in the last {drawn} samples (up to {_scene.Sampler.Settings.MaxAttempts} attempts each): {_scene.Character.Name} can stand nowhere else on this level",
                    clock.Elapsed, startNode, goalNode, counters.Steering, nextSample)
                { SteeringRejections = counters.Rejections, StartPlacement = startPlacement, GoalPlacement = goalPlacement };
            }

            int batch = settings.BatchSize;
            if (settings.MaxNodes is int max)
            {
                batch = Math.Min(batch, Math.Max(1, max - roadmap.Nodes.Count));
            }

            // Sample a round in parallel; keep the valid ones in sample order.
            var samples = new PoseEvaluation?[batch];
            long first = nextSample;
            SampleRegion? region = focus?.RegionAt(roadmap.Nodes.Count);
            if (RunParallel(batch, settings.Threads, StopNow,
                i => samples[i] = _scene.Sampler.Sample(SeedMixer.Create(settings.Seed, first + i), region, out _)))
            {
                continue; // the termination check at the top of the loop ends the bake
            }

            nextSample += batch;
            PoseEvaluation[] valid = [.. samples.Where(s => s is not null).Select(s => s!)];
            if (valid.Length == 0 && region is not null)
            {
                // Nothing valid in the corridor: widen it; only rounds over the whole level count as empty.
                focus!.Widen();
            }
            else
            {
                emptyRounds = valid.Length == 0 ? emptyRounds + 1 : 0;
            }

            if (valid.Length > 0 && Insert(roadmap, index, reach, valid, settings, counters, StopNow) is null)
            {
                continue; // cut short while steering: the roadmap is unchanged and the check above ends the bake
            }

            rounds++;
        }
    }

    /// <summary>
    /// Adds the poses as nodes and steers every new node to and from its nearest reachable neighbours (earlier
    /// nodes, found through <paramref name="index"/>, and the new nodes before it). Returns the new node ids, or
    /// <c>null</c> (roadmap and index unchanged) when <paramref name="stopNow"/> cut it short.
    /// </summary>
    private int[]? Insert(RoadmapBuilder roadmap, NodeIndex index, ReachTest reach, PoseEvaluation[] poses, BakeSettings settings, Counters counters, Func<bool> stopNow)
    {
        int firstId = roadmap.Nodes.Count;

        // Pairs (new node i, earlier node j), j among the nearest within reach, in a fixed order: by (distance, id),
        // exactly as a scan over every earlier node would rank them.
        List<(int I, int J)> pairs = Pairs(poses, firstId, settings.MaxNeighbours, (p, found) => index.OfferWithinReach(p, reach, settings.MaxNeighbours, found), reach.InReach);

        // Walk pairs likewise: the nearest within walking distance, horizontally.
        bool walking = settings.Locomotion == Locomotion.WalkAndJump && _scene.Walking.Limits.CanWalk && settings.MaxWalkNeighbours > 0;
        float walkDistance = settings.MaxWalkDistance ?? BakeSettings.DefaultMaxWalkDistance(_scene.Walking.Limits);
        List<(int I, int J)> walkPairs = walking
            ? Pairs(poses, firstId, settings.MaxWalkNeighbours, (p, found) => index.OfferWithin(p, walkDistance, settings.MaxWalkNeighbours, found), (p, q) => new Vector2(q.X - p.X, q.Z - p.Z).LengthSquared() <= walkDistance * walkDistance)
            : [];

        RoadmapNode NodeOf(int id) => id < firstId ? roadmap.Nodes[id] : ToNode(poses[id - firstId], id);
        var forward = new SteeringResult[pairs.Count];
        var backward = new SteeringResult[pairs.Count];
        var walkForward = new WalkResult[walkPairs.Count];
        var walkBackward = new WalkResult[walkPairs.Count];
        bool cut = RunParallel(pairs.Count + walkPairs.Count, settings.Threads, stopNow, n =>
        {
            if (n < pairs.Count)
            {
                RoadmapNode a = NodeOf(pairs[n].I);
                RoadmapNode b = NodeOf(pairs[n].J);
                forward[n] = _scene.Steering.Steer(a.Pose, a.Cone, b.Pose, b.Cone);
                backward[n] = _scene.Steering.Steer(b.Pose, b.Cone, a.Pose, a.Cone);
            }
            else
            {
                int w = n - pairs.Count;
                RoadmapNode a = NodeOf(walkPairs[w].I);
                RoadmapNode b = NodeOf(walkPairs[w].J);
                walkForward[w] = _scene.Walking.Steer(a, b, walkDistance);
                walkBackward[w] = _scene.Walking.Steer(b, a, walkDistance);
            }
        });
        if (cut)
        {
            return null;
        }

        counters.Steering += 2L * pairs.Count;
        int[] ids = new int[poses.Length];
        for (int k = 0; k < poses.Length; k++)
        {
            ids[k] = firstId + k;
            roadmap.AddNode(ToNode(poses[k], firstId + k));
            index.Add(poses[k].Pose.Position);
        }

        for (int n = 0; n < pairs.Count; n++)
        {
            counters.Count(forward[n]);
            counters.Count(backward[n]);
            (int i, int j) = pairs[n];
            if (forward[n].Succeeded)
            {
                roadmap.AddEdge(new RoadmapEdge(i, j, forward[n].Arc));
            }

            if (backward[n].Succeeded)
            {
                roadmap.AddEdge(new RoadmapEdge(j, i, backward[n].Arc));
            }
        }

        for (int n = 0; n < walkPairs.Count; n++)
        {
            (int i, int j) = walkPairs[n];
            if (walkForward[n].Walk is Walk there)
            {
                roadmap.AddWalk(new RoadmapWalk(i, j, there.Length, there.Length / there.Speed));
            }

            if (walkBackward[n].Walk is Walk back)
            {
                roadmap.AddWalk(new RoadmapWalk(j, i, back.Length, back.Length / back.Speed));
            }
        }

        return ids;
    }

    /// <summary>
    /// For each new pose (id <paramref name="firstId"/> + k): the (new id, other id) pairs with the nearest
    /// <paramref name="count"/> earlier nodes (<paramref name="offerEarlier"/> offers those of the index) and earlier
    /// new poses passing <paramref name="near"/>, by (distance, id).
    /// </summary>
    private static List<(int I, int J)> Pairs(PoseEvaluation[] poses, int firstId, int count, Action<Vector3, List<(float Distance, int Id)>> offerEarlier, Func<Vector3, Vector3, bool> near)
    {
        var pairs = new List<(int I, int J)>();
        var candidates = new List<(float Distance, int Id)>();
        for (int k = 0; k < poses.Length; k++)
        {
            Vector3 p = poses[k].Pose.Position;
            candidates.Clear();
            offerEarlier(p, candidates);
            for (int m = 0; m < k; m++)
            {
                Vector3 q = poses[m].Pose.Position;
                if (near(p, q))
                {
                    NodeIndex.Offer(candidates, count, (Vector3.Distance(p, q), firstId + m));
                }
            }

            NodeIndex.Finish(candidates);
            foreach ((_, int j) in candidates)
            {
                pairs.Add((firstId + k, j));
            }
        }

        return pairs;
    }

    /// <summary>
    /// Stances on the straight line from <paramref name="start"/>'s contact centre to <paramref name="goal"/>'s, when
    /// that line runs on open ground (<see cref="LineIsClear"/>): one every neighbour cell (<see cref="NodeIndex.CellSizeFor"/>:
    /// half the jump reach) or closer, each placed facing along the line within the request's tolerance of its point
    /// (<see cref="TrunkSampler.PlaceFacing"/>); none at all when any point has nothing to stand on so near, or when
    /// the line is shorter than two cells. Why: random samples are drawn by area, so a narrow surface that runs the
    /// route's way (a 0.3 m beam between two platforms, under half a percent of the level) receives almost none, and a
    /// bake that stops at its first connection finds it over the wide floor below. A bake that stops when connected
    /// adds these stances once, at the connection, before it stops (<see cref="Bake"/>): a route no random sample
    /// found is then one search away, and the query takes it when it costs less. Deterministic: placement draws
    /// nothing at random.
    /// </summary>
    internal PoseEvaluation[] LineStances(PoseEvaluation start, PoseEvaluation goal, BakeSettings settings)
    {
        Vector3 from = Contact.Centre(start.Contacts, start.Pose.Position);
        Vector3 to = Contact.Centre(goal.Contacts, goal.Pose.Position);
        var flat = new Vector2(to.X - from.X, to.Z - from.Z);
        float across = flat.Length();
        int spans = (int)MathF.Ceiling(across / NodeIndex.CellSizeFor(_scene.Steering.Limits));
        if (spans < 2 || !float.IsFinite(across))
        {
            return [];
        }

        if (!LineIsClear(from, to, settings.Tolerance))
        {
            return [];
        }

        float facing = MathF.Atan2(flat.X, flat.Y);
        var stances = new List<PoseEvaluation>();
        for (int k = 1; k < spans; k++)
        {
            if (_scene.Sampler.PlaceFacing(Vector3.Lerp(from, to, (float)k / spans), settings.Tolerance, facing, settings.CanStand).Pose is not { } pose)
            {
                return [];
            }

            stances.Add(pose);
        }

        return [.. stances];
    }

    /// <summary>
    /// Stances on the ground within a jump's reach of whichever of <paramref name="start"/> and <paramref name="goal"/>
    /// is raised above the other by more than the step height (up on a beam or a ledge, the other on the floor): under
    /// the straight line from the raised end back toward the other, at a quarter, a half, three quarters and one
    /// neighbour cell (<see cref="NodeIndex.CellSizeFor"/>: half the jump reach) from it, each placed facing the raised
    /// end within the request's tolerance of the ground straight below the line. Random samples drawn by area rarely
    /// land within a hop of a raised goal's side: the frog going from the floor up onto a beam's middle hopped under
    /// the beam, round to its far side and up from there (5 hops, 1.6 times the straight distance), every stance of the
    /// near side too far to jump up from (its takeoff speed). Deterministic.
    /// </summary>
    internal PoseEvaluation[] ApproachStances(PoseEvaluation start, PoseEvaluation goal, BakeSettings settings)
    {
        Vector3 from = Contact.Centre(start.Contacts, start.Pose.Position);
        Vector3 to = Contact.Centre(goal.Contacts, goal.Pose.Position);
        float across = new Vector2(to.X - from.X, to.Z - from.Z).Length();
        float cell = NodeIndex.CellSizeFor(_scene.Steering.Limits);
        if (!(across > 0.25f * cell) || !float.IsFinite(across))
        {
            return [];
        }

        var stances = new List<PoseEvaluation>();
        foreach ((Vector3 end, Vector3 other) in new[] { (to, from), (from, to) })
        {
            if (!(end.Y - other.Y > _scene.Character.StepReach))
            {
                continue; // not raised: walked or hopped up to as any stance is
            }

            var back = new Vector2(other.X - end.X, other.Z - end.Z) / across;
            float facing = MathF.Atan2(-back.X, -back.Y);
            for (int k = 1; k <= ApproachSteps && k * cell / ApproachSteps < across; k++)
            {
                Vector3 point = Vector3.Lerp(end, other, k * cell / ApproachSteps / across);
                float top = end.Y + _scene.Character.StanceLift.Max;
                if (_scene.Bvh.Raycast(point with { Y = top }, -Vector3.UnitY, top - other.Y + settings.Tolerance.UpDown, out RayHit ground)
                    && ground.Normal.Y > 0f && ground.Point.Y < end.Y - _scene.Character.StepReach
                    && _scene.Sampler.PlaceFacing(ground.Point, settings.Tolerance, facing, settings.CanStand).Pose is { } pose)
                {
                    stances.Add(pose);
                }
            }
        }

        return [.. stances];
    }

    /// <summary>How many stances <see cref="ApproachStances"/> places toward the other end, over one neighbour cell.</summary>
    private const int ApproachSteps = 4;

    /// <summary>
    /// Stances along the narrow surfaces that run the request's way (a beam, a ledge, a walkway: a contact surface
    /// facing up, at least two neighbour cells long and at most <see cref="NarrowShare"/> as wide as long, its long axis
    /// within <see cref="NarrowTurn"/> of the way from <paramref name="start"/> to <paramref name="goal"/> and its
    /// middle within the request's first corridor, <see cref="RequestFocus"/>): along the middle of its long axis,
    /// inset half a cell from its ends, one every neighbour cell or closer, and one more a span beyond either end (where
    /// the surface leads on at its height, as a beam's platforms do), each placed facing the goal's way where
    /// something stands (<see cref="TrunkSampler.PlaceFacing"/>), the axis running on open ground
    /// (<see cref="LineIsClear"/>). Random samples drawn by area reach such a surface a few times at most: from one
    /// platform to the other across a beam the frog hopped down, across the floor and back up. Deterministic.
    /// </summary>
    internal PoseEvaluation[] NarrowStances(PoseEvaluation start, PoseEvaluation goal, BakeSettings settings)
    {
        Vector3 from = Contact.Centre(start.Contacts, start.Pose.Position);
        Vector3 to = Contact.Centre(goal.Contacts, goal.Pose.Position);
        var way = new Vector2(to.X - from.X, to.Z - from.Z);
        float across = way.Length();
        float cell = NodeIndex.CellSizeFor(_scene.Steering.Limits);
        if (!(across > 1e-3f) || !float.IsFinite(across))
        {
            return [];
        }

        way /= across;
        float corridor = RequestFocus.FirstRadius(cell, across);
        var a = new Vector2(from.X, from.Z);
        float Off(Vector2 p) => Vector2.Distance(p, a + (way * Math.Clamp(Vector2.Dot(p - a, way), 0f, across)));

        // The corners of each upward surface's triangles near the way, surface by surface in id order.
        var corners = new SortedDictionary<int, List<Vector3>>();
        IReadOnlyList<Triangle> triangles = _scene.Level.Triangles;
        for (int t = 0; t < triangles.Count; t++)
        {
            int surface = _scene.Surfaces.SurfaceOf(t);
            Triangle triangle = triangles[t];
            if (surface < 0 || _scene.Surfaces.Surfaces[surface].Normal.Y < NarrowUp
                || Off(new Vector2(triangle.Centroid.X, triangle.Centroid.Z)) > corridor + (2f * cell))
            {
                continue;
            }

            if (!corners.TryGetValue(surface, out List<Vector3>? points))
            {
                corners[surface] = points = [];
            }

            points.AddRange([triangle.A, triangle.B, triangle.C]);
        }

        var stances = new List<PoseEvaluation>();
        float facing = MathF.Atan2(way.X, way.Y);
        foreach (List<Vector3> points in corners.Values)
        {
            // The long axis: the principal direction of the corners seen from above, toward the goal.
            Vector3 mean = points.Aggregate(Vector3.Zero, (sum, p) => sum + p) / points.Count;
            (float xx, float xz, float zz) = (0f, 0f, 0f);
            foreach (Vector3 p in points)
            {
                (float dx, float dz) = (p.X - mean.X, p.Z - mean.Z);
                (xx, xz, zz) = (xx + (dx * dx), xz + (dx * dz), zz + (dz * dz));
            }

            float angle = 0.5f * MathF.Atan2(2f * xz, xx - zz);
            var axis = new Vector2(MathF.Cos(angle), MathF.Sin(angle));
            if (Vector2.Dot(axis, way) < 0f)
            {
                axis = -axis;
            }

            var side = new Vector2(-axis.Y, axis.X);
            var centre = new Vector2(mean.X, mean.Z);
            (float lo, float hi, float left, float right) = (float.MaxValue, float.MinValue, float.MaxValue, float.MinValue);
            foreach (Vector3 p in points)
            {
                var d = new Vector2(p.X, p.Z) - centre;
                (lo, hi) = (MathF.Min(lo, Vector2.Dot(d, axis)), MathF.Max(hi, Vector2.Dot(d, axis)));
                (left, right) = (MathF.Min(left, Vector2.Dot(d, side)), MathF.Max(right, Vector2.Dot(d, side)));
            }

            float length = hi - lo;
            Vector2 middle = centre + (side * (0.5f * (left + right))) + (axis * (0.5f * (lo + hi)));
            if (length < 2f * cell || right - left > NarrowShare * length || Vector2.Dot(axis, way) < MathF.Cos(NarrowTurn) || Off(middle) > corridor)
            {
                continue;
            }

            // Along the middle of the long axis at the surface's height, inset half a cell from its ends.
            Vector2 first = middle - (axis * ((0.5f * length) - (0.5f * cell)));
            Vector2 last = middle + (axis * ((0.5f * length) - (0.5f * cell)));
            var head = new Vector3(first.X, mean.Y, first.Y);
            var tail = new Vector3(last.X, mean.Y, last.Y);
            if (!LineIsClear(head, tail, settings.Tolerance))
            {
                continue;
            }

            // And a cell beyond either end, where the surface leads on at its height (a beam's platforms).
            int spans = Math.Max(1, (int)MathF.Ceiling(Vector3.Distance(head, tail) / cell));
            for (int k = -1; k <= spans + 1; k++)
            {
                if (_scene.Sampler.PlaceFacing(Vector3.Lerp(head, tail, (float)k / spans), settings.Tolerance, facing, settings.CanStand).Pose is { } pose)
                {
                    stances.Add(pose);
                }
            }
        }

        return [.. stances];
    }

    /// <summary>Least up component of a surface's normal for <see cref="NarrowStances"/> (about 25°).</summary>
    private const float NarrowUp = 0.9f;

    /// <summary>Greatest width of a narrow surface (<see cref="NarrowStances"/>) as a share of its length.</summary>
    private const float NarrowShare = 0.25f;

    /// <summary>Greatest angle (radians) between a narrow surface's long axis and the request's way (<see cref="NarrowStances"/>).</summary>
    private const float NarrowTurn = MathF.PI / 6f;

    /// <summary>
    /// True when the line from <paramref name="from"/> to <paramref name="to"/> (world metres) runs on open ground:
    /// every <see cref="LineProbe"/> metres the ground straight below is within the tolerance's up/down bound of the
    /// line (no hole, no step beyond it), and nothing stands in the way between probes at the height of the band's top
    /// and of the trunk's highest stance lift (no block, wall or door frame).
    /// </summary>
    private bool LineIsClear(Vector3 from, Vector3 to, EndpointTolerance tolerance)
    {
        float band = tolerance.UpDown;
        float[] heights = [band + LineProbe, MathF.Max(band + LineProbe, _scene.Character.StanceLift.Max)];
        int probes = (int)MathF.Ceiling(Vector3.Distance(from, to) / LineProbe);
        Vector3 along = Vector3.Normalize(to - from);
        float step = Vector3.Distance(from, to) / probes;
        for (int k = 0; k <= probes; k++)
        {
            Vector3 point = Vector3.Lerp(from, to, (float)k / probes);
            if (!_scene.Bvh.Raycast(point + (Vector3.UnitY * band), -Vector3.UnitY, 2f * band, out RayHit ground) || MathF.Abs(ground.Point.Y - point.Y) > band)
            {
                return false;
            }

            foreach (float height in heights)
            {
                if (k < probes && _scene.Bvh.Raycast(point + (Vector3.UnitY * height), along, step, out _))
                {
                    return false;
                }
            }
        }

        return true;
    }

    /// <summary>Spacing (metres) of the ground probes of <see cref="LineIsClear"/>.</summary>
    private const float LineProbe = 0.1f;

    private static RoadmapNode ToNode(PoseEvaluation pose, int id) => new(id, pose.Pose, pose.Cone, pose.Contacts);

    /// <summary>Runs <paramref name="body"/> for 0..count−1 on up to <paramref name="threads"/> threads (in order on this one for 1), polling <paramref name="stopNow"/> before each item; true when it stopped the run early.</summary>
    internal static bool RunParallel(int count, int threads, Func<bool> stopNow, Action<int> body)
    {
        bool stopped = false;
        if (threads <= 1 || count <= 1)
        {
            for (int i = 0; i < count; i++)
            {
                if (stopNow())
                {
                    return true;
                }

                body(i);
            }

            return false;
        }

        Parallel.For(0, count, new ParallelOptions { MaxDegreeOfParallelism = threads }, (i, loop) =>
        {
            if (Volatile.Read(ref stopped) || stopNow())
            {
                Volatile.Write(ref stopped, true);
                loop.Stop();
                return;
            }

            body(i);
        });
        return stopped;
    }

    /// <summary>The caller's condition first, then those of the settings: one condition carried down to every loop.</summary>
    private static TerminationCondition BuildTermination(BakeSettings settings, TerminationCondition? extra)
    {
        TerminationCondition? stop = extra;
        if (settings.StopWhenConnected)
        {
            stop = Or(stop, TerminationCondition.StartGoalConnected());
        }

        if (settings.TimeLimit is TimeSpan limit)
        {
            stop = Or(stop, TerminationCondition.Timeout(limit));
        }

        if (settings.MaxNodes is int max)
        {
            stop = Or(stop, TerminationCondition.NodeCount(max));
        }

        return stop ?? throw new ArgumentException("Nothing would stop this bake: set MaxNodes, TimeLimit, StopWhenConnected or a termination condition.");

        static TerminationCondition Or(TerminationCondition? left, TerminationCondition right) => left is null ? right : left | right;
    }

    private static bool Connected(RoadmapBuilder roadmap, int? start, int? goal) =>
        start is int s && goal is int g && roadmap.Reaches(s, g);

    private sealed class Counters
    {
        public long Steering { get; set; }

        public Dictionary<SteeringFailure, long> Rejections { get; } = [];

        public void Count(in SteeringResult result)
        {
            if (!result.Succeeded)
            {
                Rejections[result.Failure] = Rejections.GetValueOrDefault(result.Failure) + 1;
            }
        }
    }
}
