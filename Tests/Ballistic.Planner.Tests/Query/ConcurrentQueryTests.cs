using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Query;

/// <summary>One roadmap and one scene shared by many threads, each with its own query: the same answers as one thread.</summary>
public sealed class ConcurrentQueryTests
{
    [Test]
    public void SixteenThreadsOnOneRoadmapAnswerAsOneThreadDoes()
    {
        var scene = PlanningScene.Create(GapCourse.Build(), CharacterPresets.Skeleton());
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 8, MaxNodes = 200, Threads = 2 }).Roadmap;

        // 50 seeded requests of every kind: point to point, node to point, node to node, with and without rejected jumps.
        var random = new Random(21);
        Vector3 Point() => new((float)(random.NextDouble() * 20.0) - 7.5f, 1f, (float)(random.NextDouble() * 3.6) - 1.8f);
        RoadmapNode Node() => roadmap.Nodes[random.Next(roadmap.Nodes.Count)];
        var requests = new List<Func<PathQuery, PlanResult>>();
        for (int i = 0; i < 50; i++)
        {
            (Vector3 a, Vector3 b, RoadmapNode c, RoadmapNode d) = (Point(), Point(), Node(), Node());
            var rejected = new HashSet<(int From, int To)>();
            foreach (RoadmapEdge edge in roadmap.Edges.Where((_, k) => k % 9 == i % 9))
            {
                rejected.Add((edge.From, edge.To));
            }

            requests.Add((i % 4) switch
            {
                0 => q => q.Plan(a, b),
                1 => q => q.Plan(c, b, rejected: i % 8 == 1 ? rejected : null),
                2 => q => q.Plan(c, d, rejected: rejected),
                _ => q => q.Plan(c, d),
            });
        }

        string[] RunAll(PathQuery query) => [.. requests.Select(r => PathQueryTests.Describe(r(query)))];
        string[] expected = RunAll(new PathQuery(scene, roadmap));
        Assert.That(expected.Count(e => e.StartsWith("Exact", StringComparison.Ordinal) && e.Contains('>', StringComparison.Ordinal)), Is.GreaterThan(20), "many requests find paths");

        var results = new string[16][];
        using var ready = new Barrier(16);
        Thread[] threads = [.. Enumerable.Range(0, 16).Select(t => new Thread(() =>
        {
            try
            {
                var query = new PathQuery(scene, roadmap);
                ready.SignalAndWait();
                results[t] = RunAll(query);
            }
            catch (Exception e)
            {
                results[t] = [$"thread {t} threw {e}"];
            }
        }))];
        foreach (Thread thread in threads)
        {
            thread.Start();
        }

        foreach (Thread thread in threads)
        {
            thread.Join();
        }

        for (int t = 0; t < 16; t++)
        {
            Assert.That(results[t], Is.EqualTo(expected), $"thread {t}");
        }
    }
}
