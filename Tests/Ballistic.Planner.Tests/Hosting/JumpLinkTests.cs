using System.Numerics;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Runtime;
using Ballistic.Planner.Tests.Support;
using Ballistic.Runtime.Core;
using Ballistic.Runtime;
using Ballistic.Runtime.Kinds;
using Ballistic.Runtime.Hosting;
using Ballistic.Runtime.Links;
using Ballistic.Runtime.Paths;

namespace Ballistic.Planner.Tests.Hosting;

/// <summary>The roadmap's jumps as one-way navigation links: ends, costs, filters and merging, and an agent taken across one.</summary>
public sealed class JumpLinkTests
{
    private static Roadmap Roadmap => HostingWorlds.Desert.Roadmap;

    [Test]
    public void LinksAreOneWayFromTheTakeoffCentreToTheLandingCentreAndPricedByFlightTime()
    {
        JumpLinkSet set = JumpLinkSet.Build(Roadmap, new JumpLinkSettings { ReferenceSpeed = 4f, EnterCost = 1.5f });
        Assert.That(set.Count, Is.GreaterThan(100));
        Assert.That(set.Merged, Is.Zero);
        Assert.That(set.Candidates, Is.EqualTo(set.Count), "no merging, no cap: every candidate is a link");
        float minUp = MathF.Cos(45f * MathF.PI / 180f);
        int ground = Roadmap.Edges.Count(e => Roadmap.Nodes[e.From].Cone.Axis.Y >= minUp && Roadmap.Nodes[e.To].Cone.Axis.Y >= minUp &&
            Vector3.Distance(Roadmap.ContactCentres[e.From], Roadmap.ContactCentres[e.To]) >= 1e-3f);
        Assert.That(set.Count, Is.EqualTo(ground), "every jump between stances on walkable ground");

        var byEdge = new HashSet<int>();
        foreach (JumpLink link in set.Links)
        {
            RoadmapEdge edge = Roadmap.Edges[link.Edge];
            Assert.That(byEdge.Add(link.Edge), Is.True, "one link per jump");
            Assert.That((link.From, link.To), Is.EqualTo((edge.From, edge.To)));
            Assert.That(link.Start, Is.EqualTo(Roadmap.ContactCentres[edge.From]), "start: the takeoff stance's contact centre");
            Assert.That(link.End, Is.EqualTo(Roadmap.ContactCentres[edge.To]), "end: the landing stance's contact centre");
            Assert.That(link.FlightTime, Is.EqualTo(edge.Arc.FlightTime));
            Assert.That(link.TravelCost * link.Length, Is.EqualTo(edge.Arc.FlightTime * 4f).Within(1e-4f * (1f + link.FlightTime * 4f)), "Godot's cost: travel cost × length = flight time × reference speed");
            Assert.That(link.EnterCost, Is.EqualTo(1.5f));
            Assert.That(link.Cost, Is.EqualTo((edge.Arc.FlightTime * 4f) + 1.5f).Within(1e-3f));
        }

        // One-way: a jump back is a link of its own (when the roadmap has it), never the same one.
        JumpLink some = set.Links.First(l => set.Links.Any(b => b.From == l.To && b.To == l.From));
        JumpLink back = set.Links.First(b => b.From == some.To && b.To == some.From);
        Assert.That(back.Start, Is.EqualTo(some.End));
        Assert.That(back.Edge, Is.Not.EqualTo(some.Edge));
        Assert.That(set.Links.Zip(set.Links.Skip(1)).All(p => p.First.FlightTime < p.Second.FlightTime || (p.First.FlightTime == p.Second.FlightTime && p.First.Edge < p.Second.Edge)), Is.True, "cheapest first");
    }

    [Test]
    public void FiltersKeepExactlyTheLongJumpsAndTheClimbs()
    {
        var settings = new JumpLinkSettings { MinHorizontalDistance = 2f, MinHeightChange = 0.5f, MaxSlopeDegrees = 30f };
        JumpLinkSet set = JumpLinkSet.Build(Roadmap, settings);
        float minUp = MathF.Cos(30f * MathF.PI / 180f);
        var kept = set.Links.Select(l => l.Edge).ToHashSet();
        Assert.That(kept, Is.Not.Empty);
        for (int e = 0; e < Roadmap.Edges.Count; e++)
        {
            RoadmapEdge edge = Roadmap.Edges[e];
            Vector3 a = Roadmap.ContactCentres[edge.From];
            Vector3 b = Roadmap.ContactCentres[edge.To];
            bool far = new Vector2(b.X - a.X, b.Z - a.Z).Length() > 2f;
            bool climb = MathF.Abs(b.Y - a.Y) > 0.5f;
            bool flat = Roadmap.Nodes[edge.From].Cone.Axis.Y >= minUp && Roadmap.Nodes[edge.To].Cone.Axis.Y >= minUp;
            Assert.That(kept.Contains(e), Is.EqualTo((far || climb) && flat), $"edge {e}: {Vector2.Distance(new(a.X, a.Z), new(b.X, b.Z)):0.##} m across, {b.Y - a.Y:0.##} m up");
        }

        Assert.That(set.Count, Is.LessThan(JumpLinkSet.Build(Roadmap).Count));
    }

