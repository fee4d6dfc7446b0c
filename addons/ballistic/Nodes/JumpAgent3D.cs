#nullable enable
using System.Collections.Generic;
using System.Linq;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.DebugDraw;
using Ballistic.Runtime.Hosting;
using Ballistic.Runtime.Links;
using Ballistic.Runtime.Paths;
using Godot;

namespace Ballistic.Addon;

/// <summary>
/// The AI jump controller of one NPC, in the manner of <c>NavigationAgent3D</c>: set <see cref="TargetPosition"/> and
/// the agent plans a sequence of ballistic jumps and walks on its <see cref="JumpRoadmap3D"/> and performs them, moving its parent
/// <see cref="Node3D"/> (or, with <see cref="MoveParent"/> off, only reporting where the body should be, for users
/// who move their own <c>CharacterBody3D</c>). Beside a <see cref="NavigationAgent3D"/> that walks a navmesh with the
/// roadmap's published links, it performs the jump of each link the navigation agent reaches. All decisions are
/// <see cref="JumpAgentLogic"/>'s; this node forwards Godot values to it and re-emits its signals.
/// </summary>
[GlobalClass]
[Icon("res://addons/ballistic/icons/JumpAgent3D.svg")]
public partial class JumpAgent3D : Node
{
    private JumpAgentLogic? _logic;
    private JumpRoadmap3D? _roadmap;
    private NavigationAgent3D? _navigationAgent;
    private bool _linkJump;
    private Vector3 _target;
    private bool _targetSet;

    /// <summary>A path was found (or replaced) toward the target.</summary>
    [Signal]
    public delegate void PathChangedEventHandler();

    /// <summary>The agent took off from <paramref name="from"/> toward <paramref name="to"/> (body points, world metres) at <paramref name="velocity"/> (m/s), landing after <paramref name="flightTime"/> seconds.</summary>
    [Signal]
    public delegate void JumpStartedEventHandler(Vector3 from, Vector3 to, Vector3 velocity, double flightTime);

    /// <summary>The agent landed at <paramref name="position"/> (world metres).</summary>
    [Signal]
    public delegate void LandedEventHandler(Vector3 position);

    /// <summary>
    /// The agent started walking from <paramref name="from"/> to <paramref name="to"/> (body points on the ground, world
    /// metres) along the ground, arriving after <paramref name="duration"/> seconds (<see cref="GetCurrentPath"/> holds
    /// the way; <see cref="GetBodyPosition"/> and <see cref="GetBodyVelocity"/> follow it each tick).
    /// </summary>
    [Signal]
    public delegate void WalkStartedEventHandler(Vector3 from, Vector3 to, double duration);

    /// <summary>The agent finished a walk, standing at <paramref name="position"/> (world metres).</summary>
    [Signal]
    public delegate void WalkFinishedEventHandler(Vector3 position);

    /// <summary>The agent reached its target.</summary>
    [Signal]
    public delegate void TargetReachedEventHandler();

    /// <summary>Navigation ended: the target was reached or cannot be (emitted after <see cref="TargetReached"/> or <see cref="PathFailed"/>).</summary>
    [Signal]
    public delegate void NavigationFinishedEventHandler();

    /// <summary>No path leads to the target; <paramref name="reason"/> says why in one sentence.</summary>
    [Signal]
    public delegate void PathFailedEventHandler(string reason);

    /// <summary>The roadmap the agent jumps on; empty: the first <see cref="JumpRoadmap3D"/> in the scene.</summary>
    [Export]
    public NodePath RoadmapPath { get; set; } = new();

    /// <summary>Where to go, world metres (a point on or near a surface). Setting it plans a path.</summary>
    [Export]
    public Vector3 TargetPosition
    {
        get => _target;
        set
        {
            _target = value;
            _targetSet = true;
            if (_logic is not null)
            {
                _logic.TargetPosition = value.ToNumerics();
            }
        }
    }

    /// <summary>A target this close to the agent's stance (metres) counts as reached, like <c>NavigationAgent3D.TargetDesiredDistance</c>.</summary>
    [Export(PropertyHint.Range, "0,5,0.01,or_greater,suffix:m")]
    public float TargetDesiredDistance { get; set; } = 0.5f;

    /// <summary>Move the parent <see cref="Node3D"/> along the jumps and walks; off, the node only reports (read <see cref="GetBodyPosition"/> and <see cref="GetBodyVelocity"/>).</summary>
    [Export]
    public bool MoveParent { get; set; } = true;

    /// <summary>Start the target given in the scene when the roadmap is ready (otherwise set <see cref="TargetPosition"/> from code).</summary>
    [Export]
    public bool StartWithTarget { get; set; }

