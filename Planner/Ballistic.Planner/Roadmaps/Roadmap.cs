namespace Ballistic.Planner.Roadmaps;

/// <summary>
/// A directed graph of root poses linked by valid jumps, baked for one character on one level. Nodes and edges
/// are kept in insertion order, so that a given seed gives the same roadmap byte for byte.
/// </summary>
public sealed class Roadmap
{
    private readonly List<RoadmapNode> _nodes = [];
    private readonly List<RoadmapEdge> _edges = [];
    private readonly List<List<int>> _outgoing = [];
    private readonly List<int> _edgeTargets = [];
    private readonly List<float> _edgeFlightTimes = [];

    /// <summary>Creates an empty roadmap for a level and character.</summary>
    /// <param name="levelFingerprint">The level's <see cref="Levels.Level.Fingerprint"/>.</param>
    /// <param name="characterFingerprint">The character's <see cref="Characters.ReducedCharacter.Fingerprint"/>.</param>
    /// <param name="characterName">The character's name, for messages.</param>
    /// <param name="seed">The seed the roadmap was baked with.</param>
    public Roadmap(string levelFingerprint, string characterFingerprint, string characterName, int seed)
    {
        LevelFingerprint = levelFingerprint;
        CharacterFingerprint = characterFingerprint;
        CharacterName = characterName;
        Seed = seed;
    }

    /// <summary>Fingerprint of the level the roadmap was baked on.</summary>
    public string LevelFingerprint { get; }

    /// <summary>Fingerprint of the character the roadmap was baked for.</summary>
    public string CharacterFingerprint { get; }

    /// <summary>Name of the character the roadmap was baked for.</summary>
    public string CharacterName { get; }

    /// <summary>Seed of the bake.</summary>
    public int Seed { get; }

    /// <summary>The nodes, indexed by id.</summary>
    public IReadOnlyList<RoadmapNode> Nodes => _nodes;

    /// <summary>The edges, in insertion order.</summary>
    public IReadOnlyList<RoadmapEdge> Edges => _edges;

    /// <summary>The fastest horizontal speed (m/s) of any edge: flight time ≥ horizontal distance / this, an admissible A* bound.</summary>
    public float MaxHorizontalSpeed { get; private set; }

    /// <summary>Landing node of each edge, by edge index (a compact copy for searches).</summary>
    public IReadOnlyList<int> EdgeTargets => _edgeTargets;

    /// <summary>Flight time of each edge in seconds, by edge index (a compact copy for searches).</summary>
    public IReadOnlyList<float> EdgeFlightTimes => _edgeFlightTimes;

    /// <summary>Indices (into <see cref="Edges"/>) of the edges leaving node <paramref name="node"/>.</summary>
    public IReadOnlyList<int> Outgoing(int node) => _outgoing[node];

    /// <summary>Adds a node; its id must be the current node count.</summary>
    /// <exception cref="ArgumentException">The node's id is not the next id.</exception>
    public void AddNode(RoadmapNode node)
    {
        ArgumentNullException.ThrowIfNull(node);
        if (node.Id != _nodes.Count)
        {
            throw new ArgumentException($"Node id {node.Id} is not the next id {_nodes.Count}.", nameof(node));
        }

        _nodes.Add(node);
        _outgoing.Add([]);
    }

    /// <summary>Adds a directed edge between existing nodes.</summary>
    /// <exception cref="ArgumentOutOfRangeException">An endpoint is not a node of this roadmap.</exception>
    public void AddEdge(RoadmapEdge edge)
    {
        if ((uint)edge.From >= (uint)_nodes.Count || (uint)edge.To >= (uint)_nodes.Count)
        {
            throw new ArgumentOutOfRangeException(nameof(edge), $"Edge {edge.From} → {edge.To} names a node outside 0..{_nodes.Count - 1}.");
        }

        _outgoing[edge.From].Add(_edges.Count);
        _edges.Add(edge);
        _edgeTargets.Add(edge.To);
        _edgeFlightTimes.Add(edge.Arc.FlightTime);
        MaxHorizontalSpeed = MathF.Max(MaxHorizontalSpeed, edge.Arc.HorizontalSpeed);
    }

    /// <summary>True when a path of edges leads from <paramref name="from"/> to <paramref name="to"/>.</summary>
    public bool Reaches(int from, int to)
    {
        if (from == to)
        {
            return true;
        }

        var seen = new bool[_nodes.Count];
        var stack = new Stack<int>();
        stack.Push(from);
        seen[from] = true;
        while (stack.Count > 0)
        {
            int node = stack.Pop();
            foreach (int e in _outgoing[node])
            {
                int next = _edges[e].To;
                if (next == to)
                {
                    return true;
                }

                if (!seen[next])
                {
                    seen[next] = true;
                    stack.Push(next);
                }
            }
        }

        return false;
    }
}