    [Test]
    public void MergingAndTheCapAreDeterministicAndLeaveNoNearDuplicates()
    {
        const float radius = 1.5f;
        var settings = new JumpLinkSettings { MergeRadius = radius };
        JumpLinkSet merged = JumpLinkSet.Build(Roadmap, settings);
        JumpLinkSet all = JumpLinkSet.Build(Roadmap);
        Assert.That(merged.Merged, Is.GreaterThan(0));
        Assert.That(merged.Count + merged.Merged, Is.EqualTo(all.Count));
        Assert.That(JumpLinkSet.Build(Roadmap, settings).Links, Is.EqualTo(merged.Links), "the same links in the same order");

        static bool Near(JumpLink a, JumpLink b) => Vector3.Distance(a.Start, b.Start) <= radius && Vector3.Distance(a.End, b.End) <= radius;
        for (int i = 0; i < merged.Count; i++)
        {
            for (int j = i + 1; j < merged.Count; j++)
            {
                Assert.That(Near(merged.Links[i], merged.Links[j]), Is.False, $"links {i} and {j} are near duplicates");
            }
        }

        // Every dropped jump is a near duplicate of a link kept, one at least as quick.
        var keptEdges = merged.Links.Select(l => l.Edge).ToHashSet();
        foreach (JumpLink dropped in all.Links.Where(l => !keptEdges.Contains(l.Edge)))
        {
            Assert.That(merged.Links.Any(k => Near(k, dropped) && k.FlightTime <= dropped.FlightTime), Is.True, $"edge {dropped.Edge} was dropped without a kept link near it");
        }

        JumpLinkSet capped = JumpLinkSet.Build(Roadmap, settings with { MaxLinks = 10 });
        Assert.That(capped.Links, Is.EqualTo(merged.Links.Take(10)), "the cap keeps the first links");
    }

    [Test]
    public void BadSettingsAreRefusedNamingTheSetting()
    {
        foreach ((JumpLinkSettings settings, string name) in new[]
        {
            (new JumpLinkSettings { ReferenceSpeed = 0f }, "ReferenceSpeed"),
            (new JumpLinkSettings { MergeRadius = -1f }, "MergeRadius"),
            (new JumpLinkSettings { MinHeightChange = float.NaN }, "MinHeightChange"),
            (new JumpLinkSettings { MaxSlopeDegrees = 200f }, "MaxSlopeDegrees"),
            (new JumpLinkSettings { MaxLinks = -1 }, "MaxLinks"),
        })
        {
            ArgumentException e = Assert.Throws<ArgumentException>(() => JumpLinkSet.Build(Roadmap, settings))!;
            Assert.That(e.Message, Does.Contain(name));
        }
    }

    [Test]
    public void ALinkIsFoundFromItsEnds()
    {
        JumpLinkSet set = JumpLinkSet.Build(Roadmap, new JumpLinkSettings { MergeRadius = 1f });
        for (int i = 0; i < set.Count; i += 17)
        {
            JumpLink link = set.Links[i];
            int found = set.FindLink(link.Start + new Vector3(0.2f, 0f, 0f), link.End, 0.5f);
            Assert.That(found, Is.GreaterThanOrEqualTo(0));
            JumpLink other = set.Links[found];
            float sum = Vector3.Distance(other.Start, link.Start + new Vector3(0.2f, 0f, 0f)) + Vector3.Distance(other.End, link.End);
            Assert.That(sum, Is.LessThanOrEqualTo(0.2f + 1e-5f), $"link {i}: found link {found}, farther");
        }

        Assert.That(set.FindLink(new Vector3(500f, 0f, 500f), new Vector3(510f, 0f, 500f), 1f), Is.EqualTo(-1));
    }

