using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Rigs;

/// <summary>
/// A whole character: its rig, its limbs, its reference poses and the bone radii used for collision and for the
/// exported mesh. The reduced model the planner uses is derived from it by sampling its joints (<see cref="ReducedModelBuilder"/>).
/// </summary>
public sealed class CharacterModel
{
    private readonly CharacterSource? _source;

    /// <summary>Creates a character model, checking that every reference pose fits the rig.</summary>
    /// <exception cref="RigException">A pose has the wrong number of angles or leaves a joint's limits, or a radius is missing.</exception>
    public CharacterModel(string name, Rig rig, IReadOnlyList<RigLimb> limbs, IReadOnlyList<int> trunkJoints, IReadOnlyList<float> boneRadii, float[] contactPose, float[] flexionPose, float[] extendingPose)
    {
        ArgumentNullException.ThrowIfNull(rig);
        ArgumentNullException.ThrowIfNull(limbs);
        ArgumentNullException.ThrowIfNull(trunkJoints);
        ArgumentNullException.ThrowIfNull(boneRadii);
        if (limbs.Count == 0)
        {
            throw new RigException($"Character '{name}' has no limbs.");
        }

        if (boneRadii.Count != rig.Joints.Count)
        {
            throw new RigException($"Character '{name}': {boneRadii.Count} bone radii for {rig.Joints.Count} joints.");
        }

        foreach ((string poseName, float[] pose) in new[] { ("contact", contactPose), ("flexion", flexionPose), ("extending", extendingPose) })
        {
            if (pose is null || pose.Length != rig.DofCount || !rig.WithinLimits(pose))
            {
                throw new RigException($"Character '{name}': the {poseName} pose must give {rig.DofCount} angles within the joint limits.");
            }
        }

        Name = name;
        Rig = rig;
        Limbs = [.. limbs];
        TrunkJoints = [.. trunkJoints];
        BoneRadii = [.. boneRadii];
        ContactPose = contactPose;
        FlexionPose = flexionPose;
        ExtendingPose = extendingPose;
    }

    /// <summary>Character name; the reduced model and presets use the same.</summary>
    public string Name { get; }

    /// <summary>The kinematic skeleton.</summary>
    public Rig Rig { get; }

    /// <summary>The limbs, in the order of the reduced model's limbs.</summary>
    public IReadOnlyList<RigLimb> Limbs { get; }

    /// <summary>Joints that belong to the trunk (bounded by W0) rather than to a limb.</summary>
    public IReadOnlyList<int> TrunkJoints { get; }

    /// <summary>Radius (metres) of the bone from each joint's parent to the joint (the root's is its own).</summary>
    public IReadOnlyList<float> BoneRadii { get; }

    /// <summary>The pose limbs take when in contact (standing, ready).</summary>
    public float[] ContactPose { get; }

    /// <summary>
    /// The pose a limb with no contact takes while the body stands (<see cref="ContactPose"/> by default): a rig
    /// loaded from a spec that gives no contact pose and modelled with its arms held out (a T- or A-pose, as Mixamo and
    /// most humanoid exports are) has its free hands hanging at its sides here instead (<see cref="HangingArms"/>).
    /// </summary>
    /// <exception cref="RigException">The pose has the wrong number of angles or leaves a joint's limits.</exception>
    internal float[] HangingPose
    {
        get => _hanging ?? ContactPose;
        init => _hanging = value.Length == Rig.DofCount && Rig.WithinLimits(value)
            ? value
            : throw new RigException($"Character '{Name}': the hanging pose must give {Rig.DofCount} angles within the joint limits.");
    }

    private readonly float[]? _hanging;

    /// <summary>
    /// <see cref="HangingPose"/> with every hand hanging close to straight down at its side (<see cref="HangingArms"/>):
    /// where a free hand's own hanging pose would touch the level (a dune's flank beside the body), it is tried before
    /// the flexion pose, so that the arm stays down.
    /// </summary>
    internal float[] LoweredPose => _lowered ??= HangingArms.Derive(Rig, Limbs, HangingPose, every: true);

    private float[]? _lowered;

    /// <summary>The crouched pose before takeoff and after landing.</summary>
    public float[] FlexionPose { get; }

    /// <summary>The stretched pose at the apex of a jump.</summary>
    public float[] ExtendingPose { get; }

    /// <summary>
    /// The rigged glTF this character was loaded from, with each joint's node, or <c>null</c> for a character built
    /// in code. When set, the animated GLB carries the file's own meshes and skin rather than bone boxes.
    /// </summary>
    /// <exception cref="RigException">The source maps a different number of joints than the rig has.</exception>
    internal CharacterSource? Source
    {
        get => _source;
        init => _source = value is null || value.JointNodes.Count == Rig.Joints.Count
            ? value
            : throw new RigException($"Character '{Name}': the source maps {value.JointNodes.Count} joints, but the rig has {Rig.Joints.Count}.");
    }

