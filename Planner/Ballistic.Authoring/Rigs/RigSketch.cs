using System.Numerics;
using Ballistic.Planner.Rigs;

namespace Ballistic.Authoring.Rigs;

/// <summary>A joint list under construction, with named joints, bone radii and named pose angles.</summary>
internal sealed class RigSketch
{
    private readonly List<Joint> _joints = [];
    private readonly List<float> _radii = [];

    public IReadOnlyList<Joint> Joints => _joints;

    public IReadOnlyList<float> Radii => _radii;

    /// <summary>Adds a joint; returns its index.</summary>
    public int Add(string name, string? parent, Vector3 offset, float radius, params JointAxis[] axes)
    {
        int parentIndex = parent is null ? -1 : _joints.FindIndex(j => j.Name == parent);
        if (parent is not null && parentIndex < 0)
        {
            throw new RigException($"Joint '{name}' names the unknown parent '{parent}'.");
        }

        _joints.Add(new Joint(name, parentIndex, offset, Quaternion.Identity, axes));
        _radii.Add(radius);
        return _joints.Count - 1;
    }

    public int IndexOf(string name) => _joints.FindIndex(j => j.Name == name);

    /// <summary>A rotation about +X (pitch: positive tips +Y toward +Z) with limits in degrees.</summary>
    public static JointAxis X(float minDegrees, float maxDegrees) => new(Vector3.UnitX, Radians(minDegrees), Radians(maxDegrees));

    /// <summary>A rotation about +Y (yaw) with limits in degrees.</summary>
    public static JointAxis Y(float minDegrees, float maxDegrees) => new(Vector3.UnitY, Radians(minDegrees), Radians(maxDegrees));

    /// <summary>A rotation about +Z (roll: positive tips +X toward +Y) with limits in degrees.</summary>
    public static JointAxis Z(float minDegrees, float maxDegrees) => new(Vector3.UnitZ, Radians(minDegrees), Radians(maxDegrees));

    /// <summary>A configuration for a rig made from this sketch: every angle 0, then the named joints' angles (degrees).</summary>
    public float[] Pose(Rig rig, params (string Joint, float[] Degrees)[] angles)
    {
        float[] q = rig.Neutral();
        foreach ((string joint, float[] degrees) in angles)
        {
            int j = rig.IndexOf(joint);
            if (j < 0)
            {
                throw new RigException($"Pose names the unknown joint '{joint}'.");
            }

            for (int k = 0; k < degrees.Length && k < rig.DofsOf(j); k++)
            {
                q[rig.FirstDof(j) + k] = rig.Dofs[rig.FirstDof(j) + k].Clamp(Radians(degrees[k]));
            }
        }

        return q;
    }

    public static float Radians(float degrees) => degrees * MathF.PI / 180f;
}
