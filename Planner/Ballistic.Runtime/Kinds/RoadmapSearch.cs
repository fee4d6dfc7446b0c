using System.Numerics;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime.Core;

namespace Ballistic.Runtime.Kinds;

/// <summary>
/// The searches of one character kind, on any thread: path queries over the kind's roadmap, each search renting one
/// (with its reusable scratch) from a pool, so that searches run at once on several threads. A query's scratch does
/// not change its results: the same request gives the same path whichever query serves it.
/// <para>
/// With <see cref="WorldSettings.PrepareSearches"/>, one background thread prepares the kind's searches
/// (<see cref="PathQuery.Prepare"/>) from the start until done or <see cref="StopPreparing"/>: it changes no result.
/// </para>
/// </summary>
internal sealed class RoadmapSearch
{
    private readonly CharacterKind _kind;
    private readonly System.Collections.Concurrent.ConcurrentBag<PathQuery> _queries = [];
    private readonly QuerySettings _settings;
    private readonly CancellationTokenSource? _preparing;

    public RoadmapSearch(CharacterKind kind, WorldSettings world)
    {
        _kind = kind;
        _settings = new QuerySettings
        {
            Tolerance = world.Tolerance,
            CanStand = kind.Animator.CanStand,
            Locomotion = world.Locomotion,
            JumpEffort = kind.JumpEffort ?? world.JumpEffort,
            JumpHeightEffort = kind.JumpHeightEffort ?? world.JumpHeightEffort,
        };
        if (world.PrepareSearches)
        {
            _preparing = new CancellationTokenSource();
            CancellationToken token = _preparing.Token;
            Preparation = Task.Factory.StartNew(
                () => new PathQuery(_kind.Scene, _kind.Roadmap).Prepare(_settings, threads: 1, TerminationCondition.Cancellation(token)),
                token,
                TaskCreationOptions.LongRunning,
                TaskScheduler.Default);
        }
    }

    /// <summary>The background preparation of the kind's searches (node pairs prepared), or <c>null</c> without <see cref="WorldSettings.PrepareSearches"/>.</summary>
    public Task<int>? Preparation { get; }

    /// <summary>Stops the background preparation, if any (the kind was removed or replaced, the world disposed); what it prepared stays in the scene.</summary>
    public void StopPreparing() => _preparing?.Cancel();

    /// <summary>The query settings of every search: the world's tolerance, locomotion, the kind's jump costs (else the world's), the kind's standing check.</summary>
    public QuerySettings Settings => _settings;

    /// <summary>
    /// Searches from the stance <paramref name="start"/> to the point <paramref name="target"/> (to its roadmap node,
    /// when one stands there), in steps (<see cref="PathQuery"/>'s: <c>null</c> at each pause point, then the result);
    /// thread-safe. The query serving it is the search's until its steps end or are disposed.
    /// </summary>
    /// <remarks>The request's repair record gives the moves to avoid and, once its walks failed, jumps only; it must not change during the search.</remarks>
    public IEnumerable<PlanResult?> Search(RoadmapNode start, Vector3 target, JumpRepair repair)
    {
        QuerySettings settings = repair.Adjust(_settings);
        IReadOnlySet<(int From, int To)> rejected = repair.Excluded;
        PathQuery query = _queries.TryTake(out PathQuery? pooled) ? pooled : new PathQuery(_kind.Scene, _kind.Roadmap);
        try
        {
            IEnumerable<PlanResult?> steps = _kind.Roadmap.FindNode(target, _settings.Tolerance) is int goal
                ? query.PlanSteps(start, _kind.Roadmap.Nodes[goal], settings, rejected, termination: null)
                : query.PlanSteps(start, target, settings, rejected, termination: null);
            foreach (PlanResult? step in steps)
            {
                yield return step;
            }
        }
        finally
        {
            _queries.Add(query);
        }
    }
}
