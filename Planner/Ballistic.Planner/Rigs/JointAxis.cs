using System.Numerics;

namespace Ballistic.Planner.Rigs;

/// <summary>
/// One rotational degree of freedom of a joint: a rotation about <see cref="Axis"/> (a unit vector in the joint's
/// rest frame) by an angle in [<see cref="Min"/>, <see cref="Max"/>] radians.
/// </summary>
/// <param name="Axis">Unit rotation axis in the joint's rest frame.</param>
/// <param name="Min">Lower limit, radians.</param>
/// <param name="Max">Upper limit, radians (≥ <paramref name="Min"/>).</param>
internal readonly record struct JointAxis(Vector3 Axis, float Min, float Max)
{
    /// <summary>Clamps an angle to the limits.</summary>
    public float Clamp(float angle) => Math.Clamp(angle, Min, Max);
}
