using System.Numerics;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Runtime;
using Ballistic.Planner.Tests.Support;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;
using Ballistic.Runtime.Paths;

namespace Ballistic.Planner.Tests.Hosting;

/// <summary>What the hosting layer added to the world: one given jump performed, a kind replaced by its rebake.</summary>
public sealed class PerformJumpTests
{
    [Test]
    public void PerformJumpWarpsToTheTakeoffAndFliesExactlyThatEdge()
    {
        Roadmap roadmap = RuntimeWorlds.DesertSkeleton.Roadmap;
        (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert();
        using (world)
        {
            int edge = Enumerable.Range(0, roadmap.Edges.Count).First(e => Vector3.Distance(roadmap.Positions[roadmap.Edges[e].From], roadmap.Positions[roadmap.Edges[e].To]) > 2f);
            RoadmapEdge jump = roadmap.Edges[edge];
            AgentHandle agent = world.AddAgent(kind, RuntimeWorlds.Point(roadmap.Nodes[(jump.From + 1) % roadmap.Nodes.Count])).Agent;

            Assert.That(world.PerformJump(agent, edge).Ok, Is.True);
            Assert.That(world.GetStance(agent), Is.SameAs(roadmap.Nodes[jump.From]), "standing on the takeoff node at once");
            Assert.That(world.GetRootPose(agent), Is.EqualTo(roadmap.Nodes[jump.From].Pose));
            Assert.That(world.GetTarget(agent), Is.EqualTo(roadmap.ContactCentres[jump.To]));
            Assert.That(world.IsPathPending(agent), Is.True);

            AgentPath? path = null;
            List<JumpEvent> events = RuntimeWorlds.Run(world, 600, RuntimeWorlds.Concluded, w => path ??= w.GetPath(agent));
            Assert.That(events.Select(e => e.Kind), Is.EqualTo(new[] { JumpEventKind.PathFound, JumpEventKind.JumpStarted, JumpEventKind.Landed, JumpEventKind.TargetReached }), string.Join("; ", events.Select(e => e.Reason)));
            Assert.That(path!.Moves.Single().Arc, Is.EqualTo(jump.Arc), "the roadmap's own arc, no search");
            Assert.That(events[1].Velocity, Is.EqualTo(jump.Arc.TakeoffVelocity));
            PhysicsChecks.AssertJump(RuntimeWorlds.DesertSkeleton.Scene, roadmap.Nodes[jump.From], roadmap.Nodes[jump.To], path.Moves[0].Arc, $"edge {edge}");
            Assert.That(world.GetRootPose(agent).Position, Is.EqualTo(roadmap.Nodes[jump.To].Pose.Position));
            Assert.That(world.GetStance(agent), Is.SameAs(roadmap.Nodes[jump.To]));

            Assert.That(world.PerformJump(agent, -1).Status, Is.EqualTo(RuntimeStatus.InvalidArgument));
            Assert.That(world.PerformJump(agent, roadmap.Edges.Count).Reason, Does.Contain("not an edge"));
            Assert.That(world.PerformJump(default, edge).Status, Is.EqualTo(RuntimeStatus.UnknownAgent));
            Assert.That(world.GetStance(agent), Is.SameAs(roadmap.Nodes[jump.To]), "refused: the agent stays");
        }
    }

    [Test]
    public void AKindIsReplacedInPlaceWithItsAgentsUnderTheirHandles()
    {
        (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert();
        using (world)
        {
            CharacterKind rebaked = HostingWorlds.DesertRebaked;
            AgentHandle agent = world.AddAgent(kind, RuntimeWorlds.Point(RuntimeWorlds.DesertSkeleton.Roadmap.Nodes[0])).Agent;
            Assert.That(world.ReplaceKind(kind, HostingWorlds.Gap).Status, Is.EqualTo(RuntimeStatus.Mismatch));
            Assert.That(world.ReplaceKind(new KindHandle(3, 1), rebaked).Status, Is.EqualTo(RuntimeStatus.UnknownKind));
            Assert.That(world.Kinds[0], Is.SameAs(RuntimeWorlds.DesertSkeleton), "refused: unchanged");
            Assert.That(world.GetStance(agent), Is.SameAs(RuntimeWorlds.DesertSkeleton.Roadmap.Nodes[0]), "refused: the agent stays on the old roadmap");

            RuntimeResult replaced = world.ReplaceKind(kind, rebaked);
            Assert.That(replaced.Ok, Is.True, replaced.ToString());
            Assert.That(replaced.Reason, Does.Contain("1 agent put on its new roadmap, 0 agents finishing a move first, 0 agents unplaced"));
            Assert.That(world.Kinds, Has.Count.EqualTo(1));
            Assert.That(world.Kinds[0], Is.SameAs(rebaked));
            Assert.That(world.IsValid(agent), Is.True, "the agent keeps its handle");
            Assert.That(world.GetKind(agent), Is.EqualTo(kind));
            RoadmapNode stance = world.GetStance(agent)!;
            Assert.That(stance.Pose, Is.EqualTo(RuntimeWorlds.DesertSkeleton.Roadmap.Nodes[0].Pose), "the same body keeps the very stance it stood on");
            Assert.That(world.GetRootPose(agent), Is.EqualTo(stance.Pose), "not moved");
            Assert.That((stance.Id >= 0 && stance.Id < rebaked.Roadmap.Nodes.Count && rebaked.Roadmap.Nodes[stance.Id].Pose == stance.Pose) || stance.Id < 0, Is.True, "a node of the new roadmap, or a stance off it (no id of the old one)");
            Assert.That(RuntimeWorlds.Run(world, 2).Select(e => e.Kind), Does.Not.Contain(JumpEventKind.Removed), "a rebake is not a removal");

            // Agents of the kind now search the new roadmap.
            (RoadmapNode from, RoadmapNode to) = RuntimeWorlds.ConnectedPairs(rebaked.Roadmap, 1, seed: 51)[0];
            AgentHandle again = world.AddAgent(kind, rebaked.Roadmap.ContactCentres[from.Id]).Agent;
            Assert.That(world.GetStance(again), Is.SameAs(rebaked.Roadmap.Nodes[from.Id]));
            world.SetTarget(again, rebaked.Roadmap.ContactCentres[to.Id]);
            AgentPath? path = null;
            List<JumpEvent> events = RuntimeWorlds.Run(world, 3600, RuntimeWorlds.Concluded, w => path ??= w.GetPath(again));
            Assert.That(events[^1].Kind, Is.EqualTo(JumpEventKind.TargetReached), string.Join("; ", events.Select(e => e.Reason)));
            // Every takeoff is a node of the new roadmap, or a stance the query placed (facing a jump: ids n + 2 on).
            int placedFrom = rebaked.Roadmap.Nodes.Count + 2;
            Assert.That(path!.Moves.All(m => m.From.Id >= placedFrom || ReferenceEquals(m.From, rebaked.Roadmap.Nodes[m.From.Id])), Is.True, "every takeoff is a node of the new roadmap");
            Assert.That(path.Moves.Count(m => m.From.Id < placedFrom), Is.Positive);
        }
    }
}
