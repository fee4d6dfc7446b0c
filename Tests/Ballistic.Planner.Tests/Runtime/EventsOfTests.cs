using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>
/// One agent's events are one range (<see cref="JumpWorld.EventsOf"/>): exactly that agent's events of the tick, in
/// order, without walking every agent's; a slot reused within a tick keeps the old agent's events apart from the new
/// one's; reading them allocates nothing.
/// </summary>
public sealed class EventsOfTests
{
    [Test]
    public void EachAgentsRangeIsItsEventsInOrder()
    {
        (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert();
        using (world)
        {
            var agents = new List<AgentHandle>();
            foreach ((RoadmapNode from, RoadmapNode to) in RuntimeWorlds.ConnectedPairs(RuntimeWorlds.DesertSkeleton.Roadmap, 5, seed: 63))
            {
                AgentHandle agent = world.AddAgent(kind, RuntimeWorlds.Point(from)).Agent;
                Assert.That(world.SetTarget(agent, RuntimeWorlds.Point(to)).Ok, Is.True);
                agents.Add(agent);
            }

            int seen = 0;
            for (int tick = 0; tick < 600; tick++)
            {
                if (tick == 40)
                {
                    // Remove one agent and add another in its slot before the next tick: its range holds both, apart.
                    RoadmapNode stance = world.GetStance(agents[0]) ?? RuntimeWorlds.DesertSkeleton.Roadmap.Nodes[0];
                    Assert.That(world.RemoveAgent(agents[0]).Ok, Is.True);
                    AgentHandle again = world.AddAgent(kind, RuntimeWorlds.Point(RuntimeWorlds.DesertSkeleton.Roadmap.Nodes[stance.Id])).Agent;
                    Assert.That(again.Index, Is.EqualTo(agents[0].Index), "the slot is reused");
                    agents.Add(again);
                }

                world.Step();
                JumpEvent[] all = world.Events.ToArray();
                foreach (AgentHandle agent in agents)
                {
                    JumpEvent[] mine = world.EventsOf(agent).ToArray();
                    Assert.That(mine, Is.EqualTo(all.Where(e => e.Agent == agent).ToArray()), $"{agent} on tick {world.Tick}");
                    seen += mine.Length;
                }
            }

            Assert.That(seen, Is.GreaterThan(20), "the agents found paths, took off and landed");
            Assert.That(world.EventsOf(default).IsEmpty, Is.True);
        }
    }

    [Test]
    public void ReadingOneAgentsEventsAllocatesNothing()
    {
        (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert();
        using (world)
        {
            (AgentHandle agent, _, _) = RuntimeWorlds.SendAcross(world, kind, seed: 12);
            int found = 0;
            for (int tick = 0; tick < 300; tick++)
            {
                world.Step();
                long before = GC.GetAllocatedBytesForCurrentThread();
                found += world.EventsOf(agent).Length; // sorts this tick's events by agent
                long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
                if (tick > 0)
                {
                    Assert.That(allocated, Is.Zero, $"tick {tick}: the sort's buffers grew on the first read only");
                }
            }

            Assert.That(found, Is.Positive);
        }
    }
}
