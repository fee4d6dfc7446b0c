using System.Numerics;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Runtime;
using Ballistic.Runtime.Core;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Kinds;
using Ballistic.Runtime.Hosting;
using Ballistic.Runtime.Paths;

namespace Ballistic.Planner.Tests.Hosting;

/// <summary>The agent node's logic without a scene: targets, finished and reachable, the path as points, the next jump, signals in order, the body point.</summary>
public sealed class JumpAgentLogicTests
{
    private const int MaxTicks = 60 * 60;
    private static readonly Vector3 Gravity = new(0f, -9.81f, 0f);

    /// <summary>An agent registered on the desert host and sent across a trip of two jumps (seed 41), before any tick.</summary>
    private static (JumpWorld Host, JumpAgentLogic Logic, RoadmapNode From, RoadmapNode To) SentOnATwoJumpTrip()
    {
        (RoadmapNode from, RoadmapNode to) = HostingWorlds.PairsWithJumps(2, 1, seed: 41).Single();
        (JumpWorld host, KindHandle region) = HostingWorlds.DesertServer();
        var logic = new JumpAgentLogic(host);
        Assert.That(logic.Register(region, RuntimeWorlds.Point(from)).Ok, Is.True);
        logic.TargetPosition = RuntimeWorlds.Point(to);
        return (host, logic, from, to);
    }

    [Test]
    public void ATwoJumpTripRaisesTheSignalsInOrderAndTheBodyFliesTheAnnouncedParabolas()
    {
        (JumpWorld host, JumpAgentLogic logic, RoadmapNode from, RoadmapNode to) = SentOnATwoJumpTrip();
        using (host)
        {
            int airborne = 0;
            List<AgentSignal> signals = HostingWorlds.Run(logic, MaxTicks, HostingWorlds.Finished, () =>
            {
                if (logic.TryGetCurrentJump(out JumpInfo jump))
                {
                    // The body point is on the parabola of the takeoff signal: From + V·t + ½·g·t².
                    float t = (float)(host.Time - jump.TakeoffTime);
                    Vector3 parabola = jump.TakeoffPoint + (jump.BodyVelocity * t) + (0.5f * t * t * Gravity);
                    Assert.That(Vector3.Distance(logic.BodyPosition, parabola), Is.LessThan(1e-3f), $"body off its parabola at t = {t:0.###} s");
                    Assert.That(Vector3.Distance(logic.BodyVelocity, jump.BodyVelocity + (t * Gravity)), Is.LessThan(1e-3f));
                    Assert.That(logic.RootPose.Position, Is.EqualTo(jump.Arc.PositionAt(t)), "the root pose is the runtime's, exactly on the arc");
                    airborne++;
                }
            });

            // The searched trip has two jumps; the path flown may differ (jumps turned to face their way, a hop to turn,
            // or another route once a move the body could not perform was set aside): one or more jumps, each landed.
            int jumps = signals.Count(s => s.Kind == AgentSignalKind.JumpStarted);
            Assert.That(jumps, Is.GreaterThanOrEqualTo(1));
            Assert.That(signals.Select(s => s.Kind), Is.EqualTo(new[] { AgentSignalKind.PathChanged }
                .Concat(Enumerable.Repeat(new[] { AgentSignalKind.JumpStarted, AgentSignalKind.Landed }, jumps).SelectMany(x => x))
                .Concat([AgentSignalKind.TargetReached, AgentSignalKind.NavigationFinished])), string.Join("; ", signals));
            Assert.That(signals.Zip(signals.Skip(1)).All(p => p.First.Time <= p.Second.Time + 1e-9), Is.True, "signal times never go back");
            Assert.That(airborne, Is.GreaterThan(10));

            var takeoffs = signals.Where(s => s.Kind == AgentSignalKind.JumpStarted).ToList();
            var landings = signals.Where(s => s.Kind == AgentSignalKind.Landed).ToList();
            Assert.That(Vector3.Distance(takeoffs[0].From, RuntimeWorlds.Point(from)), Is.LessThan(1e-4f), "the first takeoff is where the agent stood");
            for (int i = 1; i < jumps; i++)
            {
                Assert.That(Vector3.Distance(takeoffs[i].From, landings[i - 1].To), Is.LessThan(1e-4f), $"takeoff {i + 1} is where jump {i} landed");
            }

            Assert.That(Vector3.Distance(landings[^1].To, RuntimeWorlds.Point(to)), Is.LessThan(1e-4f), "the last landing is the target node");
            for (int i = 0; i < jumps; i++)
            {
                AgentSignal s = takeoffs[i];
                Vector3 end = s.From + (s.Velocity * s.Duration) + (0.5f * s.Duration * s.Duration * Gravity);
                Assert.That(Vector3.Distance(end, s.To), Is.LessThan(1e-2f), $"jump {i}: the body's parabola lands on the landing point");
                Assert.That(landings[i].Time - s.Time, Is.EqualTo(s.Duration).Within(1e-4));
                Assert.That((s.Move, landings[i].Move, landings[i].From, landings[i].Duration), Is.EqualTo((i, i, s.From, s.Duration)), $"jump {i}: its landing names the same move");
            }

            Assert.That(logic.IsNavigationFinished(), Is.True);
            Assert.That(logic.IsTargetReached(), Is.True);
            Assert.That(Vector3.Distance(logic.BodyPosition, RuntimeWorlds.Point(to)), Is.LessThan(1e-4f));
            Assert.That(logic.BodyVelocity, Is.EqualTo(Vector3.Zero));
        }
    }

