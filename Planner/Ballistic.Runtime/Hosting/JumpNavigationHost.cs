using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Runtime.Hosting;

/// <summary>
/// The engine-free core of the <c>JumpNavigationServer</c> autoload, after Godot's <c>NavigationServer3D</c>: regions
/// (one per <c>JumpRoadmap3D</c> node, each a character kind: scene, roadmap, animator) and agents (one per
/// <c>JumpAgent3D</c> node) named by handles, one <see cref="JumpWorld"/> behind them, stepped by <see cref="Step"/>,
/// whose events are sorted into one queue per agent.
/// </summary>
/// <remarks>
/// <para>
/// Order does not matter, as in Godot's <c>_Ready</c> (children before parents, siblings in order): a region handle
/// exists from <see cref="CreateRegion"/>, before the region has a roadmap; an agent registered on it waits
/// (<see cref="HostAgentState.Waiting"/>, its target kept) and joins the world where it stands when
/// <see cref="SetRegionKind"/> gives the region its roadmap. Giving a region a new roadmap of the same level (a
/// rebake) keeps its agents in the world under the same handles, and moves none of them: each is put on the new
/// roadmap where it stands, or, in a jump or a walk, where that move ends (<see cref="JumpWorld.ReplaceKind"/>), its
/// target asked again. Clearing a region's roadmap sends its agents back to waiting; freeing
/// the region detaches them for good; both with a <see cref="JumpEventKind.Removed"/> event saying why.
/// </para>
/// <para>
/// One level at a time: the world is created on the level of the first region given a roadmap, and a region of
/// another level is refused with the reason while any other region holds a roadmap. When none does (the scene was
/// changed and the old regions freed), the next region's level starts a new world. A freed region's kind stays in the
/// world (holding its roadmap) until another region reuses its slot or the world ends.
/// </para>
/// <para>
/// Like the world: calls and <see cref="Step"/> belong on one thread (the game loop); a change called from another
/// thread while that thread steps or changes the host is refused with <see cref="RuntimeStatus.Busy"/>
/// (<see cref="Step"/>, draining, <see cref="CreateRegion"/> and the reachability test wait for it instead), so a
/// breach never corrupts the host. No call throws for a bad handle
/// or bad input (a <see cref="RuntimeResult"/> says why), nor after <see cref="Dispose"/>: then every call but
/// <see cref="Step"/> does nothing and says so (<see cref="RuntimeStatus.Disposed"/>, false or no value). Positions are world metres, Y up: an agent's position and
/// target are points on or near a surface (its body's ground point), as <see cref="JumpWorld.AddAgent"/> takes them.
/// Stepping allocates nothing once the queues have grown to their working size: the node of each agent must drain its
/// queue every physics tick (<see cref="TryDequeueEvent"/>). A queue nobody drains keeps only its newest
/// <see cref="MaxQueuedEvents"/> events (each move event carries its path, so a node that drains again picks up the
/// path it is on), so that an agent whose node stopped draining does not hold every path it was ever given.
/// </para>
/// </remarks>
public sealed class JumpNavigationHost : IDisposable
{
    /// <summary>Most events an agent's queue holds: past that, the oldest goes as each new one comes.</summary>
    public const int MaxQueuedEvents = 256;

    /// <summary>Nodes near a stance or target that a reachability test starts from or aims at when it is no roadmap node.</summary>
    private const int NearbyNodes = 32;

    private readonly List<RegionRecord> _regions = [];
    private readonly Stack<int> _freeRegions = new();
    private readonly List<AgentRecord> _agents = [];
    private readonly Stack<int> _freeAgents = new();
    private readonly Stack<KindHandle> _retiredKinds = new();
    private readonly List<(float Distance, int Id)> _nearest = [];
    private int[] _bySlot = [];
    private int[] _seen = [];
    private int[] _goal = [];
    private int[] _stack = [];
    private int _stamp;
    private JumpWorld? _world;
    private bool _disposed;

    /// <summary>Held by the thread stepping or changing the host (<see cref="Gate"/>).</summary>
    private readonly object _gate = new();

    /// <summary>Creates a host with no world yet.</summary>
    /// <param name="settings">The settings of the worlds it creates; when <c>null</c>, the defaults with a real-time wait for late animations (<see cref="WorldSettings.RealTimeAnimationWait"/>): the host serves a game stepping at its physics rate.</param>
    /// <exception cref="ArgumentException">A setting is out of range.</exception>
    public JumpNavigationHost(WorldSettings? settings = null)
    {
        Settings = settings ?? new WorldSettings { MaxAnimationWait = WorldSettings.RealTimeAnimationWait };
        if (Settings.Problem() is { } problem)
        {
            throw new ArgumentException($"World settings: {problem}.", nameof(settings));
        }

        Settings.Tolerance.Validate();
    }

