namespace Ballistic.Runtime.Agents;

/// <summary>
/// The world's queue of path requests, first come first served: data shared by whoever asks for a path (the world's
/// calls, the locomotion system when an agent stops with a target waiting) and the path-request system, which
/// searches from its head. Asking replaces the agent's pending request (<see cref="AgentStore.Request"/>); a
/// replaced or cancelled request stays queued and is skipped when reached. Requests come from a pool that the
/// path-request system gives them back to once it is done with them (<see cref="Return"/>): asking allocates nothing
/// once the pool and the queue have grown.
/// </summary>
internal sealed class PathQueue(AgentStore agents)
{
    private readonly Queue<PathRequest> _queue = new();
    private readonly Stack<PathRequest> _pool = new();

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
        PathRequest request = _pool.Count > 0 ? _pool.Pop() : new PathRequest();
        request.Reset(agents.HandleOf(slot), agents.Target[slot], forcedEdge);
        agents.Request[slot] = request;
        agents.Navigate(slot, NavigationStatus.Planning);
        _queue.Enqueue(request);
    }

    /// <summary>Forgets the pending request of the agent in <paramref name="slot"/> (its result, if any, is dropped on delivery).</summary>
    public void Cancel(int slot) => agents.Request[slot] = null;

    /// <summary>Takes the request at the head of the queue, if any.</summary>
    public bool TryTake([System.Diagnostics.CodeAnalysis.NotNullWhen(true)] out PathRequest? request) => _queue.TryDequeue(out request);

    /// <summary>
    /// Takes back <paramref name="request"/> for a later use: one no agent, queue or system refers to any more and
    /// whose job, if it was started, has ended (a stale entry a background thread may still hold finds the job claimed
    /// and leaves it: <see cref="RequestJob.TryRun"/>).
    /// </summary>
    public void Return(PathRequest request) => _pool.Push(request);
}
