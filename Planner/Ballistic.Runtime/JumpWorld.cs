using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;
using Ballistic.Runtime.Paths;
using BodyPointRunner = Ballistic.Runtime.Systems.BodyPointSystem;
using LocomotionRunner = Ballistic.Runtime.Systems.LocomotionSystem;
using PathRequestRunner = Ballistic.Runtime.Systems.PathRequestSystem;
using PoseRunner = Ballistic.Runtime.Systems.PoseSystem;
using RoadmapSearch = Ballistic.Runtime.Kinds.RoadmapSearch;

namespace Ballistic.Runtime;

/// <summary>
/// Many agents navigating one level by jumps and walks, stepped per tick: the ECS core under the Godot nodes. The world holds
/// one frozen roadmap per character kind (like a navigation map with one region per agent size), agents as
/// entities whose components live in arrays (<see cref="AgentHandle"/>s name them; a game adds its own components
/// with <see cref="AddComponentColumn{T}"/> and iterates agents with <see cref="Query"/>), and an ordered list of
/// systems run by <see cref="Step()"/> (<see cref="Systems"/>): by default path requests (a budgeted queue), locomotion
/// (exactly on the arcs and along the walks), pose (joint buffers from the whole-body animation), and the game's own
/// inserted between them. Changes recorded in <see cref="Commands"/> are played back at the start of each tick. What
/// happened comes out as <see cref="Events"/>.
/// </summary>
/// <remarks>
/// <para>
/// One table for everything the Godot nodes register, in any order: a kind may exist before its roadmap
/// (<see cref="CreateKind"/>; a rebake or a clear is <see cref="ReplaceKind"/>, a node leaving <see cref="RemoveKind"/>),
/// and each agent is one entity whose handle never changes while it lives; its <see cref="AgentLifecycle"/> says
/// whether it is simulated (on its kind's roadmap) or waits for a roadmap, for a place to stand, or was detached
/// with its kind. A world made without a level takes its first roadmap's and moves to another only while no kind
/// holds one.
/// </para>
/// <para>
/// Deterministic: the same kinds, settings and calls between the same ticks give the same trajectories and events,
/// whatever <see cref="WorldSettings.AnimationThreads"/> (with <see cref="WorldSettings.WaitForAnimation"/>, the
/// default). Calls and <see cref="Step()"/> belong on one thread (the game loop); animations are solved on others.
/// A change called from another thread while the world steps or changes is refused with
/// <see cref="RuntimeStatus.Busy"/> (<see cref="Step()"/> and <see cref="Dispose"/> wait for a call in progress), so a
/// breach never corrupts the world; changes from other threads go through <see cref="Commands"/>.
/// No call throws for a bad handle or bad input: each returns a <see cref="RuntimeResult"/> with the reason, and
/// no exception escapes a tick. After <see cref="Dispose"/> every call that changes the world does nothing and
/// returns <see cref="RuntimeStatus.Disposed"/>; <see cref="Step()"/> throws. Positions are the trunk centre in world
/// metres, Y up; times are seconds.
/// </para>
/// </remarks>
public sealed class JumpWorld : IDisposable
{
    private readonly List<CharacterKind?> _kinds = [];
    private readonly List<RoadmapSearch?> _searches = [];
    private readonly List<string> _kindNames = [];
    private readonly List<int> _kindGenerations = [];
    private readonly List<bool> _kindAlive = [];
    private readonly Stack<int> _freeKinds = new();
    private readonly List<(float Distance, int Id)> _nearest = [];
    private int[] _seen = [];
    private int[] _goal = [];
    private int[] _stack = [];
    private int _stamp;

    /// <summary>The level was given at construction: kinds of another level are refused even while no kind holds a roadmap.</summary>
    private readonly bool _levelPinned;
    private readonly AgentStore _agents = new();
    private readonly EventBuffer _events = new();
    private readonly EventBuffer _pending = new();
    private readonly PathQueue _queue;
    private readonly PathRequestRunner _requests;
    private readonly PoseRunner _pose;
    private readonly List<IComponentColumn> _columns = [];
    private readonly Action<IJumpSystem, Exception> _systemFailed;
    private readonly Action<AgentHandle, string> _commandRefused;
    private readonly Action<AgentHandle, Vector3, string?> _commandAdded;
    private bool _disposed;

    /// <summary>Held by the thread stepping or changing the world (<see cref="Gate"/>).</summary>
    private readonly object _gate = new();

    /// <summary>Agents flagged <see cref="AgentStore.Rehome"/>: the tick looks for those that stopped only while there are some.</summary>
    private int _rehoming;

    /// <summary>Creates an empty world on a level, which it keeps: a kind of another level is refused.</summary>
    /// <param name="level">The level every kind's scene must be built on.</param>
    /// <param name="settings">Tick rate, budgets and threads; defaults when <c>null</c>.</param>
    /// <exception cref="ArgumentException">A setting is out of range.</exception>
    public JumpWorld(Level level, WorldSettings? settings = null)
        : this(settings)
    {
        ArgumentNullException.ThrowIfNull(level);
        Level = level;
        _levelPinned = true;
    }

    /// <summary>
    /// Creates an empty world whose level follows its kinds, as a game's scenes change: the level of the first kind
    /// given a roadmap; a kind of another level is refused while some kind holds a roadmap, and becomes the world's
    /// level when none does (the scene was changed and the old kinds cleared or removed).
    /// </summary>
    /// <param name="settings">Tick rate, budgets and threads; defaults when <c>null</c>.</param>
    /// <exception cref="ArgumentException">A setting is out of range.</exception>
    public JumpWorld(WorldSettings? settings = null)
    {
        Settings = settings ?? new WorldSettings();
        if (Settings.Problem() is { } problem)
        {
            throw new ArgumentException($"World settings: {problem}.", nameof(settings));
        }

        Settings.Tolerance.Validate();
        _queue = new PathQueue(_agents);
        _requests = new PathRequestRunner(Settings, _agents, _queue, _events, _kinds, _searches);
        var locomotion = new LocomotionRunner(_agents, _events, _queue);
        _pose = new PoseRunner(_agents);
        var body = new BodyPointRunner(_agents);
        PathRequestSystem = new BuiltInSystem(this, "path-request system", _requests.Update);
        LocomotionSystem = new BuiltInSystem(this, "locomotion system", locomotion.Update);
        BodyPointSystem = new BuiltInSystem(this, "body-point system", (_, time) => body.Update(time));
        PoseSystem = new BuiltInSystem(this, "pose system", (_, time) => _pose.Update(time));
        Systems = new JumpSystemList(this, [PathRequestSystem, LocomotionSystem, BodyPointSystem, PoseSystem]);
        Commands = new JumpCommandBuffer();
        _systemFailed = (system, e) => _events.Add(new JumpEvent(JumpEventKind.SystemFailed, default, Tick, Time, -1, default, default, default, 0f, Planner.Planning.PlannerStatus.Exact,
            OneLine.Of($"{JumpSystemList.Describe(system)} threw {e.GetType().Name}: {e.Message} (the tick went on with the next system)")));
        _commandRefused = (agent, reason) => _pending.Add(new JumpEvent(JumpEventKind.CommandRefused, agent, Tick, Time, -1, default, default, default, 0f, Planner.Planning.PlannerStatus.Exact, reason));
        _commandAdded = (agent, point, reason) => _pending.Add(new JumpEvent(JumpEventKind.Added, agent, Tick, Time, -1, point, default, default, 0f, Planner.Planning.PlannerStatus.Exact, reason));
    }

    /// <summary>
    /// The systems <see cref="Step()"/> runs, in order: by default <see cref="PathRequestSystem"/>,
    /// <see cref="LocomotionSystem"/>, <see cref="BodyPointSystem"/>, <see cref="PoseSystem"/>. Insert the game's own
    /// between them; remove the pose system when nobody reads poses (the body-point system when nobody reads body
    /// points: the Godot nodes do).
    /// </summary>
    public JumpSystemList Systems { get; }

    /// <summary>
    /// The path-request system: starts queued requests within the tick's budget
    /// (<see cref="WorldSettings.MaxSearchesPerTick"/>), each searched and animated in the background, and delivers each
    /// outcome <see cref="WorldSettings.PathLatencyTicks"/> after its start (<see cref="JumpEventKind.PathFound"/>,
    /// <see cref="JumpEventKind.PathFailed"/>): the tick itself never searches, except that a world without
    /// <see cref="WorldSettings.MaxAnimationWait"/> solves, while it waits for a late request, those no background
    /// thread has started.
    /// </summary>
    public IJumpSystem PathRequestSystem { get; }

    /// <summary>
    /// The locomotion system: moves each agent along its path (root poses exactly on the arcs and walks, states), emits
    /// the takeoff, landing, walk and arrival events, and queues a new request for an agent stopping with a target.
    /// </summary>
    public IJumpSystem LocomotionSystem { get; }

