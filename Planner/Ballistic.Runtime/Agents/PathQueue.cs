namespace Ballistic.Runtime.Agents;

/// <summary>
/// The world's queue of path requests, first come first served: data shared by whoever asks for a path (the world's
/// calls, the locomotion system when an agent stops with a target waiting) and the path-request system, which
/// searches from its head. Asking replaces the agent's pending request (<see cref="AgentStore.Request"/>); a
/// replaced or cancelled request stays queued and is skipped when reached.
/// </summary>
internal sealed class PathQueue(AgentStore agents)
{
    private readonly LinkedList<PathRequest> _queue = new();

    /// <summary>Requests waiting for a search (including replaced ones not reached yet).</summary>
    public int Count => _queue.Count;

    /// <summary>Queues a request for the agent in <paramref name="slot"/> toward its target, replacing any pending one.</summary>
    public void Request(int slot) => Request(slot, -1);

    /// <summary>
    /// Queues a request for the agent in <paramref name="slot"/> toward its target, replacing any pending one, whose
    /// whole path is <paramref name="moves"/> (the agent stands on the first one's stance): no search.
    /// </summary>
    public void Request(int slot, IReadOnlyList<Ballistic.Planner.Roadmaps.Move> moves)
    {
        Request(slot, -1);
        agents.Request[slot]!.ForcedMoves = moves;
    }

    /// <summary>
    /// Queues a request for the agent in <paramref name="slot"/> toward its target, replacing any pending one: with
    /// <paramref name="forcedEdge"/> ≥ 0, that roadmap edge is the whole path (the agent stands on its takeoff node).
    /// </summary>
    public void Request(int slot, int forcedEdge)
    {
        var request = new PathRequest(agents.HandleOf(slot), agents.Target[slot]) { ForcedEdge = forcedEdge };
        agents.Request[slot] = request;
        agents.Navigate(slot, NavigationStatus.Planning);
        _queue.AddLast(request);
    }

    /// <summary>Forgets the pending request of the agent in <paramref name="slot"/> (its result, if any, is dropped on delivery).</summary>
    public void Cancel(int slot) => agents.Request[slot] = null;

    /// <summary>Takes the request at the head of the queue, if any.</summary>
    public bool TryTake([System.Diagnostics.CodeAnalysis.NotNullWhen(true)] out PathRequest? request)
    {
        if (_queue.First is { } first)
        {
            request = first.Value;
            _queue.RemoveFirst();
            return true;
        }

        request = null;
        return false;
    }
}
