using System.Numerics;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Rigs;

/// <summary>
/// A kinematic skeleton: joints in parent-before-child order, the first being the root joint (the pelvis or thorax)
/// placed by the character's root pose. A configuration is one angle per degree of freedom (<see cref="DofCount"/>);
/// forward kinematics gives every joint's world position and rotation. Y up, metres, radians.
/// </summary>
public sealed class Rig
{
    private readonly Joint[] _joints;
    private readonly int[] _firstDof;
    private readonly JointAxis[] _dofs;
    private readonly int[] _dofJoint;

    /// <summary>Creates a rig, checking the joint order and limits.</summary>
    /// <param name="joints">Joints, parents before children; joint 0 is the root (parent −1).</param>
    /// <param name="rootOffset">The root joint's position in the trunk frame (relative to the trunk box centre), metres.</param>
    /// <exception cref="RigException">Names repeat, a parent comes after its child, an axis is not unit, or a limit is inverted.</exception>
    internal Rig(IReadOnlyList<Joint> joints, Vector3 rootOffset)
    {
        ArgumentNullException.ThrowIfNull(joints);
        if (joints.Count == 0 || joints[0].Parent != -1)
        {
            throw new RigException("A rig needs a root joint first, with parent −1.");
        }

        var names = new HashSet<string>(StringComparer.Ordinal);
        var dofs = new List<JointAxis>();
        var dofJoint = new List<int>();
        _firstDof = new int[joints.Count + 1];
        for (int j = 0; j < joints.Count; j++)
        {
            Joint joint = joints[j];
            if (!names.Add(joint.Name))
            {
                throw new RigException($"Joint name '{joint.Name}' is used twice.");
            }

            if (j > 0 && (joint.Parent < 0 || joint.Parent >= j))
            {
                throw new RigException($"Joint '{joint.Name}' names parent {joint.Parent}; parents must come before their children.");
            }

            _firstDof[j] = dofs.Count;
            foreach (JointAxis axis in joint.Axes)
            {
                if (MathF.Abs(axis.Axis.Length() - 1f) > 1e-3f || !(axis.Min <= axis.Max))
                {
                    throw new RigException($"Joint '{joint.Name}': every axis must be a unit vector with min ≤ max.");
                }

                dofs.Add(axis);
                dofJoint.Add(j);
            }
        }

        _firstDof[joints.Count] = dofs.Count;
        _joints = [.. joints];
        _dofs = [.. dofs];
        _dofJoint = [.. dofJoint];
        RootOffset = rootOffset;
    }

    /// <summary>The joints, parents before children.</summary>
    internal IReadOnlyList<Joint> Joints => _joints;

    /// <summary>Number of rotational degrees of freedom.</summary>
    public int DofCount => _dofs.Length;

    /// <summary>The degrees of freedom in configuration order.</summary>
    internal IReadOnlyList<JointAxis> Dofs => _dofs;

    /// <summary><see cref="Dofs"/> as a span: read by the IK's inner loops without an interface call per axis.</summary>
    internal ReadOnlySpan<JointAxis> DofSpan => _dofs;

    /// <summary>The root joint's position in the trunk frame, metres.</summary>
    public Vector3 RootOffset { get; }

    /// <summary>Index of the first degree of freedom of joint <paramref name="joint"/> in a configuration.</summary>
    public int FirstDof(int joint) => _firstDof[joint];

    /// <summary>Number of degrees of freedom of joint <paramref name="joint"/>.</summary>
    public int DofsOf(int joint) => _firstDof[joint + 1] - _firstDof[joint];

    /// <summary>The joint a degree of freedom belongs to.</summary>
    public int JointOfDof(int dof) => _dofJoint[dof];

    /// <summary>Index of the joint called <paramref name="name"/>, or −1.</summary>
    public int IndexOf(string name) => Array.FindIndex(_joints, j => j.Name == name);

