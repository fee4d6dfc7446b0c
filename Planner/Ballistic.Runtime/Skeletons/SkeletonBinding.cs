using System.Numerics;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;

namespace Ballistic.Runtime.Skeletons;

/// <summary>
/// Maps a runtime rig's joints to a target skeleton's bones by name and converts the runtime's pose buffers
/// (<see cref="JumpWorld.GetRootPose"/>, <see cref="JumpWorld.GetJointRotations"/>) into the pose an engine skeleton
/// takes: each driven bone's full local rotation in its parent bone's space (Godot:
/// <c>Skeleton3D.SetBonePoseRotation</c>) and, for each bone with no driven bone above it, its local position
/// (<c>SetBonePosePosition</c>), so that the skeleton's bones are where the runtime's joints are in the world.
/// </summary>
/// <remarks>
/// <para>
/// <b>Matching.</b> Each joint takes, in order: the bone the options' rename map names; the bone with exactly its
/// name; the bone with the name Godot's importer gives it (':' and '/' → '_'); the only bone with the same name
/// ignoring case and separators. A bone serves one joint. Bones matched by no joint (helper nodes between bones,
/// twist bones, extra roots) stay at their rest. The root joint and every joint from it down each limb must be
/// matched, else there is no binding and the error names the first missing bone.
/// </para>
/// <para>
/// <b>Retargeting.</b> A bone keeps the world-space rotation its joint made since the rest pose:
/// G_b(t) = W_j(t) · W_j,rest⁻¹ · A · R_b, where W_j(t) is joint j's world rotation now, W_j,rest its rotation in
/// the rig's rest pose (every angle zero, root pose at the identity), R_b the bone's rest rotation in the skeleton's
/// space (rests composed from the root), and A the rest alignment taking the skeleton's space to the rig's rest
/// frame (<see cref="SkeletonBindingOptions.RestAlignment"/>, fitted by default). The local rotation written is
/// ρ_b = G_parent(t)⁻¹ · G_b(t), where G_parent is the parent bone's world rotation now (an undriven parent at its
/// rest under its own parent; a root bone's parent is the skeleton node's global rotation). When the skeleton is
/// the rig's own file the offsets W_j,rest⁻¹ · A · R_b are the identity and the bones follow the joints exactly;
/// when its rests differ (other bone axes, another rest pose) the bones still turn as the joints turn.
/// A bone with no driven bone above it is placed at its joint's world position; the others keep their rest
/// translations (their proportions).
/// </para>
/// <para>
/// Conversions allocate nothing but use buffers of the binding: call them from one thread at a time (the game
/// loop). Bind once per skeleton and character.
/// </para>
/// </remarks>
public sealed class SkeletonBinding
{
    private readonly Rig _rig;
    private readonly int[] _jointBone;
    private readonly int[] _boneJoint;
    private readonly JointMatch[] _matches;
    private readonly int[] _jointParent;
    private readonly Vector3[] _jointOffset;
    private readonly Vector3 _rootOffset;
    private readonly Quaternion[] _retarget;
    private readonly bool[] _positioned;
    private readonly int[] _drivenBones;
    private readonly int[] _positionedBones;
    private readonly int[] _boneParent;
    private readonly Vector3[] _restPosition;
    private readonly Quaternion[] _restRotation;
    private readonly float[] _restScale;
    private readonly string[] _unmatched;

    // Scratch, per conversion.
    private readonly Quaternion[] _local;
    private readonly Quaternion[] _jointRotation;
    private readonly Vector3[] _jointPosition;
    private readonly Quaternion[] _boneRotation;
    private readonly Vector3[] _bonePosition;
    private readonly float[] _boneScale;

