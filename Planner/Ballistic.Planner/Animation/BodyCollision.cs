using System.Numerics;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;

namespace Ballistic.Planner.Animation;

/// <summary>
/// Checks that no bone of the character passes through the level. Every bone is the segment from its parent joint
/// to its joint, tested as a box around the segment: a limb's bones (its chain and everything below its effector,
/// such as toes, plus the segment from the effector to its contact point) are thin, since feet rest on the
/// surface; every other bone (spine, neck, head, tail, ears) is as thick as half its radius
/// (<see cref="CharacterModel.BoneRadii"/>), since it should not even touch the level. Within
/// <see cref="ContactClearance"/> of a held contact point a bone may touch. Helper bones of a loaded rig that are no
/// body part (<see cref="CharacterSource.BodyBones"/>) are not checked. Thread-safe.
/// </summary>
public sealed class BodyCollision
{
    /// <summary>Distance from a contact point within which a bone may touch the surface, metres.</summary>
    public const float ContactClearance = 0.01f;

    /// <summary>Half-thickness of a limb bone's box, metres.</summary>
    private const float Thickness = 0.002f;

    private readonly TriangleBvh _bvh;
    private readonly CharacterModel _model;
    private readonly int[][] _limbBones;
    private readonly int[] _otherBones;
    private readonly float[] _otherThickness;

    /// <summary>Creates a checker of <paramref name="model"/>'s bones against a level.</summary>
    public BodyCollision(TriangleBvh bvh, CharacterModel model)
    {
        ArgumentNullException.ThrowIfNull(bvh);
        ArgumentNullException.ThrowIfNull(model);
        _bvh = bvh;
        _model = model;
        Rig rig = model.Rig;
        var owned = new bool[rig.Joints.Count];
        _limbBones = new int[model.Limbs.Count][];
        for (int l = 0; l < model.Limbs.Count; l++)
        {
            RigLimb limb = model.Limbs[l];
            var bones = new List<int>();
            for (int i = 1; i < limb.Chain.Count; i++)
            {
                bones.Add(limb.Chain[i]);
            }

            for (int j = 0; j < rig.Joints.Count; j++)
            {
                if (j != limb.EffectorJoint && rig.IsAncestor(limb.EffectorJoint, j))
                {
                    bones.Add(j);
                }
            }

            foreach (int j in bones)
            {
                owned[j] = true;
            }

            _limbBones[l] = [.. bones];
        }

        // Bones that are no body part (a loaded rig's helper bones: IK targets, control bones) are not checked.
        IReadOnlyList<bool> body = model.Source?.BodyBones ?? [];
        bool IsBody(int j) => body.Count == 0 || body[j];
        for (int l = 0; l < _limbBones.Length; l++)
        {
            _limbBones[l] = [.. _limbBones[l].Where(IsBody)];
        }

        var others = new List<int>();
        for (int j = 1; j < rig.Joints.Count; j++)
        {
            if (!owned[j] && IsBody(j))
            {
                others.Add(j);
            }
        }

        _otherBones = [.. others];
        _otherThickness = [.. others.Select(j => MathF.Max(Thickness, 0.5f * model.BoneRadii[j]))];
    }

    /// <summary>The bones (joint indices; each is the segment from its parent) checked with limb <paramref name="limb"/>.</summary>
    public IReadOnlyList<int> LimbBones(int limb) => _limbBones[limb];

    /// <summary>The bones that belong to no limb (spine, neck, head, tail…), checked with their radii.</summary>
    public IReadOnlyList<int> OtherBones => _otherBones;

