using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Contacts;

/// <summary>The result of checking a root pose: its validity, estimated contacts and centroidal friction cone.</summary>
/// <param name="Pose">The pose checked.</param>
/// <param name="Validity">Valid, or why not.</param>
/// <param name="Contacts">Estimated contacts, one per touching limb (empty when the trunk collides).</param>
/// <param name="Cone">The centroidal cone (axis = normalised sum of contact normals, μ = least μ); meaningful only when valid.</param>
public sealed record PoseEvaluation(RootPose Pose, PoseValidity Validity, IReadOnlyList<Contact> Contacts, FrictionCone Cone)
{
    /// <summary>True when the pose can be a roadmap node.</summary>
    public bool IsValid => Validity == PoseValidity.Valid;
}
