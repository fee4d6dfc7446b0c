using Ballistic.Planner.Animation;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Runtime.Systems;

/// <summary>
/// What one world's delivered path requests found about one kind's roadmap stances: those the body cannot crouch on
/// (no jump takes off from them) or absorb a landing on (none lands on them), each with the animator's reason. Each
/// request the world starts afterwards sets them aside before its first search (<see cref="JumpRepair.Remember"/>),
/// so that an agent standing where it cannot crouch is told so after one search instead of animating and repairing
/// a path for every target it is sent to. Learned and taught on the tick thread, in delivery and start order, so that
/// the world stays deterministic whatever its threads. Of one kind (its body and its roadmap): forgotten when the
/// world's kind changes (a rebake, or another kind in its slot).
/// </summary>
internal sealed class StanceLessons(CharacterKind kind)
{
    private readonly SortedDictionary<int, string> _noTakeoffs = [];
    private readonly SortedDictionary<int, string> _noLandings = [];

    /// <summary>The kind whose body the lessons are about, on whose roadmap's node ids.</summary>
    public CharacterKind Kind { get; } = kind;

    private Roadmap Roadmap => Kind.Roadmap;

    /// <summary>Keeps the roadmap stances <paramref name="repair"/> (a delivered request's) set aside, with their reasons; placed stances (ids past the roadmap's) are the request's own and are not kept.</summary>
    public void Learn(JumpRepair repair)
    {
        if (Learn(repair.StancesSetAside(ProblemStance.Takeoff), _noTakeoffs) | Learn(repair.StancesSetAside(ProblemStance.Landing), _noLandings))
        {
            Taught = new TaughtStances([.. _noTakeoffs.Select(p => (p.Key, p.Value))], [.. _noLandings.Select(p => (p.Key, p.Value))]);
        }
    }

    /// <summary>Every stance learned so far, in node order: what a request started now is taught (<see cref="TaughtStances.Teach"/>).</summary>
    public TaughtStances Taught { get; private set; } = TaughtStances.None;

    private bool Learn(Dictionary<int, string> found, SortedDictionary<int, string> into)
    {
        bool learned = false;
        foreach ((int node, string reason) in found)
        {
            if (node >= 0 && node < Roadmap.Nodes.Count)
            {
                learned |= into.TryAdd(node, reason);
            }
        }

        return learned;
    }
}