    /// <summary>
    /// The body-point system: writes each agent's body point (<see cref="GetBodyPoint"/>: where a game puts its body
    /// node, with velocity and heading) from its path at this tick.
    /// </summary>
    public IJumpSystem BodyPointSystem { get; }

    /// <summary>The pose system: fills each agent's joint angles and rotations from its animation (<see cref="GetJointRotations"/>), for agents with poses enabled.</summary>
    public IJumpSystem PoseSystem { get; }

    /// <summary>
    /// The world's command buffer: changes recorded from any thread, played back in order at the start of the next
    /// <see cref="Step()"/>, before the systems run.
    /// </summary>
    public JumpCommandBuffer Commands { get; }

    /// <summary>True from <see cref="Dispose"/> on.</summary>
    internal bool IsDisposed => _disposed;

    /// <summary>True while <see cref="Step()"/> runs.</summary>
    internal bool IsStepping { get; private set; }

    /// <summary>
    /// Adds a column for a component of the game's own (stamina, a look-at point, a team): one value of
    /// <typeparamref name="T"/> per agent that has one (<see cref="ComponentColumn{T}.Set"/>), forgotten when the agent
    /// is removed. Systems select agents that have it with <see cref="AgentQuery.With{T}"/>.
    /// </summary>
    /// <param name="name">The component's name, for messages.</param>
    /// <exception cref="ObjectDisposedException">The world was disposed.</exception>
    public ComponentColumn<T> AddComponentColumn<T>(string name)
        where T : struct
    {
        using Gate gate = Gate.Wait(_gate);
        ObjectDisposedException.ThrowIf(_disposed, this);
        var column = new ComponentColumn<T>(this, _agents, string.IsNullOrWhiteSpace(name) ? typeof(T).Name : name);
        _columns.Add(column);
        return column;
    }

    /// <summary>
    /// The active agents (<see cref="AgentLifecycle.Active"/>: on their kind's roadmap) <paramref name="query"/>
    /// selects, for <c>foreach</c>, in slot order; allocates nothing. A query naming another world's column selects
    /// nobody.
    /// </summary>
    public AgentQueryResult Query(in AgentQuery query) => new(_agents, query, _disposed || !query.IsOf(this));

    /// <summary>The level: the one given at construction, else that of the kinds holding roadmaps (the last one while none does); <c>null</c> before any.</summary>
    public Level? Level { get; private set; }

    /// <summary>The settings.</summary>
    public WorldSettings Settings { get; }

    /// <summary>Ticks stepped so far.</summary>
    public long Tick { get; private set; }

    /// <summary>World time, seconds: <see cref="Tick"/> × <see cref="WorldSettings.TickSeconds"/>.</summary>
    public double Time => Tick * Settings.TickSeconds;

    /// <summary>
    /// Every agent's root pose (<see cref="GetRootPose"/>) as one span indexed by <see cref="AgentHandle.Index"/>, for
    /// systems and game code that read many agents a query selected (<c>world.RootPoses[agent.Index]</c>), as a DOTS
    /// job reads a component array. Entries of slots without an active agent are stale. Valid until the next change
    /// that adds an agent; written by the systems only.
    /// </summary>
    public ReadOnlySpan<RootPose> RootPoses => _agents.Root.AsSpan(0, _agents.HighWater);

    /// <summary>Every agent's body point (<see cref="GetBodyPoint"/>) as one span indexed by <see cref="AgentHandle.Index"/>; as <see cref="RootPoses"/>.</summary>
    public ReadOnlySpan<BodyPoint> BodyPoints => _agents.Body.AsSpan(0, _agents.HighWater);

    /// <summary>What every agent does this tick (<see cref="GetState"/>) as one span indexed by <see cref="AgentHandle.Index"/>; as <see cref="RootPoses"/>.</summary>
    public ReadOnlySpan<AgentState> States => _agents.State.AsSpan(0, _agents.HighWater);

    /// <summary>Where every agent's navigation stands (<see cref="GetNavigationStatus"/>) as one span indexed by <see cref="AgentHandle.Index"/>; as <see cref="RootPoses"/>.</summary>
    public ReadOnlySpan<NavigationStatus> NavigationStatuses => _agents.Navigation.AsSpan(0, _agents.HighWater);

    /// <summary>
    /// Where the agent's navigation stands: idle (no target), planning, following a path, reached its target, or
    /// failed (<see cref="GetNavigationFailure"/>); <see cref="NavigationStatus.Idle"/> for an unknown agent.
    /// </summary>
    public NavigationStatus GetNavigationStatus(AgentHandle agent) => _agents.IsValid(agent) ? _agents.Navigation[agent.Index] : NavigationStatus.Idle;

    /// <summary>Why the agent's last path failed, while its status is <see cref="NavigationStatus.Failed"/>; otherwise <c>null</c>.</summary>
    public string? GetNavigationFailure(AgentHandle agent) => _agents.IsValid(agent) ? _agents.NavigationFailure[agent.Index] : null;

    /// <summary>Agents added and not removed, in any <see cref="AgentLifecycle"/>.</summary>
    public int AgentCount => _agents.Count;

    /// <summary>The character kinds (scene, roadmap, animator), by <see cref="KindHandle.Index"/>; <c>null</c> for a kind without a roadmap (or removed).</summary>
    public IReadOnlyList<CharacterKind?> Kinds => _kinds;

    /// <summary>The events of the last <see cref="Step()"/>, in order: path found or failed, then takeoffs, landings, walks started and finished, and arrivals.</summary>
    public ReadOnlySpan<JumpEvent> Events => _events.Events;

    /// <summary>
    /// The events of <paramref name="agent"/> during the last <see cref="Step()"/>, in order (the same events as in
    /// <see cref="Events"/>, one contiguous range per agent): what a game object of one agent reads each tick without
    /// walking every agent's events. Empty for an agent with none, or unknown. Allocates nothing once the buffers have
    /// grown; valid until the next <see cref="Step()"/>.
    /// </summary>
    public ReadOnlySpan<JumpEvent> EventsOf(AgentHandle agent)
    {
        // The first read after a change sorts the buffer: never while another thread steps.
        using Gate gate = Gate.Wait(_gate);
        return _disposed ? [] : _events.Of(agent, _agents.Generation.Length);
    }

    /// <summary>Path requests waiting for a search.</summary>
    public int QueuedRequests => _queue.Count;

    /// <summary>Requests started and not delivered yet: being searched or animated, or waiting for their due tick.</summary>
    public int AnimatingRequests => _requests.Animating;

    /// <summary>Requests started (searches) during the last tick.</summary>
    public int LastTickSearches => _requests.LastTickSearches;

    /// <summary>
    /// Steps the tick thread took during the last tick advancing path requests in slices (a world with no background
    /// threads, <see cref="WorldSettings.PlanningTimePerTick"/>; the steps taken finishing a due request not counted).
    /// </summary>
    public int LastTickPlanningSteps => _requests.LastTickSteps;

    /// <summary>
    /// Path requests a tick stopped waiting for, since the world began: their animation was late on their due tick and
    /// <see cref="WorldSettings.MaxAnimationWait"/> was spent, so they were delivered at the first tick they were ready
    /// (the run then depends on machine speed). Zero on a machine that keeps up, and always with no wait limit.
    /// </summary>
    public long LateRequests => _requests.LateRequests;


    /// <summary>Adds a character kind; its scene must be of this world's level and its roadmap baked for it.</summary>
    public AddKindResult AddKind(CharacterKind kind)
    {
        using Gate gate = Gate.Enter(_gate, "world", out RuntimeResult? busy);
        if (busy is { } crowded)
        {
            return new AddKindResult(crowded, default);
        }

        if (Gone() is { } gone)
        {
            return new AddKindResult(gone, default);
        }

        if (Check(kind, -1) is { } refused)
        {
            return new AddKindResult(refused, default);
        }

        KindHandle handle = NewKind(kind.Name);
        Level = kind.Scene.Level;
        _kinds[handle.Index] = kind;
        SetSearch(handle.Index, new RoadmapSearch(kind, Settings));
        return new AddKindResult(RuntimeResult.Success, handle);
    }

    /// <summary>
    /// Creates a kind without a roadmap yet (a <c>JumpRoadmap3D</c> node gets its handle when first asked, so that
    /// agents readied before it can name it): agents added to it wait (<see cref="AgentLifecycle.Waiting"/>) until
    /// <see cref="ReplaceKind"/> gives it one. The default handle after <see cref="Dispose"/>, or while another
    /// thread changes the world.
    /// </summary>
    /// <param name="name">A name for messages (the node's path); "kind N" when empty.</param>
    public KindHandle CreateKind(string name)
    {
        using Gate gate = Gate.Enter(_gate, "world", out RuntimeResult? busy);
        return busy is null && !_disposed ? NewKind(name) : default;
    }

