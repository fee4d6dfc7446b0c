using Ballistic.Planner.Animation;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;
using Ballistic.Runtime.Paths;

namespace Ballistic.Runtime.Systems;

/// <summary>
/// Serves path requests after Detour's path queue: a request waits in a first-come queue; each tick searches as many
/// as the budget allows (<see cref="WorldSettings.MaxSearchesPerTick"/>, <see cref="WorldSettings.MaxExpansionsPerTick"/>);
/// a found path is animated in the background and delivered to its agent exactly <see cref="WorldSettings.PathLatencyTicks"/>
/// later. A path whose animation shows a move (jump or walk) the body cannot perform is searched again without it
/// (lazy repair, up to <see cref="WorldSettings.RepairRounds"/> searches) before it is reported as failed. Requests
/// come from the world's <see cref="PathQueue"/>, which the world's calls and the locomotion system fill.
/// </summary>
internal sealed class PathRequestSystem : IDisposable
{
    private readonly WorldSettings _settings;
    private readonly AgentStore _agents;
    private readonly EventBuffer _events;
    private readonly List<CharacterKind> _kinds;
    private readonly List<RoadmapSearch> _searches;
    private readonly PathQueue _queue;
    private readonly List<PathRequest> _inFlight = [];
    private readonly TaskScheduler? _scheduler;
    private readonly CancellationTokenSource _shutdown = new();

    public PathRequestSystem(WorldSettings settings, AgentStore agents, PathQueue queue, EventBuffer events, List<CharacterKind> kinds, List<RoadmapSearch> searches)
    {
        _queue = queue;
        _settings = settings;
        _agents = agents;
        _events = events;
        _kinds = kinds;
        _searches = searches;
        if (settings.AnimationThreads > 0)
        {
            _scheduler = new ConcurrentExclusiveSchedulerPair(TaskScheduler.Default, settings.AnimationThreads).ConcurrentScheduler;
        }
    }

    /// <summary>Requests waiting for a search.</summary>
    public int Queued => _queue.Count;

    /// <summary>Requests searched and being animated.</summary>
    public int Animating => _inFlight.Count;

    /// <summary>Searches made during the last tick.</summary>
    public int LastTickSearches { get; private set; }

    /// <summary>Work (expansions and placement costs) spent during the last tick.</summary>
    public int LastTickWork { get; private set; }

    public void Update(long tick, double time)
    {
        Search(tick, time);
        Deliver(tick, time);
    }

    private void Search(long tick, double time)
    {
        int searches = 0;
        int work = 0;
        while (searches < _settings.MaxSearchesPerTick && work < _settings.MaxExpansionsPerTick && _queue.TryTake(out PathRequest? request))
        {
            int slot = request.Agent.Index;
            if (!Current(request))
            {
                continue;
            }

            searches++;
            try
            {
                work += SearchOne(slot, request, tick, time);
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                Fail(slot, request, PlannerStatus.NoPath, $"internal error while searching: {e.Message}", tick, time);
            }
        }

        LastTickSearches = searches;
        LastTickWork = work;
    }

    private int SearchOne(int slot, PathRequest request, long tick, double time)
    {
        CharacterKind kind = _kinds[_agents.Kind[slot]];
        request.Start = _agents.Stance[slot]!;
        request.Rounds++;
        int work = 0;
        if (request.ForcedEdge >= 0)
        {
            // One given jump of the roadmap: no search.
            Roadmap roadmap = kind.Roadmap;
            RoadmapEdge edge = roadmap.Edges[request.ForcedEdge];
            request.Moves = [new Jump(roadmap.Nodes[edge.From], roadmap.Nodes[edge.To], edge.Arc)];
        }
        else if (request.ForcedMoves is { } forced)
        {
            // The given moves: no search.
            request.Moves = forced;
        }
        else
        {
            PlanResult result = _searches[_agents.Kind[slot]].Search(request.Start, request.Target, request.Repair, _settings.PlacementCost, out work);
            if (result.Status != PlannerStatus.Exact)
            {
                string? repaired = request.Repair.SearchFailed(result.Reason);
                Fail(slot, request, repaired is null ? result.Status : PlannerStatus.AnimationFailed, repaired ?? result.Reason, tick, time);
                return work;
            }

            if (result.Moves.Count == 0)
            {
                _agents.Request[slot] = null;
                _agents.State[slot] = AgentState.Idle;
                _agents.HasTarget[slot] = false;
                _events.Add(new JumpEvent(JumpEventKind.TargetReached, request.Agent, tick, time, -1, _agents.Root[slot].Position, request.Target, default, 0f, PlannerStatus.Exact, null));
                return work;
            }

            request.Moves = result.Moves;
        }

        request.DueTick = tick + _settings.PathLatencyTicks;
        IReadOnlyList<Move> moves = request.Moves;
        IJumpAnimator animator = kind.PathAnimator;
        float frameRate = _settings.AnimationFrameRate;
        if (_scheduler is null)
        {
            // On the tick; an animator that throws fails the request on its due tick, as a background job's would, so
            // that events do not depend on the thread count.
            try
            {
                request.Solved = animator.Animate(moves, frameRate);
                request.Job = null;
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                request.Solved = null;
                request.Job = Task.FromException<JumpAnimation>(e);
            }
        }
        else
        {
            request.Solved = null;
            request.Job = Task.Factory.StartNew(() => animator.Animate(moves, frameRate), _shutdown.Token, TaskCreationOptions.None, _scheduler);
        }

        _inFlight.Add(request);
        _agents.State[slot] = AgentState.Stance;
        return work;
    }

