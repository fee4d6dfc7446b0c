using System.Numerics;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;

namespace Ballistic.Planner.Animation;

/// <summary>
/// A whole-body animation of a path of moves (jumps and walks): flights, walks with a gait, and on the ground around
/// each jump a stance in which the body crouches before takeoff and absorbs the landing (the root sinking and rising
/// on held contacts) while limbs whose contacts change step one at a time. A clip that starts with a jump begins with
/// its crouch (<see cref="LeadIn"/>), one that ends with a landing ends once the body has absorbed it and stood up
/// (<see cref="LeadOut"/>). Frames at a fixed rate (per jump, the last frame falls exactly on landing), the contact
/// phases, the moves (the root is evaluated exactly on a jump's arc or a walk's path at any time, and between the
/// frames of a stance in between) and the problems found: an animation with problems must not be reported as a
/// success.
/// </summary>
public sealed class JumpAnimation
{
    private readonly float[] _moveStarts;
    private readonly Move[] _moves;
    private readonly int[] _jumpMoves;

    /// <summary>Creates an animation.</summary>
    /// <param name="model">The character.</param>
    /// <param name="moves">The moves animated, in order.</param>
    /// <param name="stances">Duration (seconds) of the stance after each move but the last (one fewer than the moves).</param>
    /// <param name="frames">The frames, in time order.</param>
    /// <param name="contactPhases">When each limb holds which contact point.</param>
    /// <param name="problems">What could not be animated cleanly, per move.</param>
    /// <param name="failedContactPoses">Contact poses that fail the no-slip test.</param>
    /// <param name="collidingFrames">Frames with a bone through the level.</param>
    /// <param name="leadIn">Seconds of stance before the first move starts (a crouch before a first jump).</param>
    /// <param name="leadOut">Seconds of stance after the last move ends (a landing absorbed).</param>
    internal JumpAnimation(CharacterModel model, IReadOnlyList<Move> moves, IReadOnlyList<float> stances, IReadOnlyList<AnimationFrame> frames, IReadOnlyList<ContactPhase> contactPhases, IReadOnlyList<JumpProblem> problems, int failedContactPoses, int collidingFrames, float leadIn = 0f, float leadOut = 0f)
    {
        ArgumentNullException.ThrowIfNull(model);
        ArgumentNullException.ThrowIfNull(moves);
        ArgumentNullException.ThrowIfNull(stances);
        ArgumentNullException.ThrowIfNull(frames);
        ArgumentNullException.ThrowIfNull(contactPhases);
        ArgumentNullException.ThrowIfNull(problems);
        if (moves.Count > 0 && stances.Count != moves.Count - 1)
        {
            throw new ArgumentException($"{moves.Count} moves need {moves.Count - 1} stances between them, not {stances.Count}.", nameof(stances));
        }

        if (!(leadIn >= 0f) || !(leadOut >= 0f) || !float.IsFinite(leadIn) || !float.IsFinite(leadOut))
        {
            throw new ArgumentException($"The lead-in ({leadIn} s) and lead-out ({leadOut} s) must be finite and not negative.", nameof(leadIn));
        }

        Model = model;
        _moves = [.. moves];
        Moves = Array.AsReadOnly(_moves);
        _jumpMoves = [.. Enumerable.Range(0, _moves.Length).Where(i => _moves[i] is Jump)];
        Arcs = [.. _jumpMoves.Select(i => ((Jump)_moves[i]).Arc)];
        Stances = [.. stances];
        _frames = [.. frames];
        Frames = Array.AsReadOnly(_frames);
        _frameTimes = [.. _frames.Select(f => f.Time)];
        _frameRoots = [.. _frames.Select(f => f.Root)];
        _frameTurns = new RotationBlend[Math.Max(0, _frameRoots.Length - 1)];
        for (int f = 0; f < _frameTurns.Length; f++)
        {
            _frameTurns[f] = RotationBlend.Between(_frameRoots[f].Rotation, _frameRoots[f + 1].Rotation);
        }

        _frameLookup = new SortedLookup(_frameTimes);
        ContactPhases = [.. contactPhases];
        Problems = [.. problems];
        FailedContactPoses = failedContactPoses;
        CollidingFrames = collidingFrames;
        LeadIn = leadIn;
        LeadOut = leadOut;
        _moveStarts = new float[_moves.Length + 1];
        _moveStarts[0] = _moves.Length > 0 ? leadIn : 0f;
        for (int i = 0; i < _moves.Length; i++)
        {
            _moveStarts[i + 1] = _moveStarts[i] + _moves[i].Duration + (i < stances.Count ? stances[i] : leadOut);
        }

        // How far each walking frame's root is above its walk's path (an upright walk's lift and bob); lifts under
        // 0.1 mm are rounding, not a lift, and count as none.
        _lifts = new float[Frames.Count];
        for (int f = 0; f < _lifts.Length && _moves.Length > 0; f++)
        {
            int m = MoveIndex(Frames[f].Time);
            float t = Frames[f].Time - _moveStarts[m];
            if (_moves[m] is Walk walk && t >= 0f && t <= walk.Duration)
            {
                float lift = Frames[f].Root.Position.Y - walk.PoseAt(t).Position.Y;
                _lifts[f] = MathF.Abs(lift) >= 1e-4f ? lift : 0f;
                _lifted |= _lifts[f] != 0f;
            }
        }
    }

