using System.Numerics;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>Same kinds, settings and calls: the same trajectories and events, whatever the animation threads; no allocation on a plain tick.</summary>
public sealed class DeterminismTests
{
    /// <summary>Eight agents sent to seeded targets, retargeted half-way: every tick's root positions and every event, as text.</summary>
    private static List<string> Scenario(int threads)
    {
        (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert(RuntimeWorlds.JumpOnly with { AnimationThreads = threads, PathLatencyTicks = 3, MaxSearchesPerTick = 3 });
        using (world)
        {
            Roadmap roadmap = RuntimeWorlds.DesertSkeleton.Roadmap;
            List<(RoadmapNode From, RoadmapNode To)> pairs = RuntimeWorlds.ConnectedPairs(roadmap, 8, seed: 11);
            var agents = pairs.Select(p => world.AddAgent(kind, RuntimeWorlds.Point(p.From)).Agent).ToList();
            for (int i = 0; i < agents.Count; i++)
            {
                world.SetTarget(agents[i], RuntimeWorlds.Point(pairs[i].To));
            }

            var trace = new List<string>();
            for (int tick = 0; tick < 600; tick++)
            {
                if (tick == 150)
                {
                    // Retarget every other agent to another's start, mid-path.
                    for (int i = 0; i < agents.Count; i += 2)
                    {
                        world.SetTarget(agents[i], RuntimeWorlds.Point(pairs[(i + 3) % pairs.Count].From));
                    }
                }

                world.Step();
                foreach (JumpEvent e in world.Events)
                {
                    trace.Add($"{e.Tick} {e.Kind} {e.Agent} {e.Jump} {e.Time:R} {e.From} {e.To} {e.Velocity} {e.Reason}");
                }

                foreach (AgentHandle agent in agents)
                {
                    Vector3 p = world.GetRootPose(agent).Position;
                    trace.Add($"{tick} {agent} {world.GetState(agent)} {p.X:R} {p.Y:R} {p.Z:R}");
                }
            }

            return trace;
        }
    }

    [Test]
    public void TrajectoriesAndEventsDoNotDependOnTheAnimationThreads()
    {
        List<string> inline = Scenario(threads: 0);
        List<string> one = Scenario(threads: 1);
        List<string> four = Scenario(threads: 4);
        List<string> eight = Scenario(threads: 8);
        Assert.That(inline.Count(l => l.Contains("JumpStarted", StringComparison.Ordinal)), Is.GreaterThan(8), "agents jumped");
        Assert.That(one, Is.EqualTo(inline));
        Assert.That(four, Is.EqualTo(inline));
        Assert.That(eight, Is.EqualTo(inline), "more work items than cores");
    }

    [Test]
    public void ATickOfAgentsInStanceOrFlightAllocatesNothing()
    {
        (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert();
        using (world)
        {
            List<(RoadmapNode From, RoadmapNode To)> pairs = RuntimeWorlds.ConnectedPairs(RuntimeWorlds.DesertSkeleton.Roadmap, 6, seed: 12);
            var agents = pairs.Select(p => world.AddAgent(kind, RuntimeWorlds.Point(p.From)).Agent).ToList();
            for (int i = 0; i < agents.Count; i++)
            {
                world.SetTarget(agents[i], RuntimeWorlds.Point(pairs[i].To));
            }

            // Until every path is delivered (searches and path objects allocate, by design).
            RuntimeWorlds.Run(world, 600, (w, _) => w.QueuedRequests == 0 && w.AnimatingRequests == 0);
            Assume.That(agents.Count(a => world.GetPath(a) is not null), Is.GreaterThanOrEqualTo(3), "agents follow paths");

            int measured = 0;
            int airborne = 0;
            for (int tick = 0; tick < 240; tick++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                world.Step();
                long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
                Assert.That(allocated, Is.Zero, $"tick {world.Tick} allocated {allocated} bytes");
                measured++;
                airborne += agents.Count(a => world.GetState(a) is AgentState.Flight or AgentState.Takeoff or AgentState.Landing);
            }

            Assert.That(measured, Is.EqualTo(240));
            Assert.That(airborne, Is.GreaterThan(50), "the ticks measured had agents in the air");
        }
    }
}
