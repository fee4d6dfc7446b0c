using System.Numerics;
using System.Runtime.InteropServices;
using Ballistic.Planner.Characters;

namespace Ballistic.Planner.Roadmaps;

/// <summary>
/// A spatial index of points (node positions or contact centres, world metres) for the two questions the planner
/// asks: which points lie within jump reach of a point (the bake's neighbour candidates, a query's connections),
/// and which point lies within an endpoint tolerance of a point (exact pose lookup, <see cref="Roadmap.FindNode"/>).
/// Point ids are dense and added in increasing order (a roadmap's node ids).
/// </summary>
/// <remarks>
/// <para>
/// A uniform grid over the horizontal plane (X, Z), cells hashed by their integer coordinates, each holding the
/// ids of its points in increasing order. Chosen over a k-d tree because (1) the bake inserts nodes one at a time
/// while it queries, which a grid absorbs in O(1) and a k-d tree only by rebuilding or unbalancing; (2) every
/// query has a radius known in advance (the jump reach, an endpoint tolerance), so with cells of about half the
/// reach a query reads a fixed block of 5 × 5 cells; (3) nodes are sampled on surfaces, so their horizontal density
/// is bounded by the level's (multi-storey levels stack a few floors per cell, not thousands); (4) candidate order
/// is trivially deterministic, since callers sort what they keep by (distance, id). Height is not indexed: jump
/// reach and tolerances are decided by the exact tests after the grid has narrowed the candidates.
/// </para>
/// <para>
/// The grid only narrows: every query then applies the test the linear scans applied before (the same expressions
/// and float arithmetic; for jump reach, <see cref="ReachTest"/>, whose table gives exactly the same answers) and
/// keeps the nearest by (distance, id) in a bounded heap, so its answers are the sets, in the order, a scan over
/// every point gives. The bake's cells are half its reach bound, a frozen roadmap's half its longest jump. Reading
/// is thread-safe once no more points are added.
/// </para>
/// </remarks>
internal sealed class NodeIndex
{
    /// <summary>Grid ranges covering more cells than this many times the non-empty cells read every cell instead.</summary>
    private const long DenseFactor = 1;

    private readonly Dictionary<long, List<int>> _cells = [];
    private readonly List<Vector3> _points = [];
    private readonly double _inverseCell;

    /// <summary>Creates an empty index with square cells of <paramref name="cellSize"/> metres.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The cell size is not a finite positive number.</exception>
    public NodeIndex(float cellSize)
    {
        if (!(cellSize > 0f && float.IsFinite(cellSize)))
        {
            throw new ArgumentOutOfRangeException(nameof(cellSize), cellSize, "The cell size must be a finite positive number of metres.");
        }

        CellSize = cellSize;
        _inverseCell = 1.0 / cellSize;
    }

    /// <summary>Creates an index of <paramref name="points"/> (ids 0, 1, …) with square cells of <paramref name="cellSize"/> metres.</summary>
    public NodeIndex(float cellSize, ReadOnlySpan<Vector3> points)
        : this(cellSize)
    {
        _points.Capacity = points.Length;
        foreach (Vector3 p in points)
        {
            Add(p);
        }
    }

    /// <summary>Side of the square cells, metres.</summary>
    public float CellSize { get; }

    /// <summary>Number of points.</summary>
    public int Count => _points.Count;

    /// <summary>The point of id <paramref name="id"/>, world metres.</summary>
    public Vector3 this[int id] => _points[id];

    /// <summary>A cell size suited to jump-reach queries for <paramref name="limits"/>: half the reach bound.</summary>
    public static float CellSizeFor(SteeringLimits limits) => Math.Clamp(0.5f * ReachBound(limits), 0.05f, 1e4f);

    /// <summary>
    /// An upper bound (metres) of <see cref="SteeringLimits.MaxReach"/> at every drop, with a margin: the speed
    /// limits V (takeoff) and L (landing) reach at most V·L/g horizontally, at a drop of (V² − L²)/(2g).
    /// </summary>
    public static float ReachBound(SteeringLimits limits)
    {
        ArgumentNullException.ThrowIfNull(limits);
        return (float)((double)limits.TakeoffSpeedMax * limits.LandingSpeedMax / limits.Gravity * 1.0001) + 1e-4f;
    }

