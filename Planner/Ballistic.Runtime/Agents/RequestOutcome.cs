using Ballistic.Planner.Animation;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Runtime.Agents;

/// <summary>What a path request's job found, delivered to its agent on the request's due tick.</summary>
/// <param name="Search">The search's result; <c>null</c> for given moves (no search).</param>
/// <param name="Moves">The moves found or given; empty when the search failed or found the agent on its target.</param>
/// <param name="Animation">The moves' whole-body animation; <c>null</c> when there are no moves to animate or the job failed.</param>
/// <param name="Error">An exception the search or animator threw (never expected), or <c>null</c>.</param>
/// <param name="Searching">True when <paramref name="Error"/> came from the search, false from the animator.</param>
internal sealed record RequestOutcome(PlanResult? Search, IReadOnlyList<Move> Moves, JumpAnimation? Animation, Exception? Error, bool Searching);