    /// <summary>Perform the jump of each navigation link a sibling <see cref="NavigationAgent3D"/> reaches (links published by the roadmap).</summary>
    [Export]
    public bool FollowNavigationLinks { get; set; } = true;

    /// <summary>The agent's logic (for tests and advanced use); <c>null</c> outside the tree.</summary>
    public JumpAgentLogic? Logic => _logic;

    /// <summary>Registers the agent on its roadmap's region where the parent stands.</summary>
    public override void _Ready()
    {
        if (Engine.IsEditorHint())
        {
            return;
        }

        JumpNavigationServer server = JumpNavigationServer.Get(this);
        server.Track(this);
        _roadmap = FindRoadmap();
        if (_roadmap is null)
        {
            GD.PushError($"{GetPath()}: no JumpRoadmap3D found (set RoadmapPath).");
            return;
        }

        _logic = new JumpAgentLogic(server.World, MoveParent ? AgentMotionMode.MoveParent : AgentMotionMode.ReportOnly)
        {
            TargetDesiredDistance = TargetDesiredDistance,
        };
        RuntimeResult registered = _logic.Register(_roadmap.GetWorldKind(), BodyNode()?.GlobalPosition.ToNumerics() ?? default);
        if (!registered.Ok)
        {
            GD.PushError($"{GetPath()}: {registered.Reason}");
        }

        if (StartWithTarget && _targetSet)
        {
            _logic.TargetPosition = _target.ToNumerics();
        }

        _navigationAgent = GetParent()?.FindChildren("*", nameof(NavigationAgent3D), recursive: false, owned: false).OfType<NavigationAgent3D>().FirstOrDefault();
        if (_navigationAgent is not null && FollowNavigationLinks)
        {
            _navigationAgent.LinkReached += OnLinkReached;
        }
    }

    /// <summary>Leaves the server.</summary>
    public override void _ExitTree()
    {
        if (_navigationAgent is not null)
        {
            _navigationAgent.LinkReached -= OnLinkReached;
        }

        _logic?.Unregister();
        _logic = null;
        JumpNavigationServer.Singleton?.Untrack(this);
    }

    /// <summary>Reads the logic's state after the server stepped, moves the parent and emits the signals.</summary>
    public override void _PhysicsProcess(double delta)
    {
        if (_logic is null)
        {
            return;
        }

        _logic.Mode = MoveParent || _linkJump ? AgentMotionMode.MoveParent : AgentMotionMode.ReportOnly;
        if (_logic.Mode == AgentMotionMode.ReportOnly && BodyNode() is { } own)
        {
            _logic.SyncBodyPosition(own.GlobalPosition.ToNumerics());
        }

        // By index: a foreach over the interface would allocate an enumerator every physics frame.
        IReadOnlyList<AgentSignal> signals = _logic.Update();
        for (int i = 0; i < signals.Count; i++)
        {
            Emit(signals[i]);
        }

        if (_logic.Mode == AgentMotionMode.MoveParent && _logic.Lifecycle == AgentLifecycle.Active && BodyNode() is { } body)
        {
            body.GlobalPosition = _logic.BodyPosition.ToGodot();
            body.GlobalBasis = new Basis(_logic.BodyRotation.ToGodot()) * Basis.FromScale(body.GlobalBasis.Scale);
        }
    }

    /// <summary>True when there is no path to follow: the target was reached, failed, or none was set.</summary>
    public bool IsNavigationFinished() => _logic?.IsNavigationFinished() ?? true;

    /// <summary>True when the roadmap connects the agent's stance to the target.</summary>
    public bool IsTargetReachable() => _logic?.IsTargetReachable() ?? false;

    /// <summary>True once the target was reached.</summary>
    public bool IsTargetReached() => _logic?.IsTargetReached() ?? false;

    /// <summary>The current path as world points: the jumps' arcs and the walks' ground paths sampled at most 0.25 m apart, from where the agent stood when it started.</summary>
    public Vector3[] GetCurrentPath() => _logic is null ? [] : _logic.GetCurrentPath().Select(GodotMath.ToGodot).ToArray();

    /// <summary>
    /// The next jump before it happens (or the one in progress): a dictionary with <c>from</c>, <c>to</c> (body points,
    /// world metres), <c>velocity</c> (m/s), <c>flight_time</c>, <c>takeoff_time</c>, <c>landing_time</c> (world
    /// seconds) and <c>in_progress</c>; empty when no jump lies ahead.
    /// </summary>
    public Godot.Collections.Dictionary GetNextJump()
    {
        if (_logic is null || !(_logic.TryGetCurrentJump(out JumpInfo jump) || _logic.TryGetNextJump(out jump)))
        {
            return [];
        }

        return new Godot.Collections.Dictionary
        {
            ["from"] = jump.TakeoffPoint.ToGodot(),
            ["to"] = jump.LandingPoint.ToGodot(),
            ["velocity"] = jump.BodyVelocity.ToGodot(),
            ["flight_time"] = jump.FlightTime,
            ["takeoff_time"] = jump.TakeoffTime,
            ["landing_time"] = jump.LandingTime,
            ["in_progress"] = jump.InProgress,
        };
    }