    /// <summary>True when a bone of <paramref name="limb"/> (chain, bones below the effector, effector to contact point) passes through the level.</summary>
    /// <param name="limb">The limb.</param>
    /// <param name="positions">World positions of every joint.</param>
    /// <param name="rotations">World rotations of every joint.</param>
    /// <param name="contact">The contact point the limb holds, or <c>null</c>.</param>
    public bool LimbCollides(RigLimb limb, ReadOnlySpan<Vector3> positions, ReadOnlySpan<Quaternion> rotations, Vector3? contact)
    {
        ArgumentNullException.ThrowIfNull(limb);
        int l = IndexOf(limb);
        Rig rig = _model.Rig;
        Vector3 tip = limb.EffectorPosition(positions, rotations);

        // One box around the whole limb first: in flight it is usually clear of the level, and one query says so.
        Vector3 min = Vector3.Min(tip, positions[limb.EffectorJoint]);
        Vector3 max = Vector3.Max(tip, positions[limb.EffectorJoint]);
        foreach (int j in _limbBones[l])
        {
            min = Vector3.Min(min, Vector3.Min(positions[j], positions[rig.Joints[j].Parent]));
            max = Vector3.Max(max, Vector3.Max(positions[j], positions[rig.Joints[j].Parent]));
        }

        if (!_bvh.Overlaps(new OrientedBox((min + max) * 0.5f, ((max - min) * 0.5f) + new Vector3(Thickness), Quaternion.Identity)))
        {
            return false;
        }

        foreach (int j in _limbBones[l])
        {
            if (SegmentCollides(positions[rig.Joints[j].Parent], positions[j], contact, Thickness))
            {
                return true;
            }
        }

        return SegmentCollides(positions[limb.EffectorJoint], tip, contact, Thickness);
    }

    /// <summary>
    /// The first bone that belongs to no limb (spine, neck, head, tail…) and passes through the level, or −1.
    /// </summary>
    public int OtherBoneColliding(ReadOnlySpan<Vector3> positions)
    {
        Rig rig = _model.Rig;
        for (int i = 0; i < _otherBones.Length; i++)
        {
            int j = _otherBones[i];
            if (SegmentCollides(positions[rig.Joints[j].Parent], positions[j], null, _otherThickness[i]))
            {
                return j;
            }
        }

        return -1;
    }

    /// <summary>True when the segment from <paramref name="a"/> to <paramref name="b"/>, less the part near <paramref name="contact"/>, touches the level (as a 2 mm thin box).</summary>
    public bool SegmentCollides(Vector3 a, Vector3 b, Vector3? contact) => SegmentCollides(a, b, contact, Thickness);

    private bool SegmentCollides(Vector3 a, Vector3 b, Vector3? contact, float thickness)
    {
        if (contact is Vector3 c)
        {
            // Cut the segment where it comes within the clearance of the contact point.
            bool aNear = Vector3.Distance(a, c) <= ContactClearance;
            bool bNear = Vector3.Distance(b, c) <= ContactClearance;
            if (aNear && bNear)
            {
                return false;
            }

            Vector3 d = b - a;
            float length = d.Length();
            if (length > 1e-6f)
            {
                Vector3 dir = d / length;
                if (bNear)
                {
                    b = a + (dir * MathF.Max(0f, length - ContactClearance - Vector3.Distance(b, c)));
                }
                else if (aNear)
                {
                    a += dir * MathF.Min(length, ContactClearance + Vector3.Distance(a, c));
                }
            }
        }

        Vector3 segment = b - a;
        float half = segment.Length() * 0.5f;
        if (half < 1e-5f)
        {
            return false;
        }

        Quaternion rotation = Rotations.AlignUp(segment / (2f * half));
        return _bvh.Overlaps(new OrientedBox((a + b) * 0.5f, new Vector3(thickness, half, thickness), rotation));
    }

    private int IndexOf(RigLimb limb)
    {
        for (int l = 0; l < _model.Limbs.Count; l++)
        {
            if (ReferenceEquals(_model.Limbs[l], limb))
            {
                return l;
            }
        }

        throw new ArgumentException($"Limb '{limb.Name}' is not a limb of {_model.Name}.", nameof(limb));
    }
}
