using System.Numerics;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Runtime;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Hosting;
using Ballistic.Runtime.Paths;

namespace Ballistic.Planner.Tests.Hosting;

/// <summary>The server's host: regions and agents by handle in any order, rebakes that keep agents, one level at a time, one event queue per agent.</summary>
public sealed class JumpNavigationHostTests
{
    private const int MaxTicks = 60 * 60;

    [Test]
    public void AgentsRegisteredBeforeTheirRegionHasARoadmapJoinItWhenItComes()
    {
        using JumpNavigationHost host = HostingWorlds.Host();
        (RoadmapNode from, RoadmapNode to) = RuntimeWorlds.ConnectedPairs(HostingWorlds.Desert.Roadmap, 1, seed: 31)[0];

        // Godot readies children first: the agent asks its region node for a handle before the region registers its roadmap.
        RegionHandle region = host.CreateRegion("desert");
        HostAgentResult registered = host.RegisterAgent(region, RuntimeWorlds.Point(from));
        Assert.That(registered.Ok, Is.True, registered.Result.ToString());
        HostAgentHandle agent = registered.Agent;
        Assert.That(host.GetAgentState(agent), Is.EqualTo(HostAgentState.Waiting));
        Assert.That(host.GetAgentReason(agent), Does.Contain("desert"));
        Assert.That(host.SetTarget(agent, RuntimeWorlds.Point(to)).Ok, Is.True, "a waiting agent keeps its target");
        Assert.That(host.World, Is.Null);
        host.Step();
        Assert.That(host.GetPendingEventCount(agent), Is.Zero, "nothing happens before the roadmap comes");

        RuntimeResult set = host.SetRegionKind(region, HostingWorlds.Desert);
        Assert.That(set.Ok, Is.True, set.ToString());
        Assert.That(set.Reason, Does.Contain("1 agent on it"));
        Assert.That(host.GetAgentState(agent), Is.EqualTo(HostAgentState.Active));
        Assert.That(host.World!.IsValid(host.GetWorldAgent(agent)), Is.True);
        Assert.That(Vector3.Distance(host.GetStandingPoint(agent)!.Value, RuntimeWorlds.Point(from)), Is.LessThan(1e-4f), "it joined where it was registered");

        List<JumpEvent> events = HostingWorlds.Run(host, [agent], MaxTicks, seen => seen[agent].Any(e => e.Kind is JumpEventKind.TargetReached or JumpEventKind.PathFailed))[agent];
        Assert.That(events[0].Kind, Is.EqualTo(JumpEventKind.PathFound), "the kept target was asked for");
        Assert.That(events[^1].Kind, Is.EqualTo(JumpEventKind.TargetReached), string.Join("; ", events.Select(e => e.Reason)));
        Assert.That(Vector3.Distance(host.GetStandingPoint(agent)!.Value, RuntimeWorlds.Point(to)), Is.LessThan(1e-4f));
        Assert.That(host.GetTarget(agent), Is.Null);
    }

