using System.Diagnostics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Query;

/// <summary>
/// One request's plan-and-repair loop, the one loop behind <see cref="AnimatedPlanner.Plan"/> (run to the end on the
/// caller's thread) and the runtime's path requests (run in the background, or advanced on the tick within a time
/// budget): search, animate the moves found, and, while the body cannot perform one of them, set it aside
/// (<see cref="JumpRepair"/>) and search again, up to a number of searches. The first round may perform given moves
/// instead of searching. The job is resumable: <see cref="Advance"/> runs it in steps (the search's placements,
/// steering calls, slices of A* and post-processing stages; the animation's jumps and walks) until a budget is spent,
/// and the next call goes on where it stopped; however it is sliced, it ends with the same outcome.
/// </summary>
internal sealed class PlanJob(Func<JumpRepair, TerminationCondition?, IEnumerable<PlanResult?>> search, IJumpAnimator animator, JumpRepair repair, int rounds, float frameRate) : IDisposable
{
    private IEnumerator<bool>? _steps;

    /// <summary>True while the current <see cref="Advance"/> call runs the job to its end (no slice).</summary>
    private bool _whole;

    /// <summary>Moves to perform in the first round instead of a search (a scripted path); later rounds search.</summary>
    public IReadOnlyList<Move>? Given { get; init; }

    /// <summary>Stops the request early, seen with the time since it began (before every search, inside it, before every animation); <c>null</c> for none.</summary>
    public TerminationCondition? Termination { get; init; }

    /// <summary>What the job is doing ("searching", "animating"): where an exception it throws came from.</summary>
    public string Phase { get; private set; } = "searching";

    /// <summary>Steps taken so far (each a pause point of the search or the animation).</summary>
    public int Steps { get; private set; }

    /// <summary>
    /// The outcome once the job has ended, otherwise <c>null</c>: the last search's result (its reason saying what was
    /// set aside), the clean animation when one was found, and the rounds made.
    /// </summary>
    public (PlanResult Result, JumpAnimation? Animation, int Rounds)? Outcome { get; private set; }

    /// <summary>Runs the job to its end (from where it stands): its <see cref="Outcome"/>.</summary>
    public (PlanResult Result, JumpAnimation? Animation, int Rounds) Run()
    {
        Advance(slice: null);
        return Outcome ?? throw new InvalidOperationException("The plan job ended without an outcome.");
    }

    /// <summary>
    /// Advances the job one step at a time until it ends or <paramref name="slice"/> says to stop
    /// (<see cref="TerminationCondition.ShouldStopNow"/>, polled after each step with the time since this call began:
    /// a <see cref="TerminationCondition.Timeout"/> is a time budget); at least one step per call. <c>null</c> runs it to
    /// its end. True once the job has ended (<see cref="Outcome"/> set). The slice only pauses the job; the job's own
    /// <see cref="Termination"/> ends it.
    /// </summary>
    public bool Advance(TerminationCondition? slice)
    {
        if (Outcome is not null)
        {
            return true;
        }

        _whole = slice is null;
        _steps ??= Body().GetEnumerator();
        long began = Stopwatch.GetTimestamp();
        while (_steps.MoveNext())
        {
            Steps++;
            if (slice is not null && slice.ShouldStopNow(Stopwatch.GetElapsedTime(began), out _, out _))
            {
                return false;
            }
        }

        Dispose();
        return true;
    }

    /// <summary>Ends the job where it stands (a request dropped before its end), releasing what its search holds.</summary>
    public void Dispose()
    {
        _steps?.Dispose();
        _steps = null;
    }

    /// <summary>The loop in steps: a pause after each step of a search or an animation; <see cref="Outcome"/> set at its end.</summary>
    private IEnumerable<bool> Body()
    {
        var clock = Stopwatch.StartNew();

        // The condition sees the time since this request began, not since each search began.
        TerminationCondition? stop = Termination is null ? null : new Elapsed(Termination, clock);
        PlanResult? result = null;
        if (Given is { Count: > 0 } given)
        {
            result = new PlanResult(PlannerStatus.Exact, $"{given.Count} given moves", given[0].From, given[^1].To, given, TimeSpan.Zero);
        }
        else
        {
            foreach (bool pause in Stepwise.Pauses(search(repair, stop), found => result = found))
            {
                yield return pause;
            }
        }

        for (int round = 1; ; round++)
        {
            if (result is null)
            {
                throw new InvalidOperationException("A search ended without a result.");
            }

            if (result.Status is PlannerStatus.Cancelled or PlannerStatus.Timeout)
            {
                Outcome = (result with { Elapsed = clock.Elapsed }, null, round);
                yield break;
            }

            if (result.Status != PlannerStatus.Exact)
            {
                PlanResult failed = repair.SearchFailed(result.Reason) is string repaired
                    ? result with { Status = PlannerStatus.AnimationFailed, Reason = repaired }
                    : result;
                Outcome = (failed with { Elapsed = clock.Elapsed }, null, round);
                yield break;
            }

            if (result.Moves.Count == 0)
            {
                Outcome = (result with { Elapsed = clock.Elapsed }, null, round);
                yield break;
            }

            if (stop is not null && stop.ShouldStopNow(clock.Elapsed, out PlannerStatus status, out string reason))
            {
                Outcome = (result with { Status = status, Reason = reason, Moves = [], Elapsed = clock.Elapsed }, null, round);
                yield break;
            }

            Phase = "animating";
            JumpAnimation? animation = null;
            foreach (bool pause in Stepwise.Pauses(Animate(result.Moves), animated => animation = animated))
            {
                yield return pause;
            }

            if (animation is null)
            {
                throw new InvalidOperationException("An animation ended without a result.");
            }

            if (animation.IsClean)
            {
                // The moves as animated: a walk slowed where its steps shorten takes longer, and a jump's stances are
                // those its takeoff and landing stand on (JumpAnimator).
                Outcome = (result with { Reason = result.Reason + repair.SuccessNote(), Moves = animation.Moves, Elapsed = clock.Elapsed }, animation, round);
                yield break;
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
                Outcome = (failed, null, round);
                yield break;
            }

            yield return true;
            Phase = "searching";
            result = null;
            foreach (bool pause in Stepwise.Pauses(search(repair, stop), found => result = found))
            {
                yield return pause;
            }
        }
    }

    /// <summary>
    /// The moves' animation: in steps when the job is advanced in slices and the animator animates in steps
    /// (<see cref="IStepwiseAnimator"/>), otherwise in one (a job run whole takes the animator's own call: a path cache
    /// then lets requests for the same path wait for the one solving it instead of solving it again).
    /// </summary>
    private IEnumerable<JumpAnimation?> Animate(IReadOnlyList<Move> moves) =>
        !_whole && animator is IStepwiseAnimator stepwise ? stepwise.AnimateSteps(moves, frameRate) : Once(moves);

    private IEnumerable<JumpAnimation?> Once(IReadOnlyList<Move> moves)
    {
        yield return animator.Animate(moves, frameRate);
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