    /// <summary>The frames, in time order (<see cref="Frames"/>), read by the per-tick samplers without an interface call.</summary>
    private readonly AnimationFrame[] _frames;

    /// <summary>Each frame's time (seconds), contiguous: the per-tick samplers search it for the frames around a time.</summary>
    private readonly float[] _frameTimes;

    /// <summary>Each frame's root, contiguous: read every tick for agents standing between moves (<see cref="FrameRoot"/>).</summary>
    private readonly RootPose[] _frameRoots;

    /// <summary>The root's turn from each frame to the next (<c>_frameTurns[f]</c>: frame f to f + 1), its angle worked out once.</summary>
    private readonly RotationBlend[] _frameTurns;

    /// <summary>Finds the frames around a time in <see cref="_frameTimes"/> (<see cref="FrameAtOrAfter"/>).</summary>
    private readonly SortedLookup _frameLookup;

    /// <summary>Whether any frame's root is lifted above its walk's path (else <see cref="WalkLift(float)"/> is 0 everywhere).</summary>
    private readonly bool _lifted;

    /// <summary>Per frame: how far (metres, world up) its root is above its walk's path; 0 outside walks.</summary>
    private readonly float[] _lifts;

    /// <summary>Seconds of stance before the first move starts: the crouch before a first jump (0 before a walk).</summary>
    public float LeadIn { get; }

    /// <summary>Seconds of stance after the last move ends: the last landing absorbed, the body standing up (0 after a walk).</summary>
    public float LeadOut { get; }

    /// <summary>Duration (seconds) of the stance after each move but the last: landing absorbed, limbs re-stepping, the crouch before the next takeoff.</summary>
    public IReadOnlyList<float> Stances { get; }

    /// <summary>What could not be animated cleanly; empty when every jump animates with held contacts and no bone in the level.</summary>
    internal IReadOnlyList<JumpProblem> Problems { get; }

    /// <summary>True when nothing went wrong: every contact pose passes the no-slip test and no bone passes through the level.</summary>
    public bool IsClean => Problems.Count == 0;

    /// <summary>The character.</summary>
    public CharacterModel Model { get; }

    /// <summary>The moves animated (jumps and walks), in order.</summary>
    public IReadOnlyList<Move> Moves { get; }

    /// <summary>The arcs of the jump moves, in order (the n-th jump's arc at index n).</summary>
    public IReadOnlyList<BallisticArc> Arcs { get; }

    /// <summary>The frames, in time order.</summary>
    internal IReadOnlyList<AnimationFrame> Frames { get; }

