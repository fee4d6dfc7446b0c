using System.Numerics;
using Ballistic.Planner.Contacts;

namespace Ballistic.Planner.Sampling;

/// <summary>
/// Where a requested start or goal point put the character: the valid pose chosen (when one lies within the
/// tolerance), the centre of its contacts and how far that centre is from the requested point.
/// </summary>
/// <param name="Requested">The requested point, world metres.</param>
/// <param name="Pose">The valid pose placed, or <c>null</c> when none lies within the tolerance.</param>
/// <param name="ContactCentre">Centre of the pose's contacts, world metres (the requested point when there is no pose).</param>
/// <param name="Across">Horizontal distance from the requested point to the contact centre, metres.</param>
/// <param name="UpDown">Vertical distance from the requested point to the contact centre, metres.</param>
/// <param name="NearestValid">
/// When no pose was placed: the distance (metres) from the requested point to the contact centre of the nearest
/// valid pose found beyond the tolerance, or <c>null</c> when the search found none at all.
/// </param>
internal sealed record EndpointPlacement(Vector3 Requested, PoseEvaluation? Pose, Vector3 ContactCentre, float Across, float UpDown, float? NearestValid)
{
    /// <summary>True when a valid pose was placed within the tolerance.</summary>
    public bool Placed => Pose is not null;

    /// <summary>
    /// Why nothing was placed, as a sentence fragment naming <paramref name="what"/> (start or goal), or <c>null</c>
    /// when a pose was placed.
    /// </summary>
    public string? Failure(string what, EndpointTolerance tolerance) => Placed
        ? null
        : $"no valid pose stands within {tolerance} of the {what} ({Requested.X:0.###}, {Requested.Y:0.###}, {Requested.Z:0.###})"
            + (NearestValid is float d ? $"; the nearest valid pose found stands {d:0.00} m from it" : "; none was found nearby");
}