    private SkeletonBinding(CharacterModel model, TargetSkeleton target, int[] jointBone, JointMatch[] matches, Quaternion alignment, Quaternion[] retarget)
    {
        Model = model;
        Target = target;
        _rig = model.Rig;
        int joints = _rig.Joints.Count;
        int bones = target.BoneCount;
        _jointBone = jointBone;
        _matches = matches;
        RestAlignment = alignment;
        _retarget = retarget;
        _boneJoint = new int[bones];
        Array.Fill(_boneJoint, -1);
        for (int j = 0; j < joints; j++)
        {
            if (jointBone[j] >= 0)
            {
                _boneJoint[jointBone[j]] = j;
            }
        }

        _jointParent = new int[joints];
        _jointOffset = new Vector3[joints];
        for (int j = 0; j < joints; j++)
        {
            _jointParent[j] = _rig.Joints[j].Parent;
            _jointOffset[j] = _rig.Joints[j].Offset;
        }

        _rootOffset = _rig.RootOffset + _rig.Joints[0].Offset;
        _boneParent = [.. target.Parents];
        _restPosition = new Vector3[bones];
        _restRotation = new Quaternion[bones];
        _restScale = new float[bones];
        for (int b = 0; b < bones; b++)
        {
            _restPosition[b] = target.Rests[b].Position;
            _restRotation[b] = target.Rests[b].Rotation;
            _restScale[b] = target.Rests[b].Scale.X;
        }

        // A driven bone with no driven bone above it is placed at its joint's world position.
        _positioned = new bool[bones];
        var driven = new List<int>();
        var positioned = new List<int>();
        for (int b = 0; b < bones; b++)
        {
            if (_boneJoint[b] < 0)
            {
                continue;
            }

            driven.Add(b);
            bool drivenAbove = false;
            for (int p = _boneParent[b]; p >= 0 && !drivenAbove; p = _boneParent[p])
            {
                drivenAbove = _boneJoint[p] >= 0;
            }

            if (!drivenAbove)
            {
                _positioned[b] = true;
                positioned.Add(b);
            }
        }

        _drivenBones = [.. driven];
        _positionedBones = [.. positioned];
        _unmatched = [.. Enumerable.Range(0, joints).Where(j => jointBone[j] < 0).Select(j => _rig.Joints[j].Name)];
        _local = new Quaternion[joints];
        _jointRotation = new Quaternion[joints];
        _jointPosition = new Vector3[joints];
        _boneRotation = new Quaternion[bones];
        _bonePosition = new Vector3[bones];
        _boneScale = new float[bones];
    }

    /// <summary>The character whose rig is bound.</summary>
    public CharacterModel Model { get; }

    /// <summary>The skeleton it is bound to.</summary>
    public TargetSkeleton Target { get; }

    /// <summary>For each runtime joint (rig order), the index of its bone in the target skeleton, or −1.</summary>
    public IReadOnlyList<int> JointBones => _jointBone;

    /// <summary>For each target bone, the runtime joint driving it, or −1 for a bone left at its rest.</summary>
    public IReadOnlyList<int> BoneJoints => _boneJoint;

    /// <summary>How each runtime joint found its bone.</summary>
    public IReadOnlyList<JointMatch> Matches => _matches;

    /// <summary>Names of the runtime joints no bone matched (none of them needed by the limbs); empty when every joint is bound.</summary>
    public IReadOnlyList<string> UnmatchedJoints => _unmatched;

    /// <summary>Indices of the driven bones, ascending: set their pose rotations (<c>SetBonePoseRotation</c>) every frame.</summary>
    public IReadOnlyList<int> DrivenBones => _drivenBones;

    /// <summary>
    /// Indices of the driven bones with no driven bone above them (the root bone, and extra root bones such as a tail
    /// hung from the armature), ascending: set their pose positions (<c>SetBonePosePosition</c>) every frame too.
    /// </summary>
    public IReadOnlyList<int> PositionedBones => _positionedBones;

    /// <summary>The rotation from the skeleton's space to the rig's rest frame in use (A in the class remarks).</summary>
    public Quaternion RestAlignment { get; }

    /// <summary>Number of target bones: the length the conversions' output spans need.</summary>
    public int BoneCount => _boneParent.Length;

