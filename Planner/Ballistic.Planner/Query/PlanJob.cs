using System.Diagnostics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Query;

/// <summary>
/// One request's plan-and-repair loop, the one loop behind <see cref="AnimatedPlanner.Plan"/> (run to the end on the
/// caller's thread) and the runtime's path requests (run in the background): search, animate the moves found, and,
/// while the body cannot perform one of them, set it aside (<see cref="JumpRepair"/>) and search again, up to a number
/// of searches. The first round may perform given moves instead of searching.
/// </summary>
internal sealed class PlanJob(Func<JumpRepair, TerminationCondition?, PlanResult> search, IJumpAnimator animator, JumpRepair repair, int rounds, float frameRate)
{
    /// <summary>Moves to perform in the first round instead of a search (a scripted path); later rounds search.</summary>
    public IReadOnlyList<Move>? Given { get; init; }

    /// <summary>Stops the request early, seen with the time since it began (before every search, inside it, before every animation); <c>null</c> for none.</summary>
    public TerminationCondition? Termination { get; init; }

    /// <summary>What the job is doing ("searching", "animating"): where an exception it throws came from.</summary>
    public string Phase { get; private set; } = "searching";

    /// <summary>Runs the loop: the last search's result (its reason saying what was set aside), the clean animation when one was found, and the rounds made.</summary>
    public (PlanResult Result, JumpAnimation? Animation, int Rounds) Run()
    {
        var clock = Stopwatch.StartNew();

        // The condition sees the time since this request began, not since each search began.
        TerminationCondition? stop = Termination is null ? null : new Elapsed(Termination, clock);
        PlanResult result = Given is { Count: > 0 } given
            ? new PlanResult(PlannerStatus.Exact, $"{given.Count} given moves", given[0].From, given[^1].To, given, TimeSpan.Zero)
            : search(repair, stop);
        for (int round = 1; ; round++)
        {
            if (result.Status is PlannerStatus.Cancelled or PlannerStatus.Timeout)
            {
                return (result with { Elapsed = clock.Elapsed }, null, round);
            }

            if (result.Status != PlannerStatus.Exact)
            {
                PlanResult failed = repair.SearchFailed(result.Reason) is string repaired
                    ? result with { Status = PlannerStatus.AnimationFailed, Reason = repaired }
                    : result;
                return (failed with { Elapsed = clock.Elapsed }, null, round);
            }

            if (result.Moves.Count == 0)
            {
                return (result with { Elapsed = clock.Elapsed }, null, round);
            }

            if (stop is not null && stop.ShouldStopNow(clock.Elapsed, out PlannerStatus status, out string reason))
            {
                return (result with { Status = status, Reason = reason, Moves = [], Elapsed = clock.Elapsed }, null, round);
            }

            Phase = "animating";
            JumpAnimation animation = animator.Animate(result.Moves, frameRate);
            if (animation.IsClean)
            {
                // The moves as animated: a walk slowed where its steps shorten takes longer, and a jump's stances are
                // those its takeoff and landing stand on (JumpAnimator).
                return (result with { Reason = result.Reason + repair.SuccessNote(), Moves = animation.Moves, Elapsed = clock.Elapsed }, animation, round);
            }

            repair.Reject(result.Moves, animation);
            if (repair.IsExhausted(round, rounds))
            {
                PlanResult failed = result with
                {
                    Status = PlannerStatus.AnimationFailed,
                    Reason = repair.RoundsExhausted(round),
                    Moves = [],
                    Elapsed = clock.Elapsed,
                };
                return (failed, null, round);
            }

            Phase = "searching";
            result = search(repair, stop);
        }
    }

    /// <summary>A condition polled with the time since a whole request began, whatever the time its caller passes.</summary>
    private sealed class Elapsed(TerminationCondition inner, Stopwatch clock) : TerminationCondition
    {
        public override bool ShouldStop(in BakeState state, out PlannerStatus status, out string reason) =>
            inner.ShouldStop(state with { Elapsed = clock.Elapsed }, out status, out reason);

        public override bool ShouldStopNow(TimeSpan elapsed, out PlannerStatus status, out string reason) =>
            inner.ShouldStopNow(clock.Elapsed, out status, out reason);
    }
}
