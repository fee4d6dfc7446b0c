namespace Ballistic.Planner.Tests.Godot;

/// <summary>Which of Godot's text formats a <see cref="GodotFile"/> is, chosen by its extension.</summary>
public enum GodotFileKind
{
    /// <summary>A <c>.tscn</c> scene: <c>[gd_scene …]</c> then ext/sub resources, nodes, connections, editable paths.</summary>
    Scene,

    /// <summary>A <c>.tres</c> resource: <c>[gd_resource …]</c> then ext/sub resources and one <c>[resource]</c>.</summary>
    Resource,

    /// <summary>A ConfigFile (<c>plugin.cfg</c>, <c>project.godot</c>, <c>*.import</c>): sections of <c>key=value</c>.</summary>
    Config,
}
