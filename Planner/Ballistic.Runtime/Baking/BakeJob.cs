using System.Diagnostics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.IO;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;

namespace Ballistic.Runtime.Baking;

/// <summary>
/// A roadmap bake on a background thread, for the editor: <see cref="Start"/> it, poll <see cref="IsBaking"/>,
/// <see cref="Progress"/> and <see cref="Outcome"/> each frame (or await <see cref="Completion"/>), and
/// <see cref="Cancel"/> it. The bake builds the <see cref="PlanningScene"/> with its defaults (as the runtime does)
/// and runs the planner's <see cref="RoadmapBaker"/>, deterministic whatever the thread count.
/// </summary>
/// <remarks>
/// Nothing escapes the bake's thread: invalid settings and any exception become a <see cref="BakeJobStatus.Failed"/>
/// outcome with a one-line reason. Only a success carries data: a failed or cancelled bake hands out nothing, so the
/// caller keeps its previous roadmap. <see cref="Cancel"/> called before the outcome is set always ends in
/// <see cref="BakeJobStatus.Cancelled"/>. A bake that ends on its time limit with nodes succeeds (the time limit is
/// a budget, as in the command line's bake); one that places no node fails. Disposing cancels and waits for the
/// thread. Every member is thread-safe.
/// </remarks>
public sealed class BakeJob : IDisposable
{
    private readonly CancellationTokenSource _cancel = new();
    private readonly object _gate = new(); // not System.Threading.Lock, which net8.0 lacks
    private readonly TaskCompletionSource<BakeOutcome> _completion = new(TaskCreationOptions.RunContinuationsAsynchronously);
    private readonly Stopwatch _clock = Stopwatch.StartNew();
    private readonly ProgressTracker _tracker;
    private readonly Task _worker;
    private volatile BakeOutcome? _outcome;
    private bool _disposed;

    private BakeJob(Level level, ReducedCharacter character, BakeSettings settings)
    {
        _tracker = new ProgressTracker(settings.MaxNodes, settings.TimeLimit, _clock);
        _worker = Task.Factory.StartNew(() => Work(level, character, settings), CancellationToken.None, TaskCreationOptions.LongRunning, TaskScheduler.Default);
    }

    /// <summary>True until the outcome is set.</summary>
    public bool IsBaking => _outcome is null;

    /// <summary>Where the bake stands; any thread, any time.</summary>
    public BakeProgress Progress => _tracker.Current;

    /// <summary>How the bake ended, or <c>null</c> while it runs (poll this each frame).</summary>
    public BakeOutcome? Outcome => _outcome;

    /// <summary>Completes with the outcome; never faults nor is cancelled. Continuations run on the thread pool, not the caller's thread.</summary>
    public Task<BakeOutcome> Completion => _completion.Task;

    /// <summary>Starts a bake on a new background thread.</summary>
    /// <param name="level">The level (e.g. <see cref="SourceGeometry.Build"/>).</param>
    /// <param name="character">The character (e.g. <see cref="CharacterAsset.Load"/>).</param>
    /// <param name="settings">Seed, node budget, time limit, threads (e.g. <see cref="Settings"/>); invalid ones, or ones with neither a node budget nor a time limit, give a failed outcome.</param>
    public static BakeJob Start(Level level, ReducedCharacter character, BakeSettings settings)
    {
        ArgumentNullException.ThrowIfNull(level);
        ArgumentNullException.ThrowIfNull(character);
        ArgumentNullException.ThrowIfNull(settings);
        return new BakeJob(level, character, settings);
    }

    /// <summary>
    /// Bakes on the calling thread (a node's <c>BakeRoadmap(onThread: false)</c>, the CLI's <c>bake</c>), with the
    /// same outcome a <see cref="BakeJob"/> would give: the one place a bake's ending is classified.
    /// </summary>
    /// <param name="level">The level.</param>
    /// <param name="character">The character.</param>
    /// <param name="settings">Seed, node budget, time limit, threads.</param>
    /// <param name="cancellation">Cancels the bake; a cancellation seen before the outcome gives <see cref="BakeJobStatus.Cancelled"/>.</param>
    /// <param name="progress">Also told the baker's progress (a console line), or <c>null</c>.</param>
    public static BakeOutcome Run(Level level, ReducedCharacter character, BakeSettings settings, CancellationToken cancellation = default, IProgress<BakeState>? progress = null)
    {
        ArgumentNullException.ThrowIfNull(level);
        ArgumentNullException.ThrowIfNull(character);
        ArgumentNullException.ThrowIfNull(settings);
        var clock = Stopwatch.StartNew();
        BakeOutcome outcome = Execute(level, character, settings, cancellation, new ProgressTracker(settings.MaxNodes, settings.TimeLimit, clock, progress), clock);
        return cancellation.IsCancellationRequested && outcome.Status != BakeJobStatus.Cancelled ? BakeOutcome.Cancellation(outcome.ElapsedSeconds, outcome.Result) : outcome;
    }

