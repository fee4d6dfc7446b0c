namespace Ballistic.Planner.Tests.Godot;

/// <summary>
/// One Godot engine class as the scene tests know it: its parent class and the properties it adds (snake_case, as
/// written in scenes), plus prefixes of the indexed properties it stores (e.g. <c>surface_material_override/</c>).
/// </summary>
/// <param name="Name">The class name, e.g. <c>MeshInstance3D</c>.</param>
/// <param name="Parent">The parent class, or null for <c>Object</c>.</param>
/// <param name="Properties">The properties this class adds (not its parents').</param>
/// <param name="Prefixes">Prefixes of the dynamic <c>prefix/…</c> properties this class adds.</param>
public sealed record GodotClass(string Name, string? Parent, IReadOnlyList<string> Properties, IReadOnlyList<string> Prefixes);
