using System.Numerics;
using System.Reflection;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;
using Ballistic.Runtime.Paths;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>
/// The runtime as an ECS a Unity DOTS user would recognise: an ordered system list the game extends and reorders,
/// systems that talk only through components and events, queries, the game's own component columns, and a command
/// buffer played back at the start of the tick.
/// </summary>
public sealed class EcsTests
{
    [Test]
    public void AGameSystemInsertedBetweenLocomotionAndPoseSeesTheAgentsMovedAndTheirPosesNotYetFilled()
    {
        (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert();
        using (world)
        {
            AgentHandle agent = RuntimeWorlds.SendAcross(world, kind, seed: 11).Agent;
            var order = new List<string>();
            var first = new Probe("first", order);
            var middle = new Probe("middle", order, agent);
            var last = new Probe("last", order);
            Assert.That(world.Systems.InsertBefore(world.PathRequestSystem, first).Ok, Is.True);
            Assert.That(world.Systems.InsertAfter(world.LocomotionSystem, middle).Ok, Is.True);
            Assert.That(world.Systems.Add(last).Ok, Is.True);
            Assert.That(world.Systems, Is.EqualTo(new IJumpSystem[] { first, world.PathRequestSystem, world.LocomotionSystem, middle, world.BodyPointSystem, world.PoseSystem, last }));

            int posesFilledAfterMiddle = 0;
            int onPath = 0;
            Quaternion[] before = world.GetJointRotations(agent).ToArray();
            for (int tick = 1; tick <= 240; tick++)
            {
                onPath += world.GetPath(agent) is null ? 0 : 1;
                order.Clear();
                world.Step();
                Assert.That(order, Is.EqualTo(new[] { "first", "middle", "last" }), $"tick {tick}");
                Assert.That(middle.Tick.Tick, Is.EqualTo(world.Tick));
                Assert.That(middle.Tick.Time, Is.EqualTo(world.Time));
                Assert.That(middle.Tick.DeltaSeconds, Is.EqualTo(world.Settings.TickSeconds));

                // Locomotion ran before it: the root it saw is the tick's; the pose system had not: the rotations it
                // saw are the tick before's.
                Assert.That(middle.Root, Is.EqualTo(world.GetRootPose(agent)), $"tick {tick}");
                Assert.That(middle.Rotations, Is.EqualTo(before), $"tick {tick}");
                Quaternion[] after = world.GetJointRotations(agent).ToArray();
                posesFilledAfterMiddle += after.SequenceEqual(before) ? 0 : 1;
                before = after;
            }

            Assert.That(onPath, Is.GreaterThan(60), "the agent followed its path");
            Assert.That(posesFilledAfterMiddle, Is.GreaterThan(0.8 * onPath), $"the pose system, after the probe, changed the pose on most of the {onPath} ticks on the path");
        }
    }

    [Test]
    public void WithoutThePoseSystemAgentsMoveButTheirPosesStayAndPutBackItFillsThemAgain()
    {
        (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert();
        using (world)
        {
            AgentHandle agent = RuntimeWorlds.SendAcross(world, kind, seed: 11).Agent;
            RuntimeWorlds.Run(world, 60, (w, _) => w.GetPath(agent) is not null);
            Assert.That(world.GetPath(agent), Is.Not.Null);
            RuntimeWorlds.Run(world, 20);

            IJumpSystem pose = world.PoseSystem;
            Assert.That(world.Systems.Remove(pose).Ok, Is.True);
            Quaternion[] frozen = world.GetJointRotations(agent).ToArray();
            Vector3 from = world.GetRootPose(agent).Position;
            RuntimeWorlds.Run(world, 30);
            Assert.That(world.GetRootPose(agent).Position, Is.Not.EqualTo(from), "locomotion still runs");
            Assert.That(world.GetJointRotations(agent).ToArray(), Is.EqualTo(frozen), "no pose system, no pose");

            Assert.That(world.Systems.InsertAfter(world.LocomotionSystem, pose).Ok, Is.True);
            world.Step();
            Assert.That(world.GetJointRotations(agent).ToArray(), Is.Not.EqualTo(frozen));
        }
    }

    [Test]
    public void TheBodyPointIsAComponentOnTheParabolaAlongTheWalkAndOnTheStanceWithNoHost()
    {
        (JumpWorld world, KindHandle kind) = WalkingPaths.World();
        using (world)
        {
            IReadOnlyList<Move> moves = WalkingPaths.WalkJumpWalk();
            AgentHandle agent = world.AddAgent(kind, WalkingPaths.Centre(moves[0].To)).Agent;
            Assert.That(world.GetBodyPoint(agent).Position, Is.EqualTo(world.GetStance(agent)!.ContactCentre), "placed at once");
            Assert.That(world.PerformMoves(agent, moves).Ok, Is.True);
            Assert.That(world.GetBodyPoint(agent).Position, Is.EqualTo(moves[0].From.ContactCentre), "moved onto the first stance at once");

            double dt = world.Settings.TickSeconds;
            BodyPoint? previous = null;
            int flying = 0, walking = 0, landed = 0;
            for (int tick = 0; tick < 3600 && world.GetTarget(agent) is not null; tick++)
            {
                world.Step();
                BodyPoint body = world.GetBodyPoint(agent);
                AgentState state = world.GetState(agent);
                bool inJump = world.TryGetCurrentJump(agent, out JumpInfo jump);
                if (inJump && previous is { } p && jump.TakeoffTime < world.Time - dt)
                {
                    // A parabola under gravity: velocity falls by g·dt, position moves by the mean velocity.
                    Assert.That(body.Velocity.Y - p.Velocity.Y, Is.EqualTo(-9.81 * dt).Within(1e-3), $"tick {world.Tick}");
                    Assert.That(Vector3.Distance(body.Position - p.Position, (body.Velocity + p.Velocity) * (float)(0.5 * dt)), Is.LessThan(1e-4f), $"tick {world.Tick}");
                    flying++;
                }
                else if (state == AgentState.Walking)
                {
                    Assert.That(body.Velocity.Length(), Is.LessThanOrEqualTo(world.TryGetCurrentWalk(agent, out WalkInfo walk) ? walk.Walk.Speed * 1.01f : 0f));

                    // The body-point system's values, cached on the path, are the one formula's to the bit.
                    PathMove move = world.GetPath(agent)!.Moves[walk.Index];
                    Assert.That(body.Position, Is.EqualTo(BodyMotion.InWalk(move, (float)(world.Time - walk.StartTime)).Position), $"tick {world.Tick}");
                    walking++;
                }
                else if (!inJump && state is AgentState.Stance or AgentState.Idle && previous is { } before && before.Velocity.Y < -1f)
                {
                    Assert.That(body.Position, Is.EqualTo(moves[1].To.ContactCentre), "landed on the landing stance's contact centre");
                    landed++;
                }

                Assert.That(body.Heading.Length(), Is.EqualTo(1f).Within(1e-5f));
                previous = body;
            }

            Assert.That(flying, Is.GreaterThan(10), "ticks checked in flight");
            Assert.That(landed, Is.EqualTo(1), "the landing was met once");
            Assert.That(walking, Is.GreaterThan(30));
            Assert.That(world.GetBodyPoint(agent).Position, Is.EqualTo(moves[^1].To.ContactCentre), $"arrived on the last stance's contact centre: tick {world.Tick} {world.GetState(agent)} stance {world.GetStance(agent)?.ContactCentre} path {world.GetPath(agent)} target {world.GetTarget(agent)} walking {walking}");
        }
    }

    [Test]
    public void SystemListChangesThatCannotBeMadeAreRefusedWithAReasonAndChangeNothing()
    {
        (JumpWorld world, _) = WalkingPaths.World();
        (JumpWorld other, KindHandle otherKind) = WalkingPaths.World();
        using (other)
        {
            var probe = new Probe("probe", []);
            IJumpSystem[] original = [.. world.Systems];
            void Refused(RuntimeResult result, RuntimeStatus status, string says)
            {
                Assert.That(result.Status, Is.EqualTo(status), result.ToString());
                Assert.That(result.Reason, Does.Contain(says));
                Assert.That(world.Systems, Is.EqualTo(original));
            }

            Refused(world.Systems.Add(null!), RuntimeStatus.InvalidArgument, "null");
            Refused(world.Systems.Add(world.PoseSystem), RuntimeStatus.InvalidArgument, "already");
            Refused(world.Systems.Add(other.PoseSystem), RuntimeStatus.InvalidArgument, "another world");
            Refused(world.Systems.InsertAfter(probe, world.PoseSystem), RuntimeStatus.InvalidArgument, "not in the world's system list");
            Refused(world.Systems.InsertBefore(null!, probe), RuntimeStatus.InvalidArgument, "not in the world's system list");
            Refused(world.Systems.Remove(probe), RuntimeStatus.InvalidArgument, "not in the world's system list");

            // From inside a tick: refused, the tick goes on.
            RuntimeResult inside = default;
            var meddler = new Meddler(w => inside = w.Systems.Remove(w.PoseSystem));
            Assert.That(world.Systems.Add(meddler).Ok, Is.True);
            original = [.. world.Systems];
            world.Step();
            Refused(inside, RuntimeStatus.Busy, "stepping");

            // A world's own system runs only when that world steps it: not run by hand, not by another world.
            IReadOnlyList<Move> moves = WalkingPaths.WalkJumpWalk();
            AgentHandle agent = other.AddAgent(otherKind, WalkingPaths.Centre(moves[0].To)).Agent;
            Assert.That(other.PerformMoves(agent, moves).Ok, Is.True);
            RuntimeWorlds.Run(other, 30, (w, _) => w.GetPath(agent) is not null);
            RootPose held = other.GetRootPose(agent);
            var later = new TickContext(other.Tick + 60, other.Time + 1.0, other.Settings.TickSeconds);
            other.LocomotionSystem.Update(later, other);
            other.LocomotionSystem.Update(later, world);
            Assert.That(other.GetRootPose(agent), Is.EqualTo(held));

            world.Dispose();
            Refused(world.Systems.Remove(meddler), RuntimeStatus.Disposed, "disposed");
        }
    }

    [Test]
    public void AGameSystemThatThrowsIsReportedAsAnEventAndTheTickGoesOn()
    {
        (JumpWorld world, KindHandle kind) = WalkingPaths.World();
        using (world)
        {
            IReadOnlyList<Move> moves = WalkingPaths.WalkJumpWalk();
            AgentHandle agent = world.AddAgent(kind, WalkingPaths.Centre(moves[0].To)).Agent;
            Assert.That(world.PerformMoves(agent, moves).Ok, Is.True);
            RuntimeWorlds.Run(world, 30, (w, _) => w.GetPath(agent) is not null);

            Assert.That(world.Systems.InsertBefore(world.LocomotionSystem, new Meddler(_ => throw new InvalidDataException("stamina table\nis empty"))).Ok, Is.True);
            Assert.That(world.Systems.Add(new Meddler(w => w.Step())).Ok, Is.True);
            Vector3 from = world.GetRootPose(agent).Position;
            Assert.DoesNotThrow(world.Step);

            JumpEvent[] failed = [.. world.Events.ToArray().Where(e => e.Kind == JumpEventKind.SystemFailed)];
            Assert.That(failed, Has.Length.EqualTo(2));
            Assert.That(failed[0].Reason, Does.Contain("Meddler").And.Contain("InvalidDataException").And.Contain("stamina table").And.Not.Contain("\n"));
            Assert.That(failed[1].Reason, Does.Contain("InvalidOperationException").And.Contain("inside a system"));
            Assert.That(failed.All(e => !e.Agent.IsAssigned && e.Tick == world.Tick), Is.True);
            Assert.That(world.GetRootPose(agent).Position, Is.Not.EqualTo(from), "locomotion ran after the system that threw");
            Assert.DoesNotThrow(world.Step, "the world steps on");
        }
    }

    [Test]
    public void QueriesSelectTheAgentsTheirStatesKindAndComponentsSayInSlotOrder()
    {
        (JumpWorld world, KindHandle kind) = WalkingPaths.World();
        using (world)
        {
            var agents = new List<AgentHandle>();
            for (int i = 0; i < 6; i++)
            {
                IReadOnlyList<Move> moves = WalkingPaths.WalkJumpWalk(i % 3);
                AgentHandle agent = world.AddAgent(kind, WalkingPaths.Centre(moves[0].To)).Agent;
                if (i % 2 == 0)
                {
                    Assert.That(world.PerformMoves(agent, moves).Ok, Is.True);
                }

                agents.Add(agent);
            }

            ComponentColumn<float> stamina = world.AddComponentColumn<float>("stamina");
            ComponentColumn<int> team = world.AddComponentColumn<int>("team");
            for (int i = 0; i < agents.Count; i++)
            {
                Assert.That(stamina.Set(agents[i], i).Ok, Is.True);
                if (i % 3 == 0)
                {
                    Assert.That(team.Set(agents[i], 7).Ok, Is.True);
                }
            }

            Assert.That(world.RemoveAgent(agents[1]).Ok, Is.True);
            (JumpWorld other, _) = WalkingPaths.World();
            using (other)
            {
                ComponentColumn<int> foreign = other.AddComponentColumn<int>("foreign");
                Assert.That(world.Query(new AgentQuery().With(foreign)).Count(), Is.Zero, "another world's column selects nobody here");
            }

            var seenStates = new HashSet<AgentState>();
            for (int tick = 0; tick < 400; tick++)
            {
                world.Step();
                AgentHandle[] live = new AgentHandle[world.AgentCount];
                Assert.That(world.CopyAgents(live), Is.EqualTo(live.Length));
                seenStates.UnionWith(live.Select(world.GetState));
                foreach (AgentStates states in new[] { AgentStates.All, AgentStates.Jumping, AgentStates.Walking, AgentStates.Standing, AgentStates.Flight | AgentStates.Idle, AgentStates.None })
                {
                    AgentQuery query = new AgentQuery().InStates(states).OfKind(kind).With(stamina);
                    AgentHandle[] expected = [.. live.Where(a => (states & (AgentStates)(1 << (int)world.GetState(a))) != 0)];
                    Assert.That(Handles(world.Query(query)), Is.EqualTo(expected), $"{states} on tick {world.Tick}");
                }

                Assert.That(Handles(world.Query(new AgentQuery().With(team))), Is.EqualTo(new[] { agents[0], agents[3] }));
                Assert.That(Handles(world.Query(new AgentQuery().With(stamina).Without(team))), Is.EqualTo(new[] { agents[2], agents[4], agents[5] }));
                Assert.That(Handles(world.Query(new AgentQuery().OfKind(new KindHandle(kind.Index + 1, 1)))), Is.Empty);
            }

            Assert.That(seenStates, Is.SupersetOf(new[] { AgentState.Idle, AgentState.Stance, AgentState.Walking }), "the states queried were met");
            Assert.That(seenStates.Overlaps([AgentState.Takeoff, AgentState.Flight, AgentState.Landing]), Is.True, $"agents were met in jumps: {string.Join(", ", seenStates)}");
        }
    }

    [Test]
    public void AGameComponentFollowsItsAgentAndGoesWithIt()
    {
        (JumpWorld world, KindHandle kind) = WalkingPaths.World();
        using (world)
        {
            Vector3 at = WalkingPaths.Centre(WalkingPaths.WalkJumpWalk()[0].To);
            AgentHandle a = world.AddAgent(kind, at).Agent;
            AgentHandle b = world.AddAgent(kind, at).Agent;
            ComponentColumn<Vector3> lookAt = world.AddComponentColumn<Vector3>("look-at");
            Assert.That(lookAt.Has(a), Is.False);
            Assert.That(lookAt.TryGet(a, out _), Is.False);
            Assert.Throws<InvalidOperationException>(() => lookAt.GetRef(a));

            Assert.That(lookAt.Set(a, new Vector3(1, 2, 3)).Ok, Is.True);
            lookAt.GetRef(a).Y += 10f;
            Assert.That(lookAt.TryGet(a, out Vector3 value) && value == new Vector3(1, 12, 3), Is.True, value.ToString());
            Assert.That(lookAt.Has(b), Is.False, "a value is the agent's own");

            Assert.That(world.RemoveAgent(a).Ok, Is.True);
            Assert.That(lookAt.Has(a), Is.False);
            RuntimeResult stale = lookAt.Set(a, Vector3.One);
            Assert.That(stale.Status, Is.EqualTo(RuntimeStatus.UnknownAgent));
            Assert.That(stale.Reason, Does.Contain("look-at"));

            AgentHandle c = world.AddAgent(kind, at).Agent;
            Assert.That(c.Index, Is.EqualTo(a.Index), "the removed agent's slot is reused");
            Assert.That(lookAt.Has(c), Is.False, "a reused slot starts without the removed agent's value");
            Assert.That(lookAt.Set(c, Vector3.UnitX).Ok && lookAt.Remove(c).Ok && !lookAt.Has(c), Is.True);
        }
    }

    [Test]
    public void CommandsRecordedOnAnyThreadArePlayedAtTheStartOfTheNextTickAsTheCallsWouldBe()
    {
        // Two worlds: one called directly between ticks, one through its command buffer from other threads.
        (JumpWorld direct, KindHandle kind) = WalkingPaths.World();
        (JumpWorld buffered, _) = WalkingPaths.World();
        using (direct)
        using (buffered)
        {
            Roadmap roadmap = WalkingPaths.Kind.Roadmap;
            List<(RoadmapNode From, RoadmapNode To)> pairs = RuntimeWorlds.ConnectedPairs(roadmap, 8, seed: 5);
            AgentHandle[] agents = [.. pairs.Select(p => direct.AddAgent(kind, RuntimeWorlds.Point(p.From)).Agent)];
            Assert.That(pairs.Select(p => buffered.AddAgent(kind, RuntimeWorlds.Point(p.From)).Agent), Is.EqualTo(agents));

            for (int i = 0; i < agents.Length; i++)
            {
                Assert.That(direct.SetTarget(agents[i], RuntimeWorlds.Point(pairs[i].To)).Ok, Is.True);
            }

            // Recorded in the order of the calls: the same queue, the same searches, the same events.
            for (int i = 0; i < agents.Length; i++)
            {
                buffered.Commands.SetTarget(agents[i], RuntimeWorlds.Point(pairs[i].To));
            }

            Assert.That(buffered.Commands.Count, Is.EqualTo(agents.Length));
            Assert.That(buffered.GetTarget(agents[0]), Is.Null, "nothing happens before the tick");

            var seenDirect = new List<JumpEvent>();
            var seenBuffered = new List<JumpEvent>();
            for (int tick = 0; tick < 240; tick++)
            {
                if (tick == 90)
                {
                    Assert.That(direct.ClearTarget(agents[2]).Ok && direct.Warp(agents[3], RuntimeWorlds.Point(pairs[3].From)).Ok, Is.True);
                    buffered.Commands.ClearTarget(agents[2]);
                    buffered.Commands.Warp(agents[3], RuntimeWorlds.Point(pairs[3].From));
                }

                direct.Step();
                buffered.Step();
                Assert.That(buffered.Commands.Count, Is.Zero);
                seenDirect.AddRange(direct.Events.ToArray());
                seenBuffered.AddRange(buffered.Events.ToArray());
                foreach (AgentHandle agent in agents)
                {
                    Assert.That(buffered.GetRootPose(agent), Is.EqualTo(direct.GetRootPose(agent)), $"{agent} on tick {direct.Tick}");
                }
            }

            // Each world has its own path objects: the events are compared with their paths' shape (moves, duration) in place of the reference.
            static IEnumerable<(JumpEvent Event, int? Moves, float? Duration)> Shape(List<JumpEvent> events) =>
                events.Select(e => (e with { Path = null }, e.Path?.Moves.Count, e.Path?.Duration));
            Assert.That(Shape(seenBuffered), Is.EqualTo(Shape(seenDirect)));
            Assert.That(seenDirect.Count(e => e.Kind == JumpEventKind.PathFound), Is.GreaterThanOrEqualTo(agents.Length), "the agents set off");

            // Refused on play: an agent removed meanwhile, a target that is not a point.
            buffered.Commands.RemoveAgent(agents[0]);
            buffered.Commands.SetTarget(agents[0], Vector3.Zero);
            buffered.Commands.SetTarget(agents[1], new Vector3(float.NaN, 0f, 0f));
            buffered.Commands.SetPoseEnabled(agents[1], false);
            buffered.Step();
            JumpEvent[] events = buffered.Events.ToArray();
            Assert.That(events.Take(3).Select(e => (e.Kind, e.Agent)), Is.EqualTo(new[]
            {
                (JumpEventKind.Removed, agents[0]), (JumpEventKind.CommandRefused, agents[0]), (JumpEventKind.CommandRefused, agents[1]),
            }));
            Assert.That(events[1].Reason, Does.StartWith("SetTarget of ").And.Contain("UnknownAgent"));
            Assert.That(events[2].Reason, Does.Contain("not finite"));
            Assert.That(buffered.IsValid(agents[0]), Is.False);

            // From four threads at once, while the world steps: every command lands, on the tick after it was recorded.
            int stepped = 0;
            Parallel.For(0, 5, t =>
            {
                if (t == 4)
                {
                    for (; stepped < 30; stepped++)
                    {
                        buffered.Step();
                    }

                    return;
                }

                for (int round = 0; round < 200; round++)
                {
                    for (int i = 1 + t; i < agents.Length; i += 4)
                    {
                        buffered.Commands.SetTarget(agents[i], RuntimeWorlds.Point(pairs[(i + round) % pairs.Count].To));
                    }
                }
            });
            buffered.Step();
            Assert.That(buffered.Commands.Count, Is.Zero);
            for (int i = 1; i < agents.Length; i++)
            {
                Assert.That(buffered.GetTarget(agents[i]), Is.EqualTo(RuntimeWorlds.Point(pairs[(i + 199) % pairs.Count].To)), $"{agents[i]}: its last command's target");
            }
        }
    }

    [Test]
    public void AnAgentSpawnedThroughTheCommandBufferIsAddedAndSentAsTheCallsWouldBe()
    {
        // Two worlds: one spawning with direct calls between ticks, one through its command buffer, a target given to
        // the pending handle right after the spawn.
        (JumpWorld direct, KindHandle kind) = WalkingPaths.World();
        (JumpWorld buffered, _) = WalkingPaths.World();
        using (direct)
        using (buffered)
        {
            (RoadmapNode from, RoadmapNode to) = RuntimeWorlds.ConnectedPairs(WalkingPaths.Kind.Roadmap, 1, seed: 6)[0];
            AgentHandle pending = buffered.Commands.AddAgent(kind, RuntimeWorlds.Point(from));
            buffered.Commands.SetTarget(pending, RuntimeWorlds.Point(to));
            AgentHandle sky = buffered.Commands.AddAgent(kind, new Vector3(0f, 500f, 0f));
            AgentHandle nowhere = buffered.Commands.AddAgent(new KindHandle(9, 1), Vector3.Zero);
            buffered.Commands.SetTarget(nowhere, RuntimeWorlds.Point(to));
            Assert.That(pending.IsAssigned || buffered.IsValid(pending), Is.False, "a pending handle names no agent yet");
            Assert.That(buffered.AgentCount, Is.Zero, "nothing happens before the tick");

            AgentHandle agent = direct.AddAgent(kind, RuntimeWorlds.Point(from)).Agent;
            Assert.That(direct.SetTarget(agent, RuntimeWorlds.Point(to)).Ok, Is.True);
            buffered.Step();
            direct.Step();
            JumpEvent[] played = [.. buffered.Events.ToArray().Where(e => e.Kind is JumpEventKind.Added or JumpEventKind.CommandRefused)];
            Assert.That(played.Select(e => e.Kind), Is.EqualTo(new[] { JumpEventKind.Added, JumpEventKind.Added, JumpEventKind.CommandRefused, JumpEventKind.CommandRefused }), string.Join("; ", played.Select(e => e.Reason)));
            Assert.That(played[0].Agent, Is.EqualTo(agent), "the same slot as the direct add");
            Assert.That(played[0].From, Is.EqualTo(RuntimeWorlds.Point(from)));
            Assert.That(played[0].Reason, Is.Null);
            Assert.That(buffered.GetLifecycle(played[1].Agent), Is.EqualTo(AgentLifecycle.Unplaced), "the one in the sky is added, unplaced");
            Assert.That(played[1].Reason, Does.Contain("cannot stand"));
            Assert.That(played[2].Reason, Does.StartWith("AddAgent of kind 9#1"));
            Assert.That(played[3].Reason, Does.StartWith("SetTarget of the agent pending as pending add 3 of playback 1"));
            Assert.That(buffered.GetTarget(agent), Is.EqualTo(direct.GetTarget(agent)), "the target recorded on the pending handle reached the agent");

            // 15 s at most: the route takes 10.5 s (628 ticks, the request's planning included).
            for (int tick = 0; tick < 900 && direct.GetTarget(agent) is not null; tick++)
            {
                direct.Step();
                buffered.Step();
                Assert.That(buffered.GetRootPose(agent), Is.EqualTo(direct.GetRootPose(agent)), $"tick {direct.Tick}");
            }

            Assert.That(direct.GetTarget(agent), Is.Null, "it arrived");

            // A pending handle of an earlier playback names nobody.
            buffered.Commands.SetTarget(pending, RuntimeWorlds.Point(from));
            buffered.Step();
            Assert.That(buffered.Events.ToArray().Single(e => e.Kind == JumpEventKind.CommandRefused).Reason, Does.Contain("pending add 1 of playback 1"));
            Assert.That(sky.Index, Is.EqualTo(-2));
        }
    }

    [Test]
    public void TheWorldsSystemsDoNotHoldOrCallOneAnother()
    {
        // They talk through components, events and the path queue: no system type holds another.
        Type[] systems = [.. typeof(JumpWorld).Assembly.GetTypes().Where(t => t.Namespace == "Ballistic.Runtime.Systems" && t.Name.EndsWith("System", StringComparison.Ordinal))];
        Assert.That(systems.Select(t => t.Name), Is.SupersetOf(new[] { "PathRequestSystem", "LocomotionSystem", "PoseSystem" }));
        foreach (Type system in systems)
        {
            IEnumerable<Type> held = system.GetFields(BindingFlags.Instance | BindingFlags.NonPublic | BindingFlags.Public).Select(f => f.FieldType)
                .Concat(system.GetConstructors(BindingFlags.Instance | BindingFlags.NonPublic | BindingFlags.Public).SelectMany(c => c.GetParameters()).Select(p => p.ParameterType));
            Assert.That(held.Intersect(systems), Is.Empty, $"{system.Name} holds another system");
        }
    }

    [Test]
    public void ComponentsReadAsSpansByHandleIndexAreEachAgentsOwn()
    {
        (JumpWorld world, KindHandle kind) = WalkingPaths.World();
        using (world)
        {
            List<AgentHandle> agents = WalkingPaths.SetOff(world, kind, 3);
            ComponentColumn<float> stamina = world.AddComponentColumn<float>("stamina");
            agents.Skip(1).ToList().ForEach(a => stamina.Set(a, 1f));
            int checkedAgents = 0;
            var reader = new Meddler(w =>
            {
                foreach (AgentHandle agent in w.Query(new AgentQuery()))
                {
                    Assert.That(w.RootPoses[agent.Index], Is.EqualTo(w.GetRootPose(agent)));
                    Assert.That(w.BodyPoints[agent.Index], Is.EqualTo(w.GetBodyPoint(agent)));
                    Assert.That(w.States[agent.Index], Is.EqualTo(w.GetState(agent)));
                    checkedAgents++;
                }
            });
            Assert.That(world.Systems.InsertAfter(world.BodyPointSystem, reader).Ok, Is.True);
            RuntimeWorlds.Run(world, 240, (w, _) => false);
            Assert.That(checkedAgents, Is.EqualTo(3 * 240), "every agent, every tick");

            // A game column written in place through its span: the agent's own value, nobody else's.
            foreach (AgentHandle agent in world.Query(new AgentQuery().With(stamina)))
            {
                stamina.Values[agent.Index] -= 0.25f;
            }

            Assert.That(stamina.TryGet(agents[1], out float b) && b == 0.75f && stamina.TryGet(agents[2], out float c) && c == 0.75f, Is.True);
            Assert.That(stamina.Has(agents[0]), Is.False, "the agent without a value has none");
            Assert.That(world.RootPoses.Length, Is.GreaterThanOrEqualTo(agents.Max(a => a.Index) + 1));
        }
    }

    [Test]
    public void ASteadyTickWithAGameSystemQueryAndComponentAllocatesNothing()
    {
        (JumpWorld world, KindHandle kind) = WalkingPaths.World();
        using (world)
        {
            List<AgentHandle> agents = WalkingPaths.SetOff(world, kind, 3);

            ComponentColumn<float> stamina = world.AddComponentColumn<float>("stamina");
            agents.ForEach(a => stamina.Set(a, 1f));
            var tire = new Tire(stamina);
            Assert.That(world.Systems.InsertAfter(world.LocomotionSystem, tire).Ok, Is.True);
            RuntimeWorlds.Run(world, 60, (w, _) => w.QueuedRequests == 0 && w.AnimatingRequests == 0);

            for (int tick = 0; tick < 150; tick++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                world.Step();
                long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
                Assert.That(allocated, Is.Zero, $"tick {world.Tick} allocated {allocated} bytes");
            }

            Assert.That(tire.Moving, Is.GreaterThan(100), "the system's query met moving agents");
            Assert.That(stamina.TryGet(agents[0], out float left) && left < 1f, Is.True, $"stamina {left}");
        }
    }

    private static AgentHandle[] Handles(AgentQueryResult result)
    {
        var handles = new List<AgentHandle>();
        foreach (AgentHandle agent in result)
        {
            handles.Add(agent);
        }

        return [.. handles];
    }

    /// <summary>Notes its name when run; watching one agent, what the world shows of it then.</summary>
    private sealed class Probe(string name, List<string> order, AgentHandle watched = default) : IJumpSystem
    {
        public TickContext Tick { get; private set; }

        public RootPose Root { get; private set; }

        public Quaternion[] Rotations { get; private set; } = [];

        public void Update(in TickContext tick, JumpWorld world)
        {
            order.Add(name);
            Tick = tick;
            if (watched.IsAssigned)
            {
                Root = world.GetRootPose(watched);
                Rotations = world.GetJointRotations(watched).ToArray();
            }
        }
    }

    /// <summary>Does whatever it is given to the world, each tick.</summary>
    private sealed class Meddler(Action<JumpWorld> action) : IJumpSystem
    {
        public void Update(in TickContext tick, JumpWorld world) => action(world);
    }

    /// <summary>Tires every moving agent that has stamina (jumping twice as fast as walking), through a query and the spans of the component and the states.</summary>
    private sealed class Tire(ComponentColumn<float> stamina) : IJumpSystem
    {
        private readonly AgentQuery _moving = new AgentQuery().InStates(AgentStates.Walking | AgentStates.Jumping).With(stamina);

        public int Moving { get; private set; }

        public void Update(in TickContext tick, JumpWorld world)
        {
            Span<float> left = stamina.Values;
            ReadOnlySpan<AgentState> states = world.States;
            foreach (AgentHandle agent in world.Query(_moving))
            {
                left[agent.Index] -= (states[agent.Index] == AgentState.Walking ? 0.1f : 0.2f) * (float)tick.DeltaSeconds;
                Moving++;
            }
        }
    }
}
