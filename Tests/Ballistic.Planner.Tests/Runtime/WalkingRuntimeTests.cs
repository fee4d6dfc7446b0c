using System.Numerics;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;
using Ballistic.Runtime.Paths;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>
/// Agents following paths with walks (hand-made walk → jump → walk, animated by a test double): the root exactly on
/// each walk at its speed, the walk events in order with their payloads, the walk queries, stopping at a walk's end,
/// no allocation while walking.
/// </summary>
public sealed class WalkingRuntimeTests
{
    private const int MaxTicks = 60 * 30;

    /// <summary>An agent performing <see cref="WalkingPaths.WalkJumpWalk"/>, with the moves.</summary>
    private static (JumpWorld World, AgentHandle Agent, IReadOnlyList<Move> Moves) Performing(int which = 0)
    {
        (JumpWorld world, KindHandle kind) = WalkingPaths.World();
        IReadOnlyList<Move> moves = WalkingPaths.WalkJumpWalk(which);
        AddAgentResult added = world.AddAgent(kind, WalkingPaths.Centre(moves[0].To));
        Assert.That(added.Ok, Is.True, added.Result.ToString());
        Assert.That(world.PerformMoves(added.Agent, moves).Ok, Is.True);
        Assert.That(world.GetRootPose(added.Agent), Is.EqualTo(moves[0].From.Pose), "stands on the first stance at once");
        return (world, added.Agent, moves);
    }

    [Test]
    public void AnAgentWalksJumpsAndWalksWithTheEventsInOrder()
    {
        (JumpWorld world, AgentHandle agent, IReadOnlyList<Move> moves) = Performing();
        using (world)
        {
            AgentPath? path = null;
            double pathStart = 0;
            List<JumpEvent> events = RuntimeWorlds.Run(world, MaxTicks, RuntimeWorlds.Concluded, w =>
            {
                if (path is null && w.GetPath(agent) is { } p)
                {
                    path = p;
                    pathStart = w.Time;
                }
            });

            Assert.That(events.Select(e => e.Kind), Is.EqualTo(new[]
            {
                JumpEventKind.PathFound, JumpEventKind.WalkStarted, JumpEventKind.WalkFinished, JumpEventKind.JumpStarted,
                JumpEventKind.Landed, JumpEventKind.WalkStarted, JumpEventKind.WalkFinished, JumpEventKind.TargetReached,
            }), string.Join("; ", events.Select(e => $"{e.Kind} {e.Reason}")));
            Assert.That(path, Is.Not.Null);
            Assert.That(events.Skip(1).Select(e => e.Jump), Is.EqualTo(new[] { 0, 0, 1, 1, 2, 2, 2 }), "move indices");
            Assert.That(events[1].Time, Is.EqualTo(pathStart).Within(1e-9), "the first walk starts when the path is found");

            var walks = new[] { (Walk)moves[0], (Walk)moves[2] };
            var jump = (Jump)moves[1];
            for (int w = 0; w < 2; w++)
            {
                JumpEvent started = events[1 + (4 * w)];
                JumpEvent finished = events[2 + (4 * w)];
                int index = 2 * w;
                Assert.That(started.Time, Is.EqualTo(pathStart + path!.Animation.MoveStart(index)).Within(1e-6), $"walk {index} starts on the clock");
                Assert.That(finished.Time - started.Time, Is.EqualTo(walks[w].Duration).Within(1e-4), "a walk lasts its duration: turning in place, speeding up, walking, slowing down");
                Assert.That(walks[w].Duration, Is.GreaterThanOrEqualTo(walks[w].Length / walks[w].Speed), "never faster than the walking speed");
                Assert.That(started.Duration, Is.EqualTo(walks[w].Duration));
                Assert.That(finished.Duration, Is.EqualTo(walks[w].Duration));
                Assert.That(started.From, Is.EqualTo(walks[w].From.Pose.Position));
                Assert.That(started.To, Is.EqualTo(walks[w].To.Pose.Position));
                Assert.That(started.Velocity, Is.EqualTo(Vector3.Zero));
                Assert.That(started.IsWalk && finished.IsWalk, Is.True);
            }

            Assert.That(events[3].From, Is.EqualTo(jump.Arc.Start));
            Assert.That(events[3].Velocity, Is.EqualTo(jump.Arc.TakeoffVelocity));
            Assert.That(events[4].Time - events[3].Time, Is.EqualTo(jump.Arc.FlightTime).Within(1e-4));
            Assert.That(events[3].Time - events[2].Time, Is.EqualTo(0.2).Within(1e-4), "the stance between the walk and the jump");
            Assert.That(events.Zip(events.Skip(1)).All(p => p.First.Time <= p.Second.Time + 1e-9), Is.True, "event times never go back");
            Assert.That(events[^1].Time, Is.EqualTo(events[^2].Time).Within(1e-9), "arrives as the last walk ends");
            Assert.That(world.GetRootPose(agent), Is.EqualTo(moves[2].To.Pose), "stands on the last stance");
            Assert.That(world.GetStance(agent), Is.SameAs(moves[2].To));
            Assert.That(world.GetState(agent), Is.EqualTo(AgentState.Idle));
            Assert.That(world.GetTarget(agent), Is.Null);
        }
    }

