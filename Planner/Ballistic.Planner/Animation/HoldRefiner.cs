using System.Numerics;
using System.Runtime.InteropServices;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;

namespace Ballistic.Planner.Animation;

/// <summary>
/// Keeps held contacts held between frames. A clip is played by interpolating its angles between frames while the
/// root follows its move exactly; where the body moves fast over a held limb (a push-off at several metres per
/// second) the interpolated leg sags between two frames that each hold the foot, and a toe can dip into the ground.
/// Between every two frames across which a limb holds a contact, the midpoint is checked as a player would show it
/// (the held effector no farther from its point than at the two frames plus <see cref="Tolerance"/>, no bone of the
/// limb in the level unless there is at a frame already); where it is not, a frame is added there with the limb held
/// by IK, and both halves are checked again, down to <see cref="MaxDepth"/> halvings. What still fails is
/// reported, never played as clean. Thread-safe.
/// </summary>
internal sealed class HoldRefiner
{
    /// <summary>Farthest (metres) a held effector may be from its contact point between frames.</summary>
    public const float Tolerance = 0.002f;

    /// <summary>Most times a frame interval is halved.</summary>
    public const int MaxDepth = 4;

    private readonly CharacterModel _model;
    private readonly BodyCollision _collision;
    private readonly LimbIk _ik;

    /// <summary>
    /// Whether each frame's holds are solved and checked once and remembered for the intervals on either side of it
    /// (true, the default) or again for every interval (tests: the refinement is the same to the bit).
    /// </summary>
    internal bool RemembersFrames { get; init; } = true;

    /// <summary>
    /// Whether a held limb's bones are checked against the level at an interval's two frames only when they are in it
    /// at the midpoint (true, the default: the check at the ends only decides whether a midpoint in the level counts,
    /// and a midpoint clear of it holds whatever the ends) or at every frame (tests: the refinement is the same to the bit).
    /// </summary>
    internal bool ChecksEndsWhenNeeded { get; init; } = true;

    /// <summary>How many times a limb's hold at a frame was solved (and, checking every frame, its bones checked against the level), over every clip refined.</summary>
    internal int HoldChecks => _holdChecks;

    /// <summary>How many times a held limb's bones were checked against the level, at frames and between them, over every clip refined.</summary>
    internal int BoneChecks => _boneChecks;

    /// <summary>How many times a held limb's bones were found in the level at a frame, over every clip refined (checking every frame, or asked by a midpoint in the level).</summary>
    internal int EndsInLevel => _endsInLevel;

    private int _holdChecks;
    private int _boneChecks;
    private int _endsInLevel;

    /// <summary>Creates a refiner for <paramref name="model"/>'s clips, checking bones with <paramref name="collision"/>.</summary>
    public HoldRefiner(CharacterModel model, BodyCollision collision)
    {
        _model = model;
        _collision = collision;
        _ik = new LimbIk(model.Rig, new IkSettings { Restarts = 0, MaxIterations = 24, PositionTolerance = 0.5f * Tolerance });
    }

    /// <summary>
    /// Joint positions and rotations solved for one clip (each call has its own: the refiner is thread-safe), and how
    /// each limb holds its phase at the frames of the clip checked last: a frame ends one interval and starts the next,
    /// and a halved interval's halves share its ends, so each frame is solved and checked once.
    /// </summary>
    private sealed class Pose(HoldRefiner refiner, Vector3[] positions, Quaternion[] rotations)
    {
        /// <summary>Holds known at the frames still in use (a few: an interval's ends and its halvings' middles); Clear is null until checked.</summary>
        private readonly List<(AnimationFrame Frame, int Index, Vector3 Touching, Vector3 Normal, bool? Clear)> _holds = [];

        /// <summary>The frame <see cref="Positions"/> holds solved, or <c>null</c> (another pose: <see cref="Overwritten"/>).</summary>
        private AnimationFrame? _solved;

        /// <summary>Joint positions and rotations for a frame's bones checked while <see cref="Positions"/> holds a midpoint (<see cref="ClearAt"/>).</summary>
        private readonly Vector3[] _endPositions = new Vector3[positions.Length];
        private readonly Quaternion[] _endRotations = new Quaternion[rotations.Length];
        private AnimationFrame? _endSolved;

        public Vector3[] Positions => positions;

        public Quaternion[] Rotations => rotations;

        /// <summary>How many holds were solved for this clip.</summary>
        public int Checks { get; private set; }

        /// <summary>How many times a held limb's bones were checked against the level for this clip.</summary>
        public int BoneChecks { get; set; }

        /// <summary>How many of those checks at a frame found a bone in the level.</summary>
        public int EndsInLevel { get; private set; }

