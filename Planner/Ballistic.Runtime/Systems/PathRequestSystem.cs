using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;
using Ballistic.Runtime.Paths;

namespace Ballistic.Runtime.Systems;

/// <summary>
/// Serves path requests after Detour's path queue: a request waits in a first-come queue; each tick starts at most
/// <see cref="WorldSettings.MaxSearchesPerTick"/> of them. A started request is one job, searched then animated in
/// the background (<see cref="WorldSettings.AnimationThreads"/>; on the tick with none), whose outcome (a path, a
/// failure, or the target reached already) is delivered to its agent exactly <see cref="WorldSettings.PathLatencyTicks"/>
/// later: the tick thread never searches, so no search, however long, makes a tick long (a world without
/// <see cref="WorldSettings.MaxAnimationWait"/>, which waits for late requests however long they take, has its tick
/// thread solve the requests no background thread has started while it waits: <see cref="Help"/>). Within the job, a path whose
/// animation shows a move (jump or walk) the body cannot perform is searched again without it (lazy repair, up to
/// <see cref="WorldSettings.RepairRounds"/> searches: the planner's <see cref="Planner.Query.PlanJob"/>, as
/// <see cref="Planner.Query.AnimatedPlanner"/> runs it) before it is reported as failed. Requests come from the world's
/// <see cref="PathQueue"/>, which the world's calls and the locomotion system fill. In a world with no background
/// threads the tick thread advances the started jobs itself, in request order, within
/// <see cref="WorldSettings.PlanningTimePerTick"/> a tick (Detour's sliced searches under a per-update budget),
/// finishing on its due tick any job not ended by then.
/// </summary>
internal sealed class PathRequestSystem : IDisposable
{
    private readonly WorldSettings _settings;
    private readonly AgentStore _agents;
    private readonly PathQueue _queue;
    private readonly EventBuffer _events;
    private readonly List<CharacterKind?> _kinds;
    private readonly List<RoadmapSearch?> _searches;
    private readonly List<PathRequest> _inFlight = [];
    private readonly RequestWorkers? _workers;
    private readonly Budget _slice = new();

    /// <summary>The requests whose jobs are advanced on the tick thread in slices (no background threads), until they end.</summary>
    private readonly HashSet<PathRequest> _stepped = new(ReferenceEqualityComparer.Instance);

    /// <summary>Per kind slot: the stances its delivered requests found the body cannot crouch on or absorb a landing on (<see cref="StanceLessons"/>).</summary>
    private readonly List<StanceLessons?> _lessons = [];

    public PathRequestSystem(WorldSettings settings, AgentStore agents, PathQueue queue, EventBuffer events, List<CharacterKind?> kinds, List<RoadmapSearch?> searches)
    {
        _queue = queue;
        _settings = settings;
        _agents = agents;
        _events = events;
        _kinds = kinds;
        _searches = searches;
        if (settings.AnimationThreads > 0)
        {
            _workers = new RequestWorkers(settings.AnimationThreads);
        }
    }

    /// <summary>Requests started and not delivered yet (searching or animating).</summary>
    public int Animating => _inFlight.Count;

    /// <summary>Requests started during the last tick.</summary>
    public int LastTickSearches { get; private set; }

    /// <summary>Requests a tick stopped waiting for (<see cref="WorldSettings.MaxAnimationWait"/> spent), since the world began.</summary>
    public long LateRequests { get; private set; }

    /// <summary>Steps the jobs advanced on the tick thread have taken during the last tick.</summary>
    public int LastTickSteps { get; private set; }

    public void Update(long tick, double time)
    {
        Start(tick);
        Advance();
        Deliver(tick, time);
    }

    private void Start(long tick)
    {
        int started = 0;
        while (started < _settings.MaxSearchesPerTick && _queue.TryTake(out PathRequest? request))
        {
            int slot = request.Agent.Index;
            if (!Current(request))
            {
                _queue.Return(request); // replaced or cancelled before it started
                continue;
            }

            started++;
            int kind = _agents.Kind[slot];
            request.Start = _agents.Stance[slot]!;
            StanceLessons lessons = Lessons(kind);
            request.Character = lessons.Kind;
            request.DueTick = tick + _settings.PathLatencyTicks;
            RequestJob job = request.Job;
            job.Begin(lessons.Kind, _searches[kind]!, request, lessons.Taught, _settings.RepairRounds, _settings.AnimationFrameRate);
            if (_workers is null)
            {
                // Advanced on this thread: whole now, or in slices from this tick on (Advance).
                bool whole = _settings.PlanningTimePerTick is null;
                request.Outcome = whole ? job.Run() : null;
                if (!whole)
                {
                    _stepped.Add(request);
                }
            }
            else
            {
                _workers.Enqueue(job);
            }

            _inFlight.Add(request);
            _agents.State[slot] = AgentState.Stance;
        }

        LastTickSearches = started;
    }