    [Test]
    public void TheStateTextFollowsATripFromPlanningThroughFlightToArrival()
    {
        (RoadmapNode from, RoadmapNode to) = HostingWorlds.PairsWithJumps(2, 1, seed: 41).Single();
        (JumpWorld host, KindHandle region) = HostingWorlds.DesertServer();
        using (host)
        {
            var logic = new JumpAgentLogic(host);
            Assert.That(logic.DescribeState(), Is.EqualTo("not registered"));
            logic.Register(region, RuntimeWorlds.Point(from));
            Assert.That(logic.DescribeState(), Is.EqualTo("idle"));
            logic.TargetPosition = RuntimeWorlds.Point(to);
            var seen = new List<string>();
            HostingWorlds.Run(logic, MaxTicks, HostingWorlds.Finished, () =>
            {
                string state = logic.DescribeState();
                if (seen.Count == 0 || seen[^1] != state)
                {
                    seen.Add(state);
                }

                if (logic.CurrentPath is { } path)
                {
                    Assert.That(logic.CurrentMove, Is.InRange(0, path.Moves.Count - 1));
                }
            });

            Assert.That(seen, Does.Contain("flight"), string.Join(" → ", seen));
            Assert.That(seen.IndexOf("flight"), Is.GreaterThan(0), "something (planning, stance, takeoff) comes before the flight");
            Assert.That(logic.DescribeState(), Is.EqualTo("arrived"));

            logic.TargetPosition = new Vector3(500f, 0f, 500f); // off the level
            HostingWorlds.Run(logic, MaxTicks, HostingWorlds.Finished, () => { });
            Assert.That(logic.DescribeState(), Does.StartWith("failed: "), "a failed target says why");
        }
    }

