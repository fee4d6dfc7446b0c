using System.Numerics;

namespace Ballistic.Planner.Animation;

/// <summary>A time during which a limb's contact point stays on one surface point.</summary>
/// <param name="Limb">Index of the limb.</param>
/// <param name="Position">The contact point held, world metres.</param>
/// <param name="From">Start of the phase, seconds of clip time.</param>
/// <param name="To">End of the phase, seconds of clip time.</param>
public readonly record struct ContactPhase(int Limb, Vector3 Position, float From, float To);