    [Test]
    public void WalkingTheRootIsExactlyOnTheWalkAtItsSpeed()
    {
        (JumpWorld world, AgentHandle agent, IReadOnlyList<Move> moves) = Performing();
        using (world)
        {
            float dt = (float)world.Settings.TickSeconds;
            var walkingTicks = new int[3];
            (int Index, Vector3 Position)? previous = null;
            var states = new List<AgentState>();
            RuntimeWorlds.Run(world, MaxTicks, RuntimeWorlds.Concluded, w =>
            {
                AgentState state = w.GetState(agent);
                states.Add(state);
                if (state != AgentState.Walking)
                {
                    Assert.That(w.TryGetCurrentWalk(agent, out _), Is.False, $"no walk in progress when {state}");
                    previous = null;
                    return;
                }

                Assert.That(w.TryGetCurrentWalk(agent, out WalkInfo info) && info.InProgress, Is.True, "a walk in progress is reported");
                Assert.That(w.TryGetCurrentJump(agent, out _), Is.False, "no jump while walking");
                Assert.That(info.Walk, Is.SameAs(moves[info.Index]), "the walk of the path");
                Assert.That(w.GetMoveIndex(agent), Is.EqualTo(info.Index));
                Vector3 position = w.GetRootPose(agent).Position;

                // Exactly the walk's own evaluation at the time since it started, and (independently) at the path's clock.
                Assert.That(w.GetRootPose(agent), Is.EqualTo(info.Walk.PoseAt((float)(w.Time - info.StartTime))));
                AgentPath path = w.GetPath(agent)!;
                float since = w.GetPathTime(agent) - path.Animation.MoveStart(info.Index);
                Assert.That(since, Is.InRange(0f, info.Walk.Duration + 1e-4f));
                Assert.That(Vector3.Distance(position, info.Walk.PoseAt(since).Position), Is.LessThan(1e-4f), $"off the walk at {since:0.###} s");

                // On the ground path, lifted by the first stance's trunk offset give or take how far the offset changes
                // along the walk (a stance leaning a little stands up over its contacts to walk), never faster than
                // the walking speed.
                Walk walking = info.Walk;
                Vector3 lift = walking.From.Pose.Position - walking.Path[0];
                float change = MathF.Max(Vector3.Distance(lift, walking.PoseAtDistance(0f).Position - walking.Path[0]), MathF.Max(Vector3.Distance(lift, walking.PoseAtDistance(walking.Length).Position - walking.Path[^1]), Vector3.Distance(lift, walking.To.Pose.Position - walking.Path[^1])));
                Assert.That(WalkingPaths.DistanceToPolyline(position - lift, walking.Path), Is.LessThan(change + 1e-4f), "on the ground path");
                if (previous is { } p && p.Index == info.Index)
                {
                    Vector3 step = position - p.Position;
                    float horizontal = new Vector2(step.X, step.Z).Length() / dt;
                    Assert.That(horizontal, Is.LessThanOrEqualTo(info.Speed + 1e-3f), "horizontal speed");
                    Assert.That(step.Length() / dt, Is.GreaterThanOrEqualTo((0.5f * info.Walk.SpeedAt(since - (0.5f * dt))) - 1e-3f), "it moves at the walk's speed then (ramping up and down)");
                }

                previous = (info.Index, position);
                walkingTicks[info.Index]++;
            });

            float[] expected = [((Walk)moves[0]).Duration, 0f, ((Walk)moves[2]).Duration];
            for (int i = 0; i < 3; i += 2)
            {
                Assert.That(walkingTicks[i], Is.InRange((int)(expected[i] / dt) - 1, (int)(expected[i] / dt) + 1), $"ticks walking walk {i}");
            }

            Assert.That(states, Does.Contain(AgentState.Flight).And.Contain(AgentState.Stance));
        }
    }

