using System.Numerics;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;
using Ballistic.Runtime.Paths;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>Agents in a world: paths found, followed exactly on their arcs, events in order, jumps that pass the physics checks.</summary>
public sealed class JumpWorldTests
{
    private const int MaxTicks = 60 * 60;

    [Test]
    public void AnAgentReachesItsTargetWithEventsInOrder()
    {
        (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert();
        using (world)
        {
            (RoadmapNode from, RoadmapNode to) = RuntimeWorlds.ConnectedPairs(RuntimeWorlds.DesertSkeleton.Roadmap, 1, seed: 1)[0];
            AddAgentResult added = world.AddAgent(kind, RuntimeWorlds.Point(from));
            Assert.That(added.Ok, Is.True, added.Result.ToString());
            Assert.That(world.SetTarget(added.Agent, RuntimeWorlds.Point(to)).Ok, Is.True);

            List<JumpEvent> events = RuntimeWorlds.Run(world, MaxTicks, RuntimeWorlds.Concluded);
            Assert.That(events.Select(e => e.Kind), Does.Not.Contain(JumpEventKind.PathFailed), string.Join("; ", events.Select(e => e.Reason)));
            Assert.That(events[0].Kind, Is.EqualTo(JumpEventKind.PathFound));
            Assert.That(events[^1].Kind, Is.EqualTo(JumpEventKind.TargetReached));
            var jumps = events.Skip(1).SkipLast(1).ToList();
            Assert.That(jumps, Has.Count.GreaterThanOrEqualTo(2).And.Count.EqualTo(2 * (jumps.Count / 2)));
            for (int i = 0; i < jumps.Count; i += 2)
            {
                Assert.That(jumps[i].Kind, Is.EqualTo(JumpEventKind.JumpStarted), $"event {i}");
                Assert.That(jumps[i + 1].Kind, Is.EqualTo(JumpEventKind.Landed), $"event {i + 1}");
                Assert.That(jumps[i].Jump, Is.EqualTo(i / 2));
                Assert.That(jumps[i + 1].Time - jumps[i].Time, Is.EqualTo(jumps[i].FlightTime).Within(1e-4), "landing time = takeoff time + flight time");
            }

            Assert.That(events.Zip(events.Skip(1)).All(p => p.First.Time <= p.Second.Time + 1e-9), Is.True, "event times never go back");
            Assert.That(world.GetState(added.Agent), Is.EqualTo(AgentState.Idle));
            Assert.That(world.GetTarget(added.Agent), Is.Null);
        }
    }

    [Test]
    public void OnTheGroundAnAgentCrouchesBeforeItJumpsAndAbsorbsItsLanding()
    {
        // The root on the ground follows the animation's stances: below its stance before the first takeoff (the
        // crouch) and after each landing (absorbing), never above the stance it stands on.
        (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert();
        using (world)
        {
            (AgentHandle agent, RoadmapNode from, _) = RuntimeWorlds.SendAcross(world, kind, seed: 2);
            float lowestBefore = float.PositiveInfinity;
            bool jumped = false;
            float lowestAfterLanding = float.PositiveInfinity;
            float landedAt = float.NaN;
            RuntimeWorlds.Run(world, MaxTicks, RuntimeWorlds.Concluded, w =>
            {
                AgentState state = w.GetState(agent);
                Vector3 root = w.GetRootPose(agent).Position;
                if (w.TryGetCurrentJump(agent, out JumpInfo jump))
                {
                    jumped = true;
                    landedAt = jump.Arc.End.Y;
                }
                else if (state == AgentState.Stance && !jumped)
                {
                    lowestBefore = MathF.Min(lowestBefore, root.Y);
                }
                else if (state == AgentState.Stance)
                {
                    lowestAfterLanding = MathF.Min(lowestAfterLanding, root.Y - landedAt);
                }
            });
            Assert.Multiple(() =>
            {
                Assert.That(jumped, Is.True);
                Assert.That(lowestBefore, Is.LessThan(from.Pose.Position.Y - 0.05f), "a crouch before the first takeoff");
                Assert.That(lowestAfterLanding, Is.LessThan(-0.05f), "a landing absorbed");
            });
        }
    }

    [Test]
    public void InFlightAnAgentIsExactlyOnItsArcAtEveryTick()
    {
        (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert();
        using (world)
        {
            AgentHandle agent = RuntimeWorlds.SendAcross(world, kind, seed: 2).Agent;
            int airborne = 0;
            Vector3 g = new(0f, -9.81f, 0f);
            RuntimeWorlds.Run(world, MaxTicks, RuntimeWorlds.Concluded, w =>
            {
                AgentState state = w.GetState(agent);
                if (state is not (AgentState.Takeoff or AgentState.Flight or AgentState.Landing))
                {
                    return;
                }

                Assert.That(w.TryGetCurrentJump(agent, out JumpInfo jump) && jump.InProgress, Is.True, "a jump in progress is reported");
                float t = (float)(w.Time - jump.TakeoffTime);
                Assert.That(t, Is.InRange(0f, jump.FlightTime + 1e-5f));
                Vector3 position = w.GetRootPose(agent).Position;

                // Exactly the arc's own evaluation, and the parabola of the takeoff velocity under gravity.
                Assert.That(position, Is.EqualTo(jump.Arc.PositionAt(t)));
                Vector3 ballistic = jump.From + (jump.Velocity * t) + (0.5f * t * t * g);
                Assert.That(Vector3.Distance(position, ballistic), Is.LessThan(1e-4f), $"off the parabola at t = {t:0.####} s");
                airborne++;
            });
            Assert.That(airborne, Is.GreaterThan(10), "the agent flew");
        }
    }

    [Test]
    public void WhatComesNextIsKnownBeforeTheTakeoff()
    {
        (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert();
        using (world)
        {
            AgentHandle agent = RuntimeWorlds.SendAcross(world, kind, seed: 3).Agent;
            var announced = new Dictionary<int, JumpInfo>();
            List<JumpEvent> events = RuntimeWorlds.Run(world, MaxTicks, RuntimeWorlds.Concluded, w =>
            {
                if (w.TryGetNextJump(agent, out JumpInfo next))
                {
                    Assert.That(next.InProgress, Is.False);
                    Assert.That(next.TakeoffTime, Is.GreaterThan(w.Time), "announced before it happens");
                    announced.TryAdd(next.Index, next);
                }
            });

            List<JumpEvent> takeoffs = [.. events.Where(e => e.Kind == JumpEventKind.JumpStarted)];
            Assert.That(takeoffs, Is.Not.Empty);
            foreach (JumpEvent takeoff in takeoffs.Skip(1))
            {
                Assert.That(announced.TryGetValue(takeoff.Jump, out JumpInfo before), Is.True, $"jump {takeoff.Jump} was not announced before it took off");
                Assert.That(before.TakeoffTime, Is.EqualTo(takeoff.Time).Within(1e-9));
                Assert.That(before.From, Is.EqualTo(takeoff.From));
                Assert.That(before.To, Is.EqualTo(takeoff.To));
                Assert.That(before.Velocity, Is.EqualTo(takeoff.Velocity));
            }
        }
    }

    [Test]
    public void ExecutedJumpsPassThePhysicsChecksAndChainFromWhereTheAgentStood()
    {
        CharacterKind kind = RuntimeWorlds.DesertSkeleton;
        (JumpWorld world, KindHandle handle) = RuntimeWorlds.Desert();
        using (world)
        {
            List<(RoadmapNode From, RoadmapNode To)> pairs = RuntimeWorlds.ConnectedPairs(kind.Roadmap, 4, seed: 4);
            var agents = pairs.Select(p => world.AddAgent(handle, RuntimeWorlds.Point(p.From)).Agent).ToList();
            var starts = agents.Select(a => world.GetRootPose(a).Position).ToList();
            for (int i = 0; i < agents.Count; i++)
            {
                world.SetTarget(agents[i], RuntimeWorlds.Point(pairs[i].To));
            }

            var paths = new Dictionary<AgentHandle, AgentPath>();
            List<JumpEvent> events = RuntimeWorlds.Run(world, MaxTicks,
                (w, seen) => seen.Count(e => e.Kind is JumpEventKind.TargetReached or JumpEventKind.PathFailed) == agents.Count,
                w =>
                {
                    foreach (JumpEvent e in w.Events)
                    {
                        if (e.Kind == JumpEventKind.PathFound)
                        {
                            paths[e.Agent] = w.GetPath(e.Agent)!;
                        }
                    }
                });

            Assert.That(events.Count(e => e.Kind == JumpEventKind.TargetReached), Is.EqualTo(agents.Count), string.Join("; ", events.Where(e => e.Reason is not null).Select(e => e.Reason)));
            for (int i = 0; i < agents.Count; i++)
            {
                AgentPath path = paths[agents[i]];
                Assert.That(Vector3.Distance(path.Moves[0].Arc.Start, starts[i]), Is.LessThan(1e-5f), $"agent {i}: the path starts where it stood");
                foreach (PathMove move in path.Moves)
                {
                    PhysicsChecks.AssertJump(kind.Scene, move.From, move.To, move.Arc, $"agent {i} jump {move.Index}");
                }

                Assert.That(world.GetRootPose(agents[i]).Position, Is.EqualTo(path.Goal.Pose.Position), $"agent {i} stands on its goal");
            }
        }
    }
}
