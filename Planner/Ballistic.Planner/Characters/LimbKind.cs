namespace Ballistic.Planner.Characters;

/// <summary>What a limb's effector is, for animation and reports.</summary>
public enum LimbKind
{
    /// <summary>A leg ending in a foot (sole contact).</summary>
    Foot,

    /// <summary>An arm ending in a hand (palm contact).</summary>
    Hand,
}