    /// <summary>The settings of the world; <see cref="WorldSettings.TickSeconds"/> is the fixed tick to call <see cref="Step"/> at.</summary>
    public WorldSettings Settings { get; }

    /// <summary>The world, while some region holds a roadmap; <c>null</c> before (and after the last one is cleared or freed).</summary>
    public JumpWorld? World => _world;

    /// <summary>Live regions (with or without a roadmap).</summary>
    public int RegionCount => _regions.Count - _freeRegions.Count;

    /// <summary>Registered agents, in any state.</summary>
    public int AgentCount => _agents.Count - _freeAgents.Count;

    /// <summary>
    /// Creates a region without a roadmap yet (a <c>JumpRoadmap3D</c> node gets its handle when first asked, so that
    /// agents readied before it can name it). Agents registered on it wait for its roadmap.
    /// </summary>
    /// <param name="name">A name for messages (the node's path); "region N" when empty.</param>
    public RegionHandle CreateRegion(string name)
    {
        using Gate gate = Gate.Wait(_gate);
        int index;
        RegionRecord region;
        if (_freeRegions.Count > 0)
        {
            index = _freeRegions.Pop();
            region = _regions[index];
        }
        else
        {
            index = _regions.Count;
            region = new RegionRecord();
            _regions.Add(region);
        }

        region.Generation++;
        region.Alive = true;
        region.Name = string.IsNullOrWhiteSpace(name) ? $"region {index}" : name;
        region.Kind = null;
        region.KindHandle = default;
        region.Agents.Clear();
        return new RegionHandle(index, region.Generation);
    }

    /// <summary>True while <paramref name="region"/> names a live region of this host.</summary>
    public bool IsValid(RegionHandle region) =>
        region.Generation > 0 && (uint)region.Index < (uint)_regions.Count && _regions[region.Index].Alive && _regions[region.Index].Generation == region.Generation;

    /// <summary>The region's name, or <c>null</c> for an unknown region.</summary>
    public string? GetRegionName(RegionHandle region) => IsValid(region) ? _regions[region.Index].Name : null;

    /// <summary>The region's character kind (scene, roadmap, animator), or <c>null</c> when it has none yet (or is unknown).</summary>
    public CharacterKind? GetRegionKind(RegionHandle region) => IsValid(region) ? _regions[region.Index].Kind : null;

    /// <summary>The region's kind in <see cref="World"/>, or the default handle when it has no roadmap (or is unknown).</summary>
    public KindHandle GetRegionWorldKind(RegionHandle region) => IsValid(region) && _regions[region.Index].Kind is not null ? _regions[region.Index].KindHandle : default;

    /// <summary>Agents registered on the region, in any state; zero for an unknown region.</summary>
    public int GetRegionAgentCount(RegionHandle region) => IsValid(region) ? _regions[region.Index].Agents.Count : 0;

