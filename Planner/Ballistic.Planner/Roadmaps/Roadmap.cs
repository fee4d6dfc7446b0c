using System.Collections.ObjectModel;
using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Sampling;

namespace Ballistic.Planner.Roadmaps;

/// <summary>
/// A directed graph of root poses linked by valid jumps, baked for one character on one level: immutable, made by
/// <see cref="RoadmapBuilder.Freeze"/>. Nodes and edges are kept in insertion order, so that a given seed gives the
/// same roadmap byte for byte. Besides the nodes and edges it holds, built once when frozen, the compact arrays
/// searches read (outgoing edges in compressed rows, node positions, contact centres), a spatial index of the
/// nodes and landmark flight times bounding A* searches. Thread-safe: any number of threads may read and query
/// one roadmap at once.
/// </summary>
public sealed class Roadmap
{
    private readonly RoadmapNode[] _nodes;
    private readonly RoadmapEdge[] _edges;
    private readonly int[] _edgeTargets;
    private readonly float[] _edgeFlightTimes;
    private readonly int[] _offsets;
    private readonly int[] _rowTargets;
    private readonly float[] _rowFlightTimes;
    private readonly float[] _rowEnergyHeights;
    private readonly int[] _rowEdges;
    private readonly Vector3[] _positions;
    private readonly Vector2[] _horizontal;
    private readonly Vector3[] _centres;
    private readonly NodeIndex _positionIndex;
    private readonly NodeIndex _centreIndex;
    private readonly Landmarks _landmarks;
    private readonly RoadmapWalk[] _walks;
    private readonly int[] _walkOffsets;
    private readonly int[] _walkTargets;
    private readonly float[] _walkDurations;
    private readonly int[] _walkRows;

    internal Roadmap(string levelFingerprint, string characterFingerprint, string characterName, int seed, RoadmapNode[] nodes, RoadmapEdge[] edges, RoadmapWalk[] walks)
    {
        LevelFingerprint = levelFingerprint;
        CharacterFingerprint = characterFingerprint;
        CharacterName = characterName;
        Seed = seed;
        _nodes = nodes;
        _edges = edges;
        Nodes = new ReadOnlyCollection<RoadmapNode>(nodes);
        Edges = new ReadOnlyCollection<RoadmapEdge>(edges);

        int n = nodes.Length;
        _positions = new Vector3[n];
        _horizontal = new Vector2[n];
        _centres = new Vector3[n];
        for (int i = 0; i < n; i++)
        {
            Vector3 p = nodes[i].Pose.Position;
            _positions[i] = p;
            _horizontal[i] = new Vector2(p.X, p.Z);
            _centres[i] = nodes[i].ContactCentre;
        }

        // Compressed rows: each node's outgoing edges, in insertion order.
        _edgeTargets = new int[edges.Length];
        _edgeFlightTimes = new float[edges.Length];
        _offsets = new int[n + 1];
        float longest = 0f;
        float fastest = 0f;
        for (int e = 0; e < edges.Length; e++)
        {
            RoadmapEdge edge = edges[e];
            _edgeTargets[e] = edge.To;
            _edgeFlightTimes[e] = edge.Arc.FlightTime;
            _offsets[edge.From + 1]++;
            fastest = MathF.Max(fastest, edge.Arc.HorizontalSpeed);
            longest = MathF.Max(longest, Vector2.Distance(_horizontal[edge.From], _horizontal[edge.To]));
        }

        for (int i = 0; i < n; i++)
        {
            _offsets[i + 1] += _offsets[i];
        }

        _rowTargets = new int[edges.Length];
        _rowFlightTimes = new float[edges.Length];
        _rowEnergyHeights = new float[edges.Length];
        _rowEdges = new int[edges.Length];
        int[] next = n > 0 ? _offsets[..n] : [];
        for (int e = 0; e < edges.Length; e++)
        {
            int k = next[edges[e].From]++;
            _rowTargets[k] = edges[e].To;
            _rowFlightTimes[k] = edges[e].Arc.FlightTime;
            _rowEnergyHeights[k] = edges[e].Arc.EnergyHeight;
            _rowEdges[k] = e;
        }

        MaxHorizontalSpeed = fastest;
        EdgeTargets = Array.AsReadOnly(_edgeTargets);
        EdgeFlightTimes = Array.AsReadOnly(_edgeFlightTimes);

        // Cells of half the longest jump (a proxy of the reach the roadmap was baked with); 1 m without jumps.
        float cell = longest > 0f ? Math.Clamp(0.5f * longest, 0.05f, 1e4f) : 1f;
        _positionIndex = new NodeIndex(cell, _positions);
        _centreIndex = new NodeIndex(cell, _centres);
        _landmarks = Landmarks.Build(_horizontal, _offsets, _rowTargets, _rowFlightTimes);

        // Walks in compressed rows too.
        _walks = walks;
        Walks = Array.AsReadOnly(walks);
        _walkOffsets = new int[n + 1];
        foreach (RoadmapWalk walk in walks)
        {
            _walkOffsets[walk.From + 1]++;
        }

        for (int i = 0; i < n; i++)
        {
            _walkOffsets[i + 1] += _walkOffsets[i];
        }

        _walkTargets = new int[walks.Length];
        _walkDurations = new float[walks.Length];
        _walkRows = new int[walks.Length];
        int[] nextWalk = n > 0 ? _walkOffsets[..n] : [];
        for (int w = 0; w < walks.Length; w++)
        {
            int k = nextWalk[walks[w].From]++;
            _walkTargets[k] = walks[w].To;
            _walkDurations[k] = walks[w].Duration;
            _walkRows[k] = w;
        }
    }

