using System.Numerics;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;
using Ballistic.Planner.Steering;

namespace Ballistic.Planner.Query;

/// <summary>
/// Walk where you can, jump where you must, after the search: a jump of the path whose ground can be walked part of
/// the way is cut down to what the ground requires. Its takeoff moves forward along the jump's line (seen from above)
/// as far as the ground is walkable (<see cref="Walking.WalkSteering.WalkableDistance"/>), its landing back toward
/// the takeoff likewise, and the path walks to the new takeoff and on from the new landing. The search costs a
/// metre in the air less than a metre walked (a jump is faster), so it covers walkable ground in the air; a game
/// character walks there and jumps over what it cannot walk.
/// </summary>
/// <remarks>
/// The new stances are placed like a request's start and goal (<see cref="TrunkSampler.PlaceFacing"/>, facing the
/// jump, passing the request's <see cref="QuerySettings.CanStand"/>), and every new move is checked by the same
/// steering methods as the roadmap's: the walks by <see cref="Walking.WalkSteering.Steer"/>, the jump by
/// <see cref="ParabolaSteering.Steer"/> (friction cones, speed limits, trunk sweep). The first pair of takeoff and
/// landing that passes, most ground walked first, replaces the jump; a jump with none is kept. On a level with surface
/// costs (<see cref="Levels.LevelMaterial.TravelCost"/>) a jump is cut down only over ground of its stance's own
/// material or of no cost. Moves set aside by
/// the caller are never used. New stances get ids from a counter, in the order they are placed: deterministic for
/// the same path and set-aside moves.
/// </remarks>
internal sealed class JumpTightener
{
    /// <summary>Jumps shorter than this (metres, horizontally between contact centres) are kept as they are.</summary>
    public const float MinJumpDistance = 1f;

    /// <summary>A new takeoff or landing stands at least this far (metres) back from where the walkable ground ends.</summary>
    public const float EdgeMargin = 0.45f;

    /// <summary>Candidate takeoffs (landings) are this far apart along the line, metres.</summary>
    public const float CandidateSpacing = 0.3f;

    /// <summary>The new jump covers at least this much (metres, horizontally).</summary>
    public const float MinFlight = 0.3f;

    /// <summary>Candidate takeoffs (and landings) tried per jump, besides the jump's own.</summary>
    public const int CandidatesPerSide = 4;

    /// <summary>Pairs of takeoff and landing steered per jump at most.</summary>
    public const int MaxJumpsTried = 12;

    /// <summary>A walk passing within this distance (metres, seen from above) of a spot the body could not walk hops over it (<see cref="Hop"/>).</summary>
    public const float SpotRadius = 0.2f;

    /// <summary>Spots that follow each other along a walk by at most this (metres) are hopped over at once.</summary>
    public const float SpotChain = 1f;

    /// <summary>The shortest hop (metres along the walk from takeoff to landing), unless it jumps the whole walk.</summary>
    public const float MinHop = 1f;

    /// <summary>How far (metres along the walk) before and after a spot a hop takes off and lands, nearest first.</summary>
    private static readonly float[] HopReach = [0.5f, 0.8f, 1.1f];

    /// <summary>How close a new stance's contacts' centre comes to its point on the line.</summary>
    private static readonly EndpointTolerance Placement = new(0.2f, 0.3f);

    private readonly PlanningScene _scene;
    private readonly ReachTest _reach;
    private readonly List<Vector3> _ground = [];
    private readonly SurfaceCosts? _surfaces;
    private int _nextId;

    /// <summary>The ground the current request no longer walks over (<see cref="QuerySettings.NoWalkSpots"/>): no walk passing it is made; <c>null</c> for none.</summary>
    internal WalkBarrier? Barrier { get; set; }

    /// <summary>Creates the tightener of a scene's jumps.</summary>
    public JumpTightener(PlanningScene scene)
    {
        _scene = scene;
        _reach = new ReachTest(scene.Steering.Limits);
        _surfaces = SurfaceCosts.Of(scene);
    }

