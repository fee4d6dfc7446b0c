#nullable enable
#if TOOLS
using System;
using Ballistic.Runtime.DebugDraw;
using Godot;

namespace Ballistic.Addon.Editor;

/// <summary>
/// Draws a <see cref="JumpRoadmap3D"/>'s baked roadmap in the 3D editor: its stances as crosses and its jumps as arcs,
/// in the colours of Godot's navigation debug (<see cref="DebugPalette"/>). The lines come from
/// <see cref="DebugLines"/>; this only hands them to the gizmo in the node's local space.
/// </summary>
[Tool]
public partial class JumpRoadmapGizmoPlugin : EditorNode3DGizmoPlugin
{
    private readonly DebugDrawSettings _settings = new() { MaxArcs = 1500, Colors = DebugMeshes.Palette() };
    private readonly DebugLines _lines = new(4096);

    /// <summary>Creates the line materials, one per colour.</summary>
    public JumpRoadmapGizmoPlugin()
    {
        DebugPalette palette = DebugMeshes.Palette();
        CreateMaterial("nodes", ToColor(palette.Nodes), billboard: false, onTop: true);
        CreateMaterial("jumps", ToColor(palette.Jumps), billboard: false, onTop: true);
    }

    /// <summary>The gizmo's name in the editor's View › Gizmos menu.</summary>
    public override string _GetGizmoName() => "JumpRoadmap3D";

    /// <summary>Roadmap nodes get this gizmo.</summary>
    public override bool _HasGizmo(Node3D forNode3D) => forNode3D is JumpRoadmap3D;

    /// <summary>Redraws the roadmap (after a bake the node calls <c>UpdateGizmos</c>).</summary>
    public override void _Redraw(EditorNode3DGizmo gizmo)
    {
        gizmo.Clear();
        if (gizmo.GetNode3D() is not JumpRoadmap3D roadmap)
        {
            return;
        }

        _lines.Clear();
        (DebugLineRange nodes, DebugLineRange jumps) = roadmap.AddGizmoLines(_lines, _settings);
        Transform3D toLocal = roadmap.GlobalTransform.AffineInverse();
        Add(gizmo, "nodes", _lines.VerticesOf(nodes), toLocal);
        Add(gizmo, "jumps", _lines.VerticesOf(jumps), toLocal);
    }

    private void Add(EditorNode3DGizmo gizmo, string material, ReadOnlySpan<System.Numerics.Vector3> world, Transform3D toLocal)
    {
        if (world.Length == 0)
        {
            return;
        }

        var local = new Vector3[world.Length];
        for (int i = 0; i < world.Length; i++)
        {
            local[i] = toLocal * world[i].ToGodot();
        }

        gizmo.AddLines(local, GetMaterial(material, gizmo));
    }

    private static Color ToColor(DebugColor c) => new(c.R, c.G, c.B, c.A);
}
#endif