    /// <summary>The walks (directed), in insertion order; empty for a roadmap baked without walking.</summary>
    internal IReadOnlyList<RoadmapWalk> Walks { get; }

    /// <summary>Compressed rows of the outgoing walks, as <see cref="OutgoingOffsets"/> for jumps: node i's walks are entries <c>WalkOffsets[i]</c> to <c>WalkOffsets[i + 1] − 1</c>.</summary>
    public ReadOnlySpan<int> WalkOffsets => _walkOffsets;

    /// <summary>Node walked to of each outgoing-walk entry (see <see cref="WalkOffsets"/>).</summary>
    public ReadOnlySpan<int> WalkTargets => _walkTargets;

    /// <summary>Duration in seconds of each outgoing-walk entry (see <see cref="WalkOffsets"/>).</summary>
    public ReadOnlySpan<float> WalkDurations => _walkDurations;

    /// <summary>Index into <see cref="Walks"/> of each outgoing-walk entry (see <see cref="WalkOffsets"/>).</summary>
    public ReadOnlySpan<int> WalkEntries => _walkRows;

    /// <summary>The walk of index <paramref name="walk"/> without the read-only wrapper.</summary>
    internal ref readonly RoadmapWalk Walk(int walk) => ref _walks[walk];

    /// <summary>Fingerprint of the level the roadmap was baked on.</summary>
    public string LevelFingerprint { get; }

    /// <summary>Fingerprint of the character the roadmap was baked for.</summary>
    public string CharacterFingerprint { get; }

    /// <summary>Name of the character the roadmap was baked for.</summary>
    public string CharacterName { get; }

    /// <summary>Seed of the bake.</summary>
    public int Seed { get; }

    /// <summary>The nodes, indexed by id.</summary>
    public IReadOnlyList<RoadmapNode> Nodes { get; }

    /// <summary>The edges, in insertion order.</summary>
    internal IReadOnlyList<RoadmapEdge> Edges { get; }

    /// <summary>The fastest horizontal speed (m/s) of any edge: flight time ≥ horizontal distance / this, an admissible A* bound.</summary>
    public float MaxHorizontalSpeed { get; }

    /// <summary>Landing node of each edge, by edge index.</summary>
    public IReadOnlyList<int> EdgeTargets { get; }