    /// <summary>
    /// True when <paramref name="q"/> is within jump reach of <paramref name="p"/> in either direction: their
    /// horizontal distance is at most <see cref="SteeringLimits.MaxReach"/> at their height difference taken either
    /// way. The one reach test of the bake and the query.
    /// </summary>
    public static bool InReach(SteeringLimits limits, float bound, Vector3 p, Vector3 q)
    {
        float x = new Vector2(q.X - p.X, q.Z - p.Z).Length();
        return x <= bound && (x <= limits.MaxReach(p.Y - q.Y) || x <= limits.MaxReach(q.Y - p.Y));
    }

    /// <summary>Adds a point; its id is the previous <see cref="Count"/>.</summary>
    public void Add(Vector3 point)
    {
        int id = _points.Count;
        _points.Add(point);
        long key = Key(Cell(point.X), Cell(point.Z));
        if (!_cells.TryGetValue(key, out List<int>? cell))
        {
            cell = [];
            _cells[key] = cell;
        }

        cell.Add(id);
    }

    /// <summary>
    /// The <paramref name="count"/> points nearest <paramref name="point"/> (3D distance, then id) among those within
    /// jump reach of it (<see cref="ReachTest"/>, the same answers as <see cref="InReach"/>), added to
    /// <paramref name="nearest"/> by <see cref="Offer"/>: call <see cref="Finish"/> once every candidate is offered.
    /// </summary>
    public void OfferWithinReach(Vector3 point, ReachTest reach, int count, List<(float Distance, int Id)> nearest)
    {
        var cells = new CellEnumerator(this, point, reach.Bound);
        while (cells.MoveNext())
        {
            foreach (int id in cells.Current)
            {
                Vector3 q = _points[id];
                if (reach.InReach(point, q))
                {
                    Offer(nearest, count, (Vector3.Distance(point, q), id));
                }
            }
        }
    }

    /// <summary>
    /// The <paramref name="count"/> points nearest <paramref name="point"/> (3D distance, then id) among those at most
    /// <paramref name="across"/> metres from it horizontally, added to <paramref name="nearest"/> by
    /// <see cref="Offer"/>: call <see cref="Finish"/> once every candidate is offered.
    /// </summary>
    public void OfferWithin(Vector3 point, float across, int count, List<(float Distance, int Id)> nearest)
    {
        var cells = new CellEnumerator(this, point, across);
        float squared = across * across;
        while (cells.MoveNext())
        {
            foreach (int id in cells.Current)
            {
                Vector3 q = _points[id];
                float dx = q.X - point.X;
                float dz = q.Z - point.Z;
                if ((dx * dx) + (dz * dz) <= squared)
                {
                    Offer(nearest, count, (Vector3.Distance(point, q), id));
                }
            }
        }
    }

    /// <summary>
    /// Keeps <paramref name="candidate"/> among the <paramref name="count"/> smallest (distance, id) pairs offered
    /// so far: <paramref name="kept"/> is a max-heap of them, in no useful order until <see cref="Finish"/>.
    /// </summary>
    public static void Offer(List<(float Distance, int Id)> kept, int count, (float Distance, int Id) candidate)
    {
        if (kept.Count < count)
        {
            // Sift up.
            kept.Add(candidate);
            int i = kept.Count - 1;
            while (i > 0)
            {
                int parent = (i - 1) / 2;
                if (kept[parent].CompareTo(kept[i]) >= 0)
                {
                    break;
                }

                (kept[parent], kept[i]) = (kept[i], kept[parent]);
                i = parent;
            }
        }
        else if (count > 0 && candidate.CompareTo(kept[0]) < 0)
        {
            // Replace the largest and sift down.
            kept[0] = candidate;
            int i = 0;
            while (true)
            {
                int largest = i;
                int left = (2 * i) + 1;
                int right = left + 1;
                if (left < kept.Count && kept[left].CompareTo(kept[largest]) > 0)
                {
                    largest = left;
                }

                if (right < kept.Count && kept[right].CompareTo(kept[largest]) > 0)
                {
                    largest = right;
                }

                if (largest == i)
                {
                    break;
                }

                (kept[largest], kept[i]) = (kept[i], kept[largest]);
                i = largest;
            }
        }
    }

