using System.Numerics;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime.Kinds;
using Ballistic.Runtime.Paths;

namespace Ballistic.Runtime.Agents;

/// <summary>
/// The agents' components, one array per component indexed by slot (struct of arrays). Slots of removed agents go
/// on a free list and are reused last-freed first, with a new generation, so handles of removed agents stay invalid.
/// Systems iterate slots 0..<see cref="HighWater"/> in order, which makes iteration order deterministic. A
/// registered agent (<see cref="Registered"/>, its handle valid) is simulated only while <see cref="Alive"/> (its
/// lifecycle <see cref="AgentLifecycle.Active"/>); the others keep their kind, target and <see cref="Point"/>.
/// </summary>
internal sealed class AgentStore
{
    private readonly Stack<int> _free = new();

    public int[] Generation = [];

    /// <summary>The slot holds an agent whose handle is valid, in any lifecycle.</summary>
    public bool[] Registered = [];

    /// <summary>The agent is simulated: on its kind's roadmap (<see cref="AgentLifecycle.Active"/>).</summary>
    public bool[] Alive = [];
    public AgentLifecycle[] Lifecycle = [];

    /// <summary>Why an agent out of the simulation is out (waiting, unplaced, detached); <c>null</c> while active.</summary>
    public string?[] Reason = [];

    /// <summary>Where an agent out of the simulation stands (its registered or warped point, or where it stood when lifted out), world metres.</summary>
    public Vector3[] Point = [];
    public int[] Kind = [];

    /// <summary>
    /// The character kind the agent's stance, path and pose buffers belong to: its kind's, but for an agent still
    /// finishing a move on the roadmap its kind had before a rebake (<see cref="Rehome"/>).
    /// </summary>
    public CharacterKind?[] Character = [];

    /// <summary>Put on its kind's new roadmap where it stops (a rebake came while it was in a move).</summary>
    public bool[] Rehome = [];
    public RootPose[] Root = [];

    /// <summary>The body point (ground reference, velocity, heading), written by the body-point system.</summary>
    public BodyPoint[] Body = [];

    /// <summary>The agent stopped on a stance since its body point was written: the body-point system writes it again.</summary>
    public bool[] BodyStale = [];
    public AgentState[] State = [];

    /// <summary>The stance the agent stands on (null while it follows a path).</summary>
    public RoadmapNode?[] Stance = [];

    public Vector3[] Target = [];
    public bool[] HasTarget = [];

    /// <summary>Where the agent's navigation stands, and why it failed (<see cref="NavigationStatus.Failed"/>).</summary>
    public NavigationStatus[] Navigation = [];
    public string?[] NavigationFailure = [];

    /// <summary>The path followed, its start on the world clock, the event cursor (2i: start of move i, its takeoff or first step; 2i+1: its end, a landing or arrival).</summary>
    public AgentPath?[] Path = [];
    public double[] PathStart = [];
    public int[] Cursor = [];

    /// <summary>
    /// Where the last tick found the agent in its path, as search hints (any value gives the same answers, near ones
    /// fewer steps): the walk's segment under the trunk (<see cref="Walk"/>'s path index) and the animation's frame.
    /// </summary>
    public int[] WalkSegment = [];
    public int[] Frame = [];

    /// <summary>Stop at the next stance of the path (a new target or a cleared one).</summary>
    public bool[] StopAtStance = [];

    /// <summary>The pending path request, when one is queued or being animated.</summary>
    public PathRequest?[] Request = [];

    public bool[] PoseEnabled = [];
    public bool[] PoseDirty = [];

    /// <summary>Where each agent's joint angles and rotations lie in <see cref="AnglePool"/> and <see cref="RotationPool"/> (empty while it is out of the simulation).</summary>
    public PoseSlice[] Pose = [];

    /// <summary>Every active agent's joint angles, one slice each (<see cref="Pose"/>).</summary>
    public readonly SlicePool<float> AnglePool = new();

    /// <summary>Every active agent's joint rotations, one slice each (<see cref="Pose"/>).</summary>
    public readonly SlicePool<Quaternion> RotationPool = new();

    /// <summary>The joint angles of the agent in <paramref name="slot"/>.</summary>
    public Span<float> AnglesOf(int slot) => AnglePool.Slice(Pose[slot].Angles, Pose[slot].AngleCount);

    /// <summary>The joint rotations of the agent in <paramref name="slot"/>.</summary>
    public Span<Quaternion> RotationsOf(int slot) => RotationPool.Slice(Pose[slot].Rotations, Pose[slot].RotationCount);

    /// <summary>One past the highest slot ever used.</summary>
    public int HighWater { get; private set; }

    /// <summary>Registered agents, in any lifecycle.</summary>
    public int Count { get; private set; }

    public bool IsValid(AgentHandle handle) =>
        handle.Generation > 0 && (uint)handle.Index < (uint)HighWater && Registered[handle.Index] && Generation[handle.Index] == handle.Generation;

    /// <summary>True for a valid handle of an agent in the simulation.</summary>
    public bool IsActive(AgentHandle handle) => IsValid(handle) && Alive[handle.Index];

    public AgentHandle HandleOf(int slot) => new(slot, Generation[slot]);

