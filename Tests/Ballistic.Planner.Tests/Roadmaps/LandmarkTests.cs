using System.Numerics;
using System.Runtime.Intrinsics;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Tests.Roadmaps;

/// <summary>The landmark bounds of A*: never above the least flight time, +∞ only where the goal cannot be reached, and the same bit for bit landmark by landmark or eight at once.</summary>
public sealed class LandmarkTests
{
    /// <summary>A distance list entry: mostly finite flight times, some unreachable (+∞), some zero or repeated.</summary>
    private static float Entry(Random random) => random.Next(10) switch
    {
        0 or 1 => float.PositiveInfinity,
        2 => 0f,
        3 => 1.5f,
        _ => (float)(random.NextDouble() * 60.0),
    };

    [Test]
    public void TheBoundOfEightLandmarksAtOnceIsTheBoundLandmarkByLandmark()
    {
        Assume.That(Vector256.IsHardwareAccelerated, "eight landmarks are bounded at once only with 256-bit vectors");
        var random = new Random(11);
        int infinite = 0;
        int positive = 0;
        for (int trial = 0; trial < 20_000; trial++)
        {
            // Half the trials without unreachable entries, so that most bounds are finite.
            bool reachable = trial % 2 == 0;
            float[][] lists = [.. Enumerable.Range(0, 4).Select(_ => Enumerable.Range(0, Landmarks.MaxCount).Select(_ => reachable ? (float)(random.NextDouble() * 60.0) : Entry(random)).ToArray())];
            float once = Landmarks.LowerBound(lists[0], lists[1], lists[2], lists[3]);
            float byLandmark = Landmarks.ScalarLowerBound(lists[0], lists[1], lists[2], lists[3]);
            Assert.That(BitConverter.SingleToInt32Bits(once), Is.EqualTo(BitConverter.SingleToInt32Bits(byLandmark)), $"trial {trial}: {once} at once, {byLandmark} landmark by landmark");
            infinite += float.IsPositiveInfinity(once) ? 1 : 0;
            positive += once is > 0f and < float.PositiveInfinity ? 1 : 0;
        }

        // Both kinds of outcome were compared, not only one.
        Assert.That(infinite, Is.GreaterThan(2_000));
        Assert.That(positive, Is.GreaterThan(8_000));
    }

    [Test]
    public void BoundsOnARandomRoadmapNeverExceedItsLeastFlightTimes()
    {
        var random = new Random(5);
        const int n = 80;
        Vector2[] horizontal = [.. Enumerable.Range(0, n).Select(_ => new Vector2((float)(random.NextDouble() * 100.0), (float)(random.NextDouble() * 100.0)))];

        // Jumps between nodes less than 25 m apart, each way on its own; nodes 70 to 79 are only ever jumped from.
        var rows = Enumerable.Range(0, n).Select(_ => new List<(int To, float Time)>()).ToArray();
        for (int a = 0; a < n; a++)
        {
            for (int b = 0; b < n; b++)
            {
                if (a != b && b < 70 && Vector2.Distance(horizontal[a], horizontal[b]) < 25f && random.Next(3) > 0)
                {
                    rows[a].Add((b, 0.4f + (Vector2.Distance(horizontal[a], horizontal[b]) / 10f) + (float)random.NextDouble()));
                }
            }
        }

        int[] offsets = new int[n + 1];
        for (int a = 0; a < n; a++)
        {
            offsets[a + 1] = offsets[a] + rows[a].Count;
        }

        int[] targets = [.. rows.SelectMany(r => r.Select(e => e.To))];
        float[] times = [.. rows.SelectMany(r => r.Select(e => e.Time))];
        Landmarks landmarks = Landmarks.Build(horizontal, offsets, targets, times);
        Assert.That(landmarks.Count, Is.EqualTo(Landmarks.MaxCount));

        double tightness = 0;
        int finite = 0;
        int unreachable = 0;
        int pruned = 0;
        for (int v = 0; v < n; v++)
        {
            double[] least = LeastTimes(v, rows);
            for (int g = 0; g < n; g++)
            {
                float bound = Landmarks.LowerBound(landmarks.From(v), landmarks.To(v), landmarks.From(g), landmarks.To(g));
                if (double.IsPositiveInfinity(least[g]))
                {
                    continue; // unreachable: any bound holds
                }

                Assert.That(bound, Is.LessThanOrEqualTo(least[g] * (1 + 1e-6)), $"node {v} to node {g}: bound {bound} s, least flight time {least[g]} s");
                if (least[g] > 0)
                {
                    tightness += bound / least[g];
                    finite++;
                }
            }

            for (int g = 70; g < n; g++)
            {
                // Nodes 70 to 79 are never landed on.
                if (g != v)
                {
                    unreachable++;
                    pruned += float.IsPositiveInfinity(Landmarks.LowerBound(landmarks.From(v), landmarks.To(v), landmarks.From(g), landmarks.To(g))) ? 1 : 0;
                }
            }
        }

        // A reachable goal is never bounded +∞ (above); most unreachable ones are, and A* gives them up at once.
        Assert.That(pruned, Is.GreaterThan(unreachable / 2), $"{pruned} of {unreachable} unreachable goals bounded +∞");

        // The bounds are informative, not all 0.
        Assert.That(tightness / finite, Is.GreaterThan(0.3), "mean bound over least flight time");
    }

    /// <summary>Dijkstra in doubles from <paramref name="from"/>.</summary>
    private static double[] LeastTimes(int from, List<(int To, float Time)>[] rows)
    {
        double[] least = Enumerable.Repeat(double.PositiveInfinity, rows.Length).ToArray();
        least[from] = 0;
        var open = new PriorityQueue<int, double>();
        open.Enqueue(from, 0);
        while (open.TryDequeue(out int v, out double d))
        {
            if (d > least[v])
            {
                continue;
            }

            foreach ((int to, float time) in rows[v])
            {
                if (d + time < least[to])
                {
                    least[to] = d + time;
                    open.Enqueue(to, least[to]);
                }
            }
        }

        return least;
    }
}