    /// <summary>Flight time of each edge in seconds, by edge index.</summary>
    public IReadOnlyList<float> EdgeFlightTimes { get; }

    /// <summary>Indices (into <see cref="Edges"/>) of the edges leaving node <paramref name="node"/>, in insertion order.</summary>
    public ReadOnlySpan<int> Outgoing(int node) => _rowEdges.AsSpan(_offsets[node], _offsets[node + 1] - _offsets[node]);

    /// <summary>
    /// Compressed rows of the outgoing edges: node i's edges are entries <c>OutgoingOffsets[i]</c> to
    /// <c>OutgoingOffsets[i + 1] − 1</c> of <see cref="OutgoingTargets"/>, <see cref="OutgoingFlightTimes"/> and
    /// <see cref="OutgoingEdges"/>, in insertion order. Node count + 1 entries.
    /// </summary>
    public ReadOnlySpan<int> OutgoingOffsets => _offsets;

    /// <summary>Landing node of each outgoing-edge entry (see <see cref="OutgoingOffsets"/>).</summary>
    public ReadOnlySpan<int> OutgoingTargets => _rowTargets;

    /// <summary>Flight time in seconds of each outgoing-edge entry (see <see cref="OutgoingOffsets"/>).</summary>
    public ReadOnlySpan<float> OutgoingFlightTimes => _rowFlightTimes;

    /// <summary>Energy height in metres (<see cref="Steering.BallisticArc.EnergyHeight"/>) of each outgoing-edge entry (see <see cref="OutgoingOffsets"/>).</summary>
    internal ReadOnlySpan<float> OutgoingEnergyHeights => _rowEnergyHeights;

    /// <summary>Index into <see cref="Edges"/> of each outgoing-edge entry (see <see cref="OutgoingOffsets"/>).</summary>
    public ReadOnlySpan<int> OutgoingEdges => _rowEdges;

    /// <summary>Trunk centre of each node (its pose's position), world metres, by node id.</summary>
    public ReadOnlySpan<Vector3> Positions => _positions;

    /// <summary>
    /// Centre of each node's contacts (the mean of their positions; the trunk centre for a node without contacts),
    /// world metres, by node id: where an <see cref="EndpointTolerance"/> measures a stance from.
    /// </summary>
    public ReadOnlySpan<Vector3> ContactCentres => _centres;

    /// <summary>Horizontal (X, Z) trunk centre of each node, for the A* heuristic.</summary>
    internal Vector2[] Horizontal => _horizontal;

    /// <summary>Landmark flight times, for the A* heuristic.</summary>
    internal Landmarks Landmarks => _landmarks;

    /// <summary>True when a path of jumps leads from <paramref name="from"/> to <paramref name="to"/>.</summary>
    public bool Reaches(int from, int to) =>
        Reachability.Reaches(_nodes.Length, from, to, node => _rowTargets.AsSpan(_offsets[node], _offsets[node + 1] - _offsets[node]));

    /// <summary>True when a path of jumps and walks leads from <paramref name="from"/> to <paramref name="to"/>.</summary>
    public bool ReachesWalking(int from, int to)
    {
        if (_walks.Length == 0)
        {
            return Reaches(from, to);
        }

        var targets = new List<int>();
        return Reachability.Reaches(_nodes.Length, from, to, node =>
        {
            targets.Clear();
            targets.AddRange(_rowTargets.AsSpan(_offsets[node], _offsets[node + 1] - _offsets[node]));
            targets.AddRange(_walkTargets.AsSpan(_walkOffsets[node], _walkOffsets[node + 1] - _walkOffsets[node]));
            return System.Runtime.InteropServices.CollectionsMarshal.AsSpan(targets);
        });
    }

