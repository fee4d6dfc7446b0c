using System.Numerics;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Query;

/// <summary>
/// What the level's materials add to a search's costs (<see cref="LevelMaterial.TravelCost"/>,
/// <see cref="LevelMaterial.EnterCost"/>), as navigation areas' costs do: a walk costs its time on each material times
/// that material's travel cost, plus the enter cost of each material it steps onto from another; a jump adds the
/// enter cost of the material it lands on when that is not the one it took off from. The ground under a walk is read
/// every <see cref="Spacing"/> along it, straight down. Only built for a level with such costs: on any other the
/// search's costs are the plain ones, bit for bit.
/// </summary>
internal sealed class SurfaceCosts(Level level, TriangleBvh bvh)
{
    /// <summary>Distance (metres) between the points along a walk whose ground is read.</summary>
    public const float Spacing = 0.25f;

    /// <summary>How far above a walk's path point the ground is looked for, and down to how far below it, metres.</summary>
    private const float Above = 0.5f;

    private const float Below = 1f;

    /// <summary>The material index straight below <paramref name="point"/> (world metres), or −1 where there is no ground.</summary>
    public int MaterialBelow(Vector3 point) =>
        bvh.Raycast(point + (Vector3.UnitY * Above), -Vector3.UnitY, Above + Below, out RayHit hit) ? level.MaterialIndices[hit.Triangle] : -1;

    /// <summary>The material a stance stands on: that of its contact on the costliest material to enter (−1 with none found).</summary>
    public int MaterialOf(RoadmapNode node)
    {
        int best = -1;
        foreach (Contacts.Contact contact in node.Contacts)
        {
            int m = bvh.Raycast(contact.Position + (contact.Normal * 0.05f), -contact.Normal, 0.1f, out RayHit hit) ? level.MaterialIndices[hit.Triangle] : -1;
            if (m >= 0 && (best < 0 || level.Materials[m].EnterCost > level.Materials[best].EnterCost))
            {
                best = m;
            }
        }

        return best >= 0 ? best : MaterialBelow(node.ContactCentre);
    }

    /// <summary>Seconds a jump from <paramref name="from"/> to <paramref name="to"/> adds: the landing material's enter cost when it differs from the takeoff's.</summary>
    public float Jump(RoadmapNode from, RoadmapNode to)
    {
        int landing = MaterialOf(to);
        return landing >= 0 && landing != MaterialOf(from) ? level.Materials[landing].EnterCost : 0f;
    }

    /// <summary>
    /// The cost (seconds) of walking <paramref name="path"/> (world metres, on the ground) in <paramref name="time"/>
    /// seconds, starting on material <paramref name="start"/> (−1 for unknown): the time on each material times its
    /// travel cost, plus the enter cost of each material stepped onto.
    /// </summary>
    public float Walk(IReadOnlyList<Vector3> path, float time, int start)
    {
        float length = 0f;
        float weighted = 0f;
        float entered = 0f;
        int current = start;
        foreach ((int m, float stretch) in Ground(path))
        {
            length += stretch;
            weighted += stretch * (m >= 0 ? level.Materials[m].TravelCost : 1f);
            if (m >= 0 && m != current)
            {
                if (current >= 0)
                {
                    entered += level.Materials[m].EnterCost;
                }

                current = m;
            }
        }

        return length > 1e-6f ? (time * weighted / length) + entered : time;
    }

    /// <summary>The costly materials (<see cref="LevelMaterial.HasCost"/>) under <paramref name="path"/> (world metres, on the ground), each once, in index order.</summary>
    public IEnumerable<LevelMaterial> Costly(IReadOnlyList<Vector3> path) =>
        Ground(path).Select(g => g.Material).Where(m => m >= 0 && level.Materials[m].HasCost).Distinct().Order().Select(m => level.Materials[m]);

    /// <summary>
    /// The ground along <paramref name="path"/>, read every <see cref="Spacing"/> at most: for each stretch in order,
    /// the material below its middle (−1 for none) and its length, metres.
    /// </summary>
    private IEnumerable<(int Material, float Length)> Ground(IReadOnlyList<Vector3> path)
    {
        for (int i = 1; i < path.Count; i++)
        {
            float segment = Vector3.Distance(path[i - 1], path[i]);
            int samples = Math.Max(1, (int)MathF.Ceiling(segment / Spacing));
            for (int k = 0; k < samples; k++)
            {
                yield return (MaterialBelow(Vector3.Lerp(path[i - 1], path[i], (k + 0.5f) / samples)), segment / samples);
            }
        }
    }

    /// <summary>The surface costs of <paramref name="scene"/>'s level, or <c>null</c> when it has none.</summary>
    public static SurfaceCosts? Of(Planning.PlanningScene scene) => scene.Level.HasSurfaceCosts ? new SurfaceCosts(scene.Level, scene.Bvh) : null;
}
