using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Tests.Geometry;

/// <summary>The bounded memory behind the remembered placements, steers and walks: what it keeps, what it forgets, and that threads only ever see the function's own results.</summary>
public sealed class RememberedResultsTests
{
    [Test]
    public void ResultsAreMadeOnceWhileRememberedAndTwoGenerationsBoundWhatIsKept()
    {
        var memory = new RememberedResults<int, string>(4);
        int made = 0;
        string Make(int key, int salt)
        {
            made++;
            return $"{key}:{salt}";
        }

        for (int k = 0; k < 4; k++)
        {
            Assert.That(memory.GetOrAdd(k, 7, Make), Is.EqualTo($"{k}:7"));
        }

        Assert.That(made, Is.EqualTo(4));
        Assert.That(memory.GetOrAdd(2, 99, Make), Is.EqualTo("2:7"), "remembered: the function is not asked again");
        Assert.That(made, Is.EqualTo(4));

        // The newer generation is full: the fifth key starts a new one, the first four become the older, still served.
        Assert.That(memory.GetOrAdd(4, 7, Make), Is.EqualTo("4:7"));
        Assert.That(memory.GetOrAdd(0, 99, Make), Is.EqualTo("0:7"), "found in the older generation, and kept in the newer");
        Assert.That(made, Is.EqualTo(5));

        // Two more generations later, keys 1–3 (never asked again) are forgotten and made anew; key 0 went forward each time it was asked.
        for (int k = 10; k < 17; k++)
        {
            memory.GetOrAdd(k, 7, Make);
            memory.GetOrAdd(0, 99, Make);
        }

        int before = made;
        Assert.That(memory.GetOrAdd(1, 8, Make), Is.EqualTo("1:8"), "forgotten: made anew");
        Assert.That(made, Is.EqualTo(before + 1));
        Assert.That(memory.GetOrAdd(0, 8, Make), Is.EqualTo("0:7"), "kept while asked");
    }

    [Test]
    public void AValueMadeUnderTheLockIsFoundByEveryLaterCallerAndAFailedOneIsForgotten()
    {
        var memory = new RememberedResults<int, object>(2);
        object first = memory.GetOrAddLocked(1, 0, static (_, _) => new object(), out bool added);
        Assert.That(added, Is.True);
        Assert.That(memory.GetOrAddLocked(1, 0, static (_, _) => new object(), out added), Is.SameAs(first), "remembered");
        Assert.That(added, Is.False);

        // Forgetting another value for the key keeps it; forgetting its own drops it from either generation.
        memory.Forget(1, new object());
        Assert.That(memory.GetOrAddLocked(1, 0, static (_, _) => new object(), out added), Is.SameAs(first));
        memory.GetOrAddLocked(2, 0, static (_, _) => new object(), out _);
        memory.GetOrAddLocked(3, 0, static (_, _) => new object(), out _); // 1 and 2 are now the older generation
        memory.Forget(1, first);
        Assert.That(memory.GetOrAddLocked(1, 0, static (_, _) => new object(), out added), Is.Not.SameAs(first), "made anew once forgotten");
        Assert.That(added, Is.True);
    }

    [Test]
    public void ThreadsAskingForOneKeyAtOnceShareTheOneValueMade()
    {
        var memory = new RememberedResults<int, Lazy<int>>(8);
        int solved = 0;
        var seen = new int[8];
        Parallel.For(0, 8, new ParallelOptions { MaxDegreeOfParallelism = 8 }, thread =>
        {
            Lazy<int> entry = memory.GetOrAddLocked(5, 0, (_, _) => new Lazy<int>(() => Interlocked.Increment(ref solved) + 41, LazyThreadSafetyMode.ExecutionAndPublication), out _);
            seen[thread] = entry.Value;
        });

        Assert.That(solved, Is.EqualTo(1));
        Assert.That(seen, Has.All.EqualTo(42));
    }

    [Test]
    public void ThreadsAskingAtOnceOnlyEverSeeTheFunctionsOwnResults()
    {
        var memory = new RememberedResults<int, long>(64);
        var wrong = 0;
        Parallel.For(0, 8, new ParallelOptions { MaxDegreeOfParallelism = 8 }, thread =>
        {
            var random = new Random(thread);
            for (int i = 0; i < 20_000; i++)
            {
                int key = random.Next(500);
                if (memory.GetOrAdd(key, 0, static (k, _) => ((long)k * k) + 1) != ((long)key * key) + 1)
                {
                    Interlocked.Increment(ref wrong);
                }
            }
        });

        Assert.That(wrong, Is.Zero);
    }

