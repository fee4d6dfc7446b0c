using System.Collections.Concurrent;
using System.Numerics;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Hosting;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>
/// A world belongs to one thread; game code on others (jobs, <c>async</c> continuations) breaches that easily. A
/// racing call is refused with <see cref="RuntimeStatus.Busy"/> and never corrupts the world.
/// </summary>
public sealed class ThreadMisuseTests
{
    [Test]
    public void CallsFromEightThreadsWhileANinthStepsAreRefusedOrDoneAndNeverBreakTheWorld()
    {
        (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert();
        using (world)
        {
            Roadmap roadmap = RuntimeWorlds.DesertSkeleton.Roadmap;
            AgentHandle[] agents = [.. Enumerable.Range(0, 16).Select(i => world.AddAgent(kind, RuntimeWorlds.Point(roadmap.Nodes[i * 7])).Agent)];
            (ConcurrentDictionary<RuntimeStatus, int> statuses, ConcurrentQueue<Exception> thrown) = Race(seed: 100, world.Step, random =>
            {
                AgentHandle agent = agents[random.Next(agents.Length)];
                Vector3 point = RuntimeWorlds.Point(roadmap.Nodes[random.Next(roadmap.Nodes.Count)]);
                _ = world.GetRootPose(agent); // reads race the tick too, harmlessly
                return random.Next(5) switch
                {
                    0 => world.Warp(agent, point),
                    1 => world.ClearTarget(agent),
                    2 => world.SetPoseEnabled(agent, random.Next(2) == 0),
                    3 => world.AddAgent(kind, point) is { Ok: true } added ? Remove(world, added.Agent) : RuntimeResult.Success,
                    _ => random.Next(20) == 0 ? world.SetTarget(agent, point) : world.ClearTarget(agent),
                };
            });

            Assert.That(thrown, Is.Empty, string.Join("; ", thrown.Take(3).Select(e => $"{e.GetType().Name}: {e.Message}")));
            Assert.That(statuses.GetValueOrDefault(RuntimeStatus.Busy), Is.Positive, "calls met the ticks and were refused");
            Assert.That(statuses.GetValueOrDefault(RuntimeStatus.Ok), Is.Positive, "calls between the ticks were done");
            Assert.That(statuses.Keys, Is.SubsetOf(new[] { RuntimeStatus.Ok, RuntimeStatus.Busy, RuntimeStatus.InvalidPosition }), "no other failure");

            // Whole: every agent is where the world says, and the world still plans, moves and arrives.
            Span<AgentHandle> live = new AgentHandle[world.AgentCount + 1];
            Assert.That(world.CopyAgents(live), Is.EqualTo(agents.Length), "the spawned-and-removed agents are gone, the others all there");
            Assert.That(agents.All(world.IsValid), Is.True);
            (RoadmapNode from, RoadmapNode to) = RuntimeWorlds.ConnectedPairs(roadmap, 1, seed: 61)[0];
            Assert.That(world.Warp(agents[0], RuntimeWorlds.Point(from)).Ok, Is.True);
            Assert.That(world.SetTarget(agents[0], RuntimeWorlds.Point(to)).Ok, Is.True);
            var events = RuntimeWorlds.Run(world, 3600, (w, seen) => seen.Any(e => e.Agent == agents[0] && e.Kind is JumpEventKind.TargetReached or JumpEventKind.PathFailed));
            Assert.That(events.Last(e => e.Agent == agents[0]).Kind, Is.EqualTo(JumpEventKind.TargetReached));
        }
    }

    [Test]
    public void CallsToAServerWorldsAgentsFromEightThreadsWhileANinthStepsItAreRefusedOrDoneAndNeverBreakIt()
    {
        (JumpWorld host, KindHandle region) = HostingWorlds.DesertServer();
        using (host)
        {
            Roadmap roadmap = RuntimeWorlds.DesertSkeleton.Roadmap;
            AgentHandle[] agents = [.. Enumerable.Range(0, 16).Select(i => host.AddAgent(region, RuntimeWorlds.Point(roadmap.Nodes[i * 7])).Agent)];
            (ConcurrentDictionary<RuntimeStatus, int> statuses, ConcurrentQueue<Exception> thrown) = Race(seed: 200, host.Step, random =>
            {
                AgentHandle agent = agents[random.Next(agents.Length)];
                Vector3 point = RuntimeWorlds.Point(roadmap.Nodes[random.Next(roadmap.Nodes.Count)]);
                return random.Next(5) switch
                {
                    0 => host.Warp(agent, point),
                    1 => host.ClearTarget(agent),
                    2 => host.AddAgent(region, point) is { Agent.IsAssigned: true } added ? Unregister(host, added.Agent) : RuntimeResult.Success,
                    3 => Read(host, agent, point),
                    _ => random.Next(20) == 0 ? host.SetTarget(agent, point) : host.ClearTarget(agent),
                };
            });

            Assert.That(thrown, Is.Empty, string.Join("; ", thrown.Take(3).Select(e => $"{e.GetType().Name}: {e.Message}")));
            Assert.That(statuses.GetValueOrDefault(RuntimeStatus.Busy), Is.Positive, "calls met the ticks and were refused");
            Assert.That(statuses.Keys, Is.SubsetOf(new[] { RuntimeStatus.Ok, RuntimeStatus.Busy, RuntimeStatus.InvalidPosition }), "no other failure");
            Assert.That(host.AgentCount, Is.EqualTo(agents.Length), "the registered-and-unregistered agents are gone, the others all there");
            Assert.That(agents.All(a => host.GetLifecycle(a) == AgentLifecycle.Active), Is.True);
            Assert.That(host.Query(new AgentQuery()).Count(), Is.EqualTo(agents.Length), "and the simulation holds exactly them");
        }
    }

    /// <summary>
    /// Eight threads make calls (<paramref name="call"/>, each with its own seeded random) while this one steps, once
    /// all of them are calling, 240 ticks and on until calls have both met a tick and fallen between ticks (30 s at
    /// most); returns how often each status came back and every exception thrown, on either side.
    /// </summary>
    private static (ConcurrentDictionary<RuntimeStatus, int> Statuses, ConcurrentQueue<Exception> Thrown) Race(int seed, Action step, Func<Random, RuntimeResult> call)
    {
        var statuses = new ConcurrentDictionary<RuntimeStatus, int>();
        var thrown = new ConcurrentQueue<Exception>();
        int stop = 0;
        using var calling = new CountdownEvent(8);
        Thread[] threads = [.. Enumerable.Range(0, 8).Select(t => new Thread(() =>
        {
            var random = new Random(seed + t);
            bool first = true;
            while (Volatile.Read(ref stop) == 0)
            {
                try
                {
                    statuses.AddOrUpdate(call(random).Status, 1, (_, n) => n + 1);
                }
                catch (Exception e)
                {
                    thrown.Enqueue(e);
                }

                if (first)
                {
                    first = false;
                    calling.Signal();
                }
            }
        }))];
        foreach (Thread thread in threads)
        {
            thread.Start();
        }

        try
        {
            // Ticks once every thread is calling, 240 of them and on until calls have both met a tick and fallen
            // between ticks (30 s at most): on two cores the threads may be scheduled only after 240 quick ticks
            // (a clean clone's CI run saw no call refused), so whether they met is left to the scheduler no longer.
            calling.Wait(TimeSpan.FromSeconds(30));
            var clock = System.Diagnostics.Stopwatch.StartNew();
            for (int tick = 0; tick < 240 || (!Met(statuses) && clock.Elapsed < TimeSpan.FromSeconds(30)); tick++)
            {
                step();
            }
        }
        catch (Exception e)
        {
            thrown.Enqueue(e);
        }
        finally
        {
            Volatile.Write(ref stop, 1);
            foreach (Thread thread in threads)
            {
                thread.Join();
            }
        }

        return (statuses, thrown);
    }

    /// <summary>True once calls have been refused for meeting a tick and done between ticks.</summary>
    private static bool Met(ConcurrentDictionary<RuntimeStatus, int> statuses) =>
        statuses.GetValueOrDefault(RuntimeStatus.Busy) > 0 && statuses.GetValueOrDefault(RuntimeStatus.Ok) > 0;

    /// <summary>Removes <paramref name="agent"/>, asking again while the world's thread is busy (a refused call did nothing).</summary>
    private static RuntimeResult Remove(JumpWorld world, AgentHandle agent)
    {
        RuntimeResult result;
        while ((result = world.RemoveAgent(agent)).Status == RuntimeStatus.Busy)
        {
            Thread.Yield();
        }

        return result;
    }

    /// <summary>Reads the agent's events and asks about reachability: calls that wait for the world's thread rather than being refused.</summary>
    private static RuntimeResult Read(JumpWorld host, AgentHandle agent, Vector3 point)
    {
        _ = host.EventsOf(agent).Length;
        host.IsTargetReachable(agent, point);
        return RuntimeResult.Success;
    }

    /// <summary>Removes <paramref name="agent"/>, asking again while the world's thread is busy.</summary>
    private static RuntimeResult Unregister(JumpWorld host, AgentHandle agent)
    {
        RuntimeResult result;
        while ((result = host.RemoveAgent(agent)).Status == RuntimeStatus.Busy)
        {
            Thread.Yield();
        }

        return result;
    }
}