    [Test]
    public void ARebakeKeepsTheAgentsUnderTheirHandlesMovesNoneAndKeepsTheirTargets()
    {
        (JumpNavigationHost host, RegionHandle region) = HostingWorlds.DesertHost();
        using (host)
        {
            Roadmap roadmap = HostingWorlds.Desert.Roadmap;
            List<(RoadmapNode From, RoadmapNode To)> pairs = RuntimeWorlds.ConnectedPairs(roadmap, 2, seed: 32);
            HostAgentHandle idle = host.RegisterAgent(region, RuntimeWorlds.Point(pairs[0].From)).Agent;
            HostAgentHandle moving = host.RegisterAgent(region, RuntimeWorlds.Point(pairs[1].From)).Agent;
            Assert.That(host.SetTarget(moving, RuntimeWorlds.Point(pairs[1].To)).Ok, Is.True);
            HostingWorlds.Run(host, [idle, moving], MaxTicks, _ => host.World!.GetState(host.GetWorldAgent(moving)) == AgentState.Flight);
            Assume.That(host.World!.GetState(host.GetWorldAgent(moving)), Is.EqualTo(AgentState.Flight));
            AgentHandle flying = host.GetWorldAgent(moving);
            Assert.That(host.World.TryGetCurrentJump(flying, out var jump), Is.True);
            AgentPath oldPath = host.World.GetPath(flying)!;
            Vector3 landing = oldPath.Moves[jump.Index].To.ContactCentre;
            Vector3 idleAt = host.GetStandingPoint(idle)!.Value;
            AgentHandle standing = host.GetWorldAgent(idle);
            RootPose idleRoot = host.World.GetRootPose(standing);
            JumpWorld world = host.World;

            RuntimeResult rebaked = host.SetRegionKind(region, HostingWorlds.DesertRebaked);
            Assert.That(rebaked.Ok, Is.True, rebaked.ToString());
            Assert.That(host.World, Is.SameAs(world), "same level: same world");
            Assert.That(world.Kinds, Has.Count.EqualTo(1), "the kind was replaced, not added");
            Assert.That(world.Kinds[0], Is.SameAs(HostingWorlds.DesertRebaked));
            Assert.That(host.GetWorldAgent(idle), Is.EqualTo(standing), "the world handles did not change");
            Assert.That(host.GetWorldAgent(moving), Is.EqualTo(flying));
            foreach (HostAgentHandle agent in new[] { idle, moving })
            {
                Assert.That(host.GetAgentState(agent), Is.EqualTo(HostAgentState.Active), host.GetAgentReason(agent));
                Assert.That(world.IsValid(host.GetWorldAgent(agent)), Is.True);
            }

            Assert.That(host.GetStandingPoint(idle), Is.EqualTo(idleAt), "the idle agent stays exactly where it stood");
            Assert.That(world.GetRootPose(standing), Is.EqualTo(idleRoot));
            Assert.That(world.GetStance(standing) is { } now && (Stances.IsNodeOf(HostingWorlds.DesertRebaked.Roadmap, now) || now.Id < 0), Is.True, "a node of the new roadmap, or a stance off it (no id of the old one)");
            Assert.That(world.GetPath(flying), Is.SameAs(oldPath), "the agent in flight finishes its jump");
            Assert.That(world.GetState(flying), Is.EqualTo(AgentState.Flight));

            // It flies on, lands on its landing stance and stops there, moved by no more than its own motion.
            float fastest = oldPath.Moves.Where(m => m.Walk is null).Max(m => MathF.Max(m.Arc.TakeoffVelocity.Length(), (m.Arc.TakeoffVelocity - (9.81f * m.Arc.FlightTime * Vector3.UnitY)).Length()));
            Vector3 last = world.GetRootPose(flying).Position;
            float worstStep = 0f;
            List<JumpEvent> events = HostingWorlds.Run(host, [idle, moving], MaxTicks, _ =>
            {
                Vector3 root = world.GetRootPose(flying).Position;
                worstStep = MathF.Max(worstStep, Vector3.Distance(root, last));
                last = root;
                return world.GetPath(flying) is null;
            })[moving];
            Assert.That(worstStep, Is.LessThanOrEqualTo(fastest * world.Settings.TickSeconds * 1.01f), "no tick moves the body further than its flight does");
            Assert.That(events.Select(e => e.Kind), Does.Contain(JumpEventKind.Landed));
            Assert.That(host.GetStandingPoint(moving), Is.EqualTo(landing), "it stands on its landing stance");
            Assert.That(host.GetTarget(moving), Is.EqualTo(RuntimeWorlds.Point(pairs[1].To)), "its target is kept");
            Assert.That(world.GetTarget(flying), Is.EqualTo(RuntimeWorlds.Point(pairs[1].To)), "and asked again");

            Vector3 restart = host.GetStandingPoint(moving)!.Value;
            events.AddRange(HostingWorlds.Run(host, [idle, moving], MaxTicks, seen => seen[moving].Any(e => e.Kind is JumpEventKind.TargetReached or JumpEventKind.PathFailed))[moving]);
            Assert.That(events.Select(e => e.Kind), Does.Not.Contain(JumpEventKind.Removed), "a rebake is not a removal");
            JumpEvent found = events.Last(e => e.Kind == JumpEventKind.PathFound);
            Assert.That(Vector3.Distance(found.Path!.Start.ContactCentre, restart), Is.LessThan(1e-4f), "the new path starts where the agent was put");
            // Each landing but the last is a node of the new roadmap, or a stance the query placed (facing a jump): ids n + 2 on.
            int placedFrom = HostingWorlds.DesertRebaked.Roadmap.Nodes.Count + 2;
            foreach (var move in found.Path.Moves.SkipLast(1))
            {
                Assert.That(move.To.Id >= placedFrom || Stances.IsNodeOf(HostingWorlds.DesertRebaked.Roadmap, move.To), Is.True, $"jump {move.Index} lands on a node of the new roadmap");
            }

            Assert.That(found.Path.Moves.SkipLast(1).Count(m => Stances.IsNodeOf(HostingWorlds.DesertRebaked.Roadmap, m.To)), Is.Positive, "the path goes through the new roadmap");
        }
    }

