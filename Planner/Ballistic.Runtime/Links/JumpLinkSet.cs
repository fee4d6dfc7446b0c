using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Runtime.Links;

/// <summary>
/// The navigation links made from a frozen roadmap's jumps (<see cref="Build"/>), for the node that publishes them
/// on Godot's navigation map: one one-way link per kept jump, from the takeoff stance's contact centre to the landing
/// stance's. Links are jumps only: they are made from the roadmap's edges, which are jumps, never from walks (a
/// navmesh agent walks the ground itself; a path's walks are the runtime's own moves). Deterministic: the same roadmap
/// and settings give the same links in the same order. Immutable.
/// </summary>
public sealed class JumpLinkSet
{
    private readonly JumpLink[] _links;

    private JumpLinkSet(Roadmap roadmap, JumpLinkSettings settings, JumpLink[] links, int candidates, int merged, int unperformable)
    {
        Unperformable = unperformable;
        Roadmap = roadmap;
        Settings = settings;
        _links = links;
        Links = Array.AsReadOnly(links);
        Candidates = candidates;
        Merged = merged;
    }

    /// <summary>The roadmap the links were made from (a traversal checks the agent's region still has it).</summary>
    public Roadmap Roadmap { get; }

    /// <summary>The settings they were made with.</summary>
    public JumpLinkSettings Settings { get; }

    /// <summary>The links, cheapest first (flight time, then edge index).</summary>
    public IReadOnlyList<JumpLink> Links { get; }

    /// <summary>Number of links.</summary>
    public int Count => _links.Length;

    /// <summary>Jumps that passed the distance, height and slope filters.</summary>
    public int Candidates { get; }

    /// <summary>Candidates merged into a link kept before them (<see cref="JumpLinkSettings.MergeRadius"/>).</summary>
    public int Merged { get; }

    /// <summary>Candidates dropped because the whole body could not perform their jump (checked only with an animator).</summary>
    public int Unperformable { get; }

    /// <summary>
    /// Makes the links of <paramref name="roadmap"/>: each jump whose two stances stand on ground no steeper than
    /// <see cref="JumpLinkSettings.MaxSlopeDegrees"/> and whose ends lie farther apart horizontally than
    /// <see cref="JumpLinkSettings.MinHorizontalDistance"/> or differ in height by more than
    /// <see cref="JumpLinkSettings.MinHeightChange"/> (and at least 1 mm apart) is a candidate; candidates are taken
    /// cheapest first (flight time, then edge index), each dropped when both its ends lie within
    /// <see cref="JumpLinkSettings.MergeRadius"/> of those of a link kept before it, until
    /// <see cref="JumpLinkSettings.MaxLinks"/> are kept. With an <paramref name="animator"/>, a candidate is kept only
    /// if the whole body performs its jump cleanly (animated alone at 60 frames per second, as the runtime would): a
    /// few per cent of a roadmap's jumps are not, and a traversal of such a link falls back to a search.
    /// </summary>
    /// <param name="roadmap">A frozen roadmap.</param>
    /// <param name="settings">Filters and costs; defaults when <c>null</c>.</param>
    /// <param name="animator">The whole-body animator of the roadmap's character, to keep only jumps it performs; <c>null</c> to keep them unchecked.</param>
    /// <param name="threads">Threads animating the jumps checked (about 10 ms each); the links do not depend on it.</param>
    /// <exception cref="ArgumentException">A setting is out of range.</exception>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="threads"/> is under 1.</exception>
    public static JumpLinkSet Build(Roadmap roadmap, JumpLinkSettings? settings = null, IJumpAnimator? animator = null, int threads = 1)
    {
        ArgumentNullException.ThrowIfNull(roadmap);
        ArgumentOutOfRangeException.ThrowIfLessThan(threads, 1);
        settings ??= new JumpLinkSettings();
        if (settings.Problem() is { } problem)
        {
            throw new ArgumentException($"Jump link settings: {problem}.", nameof(settings));
        }

        ReadOnlySpan<Vector3> centres = roadmap.ContactCentres;
        float minUp = MathF.Cos(settings.MaxSlopeDegrees * MathF.PI / 180f);
        var candidates = new List<JumpLink>();
        for (int e = 0; e < roadmap.Edges.Count; e++)
        {
            RoadmapEdge edge = roadmap.Edges[e];
            if (roadmap.Nodes[edge.From].Cone.Axis.Y < minUp || roadmap.Nodes[edge.To].Cone.Axis.Y < minUp)
            {
                continue;
            }

            Vector3 start = centres[edge.From];
            Vector3 end = centres[edge.To];
            float across = new Vector2(end.X - start.X, end.Z - start.Z).Length();
            float rise = MathF.Abs(end.Y - start.Y);
            float length = Vector3.Distance(start, end);
            if (length < 1e-3f || !(across > settings.MinHorizontalDistance || rise > settings.MinHeightChange))
            {
                continue;
            }

            float flight = edge.Arc.FlightTime;
            candidates.Add(new JumpLink(e, edge.From, edge.To, start, end, flight, flight * settings.ReferenceSpeed / length, settings.EnterCost));
        }

        candidates.Sort(static (a, b) => a.FlightTime != b.FlightTime ? a.FlightTime.CompareTo(b.FlightTime) : a.Edge.CompareTo(b.Edge));

        // Merge; check the jumps kept; merge again without those the body cannot perform, until every link kept was
        // checked. The fixed point is what taking the candidates one by one, checking each before keeping it, gives.
        var unperformable = new HashSet<int>();
        var performable = new HashSet<int>();
        List<int> kept;
        int merged;
        while (true)
        {
            kept = Merge(candidates, unperformable, settings, out merged);
            int[] toCheck = animator is null ? [] : [.. kept.Where(i => !performable.Contains(i))];
            if (toCheck.Length == 0)
            {
                break;
            }

            bool[] clean = new bool[toCheck.Length];
            Parallel.For(0, toCheck.Length, new ParallelOptions { MaxDegreeOfParallelism = threads }, k =>
            {
                JumpLink link = candidates[toCheck[k]];
                RoadmapEdge edge = roadmap.Edges[link.Edge];
                clean[k] = animator!.Animate([new Jump(roadmap.Nodes[edge.From], roadmap.Nodes[edge.To], edge.Arc)], 60f).IsClean;
            });
            for (int k = 0; k < toCheck.Length; k++)
            {
                (clean[k] ? performable : unperformable).Add(toCheck[k]);
            }
        }

        return new JumpLinkSet(roadmap, settings, [.. kept.Select(i => candidates[i])], candidates.Count, merged, unperformable.Count);
    }