    [Test]
    public void TheCurrentPathStartsWhereTheAgentStandsEndsAtTheTargetAndIsSampledFinely()
    {
        (RoadmapNode from, RoadmapNode to) = RuntimeWorlds.ConnectedPairs(HostingWorlds.Desert.Roadmap, 1, seed: 42, minDistance: 6f)[0];
        (JumpWorld host, KindHandle region) = HostingWorlds.DesertServer();
        using (host)
        {
            var logic = new JumpAgentLogic(host);
            logic.Register(region, RuntimeWorlds.Point(from));
            logic.TargetPosition = RuntimeWorlds.Point(to);
            Assert.That(logic.GetCurrentPath(), Is.Empty, "no path before it is found");
            Vector3 standing = logic.BodyPosition;
            HostingWorlds.Run(logic, MaxTicks, seen => seen.Count > 0);
            Assert.That(logic.BodyPosition, Is.EqualTo(standing), "still standing when the path arrives");

            foreach (float step in new[] { 0.25f, 0.1f })
            {
                logic.PathSampleStep = step;
                var path = logic.GetCurrentPath().ToList();
                Assert.That(Vector3.Distance(path[0], standing), Is.LessThan(1e-5f), "the path starts where the agent stands");
                Assert.That(HostingWorlds.WithinTolerance(path[^1], logic.TargetPosition), Is.True, $"the path ends at {path[^1]}, off the target {logic.TargetPosition}");
                for (int i = 1; i < path.Count; i++)
                {
                    Assert.That(Vector3.Distance(path[i - 1], path[i]), Is.LessThanOrEqualTo(step + 1e-5f), $"points {i - 1} and {i} of {path.Count}");
                }

                var moves = host.GetPath(logic.Agent)!.Moves;
                foreach (var move in moves)
                {
                    Assert.That(path, Does.Contain(move.From.ContactCentre), $"takeoff of jump {move.Index}");
                    Assert.That(path, Does.Contain(move.To.ContactCentre), $"landing of jump {move.Index}");
                }

                float length = path.Zip(path.Skip(1)).Sum(p => Vector3.Distance(p.First, p.Second));
                Assert.That(path.Count, Is.GreaterThanOrEqualTo((int)(length / step)), "no coarser than the step");
            }

            Assert.Throws<ArgumentOutOfRangeException>(() => logic.PathSampleStep = 0f);
            Assert.Throws<ArgumentOutOfRangeException>(() => logic.TargetDesiredDistance = float.NaN);
        }
    }

    /// <summary>
    /// Once the path is delivered, the ticks of a trip allocate nothing, those that raise signals (takeoffs, landings,
    /// the arrival) included: a signal is a struct in a reused list (before: one record allocated per signal).
    /// </summary>
    [Test]
    public void RaisingSignalsAllocatesNothing()
    {
        (JumpWorld host, JumpAgentLogic logic, RoadmapNode from, RoadmapNode to) = SentOnATwoJumpTrip();
        using (host)
        {
            HostingWorlds.Run(logic, MaxTicks, seen => seen.Any(s => s.Kind == AgentSignalKind.PathChanged));
            Assume.That(logic.CurrentPath, Is.Not.Null);
            var kinds = new AgentSignalKind[16];
            int raised = 0;
            long allocated = 0;
            for (int tick = 0; tick < MaxTicks && !logic.IsNavigationFinished(); tick++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                host.Step();
                IReadOnlyList<AgentSignal> signals = logic.Update();
                for (int i = 0; i < signals.Count && raised < kinds.Length; i++)
                {
                    kinds[raised++] = signals[i].Kind;
                }

                allocated += GC.GetAllocatedBytesForCurrentThread() - before;
            }

            Assert.That(kinds.Take(raised), Does.Contain(AgentSignalKind.JumpStarted).And.Contain(AgentSignalKind.Landed).And.Contain(AgentSignalKind.NavigationFinished), "the trip raised its signals");
            Assert.That(allocated, Is.Zero, "bytes allocated by the ticks of the trip");
        }
    }

