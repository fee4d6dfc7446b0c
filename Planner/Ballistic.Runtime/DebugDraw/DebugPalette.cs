namespace Ballistic.Runtime.DebugDraw;

/// <summary>
/// The colours of Ballistic's debug drawing, taken from Godot's navigation debug so that jumps read like the
/// navigation links and paths users know. The defaults are Godot's project-setting defaults; each colour names the
/// setting it mirrors (Godot 4.5 and later, under <c>debug/shapes/navigation/3d/</c>; earlier versions had the
/// same settings without the <c>3d/</c> segment), so the addon can read the project's own values with
/// <c>ProjectSettings.GetSetting(name, default)</c>. Values checked against Godot's
/// <c>servers/navigation_3d/navigation_server_3d_debug.cpp</c> (<c>GLOBAL_DEF</c>) and the ProjectSettings class reference.
/// </summary>
public sealed record DebugPalette
{
    /// <summary>Setting of the navigation mesh edge colour, used for roadmap nodes: default (0.5, 1, 1, 1).</summary>
    public const string NodeSetting = "debug/shapes/navigation/3d/geometry_edge_color";

    /// <summary>Setting of the navigation link colour, used for roadmap jumps: default (1, 0.5, 1, 1).</summary>
    public const string JumpSetting = "debug/shapes/navigation/3d/link_connection_color";

    /// <summary>Setting of the navigation agent path colour, used for an agent's path: default (1, 0, 0, 1).</summary>
    public const string PathSetting = "debug/shapes/navigation/3d/agent_path_color";

    /// <summary>Setting of the navigation region edge connection colour, used for friction cones: default (1, 0, 1, 1).</summary>
    public const string ConeSetting = "debug/shapes/navigation/3d/edge_connection_color";

    /// <summary>Setting of the disabled navigation link colour, used for jumps that are switched off: default (0.5, 0.5, 0.5, 1).</summary>
    public const string DisabledSetting = "debug/shapes/navigation/3d/link_connection_disabled_color";

    /// <summary>Godot's defaults.</summary>
    public static DebugPalette GodotDefaults { get; } = new();

    /// <summary>Crosses at roadmap nodes' contact centres (<see cref="NodeSetting"/>).</summary>
    public DebugColor Nodes { get; init; } = new(0.5f, 1f, 1f, 1f);

    /// <summary>Roadmap jump arcs (<see cref="JumpSetting"/>).</summary>
    public DebugColor Jumps { get; init; } = new(1f, 0.5f, 1f, 1f);

    /// <summary>An agent's current path arcs (<see cref="PathSetting"/>).</summary>
    public DebugColor Path { get; init; } = new(1f, 0f, 0f, 1f);

    /// <summary>Takeoff and landing friction cones (<see cref="ConeSetting"/>).</summary>
    public DebugColor Cones { get; init; } = new(1f, 0f, 1f, 1f);

    /// <summary>Disabled jumps (<see cref="DisabledSetting"/>).</summary>
    public DebugColor Disabled { get; init; } = new(0.5f, 0.5f, 0.5f, 1f);
}
