using System.Numerics;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;

namespace Ballistic.Runtime;

/// <summary>
/// Changes to a <see cref="JumpWorld"/>'s agents recorded now and played back, in the order recorded, at the start of
/// the world's next tick (<see cref="JumpWorld.Commands"/>), like a DOTS <c>EntityCommandBuffer</c>: for systems that
/// change agents while others iterate them, and for code on other threads (jobs, <c>async</c> continuations), which
/// must never call the world directly. Recording is thread-safe and never fails; each command is then played as the
/// world's method of the same name, and a refused one (an agent removed meanwhile, a point nobody stands on) comes out
/// as a <see cref="Events.JumpEventKind.CommandRefused"/> event of that tick with the reason. Played from one thread,
/// commands keep the world deterministic; from several, their order is the order the threads recorded them in.
/// </summary>
public sealed class JumpCommandBuffer
{
    private readonly object _lock = new();
    private List<Command> _recorded = [];
    private List<Command> _playing = [];

    internal JumpCommandBuffer()
    {
    }

    private enum Op
    {
        SetTarget,
        ClearTarget,
        Warp,
        Remove,
        SetPoseEnabled,
    }

    /// <summary>Commands recorded and not played yet.</summary>
    public int Count
    {
        get
        {
            lock (_lock)
            {
                return _recorded.Count;
            }
        }
    }

    /// <summary>Records <see cref="JumpWorld.SetTarget"/>: send the agent toward <paramref name="target"/> (world metres).</summary>
    public void SetTarget(AgentHandle agent, Vector3 target) => Record(new Command(Op.SetTarget, agent, target, false));

    /// <summary>Records <see cref="JumpWorld.ClearTarget"/>: the agent stops on the next stance of its path.</summary>
    public void ClearTarget(AgentHandle agent) => Record(new Command(Op.ClearTarget, agent, default, false));

    /// <summary>Records <see cref="JumpWorld.Warp"/>: the agent stands at <paramref name="position"/> (world metres) at once.</summary>
    public void Warp(AgentHandle agent, Vector3 position) => Record(new Command(Op.Warp, agent, position, false));

    /// <summary>Records <see cref="JumpWorld.RemoveAgent"/>.</summary>
    public void RemoveAgent(AgentHandle agent) => Record(new Command(Op.Remove, agent, default, false));

    /// <summary>Records <see cref="JumpWorld.SetPoseEnabled"/>.</summary>
    public void SetPoseEnabled(AgentHandle agent, bool enabled) => Record(new Command(Op.SetPoseEnabled, agent, default, enabled));

    /// <summary>
    /// Plays every command recorded so far on <paramref name="world"/>, in order, calling <paramref name="refused"/>
    /// with each refused one (the command's agent and the reason). Commands recorded meanwhile wait for the next play.
    /// </summary>
    internal void Play(JumpWorld world, Action<AgentHandle, string> refused)
    {
        lock (_lock)
        {
            if (_recorded.Count == 0)
            {
                return;
            }

            (_recorded, _playing) = (_playing, _recorded);
        }

        foreach (Command c in _playing)
        {
            RuntimeResult result = c.Op switch
            {
                Op.SetTarget => world.SetTarget(c.Agent, c.Point),
                Op.ClearTarget => world.ClearTarget(c.Agent),
                Op.Warp => world.Warp(c.Agent, c.Point),
                Op.Remove => world.RemoveAgent(c.Agent),
                _ => world.SetPoseEnabled(c.Agent, c.Flag),
            };
            if (!result.Ok)
            {
                refused(c.Agent, $"{Name(c.Op)} of {c.Agent} recorded in the command buffer was refused: {result}");
            }
        }

        _playing.Clear();
    }

    private static string Name(Op op) => op == Op.Remove ? "RemoveAgent" : op.ToString();

    private void Record(in Command command)
    {
        lock (_lock)
        {
            _recorded.Add(command);
        }
    }

    private readonly record struct Command(Op Op, AgentHandle Agent, Vector3 Point, bool Flag);
}
