using System.Numerics;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Runtime.Systems;

/// <summary>
/// One started path request as a job for any thread: its search (or its given moves), then the moves' whole-body
/// animation. Its inputs are read from the request when it starts, on the tick; the request does not change until its
/// outcome is delivered, so the job gives the same outcome on whichever thread and at whatever time it runs.
/// </summary>
internal sealed class RequestJob(CharacterKind kind, RoadmapSearch search, PathRequest request, float frameRate)
{
    private readonly RoadmapNode _start = request.Start!;
    private readonly Vector3 _target = request.Target;
    private readonly int _forcedEdge = request.ForcedEdge;
    private readonly IReadOnlyList<Move>? _forcedMoves = request.ForcedMoves;
    private readonly JumpRepair _repair = request.Repair;

    public RequestOutcome Run()
    {
        PlanResult? result = null;
        IReadOnlyList<Move> moves;
        try
        {
            if (_forcedEdge >= 0)
            {
                // One given jump of the roadmap: no search.
                Roadmap roadmap = kind.Roadmap;
                RoadmapEdge edge = roadmap.Edges[_forcedEdge];
                moves = [new Jump(roadmap.Nodes[edge.From], roadmap.Nodes[edge.To], edge.Arc)];
            }
            else if (_forcedMoves is { } forced)
            {
                moves = forced; // the given moves: no search
            }
            else
            {
                result = search.Search(_start, _target, _repair);
                if (result.Status != PlannerStatus.Exact || result.Moves.Count == 0)
                {
                    return new RequestOutcome(result, [], null, null, Searching: true);
                }

                moves = result.Moves;
            }
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            return new RequestOutcome(result, [], null, e, Searching: true);
        }

        try
        {
            return new RequestOutcome(result, moves, kind.PathAnimator.Animate(moves, frameRate), null, Searching: false);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            return new RequestOutcome(result, moves, null, e, Searching: false);
        }
    }
}
