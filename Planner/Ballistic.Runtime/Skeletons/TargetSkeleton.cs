using System.Numerics;

namespace Ballistic.Runtime.Skeletons;

/// <summary>
/// The skeleton a runtime rig is bound to, as an engine would describe it: bone names in index order, each bone's
/// parent index, and each bone's rest (translation, rotation and scale relative to its parent bone, or to the
/// skeleton node for a root bone). Godot: <c>Skeleton3D.GetBoneName(i)</c>, <c>GetBoneParent(i)</c> and
/// <c>GetBoneRest(i)</c> for i below <c>GetBoneCount()</c>. Immutable.
/// </summary>
public sealed class TargetSkeleton
{
    private readonly string[] _names;
    private readonly int[] _parents;
    private readonly BoneTransform[] _rests;

    /// <summary>Creates a skeleton description, checking it.</summary>
    /// <param name="names">Bone names in index order: non-empty, unique, without ':' or '/' (Godot refuses those in bone names).</param>
    /// <param name="parents">Parent index of each bone, −1 for a root bone; every parent comes before its child (as Godot's <c>SetBoneParent</c> requires).</param>
    /// <param name="rests">Rest of each bone relative to its parent bone (the skeleton node for a root bone), units of the skeleton's space.</param>
    /// <exception cref="ArgumentException">The lists differ in length, or a bone's name, parent or rest is unusable (the message names the bone).</exception>
    public TargetSkeleton(IReadOnlyList<string> names, IReadOnlyList<int> parents, IReadOnlyList<BoneTransform> rests)
    {
        ArgumentNullException.ThrowIfNull(names);
        ArgumentNullException.ThrowIfNull(parents);
        ArgumentNullException.ThrowIfNull(rests);
        if (names.Count == 0 || parents.Count != names.Count || rests.Count != names.Count)
        {
            throw new ArgumentException($"A target skeleton needs at least one bone and as many parents and rests as names ({names.Count} names, {parents.Count} parents, {rests.Count} rests).");
        }

        var seen = new Dictionary<string, int>(StringComparer.Ordinal);
        _names = new string[names.Count];
        _parents = new int[names.Count];
        _rests = new BoneTransform[names.Count];
        for (int b = 0; b < names.Count; b++)
        {
            string name = names[b];
            if (string.IsNullOrEmpty(name) || name.Contains(':', StringComparison.Ordinal) || name.Contains('/', StringComparison.Ordinal))
            {
                throw new ArgumentException($"Bone {b} is called '{name}': a bone name must be non-empty, without ':' or '/'.");
            }

            if (!seen.TryAdd(name, b))
            {
                throw new ArgumentException($"Bones {seen[name]} and {b} are both called '{name}'; bone names must be unique.");
            }

            int parent = parents[b];
            if (parent < -1 || parent >= b)
            {
                throw new ArgumentException($"Bone {b} '{name}' names parent {parent}; a parent must be −1 or a bone before it.");
            }

            BoneTransform rest = rests[b];
            if (!rest.IsFinite)
            {
                throw new ArgumentException($"Bone {b} '{name}' has a rest that is not finite or has a zero rotation.");
            }

            _names[b] = name;
            _parents[b] = parent;
            _rests[b] = rest with { Rotation = Quaternion.Normalize(rest.Rotation) };
        }
    }

    /// <summary>Number of bones.</summary>
    public int BoneCount => _names.Length;

    /// <summary>Bone names in index order.</summary>
    public IReadOnlyList<string> Names => _names;

    /// <summary>Parent of each bone (−1 for a root bone).</summary>
    public IReadOnlyList<int> Parents => _parents;

    /// <summary>Rest of each bone relative to its parent (rotations normalised).</summary>
    public IReadOnlyList<BoneTransform> Rests => _rests;

    /// <summary>Index of the bone called exactly <paramref name="name"/>, or −1.</summary>
    public int IndexOf(string name) => Array.IndexOf(_names, name);

    /// <summary>
    /// Each bone's rest in the skeleton's space (the rests composed from the root down): position, rotation and the
    /// product of the uniform scales above and at the bone (the X scale is used).
    /// </summary>
    internal (Vector3[] Positions, Quaternion[] Rotations, float[] Scales) RestInSkeleton()
    {
        int n = _names.Length;
        var positions = new Vector3[n];
        var rotations = new Quaternion[n];
        var scales = new float[n];
        for (int b = 0; b < n; b++)
        {
            BoneTransform rest = _rests[b];
            int p = _parents[b];
            if (p < 0)
            {
                positions[b] = rest.Position;
                rotations[b] = rest.Rotation;
                scales[b] = rest.Scale.X;
            }
            else
            {
                positions[b] = positions[p] + Vector3.Transform(rest.Position * scales[p], rotations[p]);
                rotations[b] = Quaternion.Normalize(rotations[p] * rest.Rotation);
                scales[b] = scales[p] * rest.Scale.X;
            }
        }

        return (positions, rotations, scales);
    }
}