    [Test]
    public void AQueueNobodyDrainsKeepsOnlyItsNewestEventsInOrder()
    {
        (JumpNavigationHost host, RegionHandle region) = HostingWorlds.DesertHost();
        using (host)
        {
            Roadmap roadmap = HostingWorlds.Desert.Roadmap;
            int edge = Enumerable.Range(0, roadmap.Edges.Count).First(e => Vector3.Distance(roadmap.Positions[roadmap.Edges[e].From], roadmap.Positions[roadmap.Edges[e].To]) > 2f);
            HostAgentHandle agent = host.RegisterAgent(region, RuntimeWorlds.Point(roadmap.Nodes[roadmap.Edges[edge].From])).Agent;
            int jumps = 0;
            int ticks = 0;
            while (jumps * 4 <= JumpNavigationHost.MaxQueuedEvents + 20)
            {
                // The same jump again and again (four events each: path, takeoff, landing, arrival), never drained.
                Assert.That(host.PerformJump(agent, edge).Ok, Is.True);
                jumps++;
                for (int i = 0; i < MaxTicks && host.GetTarget(agent) is not null; i++)
                {
                    host.Step();
                    ticks++;
                }

                Assert.That(host.GetTarget(agent), Is.Null, $"jump {jumps} arrived");
            }

            Assert.That(host.GetPendingEventCount(agent), Is.EqualTo(JumpNavigationHost.MaxQueuedEvents), $"{jumps * 4} events, the queue holds the newest {JumpNavigationHost.MaxQueuedEvents}");
            var drained = new List<JumpEvent>();
            while (host.TryDequeueEvent(agent, out JumpEvent e))
            {
                drained.Add(e);
            }

            Assert.That(drained, Has.Count.EqualTo(JumpNavigationHost.MaxQueuedEvents));
            Assert.That(drained.Select(e => e.Tick), Is.Ordered, "oldest first");
            Assert.That(drained[^1].Kind, Is.EqualTo(JumpEventKind.TargetReached), "the newest kept");
            Assert.That(drained.Count(e => e.Kind == JumpEventKind.TargetReached), Is.LessThan(jumps), "the oldest dropped");
            Assert.That(drained.Where(e => e.Kind is JumpEventKind.JumpStarted or JumpEventKind.Landed).All(e => e.Path is not null), Is.True, "each move event still carries its path");
        }
    }

    [Test]
    public void ARegionOnAnotherLevelIsRefusedWithTheReasonUntilTheOtherLevelIsGone()
    {
        (JumpNavigationHost host, RegionHandle desert) = HostingWorlds.DesertHost();
        using (host)
        {
            RegionHandle gap = host.CreateRegion("gap");
            HostAgentHandle waiting = host.RegisterAgent(gap, new Vector3(-6f, 0f, 0f)).Agent;
            JumpWorld world = host.World!;

            RuntimeResult refused = host.SetRegionKind(gap, HostingWorlds.Gap);
            Assert.That(refused.Status, Is.EqualTo(RuntimeStatus.Mismatch));
            Assert.That(refused.Reason, Does.Contain("'gap'").And.Contain("gap-course").And.Contain(world.Level.Source).And.Contain("one level at a time"));
            Assert.That(refused.Reason, Does.Not.Contain("\n"));
            Assert.That(host.GetRegionKind(gap), Is.Null, "refused: nothing changed");
            Assert.That(host.World, Is.SameAs(world));
            Assert.That(host.GetAgentState(waiting), Is.EqualTo(HostAgentState.Waiting));

            // A roadmap baked for another level than its scene's is refused too.
            var crossed = new Ballistic.Runtime.Kinds.CharacterKind(HostingWorlds.Gap.Scene, HostingWorlds.Desert.Roadmap, HostingWorlds.Gap.Animator);
            Assert.That(host.SetRegionKind(gap, crossed).Status, Is.EqualTo(RuntimeStatus.Mismatch));

            // The desert scene is left: its region freed, the gap's level starts a new world.
            Assert.That(host.FreeRegion(desert).Ok, Is.True);
            Assert.That(host.World, Is.Null, "no region holds a roadmap: the world ended");
            RuntimeResult accepted = host.SetRegionKind(gap, HostingWorlds.Gap);
            Assert.That(accepted.Ok, Is.True, accepted.ToString());
            Assert.That(host.World!.Level.Fingerprint, Is.EqualTo(HostingWorlds.Gap.Scene.Level.Fingerprint));
            Assert.That(host.GetAgentState(waiting), Is.EqualTo(HostAgentState.Active), host.GetAgentReason(waiting));
        }
    }