    /// <summary>Indices of the candidates kept, in order: not set aside, not near a link kept before, at most <see cref="JumpLinkSettings.MaxLinks"/>.</summary>
    private static List<int> Merge(List<JumpLink> candidates, HashSet<int> excluded, JumpLinkSettings settings, out int merged)
    {
        var kept = new List<int>();
        var cells = new Dictionary<(int, int, int), List<int>>();
        float radius = settings.MergeRadius;
        merged = 0;
        for (int i = 0; i < candidates.Count && kept.Count < settings.MaxLinks; i++)
        {
            if (excluded.Contains(i))
            {
                continue;
            }

            JumpLink link = candidates[i];
            if (radius > 0f)
            {
                (int x, int y, int z) = Cell(link.Start, radius);
                if (Near(link, candidates, kept, cells, x, y, z, radius))
                {
                    merged++;
                    continue;
                }

                if (!cells.TryGetValue((x, y, z), out List<int>? cell))
                {
                    cells[(x, y, z)] = cell = [];
                }

                cell.Add(i);
            }

            kept.Add(i);
        }

        return kept;
    }

    /// <summary>
    /// The link whose start lies within <paramref name="radius"/> of <paramref name="entry"/> and end within it of
    /// <paramref name="exit"/> (world metres; the least sum of the two distances, then the lowest index), or −1. For
    /// nodes told only the link's ends (a <c>NavigationLink3D</c>'s <c>link_entry_position</c>/<c>link_exit_position</c>).
    /// </summary>
    public int FindLink(Vector3 entry, Vector3 exit, float radius)
    {
        int best = -1;
        float bestDistance = float.PositiveInfinity;
        for (int i = 0; i < _links.Length; i++)
        {
            float a = Vector3.Distance(_links[i].Start, entry);
            float b = Vector3.Distance(_links[i].End, exit);
            if (a <= radius && b <= radius && a + b < bestDistance)
            {
                best = i;
                bestDistance = a + b;
            }
        }

        return best;
    }

    /// <summary>True when a kept link's start lies within <paramref name="radius"/> of the candidate's start and its end within it of the candidate's end.</summary>
    private static bool Near(in JumpLink link, List<JumpLink> candidates, List<int> kept, Dictionary<(int, int, int), List<int>> cells, int x, int y, int z, float radius)
    {
        for (int dx = -1; dx <= 1; dx++)
        {
            for (int dy = -1; dy <= 1; dy++)
            {
                for (int dz = -1; dz <= 1; dz++)
                {
                    if (!cells.TryGetValue((x + dx, y + dy, z + dz), out List<int>? cell))
                    {
                        continue;
                    }

                    foreach (int k in cell)
                    {
                        if (Vector3.Distance(candidates[k].Start, link.Start) <= radius && Vector3.Distance(candidates[k].End, link.End) <= radius)
                        {
                            return true;
                        }
                    }
                }
            }
        }

        return false;
    }

    private static (int X, int Y, int Z) Cell(Vector3 p, float size) =>
        ((int)MathF.Floor(p.X / size), (int)MathF.Floor(p.Y / size), (int)MathF.Floor(p.Z / size));
}
