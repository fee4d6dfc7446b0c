namespace Ballistic.Planner.Tests.Godot;

/// <summary>One <c>key = value</c> line (the value may span lines) of a section, starting on 1-based <paramref name="Line"/>.</summary>
/// <param name="Key">The property name as written, e.g. <c>transform</c>, <c>metadata/_edit_group_</c>, <c>Character</c>.</param>
/// <param name="Value">The parsed value.</param>
/// <param name="Line">The 1-based line of the key.</param>
public sealed record GodotProperty(string Key, GodotValue Value, int Line);
