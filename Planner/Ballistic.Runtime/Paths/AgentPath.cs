using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Runtime.Paths;

/// <summary>
/// A path an agent follows: its moves on the path's clock and the whole-body animation solved for them. Immutable;
/// the path's clock starts (at zero) on the tick the agent starts following it.
/// </summary>
public sealed class AgentPath
{
    private readonly PathMove[] _moves;

    /// <summary>Builds the path of <paramref name="jumps"/> animated by <paramref name="animation"/>.</summary>
    /// <param name="target">The point asked for, world metres.</param>
    /// <param name="jumps">The jumps, in order (at least one).</param>
    /// <param name="animation">Their whole-body animation (one arc per jump, the same arcs).</param>
    /// <exception cref="ArgumentException">No jumps, or the animation is not of these jumps.</exception>
    public AgentPath(Vector3 target, IReadOnlyList<Jump> jumps, JumpAnimation animation)
    {
        ArgumentNullException.ThrowIfNull(jumps);
        ArgumentNullException.ThrowIfNull(animation);
        if (jumps.Count == 0 || animation.Arcs.Count != jumps.Count || animation.Frames.Count == 0)
        {
            throw new ArgumentException($"A path needs at least one jump and an animation of exactly its jumps ({jumps.Count} jumps, {animation.Arcs.Count} animated).", nameof(animation));
        }

        Target = target;
        Animation = animation;
        Start = jumps[0].Takeoff;
        Goal = jumps[^1].Landing;
        _moves = new PathMove[jumps.Count];
        for (int i = 0; i < jumps.Count; i++)
        {
            float start = animation.JumpStart(i);
            float end = start + jumps[i].Arc.FlightTime;
            float takeoffEnd = start;
            float landingStart = end;
            foreach (ContactPhase phase in animation.ContactPhases)
            {
                if (phase.From <= start && phase.To > start && phase.To <= end)
                {
                    takeoffEnd = MathF.Max(takeoffEnd, phase.To);
                }

                if (phase.From > start && phase.From < landingStart)
                {
                    landingStart = phase.From;
                }
            }

            float stanceEnd = i + 1 < jumps.Count ? animation.JumpStart(i + 1) : end;
            _moves[i] = new PathMove(MoveKind.Jump, i, jumps[i].Takeoff, jumps[i].Landing, jumps[i].Arc, start, takeoffEnd, landingStart, end, stanceEnd);
        }

        Duration = _moves[^1].End;
    }

    /// <summary>The point the path was planned to, world metres.</summary>
    public Vector3 Target { get; }

    /// <summary>The moves, in order.</summary>
    public IReadOnlyList<PathMove> Moves => _moves;

    /// <summary>The stance the path starts from.</summary>
    public RoadmapNode Start { get; }

    /// <summary>The stance the path ends on (within tolerance of <see cref="Target"/>).</summary>
    public RoadmapNode Goal { get; }

    /// <summary>The whole-body animation; its clip time is the path's clock.</summary>
    public JumpAnimation Animation { get; }

    /// <summary>Length of the path on its clock, seconds: from the first takeoff to the last landing.</summary>
    public float Duration { get; }

    /// <summary>The move at <paramref name="index"/> without copying the list (for systems).</summary>
    internal ref readonly PathMove Move(int index) => ref _moves[index];

    /// <summary>Number of moves.</summary>
    public int Count => _moves.Length;
}
