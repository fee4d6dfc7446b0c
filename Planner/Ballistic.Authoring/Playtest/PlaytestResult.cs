using System.Numerics;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Authoring.Playtest;

/// <summary>The outcome of a playtest: every agent's targets, jumps and walks, and the roadmap's connectivity.</summary>
/// <param name="Settings">The settings run.</param>
/// <param name="Kind">The character kind (its scene, roadmap and animator).</param>
/// <param name="Agents">Every agent, in spawn order.</param>
/// <param name="Ticks">Ticks stepped.</param>
/// <param name="WallSeconds">Wall-clock seconds the run took.</param>
/// <param name="PairsSampled">Random roadmap node pairs sampled.</param>
/// <param name="PairsConnected">How many of them are connected by a sequence of moves: jumps, and walks unless the settings are jumps only.</param>
/// <param name="Cancelled">True when the run was stopped before its end.</param>
public sealed record PlaytestResult(PlaytestSettings Settings, CharacterKind Kind, IReadOnlyList<PlaytestAgent> Agents, long Ticks, double WallSeconds, int PairsSampled, int PairsConnected, bool Cancelled)
{
    /// <summary>Targets that ended (reached or failed).</summary>
    public int TargetsConcluded => Agents.Sum(a => a.Targets.Count(t => t.Reached || t.Failed));

    /// <summary>Targets reached.</summary>
    public int TargetsReached => Agents.Sum(a => a.Targets.Count(t => t.Reached));

    /// <summary>Targets whose path failed.</summary>
    public int TargetsFailed => Agents.Sum(a => a.Targets.Count(t => t.Failed));

    /// <summary>Jumps taken by all agents.</summary>
    public int JumpsTaken => Agents.Sum(a => a.Jumps.Count);

    /// <summary>Walks started by all agents.</summary>
    public int WalksTaken => Agents.Sum(a => a.Walks.Count);

    /// <summary>Length of the ground paths of all walks started, metres.</summary>
    public double WalkedMetres => Agents.Sum(a => a.Walks.Sum(w => (double)w.Walk.Length));

    /// <summary>What the ticks cost on this machine (<see cref="PlaytestTickTimes"/>); <c>null</c> when no tick ran.</summary>
    public PlaytestTickTimes? TickTimes { get; init; }

    /// <summary>Requests a tick stopped waiting for (<see cref="Runtime.JumpWorld.LateRequests"/>): delivered after their due tick, in a real-time run (<see cref="PlaytestSettings.RealTime"/>) on a machine too slow for the crowd; always 0 offline.</summary>
    public long LateRequests { get; init; }

    /// <summary>
    /// Agents stuck where they stand: those that reached no target and failed at least <see cref="StuckFailures"/>,
    /// every one asked from the same point (within a centimetre): a stance the level lets the character stand on but
    /// not leave (no takeoff from it animates, say), which a designer wants to know of before a player finds it. Each
    /// failed request there costs a whole search and its repairs, over and over (the desert's 100-agent playtest spent
    /// most of its time on one such agent, 256 failures).
    /// </summary>
    public IReadOnlyList<PlaytestAgent> Stuck => [.. Agents.Where(a =>
        !a.Targets.Any(t => t.Reached)
        && a.Targets.Count(t => t.Failed) >= StuckFailures
        && a.Targets.Where(t => t.Failed).All(t => Vector3.Distance(t.From, a.Targets[0].From) <= 0.01f))];

    /// <summary>Failed targets, none reached, from which an agent counts as <see cref="Stuck"/>.</summary>
    public const int StuckFailures = 3;

    /// <summary>Seconds from setting each reached target to arriving, in increasing order.</summary>
    public IReadOnlyList<double> TimesToReach => [.. Agents.SelectMany(a => a.Targets).Where(t => t.Reached).Select(t => t.ReachedAt!.Value - t.SetAt).Order()];
}