    [Test]
    public void FreeingARegionDetachesItsAgentsWithAReason()
    {
        (JumpNavigationHost host, RegionHandle region) = HostingWorlds.DesertHost();
        using (host)
        {
            (RoadmapNode from, RoadmapNode to) = RuntimeWorlds.ConnectedPairs(HostingWorlds.Desert.Roadmap, 1, seed: 33)[0];
            HostAgentHandle agent = host.RegisterAgent(region, RuntimeWorlds.Point(from)).Agent;
            host.SetTarget(agent, RuntimeWorlds.Point(to));
            HostingWorlds.Run(host, [agent], 30, seen => seen[agent].Count > 0);

            RuntimeResult freed = host.FreeRegion(region);
            Assert.That(freed.Ok, Is.True);
            Assert.That(freed.Reason, Does.Contain("1 agent detached"));
            Assert.That(host.IsValid(region), Is.False);
            Assert.That(host.GetAgentState(agent), Is.EqualTo(HostAgentState.Detached));
            Assert.That(host.GetWorldAgent(agent), Is.EqualTo(default(AgentHandle)));
            Assert.That(host.TryDequeueEvent(agent, out JumpEvent removed), Is.True);
            Assert.That(removed.Kind, Is.EqualTo(JumpEventKind.Removed));
            Assert.That(removed.Reason, Is.EqualTo("region 'desert' was unregistered"));
            Assert.That(host.TryDequeueEvent(agent, out _), Is.False, "exactly one removal");
            Assert.That(host.SetTarget(agent, RuntimeWorlds.Point(to)).Status, Is.EqualTo(RuntimeStatus.UnknownAgent));
            Assert.That(host.SetTarget(agent, RuntimeWorlds.Point(to)).Reason, Does.Contain("unregistered"));
            Assert.That(host.World, Is.Null);
            host.Step();

            Assert.That(host.UnregisterAgent(agent).Ok, Is.True);
            Assert.That(host.IsValid(agent), Is.False);
            Assert.That(host.AgentCount, Is.Zero);
            Assert.That(host.RegisterAgent(region, RuntimeWorlds.Point(from)).Result.Status, Is.EqualTo(RuntimeStatus.InvalidArgument), "a freed region takes no agent");
        }
    }

    [Test]
    public void ClearingARoadmapSendsTheAgentsBackToWaitingAndTheyReturn()
    {
        (JumpNavigationHost host, RegionHandle region) = HostingWorlds.DesertHost();
        using (host)
        {
            RoadmapNode node = HostingWorlds.Desert.Roadmap.Nodes[5];
            HostAgentHandle agent = host.RegisterAgent(region, RuntimeWorlds.Point(node)).Agent;
            Assert.That(host.SetRegionKind(region, null).Ok, Is.True);
            Assert.That(host.GetAgentState(agent), Is.EqualTo(HostAgentState.Waiting));
            Assert.That(host.World, Is.Null);
            Assert.That(host.TryDequeueEvent(agent, out JumpEvent e) && e.Kind == JumpEventKind.Removed, Is.True);
            Assert.That(e.Reason, Does.Contain("lost its roadmap"));

            Assert.That(host.SetRegionKind(region, HostingWorlds.Desert).Ok, Is.True);
            Assert.That(host.GetAgentState(agent), Is.EqualTo(HostAgentState.Active));
            Assert.That(Vector3.Distance(host.GetStandingPoint(agent)!.Value, RuntimeWorlds.Point(node)), Is.LessThan(1e-4f));
        }
    }

