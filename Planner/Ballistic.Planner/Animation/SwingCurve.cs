using System.Numerics;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Animation;

/// <summary>
/// The path of a foot swinging from one point to another (world metres): the cubic Bézier through the start, the start
/// raised along <c>up</c>, the end raised along it, and the end, so that the foot leaves the one surface straight up
/// and comes down straight onto the other, its highest point a given lift above the higher of the two; across, it moves
/// by a smoothstep. Shared by the walk's swings (<see cref="WalkGait"/>) and a leg stepping across in flight
/// (<see cref="JumpAnimator"/>).
/// </summary>
internal readonly struct SwingCurve
{
    private readonly Vector3 _start;
    private readonly Vector3 _end;
    private readonly Vector3 _up;
    private readonly float _c0;
    private readonly float _c1;

    /// <summary>A swing from <paramref name="start"/> to <paramref name="end"/> rising <paramref name="lift"/> metres above the higher of the two along <paramref name="up"/> (unit).</summary>
    public SwingCurve(Vector3 start, Vector3 end, Vector3 up, float lift)
    {
        float h0 = Vector3.Dot(start, up);
        float h1 = Vector3.Dot(end, up);
        float top = MathF.Max(h0, h1) + lift;
        (_start, _end, _up) = (start, end, up);
        _c0 = (top - h0) * 4f / 3f;
        _c1 = (top - h1) * 4f / 3f;
    }

    /// <summary>The point at <paramref name="s"/> (0 at the start, 1 at the end).</summary>
    public Vector3 At(float s) =>
        _start + ((_end - _start) * Easing.Smooth(s)) + (_up * ((_c0 * 3f * s * (1f - s) * (1f - s)) + (_c1 * 3f * s * s * (1f - s))));
}
