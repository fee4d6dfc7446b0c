using System.Numerics;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Rigs;

/// <summary>
/// The body of a character built in code (one with no <see cref="CharacterModel.Source"/>): a box along each bone,
/// from its parent joint to its joint, as wide as the bone's radius each way and skinned rigidly to the parent; one
/// box at the root joint; one from each limb's effector joint to its contact point; the boxes of each effector bone and
/// the bones below it cut flat at the plane through the limb's contact point across its contact normal (a sole that
/// stands on the ground instead of sinking its corners into it). The exported GLB draws exactly these boxes and the
/// animator checks their corners against the level, so what is checked is what is seen. Rest pose (every angle 0),
/// model frame, metres.
/// </summary>
internal sealed class BoneBoxes
{
    private readonly Vector3[] _positions;
    private readonly int[] _joints;
    private readonly int[] _indices;

    /// <summary>The joints' positions and rotations at rest, model frame, from which the boxes were built.</summary>
    private readonly (Vector3[] Positions, Quaternion[] Rotations) _rest;

    private BoneBoxes(Vector3[] positions, int[] joints, int[] indices, (Vector3[], Quaternion[]) rest)
    {
        _positions = positions;
        _joints = joints;
        _indices = indices;
        _rest = rest;
    }

    /// <summary>Each vertex in the rest pose, model frame, metres (eight per box).</summary>
    public IReadOnlyList<Vector3> Positions => _positions;

    /// <summary>The joint each vertex is skinned to (weight 1), by vertex.</summary>
    public IReadOnlyList<int> Joints => _joints;

    /// <summary>Triangle list over <see cref="Positions"/>, twelve triangles per box.</summary>
    public IReadOnlyList<int> Indices => _indices;

    /// <summary>The boxes of <paramref name="model"/>'s bones in its rest pose.</summary>
    public static BoneBoxes Of(CharacterModel model)
    {
        ArgumentNullException.ThrowIfNull(model);
        Rig rig = model.Rig;
        int jointCount = rig.Joints.Count;
        var bindPositions = new Vector3[jointCount];
        var bindRotations = new Quaternion[jointCount];
        rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), new float[rig.DofCount], bindPositions, bindRotations);
        var positions = new List<Vector3>();
        var indices = new List<int>();
        var joints = new List<int>();
        for (int j = 0; j < jointCount; j++)
        {
            int parent = rig.Joints[j].Parent;
            if (parent >= 0)
            {
                AddBox(positions, indices, joints, bindPositions[parent], bindPositions[j], model.BoneRadii[j], bindRotations[parent], parent);
            }
            else
            {
                AddBox(positions, indices, joints, bindPositions[0] - new Vector3(0f, model.BoneRadii[0] * 0.5f, 0f), bindPositions[0] + new Vector3(0f, model.BoneRadii[0] * 0.5f, 0f), model.BoneRadii[0], bindRotations[0], 0);
            }
        }

        Vector3[] tips = [.. model.Limbs.Select(l => l.EffectorPosition(bindPositions, bindRotations))];
        for (int l = 0; l < model.Limbs.Count; l++)
        {
            int effector = model.Limbs[l].EffectorJoint;
            AddBox(positions, indices, joints, bindPositions[effector], tips[l], model.BoneRadii[effector], bindRotations[effector], effector);
        }

        for (int l = 0; l < model.Limbs.Count; l++)
        {
            RigLimb limb = model.Limbs[l];
            Vector3 tip = tips[l];
            Vector3 normal = Vector3.Normalize(Vector3.Transform(limb.ContactNormal, bindRotations[limb.EffectorJoint]));
            for (int v = 0; v < positions.Count; v++)
            {
                float beyond = Vector3.Dot(positions[v] - tip, normal);
                if (beyond > 0f && (joints[v] == limb.EffectorJoint || rig.IsAncestor(limb.EffectorJoint, joints[v])))
                {
                    positions[v] -= beyond * normal;
                }
            }
        }

        return new BoneBoxes([.. positions], [.. joints], [.. indices], (bindPositions, bindRotations));
    }

    /// <summary>
    /// The vertices skinned to each joint, in that joint's own frame at rest (metres): where the corners of a posed
    /// body are, given the joints' world positions and rotations.
    /// </summary>
    internal Vector3[][] InJointFrames()
    {
        (Vector3[] bindPositions, Quaternion[] bindRotations) = _rest;
        var points = new List<Vector3>[bindPositions.Length];
        for (int j = 0; j < points.Length; j++)
        {
            points[j] = [];
        }

        for (int v = 0; v < _positions.Length; v++)
        {
            int j = _joints[v];
            Vector3 local = Vector3.Transform(_positions[v] - bindPositions[j], Quaternion.Conjugate(bindRotations[j]));
            if (!points[j].Any(p => Vector3.DistanceSquared(p, local) < 1e-10f))
            {
                points[j].Add(local);
            }
        }

        return [.. points.Select(p => p.ToArray())];
    }

    private static void AddBox(List<Vector3> positions, List<int> indices, List<int> joints, Vector3 a, Vector3 b, float radius, Quaternion frame, int joint)
    {
        Vector3 axis = b - a;
        float length = axis.Length();
        Vector3 along = length > 1e-5f ? axis / length : Vector3.Transform(Vector3.UnitY, frame);
        Vector3 side = Vector3.Cross(along, MathF.Abs(along.Y) < 0.9f ? Vector3.UnitY : Vector3.UnitX);
        side = Vector3.Normalize(side) * radius;
        Vector3 up = Vector3.Normalize(Vector3.Cross(side, along)) * radius;
        int start = positions.Count;
        for (int i = 0; i < 8; i++)
        {
            positions.Add(((i & 1) == 0 ? a : b) + ((i & 2) == 0 ? -side : side) + ((i & 4) == 0 ? -up : up));
            joints.Add(joint);
        }

        int[] faces = [0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5, 0, 4, 5, 0, 5, 1, 2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3];
        foreach (int f in faces)
        {
            indices.Add(start + f);
        }
    }
}