    /// <summary>
    /// Per limb, its standing leg (metres): a foot's root joint's greatest height above its contact point with every
    /// angle at rest (a rig modelled standing) or in the contact pose (a rig modelled with its legs spread flat, an
    /// insect's, stands only in its contact pose); 0 for a limb that is not a foot.
    /// </summary>
    internal float[] LegLengths()
    {
        var positions = new Vector3[Rig.Joints.Count];
        var rotations = new Quaternion[Rig.Joints.Count];
        float[] legs = new float[Limbs.Count];
        foreach (float[] pose in new[] { Rig.Neutral(), ContactPose })
        {
            Rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), pose, positions, rotations);
            for (int l = 0; l < Limbs.Count; l++)
            {
                RigLimb limb = Limbs[l];
                if (limb.Kind == LimbKind.Foot)
                {
                    legs[l] = MathF.Max(legs[l], positions[limb.RootJoint].Y - limb.EffectorPosition(positions, rotations).Y);
                }
            }
        }

        return legs;
    }

    /// <summary>
    /// How far (metres, along the trunk's forward axis) the foremost foot stands ahead of the trunk's centre and the
    /// hindmost behind it in the contact pose; 0 for either where no foot stands on that side.
    /// </summary>
    internal (float Ahead, float Behind) FeetAlongTrunk()
    {
        Vector3[] effectors = ContactPoseEffectors();
        float ahead = 0f;
        float behind = 0f;
        for (int l = 0; l < Limbs.Count; l++)
        {
            if (Limbs[l].Kind == LimbKind.Foot)
            {
                (ahead, behind) = (MathF.Max(ahead, effectors[l].Z), MathF.Max(behind, -effectors[l].Z));
            }
        }

        return (ahead, behind);
    }

    /// <summary>
    /// How far (metres, along the trunk's left axis) the leftmost foot stands left of the trunk's centre and the
    /// rightmost right of it in the contact pose (0 for either where no foot stands on that side), and the most any
    /// foot stands out sideways of its own hip, as a share of its own leg (<see cref="LegLengths"/>).
    /// </summary>
    internal (float Left, float Right, float Sprawl) FeetAcrossTrunk()
    {
        float[] legs = LegLengths();
        var positions = new Vector3[Rig.Joints.Count];
        var rotations = new Quaternion[Rig.Joints.Count];
        Rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), ContactPose, positions, rotations);
        float left = 0f;
        float right = 0f;
        float sprawl = 0f;
        for (int l = 0; l < Limbs.Count; l++)
        {
            if (Limbs[l].Kind != LimbKind.Foot)
            {
                continue;
            }

            float x = Limbs[l].EffectorPosition(positions, rotations).X;
            (left, right) = (MathF.Max(left, x), MathF.Max(right, -x));
            if (legs[l] > 0f)
            {
                sprawl = MathF.Max(sprawl, MathF.Abs(x - positions[Limbs[l].RootJoint].X) / legs[l]);
            }
        }

        return (left, right, sprawl);
    }

    /// <summary>
    /// The most a turn of the trunk about its up axis may be (radians, or radians per second), at most
    /// <paramref name="most"/>, so that no foot where the contact pose holds it is carried sideways under the trunk by
    /// more than <paramref name="share"/> of its own leg (<see cref="LegLengths"/>; per second for a rate): a trunk
    /// turning by θ moves a foot standing d ahead of (or behind) its centre sideways by about d·θ.
    /// </summary>
    internal float TurnLimit(float share, float most)
    {
        Vector3[] effectors = ContactPoseEffectors();
        float[] legs = LegLengths();
        float limit = most;
        for (int l = 0; l < Limbs.Count; l++)
        {
            float ahead = MathF.Abs(effectors[l].Z);
            if (legs[l] > 0f && ahead * most > share * legs[l])
            {
                limit = MathF.Min(limit, share * legs[l] / ahead);
            }
        }

        return limit;
    }

    /// <summary>Each limb's contact point (metres, trunk frame: the root at the origin, unturned) in the contact pose.</summary>
    private Vector3[] ContactPoseEffectors()
    {
        var positions = new Vector3[Rig.Joints.Count];
        var rotations = new Quaternion[Rig.Joints.Count];
        Rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), ContactPose, positions, rotations);
        return [.. Limbs.Select(l => l.EffectorPosition(positions, rotations))];
    }
}