    /// <summary>A new kind without a roadmap, in a freed index when there is one.</summary>
    private KindHandle NewKind(string? name)
    {
        int index;
        if (_freeKinds.Count > 0)
        {
            index = _freeKinds.Pop();
        }
        else
        {
            index = _kinds.Count;
            _kinds.Add(null);
            _searches.Add(null);
            _kindNames.Add("");
            _kindGenerations.Add(0);
            _kindAlive.Add(false);
        }

        _kindGenerations[index]++;
        _kindAlive[index] = true;
        _kindNames[index] = string.IsNullOrWhiteSpace(name) ? $"kind {index}" : name;
        _kinds[index] = null;
        SetSearch(index, null);
        return new KindHandle(index, _kindGenerations[index]);
    }

    /// <summary>True while <paramref name="kind"/> names a kind of this world (with or without a roadmap).</summary>
    public bool IsValid(KindHandle kind) =>
        kind.Assigned && (uint)kind.Index < (uint)_kinds.Count && _kindAlive[kind.Index] && _kindGenerations[kind.Index] == kind.Generation;

    /// <summary>The kind's name (its character's, or the one given to <see cref="CreateKind"/>); <c>null</c> for an unknown kind.</summary>
    public string? GetKindName(KindHandle kind) => IsValid(kind) ? _kindNames[kind.Index] : null;

    /// <summary>The kind's scene, roadmap and animator; <c>null</c> while it has no roadmap (or is unknown).</summary>
    public CharacterKind? GetKindCharacter(KindHandle kind) => IsValid(kind) ? _kinds[kind.Index] : null;

    /// <summary>
    /// The background preparation of the kind's searches (<see cref="WorldSettings.PrepareSearches"/>), for a loading
    /// screen to wait for: it completes with the node pairs prepared (fewer when the kind was removed or given another
    /// roadmap meanwhile), or is cancelled when that happened before it began. <c>null</c> when the world does not
    /// prepare, or the kind is unknown or has no roadmap.
    /// </summary>
    public Task<int>? GetKindPreparation(KindHandle kind) => IsValid(kind) ? _searches[kind.Index]?.Preparation : null;

    /// <summary>
    /// Removes a kind: its agents leave the simulation for good (<see cref="AgentLifecycle.Detached"/>), each with a
    /// <see cref="JumpEventKind.Removed"/> event saying so; their handles stay valid until they are removed.
    /// </summary>
    public RuntimeResult RemoveKind(KindHandle kind)
    {
        using Gate gate = EnterFor(kind, out RuntimeResult? entry);
        if (entry is { } refusal)
        {
            return refusal;
        }

        string reason = $"kind '{_kindNames[kind.Index]}' was removed";
        int count = Lift(kind.Index, AgentLifecycle.Detached, reason, everyone: true);
        _kinds[kind.Index] = null;
        SetSearch(kind.Index, null);
        _kindAlive[kind.Index] = false;
        _freeKinds.Push(kind.Index);
        return new RuntimeResult(RuntimeStatus.Ok, $"{reason}: {Count(count)} detached");
    }

    /// <summary>
    /// Takes the agents of kind <paramref name="kind"/> out of the simulation into <paramref name="lifecycle"/>, each
    /// standing where it stands (or lands), told by a <see cref="JumpEventKind.Removed"/> event; with
    /// <paramref name="everyone"/>, those already out too. Returns how many were told.
    /// </summary>
    private int Lift(int kind, AgentLifecycle lifecycle, string reason, bool everyone)
    {
        int count = 0;
        for (int slot = 0; slot < _agents.HighWater; slot++)
        {
            if (!_agents.Registered[slot] || _agents.Kind[slot] != kind || !(_agents.Alive[slot] || everyone) || _agents.Lifecycle[slot] == AgentLifecycle.Detached)
            {
                continue;
            }

            count++;
            Vector3 point = _agents.Alive[slot] && Standing(slot) is { } stance ? stance.ContactCentre : _agents.Point[slot];
            if (_agents.Alive[slot])
            {
                _queue.Cancel(slot);
                SetRehome(slot, false);
            }

            _agents.Deactivate(slot, lifecycle, reason, point);
            _pending.Add(new JumpEvent(JumpEventKind.Removed, _agents.HandleOf(slot), Tick, Time, -1, point, _agents.Target[slot], default, 0f, Planner.Planning.PlannerStatus.Exact, reason));
        }

        return count;
    }

    /// <summary>
    /// Puts the agent in <paramref name="slot"/>, out of the simulation, on its kind's roadmap where it stands, its
    /// target asked again; otherwise leaves it <see cref="AgentLifecycle.Unplaced"/>, told by a
    /// <see cref="JumpEventKind.Removed"/> event when <paramref name="tell"/>. Returns why it could not stand, or <c>null</c>.
    /// </summary>
    private RuntimeResult? Place(int slot, bool tell)
    {
        CharacterKind kind = _kinds[_agents.Kind[slot]]!;
        Vector3 point = _agents.Point[slot];
        if (Stand(kind, point, out RuntimeResult failure) is not { } stance)
        {
            string reason = $"cannot stand at {point} on the roadmap of kind '{_kindNames[_agents.Kind[slot]]}': {failure.Reason}";
            _agents.Deactivate(slot, AgentLifecycle.Unplaced, reason, point);
            if (tell)
            {
                _pending.Add(new JumpEvent(JumpEventKind.Removed, _agents.HandleOf(slot), Tick, Time, -1, point, _agents.Target[slot], default, 0f, Planner.Planning.PlannerStatus.Exact, reason));
            }

            return new RuntimeResult(failure.Status, reason);
        }

        _agents.Activate(slot, kind, stance.Node.Pose, stance.Node, stance.Angles);
        PlaceBody(slot);
        if (_agents.HasTarget[slot])
        {
            _agents.State[slot] = AgentState.Stance;
            _queue.Request(slot);
        }

        return null;
    }

    /// <summary>
    /// Replaces a kind's scene, roadmap and animator in place (a rebake), keeping its handle and its agents, each
    /// under its own handle and never moved by the swap:
    /// <list type="bullet">
    /// <item>An agent standing (idle, or waiting for its path) moves over at once: its pending request is dropped and
    /// its target asked again on the new roadmap.</item>
    /// <item>An agent in a move (a jump, or a walk) finishes that move as it was animated and stops on the stance it
    /// ends on, as when its target changes; there it moves over and plans anew toward its target. Between two moves,
    /// it stops before the next one starts.</item>
    /// </list>
    /// Moving over, an agent of an unchanged character keeps the very stance it stands on (the new roadmap's node of
    /// that pose, or a stance off the roadmap, from which searches steer into it as from any stance placed by
    /// <see cref="AddAgent"/>). For a changed character it stands on the new roadmap's node whose contacts stand there
    /// (within <see cref="WorldSettings.Tolerance"/>) or on a stance placed there, its pose buffers sized for the new
    /// rig; where the new character cannot stand, it is removed with a <see cref="JumpEventKind.Removed"/> event
    /// saying why.
    /// The replacement must pass the checks of <see cref="AddKind"/>; a refused replacement leaves the kind and its
    /// agents as they were. The result's reason counts the agents put on the new roadmap, those finishing a move first
    /// and those removed.
    /// </summary>
    /// <param name="kind">The kind to replace.</param>
    /// <param name="replacement">The new scene, roadmap and animator.</param>
    public RuntimeResult ReplaceKind(KindHandle kind, CharacterKind? replacement)
    {
        using Gate gate = EnterFor(kind, out RuntimeResult? entry);
        if (entry is { } refusal)
        {
            return refusal;
        }

        string name = _kindNames[kind.Index];
        if (replacement is null)
        {
            // Cleared: its agents leave the simulation and wait for a roadmap.
            int lifted = Lift(kind.Index, AgentLifecycle.Waiting, $"kind '{name}' lost its roadmap: the agent waits for a new one", everyone: false);
            _kinds[kind.Index] = null;
            SetSearch(kind.Index, null);
            return new RuntimeResult(RuntimeStatus.Ok, $"kind '{name}' cleared: {Count(lifted)} wait for a roadmap");
        }

        if (Check(replacement, kind.Index) is { } refused)
        {
            return refused;
        }

        if (_kinds[kind.Index] is { } old && old.Scene.Level.Fingerprint != replacement.Scene.Level.Fingerprint)
        {
            // The only kind with a roadmap moves to another level: its agents start again from where they stand.
            Lift(kind.Index, AgentLifecycle.Waiting, $"kind '{name}' moved to another level", everyone: false);
            _kinds[kind.Index] = null;
        }

        Level = replacement.Scene.Level;
        bool joining = _kinds[kind.Index] is null;
        _kinds[kind.Index] = replacement;
        SetSearch(kind.Index, new RoadmapSearch(replacement, Settings));
        if (joining)
        {
            return Join(kind.Index, replacement);
        }

        int placed = 0;
        int finishing = 0;
        int removed = 0;
        string? why = null;
        for (int slot = 0; slot < _agents.HighWater; slot++)
        {
            if (!_agents.Registered[slot] || _agents.Kind[slot] != kind.Index)
            {
                continue;
            }

            if (!_agents.Alive[slot])
            {
                // Unplaced on the old roadmap: tried again on the new one.
                if (_agents.Lifecycle[slot] == AgentLifecycle.Unplaced && Place(slot, tell: false) is null)
                {
                    placed++;
                }

                continue;
            }

            if (_agents.Path[slot] is not null)
            {
                // In a move: it ends it on the roadmap it was planned on, then stops and moves over (Rehome).
                _agents.StopAtStance[slot] = true;
                _queue.Cancel(slot);
                SetRehome(slot, true);

                finishing++;
            }
            else if (Rehome(slot) is { } failure)
            {
                removed++;
                why ??= failure;
            }
            else
            {
                placed++;
            }
        }

        return new RuntimeResult(RuntimeStatus.Ok,
            $"kind '{replacement.Name}' replaced: {Count(placed)} put on its new roadmap, {Count(finishing)} finishing a move first, {Count(removed)} unplaced" + (why is null ? "" : $" ({why})"));
    }

