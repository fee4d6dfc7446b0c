using System.Diagnostics;
using System.Numerics;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;
using Ballistic.Runtime.Paths;

namespace Ballistic.Authoring.Playtest;

/// <summary>
/// A headless playtest over the runtime: agents spawn on random roadmap stances, are sent to random stances, and
/// navigate (jumping and walking) with the runtime's systems at a fixed tick rate; each arrival or failure sends the agent to a new target.
/// Deterministic for a seed, whatever the thread count.
/// </summary>
public static class PlaytestRunner
{
    /// <summary>Runs a playtest of <paramref name="kind"/>.</summary>
    /// <param name="kind">The character kind: scene, roadmap (at least one node) and animator.</param>
    /// <param name="settings">Agents, duration, seed.</param>
    /// <param name="progress">Receives the share of simulated time done, 0–1.</param>
    /// <param name="cancellationToken">Stops the run early; the result then says so.</param>
    /// <exception cref="ArgumentException">A setting is invalid, or the roadmap has no node.</exception>
    public static PlaytestResult Run(CharacterKind kind, PlaytestSettings settings, IProgress<double>? progress = null, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(kind);
        ArgumentNullException.ThrowIfNull(settings);
        if (settings.Problem() is { } problem)
        {
            throw new ArgumentException(problem, nameof(settings));
        }

        Roadmap roadmap = kind.Roadmap;
        if (roadmap.Nodes.Count == 0)
        {
            throw new ArgumentException($"The roadmap of '{kind.Name}' has no node: bake it first.", nameof(kind));
        }

        var clock = Stopwatch.StartNew();
        var random = new Random(settings.Seed);
        using var world = new JumpWorld(kind.Scene.Level, new WorldSettings
        {
            TickRate = settings.TickRate,
            AnimationThreads = settings.AnimationThreads,
            // Offline by default: the same at any thread count and machine speed. In real time, as the Godot server's world.
            MaxAnimationWait = settings.RealTime ? WorldSettings.RealTimeAnimationWait : null,
            Locomotion = settings.Locomotion,
            JumpEffort = settings.JumpEffort,
            JumpHeightEffort = settings.JumpHeightEffort,
        });
        KindHandle handle = world.AddKind(kind).Kind;

        // Spawn on random stances the whole body can stand on.
        var agents = new List<PlaytestAgent>();
        var handles = new List<AgentHandle>();
        var indexOf = new Dictionary<AgentHandle, int>();
        for (int attempt = 0; agents.Count < settings.Agents && attempt < settings.Agents * 20; attempt++)
        {
            RoadmapNode node = roadmap.Nodes[random.Next(roadmap.Nodes.Count)];
            AddAgentResult added = world.AddAgent(handle, roadmap.ContactCentres[node.Id]);
            if (added.Ok)
            {
                indexOf[added.Agent] = agents.Count;
                agents.Add(new PlaytestAgent(agents.Count, world.GetRootPose(added.Agent).Position));
                handles.Add(added.Agent);
            }
        }

        foreach (AgentHandle agent in handles)
        {
            SendSomewhere(world, agent, agents[indexOf[agent]], roadmap, random);
        }

        long ticks = (long)Math.Ceiling(settings.Seconds * settings.TickRate);
        var paths = new Dictionary<AgentHandle, AgentPath>();
        bool cancelled = false;
        long reportEvery = Math.Max(1, ticks / 200);
        var tickMilliseconds = new List<double>((int)Math.Min(ticks, 1_000_000));
        long allocated = 0;
        TimeSpan cpuStart = Process.GetCurrentProcess().TotalProcessorTime;
        long firstTick = Stopwatch.GetTimestamp();
        for (long tick = 0; tick < ticks; tick++)
        {
            if (cancellationToken.IsCancellationRequested)
            {
                cancelled = true;
                break;
            }

            if (settings.RealTime)
            {
                // The tick's moment on the wall clock, as a game's fixed-rate loop waits for it.
                TimeSpan due = TimeSpan.FromSeconds(tick / (double)settings.TickRate) - Stopwatch.GetElapsedTime(firstTick);
                if (due > TimeSpan.Zero)
                {
                    Thread.Sleep(due);
                }
            }

            long allocatedBefore = GC.GetAllocatedBytesForCurrentThread();
            long started = Stopwatch.GetTimestamp();
            world.Step();
            tickMilliseconds.Add(Stopwatch.GetElapsedTime(started).TotalMilliseconds);
            allocated += GC.GetAllocatedBytesForCurrentThread() - allocatedBefore;
            List<AgentHandle>? resend = null;
            foreach (JumpEvent e in world.Events)
            {
                if (!indexOf.TryGetValue(e.Agent, out int index))
                {
                    continue;
                }

                PlaytestAgent agent = agents[index];
                PlaytestTarget target = agent.Targets[^1];
                switch (e.Kind)
                {
                    case JumpEventKind.PathFound:
                        paths[e.Agent] = world.GetPath(e.Agent)!;
                        break;
                    case JumpEventKind.JumpStarted:
                        PathMove move = paths[e.Agent].Moves[e.Jump];
                        agent.Jumps.Add(new ExecutedJump(index, e.Time, new Jump(move.From, move.To, move.Arc)));
                        break;
                    case JumpEventKind.WalkStarted:
                        agent.Walks.Add(new ExecutedWalk(index, e.Time, paths[e.Agent].Moves[e.Jump].Walk!));
                        break;
                    case JumpEventKind.TargetReached:
                        target.ReachedAt = e.Time;
                        (resend ??= []).Add(e.Agent);
                        break;
                    case JumpEventKind.PathFailed:
                        target.FailureStatus = e.Status;
                        target.FailureReason = e.Reason;
                        target.FailedAt = e.Time;
                        (resend ??= []).Add(e.Agent);
                        break;
                }
            }

            if (resend is not null)
            {
                foreach (AgentHandle agent in resend)
                {
                    SendSomewhere(world, agent, agents[indexOf[agent]], roadmap, random);
                }
            }

            if (tick % reportEvery == 0 || tick == ticks - 1)
            {
                progress?.Report((double)(tick + 1) / ticks);
            }
        }

        PlaytestTickTimes? tickTimes = PlaytestTickTimes.From(tickMilliseconds, Process.GetCurrentProcess().TotalProcessorTime - cpuStart, allocated);

        // Connectivity of the roadmap itself: random node pairs joined by a sequence of moves (jumps, and walks unless jumps only).
        var pairs = new Random(settings.Seed ^ 0x5eed);
        int connected = 0;
        for (int i = 0; i < settings.ReachabilityPairs; i++)
        {
            int from = pairs.Next(roadmap.Nodes.Count);
            int to = pairs.Next(roadmap.Nodes.Count);
            connected += (settings.Locomotion == Locomotion.Jump ? roadmap.Reaches(from, to) : roadmap.ReachesWalking(from, to)) ? 1 : 0;
        }

        return new PlaytestResult(settings, kind, agents, world.Tick, clock.Elapsed.TotalSeconds, settings.ReachabilityPairs, connected, cancelled) { TickTimes = tickTimes, LateRequests = world.LateRequests };
    }

    private static void SendSomewhere(JumpWorld world, AgentHandle handle, PlaytestAgent agent, Roadmap roadmap, Random random)
    {
        // Another stance than the one it stands on.
        Vector3 here = world.GetRootPose(handle).Position;
        RoadmapNode node = roadmap.Nodes[random.Next(roadmap.Nodes.Count)];
        for (int attempt = 0; attempt < 8 && Vector3.Distance(node.Pose.Position, here) < 1f; attempt++)
        {
            node = roadmap.Nodes[random.Next(roadmap.Nodes.Count)];
        }

        Vector3 target = roadmap.ContactCentres[node.Id];
        agent.Targets.Add(new PlaytestTarget(target, here, world.Time));
        world.SetTarget(handle, target);
    }
}