    /// <summary>Registers an agent of <paramref name="kind"/> out of the simulation, standing at <paramref name="point"/>, in <paramref name="lifecycle"/> for <paramref name="reason"/>; returns its slot.</summary>
    public int Register(int kind, Vector3 point, AgentLifecycle lifecycle, string reason)
    {
        int slot;
        if (_free.Count > 0)
        {
            slot = _free.Pop();
        }
        else
        {
            slot = HighWater++;
            if (slot == Alive.Length)
            {
                Grow(Math.Max(16, Alive.Length * 2));
            }
        }

        Generation[slot]++;
        Registered[slot] = true;
        Kind[slot] = kind;
        Target[slot] = default;
        HasTarget[slot] = false;
        Count++;
        Navigate(slot, NavigationStatus.Idle);
        Deactivate(slot, lifecycle, reason, point);
        return slot;
    }

    /// <summary>Puts the registered agent in <paramref name="slot"/> in the simulation, standing idle on <paramref name="stance"/> of <paramref name="character"/>.</summary>
    public void Activate(int slot, CharacterKind character, RootPose root, RoadmapNode stance, ReadOnlySpan<float> angles)
    {
        Alive[slot] = true;
        Lifecycle[slot] = AgentLifecycle.Active;
        Reason[slot] = null;
        Character[slot] = character;
        Rehome[slot] = false;
        Root[slot] = root;
        Body[slot] = new BodyPoint(default, default, Quaternion.Identity);
        BodyStale[slot] = false;
        State[slot] = AgentState.Idle;
        Stance[slot] = stance;
        Path[slot] = null;
        PathStart[slot] = 0;
        Cursor[slot] = 0;
        WalkSegment[slot] = 0;
        Frame[slot] = 0;
        StopAtStance[slot] = false;
        Request[slot] = null;
        PoseEnabled[slot] = true;
        PoseDirty[slot] = true;
        SizePose(slot, angles.Length, character.JointCount);
        angles.CopyTo(AnglesOf(slot));
    }

    /// <summary>Sizes the pose slices of the agent in <paramref name="slot"/> for <paramref name="angles"/> joint angles and <paramref name="joints"/> joint rotations (new slices, cleared, when either length changes).</summary>
    public void SizePose(int slot, int angles, int joints)
    {
        PoseSlice pose = Pose[slot];
        if (pose.AngleCount == angles && pose.RotationCount == joints)
        {
            return;
        }

        FreePose(slot);
        Pose[slot] = new PoseSlice(AnglePool.Rent(angles), angles, RotationPool.Rent(joints), joints);
    }

    private void FreePose(int slot)
    {
        PoseSlice pose = Pose[slot];
        AnglePool.Return(pose.Angles, pose.AngleCount);
        RotationPool.Return(pose.Rotations, pose.RotationCount);
        Pose[slot] = default;
    }

    /// <summary>Takes the agent in <paramref name="slot"/> out of the simulation into <paramref name="lifecycle"/>, standing at <paramref name="point"/>; its kind and target stay.</summary>
    public void Deactivate(int slot, AgentLifecycle lifecycle, string reason, Vector3 point)
    {
        Alive[slot] = false;
        Lifecycle[slot] = lifecycle;
        Reason[slot] = reason;
        Navigate(slot, NavigationStatus.Idle);
        Point[slot] = point;
        Character[slot] = null;
        Rehome[slot] = false;
        State[slot] = AgentState.Idle;
        Path[slot] = null;
        Stance[slot] = null;
        StopAtStance[slot] = false;
        Request[slot] = null;
        FreePose(slot);
    }

    /// <summary>Sets the agent's navigation status (and the failure's reason, for <see cref="NavigationStatus.Failed"/>).</summary>
    public void Navigate(int slot, NavigationStatus status, string? failure = null)
    {
        Navigation[slot] = status;
        NavigationFailure[slot] = status == NavigationStatus.Failed ? failure : null;
    }

    public void Remove(int slot)
    {
        Deactivate(slot, AgentLifecycle.Detached, "removed", default);
        Registered[slot] = false;
        Reason[slot] = null;
        _free.Push(slot);
        Count--;
    }

    private void Grow(int capacity)
    {
        Array.Resize(ref Generation, capacity);
        Array.Resize(ref Registered, capacity);
        Array.Resize(ref Alive, capacity);
        Array.Resize(ref Lifecycle, capacity);
        Array.Resize(ref Reason, capacity);
        Array.Resize(ref Point, capacity);
        Array.Resize(ref Kind, capacity);
        Array.Resize(ref Character, capacity);
        Array.Resize(ref Rehome, capacity);
        Array.Resize(ref Root, capacity);
        Array.Resize(ref Body, capacity);
        Array.Resize(ref BodyStale, capacity);
        Array.Resize(ref State, capacity);
        Array.Resize(ref Stance, capacity);
        Array.Resize(ref Target, capacity);
        Array.Resize(ref HasTarget, capacity);
        Array.Resize(ref Navigation, capacity);
        Array.Resize(ref NavigationFailure, capacity);
        Array.Resize(ref Path, capacity);
        Array.Resize(ref PathStart, capacity);
        Array.Resize(ref Cursor, capacity);
        Array.Resize(ref WalkSegment, capacity);
        Array.Resize(ref Frame, capacity);
        Array.Resize(ref StopAtStance, capacity);
        Array.Resize(ref Request, capacity);
        Array.Resize(ref PoseEnabled, capacity);
        Array.Resize(ref PoseDirty, capacity);
        Array.Resize(ref Pose, capacity);
    }
}
