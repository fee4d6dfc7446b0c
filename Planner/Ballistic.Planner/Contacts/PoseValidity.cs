namespace Ballistic.Planner.Contacts;

/// <summary>Whether a root pose can be a roadmap node, and if not why.</summary>
public enum PoseValidity
{
    /// <summary>Trunk free, enough contacts, a usable centroidal cone.</summary>
    Valid = 0,

    /// <summary>The trunk box W0 touches the level.</summary>
    TrunkCollides,

    /// <summary>Fewer limb workspaces touch an acceptable surface than the character requires.</summary>
    TooFewContacts,

    /// <summary>The contact normals cancel out (force closure): the centroidal cone has no axis.</summary>
    ForceClosure,

    /// <summary>The built-in checks pass but the scene's extra <see cref="IPoseValidator"/> refuses the pose.</summary>
    Rejected,
}
