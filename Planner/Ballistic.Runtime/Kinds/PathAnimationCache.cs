using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;

namespace Ballistic.Runtime.Kinds;

/// <summary>
/// The whole-body animations of one character kind's paths, shared by every agent and world of the kind: agents sent
/// between the same stances search the same moves, and the same moves animate the same way, so each distinct path is
/// solved once. A path is the same when its moves are, to the bit (the stances' ids, poses, cones and contacts; the
/// arcs; the walks' ground paths, speeds, turn rates and joined stances; what each move was cut or hopped from) at the
/// same frame rate: the animator is a function of those alone, so a remembered animation is exactly the one solving
/// them again gives, whichever agent or thread solved it first. A path asked for while it is being solved is waited
/// for, not solved twice (a crowd sent off in one tick); one the animator throws on is not remembered. The paths asked
/// for last are remembered, two generations of <see cref="Generation"/> (<see cref="RememberedResults{TKey, TValue}"/>).
/// Thread-safe.
/// </summary>
internal sealed class PathAnimationCache : IJumpAnimator, IStepwiseAnimator
{
    /// <summary>Paths each generation remembers, 128 to 256 in all (a 20 s path of the 39-joint skeleton at 60 frames per second keeps about 200 KB).</summary>
    internal const int Generation = 128;

    private readonly IJumpAnimator _animator;
    private readonly CharacterModel _model;
    private readonly RememberedResults<PathKey, Lazy<JumpAnimation>> _animated = new(Generation);
    private int _solved;

    /// <summary>Remembers what <paramref name="animator"/> animates for <paramref name="model"/>.</summary>
    public PathAnimationCache(IJumpAnimator animator, CharacterModel model)
    {
        ArgumentNullException.ThrowIfNull(animator);
        ArgumentNullException.ThrowIfNull(model);
        _animator = animator;
        _model = model;
    }

    /// <summary>Paths given to the animator (not found among those remembered or being solved) since this cache was made.</summary>
    public int Solved => Volatile.Read(ref _solved);

    /// <inheritdoc/>
    public JumpAnimation Animate(IReadOnlyList<Move> moves, float frameRate = 60f)
    {
        ArgumentNullException.ThrowIfNull(moves);
        return Animate(new PathKey([.. moves], frameRate), moves, frameRate);
    }

    /// <summary><see cref="Animate(IReadOnlyList{Move}, float)"/> for the moves' key, made once by the caller.</summary>
    private JumpAnimation Animate(PathKey key, IReadOnlyList<Move> moves, float frameRate)
    {
        // Solved once: an agent asking while another agent's same path is being solved waits for it; a path whose
        // solve throws is forgotten, so the next request for these moves calls the animator again.
        JumpAnimation known = _animated.GetOrSolve(
            key,
            (Animator: _animator, Moves: moves, FrameRate: frameRate),
            static s => s.Animator.Animate(s.Moves, s.FrameRate),
            ref _solved,
            out bool mine);
        return mine ? known : Rebound(known, moves);
    }

    /// <summary>
    /// <see cref="Animate(IReadOnlyList{Move}, float)"/> in steps, for a request advanced on the tick within a budget:
    /// a path remembered (or being solved by another thread) in one step, as <see cref="Animate(IReadOnlyList{Move}, float)"/>
    /// gives it; any other in the animator's steps (one when it has none), remembered at the end unless the same path
    /// was remembered meanwhile (then that one: the same motion). A path solved in steps is not waited for: another
    /// request for it meanwhile solves it too.
    /// </summary>
    IEnumerable<JumpAnimation?> IStepwiseAnimator.AnimateSteps(IReadOnlyList<Move> moves, float frameRate)
    {
        ArgumentNullException.ThrowIfNull(moves);
        var key = new PathKey([.. moves], frameRate);
        if (_animated.Contains(key) || _animator is not IStepwiseAnimator stepwise)
        {
            yield return Animate(key, moves, frameRate);
            yield break;
        }

        Interlocked.Increment(ref _solved);
        JumpAnimation? solved = null;
        foreach (bool _ in Stepwise.Pauses(stepwise.AnimateSteps(moves, frameRate), animated => solved = animated))
        {
            yield return null;
        }

        Lazy<JumpAnimation> other = _animated.GetOrAddLocked(key, solved!, static (_, s) => new Lazy<JumpAnimation>(s), out bool added);
        yield return !added && other.IsValueCreated ? Rebound(other.Value, moves) : solved;
    }

    /// <summary>The caller's own moves (equal to the remembered ones, not the same objects) with the remembered motion.</summary>
    private JumpAnimation Rebound(JumpAnimation known, IReadOnlyList<Move> moves) =>
        new(_model, moves, known.Stances, known.Frames, known.ContactPhases, known.Problems, known.FailedContactPoses, known.CollidingFrames, known.LeadIn, known.LeadOut);

