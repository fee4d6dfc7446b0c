using System.Numerics;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Steering;

namespace Ballistic.Planner.Animation;

/// <summary>
/// A whole-body animation of a path of jumps: flights and, between two jumps, a stance in which the root stays put
/// while limbs whose contacts change step one at a time. Frames at a fixed rate (per jump, the last frame falls
/// exactly on landing), the contact phases, the arcs (the root is evaluated exactly on them at any time in flight)
/// and the problems found: an animation with problems must not be reported as a success.
/// </summary>
public sealed class JumpAnimation
{
    private readonly float[] _jumpStarts;

    /// <summary>Creates an animation.</summary>
    /// <param name="model">The character.</param>
    /// <param name="arcs">The jumps' arcs, in order.</param>
    /// <param name="stances">Duration (seconds) of the stance after each jump but the last (one fewer than the arcs).</param>
    /// <param name="frames">The frames, in time order.</param>
    /// <param name="contactPhases">When each limb holds which contact point.</param>
    /// <param name="problems">What could not be animated cleanly, per jump.</param>
    /// <param name="failedContactPoses">Contact poses that fail the no-slip test.</param>
    /// <param name="collidingFrames">Frames with a bone through the level.</param>
    public JumpAnimation(CharacterModel model, IReadOnlyList<BallisticArc> arcs, IReadOnlyList<float> stances, IReadOnlyList<AnimationFrame> frames, IReadOnlyList<ContactPhase> contactPhases, IReadOnlyList<JumpProblem> problems, int failedContactPoses, int collidingFrames)
    {
        ArgumentNullException.ThrowIfNull(model);
        ArgumentNullException.ThrowIfNull(arcs);
        ArgumentNullException.ThrowIfNull(stances);
        ArgumentNullException.ThrowIfNull(frames);
        ArgumentNullException.ThrowIfNull(contactPhases);
        ArgumentNullException.ThrowIfNull(problems);
        if (arcs.Count > 0 && stances.Count != arcs.Count - 1)
        {
            throw new ArgumentException($"{arcs.Count} jumps need {arcs.Count - 1} stances between them, not {stances.Count}.", nameof(stances));
        }

        Model = model;
        Arcs = [.. arcs];
        Stances = [.. stances];
        Frames = [.. frames];
        ContactPhases = [.. contactPhases];
        Problems = [.. problems];
        FailedContactPoses = failedContactPoses;
        CollidingFrames = collidingFrames;
        _jumpStarts = new float[arcs.Count + 1];
        for (int i = 0; i < arcs.Count; i++)
        {
            _jumpStarts[i + 1] = _jumpStarts[i] + arcs[i].FlightTime + (i < stances.Count ? stances[i] : 0f);
        }
    }

    /// <summary>Duration (seconds) of the stance after each jump but the last, during which limbs re-step.</summary>
    public IReadOnlyList<float> Stances { get; }

    /// <summary>What could not be animated cleanly; empty when every jump animates with held contacts and no bone in the level.</summary>
    public IReadOnlyList<JumpProblem> Problems { get; }

    /// <summary>True when nothing went wrong: every contact pose passes the no-slip test and no bone passes through the level.</summary>
    public bool IsClean => Problems.Count == 0;

    /// <summary>The character.</summary>
    public CharacterModel Model { get; }

    /// <summary>The jumps' arcs, in order.</summary>
    public IReadOnlyList<BallisticArc> Arcs { get; }

    /// <summary>The frames, in time order.</summary>
    public IReadOnlyList<AnimationFrame> Frames { get; }

    /// <summary>When each limb holds which contact point.</summary>
    public IReadOnlyList<ContactPhase> ContactPhases { get; }

    /// <summary>Duration of the clip, seconds: the flight times and the stances between them.</summary>
    public float Duration => _jumpStarts[^1];

    /// <summary>How many takeoff or landing contact poses could not be generated to satisfy the no-slip test (the estimated contacts were then kept).</summary>
    public int FailedContactPoses { get; }

    /// <summary>How many frames still have a limb passing through the level after re-sampling.</summary>
    public int CollidingFrames { get; }

    /// <summary>Clip time at which jump <paramref name="jump"/> takes off, seconds.</summary>
    public float JumpStart(int jump) => _jumpStarts[jump];

    /// <summary>
    /// The root pose at clip time <paramref name="time"/>: exactly on the current jump's parabola in flight, at the
    /// landing pose during the stance after it.
    /// </summary>
    public RootPose RootAt(float time)
    {
        int jump = JumpIndex(time);
        return Arcs[jump].PoseAt(Math.Clamp(time - _jumpStarts[jump], 0f, Arcs[jump].FlightTime));
    }

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

        int hi = 0;
        int lo = Frames.Count - 1;
        while (hi < lo)
        {
            int mid = (hi + lo) / 2;
            if (Frames[mid].Time < time)
            {
                hi = mid + 1;
            }
            else
            {
                lo = mid;
            }
        }

        float[] after = Frames[hi].Angles;
        float[] before = Frames[Math.Max(0, hi - 1)].Angles;
        float span = Frames[hi].Time - Frames[Math.Max(0, hi - 1)].Time;
        float w = span > 0f ? Math.Clamp((time - Frames[Math.Max(0, hi - 1)].Time) / span, 0f, 1f) : 1f;
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

    private int JumpIndex(float time)
    {
        for (int i = 0; i < Arcs.Count; i++)
        {
            if (time < _jumpStarts[i + 1])
            {
                return i;
            }
        }

        return Arcs.Count - 1;
    }
}
