using System.Numerics;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime.Kinds;
using Ballistic.Runtime.Paths;

namespace Ballistic.Runtime.Agents;

/// <summary>
/// The agents' components, one array per component indexed by slot (struct of arrays). Slots of removed agents go
/// on a free list and are reused last-freed first, with a new generation, so handles of removed agents stay invalid.
/// Systems iterate slots 0..<see cref="HighWater"/> in order, which makes iteration order deterministic.
/// </summary>
internal sealed class AgentStore
{
    private readonly Stack<int> _free = new();

    public int[] Generation = [];
    public bool[] Alive = [];
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

    /// <summary>The path followed, its start on the world clock, the event cursor (2i: start of move i, its takeoff or first step; 2i+1: its end, a landing or arrival).</summary>
    public AgentPath?[] Path = [];
    public double[] PathStart = [];
    public int[] Cursor = [];

    /// <summary>Stop at the next stance of the path (a new target or a cleared one).</summary>
    public bool[] StopAtStance = [];

    /// <summary>The pending path request, when one is queued or being animated.</summary>
    public PathRequest?[] Request = [];

    public bool[] PoseEnabled = [];
    public bool[] PoseDirty = [];
    public float[][] Angles = [];
    public Quaternion[][] Rotations = [];

    /// <summary>One past the highest slot ever used.</summary>
    public int HighWater { get; private set; }

    /// <summary>Live agents.</summary>
    public int Count { get; private set; }

    public bool IsValid(AgentHandle handle) =>
        handle.Generation > 0 && (uint)handle.Index < (uint)HighWater && Alive[handle.Index] && Generation[handle.Index] == handle.Generation;

    public AgentHandle HandleOf(int slot) => new(slot, Generation[slot]);

    public int Add(int kind, CharacterKind character, RootPose root, RoadmapNode stance, float[] angles, Quaternion[] rotations)
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
        Alive[slot] = true;
        Kind[slot] = kind;
        Character[slot] = character;
        Rehome[slot] = false;
        Root[slot] = root;
        Body[slot] = new BodyPoint(default, default, Quaternion.Identity);
        BodyStale[slot] = false;
        State[slot] = AgentState.Idle;
        Stance[slot] = stance;
        Target[slot] = default;
        HasTarget[slot] = false;
        Path[slot] = null;
        PathStart[slot] = 0;
        Cursor[slot] = 0;
        StopAtStance[slot] = false;
        Request[slot] = null;
        PoseEnabled[slot] = true;
        PoseDirty[slot] = true;
        Angles[slot] = angles;
        Rotations[slot] = rotations;
        Count++;
        return slot;
    }

    public void Remove(int slot)
    {
        Alive[slot] = false;
        Character[slot] = null;
        Rehome[slot] = false;
        Path[slot] = null;
        Stance[slot] = null;
        Request[slot] = null;
        Angles[slot] = [];
        Rotations[slot] = [];
        _free.Push(slot);
        Count--;
    }

    private void Grow(int capacity)
    {
        Array.Resize(ref Generation, capacity);
        Array.Resize(ref Alive, capacity);
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
        Array.Resize(ref Path, capacity);
        Array.Resize(ref PathStart, capacity);
        Array.Resize(ref Cursor, capacity);
        Array.Resize(ref StopAtStance, capacity);
        Array.Resize(ref Request, capacity);
        Array.Resize(ref PoseEnabled, capacity);
        Array.Resize(ref PoseDirty, capacity);
        Array.Resize(ref Angles, capacity);
        Array.Resize(ref Rotations, capacity);
    }
}