    [Test]
    public void TheNextJumpIsKnownBeforeItsTakeoffAndMatchesItsSignal()
    {
        (RoadmapNode from, RoadmapNode to) = HostingWorlds.PairsWithJumps(2, 1, seed: 43).Single();
        (JumpWorld host, KindHandle region) = HostingWorlds.DesertServer();
        using (host)
        {
            var logic = new JumpAgentLogic(host, AgentMotionMode.ReportOnly);
            logic.Register(region, RuntimeWorlds.Point(from));
            Assert.That(logic.TryGetNextJump(out _), Is.False, "no path, no jump");
            logic.TargetPosition = RuntimeWorlds.Point(to);
            var announced = new Dictionary<int, JumpInfo>();
            List<AgentSignal> signals = HostingWorlds.Run(logic, MaxTicks, HostingWorlds.Finished, () =>
            {
                if (logic.TryGetNextJump(out JumpInfo next))
                {
                    Assert.That(next.InProgress, Is.False);
                    Assert.That(next.TakeoffTime, Is.GreaterThan(host.Time));
                    Assert.That(next.LandingTime - next.TakeoffTime, Is.EqualTo(next.FlightTime).Within(1e-4));
                    announced.TryAdd(next.Index, next);
                }
            });

            var takeoffs = signals.Where(s => s.Kind == AgentSignalKind.JumpStarted).ToList();
            Assert.That(takeoffs, Has.Count.EqualTo(2));
            Assert.That(announced.Keys, Is.SupersetOf(new[] { 1 }), "the second jump was announced while standing before it");
            JumpInfo second = announced[1];
            Assert.That(second.TakeoffPoint, Is.EqualTo(takeoffs[1].From));
            Assert.That(second.LandingPoint, Is.EqualTo(takeoffs[1].To));
            Assert.That(second.BodyVelocity, Is.EqualTo(takeoffs[1].Velocity));
            Assert.That(second.FlightTime, Is.EqualTo(takeoffs[1].Duration));
            Assert.That(second.TakeoffTime, Is.EqualTo(takeoffs[1].Time).Within(1e-9));
        }
    }

    [Test]
    public void TargetsWithinTheThresholdAreIgnoredAndFartherOnesReplan()
    {
        Roadmap roadmap = HostingWorlds.Desert.Roadmap;
        List<(RoadmapNode From, RoadmapNode To)> pairs = RuntimeWorlds.ConnectedPairs(roadmap, 2, seed: 44, minDistance: 6f);
        (JumpWorld host, KindHandle region) = HostingWorlds.DesertServer();
        using (host)
        {
            var logic = new JumpAgentLogic(host);
            logic.Register(region, RuntimeWorlds.Point(pairs[0].From));
            Vector3 first = RuntimeWorlds.Point(pairs[0].To);
            logic.TargetPosition = first;
            Assert.That(host.QueuedRequests, Is.EqualTo(1));
            Assert.That(logic.IsNavigationFinished(), Is.False);

            // A nudge within the threshold: nothing changes, no request.
            RuntimeResult nudged = logic.SetTarget(first + new Vector3(0.05f, 0f, 0f));
            Assert.That(nudged.Reason, Does.Contain("kept"));
            Assert.That(logic.TargetPosition, Is.EqualTo(first));
            Assert.That(host.QueuedRequests, Is.EqualTo(1));
            HostingWorlds.Run(logic, MaxTicks, seen => seen.Any(s => s.Kind == AgentSignalKind.JumpStarted));
            logic.TargetPosition = first + new Vector3(0f, 0f, 0.08f);
            Assert.That(logic.TargetPosition, Is.EqualTo(first), "in flight too");
            Assert.That(host.IsPathPending(logic.Agent), Is.False);

            // Far away (beyond the runtime's replan distance): the agent lands, replans and goes there.
            Vector3 second = RuntimeWorlds.Point(pairs[1].To);
            Assume.That(Vector3.Distance(first, second), Is.GreaterThan(host.Settings.ReplanDistance));
            logic.TargetPosition = second;
            Assert.That(logic.TargetPosition, Is.EqualTo(second));
            List<AgentSignal> signals = HostingWorlds.Run(logic, MaxTicks, HostingWorlds.Finished);
            Assert.That(signals.Count(s => s.Kind == AgentSignalKind.PathChanged), Is.EqualTo(1), "one new path: " + string.Join("; ", signals));
            Assert.That(signals[^2], Has.Property(nameof(AgentSignal.Kind)).EqualTo(AgentSignalKind.TargetReached), string.Join("; ", signals));
            Assert.That(HostingWorlds.WithinTolerance(logic.BodyPosition, second), Is.True);
        }
    }

