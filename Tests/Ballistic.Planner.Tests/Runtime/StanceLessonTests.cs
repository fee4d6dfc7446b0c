using Ballistic.Planner.Animation;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Query;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>
/// A stance the body cannot crouch on, found by one path request, is set aside by every request the world starts
/// after it: an agent standing there is told so after one search, not after animating and repairing a path for every
/// target it is sent to (the playtest's agent spawned on a block top it could not crouch on failed 85 targets in 10 s
/// that way, each a full plan and repair). The lessons are the kind's: another kind in its slot starts afresh. The same
/// outcomes whatever the threads.
/// </summary>
public sealed class StanceLessonTests
{
    [Test]
    public void AStanceTheBodyCannotCrouchOnIsSetAsideByTheRequestsThatFollow()
    {
        var told = new List<string>();
        foreach (int threads in new[] { 0, 2 })
        {
            CharacterKind desert = RuntimeWorlds.DesertSkeleton;
            Roadmap roadmap = desert.Roadmap;
            (RoadmapNode trap, RoadmapNode to) = RuntimeWorlds.ConnectedPairs(roadmap, 1, seed: 4, minDistance: 8f)[0];
            RoadmapNode other = roadmap.Nodes.First(n => n.Id != to.Id && roadmap.Reaches(trap.Id, n.Id)
                && System.Numerics.Vector3.Distance(n.Pose.Position, trap.Pose.Position) >= 6f && System.Numerics.Vector3.Distance(n.Pose.Position, to.Pose.Position) >= 6f);

            // The body cannot crouch on the trap: every jump from it is refused, as the animator refuses a stance.
            var inner = new SimpleMoveAnimator(desert.Animator);
            var refusing = new RefusingAnimator(inner, m => m is Jump && m.From.Id == trap.Id, "test: the pelvis enters the level", ProblemStance.Takeoff);
            var kind = new CharacterKind(desert.Scene, roadmap, desert.Animator, refusing);
            using var world = new JumpWorld(desert.Scene.Level, RuntimeWorlds.JumpOnly with { AnimationThreads = threads, RepairRounds = 3 });
            KindHandle handle = world.AddKind(kind).Kind;
            AgentHandle agent = world.AddAgent(handle, RuntimeWorlds.Point(trap)).Agent;

            string Fails(AgentHandle who, RoadmapNode target)
            {
                Assert.That(world.SetTarget(who, RuntimeWorlds.Point(target)).Ok, Is.True);
                List<JumpEvent> seen = RuntimeWorlds.Run(world, 120, (_, s) => s.Any(e => e.Agent == who && e.Kind is JumpEventKind.PathFailed or JumpEventKind.PathFound));
                JumpEvent? failed = seen.Cast<JumpEvent?>().FirstOrDefault(e => e!.Value.Agent == who && e.Value.Kind == JumpEventKind.PathFailed);
                Assert.That(failed, Is.Not.Null, $"{threads} threads: a path from the trap ({string.Join(", ", seen.Select(e => e.Kind))})");
                return failed!.Value.Reason!;
            }

            // The first request finds it: its path's first jump is animated and refused.
            string first = Fails(agent, to);
            int animated = inner.Calls;
            Assert.That(refusing.PathsRefused, Is.EqualTo(1), first);
            Assert.That(first, Does.Contain("set aside").And.Contain("the pelvis enters the level"));

            // Sent elsewhere, and a second agent spawned on the trap: no path is animated, and each is told why.
            string again = Fails(agent, other);
            AgentHandle second = world.AddAgent(handle, RuntimeWorlds.Point(trap)).Agent;
            string newcomer = Fails(second, to);
            Assert.Multiple(() =>
            {
                Assert.That(inner.Calls, Is.EqualTo(animated), "no path animated after the first request found the stance");
                Assert.That(again, Does.Contain($"as earlier requests found (stance {trap.Id}: test: the pelvis enters the level)"));
                Assert.That(newcomer, Does.Contain($"as earlier requests found (stance {trap.Id}: test: the pelvis enters the level)"));
            });

            // An agent on another stance still jumps, and through the trap's neighbourhood without taking off from it.
            AgentHandle third = world.AddAgent(handle, RuntimeWorlds.Point(to)).Agent;
            Assert.That(world.SetTarget(third, RuntimeWorlds.Point(other)).Ok, Is.True);
            List<JumpEvent> run = RuntimeWorlds.Run(world, 120, (_, s) => s.Any(e => e.Agent == third && e.Kind is JumpEventKind.PathFailed or JumpEventKind.PathFound));
            JumpEvent found = run.Single(e => e.Agent == third && e.Kind is JumpEventKind.PathFailed or JumpEventKind.PathFound);
            Assert.That(found.Kind, Is.EqualTo(JumpEventKind.PathFound), found.Reason);
            Assert.That(world.GetPath(third)!.Moves.Select(m => m.From.Id), Has.No.Member(trap.Id));

            // Another kind in the slot (a body that can crouch there, on the same roadmap): the lessons were the old body's.
            var able = new CharacterKind(desert.Scene, roadmap, desert.Animator, new SimpleMoveAnimator(desert.Animator));
            Assert.That(world.ReplaceKind(handle, able).Ok, Is.True);
            Assert.That(world.SetTarget(agent, RuntimeWorlds.Point(other)).Ok, Is.True);
            List<JumpEvent> freed = RuntimeWorlds.Run(world, 200, (_, s) => s.Any(e => e.Agent == agent && e.Kind is JumpEventKind.PathFailed or JumpEventKind.PathFound));
            JumpEvent leaving = freed.Single(e => e.Agent == agent && e.Kind is JumpEventKind.PathFailed or JumpEventKind.PathFound);
            Assert.That(leaving.Kind, Is.EqualTo(JumpEventKind.PathFound), leaving.Reason);
            Assert.That(world.GetPath(agent)!.Moves[0].From.Id, Is.EqualTo(trap.Id), "it takes off from the trap, which the new body can crouch on");
            told.Add($"{first} | {again} | {newcomer} | {string.Join(",", world.GetPath(agent)!.Moves.Select(m => m.To.Id))}");
        }

        Assert.That(told[1], Is.EqualTo(told[0]), "the same outcomes at 0 and 2 threads");
    }
}
