#nullable enable
using System;
using Ballistic.Runtime.DebugDraw;
using Godot;

namespace Ballistic.Addon;

/// <summary>Copies engine-free debug lines into Godot meshes: the runtime's <see cref="ImmediateMesh"/> view.</summary>
internal static class DebugMeshes
{
    /// <summary>An unshaded material coloured by vertex colour, drawn through geometry like Godot's navigation debug.</summary>
    public static StandardMaterial3D LineMaterial() => new()
    {
        ShadingMode = BaseMaterial3D.ShadingModeEnum.Unshaded,
        VertexColorUseAsAlbedo = true,
        Transparency = BaseMaterial3D.TransparencyEnum.Alpha,
        NoDepthTest = true,
    };

    /// <summary>
    /// The navigation debug colours of this project: each <see cref="DebugPalette"/> setting when the project sets it
    /// (Godot 4.7's <c>debug/shapes/navigation/3d/…</c> keys), Godot's default otherwise.
    /// </summary>
    public static DebugPalette Palette()
    {
        DebugPalette defaults = DebugPalette.GodotDefaults;
        return defaults with
        {
            Nodes = Setting(DebugPalette.NodeSetting, defaults.Nodes),
            Jumps = Setting(DebugPalette.JumpSetting, defaults.Jumps),
            Path = Setting(DebugPalette.PathSetting, defaults.Path),
            Cones = Setting(DebugPalette.ConeSetting, defaults.Cones),
            Disabled = Setting(DebugPalette.DisabledSetting, defaults.Disabled),
        };
    }

    private static DebugColor Setting(string name, DebugColor fallback)
    {
        if (!ProjectSettings.HasSetting(name))
        {
            return fallback;
        }

        Color c = ProjectSettings.GetSetting(name).AsColor();
        return new DebugColor(c.R, c.G, c.B, c.A);
    }

    /// <summary>Replaces the mesh's surfaces with one line surface holding every segment of <paramref name="lines"/> (world space).</summary>
    public static void Fill(ImmediateMesh mesh, Material material, DebugLines lines)
    {
        mesh.ClearSurfaces();
        if (lines.SegmentCount == 0)
        {
            return;
        }

        mesh.SurfaceBegin(Mesh.PrimitiveType.Lines, material);
        ReadOnlySpan<System.Numerics.Vector3> vertices = lines.Vertices;
        ReadOnlySpan<DebugColor> colors = lines.Colors;
        for (int i = 0; i < vertices.Length; i++)
        {
            DebugColor c = colors[i];
            mesh.SurfaceSetColor(new Color(c.R, c.G, c.B, c.A));
            mesh.SurfaceAddVertex(vertices[i].ToGodot());
        }

        mesh.SurfaceEnd();
    }
}
