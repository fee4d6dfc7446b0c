using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Hosting;
using Ballistic.Planner.Tests.Support;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;
using Ballistic.Runtime.Paths;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>
/// A kind rebaked under live agents (<see cref="JumpWorld.ReplaceKind"/>): every agent keeps its handle, none is moved
/// by the swap, an agent in a move finishes it and carries on from where it ends.
/// </summary>
public sealed class RebakeTests
{
    [Test]
    public void ElevenRebakesUnderEightMovingAgentsMoveNoneFasterThanItsOwnMotion()
    {
        CharacterKind[] kinds = [RuntimeWorlds.DesertSkeleton, HostingWorlds.DesertRebaked];
        using var world = new JumpWorld(kinds[0].Scene.Level, RuntimeWorlds.JumpOnly);
        KindHandle kind = world.AddKind(kinds[0]).Kind;
        var agents = new List<AgentHandle>();
        foreach ((RoadmapNode from, RoadmapNode to) in RuntimeWorlds.ConnectedPairs(kinds[0].Roadmap, 8, seed: 77, minDistance: 6f))
        {
            AgentHandle agent = world.AddAgent(kind, RuntimeWorlds.Point(from)).Agent;
            Assert.That(world.SetTarget(agent, RuntimeWorlds.Point(to)).Ok, Is.True);
            agents.Add(agent);
        }

        Vector3[] last = [.. agents.Select(a => world.GetRootPose(a).Position)];
        float[] fastest = new float[agents.Count];
        float[] worst = new float[agents.Count];
        var events = new List<JumpEvent>();
        int swaps = 0;
        int finishing = 0;
        for (int tick = 1; tick <= 60 * 60 && !agents.All(a => events.Any(e => e.Agent == a && e.Kind is JumpEventKind.TargetReached or JumpEventKind.PathFailed)); tick++)
        {
            if (tick % 41 == 0 && swaps < 11)
            {
                RootPose[] before = [.. agents.Select(world.GetRootPose)];
                finishing += agents.Count(a => world.GetPath(a) is not null);
                RuntimeResult swapped = world.ReplaceKind(kind, kinds[++swaps % 2]);
                Assert.That(swapped.Ok, Is.True, swapped.ToString());
                Assert.That(swapped.Reason, Does.Contain("0 agents unplaced"));
                Assert.That(agents.All(world.IsValid), Is.True, "every agent keeps its handle");
                Assert.That(agents.Select(world.GetRootPose), Is.EqualTo(before), "the swap moves nobody");
            }

            world.Step();
            events.AddRange(world.Events.ToArray());
            for (int i = 0; i < agents.Count; i++)
            {
                if (world.GetPath(agents[i]) is { } path)
                {
                    fastest[i] = MathF.Max(fastest[i], Fastest(path));
                }

                Vector3 root = world.GetRootPose(agents[i]).Position;
                worst[i] = MathF.Max(worst[i], Vector3.Distance(root, last[i]));
                last[i] = root;
            }
        }

        Assert.That(swaps, Is.EqualTo(11));
        Assert.That(finishing, Is.Positive, "some swaps came while agents were in a move");
        Assert.That(events.Select(e => e.Kind), Does.Not.Contain(JumpEventKind.Removed), "a rebake is not a removal");
        float tickSeconds = (float)world.Settings.TickSeconds;
        TestContext.Out.WriteLine($"{finishing} agents in a move at a swap; most moved in one tick: {worst.Max():0.000} m (moves up to {fastest.Max():0.00} m/s, {fastest.Max() * tickSeconds:0.000} m a tick)");
        for (int i = 0; i < agents.Count; i++)
        {
            // The body moves along its arcs (and crouches and stands up in its stances: a few centimetres a tick).
            Assert.That(worst[i], Is.LessThanOrEqualTo((fastest[i] * tickSeconds) + 0.05f), $"agent {i} moved {worst[i]:0.000} m in one tick; its moves go at most {fastest[i]:0.00} m/s");
        }

        Assert.That(agents.Count(a => events.Any(e => e.Agent == a && e.Kind == JumpEventKind.TargetReached)), Is.GreaterThanOrEqualTo(agents.Count / 2), "and they still get where they were sent");
    }

