using System.Numerics;

namespace Ballistic.Planner.Geometry;

/// <summary>
/// A configuration of the character's root, q⁰ in the paper: the trunk box centre in world space (metres, Y up)
/// and the trunk's local-to-world rotation. The trunk's local +Y is its "up", aligned with the supporting surface.
/// </summary>
/// <param name="Position">Trunk centre, world metres.</param>
/// <param name="Rotation">Unit local-to-world rotation of the trunk.</param>
public readonly record struct RootPose(Vector3 Position, Quaternion Rotation)
{
    /// <summary>The trunk's local +Y axis in world space: the direction the character's back points.</summary>
    public Vector3 Up => Vector3.Transform(Vector3.UnitY, Rotation);

    /// <summary>The trunk's local +Z axis in world space: the direction the character faces (glTF and Godot model front).</summary>
    public Vector3 Forward => Vector3.Transform(Vector3.UnitZ, Rotation);

    /// <summary>Maps a point of the trunk frame (metres) to world space.</summary>
    public Vector3 ToWorld(Vector3 local) => Position + Vector3.Transform(local, Rotation);
}