    /// <summary>
    /// The node whose contact centre (<see cref="ContactCentres"/>) is nearest <paramref name="point"/> (3D distance;
    /// the lowest id on a tie) among those within <paramref name="tolerance"/> of it: at most
    /// <see cref="EndpointTolerance.Across"/> metres horizontally and <see cref="EndpointTolerance.UpDown"/> metres
    /// vertically (world Y), as <see cref="TrunkSampler.Place"/> measures a placed stance. <c>null</c> when none is.
    /// Turns a target point into a roadmap node without sampling; found through the spatial index.
    /// </summary>
    /// <param name="point">The point, world metres.</param>
    /// <param name="tolerance">How close the node's contact centre must be.</param>
    /// <exception cref="ArgumentException">The tolerance is not positive, or the point is not finite.</exception>
    public int? FindNode(Vector3 point, EndpointTolerance tolerance)
    {
        tolerance.Validate();
        if (!float.IsFinite(point.X) || !float.IsFinite(point.Y) || !float.IsFinite(point.Z))
        {
            throw new ArgumentException($"The point ({point.X}, {point.Y}, {point.Z}) is not finite.", nameof(point));
        }

        int id = _centreIndex.NearestWithin(point, tolerance.Across, tolerance.UpDown);
        return id >= 0 ? id : null;
    }

    /// <summary>
    /// The nodes within jump reach of <paramref name="point"/> for <paramref name="limits"/> (horizontal distance at
    /// most <see cref="SteeringLimits.MaxReach"/> at the height difference, either way), nearest first (3D distance
    /// from the trunk centre, then id), at most <paramref name="count"/>: the nodes a query steers to and from.
    /// </summary>
    /// <param name="point">A trunk centre, world metres.</param>
    /// <param name="limits">The character's steering limits.</param>
    /// <param name="count">How many nodes to keep at most.</param>
    /// <param name="nearest">Cleared, then filled with (distance in metres, node id).</param>
    internal void Nearest(Vector3 point, SteeringLimits limits, int count, List<(float Distance, int Id)> nearest)
    {
        ArgumentNullException.ThrowIfNull(limits);
        Nearest(point, new ReachTest(limits), count, nearest);
    }

    /// <summary><see cref="Nearest(Vector3, SteeringLimits, int, List{ValueTuple{float, int}})"/> with a reach test built once by the caller.</summary>
    internal void Nearest(Vector3 point, ReachTest reach, int count, List<(float Distance, int Id)> nearest)
    {
        ArgumentNullException.ThrowIfNull(nearest);
        ArgumentOutOfRangeException.ThrowIfNegative(count);
        nearest.Clear();
        _positionIndex.OfferWithinReach(point, reach, count, nearest);
        NodeIndex.Finish(nearest);
    }

    /// <summary>The nodes whose trunk centre is at most <paramref name="across"/> metres from <paramref name="point"/> horizontally, nearest first (3D distance, then id), at most <paramref name="count"/>.</summary>
    internal void NearestWithin(Vector3 point, float across, int count, List<(float Distance, int Id)> nearest)
    {
        nearest.Clear();
        _positionIndex.OfferWithin(point, across, count, nearest);
        NodeIndex.Finish(nearest);
    }

    /// <summary>The lowest id of a node with exactly this pose, or <c>null</c>.</summary>
    internal int? FindPose(in RootPose pose)
    {
        foreach (int id in _positionIndex.CellOf(pose.Position))
        {
            if (_nodes[id].Pose == pose)
            {
                return id;
            }
        }

        return null;
    }

    /// <summary>True when <paramref name="node"/> is this roadmap's node of its id (same id, equal pose).</summary>
    internal bool Holds(RoadmapNode node) => (uint)node.Id < (uint)_nodes.Length && _nodes[node.Id].Pose == node.Pose;

    /// <summary>The node of id <paramref name="id"/> without the read-only wrapper.</summary>
    internal RoadmapNode Node(int id) => _nodes[id];

    /// <summary>The edge of index <paramref name="edge"/> without the read-only wrapper.</summary>
    internal ref readonly RoadmapEdge Edge(int edge) => ref _edges[edge];
}