    [Test]
    public void WhatComesNextIsKnownWhileWalking()
    {
        (JumpWorld world, AgentHandle agent, IReadOnlyList<Move> moves) = Performing();
        using (world)
        {
            RuntimeWorlds.Run(world, MaxTicks, (w, _) => w.GetState(agent) == AgentState.Walking);
            Assert.That(world.TryGetCurrentWalk(agent, out WalkInfo current), Is.True);
            Assert.That(current.Index, Is.Zero);
            double pathStart = world.Time - world.GetPathTime(agent);
            AgentPath path = world.GetPath(agent)!;

            Assert.That(world.TryGetNextJump(agent, out JumpInfo jump), Is.True, "the jump after the walk");
            Assert.That(jump.Index, Is.EqualTo(1));
            Assert.That(jump.InProgress, Is.False);
            Assert.That(jump.Arc, Is.EqualTo(((Jump)moves[1]).Arc));
            Assert.That(jump.TakeoffTime, Is.EqualTo(pathStart + path.Animation.MoveStart(1)).Within(1e-6));

            Assert.That(world.TryGetNextWalk(agent, out WalkInfo next), Is.True, "the walk after the jump");
            Assert.That(next.Index, Is.EqualTo(2));
            Assert.That(next.Walk, Is.SameAs(moves[2]));
            Assert.That(next.StartTime, Is.EqualTo(pathStart + path.Animation.MoveStart(2)).Within(1e-6));
            Assert.That(next.EndTime - next.StartTime, Is.EqualTo(next.Duration).Within(1e-5));

            // In the last walk nothing is left to come.
            RuntimeWorlds.Run(world, MaxTicks, (w, _) => w.TryGetCurrentWalk(agent, out WalkInfo last) && last.Index == 2);
            Assert.That(world.TryGetNextJump(agent, out _), Is.False);
            Assert.That(world.TryGetNextWalk(agent, out _), Is.False);
            Assert.That(world.GetMoveIndex(agent), Is.EqualTo(2));
        }
    }

    [Test]
    public void ANewTargetWhileWalkingStopsAtTheWalksEnd()
    {
        (JumpWorld world, AgentHandle agent, IReadOnlyList<Move> moves) = Performing();
        using (world)
        {
            RuntimeWorlds.Run(world, MaxTicks, (w, _) => w.GetState(agent) == AgentState.Walking);
            Vector3 elsewhere = RuntimeWorlds.Point(RuntimeWorlds.DesertSkeleton.Roadmap.Nodes[0]);
            Assert.That(world.SetTarget(agent, elsewhere).Ok, Is.True);
            Assert.That(world.TryGetNextJump(agent, out _), Is.False, "it will stop before the jump");
            Assert.That(world.GetState(agent), Is.EqualTo(AgentState.Walking), "it walks on to the walk's end");

            List<JumpEvent> events = RuntimeWorlds.Run(world, MaxTicks, (w, seen) => seen.Any(e => e.Kind == JumpEventKind.WalkFinished));
            Assert.That(events.Select(e => e.Kind), Is.EqualTo(new[] { JumpEventKind.WalkFinished }));
            Assert.That(world.GetPath(agent), Is.Null, "the old path is dropped at the walk's end");
            Assert.That(world.GetRootPose(agent), Is.EqualTo(moves[0].To.Pose), "stopped on the walk's last stance");
            Assert.That(world.GetStance(agent), Is.SameAs(moves[0].To));
            Assert.That(world.IsPathPending(agent), Is.True, "planning toward the new target from there");

            List<JumpEvent> after = RuntimeWorlds.Run(world, 120, (w, seen) => seen.Any(e => e.Kind is JumpEventKind.PathFound or JumpEventKind.PathFailed));
            Assert.That(after.Select(e => e.Kind), Has.No.Member(JumpEventKind.Landed), "the old jump is not performed");
        }
    }

