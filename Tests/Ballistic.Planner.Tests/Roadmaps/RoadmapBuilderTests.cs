using Ballistic.Authoring.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Roadmaps;

/// <summary>A roadmap is built, then frozen: its search arrays say what its nodes and edges say, and it never changes.</summary>
public sealed class RoadmapBuilderTests
{
    private static readonly Lazy<PlanningScene> Scene = new(() => PlanningScene.Create(GapCourse.Build(), CharacterPresets.Skeleton()));

    [Test]
    public void TheFrozenArraysDescribeTheNodesAndEdges()
    {
        Roadmap roadmap = new RoadmapBaker(Scene.Value).Bake(new BakeSettings { Seed = 3, MaxNodes = 80, Threads = 2 }).Roadmap;
        int n = roadmap.Nodes.Count;
        Assert.That(roadmap.OutgoingOffsets.Length, Is.EqualTo(n + 1));
        Assert.That(roadmap.OutgoingOffsets[n], Is.EqualTo(roadmap.Edges.Count));
        for (int i = 0; i < n; i++)
        {
            int[] expected = [.. Enumerable.Range(0, roadmap.Edges.Count).Where(e => roadmap.Edges[e].From == i)];
            Assert.That(roadmap.Outgoing(i).ToArray(), Is.EqualTo(expected), $"node {i}");
            for (int k = roadmap.OutgoingOffsets[i]; k < roadmap.OutgoingOffsets[i + 1]; k++)
            {
                RoadmapEdge edge = roadmap.Edges[roadmap.OutgoingEdges[k]];
                Assert.That(roadmap.OutgoingTargets[k], Is.EqualTo(edge.To));
                Assert.That(roadmap.OutgoingFlightTimes[k], Is.EqualTo(edge.Arc.FlightTime));
            }

            RoadmapNode node = roadmap.Nodes[i];
            Assert.That(roadmap.Positions[i], Is.EqualTo(node.Pose.Position));
            Assert.That(roadmap.ContactCentres[i], Is.EqualTo(TrunkSampler.ContactCentre(new PoseEvaluation(node.Pose, PoseValidity.Valid, node.Contacts, node.Cone))));
        }

        Assert.That(roadmap.MaxHorizontalSpeed, Is.EqualTo(roadmap.Edges.Max(e => e.Arc.HorizontalSpeed)));
        Assert.That(roadmap.EdgeTargets, Is.EqualTo(roadmap.Edges.Select(e => e.To)));

        // Reaches agrees with a search over the edge list.
        for (int from = 0; from < n; from += 7)
        {
            var seen = new HashSet<int> { from };
            var frontier = new Queue<int>([from]);
            while (frontier.TryDequeue(out int v))
            {
                foreach (RoadmapEdge e in roadmap.Edges.Where(e => e.From == v && seen.Add(e.To)))
                {
                    frontier.Enqueue(e.To);
                }
            }

            for (int to = 0; to < n; to += 5)
            {
                Assert.That(roadmap.Reaches(from, to), Is.EqualTo(seen.Contains(to)), $"{from} → {to}");
            }
        }
    }

    [Test]
    public void AFrozenRoadmapStaysAsItWasWhileTheBuilderGrows()
    {
        Roadmap baked = new RoadmapBaker(Scene.Value).Bake(new BakeSettings { Seed = 3, MaxNodes = 30, Threads = 2 }).Roadmap;
        var builder = new RoadmapBuilder(baked.LevelFingerprint, baked.CharacterFingerprint, baked.CharacterName, baked.Seed);
        foreach (RoadmapNode node in baked.Nodes.Take(20))
        {
            builder.AddNode(node);
        }

        foreach (RoadmapEdge edge in baked.Edges.Where(e => e.From < 20 && e.To < 20))
        {
            builder.AddEdge(edge);
        }

        Roadmap early = builder.Freeze();
        byte[] earlyBytes = RoadmapFile.ToBytes(early);
        foreach (RoadmapNode node in baked.Nodes.Skip(20))
        {
            builder.AddNode(node);
        }

        foreach (RoadmapEdge edge in baked.Edges.Where(e => e.From >= 20 || e.To >= 20))
        {
            builder.AddEdge(edge);
        }

        Roadmap late = builder.Freeze();
        Assert.Multiple(() =>
        {
            Assert.That(early.Nodes, Has.Count.EqualTo(20));
            Assert.That(RoadmapFile.ToBytes(early), Is.EqualTo(earlyBytes));
            Assert.That(late.Nodes, Has.Count.EqualTo(30));
            Assert.That(late.Edges, Has.Count.EqualTo(baked.Edges.Count));
            Assert.That(builder.Reaches(0, 29), Is.EqualTo(late.Reaches(0, 29)));
            Assert.That(() => builder.AddNode(baked.Nodes[0]), Throws.ArgumentException.With.Message.Contains("not the next id"));
            Assert.That(() => builder.AddEdge(baked.Edges[0] with { To = 30 }), Throws.TypeOf<ArgumentOutOfRangeException>());
            Assert.That(early.Nodes, Is.Not.AssignableTo<List<RoadmapNode>>(), "the node list cannot be cast back and changed");
        });
    }
}