    [Test]
    public void WithTheAnimatorOnlyJumpsTheBodyPerformsAreKeptAsIfCheckedOneByOne()
    {
        var settings = new JumpLinkSettings { MinHorizontalDistance = 1f, MergeRadius = 1f, MaxLinks = 40 };
        JumpLinkSet checkedSet = JumpLinkSet.Build(Roadmap, settings, HostingWorlds.Desert.Animator, threads: 2);

        // The reference: candidates one by one, cheapest first; a near duplicate of a kept link is dropped unchecked,
        // any other is animated and kept when clean.
        var candidates = JumpLinkSet.Build(Roadmap, settings with { MergeRadius = 0f, MaxLinks = int.MaxValue }).Links;
        var expected = new List<JumpLink>();
        int unperformable = 0;
        foreach (JumpLink c in candidates)
        {
            if (expected.Count == settings.MaxLinks)
            {
                break;
            }

            if (expected.Any(k => Vector3.Distance(k.Start, c.Start) <= 1f && Vector3.Distance(k.End, c.End) <= 1f))
            {
                continue;
            }

            RoadmapEdge edge = Roadmap.Edges[c.Edge];
            if (HostingWorlds.Desert.Animator.Animate([new Jump(Roadmap.Nodes[edge.From], Roadmap.Nodes[edge.To], edge.Arc)], 60f).IsClean)
            {
                expected.Add(c);
            }
            else
            {
                unperformable++;
            }
        }

        Assert.That(checkedSet.Links, Is.EqualTo(expected));
        Assert.That(checkedSet.Unperformable, Is.EqualTo(unperformable));
        Assert.That(JumpLinkSet.Build(Roadmap, settings, HostingWorlds.Desert.Animator, threads: 1).Links, Is.EqualTo(expected), "whatever the threads");
        Assert.That(JumpLinkSet.Build(Roadmap, settings).Unperformable, Is.Zero, "unchecked without an animator");
    }

    [Test]
    public void TraversingALinkPerformsThatJumpAndLandsOnTheLinksEnd()
    {
        JumpLinkSet set = JumpLinkSet.Build(Roadmap, new JumpLinkSettings { MinHorizontalDistance = 1.5f, MergeRadius = 1f, MaxLinks = 60 }, HostingWorlds.Desert.Animator, threads: 2);
        var traversal = new LinkTraversal(set);
        (JumpWorld host, KindHandle region) = HostingWorlds.DesertServer();
        using (host)
        {
            foreach (int index in new[] { 0, set.Count / 2, set.Count - 1 })
            {
                JumpLink link = set.Links[index];

                // The jump agent stands a little way off, where the navmesh agent reached the link.
                RoadmapNode near = Roadmap.Nodes.Where(n => n.Id != link.From).MinBy(n => Vector3.Distance(Roadmap.ContactCentres[n.Id], link.Start))!;
                var logic = new JumpAgentLogic(host, AgentMotionMode.ReportOnly);
                Assert.That(logic.Register(region, RuntimeWorlds.Point(near)).Ok, Is.True);

                RuntimeResult started = traversal.Traverse(logic, index);
                Assert.That(started.Ok, Is.True, started.ToString());
                Assert.That(host.GetStandingPoint(logic.Agent), Is.EqualTo(link.Start), "warped onto the takeoff stance at once");
                Assert.That(logic.TargetPosition, Is.EqualTo(link.End));
                AgentPath? path = null;
                List<AgentSignal> signals = HostingWorlds.Run(logic, 600, HostingWorlds.Finished, () => path ??= host.GetPath(logic.Agent));

                Assert.That(signals.Select(s => s.Kind), Is.EqualTo(new[]
                {
                    AgentSignalKind.PathChanged, AgentSignalKind.JumpStarted, AgentSignalKind.Landed, AgentSignalKind.TargetReached, AgentSignalKind.NavigationFinished,
                }), $"link {index}: " + string.Join("; ", signals));
                var takeoff = signals[1];
                Assert.That(takeoff.From, Is.EqualTo(link.Start));
                Assert.That(takeoff.To, Is.EqualTo(link.End));
                Assert.That(signals[2].To, Is.EqualTo(link.End));
                Assert.That(HostingWorlds.WithinTolerance(host.GetStandingPoint(logic.Agent)!.Value, link.End), Is.True);
                Assert.That(Vector3.Distance(logic.BodyPosition, link.End), Is.LessThan(1e-4f), "the body stands on the link's end");

                // Exactly the roadmap's jump, and a valid one.
                Assert.That(path, Is.Not.Null);
                PathMove move = path!.Moves.Single();
                RoadmapEdge edge = Roadmap.Edges[link.Edge];
                Assert.That(move.Arc, Is.EqualTo(edge.Arc));
                Assert.That((move.From, move.To), Is.EqualTo((Roadmap.Nodes[edge.From], Roadmap.Nodes[edge.To])));
                PhysicsChecks.AssertJump(HostingWorlds.Desert.Scene, move.From, move.To, move.Arc, $"link {index}");
                logic.Unregister();
            }
        }
    }