    /// <summary>
    /// Sorts the pairs kept by <see cref="Offer"/> by (distance, id): exactly the first ones of all the candidates
    /// offered, sorted the same way.
    /// </summary>
    public static void Finish(List<(float Distance, int Id)> kept) => kept.Sort();

    /// <summary>
    /// The id of the point nearest <paramref name="point"/> (3D distance, then the lowest id) among those within
    /// <paramref name="across"/> metres horizontally and <paramref name="upDown"/> metres vertically of it, or −1.
    /// </summary>
    public int NearestWithin(Vector3 point, float across, float upDown)
    {
        int best = -1;
        float bestDistance = float.PositiveInfinity;
        var cells = new CellEnumerator(this, point, across);
        while (cells.MoveNext())
        {
            foreach (int id in cells.Current)
            {
                Vector3 c = _points[id];
                if (new Vector2(c.X - point.X, c.Z - point.Z).Length() <= across && MathF.Abs(c.Y - point.Y) <= upDown)
                {
                    float d = Vector3.DistanceSquared(c, point);
                    if (d < bestDistance || (d == bestDistance && id < best))
                    {
                        (best, bestDistance) = (id, d);
                    }
                }
            }
        }

        return best;
    }

    /// <summary>The ids of the points in the cell holding <paramref name="point"/>, increasing: every point equal to it is among them.</summary>
    public ReadOnlySpan<int> CellOf(Vector3 point) =>
        _cells.TryGetValue(Key(Cell(point.X), Cell(point.Z)), out List<int>? cell) ? CollectionsMarshal.AsSpan(cell) : [];

    private int Cell(double coordinate)
    {
        double c = Math.Floor(coordinate * _inverseCell);
        return (int)Math.Clamp(c, int.MinValue / 4, int.MaxValue / 4);
    }

    private static long Key(int x, int z) => ((long)x << 32) | (uint)z;

    /// <summary>
    /// The non-empty cells overlapping the square of half side <c>radius</c> (plus a slack for rounding) around a
    /// point, each as the span of its ids; every cell when that square covers more cells than are filled.
    /// </summary>
    private ref struct CellEnumerator
    {
        private readonly NodeIndex _index;
        private readonly int _x0;
        private readonly int _x1;
        private readonly int _z0;
        private readonly int _z1;
        private readonly bool _all;
        private Dictionary<long, List<int>>.ValueCollection.Enumerator _every;
        private int _x;
        private int _z;

        public CellEnumerator(NodeIndex index, Vector3 centre, float radius)
        {
            _index = index;
            double r = ((double)radius * 1.01) + 0.01;
            _x0 = index.Cell(centre.X - r);
            _x1 = index.Cell(centre.X + r);
            _z0 = index.Cell(centre.Z - r);
            _z1 = index.Cell(centre.Z + r);
            _all = ((long)_x1 - _x0 + 1) * ((long)_z1 - _z0 + 1) > DenseFactor * index._cells.Count;
            _every = index._cells.Values.GetEnumerator();
            _x = _x0;
            _z = _z0 - 1;
            Current = [];
        }

        public ReadOnlySpan<int> Current { get; private set; }

        public bool MoveNext()
        {
            if (_all)
            {
                if (_every.MoveNext())
                {
                    Current = CollectionsMarshal.AsSpan(_every.Current);
                    return true;
                }

                return false;
            }

            while (true)
            {
                if (++_z > _z1)
                {
                    _z = _z0;
                    if (++_x > _x1)
                    {
                        return false;
                    }
                }

                if (_index._cells.TryGetValue(Key(_x, _z), out List<int>? cell))
                {
                    Current = CollectionsMarshal.AsSpan(cell);
                    return true;
                }
            }
        }
    }
}
