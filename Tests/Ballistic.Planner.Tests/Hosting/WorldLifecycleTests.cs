using System.Numerics;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Runtime;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;
using Ballistic.Runtime.Paths;

namespace Ballistic.Planner.Tests.Hosting;

/// <summary>
/// The world as the Godot server uses it: kinds and agents by handle in any order (a kind before its roadmap, agents
/// waiting for it), rebakes that keep agents and handles, one level at a time, frames of several ticks.
/// </summary>
public sealed class WorldLifecycleTests
{
    private const int MaxTicks = 60 * 60;

    [Test]
    public void AgentsAddedBeforeTheirKindHasARoadmapJoinItWhenItComes()
    {
        using JumpWorld world = HostingWorlds.Server();
        (RoadmapNode from, RoadmapNode to) = RuntimeWorlds.ConnectedPairs(HostingWorlds.Desert.Roadmap, 1, seed: 31)[0];

        // Godot readies children first: the agent asks its roadmap node for a kind before the node loads its roadmap.
        KindHandle kind = world.CreateKind("desert");
        AddAgentResult added = world.AddAgent(kind, RuntimeWorlds.Point(from));
        Assert.That(added.Ok, Is.True, added.Result.ToString());
        AgentHandle agent = added.Agent;
        Assert.That(world.GetLifecycle(agent), Is.EqualTo(AgentLifecycle.Waiting));
        Assert.That(world.GetAgentReason(agent), Does.Contain("desert"));
        Assert.That(world.SetTarget(agent, RuntimeWorlds.Point(to)).Ok, Is.True, "a waiting agent keeps its target");
        Assert.That(world.Level, Is.Null);
        Assert.That(world.Query(new AgentQuery()).Count(), Is.Zero, "a waiting agent is not simulated");
        world.Step();
        Assert.That(world.EventsOf(agent).Length, Is.Zero, "nothing happens before the roadmap comes");

        RuntimeResult set = world.ReplaceKind(kind, HostingWorlds.Desert);
        Assert.That(set.Ok, Is.True, set.ToString());
        Assert.That(set.Reason, Does.Contain("1 agent on it"));
        Assert.That(world.GetLifecycle(agent), Is.EqualTo(AgentLifecycle.Active));
        Assert.That(world.GetAgentReason(agent), Is.Null);
        Assert.That(world.Level!.Fingerprint, Is.EqualTo(HostingWorlds.Desert.Scene.Level.Fingerprint));
        Assert.That(Vector3.Distance(world.GetStandingPoint(agent)!.Value, RuntimeWorlds.Point(from)), Is.LessThan(1e-4f), "it joined where it was added");

        List<JumpEvent> events = HostingWorlds.Run(world, [agent], MaxTicks, seen => seen[agent].Any(e => e.Kind is JumpEventKind.TargetReached or JumpEventKind.PathFailed))[agent];
        Assert.That(events[0].Kind, Is.EqualTo(JumpEventKind.PathFound), "the kept target was asked for");
        Assert.That(events[^1].Kind, Is.EqualTo(JumpEventKind.TargetReached), string.Join("; ", events.Select(e => e.Reason)));
        Assert.That(Vector3.Distance(world.GetStandingPoint(agent)!.Value, RuntimeWorlds.Point(to)), Is.LessThan(1e-4f));
        Assert.That(world.GetTarget(agent), Is.Null);
    }

