using System.Numerics;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
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
using RoadmapSearch = Ballistic.Runtime.Systems.RoadmapSearch;

namespace Ballistic.Runtime;

/// <summary>
/// Many agents navigating one level by jumps and walks, stepped per tick: the ECS core under the Godot nodes. The world holds
/// one frozen roadmap per character kind (like a navigation map with one region per agent size), agents as
/// entities whose components live in arrays (<see cref="AgentHandle"/>s name them; a game adds its own components
/// with <see cref="AddComponentColumn{T}"/> and iterates agents with <see cref="Query"/>), and an ordered list of
/// systems run by <see cref="Step"/> (<see cref="Systems"/>): by default path requests (a budgeted queue), locomotion
/// (exactly on the arcs and along the walks), pose (joint buffers from the whole-body animation), and the game's own
/// inserted between them. Changes recorded in <see cref="Commands"/> are played back at the start of each tick. What
/// happened comes out as <see cref="Events"/>.
/// </summary>
/// <remarks>
/// Deterministic: the same kinds, settings and calls between the same ticks give the same trajectories and events,
/// whatever <see cref="WorldSettings.AnimationThreads"/> (with <see cref="WorldSettings.WaitForAnimation"/>, the
/// default). Calls and <see cref="Step"/> belong on one thread (the game loop); animations are solved on others.
/// A change called from another thread while the world steps or changes is refused with
/// <see cref="RuntimeStatus.Busy"/> (<see cref="Step"/> and <see cref="Dispose"/> wait for a call in progress), so a
/// breach never corrupts the world; changes from other threads go through <see cref="Commands"/>.
/// No call throws for a bad handle or bad input: each returns a <see cref="RuntimeResult"/> with the reason, and
/// no exception escapes a tick. After <see cref="Dispose"/> every call that changes the world does nothing and
/// returns <see cref="RuntimeStatus.Disposed"/>; <see cref="Step"/> throws. Positions are the trunk centre in world
/// metres, Y up; times are seconds.
/// </remarks>
public sealed class JumpWorld : IDisposable
{
    private readonly List<CharacterKind> _kinds = [];
    private readonly List<RoadmapSearch> _searches = [];
    private readonly AgentStore _agents = new();
    private readonly EventBuffer _events = new();
    private readonly EventBuffer _pending = new();
    private readonly PathQueue _queue;
    private readonly PathRequestRunner _requests;
    private readonly PoseRunner _pose;
    private readonly List<IComponentColumn> _columns = [];
    private readonly Action<IJumpSystem, Exception> _systemFailed;
    private readonly Action<AgentHandle, string> _commandRefused;
    private bool _disposed;

    /// <summary>Held by the thread stepping or changing the world (<see cref="Gate"/>).</summary>
    private readonly object _gate = new();

    /// <summary>Agents flagged <see cref="AgentStore.Rehome"/>: the tick looks for those that stopped only while there are some.</summary>
    private int _rehoming;

    /// <summary>Creates an empty world on a level.</summary>
    /// <param name="level">The level every kind's scene must be built on.</param>
    /// <param name="settings">Tick rate, budgets and threads; defaults when <c>null</c>.</param>
    /// <exception cref="ArgumentException">A setting is out of range.</exception>
    public JumpWorld(Level level, WorldSettings? settings = null)
    {
        ArgumentNullException.ThrowIfNull(level);
        Settings = settings ?? new WorldSettings();
        if (Settings.Problem() is { } problem)
        {
            throw new ArgumentException($"World settings: {problem}.", nameof(settings));
        }

        Settings.Tolerance.Validate();
        Level = level;
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
    }

    /// <summary>
    /// The systems <see cref="Step"/> runs, in order: by default <see cref="PathRequestSystem"/>,
    /// <see cref="LocomotionSystem"/>, <see cref="BodyPointSystem"/>, <see cref="PoseSystem"/>. Insert the game's own
    /// between them; remove the pose system when nobody reads poses (the body-point system when nobody reads body
    /// points: the Godot nodes do).
    /// </summary>
    public JumpSystemList Systems { get; }

