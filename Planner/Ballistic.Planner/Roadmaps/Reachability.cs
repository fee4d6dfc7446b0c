namespace Ballistic.Planner.Roadmaps;

/// <summary>The landing nodes of the jumps leaving <paramref name="node"/>.</summary>
internal delegate ReadOnlySpan<int> Successors(int node);

/// <summary>Whether one node of a directed graph reaches another: the one depth-first search of builders and frozen roadmaps.</summary>
internal static class Reachability
{
    public static bool Reaches(int nodeCount, int from, int to, Successors successors)
    {
        if (from == to)
        {
            return true;
        }

        var seen = new bool[nodeCount];
        var stack = new Stack<int>();
        stack.Push(from);
        seen[from] = true;
        while (stack.Count > 0)
        {
            foreach (int next in successors(stack.Pop()))
            {
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
