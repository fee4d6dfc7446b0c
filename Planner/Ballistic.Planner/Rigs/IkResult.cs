namespace Ballistic.Planner.Rigs;

/// <summary>The outcome of a limb IK solve.</summary>
/// <param name="Success">True when the effector reached its target within the tolerances; the configuration was then updated.</param>
/// <param name="PositionError">Remaining distance from the effector to its target, metres.</param>
/// <param name="NormalError">Remaining angle between the contact normal and its target, radians (0 without a normal target).</param>
/// <param name="Iterations">Iterations spent over all attempts.</param>
internal readonly record struct IkResult(bool Success, float PositionError, float NormalError, int Iterations);
