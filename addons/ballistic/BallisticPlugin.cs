#nullable enable
#if TOOLS
using Godot;

namespace Ballistic.Addon.Editor;

/// <summary>
/// The editor side of the Ballistic addon, shaped like Godot's navigation region editor: with a
/// <see cref="JumpRoadmap3D"/> selected, the 3D editor's toolbar shows "Bake Jump Roadmap" and "Clear"; roadmaps and
/// jumps are drawn by a gizmo; enabling the plugin registers the <see cref="JumpNavigationServer"/> autoload and
/// disabling it removes it. Node types register themselves through <c>[GlobalClass]</c>. No planning logic here.
/// </summary>
[Tool]
public partial class BallisticPlugin : EditorPlugin
{
    /// <summary>The autoload's name: the node is reachable at <c>/root/JumpNavigationServer</c>.</summary>
    public const string AutoloadName = "JumpNavigationServer";

    /// <summary>The autoload's script.</summary>
    public const string AutoloadPath = "res://addons/ballistic/Nodes/JumpNavigationServer.cs";

    private RoadmapBakeToolbar? _toolbar;
    private JumpRoadmapGizmoPlugin? _gizmos;

    /// <summary>Adds the toolbar (hidden until a roadmap node is selected) and the gizmo plugin.</summary>
    public override void _EnterTree()
    {
        _toolbar = new RoadmapBakeToolbar { Visible = false, UndoRedo = GetUndoRedo() };
        AddControlToContainer(CustomControlContainer.SpatialEditorMenu, _toolbar);
        _gizmos = new JumpRoadmapGizmoPlugin();
        AddNode3DGizmoPlugin(_gizmos);
    }

    /// <summary>Removes what <see cref="_EnterTree"/> added.</summary>
    public override void _ExitTree()
    {
        if (_toolbar is not null)
        {
            RemoveControlFromContainer(CustomControlContainer.SpatialEditorMenu, _toolbar);
            _toolbar.QueueFree();
            _toolbar = null;
        }

        if (_gizmos is not null)
        {
            RemoveNode3DGizmoPlugin(_gizmos);
            _gizmos = null;
        }
    }

    /// <summary>Registers the runtime autoload when the user enables the plugin.</summary>
    public override void _EnablePlugin() => AddAutoloadSingleton(AutoloadName, AutoloadPath);

    /// <summary>Removes the runtime autoload when the user disables the plugin.</summary>
    public override void _DisablePlugin() => RemoveAutoloadSingleton(AutoloadName);

    /// <summary>The plugin edits roadmap nodes.</summary>
    public override bool _Handles(GodotObject @object) => @object is JumpRoadmap3D;

    /// <summary>Remembers the roadmap node being edited.</summary>
    public override void _Edit(GodotObject @object)
    {
        if (_toolbar is not null)
        {
            _toolbar.Roadmap = @object as JumpRoadmap3D;
        }
    }

    /// <summary>Shows the toolbar while a roadmap node is selected.</summary>
    public override void _MakeVisible(bool visible)
    {
        if (_toolbar is not null)
        {
            _toolbar.Visible = visible;
        }
    }
}
#endif
