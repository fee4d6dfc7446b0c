namespace Ballistic.Planner.Levels;

/// <summary>A surface material of the level: its name and, optionally, the friction it imposes.</summary>
/// <param name="Name">Material name (from glTF, or given by code); may be empty.</param>
/// <param name="Friction">Coulomb friction coefficient μ overriding the character's default, or <c>null</c> to use the default.</param>
public sealed record LevelMaterial(string Name, float? Friction);