    [Test]
    public void ATickOfWalkingAgentsAllocatesNothing()
    {
        (JumpWorld world, KindHandle kind) = WalkingPaths.World();
        using (world)
        {
            List<AgentHandle> agents = WalkingPaths.SetOff(world, kind, 3);

            // Until every path is delivered (animations and path objects allocate, by design).
            RuntimeWorlds.Run(world, 60, (w, _) => w.QueuedRequests == 0 && w.AnimatingRequests == 0);
            Assert.That(agents.All(a => world.GetPath(a) is not null), Is.True);

            int walking = 0;
            for (int tick = 0; tick < 150; tick++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                world.Step();
                long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
                Assert.That(allocated, Is.Zero, $"tick {world.Tick} allocated {allocated} bytes");
                walking += agents.Count(a => world.GetState(a) == AgentState.Walking);
            }

            Assert.That(walking, Is.GreaterThan(100), "the ticks measured had agents walking");
        }
    }

    /// <summary>
    /// An upright walk's trunk rises above the walk's path in the animation (<see cref="Planner.Animation.JumpAnimation.WalkLift(float)"/>);
    /// the agent's root follows it (the skeleton is posed from the root and the animation's angles, solved for the
    /// lifted trunk): exactly the walk's pose raised by the lift, the lift up to the animation's own.
    /// </summary>
    [Test]
    public void AWalkingAgentsRootRisesWithItsAnimationsLift()
    {
        CharacterKind desert = RuntimeWorlds.DesertSkeleton;
        var kind = new CharacterKind(desert.Scene, desert.Roadmap, desert.Animator, new SimpleMoveAnimator(desert.Animator, lift: 0.05f));
        using var world = new JumpWorld(kind.Scene.Level, new WorldSettings { AnimationThreads = 0, Locomotion = Locomotion.WalkAndJump });
        AddKindResult addedKind = world.AddKind(kind);
        IReadOnlyList<Move> moves = WalkingPaths.WalkJumpWalk();
        AddAgentResult added = world.AddAgent(addedKind.Kind, WalkingPaths.Centre(moves[0].To));
        Assert.That(world.PerformMoves(added.Agent, moves).Ok, Is.True);
        float highest = 0f;
        int walking = 0;
        RuntimeWorlds.Run(world, MaxTicks, RuntimeWorlds.Concluded, w =>
        {
            if (w.GetState(added.Agent) != AgentState.Walking || !w.TryGetCurrentWalk(added.Agent, out WalkInfo info))
            {
                return;
            }

            walking++;
            RootPose onPath = info.Walk.PoseAt((float)(w.Time - info.StartTime));
            float lift = w.GetPath(added.Agent)!.Animation.WalkLift(w.GetPathTime(added.Agent));
            highest = MathF.Max(highest, lift);
            Assert.That(w.GetRootPose(added.Agent), Is.EqualTo(Planner.Animation.JumpAnimation.Lifted(onPath, lift)));
            Assert.That(lift, Is.InRange(0f, 0.05f + 1e-4f));
        });

        Assert.That(walking, Is.GreaterThan(30), "ticks walking were seen");
        Assert.That(highest, Is.GreaterThan(0.045f), "the trunk rose with the animation mid-walk");
    }