        /// <summary>
        /// At <paramref name="frame"/>, where the limb of <paramref name="phase"/> (index <paramref name="index"/> in
        /// the clip's phases) touches, its effector's normal, and, checking every frame
        /// (<see cref="ChecksEndsWhenNeeded"/> off) or when known, whether none of its bones is in the level
        /// (else <c>null</c>: <see cref="ClearAt"/>); solved into <see cref="Positions"/> when not known yet.
        /// </summary>
        public (Vector3 Touching, Vector3 Normal, bool? Clear) HoldAt(AnimationFrame frame, int index, ContactPhase phase)
        {
            if (Known(frame, index) is int k)
            {
                return (_holds[k].Touching, _holds[k].Normal, _holds[k].Clear);
            }

            Checks++;
            if (!ReferenceEquals(_solved, frame) || !refiner.RemembersFrames)
            {
                refiner._model.Rig.Solve(frame.Root, frame.Angles, positions, rotations);
                _solved = frame;
            }

            RigLimb limb = refiner._model.Limbs[phase.Limb];
            Vector3 touching = phase.Touching(limb, positions, rotations);
            Vector3 normal = limb.EffectorNormal(rotations);
            bool? clear = null;
            if (!refiner.ChecksEndsWhenNeeded)
            {
                // The tests' reference: checked here, on the pose just solved, not through ClearAt, so that a fault in
                // ClearAt cannot hide in both ways of refining.
                BoneChecks++;
                clear = !refiner._collision.LimbCollides(limb, positions, rotations, phase.Position);
                EndsInLevel += clear.Value ? 0 : 1;
            }

            if (refiner.RemembersFrames)
            {
                _holds.Add((frame, index, touching, normal, clear));
            }

            return (touching, normal, clear);
        }

        /// <summary>
        /// Whether none of the bones of the limb of <paramref name="phase"/> is in the level at
        /// <paramref name="frame"/>: checked when first asked, in buffers of its own (<see cref="Positions"/> may hold
        /// a midpoint), and remembered with the frame's hold.
        /// </summary>
        public bool ClearAt(AnimationFrame frame, int index, ContactPhase phase)
        {
            int? k = Known(frame, index);
            if (k is int known && _holds[known].Clear is bool clear)
            {
                return clear;
            }

            if (!ReferenceEquals(_endSolved, frame) || !refiner.RemembersFrames)
            {
                refiner._model.Rig.Solve(frame.Root, frame.Angles, _endPositions, _endRotations);
                _endSolved = frame;
            }

            BoneChecks++;
            bool checkedClear = !refiner._collision.LimbCollides(refiner._model.Limbs[phase.Limb], _endPositions, _endRotations, phase.Position);
            EndsInLevel += checkedClear ? 0 : 1;
            if (k is int i)
            {
                _holds[i] = _holds[i] with { Clear = checkedClear };
            }

            return checkedClear;
        }

        /// <summary>Where the hold of phase <paramref name="index"/> at <paramref name="frame"/> is in <see cref="_holds"/>, or <c>null</c>.</summary>
        private int? Known(AnimationFrame frame, int index)
        {
            ReadOnlySpan<(AnimationFrame Frame, int Index, Vector3 Touching, Vector3 Normal, bool? Clear)> holds = CollectionsMarshal.AsSpan(_holds);
            for (int i = 0; i < holds.Length; i++)
            {
                if (holds[i].Index == index && ReferenceEquals(holds[i].Frame, frame))
                {
                    return i;
                }
            }

            return null;
        }

        /// <summary>Notes that <see cref="Positions"/> and <see cref="Rotations"/> are about to hold a pose of no frame of the clip.</summary>
        public void Overwritten() => _solved = null;

        /// <summary>Forgets every frame but <paramref name="kept"/>: the intervals before it are refined.</summary>
        public void KeepOnly(AnimationFrame kept)
        {
            int count = 0;
            for (int i = 0; i < _holds.Count; i++)
            {
                if (ReferenceEquals(_holds[i].Frame, kept))
                {
                    _holds[count++] = _holds[i];
                }
            }

            _holds.RemoveRange(count, _holds.Count - count);
        }
    }

    /// <summary>
    /// The frames of <paramref name="clip"/> with frames added where a held contact would not hold between two of
    /// them, and the limbs (with the clip time, seconds) whose holds still fail between frames at the finest halving.
    /// </summary>
    public (List<AnimationFrame> Frames, List<(int Limb, float Time)> Failures) Refine(JumpAnimation clip)
    {
        IReadOnlyList<AnimationFrame> frames = clip.Frames;
        var refined = new List<AnimationFrame>(frames.Count);
        var failures = new List<(int Limb, float Time)>();
        if (frames.Count == 0)
        {
            return (refined, failures);
        }

        var pose = new Pose(this, new Vector3[_model.Rig.Joints.Count], new Quaternion[_model.Rig.Joints.Count]);
        refined.Add(frames[0]);
        for (int k = 1; k < frames.Count; k++)
        {
            Between(clip, pose, frames[k - 1], frames[k], 0, refined, failures);
            refined.Add(frames[k]);
            pose.KeepOnly(frames[k]);
        }

        Interlocked.Add(ref _holdChecks, pose.Checks);
        Interlocked.Add(ref _boneChecks, pose.BoneChecks);
        Interlocked.Add(ref _endsInLevel, pose.EndsInLevel);

        return (refined, failures);
    }