    [Test]
    public void ARebakeKeepsTheAgentsUnderTheirHandlesMovesNoneAndKeepsTheirTargets()
    {
        (JumpWorld world, KindHandle kind) = HostingWorlds.DesertServer();
        using (world)
        {
            Roadmap roadmap = HostingWorlds.Desert.Roadmap;
            Roadmap rebakedRoadmap = HostingWorlds.DesertRebaked.Roadmap;
            List<(RoadmapNode From, RoadmapNode To)> pairs = RuntimeWorlds.ConnectedPairs(roadmap, 2, seed: 32);
            AgentHandle idle = world.AddAgent(kind, RuntimeWorlds.Point(pairs[0].From)).Agent;
            AgentHandle moving = world.AddAgent(kind, RuntimeWorlds.Point(pairs[1].From)).Agent;
            Assert.That(world.SetTarget(moving, RuntimeWorlds.Point(pairs[1].To)).Ok, Is.True);
            HostingWorlds.Run(world, [idle, moving], MaxTicks, _ => world.GetState(moving) == AgentState.Flight);
            Assume.That(world.GetState(moving), Is.EqualTo(AgentState.Flight));
            Assert.That(world.TryGetCurrentJump(moving, out var jump), Is.True);
            AgentPath oldPath = world.GetPath(moving)!;
            Vector3 landing = oldPath.Moves[jump.Index].To.ContactCentre;
            Vector3 idleAt = world.GetStandingPoint(idle)!.Value;
            RootPose idleRoot = world.GetRootPose(idle);

            RuntimeResult rebaked = world.ReplaceKind(kind, HostingWorlds.DesertRebaked);
            Assert.That(rebaked.Ok, Is.True, rebaked.ToString());
            Assert.That(world.Kinds, Has.Count.EqualTo(1), "the kind was replaced, not added");
            Assert.That(world.Kinds[0], Is.SameAs(HostingWorlds.DesertRebaked));
            foreach (AgentHandle agent in new[] { idle, moving })
            {
                Assert.That(world.GetLifecycle(agent), Is.EqualTo(AgentLifecycle.Active), world.GetAgentReason(agent));
                Assert.That(world.IsValid(agent), Is.True, "the handles did not change");
            }

            Assert.That(world.GetStandingPoint(idle), Is.EqualTo(idleAt), "the idle agent stays exactly where it stood");
            Assert.That(world.GetRootPose(idle), Is.EqualTo(idleRoot));
            Assert.That(world.GetStance(idle) is { } now && (IsNodeOf(rebakedRoadmap, now) || now.Id < 0), Is.True, "a node of the new roadmap, or a stance off it (no id of the old one)");
            Assert.That(world.GetPath(moving), Is.SameAs(oldPath), "the agent in flight finishes its jump");
            Assert.That(world.GetState(moving), Is.EqualTo(AgentState.Flight));

            // It flies on, lands on its landing stance and stops there, moved by no more than its own motion.
            float fastest = oldPath.Moves.Where(m => m.Walk is null).Max(m => MathF.Max(m.Arc.TakeoffVelocity.Length(), (m.Arc.TakeoffVelocity - (9.81f * m.Arc.FlightTime * Vector3.UnitY)).Length()));
            Vector3 last = world.GetRootPose(moving).Position;
            float worstStep = 0f;
            List<JumpEvent> events = HostingWorlds.Run(world, [idle, moving], MaxTicks, _ =>
            {
                Vector3 root = world.GetRootPose(moving).Position;
                worstStep = MathF.Max(worstStep, Vector3.Distance(root, last));
                last = root;
                return world.GetPath(moving) is null;
            })[moving];
            Assert.That(worstStep, Is.LessThanOrEqualTo(fastest * world.Settings.TickSeconds * 1.01f), "no tick moves the body further than its flight does");
            Assert.That(events.Select(e => e.Kind), Does.Contain(JumpEventKind.Landed));
            Assert.That(world.GetStandingPoint(moving), Is.EqualTo(landing), "it stands on its landing stance");
            Assert.That(world.GetTarget(moving), Is.EqualTo(RuntimeWorlds.Point(pairs[1].To)), "its target is kept");

            Vector3 restart = world.GetStandingPoint(moving)!.Value;
            events.AddRange(HostingWorlds.Run(world, [idle, moving], MaxTicks, seen => seen[moving].Any(e => e.Kind is JumpEventKind.TargetReached or JumpEventKind.PathFailed))[moving]);
            Assert.That(events.Select(e => e.Kind), Does.Not.Contain(JumpEventKind.Removed), "a rebake is not a removal");
            JumpEvent found = events.Last(e => e.Kind == JumpEventKind.PathFound);
            Assert.That(Vector3.Distance(found.Path!.Start.ContactCentre, restart), Is.LessThan(1e-4f), "the new path starts where the agent was put");
            // Each landing but the last is a node of the new roadmap, or a stance the query placed (facing a jump): ids n + 2 on.
            int placedFrom = rebakedRoadmap.Nodes.Count + 2;
            foreach (var move in found.Path.Moves.SkipLast(1))
            {
                Assert.That(move.To.Id >= placedFrom || IsNodeOf(rebakedRoadmap, move.To), Is.True, $"jump {move.Index} lands on a node of the new roadmap");
            }

            Assert.That(found.Path.Moves.SkipLast(1).Count(m => IsNodeOf(rebakedRoadmap, m.To)), Is.Positive, "the path goes through the new roadmap");
        }
    }