    /// <summary>Puts the waiting and unplaced agents of a kind just given its roadmap on it, where each stands.</summary>
    private RuntimeResult Join(int kind, CharacterKind character)
    {
        int placed = 0;
        int unplaced = 0;
        string? why = null;
        for (int slot = 0; slot < _agents.HighWater; slot++)
        {
            if (!_agents.Registered[slot] || _agents.Alive[slot] || _agents.Kind[slot] != kind || _agents.Lifecycle[slot] == AgentLifecycle.Detached)
            {
                continue;
            }

            if (Place(slot, tell: true) is { } failure)
            {
                unplaced++;
                why ??= failure.Reason;
            }
            else
            {
                placed++;
            }
        }

        return new RuntimeResult(RuntimeStatus.Ok,
            $"kind '{_kindNames[kind]}' has a roadmap of {character.Roadmap.Nodes.Count} nodes: {Count(placed)} on it" + (unplaced > 0 ? $", {unplaced} could not stand where they were ({why})" : ""));
    }

    private static string Count(int n) => n == 1 ? "1 agent" : $"{n} agents";

    /// <summary>
    /// Puts the standing agent in <paramref name="slot"/> on its kind's roadmap (after a rebake) where it stands, its
    /// target asked again; returns why it was removed instead (a changed character that cannot stand there), or
    /// <c>null</c>.
    /// </summary>
    private string? Rehome(int slot)
    {
        CharacterKind kind = _kinds[_agents.Kind[slot]]!;
        RoadmapNode standing = _agents.Stance[slot]!;
        _queue.Cancel(slot);
        if (_agents.Character[slot]!.Scene.Character.Fingerprint == kind.Scene.Character.Fingerprint)
        {
            // The same body on the same level: the stance it stands on is still one. It stays exactly there, on the
            // new roadmap's node of that very pose, or as a stance off the roadmap (searches steer from it).
            RoadmapNode kept = kind.Roadmap.FindPose(standing.Pose) is int id ? kind.Roadmap.Nodes[id] : standing.Id < 0 ? standing : standing with { Id = -1 };
            Settle(slot, kind, kept, angles: null);
        }
        else if (Stand(kind, standing.ContactCentre, out RuntimeResult failure) is { } stance)
        {
            // Another body: it stands on the new roadmap's node there, or on a stance placed there.
            Settle(slot, kind, stance.Node, stance.Angles);
        }
        else
        {
            string reason = $"unplaced: kind '{kind.Name}' was rebaked for another character, which cannot stand where the agent stood: {failure.Reason}";
            _pending.Add(new JumpEvent(JumpEventKind.Removed, _agents.HandleOf(slot), Tick, Time, -1, standing.ContactCentre, _agents.Target[slot], default, 0f, Planner.Planning.PlannerStatus.Exact, reason));
            SetRehome(slot, false);
            _agents.Deactivate(slot, AgentLifecycle.Unplaced, reason, standing.ContactCentre);
            return reason;
        }

        if (_agents.HasTarget[slot])
        {
            _agents.State[slot] = AgentState.Stance;
            _queue.Request(slot);
        }

        return null;
    }

    /// <summary>Flags or unflags the agent in <paramref name="slot"/> to move onto its kind's new roadmap where it stops, keeping <see cref="_rehoming"/> its count.</summary>
    private void SetRehome(int slot, bool on)
    {
        if (_agents.Rehome[slot] != on)
        {
            _agents.Rehome[slot] = on;
            _rehoming += on ? 1 : -1;
        }
    }

    /// <summary>Frees the slot of a removed agent: its game components, its rebake and its store entry go.</summary>
    private void Forget(int slot)
    {
        foreach (IComponentColumn column in _columns)
        {
            column.Clear(slot);
        }

        SetRehome(slot, false);
        _agents.Remove(slot);
    }

    /// <summary>
    /// Stands the agent in <paramref name="slot"/> on <paramref name="stance"/> of <paramref name="kind"/> with the
    /// pose <paramref name="angles"/> (<c>null</c>: the pose it holds, of the same rig), idle and pathless: its pose
    /// slices sized for the kind's rig (a rebake may have changed it), its rebake settled.
    /// </summary>
    private void Settle(int slot, CharacterKind kind, RoadmapNode stance, float[]? angles)
    {
        SetRehome(slot, false);
        if (!ReferenceEquals(_agents.Character[slot], kind))
        {
            _agents.Character[slot] = kind;
            _agents.SizePose(slot, angles?.Length ?? _agents.Pose[slot].AngleCount, kind.JointCount);
        }

        _agents.Path[slot] = null;
        _agents.StopAtStance[slot] = false;
        _agents.Stance[slot] = stance;
        _agents.Root[slot] = stance.Pose;
        PlaceBody(slot);
        angles?.CopyTo(_agents.AnglesOf(slot));

        _agents.PoseDirty[slot] = true;
        _agents.State[slot] = AgentState.Idle;
        if (_agents.Navigation[slot] is NavigationStatus.Planning or NavigationStatus.Following)
        {
            _agents.Navigate(slot, NavigationStatus.Idle); // its path or request was dropped (reached and failed stay: a rebake moves nobody)
        }
    }

    /// <summary>
    /// Why <paramref name="kind"/> cannot join this world as the roadmap of kind index <paramref name="replacing"/>
    /// (−1: a new kind), or <c>null</c> when it can.
    /// </summary>
    private RuntimeResult? Check(CharacterKind? kind, int replacing)
    {
        if (kind is null)
        {
            return new RuntimeResult(RuntimeStatus.InvalidArgument, "the character kind is null");
        }

        if (Planner.Query.QuerySettings.EffortProblem(kind.JumpEffort ?? 0f, kind.JumpHeightEffort ?? 0f) is { } costs)
        {
            return new RuntimeResult(RuntimeStatus.InvalidArgument, $"kind '{kind.Name}': its {costs}");
        }

        if (kind.Roadmap.LevelFingerprint != kind.Scene.Level.Fingerprint)
        {
            return new RuntimeResult(RuntimeStatus.Mismatch, $"kind '{kind.Name}': its roadmap was baked on another level than its scene's ({kind.Scene.Level.Source})");
        }

        bool others = false;
        for (int i = 0; i < _kinds.Count; i++)
        {
            others |= i != replacing && _kinds[i] is not null;
        }

        if ((others || _levelPinned) && Level is { } level && kind.Scene.Level.Fingerprint != level.Fingerprint)
        {
            return new RuntimeResult(RuntimeStatus.Mismatch, _levelPinned
                ? $"kind '{kind.Name}': its scene is of another level ({kind.Scene.Level.Source}) than this world's ({level.Source})"
                : $"kind '{kind.Name}': its level ({kind.Scene.Level.Source}) is not the level of the other kinds ({level.Source}); one level at a time: clear or remove those kinds first");
        }

        if (kind.Roadmap.CharacterFingerprint != kind.Scene.Character.Fingerprint)
        {
            return new RuntimeResult(RuntimeStatus.Mismatch, $"kind '{kind.Name}': its roadmap was baked for another character ({kind.Roadmap.CharacterName})");
        }

        return null;
    }

