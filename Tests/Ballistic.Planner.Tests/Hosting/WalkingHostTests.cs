using System.Numerics;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Runtime;
using Ballistic.Runtime;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Kinds;
using Ballistic.Runtime.Hosting;

namespace Ballistic.Planner.Tests.Hosting;

/// <summary>
/// An agent node's logic on a path with walks (hand-made walk → jump → walk, animated by a test double): the walk
/// signals in order with their payloads, the body point walking the ground path at the walking speed in both motion
/// modes, the state text, the current path's points along the walks.
/// </summary>
public sealed class WalkingHostTests
{
    private const int MaxTicks = 60 * 30;

    /// <summary>A host with one desert region whose kind animates walks, and a registered agent performing <see cref="WalkingPaths.WalkJumpWalk"/>.</summary>
    private static (JumpWorld Host, JumpAgentLogic Logic, IReadOnlyList<Move> Moves) Performing(AgentMotionMode mode)
    {
        JumpWorld host = HostingWorlds.Server();
        KindHandle region = host.CreateKind("desert walking");
        Assert.That(host.ReplaceKind(region, WalkingPaths.Kind).Ok, Is.True);
        IReadOnlyList<Move> moves = WalkingPaths.WalkJumpWalk();
        var logic = new JumpAgentLogic(host, mode);
        Assert.That(logic.Register(region, WalkingPaths.Centre(moves[0].To)).Ok, Is.True);
        RuntimeResult performed = logic.PerformMoves(moves);
        Assert.That(performed.Ok, Is.True, performed.ToString());
        Assert.That(logic.TargetPosition, Is.EqualTo(WalkingPaths.Centre(moves[2].To)), "the last stance's contact centre is the target");
        return (host, logic, moves);
    }

    [TestCase(AgentMotionMode.MoveParent)]
    [TestCase(AgentMotionMode.ReportOnly)]
    public void TheSignalsOfAWalkJumpWalkTripComeInOrderWithTheirPayloads(AgentMotionMode mode)
    {
        (JumpWorld host, JumpAgentLogic logic, IReadOnlyList<Move> moves) = Performing(mode);
        using (host)
        {
            List<AgentSignal> signals = HostingWorlds.Run(logic, MaxTicks, HostingWorlds.Finished);
            Assert.That(signals.Select(s => s.Kind), Is.EqualTo(new[]
            {
                AgentSignalKind.PathChanged, AgentSignalKind.WalkStarted, AgentSignalKind.WalkFinished, AgentSignalKind.JumpStarted, AgentSignalKind.Landed,
                AgentSignalKind.WalkStarted, AgentSignalKind.WalkFinished, AgentSignalKind.TargetReached, AgentSignalKind.NavigationFinished,
            }), string.Join("; ", signals));
            Assert.That(signals.Zip(signals.Skip(1)).All(p => p.First.Time <= p.Second.Time + 1e-9), Is.True, "signal times never go back");

            var starts = signals.Where(s => s.Kind == AgentSignalKind.WalkStarted).ToList();
            var ends = signals.Where(s => s.Kind == AgentSignalKind.WalkFinished).ToList();
            var walks = new[] { (Walk)moves[0], (Walk)moves[2] };
            for (int w = 0; w < 2; w++)
            {
                Assert.That(starts[w].Move, Is.EqualTo(2 * w));
                Assert.That(ends[w].Move, Is.EqualTo(2 * w));
                Assert.That(starts[w].From, Is.EqualTo(WalkingPaths.Centre(walks[w].From)).Using<Vector3>(Near), "a walk starts at its first stance's contact centre");
                Assert.That(starts[w].To, Is.EqualTo(WalkingPaths.Centre(walks[w].To)).Using<Vector3>(Near));
                Assert.That(ends[w].To, Is.EqualTo(starts[w].To), "it finishes where it said it would");
                Assert.That(starts[w].Duration, Is.EqualTo(walks[w].Duration).Within(1e-5f));
                Assert.That(starts[w].Speed, Is.EqualTo(walks[w].Speed));
                Assert.That(ends[w].Time - starts[w].Time, Is.EqualTo(starts[w].Duration).Within(1e-4));
            }

            AgentSignal takeoff = signals.Where(s => s.Kind == AgentSignalKind.JumpStarted).Single();
            Assert.That(takeoff.From, Is.EqualTo(ends[0].To), "the jump takes off where the first walk ended");
            Assert.That(starts[1].From, Is.EqualTo(signals.Where(s => s.Kind == AgentSignalKind.Landed).Single().To), "the last walk starts where the jump landed");
            Assert.That(logic.IsTargetReached(), Is.True);
            Assert.That(logic.BodyPosition, Is.EqualTo(WalkingPaths.Centre(moves[2].To)).Using<Vector3>(Near));
            Assert.That(logic.BodyVelocity, Is.EqualTo(Vector3.Zero));
        }
    }

