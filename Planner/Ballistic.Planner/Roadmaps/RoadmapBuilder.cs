using System.Runtime.InteropServices;

namespace Ballistic.Planner.Roadmaps;

/// <summary>
/// A roadmap under construction: nodes and edges are added in order (the bake, a file being read), then
/// <see cref="Freeze"/> makes the immutable <see cref="Roadmap"/> that queries use. Not thread-safe.
/// </summary>
internal sealed class RoadmapBuilder
{
    private readonly List<RoadmapNode> _nodes = [];
    private readonly List<RoadmapEdge> _edges = [];
    private readonly List<RoadmapWalk> _walks = [];
    private readonly List<List<int>> _targets = [];

    /// <summary>Creates an empty roadmap for a level and character.</summary>
    /// <param name="levelFingerprint">The level's <see cref="Levels.Level.Fingerprint"/>.</param>
    /// <param name="characterFingerprint">The character's <see cref="Characters.ReducedCharacter.Fingerprint"/>.</param>
    /// <param name="characterName">The character's name, for messages.</param>
    /// <param name="seed">The seed the roadmap was baked with.</param>
    public RoadmapBuilder(string levelFingerprint, string characterFingerprint, string characterName, int seed)
    {
        ArgumentNullException.ThrowIfNull(levelFingerprint);
        ArgumentNullException.ThrowIfNull(characterFingerprint);
        ArgumentNullException.ThrowIfNull(characterName);
        LevelFingerprint = levelFingerprint;
        CharacterFingerprint = characterFingerprint;
        CharacterName = characterName;
        Seed = seed;
    }

    /// <summary>Fingerprint of the level the roadmap is baked on.</summary>
    public string LevelFingerprint { get; }

    /// <summary>Fingerprint of the character the roadmap is baked for.</summary>
    public string CharacterFingerprint { get; }

    /// <summary>Name of the character the roadmap is baked for.</summary>
    public string CharacterName { get; }

    /// <summary>Seed of the bake.</summary>
    public int Seed { get; }

    /// <summary>The nodes so far, indexed by id.</summary>
    public IReadOnlyList<RoadmapNode> Nodes => _nodes;

    /// <summary>The edges so far, in insertion order.</summary>
    public IReadOnlyList<RoadmapEdge> Edges => _edges;

    /// <summary>The walks so far, in insertion order.</summary>
    public IReadOnlyList<RoadmapWalk> Walks => _walks;

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
        _targets.Add([]);
    }

    /// <summary>Adds a directed edge between existing nodes.</summary>
    /// <exception cref="ArgumentOutOfRangeException">An endpoint is not a node of this roadmap.</exception>
    public void AddEdge(RoadmapEdge edge)
    {
        if ((uint)edge.From >= (uint)_nodes.Count || (uint)edge.To >= (uint)_nodes.Count)
        {
            throw new ArgumentOutOfRangeException(nameof(edge), $"Edge {edge.From} → {edge.To} names a node outside 0..{_nodes.Count - 1}.");
        }

        _targets[edge.From].Add(edge.To);
        _edges.Add(edge);
    }

    /// <summary>Adds a directed walk between existing nodes.</summary>
    /// <exception cref="ArgumentOutOfRangeException">An endpoint is not a node of this roadmap, or the walk joins a node to itself.</exception>
    public void AddWalk(RoadmapWalk walk)
    {
        if ((uint)walk.From >= (uint)_nodes.Count || (uint)walk.To >= (uint)_nodes.Count || walk.From == walk.To)
        {
            throw new ArgumentOutOfRangeException(nameof(walk), $"Walk {walk.From} → {walk.To} names a node outside 0..{_nodes.Count - 1} or joins a node to itself.");
        }

        _targets[walk.From].Add(walk.To);
        _walks.Add(walk);
    }

    /// <summary>True when a path of edges (jumps or walks) leads from <paramref name="from"/> to <paramref name="to"/> in the roadmap so far.</summary>
    public bool Reaches(int from, int to) =>
        Reachability.Reaches(_nodes.Count, from, to, node => CollectionsMarshal.AsSpan(_targets[node]));

    /// <summary>
    /// The roadmap so far as an immutable <see cref="Roadmap"/>, with its search arrays and spatial index built
    /// now. The builder stays usable: later additions do not change the roadmaps already frozen.
    /// </summary>
    public Roadmap Freeze() => new(LevelFingerprint, CharacterFingerprint, CharacterName, Seed, [.. _nodes], [.. _edges], [.. _walks]);
}
