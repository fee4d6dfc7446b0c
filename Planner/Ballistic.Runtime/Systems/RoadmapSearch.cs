using System.Numerics;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Runtime.Systems;

/// <summary>The searches of one character kind, on the tick thread: a path query over the kind's roadmap with reusable scratch.</summary>
internal sealed class RoadmapSearch
{
    private readonly CharacterKind _kind;
    private readonly PathQuery _query;
    private readonly QuerySettings _settings;

    public RoadmapSearch(CharacterKind kind, WorldSettings world)
    {
        _kind = kind;
        _query = new PathQuery(kind.Scene, kind.Roadmap);
        _settings = new QuerySettings
        {
            Tolerance = world.Tolerance,
            CanStand = kind.Animator.CanStand,
            Locomotion = world.Locomotion,
            JumpEffort = world.JumpEffort,
        };
    }

    /// <summary>The query settings of every search: the world's tolerance, locomotion and jump effort, the kind's standing check.</summary>
    public QuerySettings Settings => _settings;

    /// <summary>
    /// Searches from the stance <paramref name="start"/> to the point <paramref name="target"/>; <paramref name="work"/> is the search's
    /// cost in expansions (plus the placement cost when the target is not a roadmap node).
    /// </summary>
    /// <remarks>The request's repair record gives the moves to avoid and, once its walks failed, jumps only.</remarks>
    public PlanResult Search(RoadmapNode start, Vector3 target, JumpRepair repair, int placementCost, out int work)
    {
        PlanResult result;
        QuerySettings settings = repair.Adjust(_settings);
        IReadOnlySet<(int From, int To)> rejected = repair.Excluded;
        if (_kind.Roadmap.FindNode(target, _settings.Tolerance) is int goal)
        {
            result = _query.Plan(start, _kind.Roadmap.Nodes[goal], settings, rejected);
            work = result.Expansions;
        }
        else
        {
            result = _query.Plan(start, target, settings, rejected);
            work = result.Expansions + placementCost;
        }

        return result;
    }
}