    [TestCase(AgentMotionMode.MoveParent)]
    [TestCase(AgentMotionMode.ReportOnly)]
    public void TheBodyWalksTheGroundPathAtTheWalkingSpeed(AgentMotionMode mode)
    {
        (JumpWorld host, JumpAgentLogic logic, IReadOnlyList<Move> moves) = Performing(mode);
        using (host)
        {
            float dt = (float)host.Settings.TickSeconds;
            int walking = 0;
            Vector3? previous = null;
            var states = new List<string>();
            HostingWorlds.Run(logic, MaxTicks, HostingWorlds.Finished, () =>
            {
                JumpWorld world = host;
                string state = logic.DescribeState();
                if (states.Count == 0 || states[^1] != state)
                {
                    states.Add(state);
                }

                if (!world.TryGetCurrentWalk(logic.Agent, out Ballistic.Runtime.Paths.WalkInfo info))
                {
                    previous = null;
                    return;
                }

                // The ground path's point at the distance walked (the path runs between the contact centres).
                Walk walk = info.Walk;
                float t = (float)(world.Time - info.StartTime);
                Assert.That(Vector3.Distance(logic.BodyPosition, walk.PointAt(walk.DistanceAt(t))), Is.LessThan(1e-4f), $"body off the ground path at t = {t:0.###} s");
                Assert.That(WalkingPaths.DistanceToPolyline(logic.BodyPosition, walk.Path), Is.LessThan(1e-4f));
                Assert.That(logic.BodyVelocity.Length(), Is.LessThanOrEqualTo(walk.Speed + 1e-3f), "never faster than the walking speed");
                Assert.That(state, Is.EqualTo("walking"));
                Assert.That(logic.CurrentMove, Is.EqualTo(info.Index));
                Assert.That(logic.RootPose, Is.EqualTo(walk.PoseAt(t)), "the trunk is the runtime's, on the walk");
                if (previous is { } p)
                {
                    Assert.That(Vector3.Distance(p, logic.BodyPosition) / dt, Is.LessThanOrEqualTo(walk.Speed + 1e-3f));
                    Assert.That(logic.BodyVelocity.Length(), Is.GreaterThanOrEqualTo((0.5f * walk.SpeedAt(t)) - 1e-3f), "walking at the walk's speed then (ramping up and down), along the ground path");
                }

                if (mode == AgentMotionMode.ReportOnly)
                {
                    // The user's body lags a little: no warp while a path is under way.
                    Assert.That(logic.SyncBodyPosition(logic.BodyPosition + new Vector3(0.7f, 0f, 0f)).Ok, Is.True);
                }

                previous = logic.BodyPosition;
                walking++;
            });

            Assert.That(walking, Is.GreaterThan(100), "ticks walking");
            Assert.That(states, Is.SupersetOf(new[] { "walking", "flight", "stance", "arrived" }), string.Join(" → ", states));
            Assert.That(states.IndexOf("walking"), Is.LessThan(states.IndexOf("flight")), string.Join(" → ", states));
            Assert.That(logic.BodyPosition, Is.EqualTo(WalkingPaths.Centre(moves[2].To)).Using<Vector3>(Near), "no warp moved it off its path");
        }
    }