    /// <summary>
    /// A solve remembered as a lazy value runs once however many threads ask at once (the others wait for it and get
    /// its result), is counted once, and when it throws every caller sees the exception and the next call solves it
    /// again.
    /// </summary>
    [Test]
    public void ASolveIsRunOnceAcrossThreadsAndAFailedOneIsSolvedAgain()
    {
        var memory = new RememberedResults<int, Lazy<string>>(4);
        int runs = 0;
        int solves = 0;
        using var together = new Barrier(8);
        string[] got = new string[8];
        bool[] here = new bool[8];
        Parallel.For(0, 8, new ParallelOptions { MaxDegreeOfParallelism = 8 }, i =>
        {
            together.SignalAndWait();
            got[i] = memory.GetOrSolve(1, "one", s => { Interlocked.Increment(ref runs); Thread.Sleep(20); return s; }, ref solves, out here[i]);
        });

        int failing = 0;
        string Fail(string s) => Interlocked.Increment(ref failing) == 1 ? throw new InvalidOperationException("first") : s;
        Assert.Multiple(() =>
        {
            Assert.That(got, Has.All.EqualTo("one"));
            Assert.That(runs, Is.EqualTo(1), "solved once");
            Assert.That(solves, Is.EqualTo(1), "counted once");
            Assert.That(here.Count(h => h), Is.EqualTo(1), "solved here by one caller");
            Assert.That(() => memory.GetOrSolve(2, "two", Fail, ref solves, out _), Throws.InvalidOperationException);
            Assert.That(memory.GetOrSolve(2, "two", Fail, ref solves, out bool again), Is.EqualTo("two"), "solved again after it threw");
            Assert.That(again, Is.True);
            Assert.That(solves, Is.EqualTo(3));
        });
    }

    [Test]
    public void WhatAThreadMakesOrRecallsWhileKeepingIsNeverForgottenAndOtherThreadsRememberAsBefore()
    {
        var memory = new RememberedResults<int, string>(2);
        int made = 0;
        string Make(int key, int salt)
        {
            Interlocked.Increment(ref made);
            return $"{key}:{salt}";
        }

        memory.GetOrAdd(100, 1, Make); // remembered in a generation before the scope
        int keptByOther = -1;
        using (KeptResults.Keep())
        {
            Assert.That(KeptResults.Keeping, Is.True);
            for (int k = 0; k < 5; k++)
            {
                memory.GetOrAdd(k, 1, Make);
            }

            Assert.That(memory.GetOrAdd(100, 2, Make), Is.EqualTo("100:1"), "recalled from its generation");

            // Another thread, outside any scope, while this one keeps: what it makes goes into the generations.
            var other = new Thread(() =>
            {
                memory.GetOrAdd(200, 1, Make);
                keptByOther = memory.KeptCount;
            });
            other.Start();
            other.Join();
        }

        Assert.That(KeptResults.Keeping, Is.False, "the scope ended");
        Assert.That(keptByOther, Is.EqualTo(6), "keys 0–4 and 100 kept; 200, made by another thread, is not");

        // Many generations later, the kept keys are still there; 200 was forgotten.
        for (int k = 1_000; k < 1_010; k++)
        {
            memory.GetOrAdd(k, 1, Make);
        }

        int before = made;
        Assert.Multiple(() =>
        {
            for (int k = 0; k < 5; k++)
            {
                Assert.That(memory.GetOrAdd(k, 9, Make), Is.EqualTo($"{k}:1"), $"key {k} kept");
            }

            Assert.That(memory.GetOrAdd(100, 9, Make), Is.EqualTo("100:1"), "a result recalled while keeping is kept too");
            Assert.That(made, Is.EqualTo(before), "nothing kept was made again");
            Assert.That(memory.GetOrAdd(200, 9, Make), Is.EqualTo("200:9"), "forgotten: made anew");
            Assert.That(memory.KeptCount, Is.EqualTo(6));
        });

        // Trimmed, the kept results are all still there.
        memory.TrimKept();
        before = made;
        Assert.That(Enumerable.Range(0, 5).Select(k => memory.GetOrAdd(k, 9, Make)), Is.EqualTo(Enumerable.Range(0, 5).Select(k => $"{k}:1")));
        Assert.That(made, Is.EqualTo(before));

        // A failed solve is forgotten even when kept.
        memory.Forget(3, "3:1");
        Assert.That(memory.GetOrAdd(3, 9, Make), Is.EqualTo("3:9"));
        Assert.That(memory.KeptCount, Is.EqualTo(5));
    }
}