    [Test]
    public void AWalkerRebakedMidWalkFinishesTheWalkAndCarriesOnFromItsEnd()
    {
        (JumpWorld world, KindHandle kind) = WalkingPaths.World();
        using (world)
        {
            AgentHandle agent = WalkingPaths.SetOff(world, kind, 1)[0];
            RuntimeWorlds.Run(world, 600, (w, _) => w.GetState(agent) == AgentState.Walking);
            Assume.That(world.GetState(agent), Is.EqualTo(AgentState.Walking));
            AgentPath walking = world.GetPath(agent)!;
            RoadmapNode walkEnd = walking.Moves[0].To;
            Vector3? target = world.GetTarget(agent);
            RootPose before = world.GetRootPose(agent);

            RuntimeResult swapped = world.ReplaceKind(kind, HostingWorlds.DesertRebaked);
            Assert.That(swapped.Reason, Does.Contain("1 agent finishing a move first"));
            Assert.That(world.GetRootPose(agent), Is.EqualTo(before));
            Vector3 last = before.Position;
            float worst = 0f;
            List<JumpEvent> events = RuntimeWorlds.Run(world, 600, (w, _) => w.GetPath(agent) is null, w =>
            {
                worst = MathF.Max(worst, Vector3.Distance(w.GetRootPose(agent).Position, last));
                last = w.GetRootPose(agent).Position;
            });
            Assert.That(events.Select(e => e.Kind), Is.EqualTo(new[] { JumpEventKind.WalkFinished }), "the walk ends; the jump after it is not taken");
            Assert.That(world.GetStance(agent)!.Pose, Is.EqualTo(walkEnd.Pose), "it stands where the walk ends");
            Assert.That(worst, Is.LessThanOrEqualTo((WalkingPaths.FirstSpeed * 1.5f * (float)world.Settings.TickSeconds) + 0.05f), "walking, not teleported");

            Assert.That(world.GetTarget(agent), Is.EqualTo(target), "its target is kept");
            Assert.That(world.IsPathPending(agent), Is.True, "and asked again from where the walk ended");

            // Sent on across the jump it did not take: planned anew, from where it stands, on the new roadmap.
            Assert.That(world.SetTarget(agent, walking.Moves[1].To.ContactCentre).Ok, Is.True);
            events = RuntimeWorlds.Run(world, 3600, RuntimeWorlds.Concluded);
            JumpEvent found = events.First(e => e.Kind is JumpEventKind.PathFound or JumpEventKind.PathFailed);
            Assert.That(found.Kind, Is.EqualTo(JumpEventKind.PathFound), found.Reason);
            Assert.That(events[^1].Kind, Is.EqualTo(JumpEventKind.TargetReached), string.Join("; ", events.Select(e => $"{e.Kind} {e.Reason}")));
        }
    }