    /// <summary>
    /// The moves of <paramref name="path"/> in a new list, each jump cut down where the ground allows walking (see the
    /// class). New stances get ids from <paramref name="nextId"/> on.
    /// </summary>
    /// <param name="path">The path found, its moves in order.</param>
    /// <param name="nextId">The first id free for new stances (the roadmap's node count + 2); on return, the next one still free.</param>
    /// <param name="minWalk">Shortest walk (metres, horizontally) a cut adds; a stance is not moved less.</param>
    /// <param name="rejected">Moves (from id, to id) set aside, or <c>null</c>.</param>
    /// <param name="uncut">Jumps (takeoff id, landing id) to leave whole, or <c>null</c>.</param>
    /// <param name="canStand">The request's extra stance check, or <c>null</c>.</param>
    /// <param name="stop">Polled between jumps: when it returns true, the rest of the path is kept as it is.</param>
    public List<Move> Tighten(List<Move> path, ref int nextId, float minWalk, IReadOnlySet<(int From, int To)>? rejected, IReadOnlySet<(int From, int To)>? uncut, Func<PoseEvaluation, bool>? canStand, Func<bool> stop)
    {
        _nextId = nextId;
        var result = new List<Move>(path.Count);
        foreach (Move move in path)
        {
            if (move is Jump jump && uncut?.Contains((jump.From.Id, jump.To.Id)) != true && !stop() && TightenOne(jump, minWalk, rejected, canStand) is { } moves)
            {
                result.AddRange(moves);
            }
            else
            {
                result.Add(move);
            }
        }

        nextId = _nextId;
        return result;
    }

    /// <summary>Walk, shorter jump, walk (either walk may be absent) replacing <paramref name="jump"/>, or <c>null</c>.</summary>
    private List<Move>? TightenOne(Jump jump, float minWalk, IReadOnlySet<(int From, int To)>? rejected, Func<PoseEvaluation, bool>? canStand)
    {
        Vector3 a = jump.From.ContactCentre;
        Vector3 b = jump.To.ContactCentre;
        var across = new Vector2(b.X - a.X, b.Z - a.Z);
        float distance = across.Length();
        if (distance < MinJumpDistance)
        {
            return null;
        }

        List<Vector3> forward = Candidates(a, b, distance, minWalk);
        List<Vector3> backward = Candidates(b, a, distance, minWalk);
        if (forward.Count == 0 && backward.Count == 0)
        {
            return null;
        }

        // Index 0 is the jump's own stance (no walk); 1.. the candidates, farthest from it first.
        // Pairs by ground walked, most first (ties: the lower takeoff index first).
        var pairs = new List<(int T, int L, float Walked)>();
        for (int t = 0; t <= forward.Count; t++)
        {
            for (int l = 0; l <= backward.Count; l++)
            {
                float walkedA = t == 0 ? 0f : Along(a, forward[t - 1]);
                float walkedB = l == 0 ? 0f : Along(b, backward[l - 1]);
                if ((t > 0 || l > 0) && walkedA + walkedB <= distance - MinFlight)
                {
                    pairs.Add((t, l, walkedA + walkedB));
                }
            }
        }

        pairs.Sort((x, y) => y.Walked != x.Walked ? y.Walked.CompareTo(x.Walked) : x.T.CompareTo(y.T));
        if (FirstJump(pairs.Select(p => (p.T, p.L)), jump.From, [a, .. forward], jump.To, [b, .. backward], MathF.Atan2(across.X, across.Y), rejected, canStand) is not { } found)
        {
            return null;
        }

        (Walk? before, Jump cutJump, Walk? after) = found;

        (int, int)[] cut = [(jump.From.Id, jump.To.Id)];
        var moves = new List<Move>(3);
        if (before is Walk walkBefore)
        {
            moves.Add(walkBefore with { CutFrom = cut });
        }

        moves.Add(cutJump with { CutFrom = cut });
        if (after is Walk walkAfter)
        {
            moves.Add(walkAfter with { CutFrom = cut });
        }

        return moves;
    }