    [Test]
    public void AFrameOfSeveralTicksKeepsEveryTicksEventsInOrder()
    {
        // Two worlds given the same calls: one stepped a tick at a time, the other three ticks per call (a physics
        // frame catching up, as the Godot server steps): the second's events of each call are the first's of those
        // three ticks, in order, and each agent's range holds exactly its own.
        (JumpWorld single, KindHandle singleKind) = HostingWorlds.DesertServer();
        (JumpWorld framed, KindHandle framedKind) = HostingWorlds.DesertServer();
        using (single)
        using (framed)
        {
            List<(RoadmapNode From, RoadmapNode To)> pairs = RuntimeWorlds.ConnectedPairs(HostingWorlds.Desert.Roadmap, 3, seed: 36);
            var agents = new List<AgentHandle>();
            foreach ((RoadmapNode from, RoadmapNode to) in pairs)
            {
                AgentHandle a = single.AddAgent(singleKind, RuntimeWorlds.Point(from)).Agent;
                AgentHandle b = framed.AddAgent(framedKind, RuntimeWorlds.Point(from)).Agent;
                Assert.That(b, Is.EqualTo(a));
                single.SetTarget(a, RuntimeWorlds.Point(to));
                framed.SetTarget(b, RuntimeWorlds.Point(to));
                agents.Add(a);
            }

            int arrivals = 0;
            for (int frame = 0; frame < MaxTicks / 3 && arrivals < agents.Count; frame++)
            {
                var expected = new List<JumpEvent>();
                for (int i = 0; i < 3; i++)
                {
                    single.Step();
                    expected.AddRange(single.Events.ToArray().Select(Pathless));
                }

                framed.Step(3);
                Assert.That(framed.Events.ToArray().Select(Pathless), Is.EqualTo(expected), $"frame {frame}");
                foreach (AgentHandle agent in agents)
                {
                    Assert.That(framed.EventsOf(agent).ToArray().Select(Pathless), Is.EqualTo(expected.Where(e => e.Agent == agent)), $"frame {frame}, {agent}");
                }

                arrivals += expected.Count(e => e.Kind is JumpEventKind.TargetReached or JumpEventKind.PathFailed);
            }

            Assert.That(arrivals, Is.EqualTo(agents.Count), "every agent arrived");
            Assert.That(framed.Tick, Is.EqualTo(single.Tick));
            framed.Step(0);
            Assert.That(framed.Events.Length, Is.Zero, "zero ticks: no events");
            Assert.That(() => framed.Step(-1), Throws.TypeOf<ArgumentOutOfRangeException>());
        }
    }