    [Test]
    public void ARebakeForAnotherCharacterStandsEachAgentAsTheNewBodyOrUnplacesItSayingWhy()
    {
        (CharacterKind frog, CharacterKind skeleton) = Table.Value;
        using var world = new JumpWorld(frog.Scene.Level, RuntimeWorlds.JumpOnly);
        KindHandle kind = world.AddKind(frog).Kind;
        AddAgentResult open = world.AddAgent(kind, new Vector3(-3f, 0f, 0f));
        AddAgentResult under = world.AddAgent(kind, new Vector3(3.5f, 0f, 0f));
        Assert.That(open.Ok && under.Ok, Is.True, $"{open.Result}; {under.Result}");
        Vector3 openAt = world.GetStance(open.Agent)!.ContactCentre;

        RuntimeResult swapped = world.ReplaceKind(kind, skeleton);
        Assert.That(swapped.Ok, Is.True, swapped.ToString());
        Assert.That(swapped.Reason, Does.StartWith("kind 'skeleton' replaced: 1 agent put on its new roadmap, 0 agents finishing a move first, 1 agent unplaced ("));
        Assert.That(world.IsValid(open.Agent), Is.True, "the agent in the open stays, now a skeleton");
        RoadmapNode stance = world.GetStance(open.Agent)!;
        Assert.That(HostingWorlds.WithinTolerance(stance.ContactCentre, openAt), Is.True, "where it stood");
        Assert.That(world.GetJointAngles(open.Agent).ToArray(), Is.EqualTo(skeleton.Animator.Contacts.Generate(stance.Pose, stance.Contacts, stance.Cone.Axis).Angles).Within(1e-5f), "in the skeleton's pose on its stance");
        Assert.That(world.GetLifecycle(under.Agent), Is.EqualTo(AgentLifecycle.Unplaced), "the agent under the table leaves the simulation");
        Assert.That(world.IsValid(under.Agent), Is.True, "under its handle");
        Assert.That(world.Query(new AgentQuery()).Count(), Is.EqualTo(1), "only the agent in the open is simulated");

        List<JumpEvent> events = RuntimeWorlds.Run(world, 2);
        Assert.That(world.GetJointRotations(open.Agent).Length, Is.EqualTo(skeleton.JointCount), "pose buffers sized for the skeleton");
        Assert.That(world.GetJointRotations(open.Agent).ToArray().All(q => MathF.Abs(q.Length() - 1f) < 1e-3f), Is.True, "and filled");
        JumpEvent removed = events.Single();
        Assert.That((removed.Kind, removed.Agent), Is.EqualTo((JumpEventKind.Removed, under.Agent)));
        Assert.That(removed.Reason, Does.Contain("another character").And.Contain("cannot stand"));
    }

    [Test]
    public void AnAgentTheNewBodyCannotStandAsWaitsUnplacedWithTheReasonUnderItsHandle()
    {
        (CharacterKind frog, CharacterKind skeleton) = Table.Value;
        using var host = new JumpWorld(new WorldSettings { AnimationThreads = 0 });
        KindHandle region = host.CreateKind("table");
        Assert.That(host.ReplaceKind(region, frog).Ok, Is.True);
        AgentHandle open = host.AddAgent(region, new Vector3(-3f, 0f, 0f)).Agent;
        AgentHandle under = host.AddAgent(region, new Vector3(3.5f, 0f, 0f)).Agent;
        AgentHandle going = host.AddAgent(region, new Vector3(-1f, 0f, -2f)).Agent;
        Assert.That(host.SetTarget(going, new Vector3(4f, 0f, -2f)).Ok, Is.True);
        var goingEvents = new List<JumpEvent>();
        for (int i = 0; i < 1200 && !InLastMove(host, going); i++)
        {
            host.Step();
            goingEvents.AddRange(host.EventsOf(going).ToArray());
        }

        Assume.That(InLastMove(host, going), Is.True, string.Join("; ", goingEvents.Select(e => $"{e.Kind} {e.Reason}")));

        RuntimeResult rebaked = host.ReplaceKind(region, skeleton);
        Assert.That(rebaked.Ok, Is.True, rebaked.ToString());
        Assert.That(rebaked.Reason, Does.Contain("1 agent put on its new roadmap, 1 agent finishing a move first, 1 agent unplaced"));
        Assert.That(host.GetLifecycle(open), Is.EqualTo(AgentLifecycle.Active));
        Assert.That(host.GetLifecycle(under), Is.EqualTo(AgentLifecycle.Unplaced));
        Assert.That(host.IsValid(under), Is.True, "the same handle, out of the simulation");
        Assert.That(host.GetAgentReason(under), Does.Contain("another character"));
        Assert.That(host.GetStandingPoint(under)!.Value.X, Is.EqualTo(3.5f).Within(0.5f), "remembered where it stood");

        var events = new List<JumpEvent>();
        var openEvents = new List<JumpEvent>();
        for (int i = 0; i < 3; i++)
        {
            host.Step();
            events.AddRange(host.EventsOf(under).ToArray());
            openEvents.AddRange(host.EventsOf(open).ToArray());
        }

        Assert.That(events.Select(e => e.Kind), Is.EqualTo(new[] { JumpEventKind.Removed }), "told once");
        Assert.That(openEvents, Is.Empty, "the other agent is told nothing");

        // The frog on its way under the table finishes its last move as a frog, then cannot stand there as a skeleton.
        Assert.That(host.GetLifecycle(going), Is.EqualTo(AgentLifecycle.Active), "in a move: it finishes it first");
        for (int i = 0; i < 600 && host.GetLifecycle(going) == AgentLifecycle.Active; i++)
        {
            host.Step();
            goingEvents.AddRange(host.EventsOf(going).ToArray());
        }

        Assert.That(host.GetLifecycle(going), Is.EqualTo(AgentLifecycle.Unplaced), string.Join("; ", goingEvents.Select(e => $"{e.Kind} {e.Reason}")));
        Assert.That(goingEvents[^1].Kind, Is.EqualTo(JumpEventKind.Removed));
        Assert.That(host.GetAgentReason(going), Does.Contain("another character"));
        Assert.That(host.GetStandingPoint(going)!.Value.X, Is.GreaterThan(1f), "it waits where its move ended, under the table");
        Assert.That(host.GetTarget(going), Is.Not.Null, "its target is kept");

        // Warped into the open, the skeleton stands there and joins the world.
        Assert.That(host.Warp(under, new Vector3(-1f, 0f, 2f)).Ok, Is.True);
        Assert.That(host.GetLifecycle(under), Is.EqualTo(AgentLifecycle.Active));
    }

