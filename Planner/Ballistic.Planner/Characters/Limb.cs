using System.Numerics;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Characters;

/// <summary>
/// A limb of the reduced character: the box Wk bounding the workspace its effector can reach, fixed to the trunk,
/// and the surfaces it may touch.
/// </summary>
/// <param name="Name">Unique limb name, e.g. <c>left_foot</c>.</param>
/// <param name="Kind">Foot or hand.</param>
/// <param name="WorkspaceCenter">Centre of Wk in the trunk frame, metres.</param>
/// <param name="WorkspaceHalfExtents">Half extents of Wk along its own axes, metres.</param>
/// <param name="WorkspaceRotation">Rotation of Wk relative to the trunk frame.</param>
/// <param name="Filter">Surfaces the limb may touch.</param>
public sealed record Limb(string Name, LimbKind Kind, Vector3 WorkspaceCenter, Vector3 WorkspaceHalfExtents, Quaternion WorkspaceRotation, NormalFilter Filter)
{
    /// <summary>The workspace Wk in world space for the root pose <paramref name="root"/>.</summary>
    internal OrientedBox WorkspaceAt(in RootPose root) =>
        new(root.ToWorld(WorkspaceCenter), WorkspaceHalfExtents, root.Rotation * WorkspaceRotation);

    /// <summary>
    /// Where the character's contact pose holds the limb's contact point, in the trunk frame (metres); <c>null</c> for
    /// a limb given only by its box. The contact estimate on a surface is the point of it nearest here, so that the
    /// planned stance stands the limb where the animated body puts it (legs under the hips); without it, the centre of
    /// Wk's intersection with the surface (the paper's estimate).
    /// </summary>
    public Vector3? Home { get; init; }
}
