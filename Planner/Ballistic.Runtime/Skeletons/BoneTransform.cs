using System.Numerics;

namespace Ballistic.Runtime.Skeletons;

/// <summary>
/// A translation, rotation and scale, applied scale first, then rotation, then translation (Godot's
/// <c>Transform3D(Basis(rotation, scale), origin)</c>): a bone's rest relative to its parent bone, or a skeleton
/// node's global transform. Metres (or the units of the parent space), Y up.
/// </summary>
/// <param name="Position">Translation in the parent space (Godot: <c>Transform3D.Origin</c>).</param>
/// <param name="Rotation">Unit rotation (Godot: <c>Basis.GetRotationQuaternion()</c>).</param>
/// <param name="Scale">Scale along the local axes (Godot: <c>Basis.Scale</c>); the binding needs it uniform where it matters.</param>
public readonly record struct BoneTransform(Vector3 Position, Quaternion Rotation, Vector3 Scale)
{
    /// <summary>The identity: no translation, no rotation, scale 1.</summary>
    public static BoneTransform Identity { get; } = new(Vector3.Zero, Quaternion.Identity, Vector3.One);

    /// <summary>A rigid transform with scale 1.</summary>
    public BoneTransform(Vector3 position, Quaternion rotation)
        : this(position, rotation, Vector3.One)
    {
    }

    /// <summary>True when the three scale factors agree within 0.1 % and are positive and finite.</summary>
    public bool HasUniformScale
    {
        get
        {
            float s = Scale.X;
            return s > 0f && float.IsFinite(s) && float.IsFinite(Scale.Y) && float.IsFinite(Scale.Z)
                && MathF.Abs(Scale.Y - s) <= 1e-3f * s && MathF.Abs(Scale.Z - s) <= 1e-3f * s;
        }
    }

    /// <summary>True when every component is finite and the rotation is not zero.</summary>
    public bool IsFinite =>
        float.IsFinite(Position.X) && float.IsFinite(Position.Y) && float.IsFinite(Position.Z)
        && float.IsFinite(Rotation.X) && float.IsFinite(Rotation.Y) && float.IsFinite(Rotation.Z) && float.IsFinite(Rotation.W)
        && Rotation.LengthSquared() > 1e-12f
        && float.IsFinite(Scale.X) && float.IsFinite(Scale.Y) && float.IsFinite(Scale.Z);

    /// <summary>Maps a point of this transform's local space to its parent space.</summary>
    public Vector3 TransformPoint(Vector3 local) => Position + Vector3.Transform(local * Scale, Rotation);
}
