using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Animation;

/// <summary>A whole-body contact pose: root pose, every joint angle, the contacts made and their centroidal cone.</summary>
/// <param name="Root">Root pose (fixed by the planner).</param>
/// <param name="Angles">One angle per degree of freedom of the rig, radians.</param>
/// <param name="Contacts">The contacts made, one per touching limb.</param>
/// <param name="Cone">Centroidal cone of the contacts (meaningful when there is at least one).</param>
/// <param name="Valid">True when the pose makes contacts whose cone accepts the jump's velocity and no limb passes through the level.</param>
/// <param name="Reason">Why the pose is not valid, or <c>null</c>.</param>
internal sealed record ContactConfiguration(RootPose Root, float[] Angles, IReadOnlyList<LimbContact> Contacts, FrictionCone Cone, bool Valid, string? Reason)
{
    /// <summary>The contact limb <paramref name="limb"/> (an index in the character's limb list) makes, or <c>null</c> when it touches nothing.</summary>
    public LimbContact? ContactOf(int limb)
    {
        foreach (LimbContact c in Contacts)
        {
            if (c.Limb == limb)
            {
                return c;
            }
        }

        return null;
    }
}
