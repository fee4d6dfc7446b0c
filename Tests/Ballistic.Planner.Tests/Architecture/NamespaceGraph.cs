using System.Reflection;

namespace Ballistic.Planner.Tests.Architecture;

/// <summary>
/// Which namespaces of one assembly use which others of the same assembly, with the type-level uses that make each
/// edge (for messages that say what to fix).
/// </summary>
internal sealed class NamespaceGraph
{
    private readonly SortedDictionary<string, SortedSet<string>> _edges = new(StringComparer.Ordinal);
    private readonly Dictionary<(string From, string To), SortedSet<string>> _uses = [];

    /// <summary>The namespaces, in ordinal order.</summary>
    public IEnumerable<string> Namespaces => _edges.Keys;

    /// <summary>
    /// The namespace graph of <paramref name="assembly"/>: one edge per namespace another one's types use. Only the
    /// assembly's own namespaces count (its name and below), not those the compiler generates (regex sources).
    /// </summary>
    public static NamespaceGraph Of(Assembly assembly)
    {
        string root = assembly.GetName().Name!;
        bool Own(string? ns) => ns is not null && (ns == root || ns.StartsWith(root + ".", StringComparison.Ordinal));
        var graph = new NamespaceGraph();
        foreach (Type type in TypeDependencies.AllTypes(assembly))
        {
            if (!Own(type.Namespace))
            {
                continue;
            }

            string from = type.Namespace!;
            graph.AddNode(from);
            foreach (Type used in TypeDependencies.Of(type))
            {
                if (used.Assembly == assembly && Own(used.Namespace) && used.Namespace is { } to && to != from)
                {
                    graph.AddEdge(from, to, $"{Name(type)} uses {Name(used)}");
                }
            }
        }

        return graph;
    }

    /// <summary>Adds a namespace with no edges yet.</summary>
    public void AddNode(string name)
    {
        if (!_edges.ContainsKey(name))
        {
            _edges.Add(name, new SortedSet<string>(StringComparer.Ordinal));
        }
    }

    /// <summary>Records that <paramref name="from"/> uses <paramref name="to"/>, because of <paramref name="use"/>.</summary>
    public void AddEdge(string from, string to, string use)
    {
        AddNode(from);
        AddNode(to);
        _edges[from].Add(to);
        if (!_uses.TryGetValue((from, to), out SortedSet<string>? uses))
        {
            _uses[(from, to)] = uses = new SortedSet<string>(StringComparer.Ordinal);
        }

        uses.Add(use);
    }

    /// <summary>The namespaces <paramref name="from"/> uses.</summary>
    public IReadOnlySet<string> Uses(string from) => _edges.TryGetValue(from, out SortedSet<string>? to) ? to : new SortedSet<string>();

    /// <summary>
    /// One cycle of the graph as the list of namespaces along it (the first repeated at the end), or <c>null</c>
    /// when the graph is acyclic. Deterministic: the search visits namespaces in ordinal order.
    /// </summary>
    public IReadOnlyList<string>? FindCycle()
    {
        var state = new Dictionary<string, int>(StringComparer.Ordinal); // absent: new, 1: on the path, 2: done
        var path = new List<string>();
        foreach (string start in _edges.Keys)
        {
            if (!state.ContainsKey(start) && Visit(start, state, path) is { } cycle)
            {
                return cycle;
            }
        }

        return null;
    }

    /// <summary>A readable account of <paramref name="cycle"/>: each step with the type-level uses behind it.</summary>
    public string Describe(IReadOnlyList<string> cycle)
    {
        var lines = new List<string> { "Namespace cycle: " + string.Join(" -> ", cycle) };
        for (int i = 0; i + 1 < cycle.Count; i++)
        {
            SortedSet<string> uses = _uses.TryGetValue((cycle[i], cycle[i + 1]), out SortedSet<string>? u) ? u : [];
            lines.Add($"  {cycle[i]} -> {cycle[i + 1]}: {string.Join("; ", uses.Take(5))}{(uses.Count > 5 ? $"; … ({uses.Count} uses)" : string.Empty)}");
        }

        return string.Join(Environment.NewLine, lines);
    }

    /// <summary>The whole graph, one namespace per line with the namespaces it uses.</summary>
    public override string ToString() =>
        string.Join(Environment.NewLine, _edges.Select(e => $"{e.Key} -> {string.Join(", ", e.Value)}"));

    private List<string>? Visit(string node, Dictionary<string, int> state, List<string> path)
    {
        state[node] = 1;
        path.Add(node);
        foreach (string next in _edges[node])
        {
            if (!state.TryGetValue(next, out int s))
            {
                if (Visit(next, state, path) is { } cycle)
                {
                    return cycle;
                }
            }
            else if (s == 1)
            {
                return [.. path[path.IndexOf(next)..], next];
            }
        }

        path.RemoveAt(path.Count - 1);
        state[node] = 2;
        return null;
    }

    private static string Name(Type type) => type.FullName ?? type.Name;
}