    /// <summary>
    /// The path-request system: starts queued requests within the tick's budget
    /// (<see cref="WorldSettings.MaxSearchesPerTick"/>), each searched and animated in the background, and delivers each
    /// outcome <see cref="WorldSettings.PathLatencyTicks"/> after its start (<see cref="JumpEventKind.PathFound"/>,
    /// <see cref="JumpEventKind.PathFailed"/>): the tick itself never searches.
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
    /// <see cref="Step"/>, before the systems run.
    /// </summary>
    public JumpCommandBuffer Commands { get; }

    /// <summary>True from <see cref="Dispose"/> on.</summary>
    internal bool IsDisposed => _disposed;

    /// <summary>True while <see cref="Step"/> runs.</summary>
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
    /// The live agents <paramref name="query"/> selects, for <c>foreach</c>, in slot order; allocates nothing. A
    /// query naming another world's column selects nobody.
    /// </summary>
    public AgentQueryResult Query(in AgentQuery query) => new(_agents, query, _disposed || !query.IsOf(this));

    /// <summary>The level.</summary>
    public Level Level { get; }

    /// <summary>The settings.</summary>
    public WorldSettings Settings { get; }

    /// <summary>Ticks stepped so far.</summary>
    public long Tick { get; private set; }

    /// <summary>World time, seconds: <see cref="Tick"/> × <see cref="WorldSettings.TickSeconds"/>.</summary>
    public double Time => Tick * Settings.TickSeconds;

    /// <summary>Live agents.</summary>
    public int AgentCount => _agents.Count;

    /// <summary>The character kinds, by <see cref="KindHandle.Index"/>.</summary>
    public IReadOnlyList<CharacterKind> Kinds => _kinds;

    /// <summary>The events of the last <see cref="Step"/>, in order: path found or failed, then takeoffs, landings, walks started and finished, and arrivals.</summary>
    public ReadOnlySpan<JumpEvent> Events => _events.Events;

    /// <summary>
    /// The events of <paramref name="agent"/> during the last <see cref="Step"/>, in order (the same events as in
    /// <see cref="Events"/>, one contiguous range per agent): what a game object of one agent reads each tick without
    /// walking every agent's events. Empty for an agent with none, or unknown. Allocates nothing once the buffers have
    /// grown; valid until the next <see cref="Step"/>.
    /// </summary>
    public ReadOnlySpan<JumpEvent> EventsOf(AgentHandle agent) => _disposed ? [] : _events.Of(agent, _agents.Generation.Length);

    /// <summary>Path requests waiting for a search.</summary>
    public int QueuedRequests => _queue.Count;

    /// <summary>Requests started and not delivered yet: being searched or animated, or waiting for their due tick.</summary>
    public int AnimatingRequests => _requests.Animating;

    /// <summary>Requests started (searches) during the last tick.</summary>
    public int LastTickSearches => _requests.LastTickSearches;

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

        if (Check(kind) is { } refused)
        {
            return new AddKindResult(refused, default);
        }