    /// <summary>When each limb holds which contact point.</summary>
    internal IReadOnlyList<ContactPhase> ContactPhases { get; }

    /// <summary>Duration of the clip, seconds: the lead-in, the moves' durations, the stances between them and the lead-out.</summary>
    public float Duration => _moveStarts[^1];

    /// <summary>How many takeoff or landing contact poses could not be generated to satisfy the no-slip test (the estimated contacts were then kept).</summary>
    public int FailedContactPoses { get; }

    /// <summary>How many frames still have a limb passing through the level after re-sampling.</summary>
    public int CollidingFrames { get; }

    /// <summary>Clip time at which the <paramref name="jump"/>-th jump move (counting jumps only) takes off, seconds.</summary>
    public float JumpStart(int jump) => _moveStarts[_jumpMoves[jump]];

    /// <summary>Index in <see cref="Moves"/> of the <paramref name="jump"/>-th jump move (counting jumps only).</summary>
    public int MoveOfJump(int jump) => _jumpMoves[jump];

    /// <summary>Clip time at which move <paramref name="move"/> starts, seconds (the clip's duration for <c>Moves.Count</c>).</summary>
    public float MoveStart(int move) => _moveStarts[move];

    /// <summary>Clip time at which move <paramref name="move"/> ends (a landing, or the end of a walk), seconds; its stance follows until the next move starts.</summary>
    public float MoveEnd(int move) => _moveStarts[move] + _moves[move].Duration;

    /// <summary>
    /// The root pose at clip time <paramref name="time"/> (seconds): exactly on the current jump's parabola in flight,
    /// on the current walk's path while walking (<see cref="Walk.PoseAt(float)"/>), raised by the walk's <see cref="WalkLift(float)"/>;
    /// on the ground between moves (and in the
    /// lead-in and lead-out) interpolated between the frames' roots, the body sinking and rising on its contacts.
    /// </summary>
    public RootPose RootAt(float time)
    {
        int frame = -1;
        return RootAt(time, ref frame);
    }

    /// <summary>
    /// <see cref="RootAt(float)"/> with the frames found from <paramref name="frame"/>, the index returned for a
    /// moment before (an agent's last tick): the same pose to the bit whatever it is; set to this moment's.
    /// </summary>
    internal RootPose RootAt(float time, ref int frame)
    {
        int m = MoveIndex(time);
        float t = time - _moveStarts[m];
        if (!(t >= 0f && t <= _moves[m].Duration) && _frames.Length > 0)
        {
            return FrameRoot(time, ref frame);
        }

        t = Math.Clamp(t, 0f, _moves[m].Duration);
        return _moves[m] switch
        {
            Jump jump => jump.Arc.PoseAt(t),
            Walk walk => Lifted(walk.PoseAt(t), WalkLift(time, ref frame)),
            _ => throw new InvalidOperationException("Unknown move kind."),
        };
    }

    /// <summary>
    /// How far (metres, world up) the walking trunk is above its walk's path (<see cref="Walk.PoseAt(float)"/>) at clip time
    /// <paramref name="time"/> (seconds): an upright walk's hips rising over the held feet and dipping between steps,
    /// none while it turns in place or stands; interpolated between frames; 0 outside walks.
    /// </summary>
    public float WalkLift(float time)
    {
        int frame = -1;
        return WalkLift(time, ref frame);
    }

    /// <summary>
    /// <see cref="WalkLift(float)"/> with the frames found from <paramref name="frame"/>, the index returned for a
    /// moment before: the same lift whatever it is; set to this moment's.
    /// </summary>
    internal float WalkLift(float time, ref int frame)
    {
        if (!_lifted)
        {
            return 0f;
        }

        int hi = _frameLookup.FirstAtOrAbove(time, ref frame);
        int lo = Math.Max(0, hi - 1);
        float span = _frameTimes[hi] - _frameTimes[lo];
        float w = span > 0f ? Math.Clamp((time - _frameTimes[lo]) / span, 0f, 1f) : 1f;
        return _lifts[lo] == 0f && _lifts[hi] == 0f ? 0f : float.Lerp(_lifts[lo], _lifts[hi], w);
    }

