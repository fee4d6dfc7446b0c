using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Surfaces;

namespace Ballistic.Planner.Contacts;

/// <summary>
/// FINDCONTACTS and COMPUTECONE of the paper: for a root pose, each limb whose workspace Wk touches an acceptable
/// surface gets an estimated contact at the centre of Wk's intersection with the largest such surface; the
/// centroidal cone has the normalised sum of the contact normals as axis and the least friction as μ. Thread-safe.
/// </summary>
public sealed class ContactEstimator
{
    /// <summary>|Σ nᵢ| below this counts as force closure (normals cancelling out).</summary>
    public const float ForceClosureThreshold = 0.05f;

    /// <summary>Intersections smaller than this (square metres) are grazing touches, not contacts.</summary>
    public const float MinContactArea = 1e-4f;

    private readonly Level _level;
    private readonly TriangleBvh _bvh;
    private readonly SurfaceSet _surfaces;
    private readonly ReducedCharacter _character;

    /// <summary>Creates an estimator for one character on one level.</summary>
    public ContactEstimator(Level level, TriangleBvh bvh, SurfaceSet surfaces, ReducedCharacter character)
    {
        ArgumentNullException.ThrowIfNull(level);
        ArgumentNullException.ThrowIfNull(bvh);
        ArgumentNullException.ThrowIfNull(surfaces);
        ArgumentNullException.ThrowIfNull(character);
        _level = level;
        _bvh = bvh;
        _surfaces = surfaces;
        _character = character;
    }

    /// <summary>Checks the trunk, estimates the contacts and computes the cone of <paramref name="pose"/>.</summary>
    public PoseEvaluation Evaluate(in RootPose pose)
    {
        if (_bvh.Overlaps(new OrientedBox(pose.Position, _character.TrunkHalfExtents, pose.Rotation)))
        {
            return new PoseEvaluation(pose, PoseValidity.TrunkCollides, [], default);
        }

        var contacts = new List<Contact>(_character.Limbs.Count);
        var touched = new List<int>();
        for (int limbIndex = 0; limbIndex < _character.Limbs.Count; limbIndex++)
        {
            if (TryEstimate(limbIndex, pose, touched, out Contact contact))
            {
                contacts.Add(contact);
            }
        }

        if (contacts.Count < _character.RequiredContacts)
        {
            return new PoseEvaluation(pose, PoseValidity.TooFewContacts, contacts, default);
        }

        Vector3 sum = Vector3.Zero;
        float mu = float.PositiveInfinity;
        foreach (Contact c in contacts)
        {
            sum += c.Normal;
            mu = MathF.Min(mu, c.Mu);
        }

        return sum.Length() < ForceClosureThreshold
            ? new PoseEvaluation(pose, PoseValidity.ForceClosure, contacts, default)
            : new PoseEvaluation(pose, PoseValidity.Valid, contacts, new FrictionCone(sum, mu));
    }

    /// <summary>The estimated contact of one limb, when its workspace touches an acceptable surface.</summary>
    public bool TryEstimate(int limbIndex, in RootPose pose, List<int> scratch, out Contact contact)
    {
        ArgumentNullException.ThrowIfNull(scratch);
        contact = default;
        Limb limb = _character.Limbs[limbIndex];
        OrientedBox workspace = limb.WorkspaceAt(pose);
        scratch.Clear();
        _bvh.OverlappingTriangles(workspace, scratch);
        if (scratch.Count == 0)
        {
            return false;
        }

        // Area, area-weighted centroid and normal of the intersection, per surface.
        var perSurface = new Dictionary<int, (float Area, Vector3 Moment, Vector3 Normal)>();
        foreach (int t in scratch)
        {
            int surface = _surfaces.SurfaceOf(t);
            if (surface < 0)
            {
                continue;
            }

            Triangle triangle = _level.Triangles[t];
            Vector3 normal = triangle.Normal;
            if (!limb.Filter.Accepts(normal))
            {
                continue;
            }

            (float area, Vector3 centroid) = BoxClipper.ClipArea(workspace, triangle);
            if (area <= 0f)
            {
                continue;
            }

            (float Area, Vector3 Moment, Vector3 Normal) sum = perSurface.GetValueOrDefault(surface);
            perSurface[surface] = (sum.Area + area, sum.Moment + (centroid * area), sum.Normal + (normal * area));
        }

        int best = -1;
        float bestArea = MinContactArea;
        foreach ((int surface, (float area, _, _)) in perSurface)
        {
            if (area > bestArea || (area == bestArea && surface < best))
            {
                best = surface;
                bestArea = area;
            }
        }

        if (best < 0)
        {
            return false;
        }

        (float a, Vector3 moment, Vector3 weightedNormal) = perSurface[best];
        ContactSurface chosen = _surfaces.Surfaces[best];
        float mu = _level.Materials[chosen.MaterialIndex].Friction ?? _character.Friction;
        contact = new Contact(limbIndex, moment / a, Vector3.Normalize(weightedNormal), mu, best);
        return true;
    }
}
