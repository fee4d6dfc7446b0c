using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Runtime.Systems;

/// <summary>
/// One started path request as a job for any thread: the planner's plan-and-repair loop (<see cref="PlanJob"/>, the
/// one <see cref="AnimatedPlanner"/> runs) on the kind's roadmap, from the request's stance to its target, starting
/// with its given moves if any: search, animate, set aside what the body cannot perform and search again, up to
/// <c>rounds</c> searches. Its inputs are read from the request when it starts, on the tick; the request does not change
/// until its outcome is delivered, so the job gives the same outcome on whichever thread and at whatever time it runs,
/// whole (<see cref="TryRun"/>, <see cref="Run"/>) or in slices on the tick (<see cref="Advance"/>).
/// </summary>
internal sealed class RequestJob(CharacterKind kind, RoadmapSearch search, PathRequest request, int rounds, float frameRate) : IDisposable
{
    private readonly RoadmapNode _start = request.Start!;
    private readonly Vector3 _target = request.Target;
    private readonly int _forcedEdge = request.ForcedEdge;
    private readonly IReadOnlyList<Move>? _forcedMoves = request.ForcedMoves;
    private readonly JumpRepair _repair = request.Repair;
    private PlanJob? _job;
    private RequestOutcome? _outcome;
    private int _claimed;

    /// <summary>
    /// Runs the job unless a thread has already claimed it (<see cref="TryRun"/> or <see cref="Run"/>): the tick thread
    /// waiting for a request may run it itself when no background thread has started it. Null when it was claimed.
    /// </summary>
    public RequestOutcome? TryRun() => Interlocked.Exchange(ref _claimed, 1) == 0 ? Advance(slice: null) : null;

    /// <summary>Runs the job here, to its end (a world with no background threads); its outcome.</summary>
    public RequestOutcome Run() => Advance(slice: null)!;

    /// <summary>
    /// Advances the job on this thread until it ends or <paramref name="slice"/> says to stop (<see cref="PlanJob.Advance"/>;
    /// <c>null</c>: to its end): its outcome once it has ended, otherwise <c>null</c>. An exception the job throws ends
    /// it with that error as its outcome.
    /// </summary>
    public RequestOutcome? Advance(TerminationCondition? slice)
    {
        if (_outcome is not null)
        {
            return _outcome;
        }

        _claimed = 1;
        if (_job is null)
        {
            IReadOnlyList<Move>? given = _forcedMoves;
            if (_forcedEdge >= 0)
            {
                Roadmap roadmap = kind.Roadmap;
                RoadmapEdge edge = roadmap.Edges[_forcedEdge];
                given = [new Jump(roadmap.Nodes[edge.From], roadmap.Nodes[edge.To], edge.Arc)];
            }

            _job = new PlanJob((repair, _) => search.Search(_start, _target, repair), kind.PathAnimator, _repair, rounds, frameRate) { Given = given };
        }

        try
        {
            if (!_job.Advance(slice))
            {
                return null;
            }

            (PlanResult result, JumpAnimation? animation, _) = _job.Outcome!.Value;
            _outcome = new RequestOutcome(result, animation is null ? [] : result.Moves, animation, null, Searching: false);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            _outcome = new RequestOutcome(null, [], null, e, Searching: _job.Phase == "searching");
            _job.Dispose();
        }

        return _outcome;
    }

    /// <summary>Steps the job has taken (<see cref="PlanJob.Steps"/>).</summary>
    public int Steps => _job?.Steps ?? 0;

    /// <summary>Ends the job where it stands (its request dropped), releasing the query its search holds.</summary>
    public void Dispose() => _job?.Dispose();
}