    [Test]
    public void AKindOnAnotherLevelIsRefusedWithTheReasonUntilTheOtherLevelIsGone()
    {
        (JumpWorld world, KindHandle desert) = HostingWorlds.DesertServer();
        using (world)
        {
            KindHandle gap = world.CreateKind("gap");
            AgentHandle waiting = world.AddAgent(gap, new Vector3(-6f, 0f, 0f)).Agent;
            Ballistic.Planner.Levels.Level level = world.Level!;

            RuntimeResult refused = world.ReplaceKind(gap, HostingWorlds.Gap);
            Assert.That(refused.Status, Is.EqualTo(RuntimeStatus.Mismatch));
            Assert.That(refused.Reason, Does.Contain("gap-course").And.Contain(level.Source).And.Contain("one level at a time"));
            Assert.That(refused.Reason, Does.Not.Contain("\n"));
            Assert.That(world.GetKindCharacter(gap), Is.Null, "refused: nothing changed");
            Assert.That(world.Level, Is.SameAs(level));
            Assert.That(world.GetLifecycle(waiting), Is.EqualTo(AgentLifecycle.Waiting));

            // A roadmap baked for another level than its scene's is refused too.
            var crossed = new CharacterKind(HostingWorlds.Gap.Scene, HostingWorlds.Desert.Roadmap, HostingWorlds.Gap.Animator);
            Assert.That(world.ReplaceKind(gap, crossed).Status, Is.EqualTo(RuntimeStatus.Mismatch));

            // The desert scene is left: its kind removed, the gap's level becomes the world's.
            Assert.That(world.RemoveKind(desert).Ok, Is.True);
            RuntimeResult accepted = world.ReplaceKind(gap, HostingWorlds.Gap);
            Assert.That(accepted.Ok, Is.True, accepted.ToString());
            Assert.That(world.Level!.Fingerprint, Is.EqualTo(HostingWorlds.Gap.Scene.Level.Fingerprint));
            Assert.That(world.GetLifecycle(waiting), Is.EqualTo(AgentLifecycle.Active), world.GetAgentReason(waiting));

            // A world made on a level keeps it, with no kind at all.
            using var pinned = new JumpWorld(HostingWorlds.Desert.Scene.Level, RuntimeWorlds.JumpOnly);
            Assert.That(pinned.ReplaceKind(pinned.CreateKind("gap"), HostingWorlds.Gap).Status, Is.EqualTo(RuntimeStatus.Mismatch));
        }
    }

    [Test]
    public void RemovingAKindDetachesItsAgentsWithAReason()
    {
        (JumpWorld world, KindHandle kind) = HostingWorlds.DesertServer();
        using (world)
        {
            (RoadmapNode from, RoadmapNode to) = RuntimeWorlds.ConnectedPairs(HostingWorlds.Desert.Roadmap, 1, seed: 33)[0];
            AgentHandle agent = world.AddAgent(kind, RuntimeWorlds.Point(from)).Agent;
            world.SetTarget(agent, RuntimeWorlds.Point(to));
            HostingWorlds.Run(world, [agent], 30, seen => seen[agent].Count > 0);

            RuntimeResult removed = world.RemoveKind(kind);
            Assert.That(removed.Ok, Is.True);
            Assert.That(removed.Reason, Does.Contain("1 agent detached"));
            Assert.That(world.IsValid(kind), Is.False);
            Assert.That(world.GetLifecycle(agent), Is.EqualTo(AgentLifecycle.Detached));
            Assert.That(world.IsValid(agent), Is.True, "the handle stays valid until the agent is removed");
            Assert.That(world.Query(new AgentQuery()).Count(), Is.Zero);
            world.Step();
            JumpEvent[] told = world.EventsOf(agent).ToArray();
            Assert.That(told, Has.Length.EqualTo(1), "exactly one removal");
            Assert.That(told[0].Kind, Is.EqualTo(JumpEventKind.Removed));
            Assert.That(told[0].Reason, Is.EqualTo("kind 'desert' was removed"));
            Assert.That(world.SetTarget(agent, RuntimeWorlds.Point(to)).Status, Is.EqualTo(RuntimeStatus.UnknownAgent));
            Assert.That(world.SetTarget(agent, RuntimeWorlds.Point(to)).Reason, Does.Contain("detached"));
            Assert.That(world.Warp(agent, RuntimeWorlds.Point(to)).Status, Is.EqualTo(RuntimeStatus.UnknownAgent));

            Assert.That(world.RemoveAgent(agent).Ok, Is.True);
            Assert.That(world.IsValid(agent), Is.False);
            Assert.That(world.AgentCount, Is.Zero);
            Assert.That(world.AddAgent(kind, RuntimeWorlds.Point(from)).Result.Status, Is.EqualTo(RuntimeStatus.UnknownKind), "a removed kind takes no agent");
            KindHandle again = world.CreateKind("again");
            Assert.That(again.Index, Is.EqualTo(kind.Index), "the index is reused");
            Assert.That(world.IsValid(kind), Is.False, "under a new generation");
        }
    }

