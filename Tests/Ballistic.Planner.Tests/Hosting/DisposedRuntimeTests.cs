using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Runtime;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Planner.Tests.Hosting;

/// <summary>After <c>Dispose</c> the host and the world refuse every call with a result that says so: no exception, nothing silently lost.</summary>
public sealed class DisposedRuntimeTests
{
    [Test]
    public void AServerWorldDisposedUnderItsAgentsRefusesEveryCallWithoutThrowing()
    {
        (JumpWorld host, KindHandle region) = HostingWorlds.DesertServer();
        (RoadmapNode from, RoadmapNode to) = RuntimeWorlds.ConnectedPairs(HostingWorlds.Desert.Roadmap, 1, seed: 41)[0];
        AgentHandle agent = host.AddAgent(region, RuntimeWorlds.Point(from)).Agent;
        Assume.That(host.GetLifecycle(agent), Is.EqualTo(AgentLifecycle.Active));
        host.Dispose();

        // What a node leaving the tree after the server calls (JumpAgent3D._ExitTree unregisters its agent).
        RuntimeResult[] refused =
        [
            host.SetTarget(agent, RuntimeWorlds.Point(to)),
            host.ClearTarget(agent),
            host.Warp(agent, RuntimeWorlds.Point(to)),
            host.PerformJump(agent, 0),
            host.RemoveAgent(agent),
            host.AddAgent(region, RuntimeWorlds.Point(from)).Result,
            host.ReplaceKind(region, HostingWorlds.Desert),
            host.RemoveKind(region),
            host.AddKind(HostingWorlds.Desert).Result,
        ];
        Assert.Multiple(() =>
        {
            foreach (RuntimeResult result in refused)
            {
                Assert.That(result.Status, Is.EqualTo(RuntimeStatus.Disposed), result.ToString());
                Assert.That(result.Reason, Does.Contain("disposed"));
            }

            Assert.That(host.IsTargetReachable(agent, RuntimeWorlds.Point(to)), Is.False);
            Assert.That(host.GetStandingPoint(agent), Is.Not.Null, "where it was known to stand");
            Assert.That(host.CreateKind("late"), Is.EqualTo(default(KindHandle)), "no kind is made after dispose");
            Assert.That(host.EventsOf(agent).Length, Is.Zero);
            host.Dispose(); // twice: nothing happens
        });
    }

    [Test]
    public void ADisposedWorldRefusesEveryChangeAndSaysSo()
    {
        (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert(RuntimeWorlds.JumpOnly);
        (RoadmapNode from, RoadmapNode to) = RuntimeWorlds.ConnectedPairs(RuntimeWorlds.DesertSkeleton.Roadmap, 1, seed: 42)[0];
        AgentHandle agent = world.AddAgent(kind, RuntimeWorlds.Point(from)).Agent;
        Assume.That(world.IsValid(agent), Is.True);
        world.Dispose();
        RuntimeResult[] refused =
        [
            world.AddKind(RuntimeWorlds.DesertSkeleton).Result,
            world.ReplaceKind(kind, RuntimeWorlds.DesertSkeleton),
            world.AddAgent(kind, RuntimeWorlds.Point(from)).Result,
            world.SetTarget(agent, RuntimeWorlds.Point(to)),
            world.ClearTarget(agent),
            world.Warp(agent, RuntimeWorlds.Point(to)),
            world.PerformJump(agent, 0),
            world.SetPoseEnabled(agent, false),
            world.RemoveAgent(agent),
        ];
        Assert.Multiple(() =>
        {
            foreach (RuntimeResult result in refused)
            {
                Assert.That(result.Status, Is.EqualTo(RuntimeStatus.Disposed), result.ToString());
            }

            Assert.That(world.Kinds, Has.Count.EqualTo(1), "no kind was added");
            Assert.That(world.AgentCount, Is.EqualTo(1), "no agent was added or removed");
            Assert.That(world.GetTarget(agent), Is.Null, "the target was not taken");
            Assert.That(world.Step, Throws.TypeOf<ObjectDisposedException>(), "stepping a disposed world is a programming error");
        });
    }
}
