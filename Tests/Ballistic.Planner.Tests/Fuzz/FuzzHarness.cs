using System.Collections.Concurrent;
using System.Diagnostics;
using Ballistic.Planner.IO;

namespace Ballistic.Planner.Tests.Fuzz;

/// <summary>
/// Runs fuzz cases: each case builds its input files from a seed in its own folder and loads them on a worker
/// thread. A case passes when the load succeeds or throws a <see cref="BallisticInputException"/> whose message is
/// one line without the runtime's words and which wraps no programming error (a null reference, an index out of
/// range, an argument, cast, overflow or invalid operation exception), within <see cref="CaseTime"/> and allocating
/// less than <see cref="CaseBytes"/>. Failures are returned with the seed and the mutations, to replay.
/// </summary>
internal static class FuzzHarness
{
    /// <summary>
    /// The most CPU time one case's load may take on its thread (<see cref="ThreadCpuTime"/>): a machine loaded by other
    /// work slows a case's wall clock, not its CPU time (a wall-clock limit failed 3 cases in 1,500 at load 20–40).
    /// </summary>
    public static readonly TimeSpan CaseTime = TimeSpan.FromSeconds(2);

    /// <summary>The most bytes one case may allocate.</summary>
    public const long CaseBytes = 512L << 20;

    private static readonly TimeSpan Hang = TimeSpan.FromSeconds(30);

    private static readonly string[] RuntimeWords =
    [
        "Object reference", "Index was out", "Specified argument", "An item with the same key", "Null character in path", "(Parameter '",
        "Value cannot be null", "Unable to cast", "Arithmetic operation", "Input string was not", "must be non-negative",
    ];

    /// <summary>Runs the case of every seed (two at a time) and returns the failures, each with its replay line.</summary>
    /// <param name="format">Names the case maker, for the replay line.</param>
    /// <param name="seeds">One case per seed.</param>
    /// <param name="folder">Where the cases write their files (a folder of their own each).</param>
    /// <param name="make">Writes a case's files from its mutator into its folder and returns the load to run.</param>
    /// <param name="limit">The CPU time one case may take; <see cref="CaseTime"/> when <c>null</c>.</param>
    public static (List<string> Failures, int Loaded) Run(string format, IReadOnlyList<int> seeds, string folder, Func<Mutator, string, Action> make, TimeSpan? limit = null)
    {
        var failures = new ConcurrentBag<(int Seed, string Text)>();
        int loaded = 0;
        Parallel.ForEach(seeds, new ParallelOptions { MaxDegreeOfParallelism = 2 }, seed =>
        {
            if (RunOne(format, seed, folder, make, out bool succeeded, limit) is string failure)
            {
                failures.Add((seed, failure));
            }
            else if (succeeded)
            {
                Interlocked.Increment(ref loaded);
            }
        });
        return ([.. failures.OrderBy(f => f.Seed).Select(f => f.Text)], loaded);
    }

    /// <summary>Runs one case; <c>null</c> when it passes, else what went wrong with the seed and mutations.</summary>
    /// <param name="format">Names the case maker, for the replay line.</param>
    /// <param name="seed">The case's seed.</param>
    /// <param name="folder">Where the case makes its own folder.</param>
    /// <param name="make">Writes the case's files and returns the load to run.</param>
    /// <param name="loaded">Whether the load succeeded (the mutated input was still valid).</param>
    /// <param name="limit">The CPU time the case may take; <see cref="CaseTime"/> when <c>null</c>.</param>
    public static string? RunOne(string format, int seed, string folder, Func<Mutator, string, Action> make, out bool loaded, TimeSpan? limit = null)
    {
        TimeSpan most = limit ?? CaseTime;
        string caseFolder = Path.Combine(folder, $"{format}-{seed}");
        Directory.CreateDirectory(caseFolder);
        var mutator = new Mutator(seed);
        Action load = make(mutator, caseFolder);
        Exception? thrown = null;
        TimeSpan elapsed = TimeSpan.Zero;
        long allocated = 0;
        var run = Task.Factory.StartNew(
            () =>
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                TimeSpan start = ThreadCpuTime();
                try
                {
                    load();
                }
                catch (Exception e)
                {
                    thrown = e;
                }

                elapsed = ThreadCpuTime() - start;
                allocated = GC.GetAllocatedBytesForCurrentThread() - before;
            },
            CancellationToken.None,
            TaskCreationOptions.LongRunning,
            TaskScheduler.Default);
        TimeSpan hang = most * 3 > Hang ? most * 3 : Hang;
        string? problem = !run.Wait(hang)
            ? $"still running after {hang.TotalSeconds} s"
            : elapsed > most
                ? $"took {elapsed.TotalSeconds:0.00} s of CPU time (limit {most.TotalSeconds} s)"
                : allocated > CaseBytes
                    ? $"allocated {allocated >> 20} MiB (limit {CaseBytes >> 20} MiB)"
                    : thrown is null ? null : Problem(thrown);
        loaded = problem is null && thrown is null;
        Record(format, seed, problem is not null ? "failed" : loaded ? "loaded" : "refused", $"{problem ?? thrown?.Message}\t{mutator.Description}");
        if (problem is null)
        {
            Directory.Delete(caseFolder, recursive: true);
            return null;
        }