    /// <summary>Where the body should be this tick (world metres): the parent's position when <see cref="MoveParent"/> is on.</summary>
    public Vector3 GetBodyPosition() => _logic?.BodyPosition.ToGodot() ?? Vector3.Zero;

    /// <summary>The body's velocity this tick, m/s: zero on a stance, a parabola's in flight, the walking speed along the ground while walking.</summary>
    public Vector3 GetBodyVelocity() => _logic?.BodyVelocity.ToGodot() ?? Vector3.Zero;

    /// <summary>A short state for labels: "waiting", "stance", "walking", "takeoff", "flight", "landing", "failed: …".</summary>
    public string GetStateText() => _logic is null ? "not registered" : _logic.DescribeState();

    /// <summary>Moves the agent at once to stand at <paramref name="position"/> (world metres); with a target it replans.</summary>
    public void Warp(Vector3 position)
    {
        if (_logic?.Warp(position.ToNumerics()) is { Ok: false } refused)
        {
            GD.PushWarning($"{Name}: {refused.Reason}");
        }
    }

    /// <summary>Adds the current path and its cones to the debug view.</summary>
    internal void AddDebugLines(DebugLines lines, DebugDrawSettings settings)
    {
        if (_logic is not null && _logic.CurrentPath is { } path)
        {
            lines.AddPath(path, _logic.CurrentMove, settings);
            lines.AddPathCones(path, _logic.CurrentMove, settings);
        }
    }

    private void Emit(in AgentSignal signal)
    {
        switch (signal.Kind)
        {
            case AgentSignalKind.PathChanged:
                EmitSignal(SignalName.PathChanged);
                break;
            case AgentSignalKind.JumpStarted:
                EmitSignal(SignalName.JumpStarted, signal.From.ToGodot(), signal.To.ToGodot(), signal.Velocity.ToGodot(), (double)signal.Duration);
                break;
            case AgentSignalKind.Landed:
                _linkJump = false;
                EmitSignal(SignalName.Landed, signal.To.ToGodot());
                break;
            case AgentSignalKind.WalkStarted:
                EmitSignal(SignalName.WalkStarted, signal.From.ToGodot(), signal.To.ToGodot(), (double)signal.Duration);
                break;
            case AgentSignalKind.WalkFinished:
                EmitSignal(SignalName.WalkFinished, signal.To.ToGodot());
                break;
            case AgentSignalKind.TargetReached:
                EmitSignal(SignalName.TargetReached);
                break;
            case AgentSignalKind.NavigationFinished:
                EmitSignal(SignalName.NavigationFinished);
                break;
            case AgentSignalKind.PathFailed:
                _linkJump = false;
                EmitSignal(SignalName.PathFailed, signal.Reason ?? string.Empty);
                break;
        }
    }

    /// <summary>A sibling navigation agent reached one of the roadmap's published links: perform that jump.</summary>
    private void OnLinkReached(Godot.Collections.Dictionary details)
    {
        if (_logic is null || _roadmap?.NavigationLinks is not JumpLinkSet links || !details.TryGetValue("rid", out Variant rid))
        {
            return;
        }

        int link = _roadmap.FindLink(rid.AsRid());
        if (link < 0)
        {
            return; // someone else's link
        }

        RuntimeResult result = new LinkTraversal(links).Traverse(_logic, link);
        if (result.Ok)
        {
            _linkJump = true;
        }
        else
        {
            GD.PushWarning($"{Name}: cannot jump link {link}: {result.Reason}");
        }
    }

    /// <summary>The roadmap node the agent jumps on; <c>null</c> before <see cref="_Ready"/> or when none was found.</summary>
    public JumpRoadmap3D? GetRoadmap() => _roadmap ??= IsInsideTree() ? FindRoadmap() : null;

    private JumpRoadmap3D? FindRoadmap() =>
        !RoadmapPath.IsEmpty
            ? GetNodeOrNull<JumpRoadmap3D>(RoadmapPath)
            : GetTree().GetNodesInGroup(JumpRoadmap3D.GroupName).OfType<JumpRoadmap3D>().FirstOrDefault();

    private Node3D? BodyNode() => GetParent() as Node3D;
}