    /// <summary>
    /// Gives the region its roadmap, or a new one (a rebake), or none (<paramref name="kind"/> <c>null</c>: cleared).
    /// Given one, the region's agents join the world where they stand (their targets asked again; those already on
    /// its previous roadmap keep their world handles and join where the move they are in ends); an agent that
    /// cannot stand there on the new roadmap becomes <see cref="HostAgentState.Unplaced"/> with a
    /// <see cref="JumpEventKind.Removed"/> event saying why. Cleared, the agents leave the world and wait, also with
    /// a <see cref="JumpEventKind.Removed"/> event. Refused, leaving everything as it was, when the region is
    /// unknown, the roadmap was baked on another level or for another character than the kind's scene, or the
    /// kind's level is not the level of the other regions with a roadmap (see the remarks).
    /// </summary>
    /// <param name="region">The region.</param>
    /// <param name="kind">Its character kind: scene, baked roadmap and animator; <c>null</c> to clear the roadmap.</param>
    public RuntimeResult SetRegionKind(RegionHandle region, CharacterKind? kind)
    {
        using Gate gate = Gate.Enter(_gate, "host", out RuntimeResult? busy);
        if (busy is { } crowded)
        {
            return crowded;
        }

        if (Gone() is { } gone)
        {
            return gone;
        }

        if (!IsValid(region))
        {
            return UnknownRegion(region);
        }

        RegionRecord r = _regions[region.Index];
        if (kind is null)
        {
            int lifted = Lift(r, HostAgentState.Waiting, $"region '{r.Name}' lost its roadmap: the agent waits for a new one");
            Retire(r);
            return new RuntimeResult(RuntimeStatus.Ok, $"region '{r.Name}' cleared: {Agents(r.Agents.Count)} wait for a roadmap ({lifted} were in the world)");
        }

        if (kind.Roadmap.LevelFingerprint != kind.Scene.Level.Fingerprint)
        {
            return new RuntimeResult(RuntimeStatus.Mismatch, $"region '{r.Name}': its roadmap was baked on another level than its scene's ({kind.Scene.Level.Source})");
        }

        if (kind.Roadmap.CharacterFingerprint != kind.Scene.Character.Fingerprint)
        {
            return new RuntimeResult(RuntimeStatus.Mismatch, $"region '{r.Name}': its roadmap was baked for another character ({kind.Roadmap.CharacterName}) than its scene's ({kind.Name})");
        }

        bool others = false;
        foreach (RegionRecord other in _regions)
        {
            others |= other.Alive && other != r && other.Kind is not null;
        }

        if (others && kind.Scene.Level.Fingerprint != _world!.Level.Fingerprint)
        {
            return new RuntimeResult(RuntimeStatus.Mismatch,
                $"region '{r.Name}': its level ({kind.Scene.Level.Source}) is not the level of the other regions ({_world.Level.Source}); one level at a time: free or clear those regions first");
        }

        // A rebake on the same level: the world keeps the agents under their handles and moves them onto the new
        // roadmap itself, each where it stands or, in a move, where that move ends (remembered here in case the new
        // character cannot stand there and the world lets it go).
        bool rebake = r.Kind is not null && _world is not null && _world.Level.Fingerprint == kind.Scene.Level.Fingerprint;
        if (rebake)
        {
            foreach (int index in r.Agents)
            {
                AgentRecord a = _agents[index];
                if (a.State == HostAgentState.Active && Stances.Standing(_world!, a.World) is { } standing)
                {
                    a.Point = standing.ContactCentre;
                }
            }
        }
        else
        {
            Lift(r, HostAgentState.Waiting, reason: null);
        }

        if (_world is null || (!others && _world.Level.Fingerprint != kind.Scene.Level.Fingerprint))
        {
            // No other region holds a roadmap: (re)start the world on this level.
            _world?.Dispose();
            _world = new JumpWorld(kind.Scene.Level, Settings);
            _retiredKinds.Clear();
            Array.Fill(_bySlot, -1);
            r.KindHandle = default;
        }

        RuntimeResult joined;
        if (r.KindHandle.Assigned || _retiredKinds.TryPop(out r.KindHandle))
        {
            joined = _world.ReplaceKind(r.KindHandle, kind);
        }
        else
        {
            AddKindResult added = _world.AddKind(kind);
            joined = added.Result;
            r.KindHandle = added.Kind;
        }

        if (!joined.Ok)
        {
            // Not expected after the checks above; the region is left without a roadmap, its agents waiting.
            Retire(r);
            return joined;
        }

        r.Kind = kind;
        int placed = 0;
        string? firstFailure = null;
        foreach (int index in r.Agents)
        {
            AgentRecord a = _agents[index];
            if (a.State == HostAgentState.Active)
            {
                if (_world.IsValid(a.World))
                {
                    placed++;
                    continue;
                }

                // Rebaked for another character that cannot stand where the agent stood: the world let it go.
                Unplace(a, $"cannot stand at {a.Point} on the new roadmap of region '{r.Name}' (rebaked for another character)");
                Tell(a, a.Reason!);
                firstFailure ??= a.Reason;
                continue;
            }

            RuntimeResult result = Place(index, a, r, notify: true);
            if (result.Ok)
            {
                placed++;
            }
            else
            {
                firstFailure ??= result.Reason;
            }
        }

        int unplaced = r.Agents.Count - placed;
        return new RuntimeResult(RuntimeStatus.Ok,
            $"region '{r.Name}' has a roadmap of {kind.Roadmap.Nodes.Count} nodes: {Agents(placed)} on it" + (unplaced > 0 ? $", {unplaced} could not stand where they were ({firstFailure})" : ""));
    }