    /// <summary>
    /// The first pair of <paramref name="pairs"/> (indices into <paramref name="takeoffPoints"/> and
    /// <paramref name="landingPoints"/>; index 0 is <paramref name="from"/> or <paramref name="to"/> itself) whose
    /// stances can be placed there facing <paramref name="facing"/> and walked from <paramref name="from"/> and to
    /// <paramref name="to"/>, and whose jump passes the steering method (at most <see cref="MaxJumpsTried"/> steered):
    /// the walk before the jump, the jump, the walk after it (a walk absent at index 0); <c>null</c> when none does.
    /// Each stance is placed once, when a pair first needs it.
    /// </summary>
    private (Walk? Before, Jump Jump, Walk? After)? FirstJump(IEnumerable<(int T, int L)> pairs, RoadmapNode from, Vector3[] takeoffPoints, RoadmapNode to, Vector3[] landingPoints, float facing, IReadOnlySet<(int From, int To)>? rejected, Func<PoseEvaluation, bool>? canStand)
    {
        var takeoffs = new Candidate?[takeoffPoints.Length];
        var landings = new Candidate?[landingPoints.Length];
        takeoffs[0] = new Candidate(from, null);
        landings[0] = new Candidate(to, null);
        int tried = 0;
        foreach ((int t, int l) in pairs)
        {
            Candidate takeoff = takeoffs[t] ??= Place(takeoffPoints[t], facing, from, toStance: true, rejected, canStand);
            if (takeoff.Node is not RoadmapNode up)
            {
                continue;
            }

            Candidate landing = landings[l] ??= Place(landingPoints[l], facing, to, toStance: false, rejected, canStand);
            if (landing.Node is not RoadmapNode down || rejected?.Contains((up.Id, down.Id)) == true || !_reach.InReach(up.Pose.Position, down.Pose.Position))
            {
                continue;
            }

            if (++tried > MaxJumpsTried)
            {
                break;
            }

            SteeringResult steered = _scene.Steering.SteerRemembered(up.Pose, up.Cone, down.Pose, down.Cone);
            if (steered.Succeeded)
            {
                return (takeoff.Walk, new Jump(up, down, steered.Arc), landing.Walk);
            }
        }

        return null;
    }

    /// <summary>
    /// The moves of <paramref name="path"/> in a new list, each walk that passes within <see cref="SpotRadius"/> of a
    /// spot of <paramref name="spots"/> (seen from above) hopping over it: walk to a takeoff before the spot, jump,
    /// walk on from a landing after it (either walk absent when the hop leaves from the walk's own stance or lands on
    /// it). Takeoffs and landings lie <see cref="HopReach"/> before and after the spot along the walk's path, placed
    /// and checked as <see cref="Tighten"/>'s are; the shortest hop that passes is taken. A walk with several spots
    /// hops over each in turn; one with no hop that passes is kept. The new moves record the searched walk in
    /// <see cref="Move.HoppedFrom"/>.
    /// </summary>
    /// <param name="path">The path, its moves in order.</param>
    /// <param name="spots">Ground points (world metres) where the body could not walk.</param>
    /// <param name="nextId">The first id free for new stances; on return, the next one still free.</param>
    /// <param name="minWalk">Shortest walk (metres) a hop leaves before or after it; nearer a stance, it leaves from or lands on that stance.</param>
    /// <param name="rejected">Moves (from id, to id) set aside, or <c>null</c>.</param>
    /// <param name="canStand">The request's extra stance check, or <c>null</c>.</param>
    /// <param name="stop">Polled between walks: when it returns true, the rest of the path is kept as it is.</param>
    public List<Move> Hop(List<Move> path, IReadOnlyList<Vector3> spots, ref int nextId, float minWalk, IReadOnlySet<(int From, int To)>? rejected, Func<PoseEvaluation, bool>? canStand, Func<bool> stop)
    {
        _nextId = nextId;
        var result = new List<Move>(path.Count);
        foreach (Move move in path)
        {
            if (move is Walk walk && walk.CutFrom.Count == 0 && !stop())
            {
                HopOver(walk, spots, result, minWalk, rejected, canStand);
            }
            else
            {
                result.Add(move);
            }
        }

        nextId = _nextId;
        return result;
    }

