using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Tests.Roadmaps;

/// <summary>The spatial index against brute force: the same candidates in the same order as the linear scans it replaced.</summary>
public sealed class NodeIndexTests
{
    /// <summary>Speed limits of every kind: takeoff slower, faster or as fast as landing, small and large reach.</summary>
    private static readonly SteeringLimits[] Limits =
    [
        new(8f, 12f),
        new(12f, 8f),
        new(5f, 5f),
        new(1.2f, 0.9f),
        new(20f, 26f, 3.7f),
    ];

    /// <summary>The test the bake and the query applied before the index, word for word.</summary>
    private static bool OldInReach(SteeringLimits limits, Vector3 p, Vector3 q)
    {
        float x = new Vector2(q.X - p.X, q.Z - p.Z).Length();
        return x <= limits.MaxReach(p.Y - q.Y) || x <= limits.MaxReach(q.Y - p.Y);
    }

    /// <summary>The old linear scan: every point within reach, sorted by (distance, id), the first <paramref name="count"/>.</summary>
    private static List<(float Distance, int Id)> OldNearest(IReadOnlyList<Vector3> points, int upTo, Vector3 p, SteeringLimits limits, int count)
    {
        var candidates = new List<(float Distance, int Id)>();
        for (int j = 0; j < upTo; j++)
        {
            if (OldInReach(limits, p, points[j]))
            {
                candidates.Add((Vector3.Distance(p, points[j]), j));
            }
        }

        candidates.Sort();
        return [.. candidates.Take(count)];
    }

    /// <summary>Points on a few storeys, in clusters and spread out, some repeated exactly and some stacked vertically.</summary>
    private static List<Vector3> RandomPoints(Random random, int count, float extent)
    {
        var points = new List<Vector3>(count);
        float[] floors = [0f, 0.37f, 2.5f, 6.1f, 13f];
        for (int i = 0; i < count; i++)
        {
            double kind = random.NextDouble();
            if (kind < 0.05 && points.Count > 0)
            {
                points.Add(points[random.Next(points.Count)]); // the same point again
            }
            else if (kind < 0.1 && points.Count > 0)
            {
                Vector3 below = points[random.Next(points.Count)];
                points.Add(below with { Y = below.Y + (float)(random.NextDouble() * 12.0) }); // straight above another
            }
            else
            {
                float spread = kind < 0.5 ? extent * 0.05f : extent;
                float x = (float)((random.NextDouble() - 0.5) * spread);
                float z = (float)((random.NextDouble() - 0.5) * spread);
                float y = floors[random.Next(floors.Length)] + (float)((random.NextDouble() - 0.5) * 0.3);
                points.Add(new Vector3(x, y, z));
            }
        }

        return points;
    }

    [Test]
    public void TheReachBoundHoldsAtEveryDrop()
    {
        foreach (SteeringLimits limits in Limits)
        {
            float bound = NodeIndex.ReachBound(limits);
            float highest = 0f;
            for (float drop = -60f; drop <= 60f; drop += 0.0005f)
            {
                highest = MathF.Max(highest, limits.MaxReach(drop));
            }

            Assert.That(highest, Is.LessThanOrEqualTo(bound), $"V {limits.TakeoffSpeedMax}, L {limits.LandingSpeedMax}");
            Assert.That(highest, Is.GreaterThan((bound - 1e-4f) * 0.999f), "the bound is tight (V·L/g)");
        }
    }

