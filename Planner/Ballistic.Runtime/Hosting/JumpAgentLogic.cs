using System.Numerics;
using Ballistic.Planner.Geometry;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;
using Ballistic.Runtime.Paths;

namespace Ballistic.Runtime.Hosting;

/// <summary>
/// The logic of a <c>JumpAgent3D</c> node, after Godot's <c>NavigationAgent3D</c>, testable without a scene: the node
/// registers it on its region's kind in the server's <see cref="JumpWorld"/> (one entity, whose handle never changes
/// while it is registered), forwards <see cref="TargetPosition"/> and the other members, calls <see cref="Update"/>
/// every physics frame after the server stepped (<see cref="JumpWorld.Step(int)"/>), re-emits the signals it returns and, in
/// <see cref="AgentMotionMode.MoveParent"/> mode, moves its parent to <see cref="BodyPosition"/> and
/// <see cref="BodyRotation"/>.
/// </summary>
/// <remarks>
/// Positions are body points in world metres, Y up: the ground reference of the character (the origin of its Godot
/// body), which is the centre of the contacts of the stance it stands on; in a jump, it flies a parabola from the
/// takeoff stance's contact centre to the landing one's, and in a walk it moves along the walk's ground path from the
/// first stance's contact centre to the last one's (see <see cref="BodyPosition"/>). The trunk's own pose is
/// <see cref="RootPose"/>. Times are world seconds. Not thread-safe: the game loop's thread only.
/// </remarks>
public sealed class JumpAgentLogic
{
    private readonly JumpWorld _world;
    private readonly List<AgentSignal> _signals = [];
    private readonly List<AgentSignal> _pending = [];
    private readonly List<Vector3> _points = [];
    private AgentPath? _path;
    private AgentPath? _sampled;
    private float _sampledStep;
    private Vector3 _target;
    private bool _hasTarget;
    private bool _navigating;
    private bool _reached;
    private bool _failed;
    private float _threshold = 0.1f;
    private float _desiredDistance = 0.5f;
    private float _step = 0.25f;
    private Vector3? _refusedSync;

    /// <summary>The world's tick when the agent's events were last read: a frame the server stepped no tick in reads none again.</summary>
    private long _readTick = -1;

    /// <summary>Creates the logic of one agent node; <see cref="Register"/> puts it on a kind.</summary>
    /// <param name="world">The server's world.</param>
    /// <param name="mode">Who moves the character.</param>
    public JumpAgentLogic(JumpWorld world, AgentMotionMode mode = AgentMotionMode.MoveParent)
    {
        ArgumentNullException.ThrowIfNull(world);
        _world = world;
        Mode = mode;
    }

    /// <summary>The world the agent is registered in.</summary>
    public JumpWorld World => _world;

    /// <summary>Who moves the character: the node (its parent follows <see cref="BodyPosition"/>) or the user (reporting only).</summary>
    public AgentMotionMode Mode { get; set; }

    /// <summary>The agent's entity in the world; the default handle before <see cref="Register"/>.</summary>
    public AgentHandle Agent { get; private set; }

    /// <summary>True between <see cref="Register"/> and <see cref="Unregister"/>.</summary>
    public bool IsRegistered => _world.IsValid(Agent);

    /// <summary>Where the agent is in its life: waiting for its kind's roadmap, on it (active), unplaced or detached.</summary>
    public AgentLifecycle Lifecycle => _world.GetLifecycle(Agent);

    /// <summary>Why the agent waits, could not be placed or was detached (for the node's configuration warning); <c>null</c> on the roadmap.</summary>
    public string? StateReason => _world.GetAgentReason(Agent);

    /// <summary>
    /// Where the agent is asked to go, world metres (a point on or near a surface). Setting it asks the world for a
    /// path; setting it again within <see cref="TargetPositionThreshold"/> of the current target does nothing (the
    /// node may set it every frame to a moving point); further away, the agent replans from its next stance (the
    /// runtime keeps the path when the new target is within <see cref="WorldSettings.ReplanDistance"/> of the
    /// path's). A target within <see cref="TargetDesiredDistance"/> of where the agent stands is reached at once.
    /// A target that is not finite is refused with a <see cref="AgentSignalKind.PathFailed"/>. Zero until set.
    /// </summary>
    public Vector3 TargetPosition
    {
        get => _target;
        set => SetTarget(value);
    }

