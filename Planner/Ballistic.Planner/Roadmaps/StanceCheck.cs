using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;

namespace Ballistic.Planner.Roadmaps;

/// <summary>
/// Whether a roadmap's stances are true of the level it is loaded with, as the bake made them: every contact on a
/// triangle of the level (<see cref="ContactEstimator"/> puts it on one), with that triangle's normal and friction,
/// each stance with the contacts its character needs, and its friction cone the one its contacts give (axis along
/// the sum of their normals, the least of their frictions). A roadmap file's checksum only says its bytes are as
/// written; this says a stance edited by hand (lifted off the ground, its normals or cone turned) is not trusted.
/// </summary>
internal static class StanceCheck
{
    /// <summary>Farthest a contact may lie from the level's surface (metres), beyond float rounding of its coordinates: the bake puts it on a triangle.</summary>
    public const float PositionTolerance = 1e-3f;

    /// <summary>Least cosine between a contact's normal and its triangle's (about 0.8°): the bake copies the triangle's.</summary>
    public const float NormalCosine = 0.9999f;

    /// <summary>Largest difference between a stored friction coefficient and the one the level and character give.</summary>
    public const float FrictionTolerance = 1e-4f;

    /// <summary>Least cosine between a stance's cone axis and its contacts' summed normals (about 0.8°).</summary>
    public const float AxisCosine = 0.9999f;

    /// <summary>
    /// The first way in which <paramref name="roadmap"/>'s stances are not true of <paramref name="level"/> for
    /// <paramref name="character"/>, as a phrase ("node 3's contact of limb 1 is 0.35 m off the level's surface"), or
    /// <c>null</c> when every stance holds.
    /// </summary>
    public static string? FirstLie(Roadmap roadmap, Level level, ReducedCharacter character)
    {
        TriangleBvh bvh = level.Bvh;
        var near = new List<int>(32);
        foreach (RoadmapNode node in roadmap.Nodes)
        {
            if (node.Contacts.Count < character.RequiredContacts)
            {
                return $"node {node.Id} has {node.Contacts.Count} contact{(node.Contacts.Count == 1 ? "" : "s")}, fewer than the {character.RequiredContacts} {character.Name} stands on";
            }

            Vector3 sum = Vector3.Zero;
            float mu = float.PositiveInfinity;
            foreach (Contact c in node.Contacts)
            {
                if (ContactLie(node, c, level, bvh, character, near) is { } lie)
                {
                    return lie;
                }

                sum += c.Normal;
                mu = MathF.Min(mu, c.Mu);
            }

            if (node.Contacts.Count == 0)
            {
                continue;
            }

            Vector3 axis = sum.Length() > 0f ? Vector3.Normalize(sum) : Vector3.Zero;
            if (!(Vector3.Dot(axis, node.Cone.Axis) >= AxisCosine))
            {
                return $"node {node.Id}'s friction cone points {Angle(axis, node.Cone.Axis):0.#}° away from its contacts' normals";
            }

            if (!(MathF.Abs(node.Cone.Mu - mu) <= FrictionTolerance))
            {
                return $"node {node.Id}'s friction cone claims a friction of {node.Cone.Mu:G4}, its contacts' least is {mu:G4}";
            }
        }

        return null;
    }

    /// <summary>Why contact <paramref name="c"/> of <paramref name="node"/> is not on the level as the bake would put it, or <c>null</c>.</summary>
    private static string? ContactLie(RoadmapNode node, in Contact c, Level level, TriangleBvh bvh, ReducedCharacter character, List<int> near)
    {
        float reach = PositionTolerance + (1e-6f * MathF.Max(MathF.Max(MathF.Abs(c.Position.X), MathF.Abs(c.Position.Y)), MathF.Abs(c.Position.Z)));
        near.Clear();
        bvh.TrianglesNear(new Aabb(c.Position, c.Position).Inflate(reach), near);
        bool onSurface = false;
        bool facing = false;
        float friction = float.NaN;
        foreach (int t in near)
        {
            Triangle triangle = level.Triangles[t];
            if (Vector3.Distance(triangle.ClosestPoint(c.Position), c.Position) > reach)
            {
                continue;
            }

            onSurface = true;
            if (!(Vector3.Dot(triangle.Normal, c.Normal) >= NormalCosine))
            {
                continue;
            }

            facing = true;
            friction = level.FrictionOf(t, character.Friction);
            if (MathF.Abs(friction - c.Mu) <= FrictionTolerance)
            {
                return null;
            }
        }

        string which = $"node {node.Id}'s contact of limb {c.Limb}";
        if (!onSurface)
        {
            return $"{which} is {Distance(bvh, level, c.Position):G3} m off the level's surface";
        }

        return facing
            ? $"{which} claims a friction of {c.Mu:G4}, its surface's is {friction:G4}"
            : $"{which} has a normal that is not its surface's (the surface there faces otherwise)";
    }

    /// <summary>The distance (metres) from <paramref name="p"/> to the level's nearest triangle, searched in growing boxes (for the message only).</summary>
    private static float Distance(TriangleBvh bvh, Level level, Vector3 p)
    {
        var near = new List<int>();
        for (float r = 0.05f; ; r *= 2f)
        {
            near.Clear();
            bvh.TrianglesNear(new Aabb(p, p).Inflate(r), near);
            float best = float.PositiveInfinity;
            foreach (int t in near)
            {
                best = MathF.Min(best, Vector3.Distance(level.Triangles[t].ClosestPoint(p), p));
            }

            if (best <= r || r > 1e6f)
            {
                return best;
            }
        }
    }

    private static float Angle(Vector3 a, Vector3 b) => MathF.Acos(Math.Clamp(Vector3.Dot(a, b), -1f, 1f)) * 180f / MathF.PI;
}
