using System.Numerics;
using Ballistic.Planner.Characters;

namespace Ballistic.Planner.Rigs;

/// <summary>
/// A limb of a rig: the chain of joints from <see cref="RootJoint"/> (e.g. the hip) to <see cref="EffectorJoint"/>
/// (e.g. the ankle), the contact point on the effector and the effector's contact normal (sole or palm), both in
/// the effector joint's frame, and the surfaces the limb may touch.
/// </summary>
public sealed class RigLimb
{
    /// <summary>Creates a limb, checking it against the rig.</summary>
    /// <exception cref="RigException">A joint is missing, the root is not an ancestor of the effector, or the chain has no degree of freedom.</exception>
    public RigLimb(Rig rig, string name, LimbKind kind, string rootJoint, string effectorJoint, Vector3 effectorOffset, Vector3 contactNormal, NormalFilter filter)
    {
        ArgumentNullException.ThrowIfNull(rig);
        int root = rig.IndexOf(rootJoint);
        int effector = rig.IndexOf(effectorJoint);
        if (root < 0)
        {
            throw new RigException($"Limb '{name}': root bone '{rootJoint}' is not in the rig.");
        }

        if (effector < 0)
        {
            throw new RigException($"Limb '{name}': effector bone '{effectorJoint}' is not in the rig.");
        }

        if (!rig.IsAncestor(root, effector))
        {
            throw new RigException($"Limb '{name}': '{rootJoint}' is not an ancestor of '{effectorJoint}'.");
        }

        var chain = new List<int>();
        for (int j = effector; ; j = rig.Joints[j].Parent)
        {
            chain.Add(j);
            if (j == root)
            {
                break;
            }
        }

        chain.Reverse();
        var dofs = new List<int>();
        foreach (int j in chain)
        {
            for (int d = rig.FirstDof(j); d < rig.FirstDof(j) + rig.DofsOf(j); d++)
            {
                dofs.Add(d);
            }
        }

        if (dofs.Count == 0)
        {
            throw new RigException($"Limb '{name}' has no joints that move between '{rootJoint}' and '{effectorJoint}'.");
        }

        if (!(contactNormal.LengthSquared() > 0f))
        {
            throw new RigException($"Limb '{name}': the contact normal must be non-zero.");
        }

        Name = name;
        Kind = kind;
        RootJoint = root;
        EffectorJoint = effector;
        EffectorOffset = effectorOffset;
        ContactNormal = Vector3.Normalize(contactNormal);
        Filter = filter;
        _chain = [.. chain];
        Chain = Array.AsReadOnly(_chain);
        var lineage = new List<int>();
        for (int j = rig.Joints[root].Parent; j >= 0; j = rig.Joints[j].Parent)
        {
            lineage.Add(j);
        }

        lineage.Reverse();
        Lineage = [.. lineage, .. chain];
        _chainDofs = [.. dofs];
        ChainDofs = Array.AsReadOnly(_chainDofs);
        Ball = kind == LimbKind.Foot && FindBall(rig, effector, effectorOffset, ContactNormal) is Vector3 ball ? new RigLimb(this, ball) : null;
    }

    /// <summary>The same limb touching at <paramref name="ball"/> (effector frame) instead of its contact point.</summary>
    private RigLimb(RigLimb limb, Vector3 ball)
    {
        Name = limb.Name;
        Kind = limb.Kind;
        RootJoint = limb.RootJoint;
        EffectorJoint = limb.EffectorJoint;
        EffectorOffset = ball;
        ContactNormal = limb.ContactNormal;
        Filter = limb.Filter;
        _chain = limb._chain;
        Chain = limb.Chain;
        Lineage = limb.Lineage;
        _chainDofs = limb._chainDofs;
        ChainDofs = limb.ChainDofs;
    }

    /// <summary>Least distance (metres) from a foot's contact point to its ball for the foot to roll onto it.</summary>
    private const float LeastBall = 0.02f;

    /// <summary>
    /// A foot's ball in its effector joint's frame: of the joints hanging from the effector (a toe), the one farthest
    /// along the sole from the contact point, seen on the sole's plane; <c>null</c> when none is <see cref="LeastBall"/> away.
    /// </summary>
    private static Vector3? FindBall(Rig rig, int effector, Vector3 offset, Vector3 normal)
    {
        Vector3? best = null;
        float far = LeastBall;
        foreach (Joint joint in rig.Joints)
        {
            if (joint.Parent != effector)
            {
                continue;
            }

            Vector3 onSole = joint.Offset - (Vector3.Dot(joint.Offset - offset, normal) * normal);
            float d = Vector3.Distance(onSole, offset);
            if (d > far && float.IsFinite(d))
            {
                (best, far) = (onSole, d);
            }
        }

        return best;
    }

    /// <summary>
    /// The joints whose poses place the chain: <see cref="RootJoint"/>'s ancestors from the rig's first joint, then
    /// <see cref="Chain"/>, each after its parent (what the IK solves, instead of the whole rig).
    /// </summary>
    internal int[] Lineage { get; }

    /// <summary>Limb name, e.g. <c>left_foot</c>.</summary>
    public string Name { get; }

    /// <summary>Foot or hand.</summary>
    public LimbKind Kind { get; }

    /// <summary>Index of the first joint of the chain (its parent does not move with the limb).</summary>
    public int RootJoint { get; }

    /// <summary>Index of the effector joint.</summary>
    public int EffectorJoint { get; }

    /// <summary>The contact point in the effector joint's frame, metres.</summary>
    public Vector3 EffectorOffset { get; }

    /// <summary>Unit outward normal of the effector's contact face (sole, palm) in the effector joint's frame.</summary>
    public Vector3 ContactNormal { get; }

    /// <summary>Surfaces the limb may touch.</summary>
    public NormalFilter Filter { get; }

    /// <summary>Joint indices from root to effector.</summary>
    public IReadOnlyList<int> Chain { get; }

    /// <summary>Indices of the degrees of freedom that move the effector.</summary>
    public IReadOnlyList<int> ChainDofs { get; }

    /// <summary><see cref="Chain"/> as a span: walked by the IK's inner loop without an enumerator.</summary>
    internal ReadOnlySpan<int> ChainSpan => _chain;

    /// <summary><see cref="ChainDofs"/> as a span: walked by the animation's inner loops without an enumerator.</summary>
    internal ReadOnlySpan<int> ChainDofSpan => _chainDofs;

    private readonly int[] _chainDofs;

    private readonly int[] _chain;

    /// <summary>
    /// A foot touching at its ball instead of its contact point (the same chain, its effector offset the ball: the
    /// effector's child joint, a toe, seen on the sole), for a foot rolled heel up; <c>null</c> for hands and for feet
    /// with no toe bone.
    /// </summary>
    public RigLimb? Ball { get; }

    /// <summary>The contact point in world space given the joints' world positions and rotations.</summary>
    public Vector3 EffectorPosition(ReadOnlySpan<Vector3> positions, ReadOnlySpan<Quaternion> rotations) =>
        positions[EffectorJoint] + Vector3.Transform(EffectorOffset, rotations[EffectorJoint]);

    /// <summary>The contact normal in world space given the joints' world rotations.</summary>
    public Vector3 EffectorNormal(ReadOnlySpan<Quaternion> rotations) => Vector3.Transform(ContactNormal, rotations[EffectorJoint]);
}
