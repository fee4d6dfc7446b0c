using System.Numerics;

namespace Ballistic.Authoring.Playtest;

/// <summary>What one agent did during a playtest.</summary>
/// <param name="Index">Index of the agent, from zero.</param>
/// <param name="Spawn">Trunk centre where it spawned, world metres.</param>
public sealed record PlaytestAgent(int Index, Vector3 Spawn)
{
    /// <summary>The targets it was sent to, in order (the last may still be under way when the playtest ends).</summary>
    public List<PlaytestTarget> Targets { get; } = [];

    /// <summary>The jumps it took off for, in order.</summary>
    public List<ExecutedJump> Jumps { get; } = [];

    /// <summary>The walks it started, in order.</summary>
    public List<ExecutedWalk> Walks { get; } = [];
}