        return $"{format} seed {seed}: {problem}\n    mutations: {mutator.Description}\n    replay: BALLISTIC_FUZZ_REPLAY={format}:{seed} dotnet test --filter Name=Replay";
    }

    /// <summary>
    /// With <c>BALLISTIC_FUZZ_OUTCOMES=file</c>, appends each case's outcome class to that file ("format seed loaded",
    /// "refused" or "failed", then a tab, the message, a tab and the mutations), so that two versions of the loaders can be compared case by case (sort both files, then diff).
    /// </summary>
    private static void Record(string format, int seed, string outcome, string? why)
    {
        if (Environment.GetEnvironmentVariable("BALLISTIC_FUZZ_OUTCOMES") is not { Length: > 0 } file)
        {
            return;
        }

        lock (OutcomeLock)
        {
            File.AppendAllText(file, string.Create(System.Globalization.CultureInfo.InvariantCulture, $"{format} {seed} {outcome}\t{why?.ReplaceLineEndings(" ")}\n"));
        }
    }

    private static readonly object OutcomeLock = new();

    /// <summary>What is wrong with an exception coming out of a load, or <c>null</c> when it is a proper input error.</summary>
    public static string? Problem(Exception e)
    {
        if (e is not BallisticInputException)
        {
            return $"{e.GetType().Name}: {e.Message} {FirstFrame(e)}";
        }

        if (string.IsNullOrWhiteSpace(e.Message) || e.Message.Contains('\n', StringComparison.Ordinal) || e.Message.Contains('\r', StringComparison.Ordinal))
        {
            return $"{e.GetType().Name} whose message is not one line: \"{e.Message}\"";
        }

        if (RuntimeWords.FirstOrDefault(w => e.Message.Contains(w, StringComparison.Ordinal)) is string word)
        {
            return $"{e.GetType().Name} with the runtime's words (\"{word}\"): {e.Message}";
        }

        // An input error that wraps one of these hides a bug of ours (an unchecked index, a null, a method left
        // unwritten): the case fails instead of counting as refused.
        for (Exception? inner = e.InnerException; inner is not null; inner = inner.InnerException)
        {
            if (inner is NullReferenceException or IndexOutOfRangeException or ArgumentException or InvalidOperationException or InvalidCastException
                or ArithmeticException or KeyNotFoundException or NotSupportedException or NotImplementedException)
            {
                return $"{e.GetType().Name} \"{e.Message}\" wraps a programming error, {inner.GetType().Name}: {inner.Message} {FirstFrame(inner)}";
            }
        }

        return null;
    }

    /// <summary>
    /// The CPU time the calling thread has run, from Linux's <c>/proc/thread-self/schedstat</c> (nanoseconds on a
    /// CPU); where that is missing (another system), the wall clock since the process started, so that a limit still holds.
    /// </summary>
    public static TimeSpan ThreadCpuTime()
    {
        try
        {
            string text = File.ReadAllText("/proc/thread-self/schedstat");
            int space = text.IndexOf(' ', StringComparison.Ordinal);
            if (space > 0 && long.TryParse(text.AsSpan(0, space), System.Globalization.NumberStyles.None, System.Globalization.CultureInfo.InvariantCulture, out long nanoseconds))
            {
                return TimeSpan.FromTicks(nanoseconds / 100);
            }
        }
        catch (IOException)
        {
        }
        catch (UnauthorizedAccessException)
        {
        }

        return Stopwatch.GetElapsedTime(ProcessStart);
    }

    private static readonly long ProcessStart = Stopwatch.GetTimestamp();

    private static string FirstFrame(Exception e) =>
        e.StackTrace?.Split('\n').Select(l => l.Trim()).FirstOrDefault(l => l.Contains("Ballistic", StringComparison.Ordinal)) ?? e.StackTrace?.Split('\n')[0].Trim() ?? "(no stack)";
}