    /// <inheritdoc/>
    public bool CanStand(PoseEvaluation pose) => _animator.CanStand(pose);

    /// <inheritdoc/>
    public bool CanPush(RootPose root, IReadOnlyList<Contact> contacts, Vector3 velocity) => _animator.CanPush(root, contacts, velocity);

    /// <summary>A path's moves and frame rate, equal when every input of the animation is equal to the bit.</summary>
    private sealed class PathKey(Move[] moves, float frameRate) : IEquatable<PathKey>
    {
        private readonly Move[] _moves = moves;
        private readonly float _frameRate = frameRate;
        private readonly int _hash = Hash(moves, frameRate);

        public bool Equals(PathKey? other) =>
            other is not null && _hash == other._hash && Same(_frameRate, other._frameRate) && _moves.Length == other._moves.Length
            && _moves.Zip(other._moves).All(m => Same(m.First, m.Second));

        public override bool Equals(object? obj) => Equals(obj as PathKey);

        public override int GetHashCode() => _hash;

        private static int Hash(Move[] moves, float frameRate)
        {
            var hash = default(HashCode);
            hash.Add(Bits(frameRate));
            hash.Add(moves.Length);
            foreach (Move move in moves)
            {
                hash.Add(move is Jump);
                hash.Add(move.From.Id);
                hash.Add(move.To.Id);
                hash.Add(Bits(move.Duration));
                hash.Add(Bits(move.From.Pose.Position.X));
                hash.Add(Bits(move.To.Pose.Position.Z));
            }

            return hash.ToHashCode();
        }

        private static bool Same(Move a, Move b) => (a, b) switch
        {
            (Jump x, Jump y) => Same(x.Takeoff, y.Takeoff) && Same(x.Landing, y.Landing) && Same(x.Arc, y.Arc) && SameOrigin(x, y),
            (Walk x, Walk y) => Same(x.From, y.From) && Same(x.To, y.To) && Same(x.Speed, y.Speed) && Same(x.TurnRate, y.TurnRate) && Same(x.PitchSpan, y.PitchSpan)
                && x.Path.Count == y.Path.Count && x.Path.Zip(y.Path).All(p => Same(p.First, p.Second)) && x.CrossGrades.Count == y.CrossGrades.Count && x.CrossGrades.Zip(y.CrossGrades).All(g => Same(g.First, g.Second))
                && x.Via.Count == y.Via.Count && x.Via.Zip(y.Via).All(n => Same(n.First, n.Second)) && SameOrigin(x, y),
            _ => false,
        };

        /// <summary>What the two moves were cut or hopped from (the repair reads them), the same.</summary>
        private static bool SameOrigin(Move a, Move b) => a.CutFrom.SequenceEqual(b.CutFrom) && a.HoppedFrom.SequenceEqual(b.HoppedFrom);

        private static bool Same(RoadmapNode a, RoadmapNode b) =>
            ReferenceEquals(a, b)
            || (a.Id == b.Id && Same(a.Pose, b.Pose) && Same(a.Cone.Axis, b.Cone.Axis) && Same(a.Cone.Mu, b.Cone.Mu)
                && a.Contacts.Count == b.Contacts.Count && a.Contacts.Zip(b.Contacts).All(c => Same(c.First, c.Second)));

        private static bool Same(Contact a, Contact b) =>
            a.Limb == b.Limb && a.Surface == b.Surface && Same(a.Position, b.Position) && Same(a.Normal, b.Normal) && Same(a.Mu, b.Mu);

        private static bool Same(BallisticArc a, BallisticArc b) =>
            Same(a.Takeoff, b.Takeoff) && Same(a.Landing, b.Landing) && Same(a.TakeoffVelocity, b.TakeoffVelocity)
            && Same(a.LandingVelocity, b.LandingVelocity) && Same(a.FlightTime, b.FlightTime) && Same(a.Gravity, b.Gravity) && Same(a.ArcLength, b.ArcLength);

        private static bool Same(RootPose a, RootPose b) =>
            Same(a.Position, b.Position) && Same(a.Rotation.X, b.Rotation.X) && Same(a.Rotation.Y, b.Rotation.Y) && Same(a.Rotation.Z, b.Rotation.Z) && Same(a.Rotation.W, b.Rotation.W);

        private static bool Same(Vector3 a, Vector3 b) => Same(a.X, b.X) && Same(a.Y, b.Y) && Same(a.Z, b.Z);

        private static bool Same(float a, float b) => Bits(a) == Bits(b);

        private static int Bits(float x) => BitConverter.SingleToInt32Bits(x);
    }
}