    /// <summary>Adds <paramref name="walk"/> to <paramref name="result"/>, hopping over its spots (see <see cref="Hop"/>).</summary>
    private void HopOver(Walk walk, IReadOnlyList<Vector3> spots, List<Move> result, float minWalk, IReadOnlySet<(int From, int To)>? rejected, Func<PoseEvaluation, bool>? canStand)
    {
        (int, int)[] searched = [.. walk.Segments];
        Walk? rest = walk;
        while (rest is not null && FirstStretch(rest, spots) is (float first, float last) && HopAt(rest, first, last, minWalk, rejected, canStand) is { } hop)
        {
            if (hop.Before is Walk before)
            {
                result.Add(before with { HoppedFrom = searched });
            }

            result.Add(hop.Jump with { HoppedFrom = searched });
            rest = hop.After is Walk after ? after with { HoppedFrom = searched } : null;
        }

        if (rest is not null)
        {
            result.Add(rest);
        }
    }

    /// <summary>
    /// The shortest hop (at least <see cref="MinHop"/>) over the stretch from <paramref name="first"/> to
    /// <paramref name="last"/> metres along <paramref name="walk"/> that passes, with the walks before and after it
    /// (each absent when the hop leaves from or lands on the walk's own stance); <c>null</c> when none does.
    /// </summary>
    private (Walk? Before, Jump Jump, Walk? After)? HopAt(Walk walk, float first, float last, float minWalk, IReadOnlySet<(int From, int To)>? rejected, Func<PoseEvaluation, bool>? canStand)
    {
        // Index 0 is the walk's own stance (no walk); 1.. the points before (after) the spot, nearest it first.
        float[] before = [0f, .. HopReach.Select(r => first - r).Where(d => d >= minWalk)];
        float[] after = [walk.Length, .. HopReach.Select(r => last + r).Where(d => walk.Length - d >= minWalk)];

        // The shortest hop first (ties: the lower takeoff index first).
        var pairs = new List<(int T, int L)>();
        for (int t = 0; t < before.Length; t++)
        {
            for (int l = 0; l < after.Length; l++)
            {
                if (after[l] - before[t] >= MinHop || (t == 0 && l == 0))
                {
                    pairs.Add((t, l));
                }
            }
        }

        pairs.Sort((x, y) =>
        {
            int byLength = (after[x.L] - before[x.T]).CompareTo(after[y.L] - before[y.T]);
            return byLength != 0 ? byLength : x.T.CompareTo(y.T);
        });

        float facing = MathF.Atan2(walk.Path[^1].X - walk.Path[0].X, walk.Path[^1].Z - walk.Path[0].Z);
        return FirstJump(pairs, walk.From, [.. before.Select(walk.PointAt)], walk.To, [.. after.Select(walk.PointAt)], facing, rejected, canStand);
    }

    /// <summary>
    /// The first stretch of <paramref name="walk"/>'s path (metres along it) with spots beside it, within
    /// <see cref="SpotRadius"/> seen from above (not behind its start or past its end): from the first such spot to
    /// the last that follows the one before it by at most <see cref="SpotChain"/>; <c>null</c> when no spot is beside it.
    /// </summary>
    private static (float Start, float End)? FirstStretch(Walk walk, IReadOnlyList<Vector3> spots)
    {
        var at = new List<float>();
        float along = 0f;
        for (int i = 0; i + 1 < walk.Path.Count; i++)
        {
            Vector3 a = walk.Path[i];
            Vector3 b = walk.Path[i + 1];
            float span = Vector3.Distance(a, b);
            var ab = new Vector2(b.X - a.X, b.Z - a.Z);
            float flat = ab.LengthSquared();
            foreach (Vector3 spot in spots)
            {
                var ap = new Vector2(spot.X - a.X, spot.Z - a.Z);
                float u = flat > 1e-12f ? Vector2.Dot(ap, ab) / flat : 0f;
                if (u >= 0f && u <= 1f && (ap - (u * ab)).Length() <= SpotRadius)
                {
                    at.Add(along + (u * span));
                }
            }

            along += span;
        }

        if (at.Count == 0)
        {
            return null;
        }

        at.Sort();
        float end = at[0];
        foreach (float d in at)
        {
            if (d - end > SpotChain)
            {
                break;
            }

            end = d;
        }

        return (at[0], end);
    }