    /// <summary>
    /// Frees a region: its agents leave the world for good (<see cref="HostAgentState.Detached"/>), each with a
    /// <see cref="JumpEventKind.Removed"/> event saying so; their handles stay valid until unregistered.
    /// </summary>
    public RuntimeResult FreeRegion(RegionHandle region)
    {
        using Gate gate = Gate.Enter(_gate, "host", out RuntimeResult? busy);
        if (busy is { } crowded)
        {
            return crowded;
        }

        if (Gone() is { } gone)
        {
            return gone;
        }

        if (!IsValid(region))
        {
            return UnknownRegion(region);
        }

        RegionRecord r = _regions[region.Index];
        int count = r.Agents.Count;
        string reason = $"region '{r.Name}' was unregistered";
        Lift(r, HostAgentState.Detached, reason);
        foreach (int index in r.Agents)
        {
            AgentRecord a = _agents[index];
            if (a.State != HostAgentState.Detached)
            {
                // Waiting or unplaced: out of the world already, but told all the same.
                Detach(a, reason);
            }

            a.Region = -1;
        }

        r.Agents.Clear();
        Retire(r);
        r.Alive = false;
        _freeRegions.Push(region.Index);
        return new RuntimeResult(RuntimeStatus.Ok, $"{reason}: {Agents(count)} detached");
    }

    /// <summary>
    /// Registers an agent of <paramref name="region"/> standing at <paramref name="position"/> (its body's ground
    /// point, world metres). When the region has a roadmap the agent joins the world at once, as by
    /// <see cref="JumpWorld.AddAgent"/> (or stays <see cref="HostAgentState.Unplaced"/>, the result saying why);
    /// otherwise it waits for it. Refused, with no handle, for an unknown region or a position that is not finite.
    /// </summary>
    public HostAgentResult RegisterAgent(RegionHandle region, Vector3 position)
    {
        using Gate gate = Gate.Enter(_gate, "host", out RuntimeResult? busy);
        if (busy is { } crowded)
        {
            return new HostAgentResult(crowded, default);
        }

        if (Gone() is { } gone)
        {
            return new HostAgentResult(gone, default);
        }

        if (!IsValid(region))
        {
            return new HostAgentResult(UnknownRegion(region), default);
        }

        if (!Finite(position))
        {
            return new HostAgentResult(new RuntimeResult(RuntimeStatus.InvalidArgument, $"the position {position} is not finite"), default);
        }

        int index;
        AgentRecord a;
        if (_freeAgents.Count > 0)
        {
            index = _freeAgents.Pop();
            a = _agents[index];
        }
        else
        {
            index = _agents.Count;
            a = new AgentRecord();
            _agents.Add(a);
        }

        a.Generation++;
        a.Alive = true;
        a.Region = region.Index;
        a.Point = position;
        a.World = default;
        a.HasTarget = false;
        a.Target = default;
        a.Queue.Clear();
        RegionRecord r = _regions[region.Index];
        r.Agents.Add(index);
        var handle = new HostAgentHandle(index, a.Generation);
        if (r.Kind is null)
        {
            a.State = HostAgentState.Waiting;
            a.Reason = $"waiting for region '{r.Name}' to get a roadmap";
            return new HostAgentResult(new RuntimeResult(RuntimeStatus.Ok, a.Reason), handle);
        }

        return new HostAgentResult(Place(index, a, r, notify: false), handle);
    }

    /// <summary>Unregisters an agent in any state (taking it out of the world; its queue is dropped); its handle becomes invalid.</summary>
    public RuntimeResult UnregisterAgent(HostAgentHandle agent)
    {
        using Gate gate = Gate.Enter(_gate, "host", out RuntimeResult? busy);
        if (busy is { } crowded)
        {
            return crowded;
        }

        if (Gone() is { } gone)
        {
            return gone;
        }

        if (!IsValid(agent))
        {
            return UnknownAgent(agent);
        }

        AgentRecord a = _agents[agent.Index];
        string state = a.State.ToString().ToLowerInvariant();
        if (a.State == HostAgentState.Active)
        {
            Unmap(a);
        }

        if (a.Region >= 0)
        {
            _regions[a.Region].Agents.Remove(agent.Index);
        }

        a.Alive = false;
        a.Queue.Clear();
        _freeAgents.Push(agent.Index);
        return new RuntimeResult(RuntimeStatus.Ok, $"unregistered while {state}");
    }

    /// <summary>True while <paramref name="agent"/> names a registered agent of this host.</summary>
    public bool IsValid(HostAgentHandle agent) =>
        agent.Generation > 0 && (uint)agent.Index < (uint)_agents.Count && _agents[agent.Index].Alive && _agents[agent.Index].Generation == agent.Generation;