    /// <summary>
    /// Advances the jobs run on the tick thread in slices (no background threads), in request order, until
    /// <see cref="WorldSettings.PlanningTimePerTick"/> is spent: each job from where it stopped, given what is left of
    /// the budget; at least one step a tick.
    /// </summary>
    private void Advance()
    {
        LastTickSteps = 0;
        if (_workers is not null || _settings.PlanningTimePerTick is not { } budget)
        {
            return;
        }

        long began = System.Diagnostics.Stopwatch.GetTimestamp();
        foreach (PathRequest request in _inFlight)
        {
            if (!_stepped.Contains(request) || !Current(request))
            {
                continue;
            }

            // At least one step a tick, however small the budget: no job starves.
            TimeSpan left = budget - System.Diagnostics.Stopwatch.GetElapsedTime(began);
            if (left <= TimeSpan.Zero && LastTickSteps > 0)
            {
                break;
            }

            RequestJob job = request.Job;
            int before = job.Steps;
            _slice.Left = left;
            request.Outcome = job.Advance(_slice);
            LastTickSteps += job.Steps - before;
            if (request.Outcome is not null)
            {
                Ended(request);
            }
        }
    }

    private void Deliver(long tick, double time)
    {
        // In request order; a request re-queued for repair leaves the list, so walk it with an index.
        int kept = 0;
        long waitStart = 0;
        for (int i = 0; i < _inFlight.Count; i++)
        {
            PathRequest request = _inFlight[i];
            bool due = request.DueTick <= tick;
            bool ready = Ready(request);
            if (!Current(request))
            {
                if (_stepped.Remove(request))
                {
                    request.Job.Dispose(); // advanced on this thread: dropped where it stands
                    _queue.Return(request);
                }
                else if (!ready)
                {
                    _inFlight[kept++] = request; // let the job finish before dropping it
                }
                else
                {
                    _queue.Return(request);
                }

                continue;
            }

            if (due && !ready && _settings.WaitForAnimation && !request.Late)
            {
                ready = Await(i, ref waitStart);
                if (!ready)
                {
                    request.Late = true;
                    LateRequests++;
                }
            }

            if (!due || !ready)
            {
                _inFlight[kept++] = request;
                continue;
            }

            int slot = request.Agent.Index;
            RequestOutcome outcome = request.Outcome ?? request.Job.Outcome
                ?? new RequestOutcome(null, [], null, new InvalidOperationException("A request's job ended with no outcome."), Searching: false);

            // What the request found about its roadmap's stances, for the requests started from the next tick on.
            int kind = _agents.Kind[slot];
            if (outcome.Error is null && _kinds[kind] is { } owner && ReferenceEquals(owner, request.Character) && request.Job.Repair is { } repair)
            {
                Lessons(kind).Learn(repair);
            }

            Conclude(slot, request, outcome, tick, time);
            _queue.Return(request);
        }

        _inFlight.RemoveRange(kept, _inFlight.Count - kept);
    }

    /// <summary>Stances the body cannot crouch on or absorb a landing on found so far by the kind in slot <paramref name="kind"/>: anew when another kind (a rebake) took the slot.</summary>
    private StanceLessons Lessons(int kind)
    {
        while (_lessons.Count <= kind)
        {
            _lessons.Add(null);
        }

        CharacterKind owner = _kinds[kind]!;
        if (_lessons[kind] is not { } lessons || !ReferenceEquals(lessons.Kind, owner))
        {
            lessons = new StanceLessons(owner);
            _lessons[kind] = lessons;
        }

        return lessons;
    }

    /// <summary>True when the request's outcome can be read now: run on the tick thread, or its job ended.</summary>
    private bool Ready(PathRequest request) => request.Outcome is not null || (!_stepped.Contains(request) && (_workers is null || request.Job.Ended));

    /// <summary>
    /// Waits for the in-flight request at <paramref name="index"/> within what is left of this tick's
    /// <see cref="WorldSettings.MaxAnimationWait"/> (counted from the first wait of the tick,
    /// <paramref name="waitStart"/>); true when it ended (a failed job too: its outcome says so). Without a limit (an
    /// offline world, where only the outcome matters, not how long a tick takes) this thread works instead of idling
    /// until it ends (<see cref="Help"/>): an outcome is the same whichever thread solves it.
    /// </summary>
    private bool Await(int index, ref long waitStart)
    {
        PathRequest request = _inFlight[index];
        if (_stepped.Contains(request))
        {
            return Finish(request, request.Job, ref waitStart);
        }

        if (_settings.MaxAnimationWait is not { } limit)
        {
            while (!Ready(request))
            {
                if (!Help(index))
                {
                    _workers!.WaitFor(request.Job, null);
                }
            }

            return true;
        }

        TimeSpan left = WaitLeft(limit, ref waitStart);
        return left > TimeSpan.Zero && _workers!.WaitFor(request.Job, left);
    }

    /// <summary>
    /// Finishes on this thread a request advanced here in slices that is due (<see cref="Await"/>): to its end without
    /// a <see cref="WorldSettings.MaxAnimationWait"/>, otherwise within what is left of it this tick; true when it ended.
    /// </summary>
    private bool Finish(PathRequest request, RequestJob job, ref long waitStart)
    {
        if (_settings.MaxAnimationWait is not { } limit)
        {
            request.Outcome = job.Run();
        }
        else
        {
            TimeSpan left = WaitLeft(limit, ref waitStart);
            if (left <= TimeSpan.Zero)
            {
                return false;
            }

            _slice.Left = left;
            request.Outcome = job.Advance(_slice);
        }

        if (request.Outcome is null)
        {
            return false;
        }

        Ended(request);
        return true;
    }

