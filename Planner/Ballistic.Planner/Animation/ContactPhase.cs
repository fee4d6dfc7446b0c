using System.Numerics;
using Ballistic.Planner.Rigs;

namespace Ballistic.Planner.Animation;

/// <summary>A time during which a limb's contact point stays on one surface point.</summary>
/// <param name="Limb">Index of the limb.</param>
/// <param name="Position">The contact point held, world metres.</param>
/// <param name="From">Start of the phase, seconds of clip time.</param>
/// <param name="To">End of the phase, seconds of clip time.</param>
internal readonly record struct ContactPhase(int Limb, Vector3 Position, float From, float To)
{
    /// <summary>
    /// True when the limb holds <see cref="Position"/> with the ball of its foot, heel raised (a walker's trailing
    /// foot rolling off before it swings), not with its contact point.
    /// </summary>
    public bool OnBall { get; init; }

    /// <summary>The point of <paramref name="limb"/> (this phase's) that touches <see cref="Position"/>, world metres, given the joints' world positions and rotations: its contact point, or its ball when <see cref="OnBall"/>.</summary>
    public Vector3 Touching(RigLimb limb, ReadOnlySpan<Vector3> positions, ReadOnlySpan<Quaternion> rotations)
    {
        ArgumentNullException.ThrowIfNull(limb);
        return TouchingLimb(limb).EffectorPosition(positions, rotations);
    }

    /// <summary><paramref name="limb"/> as it touches in this phase: itself, or its ball (<see cref="RigLimb.Ball"/>) when <see cref="OnBall"/>.</summary>
    internal RigLimb TouchingLimb(RigLimb limb) => OnBall && limb.Ball is RigLimb ball ? ball : limb;
}