    /// <summary>Where the agent is (<see cref="HostAgentState.Detached"/> for an unknown agent).</summary>
    public HostAgentState GetAgentState(HostAgentHandle agent) => IsValid(agent) ? _agents[agent.Index].State : HostAgentState.Detached;

    /// <summary>Why the agent waits, could not be placed or was detached; <c>null</c> while it is in the world (or unknown).</summary>
    public string? GetAgentReason(HostAgentHandle agent) => IsValid(agent) ? _agents[agent.Index].Reason : null;

    /// <summary>The agent's region, or the default handle once it was detached (or for an unknown agent).</summary>
    public RegionHandle GetAgentRegion(HostAgentHandle agent) =>
        IsValid(agent) && _agents[agent.Index].Region is int r and >= 0 ? new RegionHandle(r, _regions[r].Generation) : default;

    /// <summary>
    /// The agent's handle in <see cref="World"/> while it is <see cref="HostAgentState.Active"/>, for the world's
    /// queries (root pose, joint buffers, path, next jump); the default handle otherwise. A rebake of its region on the
    /// same level keeps it; it changes when the agent leaves the world and joins again (its region cleared or freed, a
    /// roadmap of another level, a warp of an unplaced agent).
    /// </summary>
    public AgentHandle GetWorldAgent(HostAgentHandle agent) =>
        IsValid(agent) && _agents[agent.Index].State == HostAgentState.Active ? _agents[agent.Index].World : default;

    /// <summary>The agent's target, when it has one (kept while it waits, asked again when it joins the world).</summary>
    public Vector3? GetTarget(HostAgentHandle agent) => IsValid(agent) && _agents[agent.Index].HasTarget ? _agents[agent.Index].Target : null;

    /// <summary>
    /// The agent's position as the host knows it, world metres: in the world, the contact centre of the stance it stands
    /// on (or will land on); otherwise the position it was registered or warped at.
    /// </summary>
    public Vector3? GetStandingPoint(HostAgentHandle agent)
    {
        if (!IsValid(agent))
        {
            return null;
        }

        AgentRecord a = _agents[agent.Index];
        return a.State == HostAgentState.Active && _world is { } world && Stances.Standing(world, a.World) is { } stance ? stance.ContactCentre : a.Point;
    }

    /// <summary>
    /// Sends the agent toward <paramref name="target"/> (a point on or near a surface, world metres), as
    /// <see cref="JumpWorld.SetTarget"/>; an agent out of the world keeps the target and is sent when it joins.
    /// Fails for an unknown or detached agent or a target that is not finite.
    /// </summary>
    public RuntimeResult SetTarget(HostAgentHandle agent, Vector3 target)
    {
        using Gate gate = Gate.Enter(_gate, "host", out RuntimeResult? busy);
        if (busy is { } crowded)
        {
            return crowded;
        }

        if (Usable(agent, out AgentRecord? a) is { } refused)
        {
            return refused;
        }

        if (!Finite(target))
        {
            return new RuntimeResult(RuntimeStatus.InvalidArgument, $"the target {target} is not finite");
        }

        a!.Target = target;
        a.HasTarget = true;
        return a.State == HostAgentState.Active
            ? _world!.SetTarget(a.World, target)
            : new RuntimeResult(RuntimeStatus.Ok, $"target kept: the agent is {a.State.ToString().ToLowerInvariant()} ({a.Reason})");
    }

    /// <summary>Forgets the agent's target, as <see cref="JumpWorld.ClearTarget"/>.</summary>
    public RuntimeResult ClearTarget(HostAgentHandle agent)
    {
        using Gate gate = Gate.Enter(_gate, "host", out RuntimeResult? busy);
        if (busy is { } crowded)
        {
            return crowded;
        }

        if (Usable(agent, out AgentRecord? a) is { } refused)
        {
            return refused;
        }

        a!.HasTarget = false;
        return a.State == HostAgentState.Active ? _world!.ClearTarget(a.World) : RuntimeResult.Success;
    }