    /// <summary>True once a target was set (and until <see cref="ClearTarget"/>).</summary>
    public bool HasTarget => _hasTarget;

    /// <summary>A new <see cref="TargetPosition"/> this close to the current one (metres) is ignored. Default 0.1 m.</summary>
    /// <exception cref="ArgumentOutOfRangeException">Not finite, or negative.</exception>
    public float TargetPositionThreshold
    {
        get => _threshold;
        set => _threshold = NotNegative(value, nameof(TargetPositionThreshold));
    }

    /// <summary>
    /// A target this close (metres) to the point the agent stands on counts as reached without jumping, like
    /// <c>NavigationAgent3D.target_desired_distance</c>. Default 0.5 m (the runtime's tolerance across).
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException">Not finite, or negative.</exception>
    public float TargetDesiredDistance
    {
        get => _desiredDistance;
        set => _desiredDistance = NotNegative(value, nameof(TargetDesiredDistance));
    }

    /// <summary>Greatest distance between two consecutive points of <see cref="GetCurrentPath"/>, metres. Default 0.25 m.</summary>
    /// <exception cref="ArgumentOutOfRangeException">Not finite, or under 0.01 m.</exception>
    public float PathSampleStep
    {
        get => _step;
        set => _step = float.IsFinite(value) && value >= 0.01f ? value : throw new ArgumentOutOfRangeException(nameof(PathSampleStep), value, $"PathSampleStep must be finite and at least 0.01 m, not {value} m.");
    }

    /// <summary>The path the agent follows (its jumps, walks and whole-body animation); <c>null</c> when it has none.</summary>
    public AgentPath? CurrentPath => _path;

    /// <summary>
    /// Index on <see cref="CurrentPath"/> of the move in progress (a jump or a walk) or, standing between two moves, of
    /// the next one (<see cref="JumpWorld.GetMoveIndex"/>); 0 without a path.
    /// </summary>
    public int CurrentMove => _path is not null && ReferenceEquals(_world.GetPath(Agent), _path) ? Math.Max(0, _world.GetMoveIndex(Agent)) : 0;

    /// <summary>
    /// A short state for a label: "not registered", "waiting for a roadmap", "idle", "stance", "walking", "takeoff", "flight",
    /// "landing", "planning", "arrived", "unplaced: …" or "failed: …" (the last failure toward the current target).
    /// </summary>
    public string DescribeState()
    {
        if (!IsRegistered)
        {
            return "not registered";
        }

        switch (Lifecycle)
        {
            case AgentLifecycle.Waiting:
                return "waiting for a roadmap";
            case AgentLifecycle.Unplaced:
                return $"unplaced: {StateReason}";
            case AgentLifecycle.Detached:
                return $"detached: {StateReason}";
        }

        if (LastFailure is { } failure && !_navigating)
        {
            return $"failed: {failure}";
        }

        return _world.IsPathPending(Agent) ? "planning" : _world.GetState(Agent) switch
        {
            AgentState.Idle => _hasTarget && _reached ? "arrived" : "idle",
            AgentState.Stance => "stance",
            AgentState.Walking => "walking",
            AgentState.Takeoff => "takeoff",
            AgentState.Flight => "flight",
            AgentState.Landing => "landing",
            _ => "unknown",
        };
    }

    /// <summary>Why the last path toward the current target failed; <c>null</c> when it did not.</summary>
    public string? LastFailure { get; private set; }

    /// <summary>The trunk's pose this tick (centre and orientation, world frame): exactly on the arc in flight and the walk's pose while walking. Default until the agent is on a roadmap.</summary>
    public RootPose RootPose { get; private set; }

    /// <summary>
    /// The body point this tick, world metres: where the node puts its parent (<see cref="AgentMotionMode.MoveParent"/>)
    /// or where the user's body should be (<see cref="AgentMotionMode.ReportOnly"/>). On a stance, the centre of its
    /// contacts; in a jump, the trunk centre minus an offset going linearly in time from (trunk − contact centre) at
    /// the takeoff stance to that at the landing stance; in a walk, the point of the walk's ground path reached at its
    /// speed (shifted, if the path's ends are not the stances' contact centres, by an offset going linearly along it).
    /// Off the roadmap, the position registered or warped at.
    /// </summary>
    public Vector3 BodyPosition { get; private set; }