    /// <summary>True when <paramref name="ancestor"/> is <paramref name="joint"/> or one of its ancestors.</summary>
    public bool IsAncestor(int ancestor, int joint)
    {
        for (int j = joint; j >= 0; j = _joints[j].Parent)
        {
            if (j == ancestor)
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>A configuration with every angle at zero clamped into its limits.</summary>
    public float[] Neutral()
    {
        var q = new float[DofCount];
        for (int i = 0; i < q.Length; i++)
        {
            q[i] = _dofs[i].Clamp(0f);
        }

        return q;
    }

    /// <summary>Clamps every angle of <paramref name="q"/> into its limits, in place.</summary>
    public void Clamp(Span<float> q)
    {
        for (int i = 0; i < q.Length; i++)
        {
            q[i] = _dofs[i].Clamp(q[i]);
        }
    }

    /// <summary>True when every angle lies within its limits (with <paramref name="tolerance"/> radians of slack).</summary>
    public bool WithinLimits(ReadOnlySpan<float> q, float tolerance = 1e-5f)
    {
        for (int i = 0; i < q.Length; i++)
        {
            if (q[i] < _dofs[i].Min - tolerance || q[i] > _dofs[i].Max + tolerance)
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>How far (radians) joint <paramref name="joint"/>'s local rotation in <paramref name="a"/> is from that in <paramref name="b"/>.</summary>
    internal float JointTurn(int joint, ReadOnlySpan<float> a, ReadOnlySpan<float> b) =>
        2f * MathF.Acos(MathF.Min(1f, MathF.Abs(Quaternion.Dot(LocalRotation(joint, a), LocalRotation(joint, b)))));

    /// <summary>The local rotation of joint <paramref name="joint"/> (rest rotation, then its axes in order).</summary>
    public Quaternion LocalRotation(int joint, ReadOnlySpan<float> q)
    {
        Quaternion r = _joints[joint].RestRotation;
        for (int d = _firstDof[joint]; d < _firstDof[joint + 1]; d++)
        {
            r *= Quaternion.CreateFromAxisAngle(_dofs[d].Axis, q[d]);
        }

        return r;
    }

    /// <summary>
    /// Forward kinematics: the world position and rotation of every joint for root pose <paramref name="root"/> and
    /// configuration <paramref name="q"/>, written into the two spans (length = joint count).
    /// </summary>
    public void Solve(in RootPose root, ReadOnlySpan<float> q, Span<Vector3> positions, Span<Quaternion> rotations)
    {
        if (q.Length != DofCount || positions.Length < _joints.Length || rotations.Length < _joints.Length)
        {
            throw new ArgumentException($"Forward kinematics needs {DofCount} angles and room for {_joints.Length} joints.");
        }

        for (int j = 0; j < _joints.Length; j++)
        {
            SolveJoint(j, root, q, positions, rotations);
        }
    }

    /// <summary>
    /// <see cref="Solve"/> for the joints of <paramref name="chain"/> only (in order, each after its parent), the others'
    /// entries left as they are: after a full solve, when only the chain's own angles changed, the same numbers a full
    /// solve gives, bit for bit (the IK moves one limb many times over).
    /// </summary>
    internal void SolveChain(in RootPose root, IReadOnlyList<int> chain, ReadOnlySpan<float> q, Span<Vector3> positions, Span<Quaternion> rotations)
    {
        for (int i = 0; i < chain.Count; i++)
        {
            SolveJoint(chain[i], root, q, positions, rotations);
        }
    }

    /// <summary>Joint <paramref name="j"/>'s world position and rotation from its parent's (the root pose for joint 0).</summary>
    private void SolveJoint(int j, in RootPose root, ReadOnlySpan<float> q, Span<Vector3> positions, Span<Quaternion> rotations) =>
        Place(j, LocalRotation(j, q), root, positions, rotations);

    /// <summary>Joint <paramref name="j"/>'s world position and rotation from its parent's (the root pose for joint 0) and its own <paramref name="local"/> rotation.</summary>
    private void Place(int j, Quaternion local, in RootPose root, Span<Vector3> positions, Span<Quaternion> rotations)
    {
        Joint joint = _joints[j];
        if (j == 0)
        {
            positions[0] = root.ToWorld(RootOffset + joint.Offset);
            rotations[0] = Quaternion.Normalize(root.Rotation * local);
        }
        else
        {
            positions[j] = positions[joint.Parent] + Vector3.Transform(joint.Offset, rotations[joint.Parent]);
            rotations[j] = Quaternion.Normalize(rotations[joint.Parent] * local);
        }
    }

    /// <summary>
    /// The world axis of degree of freedom <paramref name="dof"/> given the joints' world rotations: the axis after
    /// the rest rotation and the joint's earlier axes.
    /// </summary>
    public Vector3 WorldAxis(int dof, ReadOnlySpan<float> q, ReadOnlySpan<Quaternion> rotations)
    {
        int joint = _dofJoint[dof];
        Joint j = _joints[joint];
        Quaternion parent = joint == 0 ? rotations[0] * Quaternion.Conjugate(LocalRotation(0, q)) : rotations[j.Parent];
        Quaternion frame = parent * j.RestRotation;
        for (int d = _firstDof[joint]; d < dof; d++)
        {
            frame *= Quaternion.CreateFromAxisAngle(_dofs[d].Axis, q[d]);
        }

        return Vector3.Normalize(Vector3.Transform(_dofs[dof].Axis, frame));
    }

    /// <summary>
    /// The turns of <paramref name="chain"/>'s degrees of freedom under <paramref name="q"/> into
    /// <paramref name="turns"/>: a joint's axes one after another, each joint's after its parent's (a limb's
    /// <see cref="RigLimb.ChainDofs"/> order), each the rotation <see cref="LocalRotation(int, ReadOnlySpan{float})"/> multiplies in for it.
    /// </summary>
    internal void Turns(ReadOnlySpan<int> chain, ReadOnlySpan<float> q, Span<Quaternion> turns)
    {
        int i = 0;
        foreach (int joint in chain)
        {
            for (int d = _firstDof[joint]; d < _firstDof[joint + 1]; d++)
            {
                turns[i++] = Quaternion.CreateFromAxisAngle(_dofs[d].Axis, q[d]);
            }
        }
    }

    /// <summary>
    /// <see cref="SolveChain(in RootPose, IReadOnlyList{int}, ReadOnlySpan{float}, Span{Vector3}, Span{Quaternion})"/> from the turns <see cref="Turns"/> gives for the same chain and angles: the same
    /// numbers bit for bit, each turn computed once for this and for <see cref="WorldAxes"/>.
    /// </summary>
    internal void SolveChain(in RootPose root, ReadOnlySpan<int> chain, ReadOnlySpan<Quaternion> turns, Span<Vector3> positions, Span<Quaternion> rotations)
    {
        int i = 0;
        foreach (int j in chain)
        {
            Place(j, LocalRotation(j, turns[i..]), root, positions, rotations);
            i += DofsOf(j);
        }
    }

    /// <summary><see cref="LocalRotation(int, ReadOnlySpan{float})"/> of joint <paramref name="joint"/> from its axes' turns (<see cref="Turns"/>), first of <paramref name="turns"/>: the same product, bit for bit.</summary>
    private Quaternion LocalRotation(int joint, ReadOnlySpan<Quaternion> turns)
    {
        Quaternion r = _joints[joint].RestRotation;
        for (int k = 0; k < DofsOf(joint); k++)
        {
            r *= turns[k];
        }

        return r;
    }

    /// <summary>
    /// <see cref="WorldAxis"/> of each degree of freedom of <paramref name="chain"/> (in <see cref="Turns"/>' order)
    /// into <paramref name="axes"/>, from the turns <see cref="Turns"/> gives for the same angles: the same numbers bit
    /// for bit, a joint's axes from one running product of its rest rotation and its earlier axes' turns instead of
    /// that product made anew for each axis (the IK asks for a limb's axes at every iteration).
    /// </summary>
    internal void WorldAxes(ReadOnlySpan<int> chain, ReadOnlySpan<Quaternion> turns, ReadOnlySpan<Quaternion> rotations, Span<Vector3> axes)
    {
        int i = 0;
        foreach (int j in chain)
        {
            Quaternion parent = j == 0 ? rotations[0] * Quaternion.Conjugate(LocalRotation(0, turns[i..])) : rotations[_joints[j].Parent];
            Quaternion frame = parent * _joints[j].RestRotation;
            for (int d = _firstDof[j]; d < _firstDof[j + 1]; d++)
            {
                axes[i] = Vector3.Normalize(Vector3.Transform(_dofs[d].Axis, frame));
                frame *= turns[i++];
            }
        }
    }
}