    /// <summary>Adds to <paramref name="output"/> the frames needed strictly between <paramref name="a"/> and <paramref name="b"/>.</summary>
    private void Between(JumpAnimation clip, Pose pose, AnimationFrame a, AnimationFrame b, int depth, List<AnimationFrame> output, List<(int Limb, float Time)> failures)
    {
        Vector3[] positions = pose.Positions;
        Quaternion[] rotations = pose.Rotations;
        float span = b.Time - a.Time;
        if (!(span > 1e-5f))
        {
            return;
        }

        // The phases held across the interval, and how each limb holds at its two frames (each frame solved once):
        // the midpoint must do as well.
        IReadOnlyList<ContactPhase> phases = clip.ContactPhases;
        int count = 0;
        for (int i = 0; i < phases.Count; i++)
        {
            count += phases[i].From <= a.Time + 1e-5f && phases[i].To >= b.Time - 1e-5f ? 1 : 0;
        }

        if (count == 0)
        {
            return;
        }

        var held = new ContactPhase[count];
        int[] indices = new int[count];
        for (int i = 0, h = 0; i < phases.Count; i++)
        {
            if (phases[i].From <= a.Time + 1e-5f && phases[i].To >= b.Time - 1e-5f)
            {
                (held[h], indices[h]) = (phases[i], i);
                h++;
            }
        }

        float time = a.Time + (0.5f * span);
        RootPose root = clip.RootAt(time);
        float[] angles = new float[a.Angles.Length];
        for (int d = 0; d < angles.Length; d++)
        {
            angles[d] = float.Lerp(a.Angles[d], b.Angles[d], 0.5f);
        }

        Rig rig = _model.Rig;
        var atA = new Vector3[held.Length];
        var atB = new Vector3[held.Length];
        var normals = new Vector3[held.Length];
        var clearA = new bool?[held.Length];
        var clearB = new bool?[held.Length];
        // Frame a for every limb, then frame b: each is solved at most once (alternating would solve each once a limb).
        for (int h = 0; h < held.Length; h++)
        {
            (atA[h], normals[h], clearA[h]) = pose.HoldAt(a, indices[h], held[h]);
        }

        for (int h = 0; h < held.Length; h++)
        {
            (atB[h], _, clearB[h]) = pose.HoldAt(b, indices[h], held[h]);
        }

        // Whether the limb's bones are clear of the level at both frames, so that the midpoint must be too: asked only
        // of a midpoint in the level.
        bool Clear(int h) => (clearA[h] ??= pose.ClearAt(a, indices[h], held[h])) && (clearB[h] ??= pose.ClearAt(b, indices[h], held[h]));

        // True when, in the pose last solved, the limb touches within allowed metres of its phase's point
        // (ContactPhase.Touching) and none of its bones is in the level, unless one is at either frame already.
        bool Holds(RigLimb limb, ContactPhase phase, float allowed, int h) =>
            Vector3.Distance(phase.Touching(limb, pose.Positions, pose.Rotations), phase.Position) <= allowed
            && (!InLevel(limb, phase, pose) || !Clear(h));

        bool changed = false;
        bool solved = false; // whether the pose holds the midpoint's angles solved
        for (int h = 0; h < held.Length; h++)
        {
            ContactPhase phase = held[h];
            RigLimb limb = _model.Limbs[phase.Limb];
            float allowed = MathF.Max(Vector3.Distance(atA[h], phase.Position), Vector3.Distance(atB[h], phase.Position)) + Tolerance;
            if (!solved)
            {
                pose.Overwritten();
                rig.Solve(root, angles, positions, rotations);
                solved = true;
            }

            if (Holds(limb, phase, allowed, h))
            {
                continue;
            }

            // Hold it there by IK (where the effector, or the ball it rolled onto, is at the two frames, its sole
            // turned as at the first).
            float[] trial = (float[])angles.Clone();
            RigLimb touching = phase.TouchingLimb(limb);
            bool reached = _ik.Reaches(root, trial, touching, Vector3.Lerp(atA[h], atB[h], 0.5f), normals[h]);
            pose.Overwritten();
            rig.Solve(root, trial, positions, rotations);
            if (!(reached && Holds(limb, phase, allowed, h)) && depth >= MaxDepth)
            {
                failures.Add((phase.Limb, time));
                solved = false; // the pose holds the trial, not the angles kept
                continue;
            }

            angles = trial; // the pose holds them solved
            changed = true;
        }

        if (!changed)
        {
            return;
        }

        var middle = new AnimationFrame(time, root, angles);
        if (depth < MaxDepth)
        {
            Between(clip, pose, a, middle, depth + 1, output, failures);
        }

        output.Add(middle);
        if (depth < MaxDepth)
        {
            Between(clip, pose, middle, b, depth + 1, output, failures);
        }
    }

    /// <summary>True when, in the pose last solved, a bone of <paramref name="limb"/> (holding <paramref name="phase"/>'s point) is in the level.</summary>
    private bool InLevel(RigLimb limb, ContactPhase phase, Pose pose)
    {
        pose.BoneChecks++;
        return _collision.LimbCollides(limb, pose.Positions, pose.Rotations, phase.Position);
    }
}