    /// <summary>Forgets the job of a request advanced on the tick thread once it ended.</summary>
    private void Ended(PathRequest request) => _stepped.Remove(request);

    /// <summary>What is left this tick of <see cref="WorldSettings.MaxAnimationWait"/> (<paramref name="limit"/>), counted from the tick's first wait (<paramref name="waitStart"/>, set by the first call).</summary>
    private static TimeSpan WaitLeft(TimeSpan limit, ref long waitStart)
    {
        if (waitStart == 0)
        {
            waitStart = System.Diagnostics.Stopwatch.GetTimestamp();
        }

        return limit - System.Diagnostics.Stopwatch.GetElapsedTime(waitStart);
    }

    /// <summary>
    /// Runs on this thread, to its end, the first request from <paramref name="index"/> on in request order (the one
    /// waited for first) whose job no background thread has started; false when every one has started.
    /// </summary>
    private bool Help(int index)
    {
        for (int j = index; j < _inFlight.Count; j++)
        {
            PathRequest other = _inFlight[j];
            if (Ready(other) || _workers is null || !Current(other))
            {
                continue;
            }

            if (other.Job.TryRun() is { } outcome)
            {
                other.Outcome = outcome;
                return true;
            }
        }

        return false;
    }

    /// <summary>Delivers a request's outcome on its due tick: a clean path to follow, a failure (the search's, or no path animating cleanly), or the target reached already.</summary>
    private void Conclude(int slot, PathRequest request, RequestOutcome outcome, long tick, double time)
    {
        if (outcome.Error is { } error)
        {
            Fail(slot, request, outcome.Searching ? PlannerStatus.NoPath : PlannerStatus.AnimationFailed, $"internal error while {(outcome.Searching ? "searching" : "animating")}: {error.Message}", tick, time);
            return;
        }

        if (outcome.Search is { Status: not PlannerStatus.Exact } failed)
        {
            Fail(slot, request, failed.Status, failed.Reason, tick, time);
            return;
        }

        if (outcome.Animation is not { } animation)
        {
            // The search found the agent on its target already.
            _agents.Request[slot] = null;
            _agents.State[slot] = AgentState.Idle;
            _agents.HasTarget[slot] = false;
            _agents.Navigate(slot, NavigationStatus.Reached);
            _events.Add(new JumpEvent(JumpEventKind.TargetReached, request.Agent, tick, time, -1, _agents.Root[slot].Position, request.Target, default, 0f, PlannerStatus.Exact, null));
            return;
        }

        AgentPath path = outcome.Path ?? new AgentPath(request.Target, outcome.Moves, animation);
        _agents.Request[slot] = null;
        _agents.Stance[slot] = null;
        _agents.Path[slot] = path;
        _agents.PathStart[slot] = time;
        _agents.Cursor[slot] = 0;
        _agents.StopAtStance[slot] = false;
        _agents.Navigate(slot, NavigationStatus.Following);
        _events.Add(new JumpEvent(JumpEventKind.PathFound, request.Agent, tick, time, -1, path.Start.Pose.Position, request.Target, default, 0f, PlannerStatus.Exact, null, path));
    }

    private void Fail(int slot, PathRequest request, PlannerStatus status, string reason, long tick, double time)
    {
        _agents.Request[slot] = null;
        _agents.State[slot] = AgentState.Idle;
        _agents.Navigate(slot, NavigationStatus.Failed, reason);
        _events.Add(new JumpEvent(JumpEventKind.PathFailed, request.Agent, tick, time, -1, _agents.Root[slot].Position, request.Target, default, 0f, status, reason));
    }

    /// <summary>
    /// The slice a job advanced on the tick thread may take (<see cref="PlanJob.Advance"/>): stop once
    /// <see cref="Left"/> has passed since the call began. Set before each call, on the tick thread only.
    /// </summary>
    private sealed class Budget : TerminationCondition
    {
        public TimeSpan Left { get; set; }

        public override bool ShouldStop(in BakeState state, out PlannerStatus status, out string reason) =>
            ShouldStopNow(state.Elapsed, out status, out reason);

        public override bool ShouldStopNow(TimeSpan elapsed, out PlannerStatus status, out string reason)
        {
            status = PlannerStatus.Timeout;
            reason = "the tick's planning time is spent";
            return elapsed >= Left;
        }
    }

    /// <summary>True while the request is its agent's pending one (the agent was neither removed nor given another request).</summary>
    private bool Current(PathRequest request) =>
        _agents.IsValid(request.Agent) && ReferenceEquals(_agents.Request[request.Agent.Index], request);

    public void Dispose()
    {
        // The background threads finish the jobs they are running; the queued ones are not run.
        _workers?.Dispose();
        foreach (PathRequest request in _inFlight)
        {
            if (_stepped.Contains(request))
            {
                request.Job.Dispose();
            }
        }
    }
}
