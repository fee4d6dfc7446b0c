namespace Ballistic.Planner.Contacts;

/// <summary>
/// An extra test a root pose must pass to become a roadmap node or a query's start or goal (OMPL's
/// <c>StateValidityChecker</c>), asked after the built-in checks (trunk clear of the level, enough contacts, a usable
/// cone) have passed. Use it for game rules the geometry cannot express: no stance in a trigger volume, no contact on
/// lava. Implementations must be thread-safe and deterministic.
/// </summary>
public interface IPoseValidator
{
    /// <summary>True when the pose may be used.</summary>
    /// <param name="evaluation">The pose (world frame, metres) with its estimated contacts and centroidal cone; valid by the built-in checks.</param>
    bool IsValid(PoseEvaluation evaluation);
}