        _kinds.Add(kind);
        _searches.Add(new RoadmapSearch(kind, Settings));
        return new AddKindResult(RuntimeResult.Success, new KindHandle(_kinds.Count - 1, true));
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
    public RuntimeResult ReplaceKind(KindHandle kind, CharacterKind replacement)
    {
        using Gate gate = Gate.Enter(_gate, "world", out RuntimeResult? busy);
        if (busy is { } crowded)
        {
            return crowded;
        }

        if (Gone() is { } gone)
        {
            return gone;
        }

        if (!kind.Assigned || (uint)kind.Index >= (uint)_kinds.Count)
        {
            return new RuntimeResult(RuntimeStatus.UnknownKind, $"{kind} is not a kind of this world ({_kinds.Count} kinds)");
        }

        if (Check(replacement) is { } refused)
        {
            return refused;
        }

        _kinds[kind.Index] = replacement;
        _searches[kind.Index] = new RoadmapSearch(replacement, Settings);
        int placed = 0;
        int finishing = 0;
        int removed = 0;
        string? why = null;
        for (int slot = 0; slot < _agents.HighWater; slot++)
        {
            if (!_agents.Alive[slot] || _agents.Kind[slot] != kind.Index)
            {
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
            $"kind '{replacement.Name}' replaced: {Count(placed)} put on its new roadmap, {Count(finishing)} finishing a move first, {Count(removed)} removed" + (why is null ? "" : $" ({why})"));

        static string Count(int n) => n == 1 ? "1 agent" : $"{n} agents";
    }

    /// <summary>
    /// Puts the standing agent in <paramref name="slot"/> on its kind's roadmap (after a rebake) where it stands, its
    /// target asked again; returns why it was removed instead (a changed character that cannot stand there), or
    /// <c>null</c>.
    /// </summary>
    private string? Rehome(int slot)
    {
        CharacterKind kind = _kinds[_agents.Kind[slot]];
        RoadmapNode standing = _agents.Stance[slot]!;
        _queue.Cancel(slot);
        if (_agents.Character[slot]!.Scene.Character.Fingerprint == kind.Scene.Character.Fingerprint)
        {
            // The same body on the same level: the stance it stands on is still one. It stays exactly there, on the
            // new roadmap's node of that very pose, or as a stance off the roadmap (searches steer from it).
            RoadmapNode kept = kind.Roadmap.FindPose(standing.Pose) is int id ? kind.Roadmap.Nodes[id] : standing.Id < 0 ? standing : standing with { Id = -1 };
            Settle(slot, kind, kept, _agents.Angles[slot]);
        }
        else if (Stand(kind, standing.ContactCentre, out RuntimeResult failure) is { } stance)
        {
            // Another body: it stands on the new roadmap's node there, or on a stance placed there.
            Settle(slot, kind, stance.Node, stance.Angles);
        }
        else
        {
            string reason = $"removed: kind '{kind.Name}' was rebaked for another character, which cannot stand where the agent stood: {failure.Reason}";
            _pending.Add(new JumpEvent(JumpEventKind.Removed, _agents.HandleOf(slot), Tick, Time, -1, _agents.Root[slot].Position, _agents.Target[slot], default, 0f, Planner.Planning.PlannerStatus.Exact, reason));
            Forget(slot);
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
    /// pose <paramref name="angles"/>, idle and pathless: its pose buffers sized for the kind's rig (a rebake may have
    /// changed it), its rebake settled.
    /// </summary>
    private void Settle(int slot, CharacterKind kind, RoadmapNode stance, float[] angles)
    {
        SetRehome(slot, false);
        if (!ReferenceEquals(_agents.Character[slot], kind))
        {
            _agents.Character[slot] = kind;
            if (_agents.Angles[slot].Length != angles.Length)
            {
                _agents.Angles[slot] = new float[angles.Length];
            }

            if (_agents.Rotations[slot].Length != kind.JointCount)
            {
                _agents.Rotations[slot] = new Quaternion[kind.JointCount];
            }
        }

        _agents.Path[slot] = null;
        _agents.StopAtStance[slot] = false;
        _agents.Stance[slot] = stance;
        _agents.Root[slot] = stance.Pose;
        PlaceBody(slot);
        if (!ReferenceEquals(angles, _agents.Angles[slot]))
        {
            angles.CopyTo(_agents.Angles[slot], 0);
        }

        _agents.PoseDirty[slot] = true;
        _agents.State[slot] = AgentState.Idle;
    }

    /// <summary>Why <paramref name="kind"/> cannot join this world, or <c>null</c> when it can.</summary>
    private RuntimeResult? Check(CharacterKind? kind)
    {
        if (kind is null)
        {
            return new RuntimeResult(RuntimeStatus.InvalidArgument, "the character kind is null");
        }

        if (kind.Scene.Level.Fingerprint != Level.Fingerprint)
        {
            return new RuntimeResult(RuntimeStatus.Mismatch, $"kind '{kind.Name}': its scene is of another level than this world's ({Level.Source})");
        }

        if (kind.Roadmap.LevelFingerprint != Level.Fingerprint)
        {
            return new RuntimeResult(RuntimeStatus.Mismatch, $"kind '{kind.Name}': its roadmap was baked on another level");
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
    /// placed there. Fails with <see cref="RuntimeStatus.InvalidPosition"/> when the character can stand nowhere near.
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

        if (!kind.Assigned || (uint)kind.Index >= (uint)_kinds.Count)
        {
            return new AddAgentResult(new RuntimeResult(RuntimeStatus.UnknownKind, $"{kind} is not a kind of this world ({_kinds.Count} kinds)"), default);
        }

        if (!Finite(position))
        {
            return new AddAgentResult(new RuntimeResult(RuntimeStatus.InvalidArgument, $"the position {position} is not finite"), default);
        }

        CharacterKind k = _kinds[kind.Index];
        if (Stand(k, position, out RuntimeResult failure) is not { } stance)
        {
            return new AddAgentResult(failure, default);
        }

        int slot = _agents.Add(kind.Index, k, stance.Node.Pose, stance.Node, stance.Angles, new Quaternion[k.JointCount]);
        PlaceBody(slot);
        return new AddAgentResult(RuntimeResult.Success, _agents.HandleOf(slot));
    }

    /// <summary>
    /// Removes an agent at once, in whatever state (its pending request is dropped). The result's reason, and a
    /// <see cref="JumpEventKind.Removed"/> event at the start of the next tick, say in which state it was removed.
    /// </summary>
    public RuntimeResult RemoveAgent(AgentHandle agent)
    {
        using Gate gate = Gate.Enter(_gate, "world", out RuntimeResult? busy);
        if (busy is { } crowded)
        {
            return crowded;
        }

        if (Gone() is { } gone)
        {
            return gone;
        }

        if (!_agents.IsValid(agent))
        {
            return Unknown(agent);
        }

        int slot = agent.Index;
        AgentState state = _agents.State[slot];
        string reason = _agents.Path[slot] is { } path && state is AgentState.Takeoff or AgentState.Flight or AgentState.Landing
            ? $"removed in mid-{(state == AgentState.Flight ? "flight" : state.ToString().ToLowerInvariant())} of jump {(_agents.Cursor[slot] >> 1) + 1} of {path.Count}"
            : $"removed while {state.ToString().ToLowerInvariant()}";
        _pending.Add(new JumpEvent(JumpEventKind.Removed, agent, Tick, Time, -1, _agents.Root[slot].Position, _agents.Target[slot], default, 0f, Planner.Planning.PlannerStatus.Exact, reason));
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
        using Gate gate = Gate.Enter(_gate, "world", out RuntimeResult? busy);
        if (busy is { } crowded)
        {
            return crowded;
        }

        if (Gone() is { } gone)
        {
            return gone;
        }

        if (!_agents.IsValid(agent))
        {
            return Unknown(agent);
        }

        if (!Finite(target))
        {
            return new RuntimeResult(RuntimeStatus.InvalidArgument, $"the target {target} is not finite");
        }

        int slot = agent.Index;
        bool had = _agents.HasTarget[slot];
        Vector3 previous = _agents.Target[slot];
        _agents.Target[slot] = target;
        _agents.HasTarget[slot] = true;
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
        using Gate gate = Gate.Enter(_gate, "world", out RuntimeResult? busy);
        if (busy is { } crowded)
        {
            return crowded;
        }

        if (Gone() is { } gone)
        {
            return gone;
        }

        if (!_agents.IsValid(agent))
        {
            return Unknown(agent);
        }

        int slot = agent.Index;
        _agents.HasTarget[slot] = false;
        _queue.Cancel(slot);
        if (_agents.Path[slot] is not null)
        {
            _agents.StopAtStance[slot] = true;
        }
        else
        {
            _agents.State[slot] = AgentState.Idle;
        }

        return RuntimeResult.Success;
    }

    /// <summary>
    /// Moves the agent at once to stand at <paramref name="position"/> (pushed, teleported), dropping its path; with a
    /// target it plans anew from there. Fails with <see cref="RuntimeStatus.InvalidPosition"/>, leaving the agent as it was, when it cannot stand there.
    /// </summary>
    public RuntimeResult Warp(AgentHandle agent, Vector3 position)
    {
        using Gate gate = Gate.Enter(_gate, "world", out RuntimeResult? busy);
        if (busy is { } crowded)
        {
            return crowded;
        }

        if (Gone() is { } gone)
        {
            return gone;
        }

        if (!_agents.IsValid(agent))
        {
            return Unknown(agent);
        }

        if (!Finite(position))
        {
            return new RuntimeResult(RuntimeStatus.InvalidArgument, $"the position {position} is not finite");
        }

        int slot = agent.Index;
        CharacterKind kind = _kinds[_agents.Kind[slot]];
        if (Stand(kind, position, out RuntimeResult failure) is not { } stance)
        {
            return failure;
        }

        _queue.Cancel(slot);
        Settle(slot, kind, stance.Node, stance.Angles);
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
        using Gate gate = Gate.Enter(_gate, "world", out RuntimeResult? busy);
        if (busy is { } crowded)
        {
            return crowded;
        }

        if (Gone() is { } gone)
        {
            return gone;
        }

        if (!_agents.IsValid(agent))
        {
            return Unknown(agent);
        }

        int slot = agent.Index;
        CharacterKind kind = _kinds[_agents.Kind[slot]];
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
        using Gate gate = Gate.Enter(_gate, "world", out RuntimeResult? busy);
        if (busy is { } crowded)
        {
            return crowded;
        }

        if (Gone() is { } gone)
        {
            return gone;
        }

        if (!_agents.IsValid(agent))
        {
            return Unknown(agent);
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
        CharacterKind kind = _kinds[_agents.Kind[slot]];
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
        using Gate gate = Gate.Enter(_gate, "world", out RuntimeResult? busy);
        if (busy is { } crowded)
        {
            return crowded;
        }

        if (Gone() is { } gone)
        {
            return gone;
        }

        if (!_agents.IsValid(agent))
        {
            return Unknown(agent);
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
    public void Step()
    {
        using Gate gate = Gate.Wait(_gate);
        ObjectDisposedException.ThrowIf(_disposed, this);
        if (IsStepping)
        {
            throw new InvalidOperationException("JumpWorld.Step was called from inside a system of the world's own tick");
        }

        IsStepping = true;
        try
        {
            Tick++;
            _events.Clear();
            Commands.Play(this, _commandRefused);
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

    /// <summary>The agent's kind, or the default handle for an unknown agent.</summary>
    public KindHandle GetKind(AgentHandle agent) => _agents.IsValid(agent) ? new KindHandle(_agents.Kind[agent.Index], true) : default;

    /// <summary>What the agent does this tick (<see cref="AgentState.Idle"/> for an unknown agent).</summary>
    public AgentState GetState(AgentHandle agent) => _agents.IsValid(agent) ? _agents.State[agent.Index] : AgentState.Idle;

    /// <summary>The agent's root pose this tick: trunk centre (world metres) and trunk orientation; exactly on the arc in flight and on the walk's <see cref="Walk.PoseAt"/> while walking.</summary>
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
    /// order); empty for an unknown agent. Filled by the pose system; read-only view, valid until the next tick.
    /// </summary>
    public ReadOnlySpan<float> GetJointAngles(AgentHandle agent) => _agents.IsValid(agent) ? _agents.Angles[agent.Index] : [];

    /// <summary>
    /// The agent's joint rotations this tick, one per joint of its rig (<see cref="Planner.Rigs.Rig.Joints"/> order),
    /// each local to its parent joint (the root joint's local to the root pose, <see cref="GetRootPose"/>); empty
    /// for an unknown agent. Filled by the pose system; read-only view, valid until the next tick.
    /// </summary>
    public ReadOnlySpan<Quaternion> GetJointRotations(AgentHandle agent) => _agents.IsValid(agent) ? _agents.Rotations[agent.Index] : [];

    /// <summary>Copies the handles of the live agents, in slot order, into <paramref name="destination"/>; returns how many were written.</summary>
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
            _requests.Dispose();
        }
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

    /// <summary>The refusal of every call after <see cref="Dispose"/> (but <see cref="Step"/>, which throws), or <c>null</c> before.</summary>
    private RuntimeResult? Gone() => _disposed ? new RuntimeResult(RuntimeStatus.Disposed, "the world was disposed: nothing was done") : null;

    private static RuntimeResult Unknown(AgentHandle agent) => new(RuntimeStatus.UnknownAgent, $"{agent} is not an agent of this world (never added, or removed)");

    private static bool Finite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);
}