    [Test]
    public void TheCurrentPathFollowsTheWalksAndTheArcFinely()
    {
        (JumpWorld host, JumpAgentLogic logic, IReadOnlyList<Move> moves) = Performing(AgentMotionMode.MoveParent);
        using (host)
        {
            HostingWorlds.Run(logic, MaxTicks, seen => seen.Any(s => s.Kind == AgentSignalKind.PathChanged));
            var first = (Walk)moves[0];
            var last = (Walk)moves[2];
            foreach (float step in new[] { 0.25f, 0.1f })
            {
                logic.PathSampleStep = step;
                var points = logic.GetCurrentPath().ToList();
                Assert.That(points[0], Is.EqualTo(WalkingPaths.Centre(moves[0].From)).Using<Vector3>(Near), "starts where the first walk starts");
                Assert.That(points[^1], Is.EqualTo(WalkingPaths.Centre(moves[2].To)).Using<Vector3>(Near), "ends where the last walk ends");
                for (int i = 1; i < points.Count; i++)
                {
                    Assert.That(Vector3.Distance(points[i - 1], points[i]), Is.LessThanOrEqualTo(step + 1e-5f), $"points {i - 1} and {i} of {points.Count}");
                }

                // Every stance's contact centre is a point; the points before the takeoff lie on the first walk's ground
                // path, those after the landing on the last walk's (its corner included).
                int takeoff = points.FindIndex(p => Vector3.Distance(p, WalkingPaths.Centre(moves[1].From)) < 1e-5f);
                int landing = points.FindIndex(p => Vector3.Distance(p, WalkingPaths.Centre(moves[1].To)) < 1e-5f);
                Assert.That(takeoff, Is.GreaterThan(0));
                Assert.That(landing, Is.GreaterThan(takeoff + 1), "the arc lies between");
                Assert.That(takeoff, Is.GreaterThanOrEqualTo((int)(first.Length / step)), "the first walk is sampled finely");
                Assert.That(points.Take(takeoff + 1).All(p => WalkingPaths.DistanceToPolyline(p, first.Path) < 1e-4f), Is.True, "on the first walk");
                Assert.That(points.Skip(landing).All(p => WalkingPaths.DistanceToPolyline(p, last.Path) < 1e-4f), Is.True, "on the last walk");
                Assert.That(points.Skip(landing).Min(p => Vector3.Distance(p, last.Path[1])), Is.LessThanOrEqualTo(step / 2f + 1e-4f), "the corner is followed");
            }
        }
    }

    private static bool Near(Vector3 a, Vector3 b) => Vector3.Distance(a, b) < 1e-5f;

    [Test]
    public void ATargetOnlyWalksReachCountsAsReachableUnlessTheWorldJumpsOnly()
    {
        // The desert roadmap's nodes and walks without its jumps: its nodes are joined by walks alone.
        Roadmap desert = HostingWorlds.Desert.Roadmap;
        Assume.That(desert.Walks, Is.Not.Empty, "the desert roadmap is baked with walks");
        var builder = new RoadmapBuilder(desert.LevelFingerprint, desert.CharacterFingerprint, desert.CharacterName, desert.Seed);
        foreach (RoadmapNode node in desert.Nodes)
        {
            builder.AddNode(node);
        }

        foreach (RoadmapWalk walk in desert.Walks)
        {
            builder.AddWalk(walk);
        }

        Roadmap walksOnly = builder.Freeze();
        var kind = new Ballistic.Runtime.Kinds.CharacterKind(HostingWorlds.Desert.Scene, walksOnly, HostingWorlds.Desert.Animator);
        var random = new Random(61);
        (RoadmapNode From, RoadmapNode To)? pair = null;
        for (int attempt = 0; attempt < 2_000 && pair is null; attempt++)
        {
            RoadmapNode a = walksOnly.Nodes[random.Next(walksOnly.Nodes.Count)];
            RoadmapNode b = walksOnly.Nodes[random.Next(walksOnly.Nodes.Count)];
            if (Vector3.Distance(a.Pose.Position, b.Pose.Position) > 3f && walksOnly.ReachesWalking(a.Id, b.Id) &&
                walksOnly.FindNode(RuntimeWorlds.Point(a), HostingWorlds.Tolerance) == a.Id && walksOnly.FindNode(RuntimeWorlds.Point(b), HostingWorlds.Tolerance) == b.Id)
            {
                pair = (a, b);
            }
        }

        Assert.That(pair, Is.Not.Null, "a pair joined by walks");
        (RoadmapNode from, RoadmapNode to) = pair!.Value;
        foreach ((WorldSettings settings, bool reachable) in new[] { (new WorldSettings { AnimationThreads = 0, Locomotion = Locomotion.WalkAndJump }, true), (RuntimeWorlds.JumpOnly, false) })
        {
            using var host = new JumpWorld(settings);
            KindHandle region = host.CreateKind("desert without jumps");
            Assert.That(host.ReplaceKind(region, kind).Ok, Is.True);
            AgentHandle agent = host.AddAgent(region, RuntimeWorlds.Point(from)).Agent;
            Assume.That(host.GetStance(agent), Is.SameAs(from), "the agent stands on the node");
            Assert.That(host.IsTargetReachable(agent, RuntimeWorlds.Point(to)), Is.EqualTo(reachable), $"locomotion {settings.Locomotion}");
        }
    }
}