    [Test]
    public void EachQueueGetsExactlyItsAgentsEventsInOrder()
    {
        (JumpNavigationHost host, RegionHandle region) = HostingWorlds.DesertHost();
        using (host)
        {
            List<(RoadmapNode From, RoadmapNode To)> pairs = RuntimeWorlds.ConnectedPairs(HostingWorlds.Desert.Roadmap, 3, seed: 34);
            var agents = pairs.Select(p => host.RegisterAgent(region, RuntimeWorlds.Point(p.From)).Agent).ToList();
            for (int i = 0; i < agents.Count; i++)
            {
                host.SetTarget(agents[i], RuntimeWorlds.Point(pairs[i].To));
            }

            // What the world said, per world agent, against what each queue delivers (drained only every 7 ticks).
            var expected = agents.ToDictionary(a => a, _ => new List<JumpEvent>());
            var delivered = agents.ToDictionary(a => a, _ => new List<JumpEvent>());
            var worldAgents = agents.ToDictionary(a => host.GetWorldAgent(a), a => a);
            for (int tick = 0; tick < MaxTicks && delivered.Values.Any(d => !d.Any(e => e.Kind is JumpEventKind.TargetReached or JumpEventKind.PathFailed)); tick++)
            {
                host.Step();
                foreach (JumpEvent e in host.World!.Events)
                {
                    expected[worldAgents[e.Agent]].Add(e);
                }

                if (tick % 7 == 0)
                {
                    foreach (HostAgentHandle agent in agents)
                    {
                        while (host.TryDequeueEvent(agent, out JumpEvent e))
                        {
                            delivered[agent].Add(e);
                        }
                    }
                }
            }

            foreach (HostAgentHandle agent in agents)
            {
                while (host.TryDequeueEvent(agent, out JumpEvent e))
                {
                    delivered[agent].Add(e);
                }

                Assert.That(delivered[agent], Is.EqualTo(expected[agent]), $"{agent}");
                Assert.That(expected[agent], Has.Count.GreaterThanOrEqualTo(4));
                Assert.That(delivered[agent][^1].Kind, Is.EqualTo(JumpEventKind.TargetReached));
                foreach (JumpEvent e in delivered[agent].Where(e => e.Kind is JumpEventKind.JumpStarted or JumpEventKind.Landed))
                {
                    Assert.That(e.Path, Is.Not.Null, "a jump event carries its path");
                    Assert.That(e.Path!.Moves[e.Jump].Arc.Start, Is.EqualTo(e.From));
                }
            }
        }
    }

    [Test]
    public void SteppingAllocatesNothingWhileAgentsFollowTheirPaths()
    {
        (JumpNavigationHost host, RegionHandle region) = HostingWorlds.DesertHost();
        using (host)
        {
            List<(RoadmapNode From, RoadmapNode To)> pairs = RuntimeWorlds.ConnectedPairs(HostingWorlds.Desert.Roadmap, 3, seed: 35);
            var agents = pairs.Select(p => host.RegisterAgent(region, RuntimeWorlds.Point(p.From)).Agent).ToList();
            for (int i = 0; i < agents.Count; i++)
            {
                host.SetTarget(agents[i], RuntimeWorlds.Point(pairs[i].To));
            }

            // Until every path was delivered (searching and animating allocate), then the steady state.
            HostingWorlds.Run(host, agents, 600, seen => agents.All(a => host.World!.GetPath(host.GetWorldAgent(a)) is not null));
            Assume.That(agents.All(a => host.World!.GetPath(host.GetWorldAgent(a)) is not null), Is.True);
            int measured = 0;
            for (int tick = 0; tick < 30; tick++)
            {
                if (agents.Any(a => host.World!.GetPath(host.GetWorldAgent(a)) is null))
                {
                    break; // an arrival: the next tick may queue or search
                }

                long before = GC.GetAllocatedBytesForCurrentThread();
                host.Step();
                foreach (HostAgentHandle agent in agents)
                {
                    while (host.TryDequeueEvent(agent, out _))
                    {
                    }
                }

                Assert.That(GC.GetAllocatedBytesForCurrentThread() - before, Is.Zero, $"tick {tick} allocated");
                measured++;
            }

            Assert.That(measured, Is.GreaterThan(5));
        }
    }

