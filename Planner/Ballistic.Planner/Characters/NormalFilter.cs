using System.Numerics;

namespace Ballistic.Planner.Characters;

/// <summary>
/// Which surfaces a limb may touch, by their normal: accepted when normal · <see cref="Direction"/> ≥
/// <see cref="MinCosine"/>. World frame. Feet usually need upward surfaces; hands may push off walls.
/// </summary>
/// <param name="Direction">Unit reference direction, world space (usually +Y).</param>
/// <param name="MinCosine">Smallest accepted cosine between the surface normal and the direction; −1 accepts all.</param>
public readonly record struct NormalFilter(Vector3 Direction, float MinCosine)
{
    /// <summary>Accepts every surface.</summary>
    public static NormalFilter None => new(Vector3.UnitY, -1f);

    /// <summary>Accepts surfaces whose normal is within acos(<paramref name="minCosine"/>) of world up.</summary>
    public static NormalFilter Upward(float minCosine) => new(Vector3.UnitY, minCosine);

    /// <summary>True when a surface of unit normal <paramref name="normal"/> is accepted.</summary>
    public bool Accepts(Vector3 normal) => MinCosine <= -1f || Vector3.Dot(normal, Direction) >= MinCosine;
}
