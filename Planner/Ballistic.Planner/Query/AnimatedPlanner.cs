using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Query;

/// <summary>
/// The plan use case: query a roadmap, animate the whole body along the path, and repair lazily: a jump whose
/// animation is not clean (no contact pose passing the no-slip test, a bone through the level, a contact that
/// cannot be held or stepped to) is set aside for this request and A* searches again, for a few rounds. The result
/// is exact only with a clean animation; otherwise a failure naming every jump set aside and why. Never a success
/// whose animation cuts through the level.
/// </summary>
public sealed class AnimatedPlanner
{
    /// <summary>Searches made at most per request.</summary>
    public const int DefaultRounds = 6;

    private readonly PlanningScene _scene;

    /// <summary>Creates the use case for an animator on a scene of its character's reduced model.</summary>
    public AnimatedPlanner(PlanningScene scene, IJumpAnimator animator)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(animator);
        _scene = scene;
        Animator = animator;
    }

    /// <summary>The whole-body animator.</summary>
    public IJumpAnimator Animator { get; }

    /// <summary>
    /// Bakes a roadmap from the requested start and goal until they connect, plans and animates; when no path
    /// animates cleanly (or none exists yet), bakes on (the same seed: the larger roadmap holds the smaller one) to
    /// twice the nodes, up to <see cref="BakeSettings.MaxNodes"/>, and plans again. A route found on the first
    /// connection's sparse roadmap may wander: when it runs more than <see cref="DetourLimit"/> times the straight
    /// distance between its ends (a frog hopping round a beam's end and under it to jump up onto its middle, 2.5
    /// times, 9 hops), the roadmap is baked on the same way, with stances on the ground within a hop of an end raised
    /// above the other (<see cref="BakeSettings.ApproachRaisedEnds"/>), and the request planned again, as long as that
    /// shortens the route and the budget allows (the frog: 196 nodes, 2 hops, the straight distance; 5 hops on 392
    /// nodes without the stances near the raised goal); the shortest exact plan is kept. Before any of this, with
    /// <see cref="BakeSettings.Refine"/> (the default), a first connection whose route jumps where a walk might cost less
    /// (<see cref="Costly"/>) is baked on the same way while each larger roadmap's route, searched but not animated,
    /// costs at least <see cref="CheaperBy"/> less (a hedge vaulted on the first connection, walked round on 64 nodes);
    /// the cheapest roadmap's route is then animated and repaired as above.
    /// </summary>
    /// <param name="from">Requested start point, world metres.</param>
    /// <param name="to">Requested goal point, world metres.</param>
    /// <param name="bake">Seed, threads, node budget (<see cref="BakeSettings.MaxNodes"/>, required) and endpoint tolerance; its start, goal and stop-when-connected are set here.</param>
    /// <param name="termination">
    /// An extra condition stopping every bake and every plan (cancellation, a time budget, measured from the start
    /// of each bake and each plan); a plan it stops has its status and reason.
    /// </param>
    /// <param name="progress">Receives the bakes' progress.</param>
    /// <param name="query">
    /// The plans' other settings (jump costs, connections); <c>null</c> for the defaults. Their tolerance and
    /// locomotion are the bake's.
    /// </param>
    /// <exception cref="ArgumentException">The settings are invalid or have no node budget.</exception>
    public (AnimatedPlan Plan, BakeResult Bake) BakeAndPlan(Vector3 from, Vector3 to, BakeSettings bake, TerminationCondition? termination = null, IProgress<BakeState>? progress = null, QuerySettings? query = null)
    {
        ArgumentNullException.ThrowIfNull(bake);
        if (bake.MaxNodes is not int budget)
        {
            throw new ArgumentException("BakeAndPlan needs a node budget (BakeSettings.MaxNodes).", nameof(bake));
        }

        var baker = new RoadmapBaker(_scene);
        bake = bake with { CanStand = Animator.CanStand };
        query = (query ?? new QuerySettings()) with { Tolerance = bake.Tolerance, Locomotion = bake.Locomotion };
        BakeResult result = baker.Bake(bake with { Start = from, Goal = to, StopWhenConnected = true }, termination, progress);
        PathQuery? refined = null;
        (BakeResult Bake, PathQuery Search, float Cost)? unrefined = null;
        if (bake.Refine)
        {
            (result, refined, unrefined) = Refined(baker, result, from, to, bake, budget, query, termination, progress);
        }

        (AnimatedPlan Plan, BakeResult Bake, float Detour)? best = null;
        bool shorter = false;
        while (true)
        {
            if (result.Status is PlannerStatus.InvalidStart or PlannerStatus.InvalidGoal or PlannerStatus.Cancelled)
            {
                if (best is { } kept)
                {
                    return (kept.Plan, kept.Bake);
                }

                var failed = new PlanResult(result.Status, result.Reason, null, null, [], result.Elapsed) { StartPlacement = result.StartPlacement, GoalPlacement = result.GoalPlacement };
                return (new AnimatedPlan(failed, null, [], 0), result);
            }

            AnimatedPlan plan = PlanOn(refined ?? new PathQuery(_scene, result.Roadmap), from, to, query, DefaultRounds, 60f, termination);
            refined = null;
            if (unrefined is { } first && plan.Result.Status is not (PlannerStatus.Cancelled or PlannerStatus.Timeout) && !(plan.Result.Status == PlannerStatus.Exact && plan.Result.Cost < first.Cost))
            {
                // The refined roadmap's route lost what it saved in repair (its walks set aside for jumps): the first
                // connection's route is animated too, and the cheaper exact plan kept (the first at an equal cost).
                AnimatedPlan firstPlan = PlanOn(first.Search, from, to, query, DefaultRounds, 60f, termination);
                if (firstPlan.Result.Status == PlannerStatus.Exact && (plan.Result.Status != PlannerStatus.Exact || firstPlan.Result.Cost <= plan.Result.Cost))
                {
                    (plan, result) = (firstPlan, first.Bake);
                }
            }

            unrefined = null;
            int nodes = result.Roadmap.Nodes.Count;
            if (plan.Result.Status == PlannerStatus.Exact)
            {
                float detour = Detour(plan.Result);
                if (best is { } before && detour >= before.Detour)
                {
                    // Baking on did not shorten the route: the one found before is kept.
                    return (before.Plan, before.Bake);
                }

                shorter |= best is null && detour > DetourLimit;
                best = (plan, result, detour);
                if (!shorter || detour <= DetourLimit || nodes >= budget || result.Status != PlannerStatus.Exact)
                {
                    return (plan, result);
                }
            }
            else if (best is { } found)
            {
                // A larger roadmap's plan that does not animate: the shorter exact one found before is kept.
                return (found.Plan, found.Bake);
            }
            else if (plan.Result.Status is PlannerStatus.Cancelled or PlannerStatus.Timeout || nodes >= budget || result.Status != PlannerStatus.Exact)
            {
                return (plan, result);
            }

            result = BakeOn(baker, bake with { ApproachRaisedEnds = shorter }, from, to, nodes, budget, termination, progress);
        }
    }

    /// <summary>
    /// <see cref="BakeSettings.Refine"/>: the roadmap <paramref name="connected"/> (baked until the start reached the
    /// goal), or one baked on from it while its searched route jumps and costs more than a walk could
    /// (<see cref="Costly"/>) and each larger roadmap's route costs at least <see cref="CheaperBy"/> less (twice the
    /// nodes each time, up to <paramref name="budget"/>); with the query that searched the roadmap kept, for its plan to
    /// reuse, and, when a larger roadmap was kept, the first connection with its query and its route's cost (for
    /// <see cref="BakeAndPlan"/> to fall back on when the cheaper route does not animate as cheaply). Routes are only
    /// searched here, never animated.
    /// </summary>
    private (BakeResult Bake, PathQuery? Search, (BakeResult Bake, PathQuery Search, float Cost)? First) Refined(RoadmapBaker baker, BakeResult connected, Vector3 from, Vector3 to, BakeSettings bake, int budget, QuerySettings query, TerminationCondition? termination, IProgress<BakeState>? progress)
    {
        if (connected.Status != PlannerStatus.Exact || bake.Locomotion != Locomotion.WalkAndJump)
        {
            return (connected, null, null);
        }

        var search = new PathQuery(_scene, connected.Roadmap);
        PlanResult route = search.Plan(from, to, Searched(query), rejected: null, termination);
        (BakeResult Bake, PathQuery Search, float Cost) first = (connected, search, route.Cost);
        while (route.Status == PlannerStatus.Exact && Costly(route) && connected.Roadmap.Nodes.Count < budget)
        {
            BakeResult larger = BakeOn(baker, bake, from, to, connected.Roadmap.Nodes.Count, budget, termination, progress);
            if (larger.Status != PlannerStatus.Exact)
            {
                break;
            }

            var largerSearch = new PathQuery(_scene, larger.Roadmap);
            PlanResult cheaper = largerSearch.Plan(from, to, Searched(query), rejected: null, termination);
            if (cheaper.Status != PlannerStatus.Exact || !Cheaper(cheaper, route))
            {
                break;
            }

            (connected, search, route) = (larger, largerSearch, cheaper);
        }

        return (connected, search, ReferenceEquals(search, first.Search) ? null : first);
    }

    /// <summary>
    /// The roadmap for the request baked on past <paramref name="nodes"/> (the same seed: it holds the smaller one), to
    /// twice the nodes, at least 64, at most <paramref name="budget"/>.
    /// </summary>
    private static BakeResult BakeOn(RoadmapBaker baker, BakeSettings bake, Vector3 from, Vector3 to, int nodes, int budget, TerminationCondition? termination, IProgress<BakeState>? progress) =>
        baker.Bake(bake with { Start = from, Goal = to, StopWhenConnected = false, MaxNodes = Math.Min(budget, Math.Max(64, 2 * nodes)) }, termination, progress);

    /// <summary>The query settings a plan searches with: the animator's checks of where the body can stand and push.</summary>
    private QuerySettings Searched(QuerySettings query) => query with { CanStand = Animator.CanStand, CanPush = Animator.CanPush };

    /// <summary>
    /// Whether a route that jumps costs more (<see cref="PlanResult.Cost"/>) than walking <see cref="DetourLimit"/>
    /// times the straight distance between its ends would (at the character's walking speed, on surfaces of no extra
    /// cost): a walk round might then be cheaper, and the first connection's roadmap, grown only until the start
    /// reached the goal, holds none. A hedge maze's hedge vaulted on the first connection, though walking round its open
    /// end costs less by the same costs, is such a route (informed sampling: a better route lies within what the best
    /// one found costs).
    /// </summary>
    private bool Costly(PlanResult plan)
    {
        float speed = _scene.Character.Walking.Speed;
        if (!(speed > 0f) || plan.Jumps.Count == 0 || plan.Moves.Count == 0)
        {
            return false;
        }

        return plan.Cost > DetourLimit * Straight(plan) / speed;
    }

    /// <summary>Whether <paramref name="plan"/> costs at least <see cref="CheaperBy"/> less than <paramref name="than"/> (<see cref="PlanResult.Cost"/>).</summary>
    private static bool Cheaper(PlanResult plan, PlanResult than) => plan.Cost < (1f - CheaperBy) * than.Cost;

    /// <summary>The share (5 %) by which a route found by baking on must cost less than the one before to be taken instead (<see cref="BakeAndPlan"/>).</summary>
    internal const float CheaperBy = 0.05f;

    /// <summary>
    /// Routes longer than this many times the straight distance between their ends (<see cref="Detour"/>) are planned
    /// again on a larger roadmap by <see cref="BakeAndPlan"/>.
    /// </summary>
    internal const float DetourLimit = 1.5f;

    /// <summary>
    /// How many times longer than the straight distance between its start and goal stances (their contact centres,
    /// on the ground plane; at least 1 m) <paramref name="plan"/>'s route runs across: each jump between its stances'
    /// contact centres and each walk along its path, on the ground plane.
    /// </summary>
    internal static float Detour(PlanResult plan)
    {
        if (plan.Moves.Count == 0)
        {
            return 1f;
        }

        float run = 0f;
        foreach (Move move in plan.Moves)
        {
            if (move is Walk walk)
            {
                for (int i = 1; i < walk.Path.Count; i++)
                {
                    run += Across(walk.Path[i - 1], walk.Path[i]);
                }
            }
            else
            {
                run += Across(move.From.ContactCentre, move.To.ContactCentre);
            }
        }

        return run / Straight(plan);
    }

    /// <summary>The distance (metres, on the ground plane, at least 1 m) between the contact centres of <paramref name="plan"/>'s first and last stances.</summary>
    private static float Straight(PlanResult plan) => MathF.Max(1f, Across(plan.Moves[0].From.ContactCentre, plan.Moves[^1].To.ContactCentre));

    /// <summary>The distance (metres) from <paramref name="a"/> to <paramref name="b"/> on the ground plane.</summary>
    private static float Across(Vector3 a, Vector3 b) => new Vector2(b.X - a.X, b.Z - a.Z).Length();

    /// <summary>Plans from <paramref name="from"/> to <paramref name="to"/> (world metres) on <paramref name="roadmap"/> and animates the path.</summary>
    /// <param name="roadmap">A roadmap baked for the scene's level and character.</param>
    /// <param name="from">Requested start point, on or near a surface, world metres.</param>
    /// <param name="to">Requested goal point, world metres.</param>
    /// <param name="settings">Query settings (endpoint tolerance, connections).</param>
    /// <param name="rounds">Searches made at most, besides those (at most two) whose walks did not animate cleanly.</param>
    /// <param name="frameRate">Animation frames per second.</param>
    /// <param name="termination">
    /// Stops the request early (its time and cancellation parts, measured from the request's start), checked before
    /// every search, inside it, and before every animation: the result then has that condition's status
    /// (<see cref="PlannerStatus.Cancelled"/>, <see cref="PlannerStatus.Timeout"/>) and reason. <c>null</c> for none.
    /// </param>
    /// <exception cref="ArgumentException">The roadmap was baked for another level or character, or a count is not positive.</exception>
    public AnimatedPlan Plan(Roadmap roadmap, Vector3 from, Vector3 to, QuerySettings? settings = null, int rounds = DefaultRounds, float frameRate = 60f, TerminationCondition? termination = null)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(rounds, 1);
        return PlanOn(new PathQuery(_scene, roadmap), from, to, settings ?? new QuerySettings(), rounds, frameRate, termination);
    }

    /// <summary><see cref="Plan(Roadmap, Vector3, Vector3, QuerySettings?, int, float, TerminationCondition?)"/> on <paramref name="query"/> (one that may have searched the same roadmap before: <see cref="BakeAndPlan"/>'s refining search).</summary>
    private AnimatedPlan PlanOn(PathQuery query, Vector3 from, Vector3 to, QuerySettings settings, int rounds, float frameRate, TerminationCondition? termination)
    {
        settings = Searched(settings);
        var repair = new JumpRepair(query.Roadmap.Nodes.Count + 2);
        using var job = new PlanJob((r, stop) => query.PlanSteps(from, to, r.Adjust(settings), r.Excluded, stop), Animator, repair, rounds, frameRate) { Termination = termination };
        (PlanResult result, JumpAnimation? animation, int round) = job.Run();
        return new AnimatedPlan(result, animation, repair.SetAside, round);
    }
}