    [Test]
    public void ClearingARoadmapSendsTheAgentsBackToWaitingAndTheyReturn()
    {
        (JumpWorld world, KindHandle kind) = HostingWorlds.DesertServer();
        using (world)
        {
            RoadmapNode node = HostingWorlds.Desert.Roadmap.Nodes[5];
            AgentHandle agent = world.AddAgent(kind, RuntimeWorlds.Point(node)).Agent;
            Assert.That(world.ReplaceKind(kind, null).Ok, Is.True);
            Assert.That(world.GetLifecycle(agent), Is.EqualTo(AgentLifecycle.Waiting));
            Assert.That(world.GetKindCharacter(kind), Is.Null);
            world.Step();
            Assert.That(world.EventsOf(agent).Length == 1 && world.EventsOf(agent)[0].Kind == JumpEventKind.Removed, Is.True);
            Assert.That(world.EventsOf(agent)[0].Reason, Does.Contain("lost its roadmap"));

            Assert.That(world.ReplaceKind(kind, HostingWorlds.Desert).Ok, Is.True);
            Assert.That(world.GetLifecycle(agent), Is.EqualTo(AgentLifecycle.Active));
            Assert.That(Vector3.Distance(world.GetStandingPoint(agent)!.Value, RuntimeWorlds.Point(node)), Is.LessThan(1e-4f));
        }
    }

    [Test]
    public void SteppingAllocatesNothingWhileAgentsFollowTheirPaths()
    {
        (JumpWorld world, KindHandle kind) = HostingWorlds.DesertServer();
        using (world)
        {
            List<(RoadmapNode From, RoadmapNode To)> pairs = RuntimeWorlds.ConnectedPairs(HostingWorlds.Desert.Roadmap, 3, seed: 35);
            var agents = pairs.Select(p => world.AddAgent(kind, RuntimeWorlds.Point(p.From)).Agent).ToList();
            for (int i = 0; i < agents.Count; i++)
            {
                world.SetTarget(agents[i], RuntimeWorlds.Point(pairs[i].To));
            }

            // Until every path was delivered (searching and animating allocate), then the steady state, read per agent as the nodes do.
            HostingWorlds.Run(world, agents, 600, seen => agents.All(a => world.GetPath(a) is not null));
            Assume.That(agents.All(a => world.GetPath(a) is not null), Is.True);
            int measured = 0;
            for (int tick = 0; tick < 30; tick++)
            {
                if (agents.Any(a => world.GetPath(a) is null))
                {
                    break; // an arrival: the next tick may queue or search
                }

                long before = GC.GetAllocatedBytesForCurrentThread();
                world.Step(2);
                int read = 0;
                foreach (AgentHandle agent in agents)
                {
                    read += world.EventsOf(agent).Length;
                }

                Assert.That(GC.GetAllocatedBytesForCurrentThread() - before, Is.Zero, $"tick {tick} allocated ({read} events read)");
                measured++;
            }

            Assert.That(measured, Is.GreaterThan(5));
        }
    }

