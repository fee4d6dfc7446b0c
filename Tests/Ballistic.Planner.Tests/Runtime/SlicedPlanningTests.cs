using System.Numerics;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>
/// A world with no background threads advances its path requests on the tick in slices
/// (<see cref="WorldSettings.PlanningTimePerTick"/>), as Detour's path queue spends a budget per update: the same paths
/// arrive on the same ticks as when each request is solved whole.
/// </summary>
public sealed class SlicedPlanningTests
{
    /// <summary>
    /// Four agents sent to seeded targets, two of them retargeted on the second tick (their first jobs dropped part-way):
    /// every event and every tick's root positions, as text, with the steps the tick thread took per tick.
    /// </summary>
    private static (List<string> Trace, List<int> Steps) Scenario(TimeSpan? budget)
    {
        // A kind of its own: its remembered animations (shared by the worlds of a kind) start empty.
        CharacterKind desert = RuntimeWorlds.DesertSkeleton;
        var world = new JumpWorld(desert.Scene.Level, RuntimeWorlds.JumpOnly with { PlanningTimePerTick = budget, PathLatencyTicks = 8 });
        KindHandle kind = world.AddKind(new CharacterKind(desert.Scene, desert.Roadmap, desert.Animator)).Kind;
        using (world)
        {
            Roadmap roadmap = RuntimeWorlds.DesertSkeleton.Roadmap;
            List<(RoadmapNode From, RoadmapNode To)> pairs = RuntimeWorlds.ConnectedPairs(roadmap, 4, seed: 5);
            var agents = pairs.Select(p => world.AddAgent(kind, RuntimeWorlds.Point(p.From)).Agent).ToList();
            for (int i = 0; i < agents.Count; i++)
            {
                world.SetTarget(agents[i], RuntimeWorlds.Point(pairs[i].To));
            }

            var trace = new List<string>();
            var steps = new List<int>();
            for (int tick = 0; tick < 400; tick++)
            {
                if (tick == 2)
                {
                    world.SetTarget(agents[0], RuntimeWorlds.Point(pairs[2].From));
                    world.SetTarget(agents[3], RuntimeWorlds.Point(pairs[1].To));
                }

                world.Step();
                steps.Add(world.LastTickPlanningSteps);
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

            return (trace, steps);
        }
    }

    [Test]
    public void RequestsAdvancedInSlicesArriveOnTheTicksAndWithThePathsOfWholeSearches()
    {
        (List<string> whole, List<int> none) = Scenario(budget: null);
        (List<string> sliced, List<int> steps) = Scenario(budget: TimeSpan.FromTicks(1));
        (List<string> defaulted, _) = Scenario(budget: WorldSettings.DefaultPlanningTimePerTick);
        Assert.Multiple(() =>
        {
            Assert.That(whole.Count(l => l.Contains(nameof(JumpEventKind.PathFound), StringComparison.Ordinal)), Is.GreaterThanOrEqualTo(4), "the agents found paths");
            Assert.That(none, Has.All.EqualTo(0), "solved whole on the tick each starts: no slices");

            // A budget of one clock tick: one step (the least a call takes) per tick, on every tick a job is in flight
            // before its due tick finishes it.
            Assert.That(steps.Take(7), Has.All.EqualTo(1), "one step per tick while the jobs are in flight: " + string.Join(",", steps.Take(60)));
            Assert.That(steps, Has.All.LessThanOrEqualTo(1));
            Assert.That(sliced, Is.EqualTo(whole), "the same events on the same ticks and the same trajectories");
            Assert.That(defaulted, Is.EqualTo(whole), "the same with the default budget");
        });
    }

    /// <summary>
    /// Without waiting for late requests (<see cref="WorldSettings.WaitForAnimation"/> off), a job advanced in slices is
    /// never finished on its due tick: its path arrives at the first tick after it at which the slices have ended it
    /// (later than a whole search's, one step a tick here), and the agents make the same jumps.
    /// </summary>
    [Test]
    public void WithoutWaitingASlicedRequestArrivesWhenItsSlicesEndItWithTheSameJumps()
    {
        static (Dictionary<int, long> Found, Dictionary<int, List<string>> Jumps) Run(TimeSpan? budget)
        {
            CharacterKind desert = RuntimeWorlds.DesertSkeleton;
            using var world = new JumpWorld(desert.Scene.Level, RuntimeWorlds.JumpOnly with { PlanningTimePerTick = budget, WaitForAnimation = false, PathLatencyTicks = 2 });
            KindHandle kind = world.AddKind(new CharacterKind(desert.Scene, desert.Roadmap, desert.Animator)).Kind;
            List<(RoadmapNode From, RoadmapNode To)> pairs = RuntimeWorlds.ConnectedPairs(desert.Roadmap, 3, seed: 8);
            var agents = pairs.Select(p => world.AddAgent(kind, RuntimeWorlds.Point(p.From)).Agent).ToList();
            for (int i = 0; i < agents.Count; i++)
            {
                world.SetTarget(agents[i], RuntimeWorlds.Point(pairs[i].To));
            }

            var found = new Dictionary<int, long>();
            var jumps = agents.ToDictionary(a => agents.IndexOf(a), _ => new List<string>());
            for (int tick = 0; tick < 6_000 && jumps.Values.Any(j => !j.Contains("reached")); tick++)
            {
                world.Step();
                foreach (JumpEvent e in world.Events)
                {
                    int i = agents.IndexOf(e.Agent);
                    if (e.Kind == JumpEventKind.PathFound)
                    {
                        found.TryAdd(i, e.Tick);
                    }
                    else if (e.Kind == JumpEventKind.JumpStarted)
                    {
                        jumps[i].Add($"{e.From} {e.To} {e.Velocity}");
                    }
                    else if (e.Kind == JumpEventKind.TargetReached)
                    {
                        jumps[i].Add("reached");
                    }
                }
            }

            return (found, jumps);
        }

        (Dictionary<int, long> wholeFound, Dictionary<int, List<string>> wholeJumps) = Run(budget: null);
        (Dictionary<int, long> slicedFound, Dictionary<int, List<string>> slicedJumps) = Run(budget: TimeSpan.FromTicks(1));
        Assert.Multiple(() =>
        {
            Assert.That(wholeFound, Has.Count.EqualTo(3), "every agent found a path");
            Assert.That(slicedFound.Keys, Is.EquivalentTo(wholeFound.Keys));
            Assert.That(wholeFound.Values, Has.All.EqualTo(wholeFound.Values.Min()), "whole searches arrive on their due tick");
            Assert.That(slicedFound.Values.Max(), Is.GreaterThan(wholeFound.Values.Max()), "sliced ones, one step a tick, arrive later");
            foreach ((int agent, List<string> made) in wholeJumps)
            {
                Assert.That(made, Does.Contain("reached"), $"agent {agent} reached its target");
                Assert.That(slicedJumps[agent], Is.EqualTo(made), $"agent {agent} made the same jumps");
            }
        });
    }

    [Test]
    public void APlanningBudgetThatIsNotPositiveIsRefusedWithOneLine()
    {
        var settings = new WorldSettings { PlanningTimePerTick = TimeSpan.Zero };
        Assert.That(settings.Problem(), Is.EqualTo("PlanningTimePerTick must be positive (or null: each request solved whole), not 0 s"));
        Assert.That(new WorldSettings { PlanningTimePerTick = null }.Problem(), Is.Null);
        Assert.That(new WorldSettings().PlanningTimePerTick, Is.EqualTo(TimeSpan.FromMilliseconds(2)));
    }
}