    /// <summary>
    /// Adds an agent standing at <paramref name="position"/> (a point on or near a surface, world metres): on the
    /// roadmap node whose contacts stand within <see cref="WorldSettings.Tolerance"/> of it, otherwise on a stance
    /// placed there. On a kind without a roadmap the agent waits (<see cref="AgentLifecycle.Waiting"/>) and joins there
    /// when the roadmap comes. Where the character can stand nowhere near, the agent is added
    /// <see cref="AgentLifecycle.Unplaced"/> (a warp tries again) and the result fails with
    /// <see cref="RuntimeStatus.InvalidPosition"/> and the reason, the handle given all the same. Refused, with no
    /// handle, for an unknown kind or a position that is not finite.
    /// </summary>
    /// <param name="kind">The agent's character kind.</param>
    /// <param name="position">Where it stands, world metres.</param>
    public AddAgentResult AddAgent(KindHandle kind, Vector3 position)
    {
        using Gate gate = Gate.Enter(_gate, "world", out RuntimeResult? busy);
        if (busy is { } crowded)
        {
            return new AddAgentResult(crowded, default);
        }

        if (Gone() is { } gone)
        {
            return new AddAgentResult(gone, default);
        }

        if (!IsValid(kind))
        {
            return new AddAgentResult(UnknownKind(kind), default);
        }

        if (!Finite(position))
        {
            return new AddAgentResult(new RuntimeResult(RuntimeStatus.InvalidArgument, $"the position {position} is not finite"), default);
        }

        string waiting = $"waiting for kind '{_kindNames[kind.Index]}' to get a roadmap";
        int slot = _agents.Register(kind.Index, position, AgentLifecycle.Waiting, waiting);
        if (_kinds[kind.Index] is null)
        {
            return new AddAgentResult(new RuntimeResult(RuntimeStatus.Ok, waiting), _agents.HandleOf(slot));
        }

        return new AddAgentResult(Place(slot, tell: false) ?? RuntimeResult.Success, _agents.HandleOf(slot));
    }

    /// <summary>
    /// Removes an agent at once, in whatever state (its pending request is dropped). The result's reason, and a
    /// <see cref="JumpEventKind.Removed"/> event at the start of the next tick, say in which state it was removed.
    /// </summary>
    public RuntimeResult RemoveAgent(AgentHandle agent)
    {
        using Gate gate = EnterFor(agent, out RuntimeResult? entry);
        if (entry is { } refusal)
        {
            return refusal;
        }

        int slot = agent.Index;
        AgentState state = _agents.State[slot];
        string reason = !_agents.Alive[slot] ? $"removed while {_agents.Lifecycle[slot].ToString().ToLowerInvariant()}"
            : _agents.Path[slot] is { } path && state is AgentState.Takeoff or AgentState.Flight or AgentState.Landing
            ? $"removed in mid-{(state == AgentState.Flight ? "flight" : state.ToString().ToLowerInvariant())} of jump {(_agents.Cursor[slot] >> 1) + 1} of {path.Count}"
            : $"removed while {state.ToString().ToLowerInvariant()}";
        _pending.Add(new JumpEvent(JumpEventKind.Removed, agent, Tick, Time, -1, _agents.Alive[slot] ? _agents.Root[slot].Position : _agents.Point[slot], _agents.Target[slot], default, 0f, Planner.Planning.PlannerStatus.Exact, reason));
        _queue.Cancel(slot);
        Forget(slot);
        return new RuntimeResult(RuntimeStatus.Ok, reason);
    }

    /// <summary>True while <paramref name="agent"/> names a live agent of this world.</summary>
    public bool IsValid(AgentHandle agent) => _agents.IsValid(agent);

    /// <summary>
    /// Sends the agent toward <paramref name="target"/> (a point on or near a surface, world metres). A target within
    /// <see cref="WorldSettings.ReplanDistance"/> of the current path's keeps the path; otherwise the agent finishes
    /// the jump it is in (or the stance it stands in) and plans anew from there. The outcome comes as a
    /// <see cref="JumpEventKind.PathFound"/> or <see cref="JumpEventKind.PathFailed"/> event (a target off the level fails there, with the reason).
    /// </summary>
    public RuntimeResult SetTarget(AgentHandle agent, Vector3 target)
    {
        using Gate gate = EnterFor(agent, out RuntimeResult? entry);
        if (entry is { } refusal)
        {
            return refusal;
        }

        if (!Finite(target))
        {
            return new RuntimeResult(RuntimeStatus.InvalidArgument, $"the target {target} is not finite");
        }

        int slot = agent.Index;
        if (OutOf(slot) is { } refused)
        {
            return refused;
        }

        bool had = _agents.HasTarget[slot];
        Vector3 previous = _agents.Target[slot];
        _agents.Target[slot] = target;
        _agents.HasTarget[slot] = true;
        if (!_agents.Alive[slot])
        {
            return new RuntimeResult(RuntimeStatus.Ok, $"target kept: the agent is {_agents.Lifecycle[slot].ToString().ToLowerInvariant()} ({_agents.Reason[slot]})");
        }

        if (_agents.Path[slot] is { } path)
        {
            // (An agent finishing its move before moving onto its kind's new roadmap plans anew from there in any case.)
            bool near = !_agents.Rehome[slot] && Vector3.Distance(path.Target, target) <= Settings.ReplanDistance;
            _agents.StopAtStance[slot] = !near;
            if (near)
            {
                _agents.Target[slot] = path.Target;
            }

            return RuntimeResult.Success;
        }

        if (had && _agents.Request[slot] is not null && Vector3.Distance(previous, target) <= Settings.ReplanDistance)
        {
            _agents.Target[slot] = previous;
            return RuntimeResult.Success; // the pending request already heads there
        }

        _agents.State[slot] = AgentState.Stance;
        _queue.Request(slot);
        return RuntimeResult.Success;
    }

    /// <summary>Forgets the agent's target: it stops on the next stance of its path (or at once when standing).</summary>
    public RuntimeResult ClearTarget(AgentHandle agent)
    {
        using Gate gate = EnterFor(agent, out RuntimeResult? entry);
        if (entry is { } refusal)
        {
            return refusal;
        }

        int slot = agent.Index;
        if (OutOf(slot) is { } refused)
        {
            return refused;
        }

        _agents.HasTarget[slot] = false;
        if (!_agents.Alive[slot])
        {
            return RuntimeResult.Success;
        }

        _queue.Cancel(slot);
        if (_agents.Path[slot] is not null)
        {
            _agents.StopAtStance[slot] = true; // following until it stops on the next stance
        }
        else
        {
            _agents.State[slot] = AgentState.Idle;
            _agents.Navigate(slot, NavigationStatus.Idle);
        }

        return RuntimeResult.Success;
    }

    /// <summary>
    /// Moves the agent at once to stand at <paramref name="position"/> (pushed, teleported), dropping its path; with a
    /// target it plans anew from there. Fails with <see cref="RuntimeStatus.InvalidPosition"/>, leaving the agent as it was, when it cannot stand there.
    /// A waiting agent will join there; an unplaced one tries to stand there now (staying unplaced, at the new point, when it cannot); a detached one is refused.
    /// </summary>
    public RuntimeResult Warp(AgentHandle agent, Vector3 position)
    {
        using Gate gate = EnterFor(agent, out RuntimeResult? entry);
        if (entry is { } refusal)
        {
            return refusal;
        }

        if (!Finite(position))
        {
            return new RuntimeResult(RuntimeStatus.InvalidArgument, $"the position {position} is not finite");
        }

        int slot = agent.Index;
        if (OutOf(slot) is { } refused)
        {
            return refused;
        }

        if (!_agents.Alive[slot])
        {
            _agents.Point[slot] = position;
            return _agents.Lifecycle[slot] == AgentLifecycle.Unplaced
                ? Place(slot, tell: false) ?? RuntimeResult.Success
                : new RuntimeResult(RuntimeStatus.Ok, $"position kept: {_agents.Reason[slot]}");
        }

        CharacterKind kind = _kinds[_agents.Kind[slot]]!;
        if (Stand(kind, position, out RuntimeResult failure) is not { } stance)
        {
            return failure;
        }

        _queue.Cancel(slot);
        Settle(slot, kind, stance.Node, stance.Angles);
        _agents.Navigate(slot, NavigationStatus.Idle); // pushed elsewhere: what it reached or failed is not where it stands
        if (_agents.HasTarget[slot])
        {
            _agents.State[slot] = AgentState.Stance;
            _queue.Request(slot);
        }

        return RuntimeResult.Success;
    }