    [Test]
    public void FinishedAndReachableOnAReachableTarget()
    {
        (RoadmapNode from, RoadmapNode to) = HostingWorlds.PairsWithJumps(3, 1, seed: 45).Single();
        (JumpWorld host, KindHandle region) = HostingWorlds.DesertServer();
        using (host)
        {
            var logic = new JumpAgentLogic(host);
            logic.Register(region, RuntimeWorlds.Point(from));
            Assert.That(logic.IsNavigationFinished(), Is.True, "no target: finished, as in Godot");
            Assert.That(logic.IsTargetReachable(), Is.False, "no target");

            logic.TargetPosition = RuntimeWorlds.Point(to);
            Assert.That(logic.IsNavigationFinished(), Is.False);
            Assert.That(logic.IsTargetReachable(), Is.True, "the roadmap connects the stance to the target node");
            HostingWorlds.Run(logic, MaxTicks, seen => seen.Any(s => s.Kind == AgentSignalKind.Landed));
            Assert.That(logic.IsNavigationFinished(), Is.False, "under way");
            Assert.That(logic.IsTargetReachable(), Is.True, "from the stance it landed on, too");
            List<AgentSignal> signals = HostingWorlds.Run(logic, MaxTicks, HostingWorlds.Finished);
            Assert.That(signals.Where(s => s.Kind == AgentSignalKind.PathFailed), Is.Empty);
            Assert.That(logic.IsNavigationFinished(), Is.True);
            Assert.That(logic.IsTargetReached(), Is.True);
            Assert.That(logic.IsTargetReachable(), Is.True);
        }
    }

    [Test]
    public void AnUnreachableTargetIsSaidSoBeforeAndAfterThePathFails()
    {
        Roadmap roadmap = HostingWorlds.Desert.Roadmap;
        var random = new Random(46);
        (RoadmapNode From, RoadmapNode To)? pair = null;
        for (int attempt = 0; attempt < 20_000 && pair is null; attempt++)
        {
            RoadmapNode a = roadmap.Nodes[random.Next(roadmap.Nodes.Count)];
            RoadmapNode b = roadmap.Nodes[random.Next(roadmap.Nodes.Count)];
            if (!roadmap.Reaches(a.Id, b.Id) && roadmap.FindNode(RuntimeWorlds.Point(a), HostingWorlds.Tolerance) == a.Id && roadmap.FindNode(RuntimeWorlds.Point(b), HostingWorlds.Tolerance) == b.Id)
            {
                pair = (a, b);
            }
        }

        Assume.That(pair, Is.Not.Null, "the roadmap is strongly connected: no unreachable node");
        (JumpWorld host, KindHandle region) = HostingWorlds.DesertServer();
        using (host)
        {
            var logic = new JumpAgentLogic(host);
            logic.Register(region, RuntimeWorlds.Point(pair!.Value.From));
            logic.TargetPosition = RuntimeWorlds.Point(pair.Value.To);
            Assert.That(logic.IsTargetReachable(), Is.False, "the roadmap holds no sequence of jumps there");
            Assert.That(logic.IsNavigationFinished(), Is.False, "until the planner says so");

            List<AgentSignal> signals = HostingWorlds.Run(logic, MaxTicks, HostingWorlds.Finished);
            Assert.That(signals.Select(s => s.Kind), Is.EqualTo(new[] { AgentSignalKind.PathFailed, AgentSignalKind.NavigationFinished }));
            Assert.That(signals[0].Reason, Does.Contain("no sequence of jumps"));
            Assert.That(logic.LastFailure, Is.EqualTo(signals[0].Reason));
            Assert.That(logic.IsNavigationFinished(), Is.True);
            Assert.That(logic.IsTargetReachable(), Is.False);
            Assert.That(logic.IsTargetReached(), Is.False);
            Assert.That(logic.GetCurrentPath(), Is.Empty);
        }
    }

    [Test]
    public void ATargetWithinTheDesiredDistanceIsReachedAtOnce()
    {
        (JumpWorld host, KindHandle region) = HostingWorlds.DesertServer();
        using (host)
        {
            Vector3 here = RuntimeWorlds.Point(HostingWorlds.Desert.Roadmap.Nodes[3]);
            var logic = new JumpAgentLogic(host) { TargetDesiredDistance = 0.4f };
            logic.Register(region, here);
            logic.TargetPosition = here + new Vector3(0.3f, 0f, 0f);
            Assert.That(host.QueuedRequests, Is.Zero, "no path asked for");
            Assert.That(logic.IsNavigationFinished(), Is.True);
            Assert.That(logic.IsTargetReached(), Is.True);
            host.Step();
            Assert.That(logic.Update().Select(s => s.Kind), Is.EqualTo(new[] { AgentSignalKind.TargetReached, AgentSignalKind.NavigationFinished }));
            Assert.That(logic.Update(), Is.Empty, "once");

            logic.SetTarget(new Vector3(float.NaN, 0f, 0f));
            Assert.That(logic.Update().Single(), Has.Property(nameof(AgentSignal.Kind)).EqualTo(AgentSignalKind.PathFailed));
        }
    }