    /// <summary>
    /// The first link whose jump the body cannot perform, taken off from a stance the body can stand on (a link from a
    /// stance it cannot stand on is refused before it starts), takes the agent to the link's end by other jumps.
    /// </summary>
    [Test]
    public void ALinkTheBodyCannotPerformStillTakesTheAgentToItsEndByOtherJumps()
    {
        JumpLinkSet set = JumpLinkSet.Build(Roadmap, new JumpLinkSettings { MinHorizontalDistance = 1.5f });
        int index = Enumerable.Range(0, set.Count).First(i =>
        {
            RoadmapEdge edge = Roadmap.Edges[set.Links[i].Edge];
            RoadmapNode from = Roadmap.Nodes[edge.From];
            return HostingWorlds.Desert.Animator.CanStand(new PoseEvaluation(from.Pose, PoseValidity.Valid, from.Contacts, from.Cone))
                && !HostingWorlds.Desert.Animator.Animate([new Jump(from, Roadmap.Nodes[edge.To], edge.Arc)], 60f).IsClean;
        });
        JumpLink link = set.Links[index];
        (JumpWorld host, KindHandle region) = HostingWorlds.DesertServer();
        using (host)
        {
            var logic = new JumpAgentLogic(host);
            logic.Register(region, RuntimeWorlds.Point(Roadmap.Nodes[link.From]));
            Assert.That(new LinkTraversal(set).Traverse(logic, index).Ok, Is.True);
            AgentPath? path = null;
            List<AgentSignal> signals = HostingWorlds.Run(logic, 3600, HostingWorlds.Finished, () => path ??= host.GetPath(logic.Agent));
            Assert.That(signals.Where(s => s.Kind == AgentSignalKind.PathFailed), Is.Empty, string.Join("; ", signals));
            Assert.That(signals[0], Has.Property(nameof(AgentSignal.Kind)).EqualTo(AgentSignalKind.PathChanged));
            Assert.That(signals[^2], Has.Property(nameof(AgentSignal.Kind)).EqualTo(AgentSignalKind.TargetReached), string.Join("; ", signals));
            Assert.That(path!.Moves.Any(m => m.From.Id == link.From && m.To.Id == link.To), Is.False, "the jump set aside is not used");
            Assert.That(Vector3.Distance(logic.BodyPosition, link.End), Is.LessThan(1e-4f), "the agent stands on the link's end all the same");
            foreach (PathMove move in path.Moves)
            {
                PhysicsChecks.AssertJump(HostingWorlds.Desert.Scene, move.From, move.To, move.Arc, $"jump {move.Index}");
            }
        }
    }

    [Test]
    public void StaleLinksAndBadIndicesAreRefused()
    {
        JumpLinkSet set = JumpLinkSet.Build(Roadmap);
        var traversal = new LinkTraversal(set);
        (JumpWorld host, KindHandle region) = HostingWorlds.DesertServer();
        using (host)
        {
            var logic = new JumpAgentLogic(host);
            Assert.That(traversal.Traverse(logic, 0).Status, Is.EqualTo(RuntimeStatus.InvalidPosition), "not registered");
            logic.Register(region, RuntimeWorlds.Point(Roadmap.Nodes[0]));
            Assert.That(traversal.Traverse(logic, -1).Status, Is.EqualTo(RuntimeStatus.InvalidArgument));
            Assert.That(traversal.Traverse(logic, set.Count).Status, Is.EqualTo(RuntimeStatus.InvalidArgument));

            host.ReplaceKind(region, HostingWorlds.DesertRebaked);
            RuntimeResult stale = traversal.Traverse(logic, 0);
            Assert.That(stale.Status, Is.EqualTo(RuntimeStatus.Mismatch));
            Assert.That(stale.Reason, Does.Contain("another roadmap"));
            Assert.That(host.IsPathPending(logic.Agent), Is.False, "nothing was asked");
        }
    }
}