    /// <summary>The body point's velocity this tick, m/s: zero on a stance; in a jump, a parabola's under the world's gravity; in a walk, the walking speed along the ground path.</summary>
    public Vector3 BodyVelocity { get; private set; }

    /// <summary>The body's heading this tick: a rotation about +Y turning +Z (the model's front) toward the trunk's forward axis projected on the ground.</summary>
    public Quaternion BodyRotation { get; private set; } = Quaternion.Identity;

    /// <summary>
    /// Registers the agent on <paramref name="kind"/> standing at <paramref name="position"/> (the parent's global
    /// position, world metres), as <see cref="JumpWorld.AddAgent"/> (waiting when the kind has no roadmap yet,
    /// unplaced where the character cannot stand); a target set before is sent. An agent already registered is
    /// unregistered first.
    /// </summary>
    public RuntimeResult Register(KindHandle kind, Vector3 position)
    {
        if (IsRegistered)
        {
            Unregister();
        }

        AddAgentResult registered = _world.AddAgent(kind, position);
        Agent = registered.Agent;
        _readTick = _world.Tick;
        if (!registered.Agent.IsAssigned)
        {
            return registered.Result;
        }

        BodyPosition = position;
        BodyVelocity = Vector3.Zero;
        if (_hasTarget && _navigating)
        {
            _world.SetTarget(Agent, _target);
        }

        Refresh();
        return registered.Result;
    }

    /// <summary>Unregisters the agent (the node leaves the tree); its target is kept for a later <see cref="Register"/>.</summary>
    public RuntimeResult Unregister()
    {
        RuntimeResult result = _world.RemoveAgent(Agent);
        Agent = default;
        _path = null;
        return result;
    }

    /// <summary>
    /// Sets <see cref="TargetPosition"/> and says what came of it: <see cref="RuntimeStatus.Ok"/> with a note when the
    /// target was kept (within the threshold), reached at once or stored until the agent is on a roadmap; otherwise
    /// the world's refusal (also raised as a <see cref="AgentSignalKind.PathFailed"/> on the next <see cref="Update"/>).
    /// </summary>
    public RuntimeResult SetTarget(Vector3 target)
    {
        if (!float.IsFinite(target.X) || !float.IsFinite(target.Y) || !float.IsFinite(target.Z))
        {
            string reason = $"the target position {target} is not finite";
            _pending.Add(AgentSignal.Failed(Now, reason));
            return new RuntimeResult(RuntimeStatus.InvalidArgument, reason);
        }

        if (_hasTarget && Vector3.Distance(target, _target) <= _threshold)
        {
            return new RuntimeResult(RuntimeStatus.Ok, $"within {_threshold} m of the current target: kept");
        }

        _target = target;
        _hasTarget = true;
        _reached = false;
        _failed = false;
        LastFailure = null;
        _navigating = true;
        if (!IsRegistered)
        {
            return new RuntimeResult(RuntimeStatus.Ok, "target kept until the agent is registered");
        }

        if (Lifecycle == AgentLifecycle.Active && _world.GetPath(Agent) is null && !_world.IsPathPending(Agent) &&
            _world.GetStandingPoint(Agent) is { } here && Vector3.Distance(here, target) <= _desiredDistance)
        {
            _world.ClearTarget(Agent);
            _navigating = false;
            _reached = true;
            _pending.Add(AgentSignal.Of(AgentSignalKind.TargetReached, Now));
            _pending.Add(AgentSignal.Of(AgentSignalKind.NavigationFinished, Now));
            return new RuntimeResult(RuntimeStatus.Ok, $"already within {_desiredDistance} m of the target");
        }

        RuntimeResult result = _world.SetTarget(Agent, target);
        if (!result.Ok)
        {
            Fail(_pending, Now, result.Reason ?? result.Status.ToString());
        }

        return result;
    }

    /// <summary>Forgets the target: the agent stops on the next stance of its path (or stays). Navigation is finished; no signal.</summary>
    public RuntimeResult ClearTarget()
    {
        _hasTarget = false;
        _navigating = false;
        _reached = false;
        _failed = false;
        LastFailure = null;
        return IsRegistered ? _world.ClearTarget(Agent) : RuntimeResult.Success;
    }

