using System.Runtime.InteropServices;

namespace Ballistic.Runtime.DebugDraw;

/// <summary>
/// A colour for debug lines: red, green, blue and alpha from 0 to 1, laid out as four consecutive floats like
/// Godot's <c>Color</c> (so a span of them converts to Godot colours member by member or by a memory cast).
/// </summary>
/// <param name="R">Red, 0 to 1.</param>
/// <param name="G">Green, 0 to 1.</param>
/// <param name="B">Blue, 0 to 1.</param>
/// <param name="A">Alpha (opacity), 0 to 1.</param>
[StructLayout(LayoutKind.Sequential)]
public readonly record struct DebugColor(float R, float G, float B, float A)
{
    /// <inheritdoc />
    public override string ToString() => $"Color({R}, {G}, {B}, {A})";
}