    [Test]
    public void APathOfMovesHasItsWalksOnTheAnimationsClock()
    {
        IReadOnlyList<Move> moves = WalkingPaths.WalkJumpWalk();
        var animator = new SimpleMoveAnimator(RuntimeWorlds.DesertSkeleton.Animator, stance: 0.3f);
        Planner.Animation.JumpAnimation animation = animator.Animate(moves);
        var path = new AgentPath(Vector3.One, moves, animation);
        Assert.Multiple(() =>
        {
            Assert.That(path.Count, Is.EqualTo(3));
            Assert.That(path.JumpCount, Is.EqualTo(1));
            Assert.That(path.WalkCount, Is.EqualTo(2));
            Assert.That(path.Start, Is.SameAs(moves[0].From));
            Assert.That(path.Goal, Is.SameAs(moves[2].To));
            Assert.That(path.Duration, Is.EqualTo(animation.Duration));
            Assert.That(path.Duration, Is.EqualTo(moves.Sum(m => m.Duration) + 0.6f).Within(1e-4f));
            for (int i = 0; i < 3; i++)
            {
                PathMove move = path.Moves[i];
                Assert.That(move.Index, Is.EqualTo(i));
                Assert.That(move.Kind, Is.EqualTo(moves[i] is Walk ? MoveKind.Walk : MoveKind.Jump));
                Assert.That(move.Walk, Is.SameAs(moves[i] as Walk));
                Assert.That(move.Start, Is.EqualTo(animation.MoveStart(i)));
                Assert.That(move.End, Is.EqualTo(animation.MoveEnd(i)));
                Assert.That(move.StanceEnd, Is.EqualTo(i < 2 ? animation.MoveStart(i + 1) : animation.MoveEnd(i)));
                Assert.That(move.Duration, Is.EqualTo(moves[i].Duration));
                Assert.That(move.StartPose, Is.EqualTo(moves[i].From.Pose));
                Assert.That(move.EndPose, Is.EqualTo(moves[i].To.Pose));
                Assert.That(move.ToMove(), Is.EqualTo(moves[i]));
            }

            Assert.That(path.Moves[0].TakeoffEnd, Is.EqualTo(path.Moves[0].Start), "a walk has no takeoff");
            Assert.That(path.Moves[0].LandingStart, Is.EqualTo(path.Moves[0].End), "a walk has no landing");
            Assert.That(path.Moves[1].Arc, Is.EqualTo(((Jump)moves[1]).Arc));
        });

        // An animation of other moves is refused.
        Planner.Animation.JumpAnimation other = animator.Animate([moves[1], moves[2]]);
        Assert.That(() => new AgentPath(Vector3.One, moves, other), Throws.ArgumentException);
        Planner.Animation.JumpAnimation swapped = animator.Animate([moves[0], moves[1], WalkingPaths.WalkJumpWalk(1)[2]]);
        Assert.That(() => new AgentPath(Vector3.One, moves, swapped), Throws.ArgumentException.With.Message.Contains("Move 2"));
    }

    [Test]
    public void PerformingMovesThatDoNotChainIsRefused()
    {
        (JumpWorld world, AgentHandle agent, IReadOnlyList<Move> moves) = Performing();
        using (world)
        {
            RuntimeResult result = world.PerformMoves(agent, [moves[0], moves[2]]);
            Assert.That(result.Status, Is.EqualTo(RuntimeStatus.InvalidArgument));
            Assert.That(result.Reason, Does.Contain("move 1"));
            Assert.That(world.PerformMoves(agent, []).Status, Is.EqualTo(RuntimeStatus.InvalidArgument));
        }
    }

    [Test]
    public void TheWorldsLocomotionAndJumpEffortReachTheSearch()
    {
        var settings = new WorldSettings { Locomotion = Locomotion.Jump, JumpEffort = 3.5f };
        var search = new RoadmapSearch(RuntimeWorlds.DesertSkeleton, settings);
        Assert.That(search.Settings.Locomotion, Is.EqualTo(Locomotion.Jump));
        Assert.That(search.Settings.JumpEffort, Is.EqualTo(3.5f));

        var defaults = new WorldSettings();
        Assert.That(defaults.Locomotion, Is.EqualTo(new QuerySettings().Locomotion));
        Assert.That(defaults.JumpEffort, Is.EqualTo(new QuerySettings().JumpEffort));
        Assert.That(new RoadmapSearch(RuntimeWorlds.DesertSkeleton, defaults).Settings.Locomotion, Is.EqualTo(Locomotion.WalkAndJump), "walks and jumps by default");

        Assert.That(new WorldSettings { JumpEffort = -1f }.Problem(), Does.Contain("JumpEffort"));
        Assert.That(new WorldSettings { JumpEffort = float.NaN }.Problem(), Does.Contain("JumpEffort"));
        Assert.That(new WorldSettings { Locomotion = (Locomotion)7 }.Problem(), Does.Contain("Locomotion"));
        Assert.That(() => new JumpWorld(RuntimeWorlds.DesertSkeleton.Scene.Level, new WorldSettings { JumpEffort = -1f }), Throws.ArgumentException.With.Message.Contains("JumpEffort"));
    }

