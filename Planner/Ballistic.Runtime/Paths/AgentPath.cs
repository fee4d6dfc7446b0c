using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;

namespace Ballistic.Runtime.Paths;

/// <summary>
/// A path an agent follows: its moves (jumps and walks) on the path's clock and the whole-body animation solved for
/// them. Immutable; the path's clock starts (at zero) on the tick the agent starts following it.
/// </summary>
public sealed class AgentPath
{
    private readonly PathMove[] _moves;

    /// <summary>Each move's takeoff stance's contact centre, and the goal's last (world metres): read every tick by the body-point system.</summary>
    private readonly Vector3[] _centres;

    /// <summary>Each jump's body-point takeoff velocity (<see cref="BodyMotion.BodyVelocity(in PathMove)"/>), m/s; zero for walks.</summary>
    private readonly Vector3[] _bodyVelocities;

    /// <summary>Each walk's ends (<see cref="WalkEnds"/>): read every tick by the body-point system; default for jumps.</summary>
    private readonly WalkEnds[] _walkEnds;

    /// <summary>Builds the path of <paramref name="moves"/> (a <see cref="Planner.Query.PlanResult.Moves"/>) animated by <paramref name="animation"/>.</summary>
    /// <param name="target">The point asked for, world metres.</param>
    /// <param name="moves">The moves, jumps and walks, in order (at least one).</param>
    /// <param name="animation">Their whole-body animation: of exactly these moves, in this order, with frames.</param>
    /// <exception cref="ArgumentException">No moves, an animation without frames, or an animation of other moves.</exception>
    public AgentPath(Vector3 target, IReadOnlyList<Move> moves, JumpAnimation animation)
    {
        ArgumentNullException.ThrowIfNull(moves);
        ArgumentNullException.ThrowIfNull(animation);
        if (moves.Count == 0 || animation.Moves.Count != moves.Count || animation.Frames.Count == 0)
        {
            throw new ArgumentException($"A path needs at least one move and an animation with frames of exactly its moves ({moves.Count} moves, {animation.Moves.Count} animated, {animation.Frames.Count} frames).", nameof(animation));
        }

        for (int i = 0; i < moves.Count; i++)
        {
            if (moves[i] is null || !(ReferenceEquals(moves[i], animation.Moves[i]) || moves[i].Equals(animation.Moves[i])))
            {
                throw new ArgumentException($"Move {i} of the path is not move {i} of the animation.", nameof(animation));
            }
        }

        Target = target;
        Animation = animation;
        Start = moves[0].From;
        Goal = moves[^1].To;
        _moves = new PathMove[moves.Count];
        for (int i = 0; i < moves.Count; i++)
        {
            float start = animation.MoveStart(i);
            float end = animation.MoveEnd(i);
            float stanceEnd = i + 1 < moves.Count ? animation.MoveStart(i + 1) : animation.Duration;
            switch (moves[i])
            {
                case Jump jump:
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

                    _moves[i] = new PathMove(MoveKind.Jump, i, jump.Takeoff, jump.Landing, jump.Arc, start, takeoffEnd, landingStart, end, stanceEnd);
                    break;
                case Walk walk:
                    _moves[i] = new PathMove(MoveKind.Walk, i, walk.From, walk.To, default(BallisticArc), start, start, end, end, stanceEnd) { Walk = walk };
                    break;
                default:
                    throw new ArgumentException($"Move {i} is of an unknown kind ({moves[i].GetType().Name}).", nameof(moves));
            }
        }

        Duration = animation.Duration;
        _centres = new Vector3[_moves.Length + 1];
        _bodyVelocities = new Vector3[_moves.Length];
        _walkEnds = new WalkEnds[_moves.Length];
        for (int i = 0; i < _moves.Length; i++)
        {
            _centres[i] = _moves[i].From.ContactCentre;
            _bodyVelocities[i] = _moves[i].Walk is null ? BodyMotion.BodyVelocity(_moves[i]) : Vector3.Zero;
            _walkEnds[i] = _moves[i].Walk is { } walk ? WalkEnds.Of(_moves[i].From.ContactCentre, _moves[i].To.ContactCentre, walk) : default;
        }

        _centres[^1] = _moves[^1].To.ContactCentre;
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

    /// <summary>Length of the path on its clock, seconds: the animation's, from the crouch before the first move to the last landing absorbed (the stances between included).</summary>
    public float Duration { get; }

    /// <summary>The move at <paramref name="index"/> without copying the list (for systems).</summary>
    internal ref readonly PathMove Move(int index) => ref _moves[index];

    /// <summary>The contact centre of the stance move <paramref name="index"/> leaves (<see cref="Count"/>: of the goal), world metres.</summary>
    internal Vector3 StanceCentre(int index) => _centres[index];

    /// <summary>
    /// The body point and its velocity <paramref name="t"/> seconds after the takeoff of jump move
    /// <paramref name="index"/>: <see cref="BodyMotion.InJump(in PathMove, float)"/> to the bit, from the values computed once.
    /// </summary>
    internal (Vector3 Position, Vector3 Velocity) BodyInJump(int index, float t) =>
        BodyMotion.InJump(_centres[index], _bodyVelocities[index], _moves[index].Arc.Gravity, t);

    /// <summary>
    /// The body point and its velocity <paramref name="t"/> seconds after the start of walk move
    /// <paramref name="index"/>: <see cref="BodyMotion.InWalk(in PathMove, float)"/> to the bit, from the ends computed once.
    /// </summary>
    /// <param name="index">The walk's move index.</param>
    /// <param name="t">Seconds since the walk's start.</param>
    /// <param name="segment">A path index of the walk near the trunk (a search hint: the same answer whatever it is).</param>
    internal (Vector3 Position, Vector3 Velocity) BodyInWalk(int index, float t, int segment = -1) =>
        BodyMotion.InWalk(_moves[index].Walk!, _walkEnds[index], t, segment);

    /// <summary>Number of moves.</summary>
    public int Count => _moves.Length;

    /// <summary>Number of jump moves.</summary>
    public int JumpCount => Animation.Arcs.Count;

    /// <summary>Number of walk moves.</summary>
    public int WalkCount => _moves.Length - Animation.Arcs.Count;
}