    /// <summary>
    /// Binds <paramref name="model"/>'s rig to <paramref name="target"/>. Fails, with one line naming the bone, when
    /// the root joint or a joint of a limb chain has no bone, a rename names no bone, a bone above a driven bone has a
    /// non-uniform rest scale, or the rests cannot be aligned.
    /// </summary>
    /// <param name="model">The character the runtime animates (its rig and limbs).</param>
    /// <param name="target">The engine skeleton's bones.</param>
    /// <param name="options">Renames and alignment; defaults when <c>null</c>.</param>
    public static SkeletonBindingResult Create(CharacterModel model, TargetSkeleton target, SkeletonBindingOptions? options = null)
    {
        ArgumentNullException.ThrowIfNull(model);
        ArgumentNullException.ThrowIfNull(target);
        options ??= new SkeletonBindingOptions();
        Rig rig = model.Rig;
        int joints = rig.Joints.Count;
        int bones = target.BoneCount;
        int[] jointBone = new int[joints];
        Array.Fill(jointBone, -1);
        var matches = new JointMatch[joints];
        bool[] claimed = new bool[bones];
        var byName = new Dictionary<string, int>(StringComparer.Ordinal);
        for (int b = 0; b < bones; b++)
        {
            byName[target.Names[b]] = b;
        }

        void Claim(int joint, int bone, JointMatch how)
        {
            jointBone[joint] = bone;
            matches[joint] = how;
            claimed[bone] = true;
        }

        // 1. Renames, in the joints' order.
        foreach ((string jointName, string boneName) in options.Renames.OrderBy(r => rig.IndexOf(r.Key)).ThenBy(r => r.Key, StringComparer.Ordinal))
        {
            int joint = rig.IndexOf(jointName);
            if (joint < 0)
            {
                return Fail($"The rename map names joint '{jointName}', which is not a joint of '{model.Name}'.");
            }

            if (!byName.TryGetValue(boneName ?? string.Empty, out int bone))
            {
                return Fail($"The rename map sends joint '{jointName}' to bone '{boneName}', which is not a bone of the skeleton.");
            }

            if (claimed[bone])
            {
                return Fail($"The rename map sends two joints to bone '{boneName}'.");
            }

            Claim(joint, bone, JointMatch.Renamed);
        }

        // 2. Exact names, then 3. the names Godot's importer gives them.
        foreach (JointMatch how in new[] { JointMatch.Exact, JointMatch.Sanitized })
        {
            for (int j = 0; j < joints; j++)
            {
                string name = how == JointMatch.Exact ? rig.Joints[j].Name : GodotBoneNames.Sanitize(rig.Joints[j].Name);
                if (jointBone[j] < 0 && byName.TryGetValue(name, out int bone) && !claimed[bone])
                {
                    Claim(j, bone, how);
                }
            }
        }

        // 4. Case and separators ignored, when one free bone and one unmatched joint share the key.
        if (options.MatchLoosely)
        {
            var boneKeys = new Dictionary<string, int>(StringComparer.Ordinal);
            for (int b = 0; b < bones; b++)
            {
                if (!claimed[b])
                {
                    string key = GodotBoneNames.LooseKey(target.Names[b]);
                    boneKeys[key] = boneKeys.ContainsKey(key) ? -1 : b;
                }
            }

            var jointKeys = new Dictionary<string, int>(StringComparer.Ordinal);
            for (int j = 0; j < joints; j++)
            {
                if (jointBone[j] < 0)
                {
                    string key = GodotBoneNames.LooseKey(rig.Joints[j].Name);
                    jointKeys[key] = jointKeys.ContainsKey(key) ? -1 : j;
                }
            }

            foreach ((string key, int joint) in jointKeys)
            {
                if (joint >= 0 && key.Length > 0 && boneKeys.TryGetValue(key, out int bone) && bone >= 0)
                {
                    Claim(joint, bone, JointMatch.Loose);
                }
            }
        }

        // The joints the animation cannot do without: the root and every joint from it down each limb.
        var required = new List<(int Joint, string Why)> { (0, $"the root joint of '{model.Name}'") };
        foreach (RigLimb limb in model.Limbs)
        {
            var chain = new List<int>();
            for (int j = limb.EffectorJoint; j > 0; j = rig.Joints[j].Parent)
            {
                chain.Add(j);
            }

            chain.Reverse();
            foreach (int j in chain)
            {
                string why = j == limb.RootJoint ? $"the root of limb '{limb.Name}'"
                    : j == limb.EffectorJoint ? $"the effector of limb '{limb.Name}'"
                    : rig.IsAncestor(limb.RootJoint, j) ? $"on limb '{limb.Name}'"
                    : $"above limb '{limb.Name}'";
                required.Add((j, why));
            }
        }

        var missing = new List<(int Joint, string Why)>();
        foreach ((int joint, string why) in required)
        {
            if (jointBone[joint] < 0 && !missing.Any(m => m.Joint == joint))
            {
                missing.Add((joint, why));
            }
        }

        if (missing.Count > 0)
        {
            (int first, string why) = missing[0];
            string more = missing.Count > 1 ? $" (nor for {string.Join(", ", missing.Skip(1).Select(m => $"'{rig.Joints[m.Joint].Name}'"))})" : "";
            string message = $"The skeleton has no bone for joint '{rig.Joints[first].Name}', {why}{more}; rename the bones or map them in SkeletonBindingOptions.Renames.";
            return new SkeletonBindingResult(null, message, [.. missing.Select(m => rig.Joints[m.Joint].Name)]);
        }

        // Bones above a driven bone must scale uniformly, or rotations do not compose.
        bool[] above = new bool[bones];
        for (int b = bones - 1; b >= 0; b--)
        {
            int parent = target.Parents[b];
            if (parent >= 0 && (above[b] || Array.IndexOf(jointBone, b) >= 0))
            {
                above[parent] = true;
            }
        }

        for (int b = 0; b < bones; b++)
        {
            if (above[b] && !target.Rests[b].HasUniformScale)
            {
                Vector3 s = target.Rests[b].Scale;
                return Fail($"Bone '{target.Names[b]}' has a non-uniform rest scale ({s.X:G4}, {s.Y:G4}, {s.Z:G4}) above driven bones; apply the scale in the model before importing.");
            }
        }

        // Rests: the rig's (every angle zero, root pose at the identity) and the skeleton's, in its own space.
        var restPositions = new Vector3[joints];
        var restRotations = new Quaternion[joints];
        rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), new float[rig.DofCount], restPositions, restRotations);
        (Vector3[] bonePositions, Quaternion[] boneRotations, _) = target.RestInSkeleton();

        Quaternion alignment;
        if (options.RestAlignment is Quaternion given)
        {
            if (!(given.LengthSquared() > 1e-12f) || !float.IsFinite(given.LengthSquared()))
            {
                return Fail("SkeletonBindingOptions.RestAlignment must be a finite, non-zero rotation.");
            }

            alignment = Quaternion.Normalize(given);
        }
        else
        {
            var from = new List<Vector3>();
            var to = new List<Vector3>();
            int rootBone = jointBone[0];
            for (int j = 1; j < joints; j++)
            {
                if (jointBone[j] >= 0)
                {
                    from.Add(bonePositions[jointBone[j]] - bonePositions[rootBone]);
                    to.Add(restPositions[j] - restPositions[0]);
                }
            }

            if (RestAlignmentFit.Fit(from.ToArray(), to.ToArray()) is not Quaternion fitted)
            {
                return Fail("The skeleton's rest cannot be aligned with the rig's: the matched bones lie on one line; set SkeletonBindingOptions.RestAlignment.");
            }

            alignment = fitted;
        }

        var retarget = new Quaternion[joints];
        for (int j = 0; j < joints; j++)
        {
            retarget[j] = jointBone[j] >= 0
                ? Quaternion.Normalize(Quaternion.Conjugate(restRotations[j]) * alignment * boneRotations[jointBone[j]])
                : Quaternion.Identity;
        }

        return new SkeletonBindingResult(new SkeletonBinding(model, target, jointBone, matches, alignment, retarget), null, []);

        static SkeletonBindingResult Fail(string message) => new(null, message, []);
    }

    /// <summary>
    /// Converts one agent's pose this tick (<see cref="JumpWorld.GetRootPose"/>, <see cref="JumpWorld.GetJointRotations"/>)
    /// into target bone poses, without allocating. See <see cref="Convert(in RootPose, ReadOnlySpan{Quaternion}, in BoneTransform, Span{Quaternion}, Span{Vector3})"/>.
    /// Fails, writing nothing, for an unknown agent or an agent of another character.
    /// </summary>
    public RuntimeResult Convert(JumpWorld world, AgentHandle agent, in BoneTransform skeletonGlobal, Span<Quaternion> boneRotations, Span<Vector3> bonePositions)
    {
        ArgumentNullException.ThrowIfNull(world);
        if (!world.IsValid(agent))
        {
            return new RuntimeResult(RuntimeStatus.UnknownAgent, $"{agent} is not an agent of this world");
        }

        if (world.GetLifecycle(agent) != AgentLifecycle.Active || world.GetKindCharacter(world.GetKind(agent)) is not { } kind)
        {
            return new RuntimeResult(RuntimeStatus.InvalidPosition, $"{agent} is not on a roadmap: {world.GetAgentReason(agent)}");
        }

        if (!ReferenceEquals(kind.Model.Rig, _rig))
        {
            return new RuntimeResult(RuntimeStatus.Mismatch, $"{agent} is a '{kind.Name}'; this binding is for '{Model.Name}'");
        }

        Convert(world.GetRootPose(agent), world.GetJointRotations(agent), skeletonGlobal, boneRotations, bonePositions);
        return RuntimeResult.Success;
    }

    /// <summary>
    /// Converts a runtime pose into target bone poses, without allocating. Every bone gets a local rotation in its
    /// parent bone's space (its rest rotation when undriven) and a local position in its parent's space (its rest
    /// translation unless it is one of <see cref="PositionedBones"/>); set <see cref="DrivenBones"/>' rotations and
    /// <see cref="PositionedBones"/>' positions on the engine skeleton.
    /// </summary>
    /// <param name="root">The root pose (trunk centre, world metres, and rotation).</param>
    /// <param name="jointRotations">Each joint's rotation local to its parent joint (the root joint's to the root pose), rig order.</param>
    /// <param name="skeletonGlobal">The skeleton node's world transform now (Godot: <c>Skeleton3D.GlobalTransform</c>), with a uniform scale.</param>
    /// <param name="boneRotations">Receives each bone's local pose rotation, bone order (length ≥ <see cref="BoneCount"/>).</param>
    /// <param name="bonePositions">Receives each bone's local pose position in its parent's space, the skeleton's units (length ≥ <see cref="BoneCount"/>).</param>
    /// <exception cref="ArgumentException">A span has the wrong length, or the skeleton's transform is not finite with a uniform scale.</exception>
    public void Convert(in RootPose root, ReadOnlySpan<Quaternion> jointRotations, in BoneTransform skeletonGlobal, Span<Quaternion> boneRotations, Span<Vector3> bonePositions)
    {
        int joints = _jointParent.Length;
        if (jointRotations.Length != joints)
        {
            throw new ArgumentException($"The pose has {jointRotations.Length} joint rotations; '{Model.Name}' has {joints} joints.", nameof(jointRotations));
        }

        CheckOutputs(skeletonGlobal, boneRotations, bonePositions);
        for (int j = 0; j < joints; j++)
        {
            int parent = _jointParent[j];
            if (parent < 0)
            {
                _jointRotation[j] = Quaternion.Normalize(root.Rotation * jointRotations[j]);
                _jointPosition[j] = root.ToWorld(_rootOffset);
            }
            else
            {
                _jointPosition[j] = _jointPosition[parent] + Vector3.Transform(_jointOffset[j], _jointRotation[parent]);
                _jointRotation[j] = Quaternion.Normalize(_jointRotation[parent] * jointRotations[j]);
            }
        }

        WriteBones(skeletonGlobal, boneRotations, bonePositions);
    }

    /// <summary>
    /// Converts a pose given as joint angles (one per degree of freedom, radians, <see cref="Rig.Dofs"/> order), as
    /// <see cref="Planner.Animation.JumpAnimation.Sample(float, Span{float})"/> gives them, without allocating.
    /// </summary>
    /// <exception cref="ArgumentException">A span has the wrong length, or the skeleton's transform is not finite with a uniform scale.</exception>
    public void ConvertAngles(in RootPose root, ReadOnlySpan<float> angles, in BoneTransform skeletonGlobal, Span<Quaternion> boneRotations, Span<Vector3> bonePositions)
    {
        if (angles.Length != _rig.DofCount)
        {
            throw new ArgumentException($"The pose has {angles.Length} angles; '{Model.Name}' has {_rig.DofCount} degrees of freedom.", nameof(angles));
        }

        for (int j = 0; j < _local.Length; j++)
        {
            _local[j] = _rig.LocalRotation(j, angles);
        }

        Convert(root, _local, skeletonGlobal, boneRotations, bonePositions);
    }

    private void CheckOutputs(in BoneTransform skeletonGlobal, Span<Quaternion> boneRotations, Span<Vector3> bonePositions)
    {
        if (boneRotations.Length < BoneCount || bonePositions.Length < BoneCount)
        {
            throw new ArgumentException($"The outputs need room for the skeleton's {BoneCount} bones ({boneRotations.Length} rotations, {bonePositions.Length} positions given).");
        }

        if (!skeletonGlobal.IsFinite || !skeletonGlobal.HasUniformScale)
        {
            Vector3 s = skeletonGlobal.Scale;
            throw new ArgumentException($"The skeleton's global transform must be finite with a uniform positive scale (scale ({s.X:G4}, {s.Y:G4}, {s.Z:G4})).", nameof(skeletonGlobal));
        }
    }

    /// <summary>Target bones from the joints' world rotations and positions in the scratch buffers, parents first.</summary>
    private void WriteBones(in BoneTransform skeletonGlobal, Span<Quaternion> boneRotations, Span<Vector3> bonePositions)
    {
        Quaternion skeletonRotation = Quaternion.Normalize(skeletonGlobal.Rotation);
        float skeletonScale = skeletonGlobal.Scale.X;
        for (int b = 0; b < _boneParent.Length; b++)
        {
            int parent = _boneParent[b];
            Quaternion parentRotation = parent < 0 ? skeletonRotation : _boneRotation[parent];
            Vector3 parentPosition = parent < 0 ? skeletonGlobal.Position : _bonePosition[parent];
            float parentScale = parent < 0 ? skeletonScale : _boneScale[parent];
            int joint = _boneJoint[b];
            Quaternion world;
            Quaternion local;
            if (joint >= 0)
            {
                world = Quaternion.Normalize(_jointRotation[joint] * _retarget[joint]);
                local = Quaternion.Normalize(Quaternion.Conjugate(parentRotation) * world);
            }
            else
            {
                local = _restRotation[b];
                world = Quaternion.Normalize(parentRotation * local);
            }

            Vector3 position;
            Vector3 localPosition;
            if (_positioned[b])
            {
                position = _jointPosition[joint];
                localPosition = Vector3.Transform(position - parentPosition, Quaternion.Conjugate(parentRotation)) / parentScale;
            }
            else
            {
                localPosition = _restPosition[b];
                position = parentPosition + Vector3.Transform(localPosition * parentScale, parentRotation);
            }

            _boneRotation[b] = world;
            _bonePosition[b] = position;
            _boneScale[b] = parentScale * _restScale[b];
            boneRotations[b] = local;
            bonePositions[b] = localPosition;
        }
    }
}