    [Test]
    public void AKindsJumpCostsOverrideTheWorldsAndBadOnesRefuseTheKind()
    {
        CharacterKind desert = RuntimeWorlds.DesertSkeleton;
        var world = new WorldSettings { JumpEffort = 3.5f, JumpHeightEffort = 0.25f };
        Assert.That(new RoadmapSearch(desert, world).Settings.JumpHeightEffort, Is.EqualTo(0.25f), "the world's, for a kind without its own");

        var heavy = new CharacterKind(desert.Scene, desert.Roadmap, desert.Animator) { JumpEffort = 6f, JumpHeightEffort = 2f };
        QuerySettings own = new RoadmapSearch(heavy, world).Settings;
        Assert.That((own.JumpEffort, own.JumpHeightEffort), Is.EqualTo((6f, 2f)), "the kind's own");

        var light = new CharacterKind(desert.Scene, desert.Roadmap, desert.Animator) { JumpHeightEffort = 0f };
        QuerySettings mixed = new RoadmapSearch(light, world).Settings;
        Assert.That((mixed.JumpEffort, mixed.JumpHeightEffort), Is.EqualTo((3.5f, 0f)), "each cost the kind leaves out is the world's");

        using var jumps = new JumpWorld(desert.Scene.Level, RuntimeWorlds.JumpOnly);
        var bad = new CharacterKind(desert.Scene, desert.Roadmap, desert.Animator) { JumpHeightEffort = float.NaN };
        AddKindResult refused = jumps.AddKind(bad);
        Assert.That(refused.Result.Status, Is.EqualTo(RuntimeStatus.InvalidArgument));
        Assert.That(refused.Result.Reason, Does.Contain("JumpHeightEffort must be finite and not negative"));
        Assert.That(jumps.AddKind(heavy).Result.Ok, Is.True);
    }

    [Test]
    public void APlannedPathOfWalksAndJumpsIsFollowedExactly()
    {
        // The planner's own walks (the default locomotion) on the desert, animated by the double.
        (JumpWorld world, KindHandle kind) = WalkingPaths.World();
        using (world)
        {
            Assert.That(world.Settings.Locomotion, Is.EqualTo(Locomotion.WalkAndJump));
            Roadmap roadmap = WalkingPaths.Kind.Roadmap;
            var random = new Random(71);
            AgentPath? path = null;
            AgentHandle agent = default;
            List<JumpEvent> events = [];
            for (int attempt = 0; attempt < 20 && path is null; attempt++)
            {
                RoadmapNode from = roadmap.Nodes[random.Next(roadmap.Nodes.Count)];
                RoadmapNode to = roadmap.Nodes[random.Next(roadmap.Nodes.Count)];
                if (Vector3.Distance(from.Pose.Position, to.Pose.Position) < 5f || !roadmap.ReachesWalking(from.Id, to.Id) || (roadmap.Reaches(from.Id, to.Id) && attempt < 10))
                {
                    continue;
                }

                if (agent.IsAssigned)
                {
                    world.RemoveAgent(agent);
                }

                agent = world.AddAgent(kind, RuntimeWorlds.Point(from)).Agent;
                world.SetTarget(agent, RuntimeWorlds.Point(to));
                events = RuntimeWorlds.Run(world, 120, (w, seen) => seen.Any(e => e.Kind is JumpEventKind.PathFound or JumpEventKind.PathFailed));
                if (world.GetPath(agent) is { WalkCount: > 0 } found)
                {
                    path = found;
                }
            }

            Assume.That(path, Is.Not.Null, "a planned path with walks");
            double pathStart = events.Last(e => e.Kind == JumpEventKind.PathFound && e.Agent == agent).Time;
            int walking = 0;
            events.AddRange(RuntimeWorlds.Run(world, MaxTicks, RuntimeWorlds.Concluded, w =>
            {
                if (w.GetPath(agent) is null)
                {
                    return;
                }

                int m = w.GetMoveIndex(agent);
                PathMove move = path!.Moves[m];
                float since = (float)(w.Time - (pathStart + move.Start));
                if (w.GetState(agent) == AgentState.Walking)
                {
                    Assert.That(move.Kind, Is.EqualTo(MoveKind.Walk));
                    Assert.That(w.GetRootPose(agent), Is.EqualTo(move.Walk!.PoseAt(since)), $"walk {m} at {since:0.###} s");
                    walking++;
                }
                else if (w.TryGetCurrentJump(agent, out JumpInfo jump))
                {
                    Assert.That(jump.Index, Is.EqualTo(m));
                    Assert.That(w.GetRootPose(agent).Position, Is.EqualTo(move.Arc.PositionAt(since)), $"jump {m} at {since:0.###} s");
                }
            }));

            // Each move's start and end, of its kind, in order; then the arrival on the path's goal.
            List<JumpEvent> moves = [.. events.Where(e => e.Agent == agent).SkipWhile(e => e.Kind != JumpEventKind.PathFound).Skip(1).TakeWhile(e => e.Kind != JumpEventKind.TargetReached)];
            Assert.That(moves, Has.Count.EqualTo(2 * path!.Count), string.Join("; ", events.Select(e => $"{e.Kind} {e.Reason}")));
            for (int m = 0; m < path.Count; m++)
            {
                bool walk = path.Moves[m].Kind == MoveKind.Walk;
                Assert.That(moves[2 * m].Kind, Is.EqualTo(walk ? JumpEventKind.WalkStarted : JumpEventKind.JumpStarted), $"move {m} starts");
                Assert.That(moves[(2 * m) + 1].Kind, Is.EqualTo(walk ? JumpEventKind.WalkFinished : JumpEventKind.Landed), $"move {m} ends");
                Assert.That(moves[2 * m].Move, Is.EqualTo(m));
                Assert.That(moves[(2 * m) + 1].Time - moves[2 * m].Time, Is.EqualTo(path.Moves[m].Duration).Within(1e-4));
            }

            Assert.That(walking, Is.GreaterThan(10), "ticks walking");
            Assert.That(world.GetRootPose(agent), Is.EqualTo(path.Goal.Pose), "arrived on the goal");
        }
    }

