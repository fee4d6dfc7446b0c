using System.Numerics;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Roadmaps;

/// <summary>A node of the roadmap: a valid root pose with its estimated contacts and centroidal friction cone.</summary>
/// <param name="Id">Index of the node in its roadmap.</param>
/// <param name="Pose">Root pose (trunk centre and orientation, world space).</param>
/// <param name="Cone">Centroidal friction cone at the pose.</param>
/// <param name="Contacts">Estimated limb contacts.</param>
public sealed record RoadmapNode(int Id, RootPose Pose, FrictionCone Cone, IReadOnlyList<Contact> Contacts)
{
    /// <summary>
    /// The mean of the stance's contact positions (its trunk centre when it has none), world metres: the point a
    /// game reads as where the character stands (<see cref="Roadmap.ContactCentres"/> for a roadmap's nodes).
    /// </summary>
    public Vector3 ContactCentre => Contact.Centre(Contacts, Pose.Position);
}