    [Test]
    public void BadHandlesAndPointsGetAStatusNotAnException()
    {
        (JumpNavigationHost host, RegionHandle region) = HostingWorlds.DesertHost();
        using (host)
        {
            foreach (RegionHandle bad in new[] { default, new RegionHandle(7, 1), new RegionHandle(region.Index, region.Generation + 1) })
            {
                Assert.That(host.IsValid(bad), Is.False);
                Assert.That(host.RegisterAgent(bad, Vector3.Zero).Result.Status, Is.EqualTo(RuntimeStatus.InvalidArgument));
                Assert.That(host.RegisterAgent(bad, Vector3.Zero).Agent.IsAssigned, Is.False);
                Assert.That(host.SetRegionKind(bad, HostingWorlds.Desert).Reason, Does.Contain("not a region"));
                Assert.That(host.FreeRegion(bad).Status, Is.EqualTo(RuntimeStatus.InvalidArgument));
            }

            Assert.That(host.RegisterAgent(region, new Vector3(float.NaN, 0f, 0f)).Result.Status, Is.EqualTo(RuntimeStatus.InvalidArgument));
            HostAgentResult inTheSky = host.RegisterAgent(region, new Vector3(0f, 500f, 0f));
            Assert.That(inTheSky.Result.Status, Is.EqualTo(RuntimeStatus.InvalidPosition));
            Assert.That(inTheSky.Agent.IsAssigned, Is.True, "an agent that cannot stand there yet still gets a handle");
            Assert.That(host.GetAgentState(inTheSky.Agent), Is.EqualTo(HostAgentState.Unplaced));
            Assert.That(host.GetAgentReason(inTheSky.Agent), Does.Contain("cannot stand"));
            Assert.That(host.PerformJump(inTheSky.Agent, 0).Status, Is.EqualTo(RuntimeStatus.InvalidPosition));
            Assert.That(host.Warp(inTheSky.Agent, RuntimeWorlds.Point(HostingWorlds.Desert.Roadmap.Nodes[0])).Ok, Is.True, "warped onto the ground, it joins");
            Assert.That(host.GetAgentState(inTheSky.Agent), Is.EqualTo(HostAgentState.Active));

            foreach (HostAgentHandle bad in new[] { default, new HostAgentHandle(9, 1), new HostAgentHandle(inTheSky.Agent.Index, 2) })
            {
                Assert.That(host.IsValid(bad), Is.False);
                Assert.That(host.SetTarget(bad, Vector3.Zero).Status, Is.EqualTo(RuntimeStatus.UnknownAgent));
                Assert.That(host.ClearTarget(bad).Status, Is.EqualTo(RuntimeStatus.UnknownAgent));
                Assert.That(host.Warp(bad, Vector3.Zero).Status, Is.EqualTo(RuntimeStatus.UnknownAgent));
                Assert.That(host.PerformJump(bad, 0).Status, Is.EqualTo(RuntimeStatus.UnknownAgent));
                Assert.That(host.UnregisterAgent(bad).Status, Is.EqualTo(RuntimeStatus.UnknownAgent));
                Assert.That(host.TryDequeueEvent(bad, out _), Is.False);
                Assert.That(host.IsTargetReachable(bad, Vector3.Zero), Is.False);
                Assert.That(host.GetStandingPoint(bad), Is.Null);
            }

            Assert.That(host.SetTarget(inTheSky.Agent, new Vector3(0f, float.NaN, 0f)).Status, Is.EqualTo(RuntimeStatus.InvalidArgument));
            Assert.That(host.PerformJump(inTheSky.Agent, -1).Status, Is.EqualTo(RuntimeStatus.InvalidArgument));
            Assert.That(host.PerformJump(inTheSky.Agent, HostingWorlds.Desert.Roadmap.Edges.Count).Reason, Does.Contain("not an edge"));
            Assert.Throws<ArgumentException>(() => _ = new JumpNavigationHost(new WorldSettings { TickRate = 0 }));
        }
    }
}