    /// <summary>
    /// Moves the agent to stand at <paramref name="position"/> (world metres), as <see cref="JumpWorld.Warp"/>. A
    /// waiting agent will join there; an unplaced one tries to stand there now. Fails, leaving the agent as it was,
    /// for an unknown or detached agent, a position that is not finite, or one where the character cannot stand.
    /// </summary>
    public RuntimeResult Warp(HostAgentHandle agent, Vector3 position)
    {
        using Gate gate = Gate.Enter(_gate, "host", out RuntimeResult? busy);
        if (busy is { } crowded)
        {
            return crowded;
        }

        if (Usable(agent, out AgentRecord? a) is { } refused)
        {
            return refused;
        }

        if (!Finite(position))
        {
            return new RuntimeResult(RuntimeStatus.InvalidArgument, $"the position {position} is not finite");
        }

        switch (a!.State)
        {
            case HostAgentState.Active:
                RuntimeResult warped = _world!.Warp(a.World, position);
                if (warped.Ok)
                {
                    a.Point = position;
                }

                return warped;
            case HostAgentState.Unplaced:
                a.Point = position;
                return Place(agent.Index, a, _regions[a.Region], notify: false);
            default:
                a.Point = position;
                return new RuntimeResult(RuntimeStatus.Ok, $"position kept: {a.Reason}");
        }
    }

    /// <summary>
    /// Performs exactly one jump of the agent's roadmap, edge <paramref name="edge"/> of its region's roadmap, as
    /// <see cref="JumpWorld.PerformJump"/>: the agent stands on the edge's takeoff node at once and its target becomes
    /// the landing node's contact centre. Fails for an agent that is not in the world.
    /// </summary>
    public RuntimeResult PerformJump(HostAgentHandle agent, int edge)
    {
        using Gate gate = Gate.Enter(_gate, "host", out RuntimeResult? busy);
        if (busy is { } crowded)
        {
            return crowded;
        }

        if (Usable(agent, out AgentRecord? a) is { } refused)
        {
            return refused;
        }

        if (a!.State != HostAgentState.Active)
        {
            return new RuntimeResult(RuntimeStatus.InvalidPosition, $"{agent} is not on a roadmap: {a.Reason}");
        }

        RuntimeResult result = _world!.PerformJump(a.World, edge);
        if (result.Ok)
        {
            Roadmap roadmap = _regions[a.Region].Kind!.Roadmap;
            a.Target = roadmap.ContactCentres[roadmap.Edges[edge].To];
            a.HasTarget = true;
        }

        return result;
    }

    /// <summary>
    /// Performs exactly <paramref name="moves"/> (jumps and walks, with no search), as <see cref="JumpWorld.PerformMoves"/>:
    /// the agent stands on the first move's stance at once and its target becomes the last stance's contact centre.
    /// For tests and tools. Fails for an agent that is not in the world.
    /// </summary>
    internal RuntimeResult PerformMoves(HostAgentHandle agent, IReadOnlyList<Move> moves)
    {
        using Gate gate = Gate.Enter(_gate, "host", out RuntimeResult? busy);
        if (busy is { } crowded)
        {
            return crowded;
        }

        if (Usable(agent, out AgentRecord? a) is { } refused)
        {
            return refused;
        }

        if (a!.State != HostAgentState.Active)
        {
            return new RuntimeResult(RuntimeStatus.InvalidPosition, $"{agent} is not on a roadmap: {a.Reason}");
        }

        RuntimeResult result = _world!.PerformMoves(a.World, moves);
        if (result.Ok)
        {
            a.Target = _world.GetTarget(a.World) ?? a.Target;
            a.HasTarget = true;
        }

        return result;
    }

    /// <summary>Takes the oldest undelivered event of the agent; false when its queue is empty (or the agent unknown). Allocates nothing.</summary>
    public bool TryDequeueEvent(HostAgentHandle agent, out JumpEvent e)
    {
        using Gate gate = Gate.Wait(_gate);
        e = default;
        return IsValid(agent) && _agents[agent.Index].Queue.TryDequeue(out e);
    }

    /// <summary>Events waiting in the agent's queue; zero for an unknown agent.</summary>
    public int GetPendingEventCount(HostAgentHandle agent) => IsValid(agent) ? _agents[agent.Index].Queue.Count : 0;

