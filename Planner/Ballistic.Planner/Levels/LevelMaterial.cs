using System.Globalization;

namespace Ballistic.Planner.Levels;

/// <summary>
/// A surface material of the level: its name, optionally the friction it imposes, and what crossing it costs a path
/// search (as a navigation area's costs do: a travel cost multiplying the time walked on it, an enter cost added on
/// stepping or landing onto it from another material). Costs change which routes are chosen, never a roadmap: a
/// roadmap baked before a cost changed stays valid.
/// </summary>
/// <param name="Name">Material name (from glTF, or given by code); may be empty.</param>
/// <param name="Friction">Coulomb friction coefficient μ overriding the character's default, or <c>null</c> to use the default.</param>
public sealed record LevelMaterial(string Name, float? Friction)
{
    /// <summary>Largest travel cost accepted.</summary>
    public const float MaxTravelCost = 1e3f;

    /// <summary>Largest enter cost accepted, seconds.</summary>
    public const float MaxEnterCost = 1e4f;

    /// <summary>
    /// What a second of walking on this material costs a search, in seconds of plain walking: 1 (the default) for
    /// none extra, 3 for mud a route avoids unless the way round is three times longer. At least 1: a search's
    /// estimate of the time left assumes no surface is cheaper than plain ground.
    /// </summary>
    public float TravelCost { get; init; } = 1f;

    /// <summary>
    /// Seconds a search adds each time a path steps or lands onto this material from another one (0, the default,
    /// for none): water a route enters only to save more than this.
    /// </summary>
    public float EnterCost { get; init; }

    /// <summary>True when this material costs more than plain ground to cross or enter.</summary>
    internal bool HasCost => TravelCost != 1f || EnterCost != 0f;

    /// <summary>Null when <paramref name="travelCost"/> and <paramref name="enterCost"/> are accepted, else what is wrong with them.</summary>
    internal static string? CostProblem(float travelCost, float enterCost) =>
        !(travelCost >= 1f && travelCost <= MaxTravelCost) ? $"travel cost {travelCost.ToString(CultureInfo.InvariantCulture)} must be a number from 1 to {MaxTravelCost.ToString(CultureInfo.InvariantCulture)}"
        : !(enterCost >= 0f && enterCost <= MaxEnterCost) ? $"enter cost {enterCost.ToString(CultureInfo.InvariantCulture)} must be a number of seconds from 0 to {MaxEnterCost.ToString(CultureInfo.InvariantCulture)}"
        : null;
}