    [Test]
    public void AnAnimatorThatFailsFailsTheRequestOnTheSameTickWhateverTheThreads()
    {
        CharacterKind desert = RuntimeWorlds.DesertSkeleton;
        var failing = new CharacterKind(desert.Scene, desert.Roadmap, desert.Animator, new FailingAnimator());
        (RoadmapNode from, RoadmapNode to) = RuntimeWorlds.ConnectedPairs(desert.Roadmap, 1, seed: 72)[0];
        var outcomes = new List<string>();
        foreach (int threads in new[] { 0, 2 })
        {
            using var world = new JumpWorld(desert.Scene.Level, new WorldSettings { AnimationThreads = threads, PathLatencyTicks = 4, MaxAnimationWait = null });
            KindHandle kind = world.AddKind(failing).Kind;
            AgentHandle agent = world.AddAgent(kind, RuntimeWorlds.Point(from)).Agent;
            world.SetTarget(agent, RuntimeWorlds.Point(to));
            List<JumpEvent> events = RuntimeWorlds.Run(world, 60, RuntimeWorlds.Concluded);
            JumpEvent failed = events.Single(e => e.Kind == JumpEventKind.PathFailed);
            Assert.That(failed.Reason, Does.Contain("internal error while animating").And.Contain("no animation here"));
            Assert.That(failed.Tick, Is.EqualTo(1 + 4), "the search's tick plus the latency");
            outcomes.Add(string.Join("; ", events.Select(e => $"{e.Tick} {e.Kind} {e.Reason}")));
        }

        Assert.That(outcomes[1], Is.EqualTo(outcomes[0]));
    }

    /// <summary>An animator that cannot animate anything.</summary>
    private sealed class FailingAnimator : Planner.Animation.IJumpAnimator
    {
        public Planner.Animation.JumpAnimation Animate(IReadOnlyList<Move> moves, float frameRate = 60f) => throw new InvalidOperationException("no animation here");

        public bool CanStand(Planner.Contacts.PoseEvaluation pose) => RuntimeWorlds.DesertSkeleton.Animator.CanStand(pose);
    }
}
