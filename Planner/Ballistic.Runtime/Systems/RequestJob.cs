using System.Numerics;
using Ballistic.Planner.Animation;
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
/// until its outcome is delivered, so the job gives the same outcome on whichever thread and at whatever time it runs.
/// </summary>
internal sealed class RequestJob(CharacterKind kind, RoadmapSearch search, PathRequest request, int rounds, float frameRate)
{
    private readonly RoadmapNode _start = request.Start!;
    private readonly Vector3 _target = request.Target;
    private readonly int _forcedEdge = request.ForcedEdge;
    private readonly IReadOnlyList<Move>? _forcedMoves = request.ForcedMoves;
    private readonly JumpRepair _repair = request.Repair;
    private int _claimed;

    /// <summary>
    /// Runs the job unless a thread has already claimed it (<see cref="TryRun"/> or <see cref="Run"/>): the tick thread
    /// waiting for a request may run it itself when no background thread has started it. Null when it was claimed.
    /// </summary>
    public RequestOutcome? TryRun() => Interlocked.Exchange(ref _claimed, 1) == 0 ? Solve() : null;

    /// <summary>Runs the job here (a world with no background threads); its outcome.</summary>
    public RequestOutcome Run()
    {
        _claimed = 1;
        return Solve();
    }

    private RequestOutcome Solve()
    {
        IReadOnlyList<Move>? given = _forcedMoves;
        if (_forcedEdge >= 0)
        {
            Roadmap roadmap = kind.Roadmap;
            RoadmapEdge edge = roadmap.Edges[_forcedEdge];
            given = [new Jump(roadmap.Nodes[edge.From], roadmap.Nodes[edge.To], edge.Arc)];
        }

        var job = new PlanJob((repair, _) => search.Search(_start, _target, repair), kind.PathAnimator, _repair, rounds, frameRate) { Given = given };
        try
        {
            (PlanResult result, JumpAnimation? animation, _) = job.Run();
            return new RequestOutcome(result, animation is null ? [] : result.Moves, animation, null, Searching: false);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            return new RequestOutcome(null, [], null, e, Searching: job.Phase == "searching");
        }
    }
}
