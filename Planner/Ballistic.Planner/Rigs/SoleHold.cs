using System.Numerics;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Rigs;

/// <summary>
/// How a walking foot holds the ground: IK putting the limb's contact point on a point with its contact face
/// against the surface, as flat as <see cref="FlatTolerance"/> when it can, else within the IK's default 15°; joints
/// at their limits are released so the others make up for them (<see cref="IkSettings.ReleaseLimits"/>). One rule
/// for the gait that holds the feet and for <see cref="ReducedModelBuilder.WalkableSlope"/>, which asks where it
/// can. Thread-safe.
/// </summary>
internal sealed class SoleHold
{
    /// <summary>How far a held sole may tilt from the ground when it can lie flat, radians (5°).</summary>
    public const float FlatTolerance = 5f * MathF.PI / 180f;

    /// <summary>Iterations of each solve: few, since a held foot is tracked from where it was.</summary>
    public const int Iterations = 24;

    /// <summary>Creates the rule for <paramref name="rig"/>.</summary>
    public SoleHold(Rig rig)
    {
        Flat = new LimbIk(rig, new IkSettings { Restarts = 0, MaxIterations = Iterations, NormalTolerance = FlatTolerance, ReleaseLimits = true });
        Loose = new LimbIk(rig, new IkSettings { Restarts = 0, MaxIterations = Iterations, ReleaseLimits = true });
    }

    /// <summary>The solver holding the sole within <see cref="FlatTolerance"/>.</summary>
    public LimbIk Flat { get; }

    /// <summary>The solver holding it within the IK's default 15°.</summary>
    public LimbIk Loose { get; }

    /// <summary>
    /// Moves <paramref name="limb"/>'s angles in <paramref name="q"/> (updated only on success) so that its contact point
    /// lies on <paramref name="point"/> (world metres) with its contact face against ground of normal
    /// <paramref name="groundNormal"/> (world, unit, pointing out of the ground); true when it does.
    /// </summary>
    public bool Hold(in RootPose root, float[] q, RigLimb limb, Vector3 point, Vector3 groundNormal) =>
        Flat.Solve(root, q, limb, point, -groundNormal).Success || Loose.Solve(root, q, limb, point, -groundNormal).Success;
}