    [Test]
    public void AnAgentWaitingForItsRegionGetsItsTargetWhenTheRoadmapComes()
    {
        (RoadmapNode from, RoadmapNode to) = RuntimeWorlds.ConnectedPairs(HostingWorlds.Desert.Roadmap, 1, seed: 47)[0];
        using JumpWorld host = HostingWorlds.Server();
        KindHandle region = host.CreateKind("desert");
        var logic = new JumpAgentLogic(host);
        logic.TargetPosition = RuntimeWorlds.Point(to); // before registering, even
        Assert.That(logic.Register(region, RuntimeWorlds.Point(from)).Ok, Is.True);
        Assert.That(logic.Lifecycle, Is.EqualTo(AgentLifecycle.Waiting));
        Assert.That(logic.StateReason, Does.Contain("waiting"));
        Assert.That(logic.BodyPosition, Is.EqualTo(RuntimeWorlds.Point(from)));
        Assert.That(logic.IsTargetReachable(), Is.False, "not on a roadmap yet");
        host.Step();
        Assert.That(logic.Update(), Is.Empty);

        host.ReplaceKind(region, HostingWorlds.Desert);
        List<AgentSignal> signals = HostingWorlds.Run(logic, MaxTicks, HostingWorlds.Finished);
        Assert.That(signals[0], Has.Property(nameof(AgentSignal.Kind)).EqualTo(AgentSignalKind.PathChanged));
        Assert.That(signals[^2], Has.Property(nameof(AgentSignal.Kind)).EqualTo(AgentSignalKind.TargetReached), string.Join("; ", signals));
        Assert.That(Vector3.Distance(logic.BodyPosition, RuntimeWorlds.Point(to)), Is.LessThan(1e-4f));

        // The kind is removed while the agent heads somewhere: at the next tick the path fails with the world's reason.
        logic.TargetPosition = RuntimeWorlds.Point(from);
        host.RemoveKind(region);
        Assert.That(logic.Update(), Is.Empty, "no tick since: the last tick's events are not read twice");
        host.Step();
        signals = [.. logic.Update()];
        Assert.That(signals.Select(s => s.Kind), Is.EqualTo(new[] { AgentSignalKind.PathFailed, AgentSignalKind.NavigationFinished }));
        Assert.That(signals[0].Reason, Does.Contain("kind 'desert' was removed"));
        Assert.That(logic.Lifecycle, Is.EqualTo(AgentLifecycle.Detached));
        Assert.That(logic.Unregister().Ok, Is.True);
        Assert.That(logic.IsRegistered, Is.False);
    }