    [Test]
    public void BadHandlesAndPointsGetAStatusNotAnException()
    {
        (JumpWorld world, KindHandle kind) = HostingWorlds.DesertServer();
        using (world)
        {
            foreach (KindHandle bad in new[] { default, new KindHandle(7, 1), new KindHandle(kind.Index, kind.Generation + 1) })
            {
                Assert.That(world.IsValid(bad), Is.False);
                Assert.That(world.AddAgent(bad, Vector3.Zero).Result.Status, Is.EqualTo(RuntimeStatus.UnknownKind));
                Assert.That(world.AddAgent(bad, Vector3.Zero).Agent.IsAssigned, Is.False);
                Assert.That(world.ReplaceKind(bad, HostingWorlds.Desert).Reason, Does.Contain("not a kind"));
                Assert.That(world.RemoveKind(bad).Status, Is.EqualTo(RuntimeStatus.UnknownKind));
                Assert.That(world.GetKindName(bad), Is.Null);
            }

            Assert.That(world.AddAgent(kind, new Vector3(float.NaN, 0f, 0f)).Result.Status, Is.EqualTo(RuntimeStatus.InvalidArgument));
            AddAgentResult inTheSky = world.AddAgent(kind, new Vector3(0f, 500f, 0f));
            Assert.That(inTheSky.Result.Status, Is.EqualTo(RuntimeStatus.InvalidPosition));
            Assert.That(inTheSky.Agent.IsAssigned, Is.True, "an agent that cannot stand there yet still gets a handle");
            Assert.That(world.GetLifecycle(inTheSky.Agent), Is.EqualTo(AgentLifecycle.Unplaced));
            Assert.That(world.GetAgentReason(inTheSky.Agent), Does.Contain("cannot stand"));
            Assert.That(world.GetStandingPoint(inTheSky.Agent), Is.EqualTo(new Vector3(0f, 500f, 0f)));
            Assert.That(world.PerformJump(inTheSky.Agent, 0).Status, Is.EqualTo(RuntimeStatus.InvalidPosition));
            Assert.That(world.IsTargetReachable(inTheSky.Agent, Vector3.Zero), Is.False);
            Assert.That(world.Warp(inTheSky.Agent, new Vector3(0f, 400f, 0f)).Status, Is.EqualTo(RuntimeStatus.InvalidPosition), "still nowhere to stand");
            Assert.That(world.GetLifecycle(inTheSky.Agent), Is.EqualTo(AgentLifecycle.Unplaced));
            Assert.That(world.Warp(inTheSky.Agent, RuntimeWorlds.Point(HostingWorlds.Desert.Roadmap.Nodes[0])).Ok, Is.True, "warped onto the ground, it joins");
            Assert.That(world.GetLifecycle(inTheSky.Agent), Is.EqualTo(AgentLifecycle.Active));

            foreach (AgentHandle bad in new[] { default, new AgentHandle(9, 1), new AgentHandle(inTheSky.Agent.Index, 2) })
            {
                Assert.That(world.IsValid(bad), Is.False);
                Assert.That(world.SetTarget(bad, Vector3.Zero).Status, Is.EqualTo(RuntimeStatus.UnknownAgent));
                Assert.That(world.ClearTarget(bad).Status, Is.EqualTo(RuntimeStatus.UnknownAgent));
                Assert.That(world.Warp(bad, Vector3.Zero).Status, Is.EqualTo(RuntimeStatus.UnknownAgent));
                Assert.That(world.PerformJump(bad, 0).Status, Is.EqualTo(RuntimeStatus.UnknownAgent));
                Assert.That(world.RemoveAgent(bad).Status, Is.EqualTo(RuntimeStatus.UnknownAgent));
                Assert.That(world.EventsOf(bad).Length, Is.Zero);
                Assert.That(world.IsTargetReachable(bad, Vector3.Zero), Is.False);
                Assert.That(world.GetStandingPoint(bad), Is.Null);
                Assert.That(world.GetLifecycle(bad), Is.EqualTo(AgentLifecycle.Detached));
            }

            Assert.That(world.SetTarget(inTheSky.Agent, new Vector3(0f, float.NaN, 0f)).Status, Is.EqualTo(RuntimeStatus.InvalidArgument));
            Assert.That(world.PerformJump(inTheSky.Agent, -1).Status, Is.EqualTo(RuntimeStatus.InvalidArgument));
            Assert.That(world.PerformJump(inTheSky.Agent, HostingWorlds.Desert.Roadmap.Edges.Count).Reason, Does.Contain("not an edge"));
            Assert.Throws<ArgumentException>(() => _ = new JumpWorld(new WorldSettings { TickRate = 0 }));
        }
    }

    /// <summary>The event without its path (two worlds animate equal paths into different objects), which its move index and points stand for.</summary>
    private static JumpEvent Pathless(JumpEvent e) => e with { Path = null };

    /// <summary>True when <paramref name="node"/> is <paramref name="roadmap"/>'s node of its id.</summary>
    private static bool IsNodeOf(Roadmap roadmap, RoadmapNode node) =>
        (uint)node.Id < (uint)roadmap.Nodes.Count && roadmap.Nodes[node.Id].Pose == node.Pose;
}
