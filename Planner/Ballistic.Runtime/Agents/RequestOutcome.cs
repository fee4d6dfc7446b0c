using Ballistic.Planner.Animation;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime.Paths;

namespace Ballistic.Runtime.Agents;

/// <summary>What a path request's job found, delivered to its agent on the request's due tick.</summary>
/// <param name="Search">The last search's result (with what was set aside), or that of the given moves; <c>null</c> when the job threw.</param>
/// <param name="Moves">The moves of the clean path; empty when there is none (a failure, or the agent on its target already).</param>
/// <param name="Animation">The clean path's whole-body animation; <c>null</c> when there is none.</param>
/// <param name="Error">An exception the search or animator threw (never expected), or <c>null</c>.</param>
/// <param name="Searching">True when <paramref name="Error"/> came from the search, false from the animator.</param>
/// <param name="Path">The clean path as its agent follows it (<see cref="Moves"/> animated by <see cref="Animation"/>, to the request's target), made by the job's thread so that the tick delivering it allocates nothing; <c>null</c> when there is none.</param>
internal sealed record RequestOutcome(PlanResult? Search, IReadOnlyList<Move> Moves, JumpAnimation? Animation, Exception? Error, bool Searching, AgentPath? Path = null);