    [Test]
    public void ARebakeUnderWayLetsTheAgentFinishItsJumpAndCarryOnFromItsLanding()
    {
        (RoadmapNode from, RoadmapNode to) = RuntimeWorlds.ConnectedPairs(HostingWorlds.Desert.Roadmap, 1, seed: 48, minDistance: 6f)[0];
        (JumpWorld host, KindHandle region) = HostingWorlds.DesertServer();
        using (host)
        {
            var logic = new JumpAgentLogic(host);
            logic.Register(region, RuntimeWorlds.Point(from));
            logic.TargetPosition = RuntimeWorlds.Point(to);
            HostingWorlds.Run(logic, MaxTicks, seen => seen.Any(s => s.Kind == AgentSignalKind.JumpStarted));
            Vector3[] oldPath = [.. logic.GetCurrentPath()];
            Assert.That(oldPath, Is.Not.Empty);
            Vector3 before = logic.BodyPosition;

            Assert.That(host.ReplaceKind(region, HostingWorlds.DesertRebaked).Ok, Is.True);
            host.Step();
            Assert.That(logic.Update().Where(s => s.Kind == AgentSignalKind.PathFailed), Is.Empty, "a rebake is no failure");
            Assert.That(logic.GetCurrentPath(), Is.EqualTo(oldPath), "the jump under way is finished on the path it was planned on");
            Assert.That(Vector3.Distance(logic.BodyPosition, before), Is.LessThan(0.5f), "the body is not moved by the rebake (one tick of flight)");
            Assert.That(logic.IsNavigationFinished(), Is.False, "still heading for the target");

            Vector3? put = null;
            List<AgentSignal> signals = HostingWorlds.Run(logic, MaxTicks, seen =>
            {
                if (put is null && seen.Count > 0 && seen[^1] is { Kind: AgentSignalKind.PathChanged })
                {
                    put = logic.BodyPosition;
                }

                return HostingWorlds.Finished(seen);
            });
            Assert.That(signals.Where(s => s.Kind == AgentSignalKind.Landed), Is.Not.Empty, string.Join("; ", signals));
            Assert.That(signals.Where(s => s.Kind == AgentSignalKind.PathChanged), Is.Not.Empty, string.Join("; ", signals));
            Assert.That(signals[^2], Has.Property(nameof(AgentSignal.Kind)).EqualTo(AgentSignalKind.TargetReached), string.Join("; ", signals));
            Assert.That(put, Is.Not.Null);
            Assert.That(oldPath.Min(p => Vector3.Distance(p, put!.Value)), Is.LessThan(1e-4f), "the new path starts on a stance of the old one: where the jump landed");
            Assert.That(HostingWorlds.WithinTolerance(logic.BodyPosition, RuntimeWorlds.Point(to)), Is.True);
        }
    }

    [Test]
    public void AReportingAgentFollowsTheBodyTheUserWalksAndNotIntoTheSky()
    {
        Roadmap roadmap = HostingWorlds.Desert.Roadmap;
        RoadmapNode a = roadmap.Nodes[0];
        RoadmapNode b = roadmap.Nodes.First(n => Vector3.Distance(RuntimeWorlds.Point(n), RuntimeWorlds.Point(a)) > 2f && roadmap.FindNode(RuntimeWorlds.Point(n), HostingWorlds.Tolerance) == n.Id);
        (JumpWorld host, KindHandle region) = HostingWorlds.DesertServer();
        using (host)
        {
            var logic = new JumpAgentLogic(host, AgentMotionMode.ReportOnly);
            logic.Register(region, RuntimeWorlds.Point(a));
            Assert.That(logic.SyncBodyPosition(RuntimeWorlds.Point(a) + new Vector3(0.1f, 0f, 0f)).Ok, Is.True);
            Assert.That(Vector3.Distance(host.GetStandingPoint(logic.Agent)!.Value, RuntimeWorlds.Point(a)), Is.LessThan(1e-4f), "a small drift is ignored");

            Assert.That(logic.SyncBodyPosition(RuntimeWorlds.Point(b)).Ok, Is.True);
            Assert.That(Vector3.Distance(host.GetStandingPoint(logic.Agent)!.Value, RuntimeWorlds.Point(b)), Is.LessThan(1e-4f), "the agent stands where the user walked the body");
            logic.Update();
            Assert.That(Vector3.Distance(logic.BodyPosition, RuntimeWorlds.Point(b)), Is.LessThan(1e-4f));

            Vector3 sky = RuntimeWorlds.Point(b) + new Vector3(0f, 50f, 0f);
            Assert.That(logic.SyncBodyPosition(sky).Status, Is.EqualTo(RuntimeStatus.InvalidPosition));
            Assert.That(logic.SyncBodyPosition(sky + new Vector3(0.1f, 0f, 0f)).Ok, Is.True, "not tried again near a refused place");
            Assert.That(Vector3.Distance(host.GetStandingPoint(logic.Agent)!.Value, RuntimeWorlds.Point(b)), Is.LessThan(1e-4f), "a refused warp leaves the agent where it was");
        }
    }
}