    /// <summary>True while <paramref name="agent"/> is in the last move of its path (a jump or a walk).</summary>
    private static bool InLastMove(JumpWorld world, AgentHandle agent) =>
        world.GetPath(agent) is { } path && world.GetMoveIndex(agent) == path.Count - 1 && world.GetState(agent) is not (AgentState.Stance or AgentState.Idle);

    /// <summary>
    /// A floor, and a table whose top leaves 1 m beneath it: a frog stands under it, a person cannot; the frog and
    /// skeleton kinds on it.
    /// </summary>
    private static readonly Lazy<(CharacterKind Frog, CharacterKind Skeleton)> Table = new(() =>
    {
        Level level = new LevelBuilder("table").AddBox(new Vector3(-6f, -0.2f, -4f), new Vector3(6f, 0f, 4f)).AddBox(new Vector3(1f, 1.0f, -4f), new Vector3(6f, 1.1f, 4f)).Build();
        return (Kind(level, CharacterPresets.Frog(), "frog"), Kind(level, CharacterPresets.Skeleton(), "skeleton"));
    });

    /// <summary>A kind of <paramref name="character"/> on <paramref name="level"/>, with a small roadmap.</summary>
    private static CharacterKind Kind(Level level, ReducedCharacter character, string model)
    {
        var scene = PlanningScene.Create(level, character);
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 1, MaxNodes = 80, Threads = 2 }).Roadmap;
        return new CharacterKind(scene, roadmap, new JumpAnimator(scene, CharacterPresets.Model(model)));
    }

    /// <summary>The fastest the trunk goes on <paramref name="path"/>: its arcs at takeoff or landing, its walks at their speed, m/s.</summary>
    private static float Fastest(AgentPath path) => path.Moves.Max(m => m.Walk is { } walk
        ? walk.Speed
        : MathF.Max(m.Arc.TakeoffVelocity.Length(), (m.Arc.TakeoffVelocity - (9.81f * m.Arc.FlightTime * Vector3.UnitY)).Length()));
}
