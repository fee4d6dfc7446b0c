using System.Numerics;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;

namespace Ballistic.Planner.Animation;

/// <summary>
/// Where the spec's contact pose holds each limb's effector across the trunk (metres along the trunk's left, +X of
/// the root frame): a foot's place under its hip, from which "legs under the body" is measured. Free feet are posed,
/// folded and stepped within a share of the leg of it first. Thread-safe.
/// </summary>
internal sealed class FootPlaces
{
    private readonly float[] _side;

    /// <summary>The places of <paramref name="model"/>'s limbs, from its contact pose.</summary>
    public FootPlaces(CharacterModel model)
    {
        Rig rig = model.Rig;
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), model.ContactPose, positions, rotations);
        _side = [.. model.Limbs.Select(l => l.EffectorPosition(positions, rotations).X)];
    }

    /// <summary>How far (metres, root frame +X) along the trunk's left the contact pose holds limb <paramref name="limb"/>'s effector.</summary>
    public float Side(int limb) => _side[limb];

    /// <summary>How far (metres) <paramref name="point"/> (world) lies sideways, along the trunk's left at <paramref name="root"/>, of limb <paramref name="limb"/>'s place.</summary>
    public float Off(int limb, in RootPose root, Vector3 point) =>
        MathF.Abs(Vector3.Dot(point - root.Position, Vector3.Transform(Vector3.UnitX, root.Rotation)) - _side[limb]);
}
