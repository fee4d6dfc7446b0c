using System.Numerics;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>
/// The navigation status component says, every tick, what the events said so far: planning from the target's
/// asking, following from the path found, reached from the arrival, failed (with the same reason) from a failure,
/// idle once a cleared target's agent stops.
/// </summary>
public sealed class NavigationStatusTests
{
    [Test]
    public void EachAgentsStatusFollowsItsEventsTickByTick()
    {
        (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert();
        using (world)
        {
            List<(RoadmapNode From, RoadmapNode To)> pairs = RuntimeWorlds.ConnectedPairs(RuntimeWorlds.DesertSkeleton.Roadmap, 3, seed: 61);
            AgentHandle[] agents = [.. pairs.Select(p => world.AddAgent(kind, RuntimeWorlds.Point(p.From)).Agent)];
            AgentHandle idle = world.AddAgent(kind, RuntimeWorlds.Point(RuntimeWorlds.DesertSkeleton.Roadmap.Nodes[1])).Agent;
            Assert.That(agents.Append(idle).Select(world.GetNavigationStatus), Is.All.EqualTo(NavigationStatus.Idle), "no target yet");

            world.SetTarget(agents[0], RuntimeWorlds.Point(pairs[0].To));
            world.SetTarget(agents[1], new Vector3(500f, 0f, 500f)); // off the level
            world.SetTarget(agents[2], RuntimeWorlds.Point(pairs[2].To));
            Assert.That(agents.Select(world.GetNavigationStatus), Is.All.EqualTo(NavigationStatus.Planning));

            var expected = agents.ToDictionary(a => a, _ => NavigationStatus.Planning);
            var failures = new Dictionary<AgentHandle, string?>();
            bool cleared = false;
            var seen = new HashSet<NavigationStatus>();
            for (int tick = 0; tick < 60 * 60 && expected.Values.Any(s => s is NavigationStatus.Planning or NavigationStatus.Following); tick++)
            {
                if (!cleared && world.GetState(agents[2]) == AgentState.Flight)
                {
                    // Cleared in the air: it follows its path to the next stance, then stands idle.
                    world.ClearTarget(agents[2]);
                    cleared = true;
                }

                world.Step();
                foreach (AgentHandle agent in agents)
                {
                    foreach (JumpEvent e in world.EventsOf(agent))
                    {
                        switch (e.Kind)
                        {
                            case JumpEventKind.PathFound:
                                expected[agent] = NavigationStatus.Following;
                                break;
                            case JumpEventKind.TargetReached:
                                expected[agent] = NavigationStatus.Reached;
                                break;
                            case JumpEventKind.PathFailed:
                                expected[agent] = NavigationStatus.Failed;
                                failures[agent] = e.Reason;
                                break;
                        }
                    }

                    if (agent == agents[2] && cleared && world.GetPath(agent) is null)
                    {
                        expected[agent] = NavigationStatus.Idle;
                    }

                    Assert.That(world.GetNavigationStatus(agent), Is.EqualTo(expected[agent]), $"{agent} on tick {world.Tick}");
                    Assert.That(world.NavigationStatuses[agent.Index], Is.EqualTo(expected[agent]));
                    seen.Add(expected[agent]);
                }
            }

            Assert.That(world.GetNavigationStatus(agents[0]), Is.EqualTo(NavigationStatus.Reached));
            Assert.That(world.GetNavigationStatus(agents[1]), Is.EqualTo(NavigationStatus.Failed));
            Assert.That(world.GetNavigationFailure(agents[1]), Is.EqualTo(failures[agents[1]]).And.Not.Null, "the failure's own reason");
            Assert.That(world.GetNavigationFailure(agents[0]), Is.Null);
            Assert.That(cleared && world.GetNavigationStatus(agents[2]) == NavigationStatus.Idle, Is.True, "the cleared agent stopped and stands idle");
            Assert.That(seen, Is.SupersetOf(new[] { NavigationStatus.Planning, NavigationStatus.Following, NavigationStatus.Reached, NavigationStatus.Failed, NavigationStatus.Idle }));
            Assert.That(world.GetNavigationStatus(idle), Is.EqualTo(NavigationStatus.Idle));

            // Sent again, then warped away: planning anew from where it was pushed; cleared standing: idle at once.
            world.SetTarget(agents[0], RuntimeWorlds.Point(pairs[0].From));
            Assert.That(world.GetNavigationStatus(agents[0]), Is.EqualTo(NavigationStatus.Planning));
            Assert.That(world.ClearTarget(agents[0]).Ok, Is.True);
            Assert.That(world.GetNavigationStatus(agents[0]), Is.EqualTo(NavigationStatus.Idle));
            Assert.That(world.Warp(agents[1], RuntimeWorlds.Point(pairs[1].To)).Ok, Is.True);
            Assert.That(world.GetNavigationStatus(agents[1]), Is.EqualTo(NavigationStatus.Planning), "it still has its target: asked again from there");
            Assert.That(world.GetNavigationStatus(default), Is.EqualTo(NavigationStatus.Idle));
        }
    }
}
