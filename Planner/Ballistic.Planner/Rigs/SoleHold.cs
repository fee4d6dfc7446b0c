using System.Numerics;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Rigs;

/// <summary>
/// How a walking foot holds the ground: IK putting the limb's contact point on a point with its contact face
/// against the surface, as flat as <see cref="FlatTolerance"/> when it can, else within the IK's default 15°; joints
/// at their limits are released so the others make up for them (<see cref="IkSettings.ReleaseLimits"/>). One rule
/// for the gait that holds the feet and for <see cref="ReducedModelBuilder.WalkableSlope"/>, which asks where it
/// can. A walking foot may also roll onto its ball (<see cref="Hold"/> with <c>groundUnder</c>). Thread-safe.
/// </summary>
internal sealed class SoleHold
{
    /// <summary>How far a held sole may tilt from the ground when it can lie flat, radians (5°).</summary>
    public const float FlatTolerance = 5f * MathF.PI / 180f;

    /// <summary>Most a rolling foot's heel rises, radians (30°): a walker's trailing foot peels off its heel before it swings.</summary>
    public const float MostRoll = 30f * MathF.PI / 180f;

    /// <summary>
    /// The heel's rise is tried in steps of this (radians, 6°), least first: it rises no more than the hold needs. A
    /// foot already on its ball moves its heel half a step at a time from where it is (<see cref="Hold"/>).
    /// </summary>
    private const float RollStep = 6f * MathF.PI / 180f;

    /// <summary>Iterations of each solve: few, since a held foot is tracked from where it was.</summary>
    public const int Iterations = 24;

    private readonly Rig _rig;

    /// <summary>Creates the rule for <paramref name="rig"/>.</summary>
    public SoleHold(Rig rig)
    {
        _rig = rig;
        Flat = new LimbIk(rig, new IkSettings { Restarts = 0, MaxIterations = Iterations, NormalTolerance = FlatTolerance, ReleaseLimits = true });
        Loose = new LimbIk(rig, new IkSettings { Restarts = 0, MaxIterations = Iterations, ReleaseLimits = true });
        Rolling = new LimbIk(rig, new IkSettings { Restarts = 0, MaxIterations = Iterations, NormalTolerance = 0.5f * RollStep, ReleaseLimits = true });
    }

    /// <summary>The solver holding the sole within <see cref="FlatTolerance"/>.</summary>
    public LimbIk Flat { get; }

    /// <summary>The solver holding it within the IK's default 15°.</summary>
    public LimbIk Loose { get; }

    /// <summary>The solver holding the ball with the heel up one <see cref="RollStep"/>.</summary>
    private LimbIk Rolling { get; }

    /// <summary>
    /// Moves <paramref name="limb"/>'s angles in <paramref name="q"/> (updated only on success) so that its contact point
    /// lies on <paramref name="point"/> (world metres) with its contact face against ground of normal
    /// <paramref name="groundNormal"/> (world, unit, pointing out of the ground); true when it does. With
    /// <paramref name="groundUnder"/>, where the sole cannot lie flat the foot may instead put its ball on the ground
    /// where it is when the sole lies flat on <paramref name="point"/> (facing as the foot faces in <paramref name="q"/>;
    /// on the level point <paramref name="groundUnder"/> gives under it, none: no roll; at <paramref name="ball"/> when
    /// given: where a hold that has rolled first put it, so the foot does not swivel off it, and then the foot stays on
    /// its ball, its heel lowering as far as the hold allows, rather than dropping flat at once), the heel raised
    /// up to <see cref="MostRoll"/> (<see cref="RigLimb.Ball"/>; a foot without a toe bone does not roll).
    /// </summary>
    public bool Hold(in RootPose root, float[] q, RigLimb limb, Vector3 point, Vector3 groundNormal, Func<Vector3, Vector3?>? groundUnder = null, Vector3? ball = null)
    {
        // A foot on its ball tries to stay there before the flat hold, a foot off it after; a roll that failed is not
        // tried again (a failed solve leaves q as it was, so it would fail the same way).
        return (ball is not null && groundUnder is not null && Roll(root, q, limb, point, groundNormal, groundUnder, ball))
            || Flat.Reaches(root, q, limb, point, -groundNormal)
            || (ball is null && groundUnder is not null && Roll(root, q, limb, point, groundNormal, groundUnder, null))
            || Loose.Reaches(root, q, limb, point, -groundNormal);
    }

    /// <summary>The heel raised, the ball held (<see cref="Hold"/>).</summary>
    private bool Roll(in RootPose root, float[] q, RigLimb limb, Vector3 point, Vector3 groundNormal, Func<Vector3, Vector3?> groundUnder, Vector3? ball0)
    {
        if (limb.Ball is not RigLimb ball)
        {
            return false;
        }

        int joints = _rig.Joints.Count;
        Span<Vector3> positions = joints <= 128 ? stackalloc Vector3[joints] : new Vector3[joints];
        Span<Quaternion> rotations = joints <= 128 ? stackalloc Quaternion[joints] : new Quaternion[joints];
        _rig.SolveChain(root, limb.Lineage, q, positions, rotations); // only the foot is read
        Vector3 up = Vector3.Normalize(groundNormal);
        Vector3 toBall = ball.EffectorOffset - limb.EffectorOffset;
        Vector3 along = Vector3.Transform(toBall, rotations[limb.EffectorJoint]);
        along -= Vector3.Dot(along, up) * up;
        if (along.LengthSquared() < 1e-8f)
        {
            return false;
        }

        // The ball on the level itself, not on the ground's tangent plane at the held point (on a dune's hollow that
        // left the skeleton's ball 6 mm above the sand).
        if ((ball0 ?? groundUnder(point + (Vector3.Normalize(along) * toBall.Length()))) is not Vector3 target)
        {
            return false;
        }

        Vector3 forward = target - point;
        forward -= Vector3.Dot(forward, up) * up;
        if (forward.LengthSquared() < 1e-8f)
        {
            return false;
        }

        forward = Vector3.Normalize(forward);

        // The sole's normal (out of the sole, into the ground when flat) tilted back, the heel raised by as few
        // RollSteps as hold it (each within half a step either way), up to MostRoll. A foot already on its ball
        // starts from its own heel's rise: lowered by half a step, kept, then raised half a step at a time, so that
        // from one moment to the next the heel moves by half a step at most where it can (tried from the least rise
        // on, the rise jumped a whole step between bands and the straight leg's hip swivelled 19° to follow:
        // interpolated, the ball slid a centimetre).
        Vector3 side = Vector3.Normalize(Vector3.Cross(up, forward));
        float sign = Vector3.Dot(Vector3.Transform(-up, Quaternion.CreateFromAxisAngle(side, RollStep)), forward) > 0f ? -1f : 1f;
        float least = 0.5f * RollStep;
        Vector3 normal = ball.EffectorNormal(rotations);
        float now = sign * MathF.Atan2(-Vector3.Dot(normal, forward), -Vector3.Dot(normal, up));
        (float from, float by) = ball0 is null ? (least, RollStep) : (MathF.Max(now - least, least), least);
        for (float tilt = from; tilt <= MostRoll; tilt += by)
        {
            if (Rolling.Reaches(root, q, ball, target, Vector3.Transform(-up, Quaternion.CreateFromAxisAngle(side, sign * tilt))))
            {
                return true;
            }
        }

        return false;
    }
}