    /// <summary><paramref name="pose"/> raised by <paramref name="lift"/> metres (itself when the lift is 0).</summary>
    public static RootPose Lifted(in RootPose pose, float lift) =>
        lift == 0f ? pose : new RootPose(pose.Position + new Vector3(0f, lift, 0f), pose.Rotation);

    /// <summary>The root interpolated between the frames around <paramref name="time"/> (position linearly, rotation by slerp).</summary>
    private RootPose FrameRoot(float time, ref int frame)
    {
        int hi = _frameLookup.FirstAtOrAbove(time, ref frame);
        int lo = Math.Max(0, hi - 1);
        ref readonly RootPose after = ref _frameRoots[hi];
        ref readonly RootPose before = ref _frameRoots[lo];
        float span = _frameTimes[hi] - _frameTimes[lo];
        float w = span > 0f ? Math.Clamp((time - _frameTimes[lo]) / span, 0f, 1f) : 1f;
        // The frame itself before the first frame (lo = hi, w = 1): what the slerp of a rotation with itself gives there.
        Quaternion rotation = hi == lo ? after.Rotation : _frameTurns[lo].At(before.Rotation, after.Rotation, w);
        return new RootPose(Vector3.Lerp(before.Position, after.Position, w), rotation);
    }

    /// <summary>Index of the first frame at or after <paramref name="time"/> (the last frame when none is).</summary>
    private int FrameAtOrAfter(float time) => _frameLookup.FirstAtOrAbove(time);

    /// <summary>The full pose at clip time <paramref name="time"/>: the root on the parabola, the angles interpolated between frames.</summary>
    public (RootPose Root, float[] Angles) Sample(float time)
    {
        float[] angles = new float[Model.Rig.DofCount];
        return (Sample(time, angles), angles);
    }

    /// <summary>
    /// The full pose at clip time <paramref name="time"/> (seconds) without allocating: the angles (radians, one per
    /// degree of freedom) interpolated between frames are written into <paramref name="angles"/>; returns the root
    /// pose, exactly on the current jump's parabola in flight.
    /// </summary>
    /// <exception cref="ArgumentException"><paramref name="angles"/> is shorter than the rig's degree-of-freedom count, or the clip has no frames.</exception>
    public RootPose Sample(float time, Span<float> angles)
    {
        if (Frames.Count == 0 || angles.Length < Model.Rig.DofCount)
        {
            throw new ArgumentException($"Sampling needs a clip with frames and room for {Model.Rig.DofCount} angles.", nameof(angles));
        }

        int hi = FrameAtOrAfter(time);
        int lo = Math.Max(0, hi - 1);
        float[] after = _frames[hi].Angles;
        float[] before = _frames[lo].Angles;
        float span = _frameTimes[hi] - _frameTimes[lo];
        float w = span > 0f ? Math.Clamp((time - _frameTimes[lo]) / span, 0f, 1f) : 1f;
        for (int i = 0; i < after.Length; i++)
        {
            angles[i] = float.Lerp(before[i], after[i], w);
        }

        return RootAt(time);
    }

    /// <summary>World positions and rotations of every joint at <paramref name="time"/>.</summary>
    public void Joints(float time, Span<Vector3> positions, Span<Quaternion> rotations)
    {
        (RootPose root, float[] angles) = Sample(time);
        Model.Rig.Solve(root, angles, positions, rotations);
    }

    /// <summary>Index of the move under way (or whose stance it is) at clip time <paramref name="time"/>.</summary>
    public int MoveIndex(float time)
    {
        int i = Array.BinarySearch(_moveStarts, 0, _moves.Length, time);
        i = i >= 0 ? i : ~i - 1;
        return Math.Clamp(i, 0, Math.Max(0, _moves.Length - 1));
    }
}