    /// <summary>True when the agent is not heading anywhere: no target, target reached, path failed or target cleared (like <c>NavigationAgent3D.is_navigation_finished</c>).</summary>
    public bool IsNavigationFinished() => !_navigating;

    /// <summary>True once the agent reached its current target (a <see cref="AgentSignalKind.TargetReached"/> was raised for it).</summary>
    public bool IsTargetReached() => _hasTarget && _reached;

    /// <summary>
    /// False without a target and after a <see cref="AgentSignalKind.PathFailed"/> for the current target; true once reached;
    /// otherwise whether the roadmap connects the agent's stance to a node near the target
    /// (<see cref="JumpWorld.IsTargetReachable"/>; false while the agent is off its roadmap).
    /// </summary>
    public bool IsTargetReachable()
    {
        if (!_hasTarget || _failed)
        {
            return false;
        }

        return _reached || _world.IsTargetReachable(Agent, _target);
    }

    /// <summary>
    /// The path being followed (or the last one followed to the current target), as world points of the body: from
    /// the contact centre the agent stood on when it started, each jump's parabola and each walk's ground path (the
    /// body points of <see cref="BodyPosition"/>) sampled at most <see cref="PathSampleStep"/> apart, every stance's
    /// contact centre included, to the contact centre of the last stance (within the runtime's tolerance of the target). Empty before the first path, after a failure, a
    /// warp or a new region roadmap. The list is reused: copy it to keep it.
    /// </summary>
    public IReadOnlyList<Vector3> GetCurrentPath()
    {
        if (_path is null)
        {
            _points.Clear();
            _sampled = null;
        }
        else if (!ReferenceEquals(_path, _sampled) || _sampledStep != _step)
        {
            Sample(_path);
            _sampled = _path;
            _sampledStep = _step;
        }

        return _points;
    }

    /// <summary>The jump the agent will take off for next (after the one it is in, if any), known before it happens; false when none remains on its path.</summary>
    public bool TryGetNextJump(out JumpInfo jump) => TryJump(current: false, out jump);

    /// <summary>The jump the agent is in now; false when it stands.</summary>
    public bool TryGetCurrentJump(out JumpInfo jump) => TryJump(current: true, out jump);

    /// <summary>The jump in progress (<paramref name="current"/>) or the next one, as the world describes it.</summary>
    private bool TryJump(bool current, out JumpInfo jump)
    {
        return current ? _world.TryGetCurrentJump(Agent, out jump) : _world.TryGetNextJump(Agent, out jump);
    }

    /// <summary>
    /// Performs exactly one jump of the kind's roadmap (edge index), as <see cref="JumpWorld.PerformJump"/>:
    /// the agent stands on its takeoff at once; the landing's contact centre becomes the target, so the usual signals
    /// follow (<see cref="AgentSignalKind.PathChanged"/>, <see cref="AgentSignalKind.JumpStarted"/>, <see cref="AgentSignalKind.Landed"/>,
    /// <see cref="AgentSignalKind.TargetReached"/>, <see cref="AgentSignalKind.NavigationFinished"/>).
    /// </summary>
    public RuntimeResult PerformJump(int edge) => Performed(_world.PerformJump(Agent, edge));

    /// <summary>
    /// Performs exactly <paramref name="moves"/> (jumps and walks, with no search), as
    /// <see cref="JumpWorld.PerformMoves"/>: the agent stands on the first move's stance at once; the last
    /// stance's contact centre becomes the target and the usual signals follow. For tests and tools.
    /// </summary>
    internal RuntimeResult PerformMoves(IReadOnlyList<Planner.Roadmaps.Move> moves) => Performed(_world.PerformMoves(Agent, moves));

    /// <summary>After the world performs given moves: the agent navigates toward their end.</summary>
    private RuntimeResult Performed(RuntimeResult result)
    {
        if (result.Ok)
        {
            _target = _world.GetTarget(Agent) ?? _target;
            _hasTarget = true;
            _navigating = true;
            _reached = false;
            _failed = false;
            LastFailure = null;
            _path = null;
            Refresh();
        }

        return result;
    }

    /// <summary>Moves the agent at once to stand at <paramref name="position"/> (world metres), as <see cref="JumpWorld.Warp"/>; with a target it replans from there.</summary>
    public RuntimeResult Warp(Vector3 position)
    {
        RuntimeResult result = _world.Warp(Agent, position);
        if (result.Ok)
        {
            _path = null;
            _refusedSync = null;
            Refresh();
        }

        return result;
    }

