using System.Diagnostics;
using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;
using Ballistic.Planner.Steering;

namespace Ballistic.Planner.Planning;

/// <summary>
/// Bakes a roadmap (Algorithm 1 of the paper): rounds of valid root samples, each new node steered to and from its
/// nearest neighbours within jump reach, until a termination condition holds.
/// </summary>
/// <remarks>
/// Deterministic whatever the thread count: sample k draws from its own random stream (seed, k); nodes enter the
/// roadmap in sample order; every pair's jumps are computed in parallel but inserted in pair order. A round cut
/// short by the time budget or cancellation is discarded whole, so the roadmap is always a prefix of rounds.
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
    /// <param name="termination">An extra termination condition, combined with those of <paramref name="settings"/>.</param>
    /// <param name="progress">Receives the state after every round.</param>
    /// <param name="cancellationToken">Cancels the bake; the result then has status <see cref="PlannerStatus.Cancelled"/>.</param>
    /// <exception cref="ArgumentException">The settings are invalid or nothing would ever stop the bake.</exception>
    public BakeResult Bake(BakeSettings settings, TerminationCondition? termination = null, IProgress<BakeState>? progress = null, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(settings);
        settings.Validate();
        TerminationCondition stop = BuildTermination(settings, termination, cancellationToken);
        var clock = Stopwatch.StartNew();
        var roadmap = new Roadmap(_scene.Level.Fingerprint, _scene.Character.Fingerprint, _scene.Character.Name, settings.Seed);
        var counters = new Counters();

        int? startNode = null;
        int? goalNode = null;
        EndpointPlacement? startPlacement = null;
        EndpointPlacement? goalPlacement = null;
        if (settings.Start is Vector3 start)
        {
            startPlacement = _scene.Sampler.Place(start, settings.Tolerance, settings.CanStand);
            if (startPlacement.Pose is not { } pose)
            {
                return new BakeResult(roadmap, PlannerStatus.InvalidStart, startPlacement.Failure("start", settings.Tolerance)!, clock.Elapsed, null, null, 0, 0) { StartPlacement = startPlacement };
            }

            startNode = Insert(roadmap, [pose], settings, counters, deadline: null, cancellationToken)?[0];
        }

        if (settings.Goal is Vector3 goal)
        {
            goalPlacement = _scene.Sampler.Place(goal, settings.Tolerance, settings.CanStand);
            if (goalPlacement.Pose is not { } pose)
            {
                return new BakeResult(new Roadmap(roadmap.LevelFingerprint, roadmap.CharacterFingerprint, roadmap.CharacterName, settings.Seed),
                    PlannerStatus.InvalidGoal, goalPlacement.Failure("goal", settings.Tolerance)!, clock.Elapsed, null, null, counters.Steering, 0)
                { StartPlacement = startPlacement, GoalPlacement = goalPlacement };
            }

            // The same stance as the start (start equal to goal) is the start node itself: a plan of no jumps.
            goalNode = startPlacement?.Pose is { } startPose && startPose.Pose == pose.Pose && startNode is int same
                ? same
                : Insert(roadmap, [pose], settings, counters, deadline: null, cancellationToken)?[0];
        }

        DateTime now = DateTime.UtcNow;
        DateTime? deadline = settings.TimeLimit is TimeSpan limit && limit < DateTime.MaxValue - now ? now + limit : null;
        long nextSample = 0;
        int rounds = 0;
        int emptyRounds = 0;
        while (true)
        {
            var state = new BakeState(roadmap.Nodes.Count, roadmap.Edges.Count, clock.Elapsed, Connected(roadmap, startNode, goalNode), rounds);
            progress?.Report(state);
            if (stop.ShouldStop(state, out PlannerStatus status, out string reason))
            {
                if (status == PlannerStatus.Exact && settings.StopWhenConnected && !state.StartReachesGoal)
                {
                    status = PlannerStatus.NoPath;
                    reason += "; the start does not reach the goal yet";
                }

                return new BakeResult(roadmap, status, reason, clock.Elapsed, startNode, goalNode, counters.Steering, nextSample)
                { SteeringRejections = counters.Rejections, StartPlacement = startPlacement, GoalPlacement = goalPlacement };
            }

            if (emptyRounds >= MaxEmptyRounds)
            {
                long attempts = (long)MaxEmptyRounds * settings.BatchSize * _scene.Sampler.Settings.MaxAttempts;
                return new BakeResult(roadmap, PlannerStatus.NoPath,
                    $"no valid root pose found in the last {attempts} attempts: {_scene.Character.Name} can stand nowhere else on this level",
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
            bool cut = RunParallel(batch, settings.Threads, deadline, cancellationToken,
                i => samples[i] = _scene.Sampler.Sample(SeedMixer.Create(settings.Seed, first + i)));
            if (cut)
            {
                continue; // the termination check at the top of the loop ends the bake
            }

            nextSample += batch;
            PoseEvaluation[] valid = [.. samples.Where(s => s is not null).Select(s => s!)];
            emptyRounds = valid.Length == 0 ? emptyRounds + 1 : 0;
            if (valid.Length > 0 && Insert(roadmap, valid, settings, counters, deadline, cancellationToken) is null)
            {
                continue; // cut short while steering: the roadmap is unchanged and the check above ends the bake
            }

            rounds++;
        }
    }

    /// <summary>
    /// Adds the poses as nodes and steers every new node to and from its nearest reachable neighbours. Returns the
    /// new node ids, or <c>null</c> (roadmap unchanged) when cut short by the deadline or cancellation.
    /// </summary>
    private int[]? Insert(Roadmap roadmap, PoseEvaluation[] poses, BakeSettings settings, Counters counters, DateTime? deadline, CancellationToken token)
    {
        int firstId = roadmap.Nodes.Count;
        var all = new List<(Vector3 Position, int Id)>(firstId + poses.Length);
        foreach (RoadmapNode node in roadmap.Nodes)
        {
            all.Add((node.Pose.Position, node.Id));
        }

        for (int k = 0; k < poses.Length; k++)
        {
            all.Add((poses[k].Pose.Position, firstId + k));
        }

        // Pairs (new node i, earlier node j), j among the nearest within reach, in a fixed order.
        var pairs = new List<(int I, int J)>();
        var candidates = new List<(float Distance, int Id)>();
        for (int k = 0; k < poses.Length; k++)
        {
            int i = firstId + k;
            Vector3 p = all[i].Position;
            candidates.Clear();
            for (int j = 0; j < i; j++)
            {
                Vector3 q = all[j].Position;
                float x = new Vector2(q.X - p.X, q.Z - p.Z).Length();
                SteeringLimits limits = _scene.Steering.Limits;
                if (x <= limits.MaxReach(p.Y - q.Y) || x <= limits.MaxReach(q.Y - p.Y))
                {
                    candidates.Add((Vector3.Distance(p, q), j));
                }
            }

            candidates.Sort();
            for (int c = 0; c < Math.Min(settings.MaxNeighbours, candidates.Count); c++)
            {
                pairs.Add((i, candidates[c].Id));
            }
        }

        RoadmapNode NodeOf(int id) => id < firstId ? roadmap.Nodes[id] : ToNode(poses[id - firstId], id);
        var forward = new SteeringResult[pairs.Count];
        var backward = new SteeringResult[pairs.Count];
        bool cut = RunParallel(pairs.Count, settings.Threads, deadline, token, n =>
        {
            RoadmapNode a = NodeOf(pairs[n].I);
            RoadmapNode b = NodeOf(pairs[n].J);
            forward[n] = _scene.Steering.Steer(a.Pose, a.Cone, b.Pose, b.Cone);
            backward[n] = _scene.Steering.Steer(b.Pose, b.Cone, a.Pose, a.Cone);
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

        return ids;
    }

    private static RoadmapNode ToNode(PoseEvaluation pose, int id) => new(id, pose.Pose, pose.Cone, pose.Contacts);

    /// <summary>Runs <paramref name="body"/> for 0..count−1; true when stopped early by the deadline or the token.</summary>
    private static bool RunParallel(int count, int threads, DateTime? deadline, CancellationToken token, Action<int> body)
    {
        bool stopped = false;
        bool Expired() => token.IsCancellationRequested || (deadline is DateTime d && DateTime.UtcNow >= d);
        if (threads <= 1 || count <= 1)
        {
            for (int i = 0; i < count; i++)
            {
                if (Expired())
                {
                    return true;
                }

                body(i);
            }

            return false;
        }

        Parallel.For(0, count, new ParallelOptions { MaxDegreeOfParallelism = threads }, (i, loop) =>
        {
            if (Volatile.Read(ref stopped) || Expired())
            {
                Volatile.Write(ref stopped, true);
                loop.Stop();
                return;
            }

            body(i);
        });
        return stopped;
    }

    private static TerminationCondition BuildTermination(BakeSettings settings, TerminationCondition? extra, CancellationToken token)
    {
        TerminationCondition stop = TerminationCondition.Cancellation(token);
        bool bounded = extra is not null;
        if (settings.StopWhenConnected)
        {
            stop |= TerminationCondition.StartGoalConnected();
            bounded = true;
        }

        if (settings.TimeLimit is TimeSpan limit)
        {
            stop |= TerminationCondition.Timeout(limit);
            bounded = true;
        }

        if (settings.MaxNodes is int max)
        {
            stop |= TerminationCondition.NodeCount(max);
            bounded = true;
        }

        if (extra is not null)
        {
            stop |= extra;
        }

        return bounded
            ? stop
            : throw new ArgumentException("Nothing would stop this bake: set MaxNodes, TimeLimit, StopWhenConnected or a termination condition.");
    }

    private static bool Connected(Roadmap roadmap, int? start, int? goal) =>
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