    private void Deliver(long tick, double time)
    {
        // In request order; a request re-queued for repair leaves the list, so walk it with an index.
        int kept = 0;
        for (int i = 0; i < _inFlight.Count; i++)
        {
            PathRequest request = _inFlight[i];
            bool due = request.DueTick <= tick;
            bool ready = request.Job is null || request.Job.IsCompleted;
            if (!Current(request))
            {
                if (!ready)
                {
                    _inFlight[kept++] = request; // let the job finish before dropping it
                }

                continue;
            }

            if (!due || (!ready && !_settings.WaitForAnimation))
            {
                _inFlight[kept++] = request;
                continue;
            }

            int slot = request.Agent.Index;
            try
            {
                JumpAnimation animation = request.Solved ?? request.Job!.GetAwaiter().GetResult();
                Complete(slot, request, animation, tick, time);
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                Fail(slot, request, PlannerStatus.AnimationFailed, $"internal error while animating: {e.Message}", tick, time);
            }
        }

        _inFlight.RemoveRange(kept, _inFlight.Count - kept);
    }

    private void Complete(int slot, PathRequest request, JumpAnimation animation, long tick, double time)
    {
        if (animation.IsClean)
        {
            var path = new AgentPath(request.Target, request.Moves, animation);
            _agents.Request[slot] = null;
            _agents.Stance[slot] = null;
            _agents.Path[slot] = path;
            _agents.PathStart[slot] = time;
            _agents.Cursor[slot] = 0;
            _agents.StopAtStance[slot] = false;
            _events.Add(new JumpEvent(JumpEventKind.PathFound, request.Agent, tick, time, -1, path.Start.Pose.Position, request.Target, default, 0f, PlannerStatus.Exact, null));
            return;
        }

        // A given jump or given moves the body cannot perform are set aside like any other: the request becomes a
        // search to the same stance.
        request.ForcedEdge = -1;
        request.ForcedMoves = null;
        request.Repair.Reject(request.Moves, animation);
        if (request.Repair.IsExhausted(request.Rounds, _settings.RepairRounds))
        {
            Fail(slot, request, PlannerStatus.AnimationFailed, request.Repair.RoundsExhausted(request.Rounds), tick, time);
            return;
        }

        _queue.Retry(request); // searched again first, on the next tick
    }

    private void Fail(int slot, PathRequest request, PlannerStatus status, string reason, long tick, double time)
    {
        _agents.Request[slot] = null;
        _agents.State[slot] = AgentState.Idle;
        _events.Add(new JumpEvent(JumpEventKind.PathFailed, request.Agent, tick, time, -1, _agents.Root[slot].Position, request.Target, default, 0f, status, reason));
    }

    /// <summary>True while the request is its agent's pending one (the agent was neither removed nor given another request).</summary>
    private bool Current(PathRequest request) =>
        _agents.IsValid(request.Agent) && ReferenceEquals(_agents.Request[request.Agent.Index], request);

    public void Dispose()
    {
        _shutdown.Cancel();
        foreach (PathRequest request in _inFlight)
        {
            try
            {
                request.Job?.Wait();
            }
            catch (AggregateException)
            {
                // cancelled or failed: nobody waits for it any more
            }
        }

        _shutdown.Dispose();
    }
}