    [Test]
    public void TheReachTableAgreesWithTheExactTest()
    {
        var random = new Random(17);
        foreach (SteeringLimits limits in Limits)
        {
            var test = new ReachTest(limits);
            float reach = NodeIndex.ReachBound(limits);
            for (int i = 0; i < 200_000; i++)
            {
                var p = new Vector3((float)(random.NextDouble() * 100.0 - 50.0), (float)(random.NextDouble() * 20.0), (float)(random.NextDouble() * 100.0 - 50.0));
                double kind = random.NextDouble();

                // Mostly near the boundary of the reach, where a table would err first.
                float dy = kind < 0.1 ? 0.05f * random.Next(-200, 200) : (float)((random.NextDouble() - 0.5) * 2.5 * reach);
                float x = kind < 0.2 ? 0f : (float)(random.NextDouble() * 1.1 * reach);
                float d = limits.MaxReach(-dy);
                if (kind > 0.6)
                {
                    x = MathF.Max(0f, d + (float)((random.NextDouble() - 0.5) * 1e-4 * d)); // a hair either side of the reach
                }

                double angle = random.NextDouble() * 2.0 * Math.PI;
                var q = new Vector3(p.X + (x * (float)Math.Cos(angle)), p.Y + dy, p.Z + (x * (float)Math.Sin(angle)));
                if (test.InReach(p, q) != OldInReach(limits, p, q))
                {
                    Assert.Fail($"The table says {test.InReach(p, q)} for p {p:R}, q {q:R} (V {limits.TakeoffSpeedMax}, L {limits.LandingSpeedMax}).");
                }
            }
        }
    }

    [Test]
    public void NeighboursAreThoseOfALinearScanInTheSameOrder()
    {
        var random = new Random(5);
        foreach (SteeringLimits limits in Limits)
        {
            float reach = NodeIndex.ReachBound(limits);
            List<Vector3> points = RandomPoints(random, 1_500, 8f * reach);
            var reachTest = new ReachTest(limits);
            foreach (float cell in new[] { NodeIndex.CellSizeFor(limits), 0.07f * reach, 3f * reach })
            {
                var index = new NodeIndex(cell);
                var kept = new List<(float Distance, int Id)>();
                for (int i = 0; i < points.Count; i++)
                {
                    // Query before adding, as the bake does: every earlier point is a candidate.
                    if (i % 7 == 0)
                    {
                        foreach (int count in new[] { 1, 24, 100_000 })
                        {
                            kept.Clear();
                            index.OfferWithinReach(points[i], reachTest, count, kept);
                            NodeIndex.Finish(kept);
                            Assert.That(kept, Is.EqualTo(OldNearest(points, i, points[i], limits, count)), $"point {i}, cell {cell}, count {count}");
                        }
                    }

                    index.Add(points[i]);
                }

                Assert.That(index.Count, Is.EqualTo(points.Count));
            }
        }
    }

    [Test]
    public void ToleranceLookupsAndExactLookupsMatchBruteForce()
    {
        var random = new Random(9);
        List<Vector3> points = RandomPoints(random, 3_000, 40f);
        foreach (float cell in new[] { 0.05f, 1f, 7f, 500f })
        {
            var index = new NodeIndex(cell, [.. points]);
            for (int k = 0; k < 2_000; k++)
            {
                Vector3 point = k % 2 == 0
                    ? points[random.Next(points.Count)] + new Vector3((float)(random.NextDouble() - 0.5), (float)(random.NextDouble() - 0.5) * 0.6f, (float)(random.NextDouble() - 0.5))
                    : new Vector3((float)(random.NextDouble() - 0.5) * 50f, (float)random.NextDouble() * 14f, (float)(random.NextDouble() - 0.5) * 50f);
                float across = (float)(0.05 + random.NextDouble());
                float upDown = (float)(0.05 + (random.NextDouble() * 0.5));
                int expected = -1;
                float best = float.PositiveInfinity;
                for (int id = 0; id < points.Count; id++)
                {
                    Vector3 c = points[id];
                    if (new Vector2(c.X - point.X, c.Z - point.Z).Length() <= across && MathF.Abs(c.Y - point.Y) <= upDown && Vector3.DistanceSquared(c, point) < best)
                    {
                        (expected, best) = (id, Vector3.DistanceSquared(c, point));
                    }
                }

                Assert.That(index.NearestWithin(point, across, upDown), Is.EqualTo(expected), $"point {point}, cell {cell}");
            }

            // Every point finds every point equal to it in its cell, in increasing id order.
            for (int id = 0; id < points.Count; id += 3)
            {
                int[] equal = [.. Enumerable.Range(0, points.Count).Where(j => points[j] == points[id])];
                Assert.That(index.CellOf(points[id]).ToArray().Where(j => points[j] == points[id]), Is.EqualTo(equal));
            }
        }
    }
}
