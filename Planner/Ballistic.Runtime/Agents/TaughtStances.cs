using Ballistic.Planner.Animation;
using Ballistic.Planner.Query;

namespace Ballistic.Runtime.Agents;

/// <summary>
/// The stances a kind's earlier requests found the body cannot crouch on (no takeoff from them) or absorb a landing on
/// (no landing on them), with the animator's reasons, in node order, as learned at one moment
/// (<see cref="Systems.StanceLessons.Taught"/>): what a request started then is taught. Never changed once made, so a
/// request takes it on the tick and its job teaches it on any thread.
/// </summary>
/// <param name="noTakeoffs">Node ids no jump takes off from, with why, in node order.</param>
/// <param name="noLandings">Node ids no jump lands on, with why, in node order.</param>
internal sealed class TaughtStances((int Node, string Reason)[] noTakeoffs, (int Node, string Reason)[] noLandings)
{
    /// <summary>No lesson.</summary>
    public static TaughtStances None { get; } = new([], []);

    /// <summary>Sets aside in <paramref name="repair"/> (a request's, before its first search) every stance learned, in node order.</summary>
    public void Teach(JumpRepair repair)
    {
        foreach ((int node, string reason) in noTakeoffs)
        {
            repair.Remember(node, ProblemStance.Takeoff, reason);
        }

        foreach ((int node, string reason) in noLandings)
        {
            repair.Remember(node, ProblemStance.Landing, reason);
        }
    }
}
