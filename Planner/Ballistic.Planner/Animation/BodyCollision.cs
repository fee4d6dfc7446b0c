using System.Numerics;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Sampling;

namespace Ballistic.Planner.Animation;

/// <summary>
/// Checks that a limb's bones do not pass through the level: each bone is the segment from its parent joint to it
/// (and the effector's to its contact point), tested as a thin box; within <see cref="ContactClearance"/> of a held
/// contact point the segment may touch.
/// </summary>
public sealed class BodyCollision
{
    /// <summary>Distance from a contact point within which a bone may touch the surface, metres.</summary>
    public const float ContactClearance = 0.01f;

    private const float Thickness = 0.002f;
    private readonly TriangleBvh _bvh;

    /// <summary>Creates a checker over a level.</summary>
    public BodyCollision(TriangleBvh bvh)
    {
        ArgumentNullException.ThrowIfNull(bvh);
        _bvh = bvh;
    }

    /// <summary>True when a bone of <paramref name="limb"/> passes through the level.</summary>
    /// <param name="limb">The limb.</param>
    /// <param name="positions">World positions of every joint.</param>
    /// <param name="rotations">World rotations of every joint.</param>
    /// <param name="contact">The contact point the limb holds, or <c>null</c>.</param>
    public bool LimbCollides(RigLimb limb, ReadOnlySpan<Vector3> positions, ReadOnlySpan<Quaternion> rotations, Vector3? contact)
    {
        ArgumentNullException.ThrowIfNull(limb);
        for (int i = 1; i < limb.Chain.Count; i++)
        {
            if (SegmentCollides(positions[limb.Chain[i - 1]], positions[limb.Chain[i]], contact))
            {
                return true;
            }
        }

        return SegmentCollides(positions[limb.EffectorJoint], limb.EffectorPosition(positions, rotations), contact);
    }

    /// <summary>True when the segment from <paramref name="a"/> to <paramref name="b"/>, less the part near <paramref name="contact"/>, touches the level.</summary>
    public bool SegmentCollides(Vector3 a, Vector3 b, Vector3? contact)
    {
        if (contact is Vector3 c)
        {
            // Cut the segment where it comes within the clearance of the contact point.
            bool aNear = Vector3.Distance(a, c) <= ContactClearance;
            bool bNear = Vector3.Distance(b, c) <= ContactClearance;
            if (aNear && bNear)
            {
                return false;
            }

            Vector3 d = b - a;
            float length = d.Length();
            if (length > 1e-6f)
            {
                Vector3 dir = d / length;
                if (bNear)
                {
                    b = a + (dir * MathF.Max(0f, length - ContactClearance - Vector3.Distance(b, c)));
                }
                else if (aNear)
                {
                    a += dir * MathF.Min(length, ContactClearance + Vector3.Distance(a, c));
                }
            }
        }

        Vector3 segment = b - a;
        float half = segment.Length() * 0.5f;
        if (half < 1e-5f)
        {
            return false;
        }

        Quaternion rotation = TrunkSampler.AlignUp(segment / (2f * half));
        return _bvh.Overlaps(new OrientedBox((a + b) * 0.5f, new Vector3(Thickness, half, Thickness), rotation));
    }
}