    /// <summary>
    /// For <see cref="AgentMotionMode.ReportOnly"/>: tells where the user's body stands (world metres), every tick
    /// before <see cref="Update"/>. While the agent stands with no path under way and the body is farther than the
    /// runtime's tolerance across from its stance (the user walked it), the agent is warped there; a place where the
    /// character cannot stand is not tried again until the body moves that far from it. Does nothing during a path.
    /// </summary>
    public RuntimeResult SyncBodyPosition(Vector3 position)
    {
        if (!IsRegistered)
        {
            return new RuntimeResult(RuntimeStatus.UnknownAgent, "the agent is not registered");
        }

        float across = _world.Settings.Tolerance.Across;
        AgentLifecycle lifecycle = Lifecycle;
        bool standing = lifecycle == AgentLifecycle.Active && _world.GetPath(Agent) is null && !_world.IsPathPending(Agent);
        bool waiting = lifecycle is AgentLifecycle.Waiting or AgentLifecycle.Unplaced;
        if (!(standing || waiting) || _world.GetStandingPoint(Agent) is not { } here || Vector3.Distance(here, position) <= across ||
            (_refusedSync is { } refused && Vector3.Distance(refused, position) <= across))
        {
            return RuntimeResult.Success;
        }

        RuntimeResult result = Warp(position);
        if (!result.Ok)
        {
            _refusedSync = position;
        }

        return result;
    }

    /// <summary>
    /// Call once per physics frame after the server stepped: turns the agent's events of the frame's ticks
    /// (<see cref="JumpWorld.EventsOf"/>) into signals, in order
    /// (<see cref="AgentSignalKind.PathChanged"/>, then per move <see cref="AgentSignalKind.JumpStarted"/> and <see cref="AgentSignalKind.Landed"/>
    /// or <see cref="AgentSignalKind.WalkStarted"/> and <see cref="AgentSignalKind.WalkFinished"/>, …,
    /// <see cref="AgentSignalKind.TargetReached"/>, <see cref="AgentSignalKind.NavigationFinished"/>; <see cref="AgentSignalKind.PathFailed"/> then
    /// <see cref="AgentSignalKind.NavigationFinished"/> on failure) and updates <see cref="RootPose"/>, <see cref="BodyPosition"/>,
    /// <see cref="BodyVelocity"/> and <see cref="BodyRotation"/>. The list is reused: valid until the next call.
    /// </summary>
    public IReadOnlyList<AgentSignal> Update()
    {
        _signals.Clear();
        _signals.AddRange(_pending);
        _pending.Clear();
        if (IsRegistered && _world.Tick != _readTick)
        {
            _readTick = _world.Tick;
            foreach (ref readonly JumpEvent e in _world.EventsOf(Agent))
            {
                Handle(e);
            }
        }

        Refresh();
        return _signals;
    }

    private double Now => _world.Time;

    private void Handle(in JumpEvent j)
    {
        switch (j.Kind)
        {
            case JumpEventKind.PathFound:
                _path = j.Path;
                _navigating = true;
                _failed = false;
                LastFailure = null;
                _signals.Add(AgentSignal.Of(AgentSignalKind.PathChanged, j.Time));
                break;
            case JumpEventKind.PathFailed:
                Fail(_signals, j.Time, j.Reason ?? j.Status.ToString());
                break;
            case JumpEventKind.JumpStarted when j.Path is { } path:
                PathMove move = path.Moves[j.Jump];
                _signals.Add(new AgentSignal(AgentSignalKind.JumpStarted, j.Time, j.Jump, move.From.ContactCentre, move.To.ContactCentre, BodyMotion.BodyVelocity(move), move.Arc.FlightTime, 0f, null));
                break;
            case JumpEventKind.Landed when j.Path is { } path:
                PathMove landed = path.Moves[j.Jump];
                _signals.Add(new AgentSignal(AgentSignalKind.Landed, j.Time, j.Jump, landed.From.ContactCentre, landed.To.ContactCentre, default, landed.Arc.FlightTime, 0f, null));
                break;
            case JumpEventKind.WalkStarted when j.Path is { } path:
                PathMove walk = path.Moves[j.Jump];
                _signals.Add(new AgentSignal(AgentSignalKind.WalkStarted, j.Time, j.Jump, walk.From.ContactCentre, walk.To.ContactCentre, default, walk.Walk!.Duration, walk.Walk.Speed, null));
                break;
            case JumpEventKind.WalkFinished when j.Path is { } path:
                PathMove walked = path.Moves[j.Jump];
                _signals.Add(new AgentSignal(AgentSignalKind.WalkFinished, j.Time, j.Jump, walked.From.ContactCentre, walked.To.ContactCentre, default, walked.Walk!.Duration, walked.Walk.Speed, null));
                break;
            case JumpEventKind.TargetReached:
                if (_navigating)
                {
                    _navigating = false;
                    _reached = true;
                    _signals.Add(AgentSignal.Of(AgentSignalKind.TargetReached, j.Time));
                    _signals.Add(AgentSignal.Of(AgentSignalKind.NavigationFinished, j.Time));
                }

                break;
            case JumpEventKind.Removed:
                _path = null;
                if (_navigating)
                {
                    Fail(_signals, j.Time, j.Reason ?? "the agent left its roadmap");
                }

                break;
            default:
                break;
        }
    }