    /// <summary>A stance on the line: the node, and the walk linking it to the jump's own stance (<c>null</c> for the jump's own); <see cref="Node"/> null when none could be placed or walked to.</summary>
    private readonly record struct Candidate(RoadmapNode? Node, Walk? Walk);

    /// <summary>
    /// Ground points on the line from <paramref name="from"/> toward <paramref name="toward"/> where a moved stance
    /// may stand: at most <see cref="CandidatesPerSide"/>, farthest first, from <see cref="EdgeMargin"/> short of
    /// where the walkable ground ends back to <paramref name="minWalk"/>, <see cref="CandidateSpacing"/> apart.
    /// </summary>
    private List<Vector3> Candidates(Vector3 from, Vector3 toward, float distance, float minWalk)
    {
        var result = new List<Vector3>();
        float walkable = MathF.Min(_scene.Walking.WalkableDistance(from, toward, _ground), distance - MinFlight);
        if (_surfaces is not null && _ground.Count > 0)
        {
            // A jump is cut down over its stance's own material only: where the ground turns to another that costs
            // something (mud, water), the search chose to fly over it, and a walk there would cost more than it saves.
            int own = _surfaces.MaterialBelow(_ground[0]);
            foreach (Vector3 p in _ground)
            {
                int m = _surfaces.MaterialBelow(p);
                if (m != own && m >= 0 && _scene.Level.Materials[m].HasCost)
                {
                    walkable = MathF.Min(walkable, Along(from, p));
                    break;
                }
            }
        }

        for (float s = walkable - EdgeMargin; s >= minWalk && result.Count < CandidatesPerSide; s -= CandidateSpacing)
        {
            // The traced ground point nearest s along the line (the points are at most PathSpacing apart, in order).
            Vector3 best = _ground[0];
            float off = float.PositiveInfinity;
            foreach (Vector3 p in _ground)
            {
                float d = MathF.Abs(Along(from, p) - s);
                if (d >= off)
                {
                    break;
                }

                (best, off) = (p, d);
            }

            if (result.Count == 0 || result[^1] != best)
            {
                result.Add(best);
            }
        }

        return result;
    }

    private static float Along(Vector3 from, Vector3 p) => new Vector2(p.X - from.X, p.Z - from.Z).Length();

    /// <summary>
    /// A stance placed at <paramref name="point"/> facing <paramref name="facing"/>, with the walk from
    /// <paramref name="own"/> to it (<paramref name="toStance"/>: a takeoff) or from it to <paramref name="own"/>
    /// (a landing); a candidate with no node when it cannot be placed or walked, or its walk is set aside.
    /// </summary>
    private Candidate Place(Vector3 point, float facing, RoadmapNode own, bool toStance, IReadOnlySet<(int From, int To)>? rejected, Func<PoseEvaluation, bool>? canStand)
    {
        EndpointPlacement placed = _scene.Sampler.PlaceFacing(point, Placement, facing, canStand);
        if (placed.Pose is not { } pose)
        {
            return new Candidate(null, null);
        }

        var node = new RoadmapNode(_nextId++, pose.Pose, pose.Cone, pose.Contacts);
        (RoadmapNode first, RoadmapNode second) = toStance ? (own, node) : (node, own);
        if (rejected?.Contains((first.Id, second.Id)) == true || _scene.Walking.SteerRemembered(first, second).Walk is not Walk walk || Barrier?.Bars(walk) == true)
        {
            return new Candidate(null, null);
        }

        return new Candidate(node, walk);
    }
}
