using System.Numerics;

namespace Ballistic.Planner.Characters;

/// <summary>
/// <see cref="WalkingLimits.IsWalkable"/> with its cosines and tangent worked out once: the walk check asks it at
/// every ground sample (every 5 cm of every walk steered), the gait at every foothold tried.
/// </summary>
internal readonly struct GroundSlopeTest
{
    private readonly float _anyCosine;
    private readonly float _alongCosine;
    private readonly float _acrossTangent;

    /// <summary>The test of <paramref name="limits"/>.</summary>
    public GroundSlopeTest(WalkingLimits limits)
    {
        _anyCosine = MathF.Cos(limits.MaxSlopeDegrees * MathF.PI / 180f);
        _alongCosine = MathF.Cos(limits.MaxSlopeAlongDegrees * MathF.PI / 180f);
        _acrossTangent = MathF.Tan(limits.MaxSlopeDegrees * MathF.PI / 180f);
    }

    /// <summary>See <see cref="WalkingLimits.IsWalkable"/>.</summary>
    public bool Accepts(Vector3 normal, Vector3 heading)
    {
        float up = MathF.Abs(normal.Y);
        if (up >= _anyCosine)
        {
            return true;
        }

        var ahead = new Vector2(heading.X, heading.Z);
        float length = ahead.Length();
        if (up < _alongCosine || !(length > 1e-6f))
        {
            return false;
        }

        // The part of the ground's fall across the heading: the normal's horizontal part along the side axis.
        float side = MathF.Abs(((normal.X * ahead.Y) - (normal.Z * ahead.X)) / length);
        return side <= up * _acrossTangent;
    }
}
