using System.Numerics;

namespace Ballistic.Planner.Contacts;

/// <summary>
/// A circular Coulomb friction cone with its apex at the centre of mass: the forces (and, under the impulse model,
/// the velocity changes) the contacts can produce without slipping. World frame, Y up.
/// </summary>
public readonly record struct FrictionCone
{
    /// <summary>Creates a cone from its axis and friction coefficient.</summary>
    /// <param name="axis">Cone axis in world space; normalised here. Must be finite and non-zero.</param>
    /// <param name="mu">Coulomb friction coefficient μ ≥ 0 (dimensionless); the half-angle is atan μ.</param>
    /// <exception cref="ArgumentOutOfRangeException">The axis is zero or not finite, or μ is negative or not finite.</exception>
    public FrictionCone(Vector3 axis, float mu)
    {
        float length = axis.Length();
        if (!(length > 1e-9f) || !float.IsFinite(length))
        {
            throw new ArgumentOutOfRangeException(nameof(axis), axis, "A friction cone needs a finite, non-zero axis.");
        }

        if (!(mu >= 0f) || !float.IsFinite(mu))
        {
            throw new ArgumentOutOfRangeException(nameof(mu), mu, "The friction coefficient must be finite and not negative.");
        }

        Axis = axis / length;
        Mu = mu;
    }

    /// <summary>Unit axis of the cone, world space.</summary>
    public Vector3 Axis { get; }

    /// <summary>Coulomb friction coefficient μ (dimensionless).</summary>
    public float Mu { get; }

    /// <summary>Half-angle of the cone, atan μ, in radians.</summary>
    public float HalfAngle => MathF.Atan(Mu);

    /// <summary>Cosine of the half-angle, 1 / √(1 + μ²).</summary>
    public float CosHalfAngle => 1f / MathF.Sqrt(1f + (Mu * Mu));

    /// <summary>
    /// True when the direction of <paramref name="v"/> lies in the cone, allowing <paramref name="angleTolerance"/>
    /// radians beyond its boundary. The zero vector is not in the cone.
    /// </summary>
    public bool Contains(Vector3 v, float angleTolerance = 0f)
    {
        float length = v.Length();
        if (!(length > 0f))
        {
            return false;
        }

        float cosAngle = Math.Clamp(Vector3.Dot(v, Axis) / length, -1f, 1f);
        return MathF.Acos(cosAngle) <= HalfAngle + angleTolerance;
    }

    /// <summary>The angle in radians between <paramref name="v"/> and the axis.</summary>
    public float AngleTo(Vector3 v)
    {
        float length = v.Length();
        return length > 0f ? MathF.Acos(Math.Clamp(Vector3.Dot(v, Axis) / length, -1f, 1f)) : MathF.PI;
    }
}
