using System.Numerics;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Runtime;

/// <summary>
/// Changes to a <see cref="JumpWorld"/>'s agents recorded now and played back, in the order recorded, at the start of
/// the world's next tick (<see cref="JumpWorld.Commands"/>), like a DOTS <c>EntityCommandBuffer</c>: for systems that
/// change agents while others iterate them, and for code on other threads (jobs, <c>async</c> continuations), which
/// must never call the world directly. Recording is thread-safe and never fails; each command is then played as the
/// world's method of the same name, and a refused one (an agent removed meanwhile, a point nobody stands on) comes out
/// as a <see cref="Events.JumpEventKind.CommandRefused"/> event of that tick with the reason. Played from one thread,
/// commands keep the world deterministic; from several, their order is the order the threads recorded them in.
/// An agent added by <see cref="AddAgent"/> gets its handle when played: until then a pending handle stands for it,
/// which the commands recorded after it in the same buffer may name, like a DOTS deferred entity.
/// </summary>
public sealed class JumpCommandBuffer
{
    private readonly object _lock = new();
    private List<Command> _recorded = [];
    private List<Command> _playing = [];
    private AgentHandle[] _added = [];

    /// <summary>Playbacks so far, plus one: the pending handles of the commands recorded now carry it.</summary>
    private int _epoch = 1;

    /// <summary>Agents <see cref="AddAgent"/> recorded since the last playback.</summary>
    private int _adds;

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
        Add,
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
    /// Records <see cref="JumpWorld.AddAgent"/>: an agent of <paramref name="kind"/> standing at
    /// <paramref name="position"/> (world metres). Returns a pending handle (not yet valid in the world; its
    /// <see cref="AgentHandle.IsAssigned"/> is false) that commands recorded after this one in the same buffer may name
    /// (<see cref="SetTarget"/> right after the spawn): they are played on the agent added. When played, a
    /// <see cref="Events.JumpEventKind.Added"/> event gives the agent's handle (its point is <paramref name="position"/>);
    /// a refused add (an unknown kind) comes out as a <see cref="Events.JumpEventKind.CommandRefused"/>, and the
    /// commands naming its pending handle are refused too. A pending handle means nothing after that playback.
    /// </summary>
    public AgentHandle AddAgent(KindHandle kind, Vector3 position)
    {
        lock (_lock)
        {
            var pending = new AgentHandle(-1 - _adds++, -_epoch);
            _recorded.Add(new Command(Op.Add, pending, position, false, kind));
            return pending;
        }
    }

    /// <summary>
    /// Plays every command recorded so far on <paramref name="world"/>, in order, calling <paramref name="refused"/>
    /// with each refused one (the command's agent and the reason). Commands recorded meanwhile wait for the next play.
    /// </summary>
    internal void Play(JumpWorld world, Action<AgentHandle, string> refused, Action<AgentHandle, Vector3, string?> added)
    {
        int epoch;
        int adds;
        lock (_lock)
        {
            if (_recorded.Count == 0)
            {
                return;
            }

            (_recorded, _playing) = (_playing, _recorded);
            (epoch, adds) = (_epoch++, _adds);
            _adds = 0;
        }

        if (_added.Length < adds)
        {
            _added = new AgentHandle[Math.Max(adds, 2 * _added.Length)];
        }

        foreach (Command c in _playing)
        {
            AgentHandle agent = c.Agent;
            if (agent.Generation < 0)
            {
                // A pending handle: the agent its add made in this playback (default when refused), none from another.
                agent = agent.Generation == -epoch && -1 - agent.Index < adds ? _added[-1 - agent.Index] : default;
            }

            if (c.Op == Op.Add)
            {
                AddAgentResult result = world.AddAgent(c.Kind, c.Point);
                _added[-1 - c.Agent.Index] = result.Agent;
                if (result.Agent.IsAssigned)
                {
                    added(result.Agent, c.Point, result.Ok ? null : result.Result.Reason);
                }
                else
                {
                    refused(default, $"AddAgent of {c.Kind} at {c.Point} recorded in the command buffer was refused: {result.Result}");
                }

                continue;
            }

            RuntimeResult done = c.Op switch
            {
                Op.SetTarget => world.SetTarget(agent, c.Point),
                Op.ClearTarget => world.ClearTarget(agent),
                Op.Warp => world.Warp(agent, c.Point),
                Op.Remove => world.RemoveAgent(agent),
                _ => world.SetPoseEnabled(agent, c.Flag),
            };
            if (!done.Ok)
            {
                string who = c.Agent.Generation < 0 ? $"the agent pending as {Pending(c.Agent)}" : $"{c.Agent}";
                refused(agent, $"{Name(c.Op)} of {who} recorded in the command buffer was refused: {done}");
            }
        }

        Array.Clear(_added, 0, adds);
        _playing.Clear();
    }

    private static string Name(Op op) => op == Op.Remove ? "RemoveAgent" : op.ToString();

    private static string Pending(AgentHandle pending) => $"pending add {-pending.Index} of playback {-pending.Generation}";

    private void Record(in Command command)
    {
        lock (_lock)
        {
            _recorded.Add(command);
        }
    }

    private readonly record struct Command(Op Op, AgentHandle Agent, Vector3 Point, bool Flag, KindHandle Kind = default);
}
