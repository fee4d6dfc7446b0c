#if TOOLS
using Godot;

namespace Ballistic.Addon;

/// <summary>
/// The editor side of the Ballistic addon. Node types register themselves through <c>[GlobalClass]</c>, so the
/// plugin only owns editor-only services; it holds no planning logic (that lives in the planner library).
/// </summary>
[Tool]
public partial class BallisticPlugin : EditorPlugin
{
    /// <summary>Called when the plugin is enabled or the editor starts with it enabled.</summary>
    public override void _EnterTree()
    {
        GD.Print($"Ballistic {BallisticAddonInfo.PlannerVersion}: planner loaded.");
    }
}
#endif