    /// <summary>
    /// Bake settings from the primitive values an engine resource exports.
    /// </summary>
    /// <param name="seed">Seed of every random choice.</param>
    /// <param name="maxNodes">Node budget; 0 for none (then a time limit must stop the bake).</param>
    /// <param name="timeLimitSeconds">Time limit in seconds; 0 for none.</param>
    /// <param name="threads">Worker threads; 0 for all cores but one (the editor's), at least one.</param>
    /// <exception cref="ArgumentException">A value is negative or not finite, or neither a node budget nor a time limit is given.</exception>
    public static BakeSettings Settings(int seed, int maxNodes, double timeLimitSeconds, int threads = 0)
    {
        if (maxNodes < 0)
        {
            throw new ArgumentException($"The node budget must be positive, or 0 for none, not {maxNodes}.");
        }

        if (!(timeLimitSeconds >= 0d) || !double.IsFinite(timeLimitSeconds) || timeLimitSeconds > TimeSpan.MaxValue.TotalSeconds / 2)
        {
            throw new ArgumentException($"The time limit must be a finite number of seconds, or 0 for none, not {timeLimitSeconds}.");
        }

        if (threads < 0)
        {
            throw new ArgumentException($"The thread count must be positive, or 0 for all cores but one, not {threads}.");
        }

        if (maxNodes == 0 && timeLimitSeconds == 0d)
        {
            throw new ArgumentException("Nothing would stop this bake: give a node budget, a time limit or both.");
        }

        return new BakeSettings
        {
            Seed = seed,
            MaxNodes = maxNodes > 0 ? maxNodes : null,
            TimeLimit = timeLimitSeconds > 0d ? TimeSpan.FromSeconds(timeLimitSeconds) : null,
            Threads = threads > 0 ? threads : Math.Max(1, Environment.ProcessorCount - 1),
        };
    }

    /// <summary>
    /// Asks the bake to stop; it ends <see cref="BakeJobStatus.Cancelled"/> unless its outcome was already set. Returns
    /// at once (the bake notices between work items, usually within milliseconds).
    /// </summary>
    public void Cancel()
    {
        lock (_gate)
        {
            if (_outcome is null && !_disposed)
            {
                _cancel.Cancel();
            }
        }
    }

    /// <summary>Blocks until the bake ends and returns its outcome.</summary>
    public BakeOutcome Wait() => _completion.Task.GetAwaiter().GetResult();

    /// <summary>Cancels the bake if it runs and waits for its thread to end.</summary>
    public void Dispose()
    {
        Cancel();
        _worker.Wait();
        lock (_gate)
        {
            if (_disposed)
            {
                return;
            }

            _disposed = true;
        }

        _cancel.Dispose();
    }

    private void Work(Level level, ReducedCharacter character, BakeSettings settings)
    {
        BakeOutcome outcome = Execute(level, character, settings, _cancel.Token, _tracker, _clock);
        lock (_gate)
        {
            if (_cancel.IsCancellationRequested && outcome.Status != BakeJobStatus.Cancelled)
            {
                outcome = BakeOutcome.Cancellation(outcome.ElapsedSeconds);
            }

            _tracker.Finish(outcome);
            _outcome = outcome;
        }

        _completion.SetResult(outcome);
    }

    /// <summary>The bake itself; never throws.</summary>
    private static BakeOutcome Execute(Level level, ReducedCharacter character, BakeSettings settings, CancellationToken cancellation, ProgressTracker tracker, Stopwatch clock)
    {
        try
        {
            settings.Validate();
            if (settings.MaxNodes is null && settings.TimeLimit is null && !settings.StopWhenConnected)
            {
                // The baker would accept the cancellation condition alone as a stop: a bake that ends only when cancelled.
                return BakeOutcome.Failure("Nothing would stop this bake: give a node budget, a time limit or both.", clock.Elapsed.TotalSeconds);
            }

            var scene = PlanningScene.Create(level, character);
            if (cancellation.IsCancellationRequested)
            {
                return BakeOutcome.Cancellation(clock.Elapsed.TotalSeconds);
            }

            BakeResult result = new RoadmapBaker(scene).Bake(settings, TerminationCondition.Cancellation(cancellation), tracker);
            double elapsed = clock.Elapsed.TotalSeconds;
            if (result.Status == PlannerStatus.Cancelled || cancellation.IsCancellationRequested)
            {
                return BakeOutcome.Cancellation(elapsed, result);
            }

            if (result.Status is PlannerStatus.InvalidStart or PlannerStatus.InvalidGoal)
            {
                return BakeOutcome.Failure(result.Reason, elapsed, result);
            }

            if (result.Roadmap.Nodes.Count == 0)
            {
                return BakeOutcome.Failure(result.Status == PlannerStatus.NoPath
                    ? $"{character.Name} can stand nowhere on the level {level.Source}: no valid pose in {result.SamplesDrawn} samples"
                    : $"the bake placed no node before it stopped ({result.Reason})", elapsed, result);
            }

            return BakeOutcome.Success(RoadmapData.FromBake(result, settings), result, elapsed);
        }
        catch (Exception e)
        {
            string reason = e is BallisticInputException or ArgumentException ? e.Message : $"{e.GetType().Name}: {e.Message}";
            return BakeOutcome.Failure(reason, clock.Elapsed.TotalSeconds, error: e);
        }
    }
}