    /// <summary>
    /// Performs exactly one jump of the agent's roadmap, the edge <paramref name="edge"/> (an index into its kind's
    /// <see cref="Roadmap.Edges"/>): the agent is moved at once onto the edge's takeoff node (pushed, as by
    /// <see cref="Warp"/>, dropping its path and any pending request), and its target becomes the landing node's
    /// contact centre. No search is made: the one-jump path is the roadmap's own arc, animated like any path and
    /// delivered <see cref="WorldSettings.PathLatencyTicks"/> later as a <see cref="JumpEventKind.PathFound"/> event,
    /// followed by <see cref="JumpEventKind.JumpStarted"/>, <see cref="JumpEventKind.Landed"/> and
    /// <see cref="JumpEventKind.TargetReached"/>. When the whole body cannot perform that jump, it is set aside as a
    /// path search sets aside such jumps, and the request becomes a search from the takeoff node to the same landing
    /// (so the agent still gets there, by other jumps, or a <see cref="JumpEventKind.PathFailed"/> event says why).
    /// Fails at once, leaving the agent as it was, for an edge that is not the roadmap's or a takeoff node the body
    /// cannot stand on.
    /// </summary>
    /// <param name="agent">The agent.</param>
    /// <param name="edge">Index of the jump in the agent's kind's roadmap edges.</param>
    public RuntimeResult PerformJump(AgentHandle agent, int edge)
    {
        using Gate gate = EnterFor(agent, out RuntimeResult? entry);
        if (entry is { } refusal)
        {
            return refusal;
        }

        int slot = agent.Index;
        if (NotActive(slot) is { } refused)
        {
            return refused;
        }

        CharacterKind kind = _kinds[_agents.Kind[slot]]!;
        Roadmap roadmap = kind.Roadmap;
        if ((uint)edge >= (uint)roadmap.Edges.Count)
        {
            return new RuntimeResult(RuntimeStatus.InvalidArgument, $"jump edge {edge} is not an edge of kind '{kind.Name}''s roadmap ({roadmap.Edges.Count} edges)");
        }

        RoadmapEdge jump = roadmap.Edges[edge];
        RoadmapNode from = roadmap.Nodes[jump.From];
        if (!kind.Animator.CanStand(new PoseEvaluation(from.Pose, PoseValidity.Valid, from.Contacts, from.Cone)))
        {
            return new RuntimeResult(RuntimeStatus.InvalidPosition, $"the body of kind '{kind.Name}' cannot stand on node {jump.From}, the takeoff of jump edge {edge}");
        }

        float[] angles = kind.Animator.Contacts.Generate(from.Pose, from.Contacts, from.Cone.Axis).Angles;
        _queue.Cancel(slot);
        Settle(slot, kind, from, angles);
        _agents.Target[slot] = roadmap.ContactCentres[jump.To];
        _agents.HasTarget[slot] = true;
        _agents.State[slot] = AgentState.Stance;
        _queue.Request(slot, edge);
        return RuntimeResult.Success;
    }

    /// <summary>
    /// Performs exactly <paramref name="moves"/> (jumps and walks, each starting on the stance the one before ends on),
    /// with no search: the agent is moved at once onto the first move's stance (pushed, as by <see cref="Warp"/>,
    /// dropping its path and any pending request) and its target becomes the last stance's contact centre. The moves
    /// are animated like any path and delivered <see cref="WorldSettings.PathLatencyTicks"/> later as a
    /// <see cref="JumpEventKind.PathFound"/> event; a move the body cannot perform is set aside and the request
    /// becomes a search to the same stance, as for <see cref="PerformJump"/>. For tests and tools (scripted paths).
    /// Fails at once, leaving the agent as it was, for no moves or moves that do not chain.
    /// </summary>
    internal RuntimeResult PerformMoves(AgentHandle agent, IReadOnlyList<Move> moves)
    {
        using Gate gate = EnterFor(agent, out RuntimeResult? entry);
        if (entry is { } refusal)
        {
            return refusal;
        }

        if (moves is null || moves.Count == 0 || moves.Any(m => m is null))
        {
            return new RuntimeResult(RuntimeStatus.InvalidArgument, "there are no moves to perform (or one is null)");
        }

        for (int i = 1; i < moves.Count; i++)
        {
            if (!ReferenceEquals(moves[i].From, moves[i - 1].To) && moves[i].From != moves[i - 1].To)
            {
                return new RuntimeResult(RuntimeStatus.InvalidArgument, $"move {i} does not start on the stance move {i - 1} ends on");
            }
        }

        int slot = agent.Index;
        if (NotActive(slot) is { } refused)
        {
            return refused;
        }

        CharacterKind kind = _kinds[_agents.Kind[slot]]!;
        RoadmapNode from = moves[0].From;
        float[] angles = kind.Animator.Contacts.Generate(from.Pose, from.Contacts, from.Cone.Axis).Angles;
        _queue.Cancel(slot);
        Settle(slot, kind, from, angles);
        _agents.Target[slot] = moves[^1].To.ContactCentre;
        _agents.HasTarget[slot] = true;
        _agents.State[slot] = AgentState.Stance;
        _queue.Request(slot, [.. moves]);
        return RuntimeResult.Success;
    }

    /// <summary>Turns the pose system on or off for one agent (off for agents nobody sees; on by default).</summary>
    public RuntimeResult SetPoseEnabled(AgentHandle agent, bool enabled)
    {
        using Gate gate = EnterFor(agent, out RuntimeResult? entry);
        if (entry is { } refusal)
        {
            return refusal;
        }

        _agents.PoseEnabled[agent.Index] = enabled;
        _agents.PoseDirty[agent.Index] = true;
        return RuntimeResult.Success;
    }

    /// <summary>
    /// One tick: the events of the tick before are cleared; the commands recorded in <see cref="Commands"/> are
    /// played back; then each system of <see cref="Systems"/> runs in order (by default: path requests are searched
    /// within the budget and paths due are delivered; agents move along their paths; poses are filled). Never throws
    /// but for the cases below: a game system's exception becomes a <see cref="JumpEventKind.SystemFailed"/> event.
    /// </summary>
    /// <exception cref="ObjectDisposedException">The world was disposed.</exception>
    /// <exception cref="InvalidOperationException">Called from inside a system of this world's tick.</exception>
    public void Step() => Step(1);

    /// <summary>
    /// <paramref name="ticks"/> ticks in a row, as a game frame that catches up (a physics frame longer than a tick):
    /// <see cref="Events"/> and <see cref="EventsOf"/> then hold the events of all of them, in order, so that a node
    /// reading its agent's events once a frame misses none. Zero ticks clears the events and does nothing else.
    /// </summary>
    /// <param name="ticks">Ticks to run, zero or more.</param>
    /// <exception cref="ObjectDisposedException">The world was disposed.</exception>
    /// <exception cref="InvalidOperationException">Called from inside a system of this world's tick.</exception>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="ticks"/> is negative.</exception>
    public void Step(int ticks)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(ticks);
        using Gate gate = Gate.Wait(_gate);
        ObjectDisposedException.ThrowIf(_disposed, this);
        if (IsStepping)
        {
            throw new InvalidOperationException("JumpWorld.Step was called from inside a system of the world's own tick");
        }