    private void Fail(List<AgentSignal> signals, double time, string reason)
    {
        _path = null;
        _failed = true;
        LastFailure = reason;
        if (_navigating)
        {
            _navigating = false;
            signals.Add(AgentSignal.Failed(time, reason));
            signals.Add(AgentSignal.Of(AgentSignalKind.NavigationFinished, time));
        }
        else
        {
            signals.Add(AgentSignal.Failed(time, reason));
        }
    }

    /// <summary>Reads this tick's root pose and body point from the world (its body-point system wrote them).</summary>
    private void Refresh()
    {
        if (Lifecycle != AgentLifecycle.Active)
        {
            BodyPosition = _world.GetStandingPoint(Agent) ?? BodyPosition;
            BodyVelocity = Vector3.Zero;
            return;
        }

        RootPose = _world.GetRootPose(Agent);
        BodyPoint body = _world.GetBodyPoint(Agent);
        BodyPosition = body.Position;
        BodyVelocity = body.Velocity;
        BodyRotation = body.Heading;
    }

    /// <summary>Samples the body point along the path, at most <see cref="PathSampleStep"/> apart.</summary>
    private void Sample(AgentPath path)
    {
        _points.Clear();
        _points.Add(path.Moves[0].From.ContactCentre);
        foreach (PathMove move in path.Moves)
        {
            if (move.Walk is { } walk)
            {
                // Uniform in distance: a step of the ground path plus the offset's share is at most a step apart.
                Vector3 shift = (move.To.ContactCentre - walk.Path[^1]) - (move.From.ContactCentre - walk.Path[0]);
                int n = Math.Max(1, (int)MathF.Ceiling((walk.Length + shift.Length()) / _step));
                for (int k = 1; k < n; k++)
                {
                    _points.Add(BodyMotion.InWalk(move, walk.TimeAtDistance(walk.Length * k / n)).Position);
                }
            }
            else
            {
                float flight = move.Arc.FlightTime;
                Vector3 v0 = BodyMotion.BodyVelocity(move);
                Vector3 v1 = v0 - new Vector3(0f, move.Arc.Gravity * flight, 0f);

                // The body point's speed is greatest at an end of the flight (|v0 − g·t| is convex in t): n samples
                // uniform in time are then at most step apart.
                float travel = MathF.Max(v0.Length(), v1.Length()) * flight;
                int n = Math.Max(1, (int)MathF.Ceiling(travel / _step));
                for (int k = 1; k < n; k++)
                {
                    _points.Add(BodyMotion.InJump(move, flight * k / n).Position);
                }
            }

            // The end point itself (the arc meets it within millimetres): bridged if ever farther than a step.
            Vector3 end = move.To.ContactCentre;
            Vector3 last = _points[^1];
            int bridge = (int)MathF.Ceiling(Vector3.Distance(last, end) / _step);
            for (int k = 1; k < bridge; k++)
            {
                _points.Add(Vector3.Lerp(last, end, (float)k / bridge));
            }

            _points.Add(end);
        }
    }

    private static float NotNegative(float value, string name) =>
        float.IsFinite(value) && value >= 0f ? value : throw new ArgumentOutOfRangeException(name, value, $"{name} must be finite and not negative, not {value} m.");
}