    /// <summary>
    /// Whether the agent's roadmap connects where it stands to <paramref name="target"/>: a path of jumps (and of the
    /// roadmap's walks, unless the world's <see cref="WorldSettings.Locomotion"/> is jumps only) leads from its stance (a roadmap node, or for a stance off the roadmap any of the nearest nodes within jump reach) to the
    /// node standing at the target (<see cref="Roadmap.FindNode"/>), or, when none stands there, to any of the
    /// nearest nodes within jump reach of the target. An estimate for stances and targets off the roadmap (the
    /// planner must still steer to and from them); false for an agent that is not in the world. Allocates nothing
    /// once its scratch has grown to the roadmap's size.
    /// </summary>
    public bool IsTargetReachable(HostAgentHandle agent, Vector3 target)
    {
        using Gate gate = Gate.Wait(_gate);
        if (_disposed || !IsValid(agent) || !Finite(target) || _agents[agent.Index].State != HostAgentState.Active)
        {
            return false;
        }

        AgentRecord a = _agents[agent.Index];
        CharacterKind kind = _regions[a.Region].Kind!;
        Roadmap roadmap = kind.Roadmap;
        if (Stances.Standing(_world!, a.World) is not { } stance || roadmap.Nodes.Count == 0)
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
        if (Stances.IsNodeOf(roadmap, stance))
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

    /// <summary>Puts <paramref name="node"/> on the reachability test's stack unless it was seen.</summary>
    private void Push(int node, ref int top)
    {
        if (_seen[node] != _stamp)
        {
            _seen[node] = _stamp;
            _stack[top++] = node;
        }
    }

    /// <summary>
    /// One tick of the world (call it from <c>_PhysicsProcess</c> at <see cref="WorldSettings.TickSeconds"/>), then
    /// its events into the queues of their agents, in order. Does nothing while no region has a roadmap.
    /// </summary>
    /// <exception cref="ObjectDisposedException">The host was disposed.</exception>
    public void Step()
    {
        using Gate gate = Gate.Wait(_gate);
        ObjectDisposedException.ThrowIf(_disposed, this);
        if (_world is null)
        {
            return;
        }

        _world.Step();
        foreach (ref readonly JumpEvent e in _world.Events)
        {
            Route(e);
        }
    }

    /// <summary>Stops the world (waiting for its background animations).</summary>
    public void Dispose()
    {
        using Gate gate = Gate.Wait(_gate);
        if (!_disposed)
        {
            _disposed = true;
            _world?.Dispose();
            _world = null;
        }
    }

    private void Route(in JumpEvent e)
    {
        int slot = e.Agent.Index;
        if ((uint)slot >= (uint)_bySlot.Length || _bySlot[slot] < 0)
        {
            return; // an agent the host took out of the world itself: its removal was told already
        }

        AgentRecord a = _agents[_bySlot[slot]];
        if (a.World != e.Agent)
        {
            return;
        }

        switch (e.Kind)
        {
            case JumpEventKind.Removed:
                // The world let the agent go itself (its region was rebaked for another character, which cannot stand
                // where the agent stopped): it waits, unplaced, where it stood (remembered at the rebake).
                Unplace(a, e.Reason ?? "the world removed the agent");
                break;
            case JumpEventKind.TargetReached:
                a.HasTarget = false;
                break;
            default:
                break;
        }

        Enqueue(a, e);
    }

    /// <summary>Adds the agent to the world on its region's kind, where it was; asks its target again.</summary>
    private RuntimeResult Place(int index, AgentRecord a, RegionRecord r, bool notify)
    {
        AddAgentResult added = _world!.AddAgent(r.KindHandle, a.Point);
        if (!added.Ok)
        {
            a.State = HostAgentState.Unplaced;
            a.Reason = $"cannot stand at {a.Point} on the roadmap of region '{r.Name}': {added.Result.Reason}";
            if (notify)
            {
                Tell(a, a.Reason);
            }

            return new RuntimeResult(added.Result.Status, a.Reason);
        }

        a.State = HostAgentState.Active;
        a.Reason = null;
        a.World = added.Agent;
        if (_bySlot.Length <= added.Agent.Index)
        {
            int old = _bySlot.Length;
            Array.Resize(ref _bySlot, Math.Max(16, Math.Max(added.Agent.Index + 1, 2 * old)));
            Array.Fill(_bySlot, -1, old, _bySlot.Length - old);
        }

        _bySlot[added.Agent.Index] = index;
        if (a.HasTarget)
        {
            _world.SetTarget(a.World, a.Target);
        }

        return RuntimeResult.Success;
    }

    /// <summary>
    /// Takes the region's agents out of the world, each remembering where it stands, into <paramref name="state"/>;
    /// with a <paramref name="reason"/>, each is told by a removal event. Returns how many were in the world.
    /// </summary>
    private int Lift(RegionRecord r, HostAgentState state, string? reason)
    {
        int lifted = 0;
        foreach (int index in r.Agents)
        {
            AgentRecord a = _agents[index];
            if (a.State != HostAgentState.Active)
            {
                if (reason is not null && state == HostAgentState.Waiting)
                {
                    a.State = HostAgentState.Waiting;
                    a.Reason = reason;
                }

                continue;
            }

            lifted++;
            if (Stances.Standing(_world!, a.World) is { } stance)
            {
                a.Point = stance.ContactCentre;
            }

            Unmap(a);
            a.State = state;
            a.Reason = reason ?? $"moving onto the new roadmap of region '{r.Name}'";
            if (reason is not null)
            {
                Tell(a, reason);
            }
        }

        return lifted;
    }

    /// <summary>Detaches an agent out of the world for good, telling it why.</summary>
    private void Detach(AgentRecord a, string reason)
    {
        a.State = HostAgentState.Detached;
        a.Reason = reason;
        Tell(a, reason);
    }

    /// <summary>Queues a removal event for an agent the host took out of the world (or that could not join it).</summary>
    private void Tell(AgentRecord a, string reason) =>
        Enqueue(a, new JumpEvent(JumpEventKind.Removed, a.World, _world?.Tick ?? 0, _world?.Time ?? 0, -1, a.Point, a.Target, default, 0f, PlannerStatus.Exact, reason));

    /// <summary>Queues <paramref name="e"/> for the agent's node, dropping the oldest past <see cref="MaxQueuedEvents"/>.</summary>
    private static void Enqueue(AgentRecord a, in JumpEvent e)
    {
        if (a.Queue.Count >= MaxQueuedEvents)
        {
            a.Queue.Dequeue();
        }

        a.Queue.Enqueue(e);
    }

    /// <summary>Removes the agent from the world and forgets its world handle.</summary>
    private void Unmap(AgentRecord a)
    {
        _world!.RemoveAgent(a.World);
        Forget(a);
    }

    /// <summary>Forgets the agent's world handle and path (the world no longer holds it).</summary>
    private void Forget(AgentRecord a)
    {
        _bySlot[a.World.Index] = -1;
        a.World = default;
    }

    /// <summary>The world let the agent go (a rebake for a body that cannot stand where it is): it waits, unplaced, for <paramref name="reason"/>.</summary>
    private void Unplace(AgentRecord a, string reason)
    {
        Forget(a);
        a.State = HostAgentState.Unplaced;
        a.Reason = reason;
    }

    /// <summary>Leaves the region without a roadmap: its world kind is kept for reuse; the world ends when no region holds a roadmap.</summary>
    private void Retire(RegionRecord r)
    {
        if (r.KindHandle.Assigned)
        {
            _retiredKinds.Push(r.KindHandle);
        }

        r.Kind = null;
        r.KindHandle = default;
        foreach (RegionRecord other in _regions)
        {
            if (other.Alive && other.Kind is not null)
            {
                return;
            }
        }

        _world?.Dispose();
        _world = null;
        _retiredKinds.Clear();
        Array.Fill(_bySlot, -1);
    }

    private RuntimeResult? Usable(HostAgentHandle agent, out AgentRecord? record)
    {
        record = null;
        if (Gone() is { } gone)
        {
            return gone;
        }

        if (!IsValid(agent))
        {
            return UnknownAgent(agent);
        }

        record = _agents[agent.Index];
        return record.State == HostAgentState.Detached ? new RuntimeResult(RuntimeStatus.UnknownAgent, $"{agent} is detached: {record.Reason}") : null;
    }

    /// <summary>The refusal of every call after <see cref="Dispose"/>, or <c>null</c> before.</summary>
    private RuntimeResult? Gone() => _disposed ? new RuntimeResult(RuntimeStatus.Disposed, "the jump navigation host was disposed: nothing was done") : null;

    private static RuntimeResult UnknownRegion(RegionHandle region) => new(RuntimeStatus.InvalidArgument, $"{region} is not a region of this host (never created, or freed)");

    private static RuntimeResult UnknownAgent(HostAgentHandle agent) => new(RuntimeStatus.UnknownAgent, $"{agent} is not an agent of this host (never registered, or unregistered)");

    private static string Agents(int count) => count == 1 ? "1 agent" : $"{count} agents";

    private static bool Finite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);

    /// <summary>One region: its name, its kind in the world while it has a roadmap, its agents in registration order.</summary>
    private sealed class RegionRecord
    {
        public int Generation;
        public bool Alive;
        public string Name = "";
        public CharacterKind? Kind;
        public KindHandle KindHandle;
        public readonly List<int> Agents = [];
    }

    /// <summary>One agent: its region, state, where it stands, its target, its world handle and its event queue.</summary>
    private sealed class AgentRecord
    {
        public int Generation;
        public bool Alive;
        public int Region = -1;
        public HostAgentState State;
        public string? Reason;
        public Vector3 Point;
        public AgentHandle World;
        public bool HasTarget;
        public Vector3 Target;
        public readonly Queue<JumpEvent> Queue = new();
    }
}