        _events.Clear();
        for (int i = 0; i < ticks; i++)
        {
            StepOnce();
        }
    }

    /// <summary>One tick, its events added to those of the ticks before it in this <see cref="Step(int)"/>.</summary>
    private void StepOnce()
    {
        IsStepping = true;
        try
        {
            Tick++;
            Commands.Play(this, _commandRefused, _commandAdded);
            if (_rehoming > 0)
            {
                // Agents that ended the move they were in when their kind was rebaked: onto the new roadmap.
                for (int slot = 0; slot < _agents.HighWater && _rehoming > 0; slot++)
                {
                    if (_agents.Alive[slot] && _agents.Rehome[slot] && _agents.Path[slot] is null)
                    {
                        Rehome(slot);
                    }
                }
            }

            foreach (ref readonly JumpEvent e in _pending.Events)
            {
                _events.Add(e);
            }

            _pending.Clear();
            Systems.Run(new TickContext(Tick, Time, Settings.TickSeconds), _systemFailed);
        }
        finally
        {
            IsStepping = false;
        }
    }

    /// <summary>Runs the pose system alone at the current time (benchmarks).</summary>
    internal void FillPoses() => _pose.Update(Time);

    /// <summary>The agent's kind, or the default handle for an unknown or detached agent (its kind was removed).</summary>
    public KindHandle GetKind(AgentHandle agent) =>
        _agents.IsValid(agent) && _agents.Lifecycle[agent.Index] != AgentLifecycle.Detached ? new KindHandle(_agents.Kind[agent.Index], _kindGenerations[_agents.Kind[agent.Index]]) : default;

    /// <summary>Where the agent is in its life (<see cref="AgentLifecycle.Detached"/> for an unknown agent): only active agents move.</summary>
    public AgentLifecycle GetLifecycle(AgentHandle agent) => _agents.IsValid(agent) ? _agents.Lifecycle[agent.Index] : AgentLifecycle.Detached;

    /// <summary>Why the agent waits, could not be placed or was detached; <c>null</c> while it is active (or unknown).</summary>
    public string? GetAgentReason(AgentHandle agent) => _agents.IsValid(agent) ? _agents.Reason[agent.Index] : null;

    /// <summary>
    /// Where the agent stands, world metres: active, the contact centre of the stance it stands on (or will stand on
    /// at the end of the move it is in); otherwise the point it was added or warped at, or stood at when it left the
    /// simulation. <c>null</c> for an unknown agent.
    /// </summary>
    public Vector3? GetStandingPoint(AgentHandle agent)
    {
        if (!_agents.IsValid(agent))
        {
            return null;
        }

        int slot = agent.Index;
        return _agents.Alive[slot] && Standing(slot) is { } stance ? stance.ContactCentre : _agents.Point[slot];
    }

    /// <summary>
    /// The stance the active agent in <paramref name="slot"/> stands on, or, following a path, the one it stands on
    /// next: the end of the move it is in, or the first stance of the next move between two moves.
    /// </summary>
    private RoadmapNode? Standing(int slot)
    {
        if (_agents.Stance[slot] is { } stance)
        {
            return stance;
        }

        if (_agents.Path[slot] is not { } path)
        {
            return null;
        }

        float t = (float)(Time - _agents.PathStart[slot]);
        for (int i = 0; i < path.Count; i++)
        {
            PathMove move = path.Moves[i];
            if (t < move.Start)
            {
                return move.From;
            }

            if (t < move.End)
            {
                return move.To;
            }
        }

        return path.Goal;
    }

    /// <summary>
    /// Whether the agent's roadmap connects where it stands to <paramref name="target"/>: a path of jumps (and of the
    /// roadmap's walks, unless <see cref="WorldSettings.Locomotion"/> is jumps only) leads from its stance (a roadmap
    /// node, or for a stance off the roadmap any of the nearest nodes within jump reach) to the node standing at the
    /// target (<see cref="Roadmap.FindNode"/>), or, when none stands there, to any of the nearest nodes within jump
    /// reach of the target. An estimate for stances and targets off the roadmap (the planner must still steer to and
    /// from them); false for an agent that is not active. Allocates nothing once its scratch has grown to the
    /// roadmap's size.
    /// </summary>
    public bool IsTargetReachable(AgentHandle agent, Vector3 target)
    {
        using Gate gate = Gate.Wait(_gate);
        if (_disposed || !_agents.IsActive(agent) || !Finite(target))
        {
            return false;
        }

        CharacterKind kind = _agents.Character[agent.Index]!;
        Roadmap roadmap = kind.Roadmap;
        if (Standing(agent.Index) is not { } stance || roadmap.Nodes.Count == 0)
        {
            return false;
        }

        int n = roadmap.Nodes.Count;
        if (_seen.Length < n)
        {
            _seen = new int[n];
            _goal = new int[n];
            _stack = new int[n];
        }

        if (++_stamp == int.MaxValue)
        {
            Array.Clear(_seen);
            Array.Clear(_goal);
            _stamp = 1;
        }

        SteeringLimits limits = kind.Scene.Steering.Limits;
        if (roadmap.FindNode(target, Settings.Tolerance) is int goal)
        {
            _goal[goal] = _stamp;
        }
        else
        {
            roadmap.Nearest(target, limits, NearbyNodes, _nearest);
            foreach ((_, int id) in _nearest)
            {
                _goal[id] = _stamp;
            }
        }

        int top = 0;
        if ((uint)stance.Id < (uint)roadmap.Nodes.Count && roadmap.Nodes[stance.Id].Pose == stance.Pose)
        {
            _seen[stance.Id] = _stamp;
            _stack[top++] = stance.Id;
        }
        else
        {
            roadmap.Nearest(stance.Pose.Position, limits, NearbyNodes, _nearest);
            foreach ((_, int id) in _nearest)
            {
                _seen[id] = _stamp;
                _stack[top++] = id;
            }
        }

        ReadOnlySpan<int> offsets = roadmap.OutgoingOffsets;
        ReadOnlySpan<int> targets = roadmap.OutgoingTargets;
        bool walking = Settings.Locomotion != Locomotion.Jump && roadmap.Walks.Count > 0;
        ReadOnlySpan<int> walkOffsets = walking ? roadmap.WalkOffsets : default;
        ReadOnlySpan<int> walkTargets = walking ? roadmap.WalkTargets : default;
        while (top > 0)
        {
            int node = _stack[--top];
            if (_goal[node] == _stamp)
            {
                return true;
            }

            for (int i = offsets[node]; i < offsets[node + 1]; i++)
            {
                Push(targets[i], ref top);
            }

            if (walking)
            {
                for (int i = walkOffsets[node]; i < walkOffsets[node + 1]; i++)
                {
                    Push(walkTargets[i], ref top);
                }
            }
        }

        return false;
    }

    /// <summary>Nodes near a stance or target that a reachability test starts from or aims at when it is no roadmap node.</summary>
    private const int NearbyNodes = 32;

    /// <summary>Puts <paramref name="node"/> on the reachability test's stack unless it was seen.</summary>
    private void Push(int node, ref int top)
    {
        if (_seen[node] != _stamp)
        {
            _seen[node] = _stamp;
            _stack[top++] = node;
        }
    }

    /// <summary>What the agent does this tick (<see cref="AgentState.Idle"/> for an unknown agent).</summary>
    public AgentState GetState(AgentHandle agent) => _agents.IsValid(agent) ? _agents.State[agent.Index] : AgentState.Idle;

    /// <summary>The agent's root pose this tick: trunk centre (world metres) and trunk orientation; exactly on the arc in flight and on the walk's <see cref="Walk.PoseAt(float)"/> while walking.</summary>
    public RootPose GetRootPose(AgentHandle agent) => _agents.IsValid(agent) ? _agents.Root[agent.Index] : default;

    /// <summary>
    /// The agent's body point this tick (<see cref="BodyPoint"/>: the ground reference where a game puts its body node,
    /// its velocity and heading), as the body-point system wrote it (and as <see cref="AddAgent"/>, <see cref="Warp"/> and
    /// <see cref="PerformJump"/> place it at once); default for an unknown agent.
    /// </summary>
    public BodyPoint GetBodyPoint(AgentHandle agent) => _agents.IsValid(agent) ? _agents.Body[agent.Index] : default;

    /// <summary>The stance the agent stands on, or <c>null</c> while it follows a path (or for an unknown agent).</summary>
    public RoadmapNode? GetStance(AgentHandle agent) => _agents.IsValid(agent) ? _agents.Stance[agent.Index] : null;

    /// <summary>The agent's target, when it has one.</summary>
    public Vector3? GetTarget(AgentHandle agent) => _agents.IsValid(agent) && _agents.HasTarget[agent.Index] ? _agents.Target[agent.Index] : null;

    /// <summary>The path the agent follows, or <c>null</c>.</summary>
    public AgentPath? GetPath(AgentHandle agent) => _agents.IsValid(agent) ? _agents.Path[agent.Index] : null;

    /// <summary>Seconds since the agent started following its path (its animation's clip time); zero without a path.</summary>
    public float GetPathTime(AgentHandle agent) =>
        _agents.IsValid(agent) && _agents.Path[agent.Index] is not null ? (float)(Time - _agents.PathStart[agent.Index]) : 0f;

    /// <summary>True while the agent's request waits for a search or its path for its animation.</summary>
    public bool IsPathPending(AgentHandle agent) => _agents.IsValid(agent) && _agents.Request[agent.Index] is not null;

    /// <summary>
    /// The jump the agent is in the air for now (takeoff, flight or landing), with its exact arc and world times of
    /// takeoff and landing: the agent's root is <c>Arc.PositionAt((float)(Time − TakeoffTime))</c>. False when the
    /// agent stands or walks (or is unknown).
    /// </summary>
    public bool TryGetCurrentJump(AgentHandle agent, out JumpInfo jump)
    {
        jump = default;
        if (!CurrentMove(agent, out AgentPath? path, out int index) || path.Move(index).Kind != MoveKind.Jump)
        {
            return false;
        }

        jump = DescribeJump(agent.Index, path, index, inProgress: true);
        return true;
    }

    /// <summary>
    /// The next jump the agent will take off for (after the move it is in, if any, and any walks before it), with its
    /// exact arc and the world times of its takeoff and landing, known before it happens. False when no takeoff remains
    /// on the agent's path (or it has none, or is unknown), or when the agent will stop before it (a new target, a
    /// cleared one).
    /// </summary>
    public bool TryGetNextJump(AgentHandle agent, out JumpInfo jump)
    {
        jump = default;
        if (NextMove(agent, MoveKind.Jump, out AgentPath? path) is not int index)
        {
            return false;
        }

        jump = DescribeJump(agent.Index, path!, index, inProgress: false);
        return true;
    }

    /// <summary>
    /// The walk the agent is walking now, with the world times of its start and end: the agent's root is
    /// <c>Walk.PoseAt((float)(Time − StartTime))</c>, raised by the animation's <c>WalkLift</c>. False when the agent stands or jumps (or is unknown).
    /// </summary>
    public bool TryGetCurrentWalk(AgentHandle agent, out WalkInfo walk)
    {
        walk = default;
        if (!CurrentMove(agent, out AgentPath? path, out int index) || path.Move(index).Walk is null)
        {
            return false;
        }

        walk = DescribeWalk(agent.Index, path, index, inProgress: true);
        return true;
    }

    /// <summary>
    /// The next walk the agent will start (after the move it is in, if any, and any jumps before it), with the world
    /// times of its start and end, known before it happens. False when no walk remains on the agent's path (or it has
    /// none, or is unknown), or when the agent will stop before it (a new target, a cleared one).
    /// </summary>
    public bool TryGetNextWalk(AgentHandle agent, out WalkInfo walk)
    {
        walk = default;
        if (NextMove(agent, MoveKind.Walk, out AgentPath? path) is not int index)
        {
            return false;
        }

        walk = DescribeWalk(agent.Index, path!, index, inProgress: false);
        return true;
    }

    /// <summary>
    /// Index among the moves of the agent's path (<see cref="AgentPath.Moves"/>) of the move it is performing now (a
    /// jump in the air or a walk), or, standing between two moves, of the next one; −1 without a path (or for an
    /// unknown agent).
    /// </summary>
    public int GetMoveIndex(AgentHandle agent)
    {
        if (!_agents.IsValid(agent) || _agents.Path[agent.Index] is not { } path)
        {
            return -1;
        }

        return Math.Min(_agents.Cursor[agent.Index] >> 1, path.Count - 1);
    }

    /// <summary>The path and index of the move the agent is performing now (between its start and its end).</summary>
    private bool CurrentMove(AgentHandle agent, [System.Diagnostics.CodeAnalysis.NotNullWhen(true)] out AgentPath? path, out int index)
    {
        path = null;
        index = -1;
        if (!_agents.IsValid(agent) || _agents.Path[agent.Index] is not { } p || (_agents.Cursor[agent.Index] & 1) == 0)
        {
            return false;
        }

        path = p;
        index = _agents.Cursor[agent.Index] >> 1;
        return true;
    }

    /// <summary>The index of the first move of <paramref name="kind"/> not started yet, unless the agent stops before it.</summary>
    private int? NextMove(AgentHandle agent, MoveKind kind, out AgentPath? path)
    {
        path = null;
        if (!_agents.IsValid(agent) || _agents.Path[agent.Index] is not { } p || _agents.StopAtStance[agent.Index])
        {
            return null;
        }

        path = p;
        for (int i = (_agents.Cursor[agent.Index] + 1) >> 1; i < p.Count; i++)
        {
            if (p.Move(i).Kind == kind)
            {
                return i;
            }
        }

        return null;
    }

    private JumpInfo DescribeJump(int slot, AgentPath path, int index, bool inProgress)
    {
        ref readonly PathMove move = ref path.Move(index);
        double start = _agents.PathStart[slot];
        return new JumpInfo(index, move.Arc, start + move.Start, start + move.End, inProgress, move.From.ContactCentre, move.To.ContactCentre, BodyMotion.BodyVelocity(move));
    }

    private WalkInfo DescribeWalk(int slot, AgentPath path, int index, bool inProgress)
    {
        ref readonly PathMove move = ref path.Move(index);
        double start = _agents.PathStart[slot];
        return new WalkInfo(index, move.Walk!, start + move.Start, start + move.End, inProgress);
    }

    /// <summary>
    /// The agent's joint angles this tick, one per degree of freedom of its rig (radians, <see cref="Planner.Rigs.Rig.Dofs"/>
    /// order); empty for an unknown agent. Filled by the pose system; a read-only view of the agent's slice of the
    /// world's pose pool, valid until the next tick or the next change to the world's agents or kinds (the pool may
    /// grow or the slice move then).
    /// </summary>
    public ReadOnlySpan<float> GetJointAngles(AgentHandle agent) => _agents.IsValid(agent) ? _agents.AnglesOf(agent.Index) : [];

    /// <summary>
    /// The agent's joint rotations this tick, one per joint of its rig (<see cref="Planner.Rigs.Rig.Joints"/> order),
    /// each local to its parent joint (the root joint's local to the root pose, <see cref="GetRootPose"/>); empty
    /// for an unknown agent. Filled by the pose system; a read-only view of the agent's slice of the world's pose
    /// pool, valid until the next tick or the next change to the world's agents or kinds (the pool may grow or the
    /// slice move then).
    /// </summary>
    public ReadOnlySpan<Quaternion> GetJointRotations(AgentHandle agent) => _agents.IsValid(agent) ? _agents.RotationsOf(agent.Index) : [];

    /// <summary>Copies the handles of the active agents (on their kind's roadmap), in slot order, into <paramref name="destination"/>; returns how many were written.</summary>
    public int CopyAgents(Span<AgentHandle> destination)
    {
        int n = 0;
        for (int slot = 0; slot < _agents.HighWater && n < destination.Length; slot++)
        {
            if (_agents.Alive[slot])
            {
                destination[n++] = _agents.HandleOf(slot);
            }
        }

        return n;
    }

    /// <summary>Waits for background animations to end and stops the world.</summary>
    public void Dispose()
    {
        using Gate gate = Gate.Wait(_gate);
        if (!_disposed)
        {
            _disposed = true;
            foreach (RoadmapSearch? search in _searches)
            {
                search?.StopPreparing();
            }

            _requests.Dispose();
        }
    }

    /// <summary>Sets kind <paramref name="index"/>'s searches, stopping the preparation of those they replace.</summary>
    private void SetSearch(int index, RoadmapSearch? search)
    {
        _searches[index]?.StopPreparing();
        _searches[index] = search;
    }

    /// <summary>The stance an agent of <paramref name="kind"/> takes at <paramref name="point"/>, with its pose's joint angles.</summary>
    private (RoadmapNode Node, float[] Angles)? Stand(CharacterKind kind, Vector3 point, out RuntimeResult failure)
    {
        failure = RuntimeResult.Success;
        RoadmapNode node;
        if (kind.Roadmap.FindNode(point, Settings.Tolerance) is int id &&
            kind.Animator.CanStand(new PoseEvaluation(kind.Roadmap.Nodes[id].Pose, PoseValidity.Valid, kind.Roadmap.Nodes[id].Contacts, kind.Roadmap.Nodes[id].Cone)))
        {
            node = kind.Roadmap.Nodes[id];
        }
        else
        {
            EndpointPlacement placement = kind.Scene.Sampler.Place(point, Settings.Tolerance, kind.Animator.CanStand);
            if (placement.Pose is not { } pose)
            {
                failure = new RuntimeResult(RuntimeStatus.InvalidPosition, placement.Failure("position", Settings.Tolerance));
                return null;
            }

            node = new RoadmapNode(-1, pose.Pose, pose.Cone, pose.Contacts);
        }

        float[] angles = kind.Animator.Contacts.Generate(node.Pose, node.Contacts, node.Cone.Axis).Angles;
        return (node, (float[])angles.Clone());
    }

    /// <summary>The body point of the agent in <paramref name="slot"/> standing on its stance, at once (not waiting for the body-point system).</summary>
    private void PlaceBody(int slot) =>
        _agents.Body[slot] = BodyPointRunner.Standing(_agents.Stance[slot]!.ContactCentre, _agents.Root[slot], _agents.Body[slot].Heading);

    /// <summary>The refusal of every call after <see cref="Dispose"/> (but <see cref="Step()"/>, which throws), or <c>null</c> before.</summary>
    /// <summary>
    /// Enters the world's gate for a change to <paramref name="agent"/>: <paramref name="refused"/> says why not when
    /// another thread holds the world, the world was disposed or the handle names no agent of it (the gate, if
    /// entered, is left when the returned gate is disposed).
    /// </summary>
    private Gate EnterFor(AgentHandle agent, out RuntimeResult? refused)
    {
        Gate gate = Gate.Enter(_gate, "world", out refused);
        refused ??= Gone() ?? (_agents.IsValid(agent) ? null : Unknown(agent));
        return gate;
    }

    /// <summary>As <see cref="EnterFor(AgentHandle, out RuntimeResult?)"/>, for a change to the kind <paramref name="kind"/>.</summary>
    private Gate EnterFor(KindHandle kind, out RuntimeResult? refused)
    {
        Gate gate = Gate.Enter(_gate, "world", out refused);
        refused ??= Gone() ?? (IsValid(kind) ? null : UnknownKind(kind));
        return gate;
    }

    private RuntimeResult? Gone() => _disposed ? new RuntimeResult(RuntimeStatus.Disposed, "the world was disposed: nothing was done") : null;

    private static RuntimeResult Unknown(AgentHandle agent) => new(RuntimeStatus.UnknownAgent, $"{agent} is not an agent of this world (never added, or removed)");

    private RuntimeResult UnknownKind(KindHandle kind) => new(RuntimeStatus.UnknownKind, $"{kind} is not a kind of this world (never added, or removed; {_kinds.Count - _freeKinds.Count} kinds)");

    /// <summary>The refusal of a change to a detached agent, or <c>null</c>.</summary>
    private RuntimeResult? OutOf(int slot) =>
        _agents.Lifecycle[slot] == AgentLifecycle.Detached ? new RuntimeResult(RuntimeStatus.UnknownAgent, $"{_agents.HandleOf(slot)} is detached: {_agents.Reason[slot]}") : null;

    /// <summary>The refusal of a move asked of an agent out of the simulation, or <c>null</c>.</summary>
    private RuntimeResult? NotActive(int slot) =>
        OutOf(slot) ?? (_agents.Alive[slot] ? null : new RuntimeResult(RuntimeStatus.InvalidPosition, $"{_agents.HandleOf(slot)} is not on a roadmap: {_agents.Reason[slot]}"));

    private static bool Finite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);
}
