namespace Ballistic.Planner.Rigs;

/// <summary>Parameters of the damped-least-squares limb IK.</summary>
internal sealed record IkSettings
{
    /// <summary>Iterations per attempt.</summary>
    public int MaxIterations { get; init; } = 80;

    /// <summary>Attempts from other starting configurations when the first does not converge.</summary>
    public int Restarts { get; init; } = 6;

    /// <summary>Damping λ of (J Jᵀ + λ² I); larger is steadier near singularities, slower to converge.</summary>
    public double Damping { get; init; } = 0.03;

    /// <summary>A solution must put the effector within this distance of its target, metres.</summary>
    public float PositionTolerance { get; init; } = 1e-3f;

    /// <summary>A solution must align the contact normal within this angle of its target, radians (15°).</summary>
    public float NormalTolerance { get; init; } = 15f * MathF.PI / 180f;

    /// <summary>Weight of a radian of normal error against a metre of position error.</summary>
    public double NormalWeight { get; init; } = 0.2;

    /// <summary>Largest change of one angle per iteration, radians.</summary>
    public double MaxStep { get; init; } = 0.3;

    /// <summary>
    /// Leave a joint held at a limit out of a step that would push it past the limit, so that the other joints make up
    /// for it: the solver tracks a moving target with a joint at its limit (an ankle bent as far as it goes) instead
    /// of stalling a millimetre or two short. Off by default, since it changes which of several solutions a solve
    /// lands on; the walking gait turns it on for the feet it holds.
    /// </summary>
    public bool ReleaseLimits { get; init; }

    /// <summary>Solve the small damped systems with MathNet.Numerics instead of the built-in Cholesky.</summary>
    public bool UseMathNet { get; init; }
}
