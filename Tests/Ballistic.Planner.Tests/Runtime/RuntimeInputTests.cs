using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>Bad handles, bad points, mismatched roadmaps, removal in mid-flight, retargeting, budgets: a status or an event with the reason, never an exception.</summary>
public sealed class RuntimeInputTests
{
    [Test]
    public void UnknownAndRemovedHandlesGetAStatusNotAnException()
    {
        (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert();
        using (world)
        {
            RoadmapNode node = RuntimeWorlds.DesertSkeleton.Roadmap.Nodes[0];
            AgentHandle agent = world.AddAgent(kind, RuntimeWorlds.Point(node)).Agent;
            Assert.That(world.RemoveAgent(agent).Ok, Is.True);
            AgentHandle reused = world.AddAgent(kind, RuntimeWorlds.Point(node)).Agent;
            Assert.That(reused.Index, Is.EqualTo(agent.Index), "the slot is reused");

            foreach (AgentHandle bad in new[] { default, agent, new AgentHandle(99, 1), new AgentHandle(-1, 1) })
            {
                Assert.That(world.IsValid(bad), Is.False, bad.ToString());
                Assert.That(world.SetTarget(bad, Vector3.Zero).Status, Is.EqualTo(RuntimeStatus.UnknownAgent));
                Assert.That(world.ClearTarget(bad).Status, Is.EqualTo(RuntimeStatus.UnknownAgent));
                Assert.That(world.Warp(bad, Vector3.Zero).Status, Is.EqualTo(RuntimeStatus.UnknownAgent));
                Assert.That(world.RemoveAgent(bad).Status, Is.EqualTo(RuntimeStatus.UnknownAgent));
                Assert.That(world.SetPoseEnabled(bad, false).Status, Is.EqualTo(RuntimeStatus.UnknownAgent));
                Assert.That(world.TryGetNextJump(bad, out _), Is.False);
                Assert.That(world.GetJointRotations(bad).Length, Is.Zero);
                Assert.That(world.GetPath(bad), Is.Null);
            }

            Assert.That(world.IsValid(reused), Is.True, "the new agent in the slot is not confused with the removed one");
            Assert.That(world.AddAgent(default, RuntimeWorlds.Point(node)).Result.Status, Is.EqualTo(RuntimeStatus.UnknownKind));
            Assert.That(world.AddAgent(new KindHandle(5, 1), RuntimeWorlds.Point(node)).Result.Status, Is.EqualTo(RuntimeStatus.UnknownKind));
        }
    }

    [Test]
    public void PointsNobodyCanStandOnAreRefusedWithTheReason()
    {
        (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert();
        using (world)
        {
            AddAgentResult inTheSky = world.AddAgent(kind, new Vector3(0f, 500f, 0f));
            Assert.That(inTheSky.Result.Status, Is.EqualTo(RuntimeStatus.InvalidPosition));
            Assert.That(inTheSky.Result.Reason, Does.Contain("position"));
            Assert.That(world.AddAgent(kind, new Vector3(float.NaN, 0f, 0f)).Result.Status, Is.EqualTo(RuntimeStatus.InvalidArgument));

            AgentHandle agent = world.AddAgent(kind, RuntimeWorlds.Point(RuntimeWorlds.DesertSkeleton.Roadmap.Nodes[0])).Agent;
            Assert.That(world.SetTarget(agent, new Vector3(0f, float.PositiveInfinity, 0f)).Status, Is.EqualTo(RuntimeStatus.InvalidArgument));
            Vector3 before = world.GetRootPose(agent).Position;
            Assert.That(world.Warp(agent, new Vector3(1000f, 0f, 1000f)).Status, Is.EqualTo(RuntimeStatus.InvalidPosition));
            Assert.That(world.GetRootPose(agent).Position, Is.EqualTo(before), "a refused warp leaves the agent where it was");

            // A target off the level: the path request fails with the planner's reason.
            Assert.That(world.SetTarget(agent, new Vector3(1000f, 0f, 1000f)).Ok, Is.True);
            List<JumpEvent> events = RuntimeWorlds.Run(world, 30, (_, seen) => seen.Count > 0);
            Assert.That(events, Has.Count.EqualTo(1));
            Assert.That(events[0].Kind, Is.EqualTo(JumpEventKind.PathFailed));
            Assert.That(events[0].Status, Is.EqualTo(PlannerStatus.InvalidGoal));
            Assert.That(events[0].Reason, Does.Contain("goal"));
            Assert.That(world.GetState(agent), Is.EqualTo(AgentState.Idle));
        }
    }

    [Test]
    public void ARoadmapForAnotherCharacterOrLevelIsRefused()
    {
        CharacterKind skeleton = RuntimeWorlds.DesertSkeleton;
        var frogScene = PlanningScene.Create(skeleton.Scene.Level, CharacterPresets.Frog());
        var wrong = new CharacterKind(frogScene, skeleton.Roadmap, new JumpAnimator(frogScene, CharacterPresets.Model("frog")));
        using var world = new JumpWorld(skeleton.Scene.Level, new WorldSettings { AnimationThreads = 0 });
        AddKindResult added = world.AddKind(wrong);
        Assert.That(added.Result.Status, Is.EqualTo(RuntimeStatus.Mismatch));
        Assert.That(added.Result.Reason, Does.Contain("another character").And.Contain("skeleton"));

        var gap = PlanningScene.Create(GapCourseLevel(), CharacterPresets.Skeleton());
        using var other = new JumpWorld(gap.Level);
        Assert.That(other.AddKind(skeleton).Result.Status, Is.EqualTo(RuntimeStatus.Mismatch));
        Assert.That(other.AddKind(null!).Result.Status, Is.EqualTo(RuntimeStatus.InvalidArgument));
        Assert.Throws<ArgumentException>(() => _ = new JumpWorld(gap.Level, new WorldSettings { TickRate = 0 }));
    }

    [Test]
    public void AnAgentRemovedInMidFlightLeavesAReasonAndNothingElse()
    {
        (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert();
        using (world)
        {
            AgentHandle agent = RuntimeWorlds.SendAcross(world, kind, seed: 21).Agent;
            RuntimeWorlds.Run(world, 600, (w, _) => w.GetState(agent) == AgentState.Flight);
            Assume.That(world.GetState(agent), Is.EqualTo(AgentState.Flight));

            RuntimeResult removed = world.RemoveAgent(agent);
            Assert.That(removed.Ok, Is.True);
            Assert.That(removed.Reason, Does.StartWith("removed in mid-flight of jump"));
            List<JumpEvent> events = RuntimeWorlds.Run(world, 120);
            Assert.That(events, Has.Count.EqualTo(1));
            Assert.That(events[0].Kind, Is.EqualTo(JumpEventKind.Removed));
            Assert.That(events[0].Reason, Is.EqualTo(removed.Reason));
        }
    }

    [Test]
    public void ANewTargetFarAwayIsPlannedFromTheNextStance()
    {
        Roadmap roadmap = RuntimeWorlds.DesertSkeleton.Roadmap;
        (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert();
        using (world)
        {
            List<(RoadmapNode From, RoadmapNode To)> pairs = RuntimeWorlds.ConnectedPairs(roadmap, 2, seed: 22);
            AgentHandle agent = world.AddAgent(kind, RuntimeWorlds.Point(pairs[0].From)).Agent;
            world.SetTarget(agent, RuntimeWorlds.Point(pairs[0].To));
            RuntimeWorlds.Run(world, 600, (w, _) => w.GetState(agent) == AgentState.Flight);
            Assume.That(world.GetState(agent), Is.EqualTo(AgentState.Flight));
            Assert.That(world.TryGetCurrentJump(agent, out var current), Is.True);

            Vector3 second = RuntimeWorlds.Point(pairs[1].To);
            Assert.That(world.SetTarget(agent, second).Ok, Is.True);
            Assert.That(world.TryGetNextJump(agent, out _), Is.False, "no further takeoff on the old path");
            List<JumpEvent> events = RuntimeWorlds.Run(world, 3600, RuntimeWorlds.Concluded);

            // The jump in progress lands; the agent stops there; the new path starts from that landing.
            Assert.That(events[0].Kind, Is.EqualTo(JumpEventKind.Landed));
            Assert.That(events[0].To, Is.EqualTo(current.To));
            Assert.That(events.Count(e => e.Kind == JumpEventKind.PathFound), Is.EqualTo(1));
            JumpEvent found = events.First(e => e.Kind == JumpEventKind.PathFound);
            Assert.That(Vector3.Distance(found.From, current.To), Is.LessThan(1e-5f), "the new path starts where the agent landed");
            Assert.That(events[^1].Kind, Is.EqualTo(JumpEventKind.TargetReached), string.Join("; ", events.Select(e => e.Reason)));
            Assert.That(Vector3.Distance(events[^1].To, second), Is.LessThan(1e-5f));
        }
    }

    [Test]
    public void SearchesPerTickStayWithinTheBudget()
    {
        Roadmap roadmap = RuntimeWorlds.DesertSkeleton.Roadmap;
        (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert(RuntimeWorlds.JumpOnly with { AnimationThreads = 2, MaxSearchesPerTick = 4 });
        using (world)
        {
            var random = new Random(5);
            var agents = new List<AgentHandle>();
            for (int i = 0; i < 40; i++)
            {
                RoadmapNode node = roadmap.Nodes[random.Next(roadmap.Nodes.Count)];
                AddAgentResult added = world.AddAgent(kind, RuntimeWorlds.Point(node));
                if (added.Ok)
                {
                    agents.Add(added.Agent);
                    world.SetTarget(added.Agent, RuntimeWorlds.Point(roadmap.Nodes[random.Next(roadmap.Nodes.Count)]));
                }
            }

            Assert.That(world.QueuedRequests, Is.EqualTo(agents.Count));
            int ticks = 0;
            var answered = new HashSet<AgentHandle>();
            while ((world.QueuedRequests > 0 || world.AnimatingRequests > 0) && ticks++ < 2000)
            {
                world.Step();
                Assert.That(world.LastTickSearches, Is.LessThanOrEqualTo(4));
                foreach (JumpEvent e in world.Events)
                {
                    if (e.Kind is JumpEventKind.PathFound or JumpEventKind.PathFailed or JumpEventKind.TargetReached)
                    {
                        answered.Add(e.Agent);
                    }
                }
            }

            Assert.That(ticks, Is.GreaterThanOrEqualTo(agents.Count / 4), "the queue took several ticks");
            Assert.That(answered, Has.Count.EqualTo(agents.Count), "every request was answered");
        }
    }

    private static Ballistic.Planner.Levels.Level GapCourseLevel() => Support.GapCourse.Build();
}
