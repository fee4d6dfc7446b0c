using System.Numerics;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;
using Ballistic.Planner.Steering;

namespace Ballistic.Planner.Query;

/// <summary>
/// Jumps made facing the way they go, after the search: a roadmap stance faces whichever way it was sampled, so a
/// jump between two of them may leave sideways or land backwards. For each jump of the path travelling at least
/// <see cref="MinDistance"/> across whose takeoff (landing) heading is more than <see cref="TakeoffTurn"/>
/// (<see cref="LandingTurn"/>) off its direction, a new takeoff (landing) stance is placed where the old one stands,
/// facing the jump (<see cref="TrunkSampler.PlaceFacingWithin"/>: contacts on the level, within
/// <see cref="Placement"/> of where the old one stands (<see cref="Standing"/>), the request's
/// <see cref="QuerySettings.CanStand"/>), and the jump is
/// steered again between the stances it uses (friction cones of the contacts it actually stands on, speed limits,
/// trunk sweep). A new landing is placed only where the character can turn back into the old one, or, when the
/// jump after travels <see cref="MinDistance"/> or more and would leave the old one off its way, where that jump
/// can be steered from and then faces its way (it goes on from the new landing). The character turns in place into
/// the new takeoff and out of the new landing: a walker by a turn
/// walk (<see cref="Walking.WalkSteering.Turn"/>, its feet re-stepping) or, when the walk before the jump can be
/// steered to the new takeoff directly (the walk after it from the new landing), by that walk's own turn; a
/// character that does not walk, a request that only jumps, or a walker on ground too steep to walk, by a hop in
/// place, steered like any jump. When the jump cannot be steered from the turned takeoff (or to the turned landing),
/// the next stance is placed and tried: facing within <see cref="Yaws"/>, then within <see cref="WideYaws"/>, where
/// the old one stands, then one and two <see cref="HopShift"/> along the jump and back, the start or goal placed again
/// at the request's point first; where no turn into a takeoff links (ground too steep to walk or hop round on) and a
/// jump lands there, a takeoff turned part of the way back toward that jump (<see cref="RelandYaws"/>), on which the
/// jump before lands instead, no more than <see cref="StillOffLanding"/> off its own way; a turned end is dropped
/// (kept as searched) only when none steers.
/// </summary>
/// <remarks>
/// A jump is faced only when every move linking it to the path passes its checks; otherwise it is kept as it was
/// searched. The new moves record the jump they replace in <see cref="Move.CutFrom"/> (its own cut, or the jump
/// itself), so that when one of them does not animate, <see cref="JumpRepair"/> gives that jump back whole
/// (<see cref="QuerySettings.UncutJumps"/>), as it does for a cut jump; such a jump is faced again turning by hops
/// only (a turn walk the gait could not perform is the usual cause), and after <see cref="JumpRepair.CutRounds"/>
/// rounds with such failures no jump is turned. The path still starts and ends on the
/// request's start and goal stances, or on stances placed again at the request's points facing the first and last
/// jumps. New stances get ids from a counter in the order they are placed:
/// deterministic for the same path. Jumps left still off their way are listed in <see cref="Unturned"/>: the query
/// searches again without them (<see cref="PathQuery.FacingSearches"/>).
/// </remarks>
internal sealed class JumpFacer
{
    /// <summary>Jumps shorter than this (metres, horizontally between the trunk's takeoff and landing) are kept as they are: a hop may go any way.</summary>
    public const float MinDistance = 0.9f;

    /// <summary>A takeoff whose heading is more than this (radians, 20°) off the jump's direction is turned to face it.</summary>
    public const float TakeoffTurn = 20f * MathF.PI / 180f;

    /// <summary>A landing whose heading is more than this (radians, 30°) off the jump's direction is turned to face it.</summary>
    public const float LandingTurn = 30f * MathF.PI / 180f;

    /// <summary>The farthest (metres, horizontally between contact centres) a turn in place moves the stance.</summary>
    public const float MaxTurnShift = 0.5f;

    /// <summary>Yaws (radians, from the jump's direction) a new stance is tried at, in order.</summary>
    internal static readonly float[] Yaws = [0f, 10f * MathF.PI / 180f, -10f * MathF.PI / 180f];

    /// <summary>How close a new stance's contacts' centre comes to the old one's.</summary>
    private static readonly EndpointTolerance Placement = new(0.2f, 0.3f);

    private readonly PlanningScene _scene;
    private readonly bool _walking;
    private readonly Func<PoseEvaluation, bool>? _canStand;
    private readonly Func<RootPose, IReadOnlyList<Contact>, Vector3, bool>? _canPush;
    private readonly IReadOnlyList<RootPose> _refused;
    private readonly WalkBarrier? _barrier;
    private int _nextId;

    /// <summary>Whether the jump being faced (or the last one, for the moves after it) turns by hops only: the request does not walk, or the repair gave it back once (its turn walks did not animate).</summary>
    private bool _hops;
    private RoadmapNode? _placedGoal;

    /// <summary>The last turned landing and the moves turning from it back into the stance it replaced, found when it was placed.</summary>
    private (RoadmapNode From, List<Move> Moves)? _turnBack;

    /// <summary>Creates the facer of one request's path.</summary>
    /// <param name="scene">The level and character.</param>
    /// <param name="walking">Whether the request walks (turns are walked) or only jumps (turns are hopped).</param>
    /// <param name="canStand">The request's extra stance check, or <c>null</c>.</param>
    /// <param name="refused">Stances the body could not crouch or absorb on for a faced jump (<see cref="QuerySettings.RefusedTurns"/>), or <c>null</c>: not placed again.</param>
    /// <param name="canPush">Whether the body pushes off with a velocity (absorbs it, given reversed) at either end of a turn hop (<see cref="QuerySettings.CanPush"/>), or <c>null</c>: not checked.</param>
    /// <param name="barrier">The ground the request no longer walks over (<see cref="QuerySettings.NoWalkSpots"/>), or <c>null</c>: no walk passing it is made.</param>
    public JumpFacer(PlanningScene scene, bool walking, Func<PoseEvaluation, bool>? canStand, IReadOnlyList<RootPose>? refused = null, Func<RootPose, IReadOnlyList<Contact>, Vector3, bool>? canPush = null, WalkBarrier? barrier = null)
    {
        _barrier = barrier;
        _scene = scene;
        _walking = walking;
        _canStand = canStand;
        _canPush = canPush;
        _refused = refused ?? [];
    }

    /// <summary>
    /// The moves of <paramref name="path"/> in a new list, its jumps facing the way they go where the checks allow
    /// (see the class). New stances get ids from <paramref name="nextId"/> on.
    /// </summary>
    /// <param name="path">The path, its moves in order, each starting where the one before ends.</param>
    /// <param name="nextId">The first id free for new stances; on return, the next one still free.</param>
    /// <param name="rejected">Moves (from id, to id) set aside, or <c>null</c>: never used.</param>
    /// <param name="uncut">Jumps (takeoff id, landing id) the repair gave back because a move made from them did not animate, or <c>null</c>: faced again turning by hops only.</param>
    /// <param name="unfaced">Jumps (takeoff id, landing id) whose hops did not animate either, or <c>null</c>: left as searched.</param>
    /// <param name="placeStart">As <paramref name="placeGoal"/>, for the path's start and a first jump taking off off its way.</param>
    /// <param name="placeGoal">
    /// Places the path's goal again facing a yaw (radians about +Y) within one of the yaw offsets given (radians) for
    /// a last jump landing off its way (at the request's own point, within its tolerance), or returns <c>null</c>;
    /// each call places a new stance with the same id. <c>null</c> when the goal must stay (a roadmap node given): the
    /// path then turns in place into it.
    /// </param>
    /// <param name="stop">Polled between jumps: when it returns true, the rest of the path is linked as it is.</param>
    public List<Move> Face(List<Move> path, ref int nextId, IReadOnlySet<(int From, int To)>? rejected, IReadOnlySet<(int From, int To)>? uncut, IReadOnlySet<(int From, int To)>? unfaced, Func<float, float[], RoadmapNode?>? placeStart, Func<float, float[], RoadmapNode?>? placeGoal, Func<bool> stop)
    {
        _nextId = nextId;
        _firstPlaced = nextId;
        _unturned.Clear();
        var result = new List<Move>(path.Count + 4);
        if (path.Count == 0)
        {
            return result;
        }

        RoadmapNode current = path[0].From;
        for (int i = 0; i < path.Count; i++)
        {
            Move move = path[i];
            if (move is Jump given)
            {
                // Kept for the moves after it: the turn out of its landing is made the same way.
                _hops = !_walking || Given(given, uncut);
            }

            if (move is Jump jump && Far(jump) && !Given(jump, unfaced) && !stop() && FaceOne(jump, current, result, rejected, i == 0 ? placeStart : null, i == path.Count - 1 ? placeGoal : null, i + 1 < path.Count ? path[i + 1] : null) is RoadmapNode landed)
            {
                current = landed;
            }
            else if (move is Jump unturned && Far(unturned) && Given(unturned, unfaced) && StillOff(unturned) && !SwungBefore(unturned, rejected) && !stop()
                && Swung(unturned, current, result, rejected, Cut(unturned)) is RoadmapNode swung)
            {
                // Its turned stances did not animate: a jump swung toward its landing's heading, once.
                current = swung;
            }
            else
            {
                current = Continue(move, current, result, rejected);
            }

            if (move is Jump searched && result[^1] is Jump made && Far(made) && StillOff(made))
            {
                _unturned.AddRange(Cut(searched));
            }
        }

        if (current.Id != path[^1].To.Id && !ReferenceEquals(current, _placedGoal))
        {
            // Only reached when the last landing was turned, not the goal placed again: turn back into the goal's stance (checked when placed).
            result.AddRange(TurnBack(current, path[^1].To, rejected, Cut(path[^1])));
        }

        nextId = _nextId;
        return result;
    }

    /// <summary>
    /// The searched jumps (takeoff id, landing id; those a cut jump was cut from) the last <see cref="Face"/> left
    /// taking off more than <see cref="StillOffTakeoff"/> or landing more than <see cref="StillOffLanding"/> off their
    /// way: no turned stance steered, or the repair gave them back unturned.
    /// </summary>
    public IReadOnlyList<(int From, int To)> Unturned => _unturned;

    private readonly List<(int From, int To)> _unturned = [];

    /// <summary>A jump taking off more than this (radians, 30°) off its way is still off after facing.</summary>
    public const float StillOffTakeoff = 30f * MathF.PI / 180f;

    /// <summary>A jump landing more than this (radians, 45°) off its way is still off after facing.</summary>
    public const float StillOffLanding = 45f * MathF.PI / 180f;

    /// <summary>Whether <paramref name="jump"/> takes off or lands further off its way than a viewer accepts (<see cref="StillOffTakeoff"/>, <see cref="StillOffLanding"/>).</summary>
    private static bool StillOff(Jump jump) => StillOff(jump.From, jump.To, jump.Arc);

    /// <summary><see cref="StillOff(Jump)"/> of a jump from <paramref name="from"/> to <paramref name="to"/> on <paramref name="arc"/>.</summary>
    private static bool StillOff(RoadmapNode from, RoadmapNode to, in BallisticArc arc)
    {
        float facing = Way(arc);
        return Off(from, facing) > StillOffTakeoff || Off(to, facing) > StillOffLanding;
    }

    /// <summary>
    /// Whether a jump from <paramref name="from"/> to <paramref name="to"/> on <paramref name="arc"/> reads as facing
    /// its way as it stands: not <see cref="Far(in BallisticArc)"/> (a hop may go any way), or not still off its way
    /// (<see cref="StillOff(RoadmapNode, RoadmapNode, in BallisticArc)"/>).
    /// </summary>
    internal static bool Faces(RoadmapNode from, RoadmapNode to, in BallisticArc arc) => !Far(arc) || !StillOff(from, to, arc);

    /// <summary>The yaw (radians about +Y, 0 along +Z) of <paramref name="arc"/>'s direction across, from takeoff to landing.</summary>
    private static float Way(BallisticArc arc) => MathF.Atan2(arc.End.X - arc.Start.X, arc.End.Z - arc.Start.Z);

    /// <summary>Whether <paramref name="jump"/> travels far enough across to need facing.</summary>
    private static bool Far(Jump jump) => Far(jump.Arc);

    /// <summary>Whether a jump on <paramref name="arc"/> travels <see cref="MinDistance"/> or more across, from takeoff to landing.</summary>
    private static bool Far(in BallisticArc arc)
    {
        Vector3 across = arc.End - arc.Start;
        return new Vector2(across.X, across.Z).Length() >= MinDistance;
    }

    /// <summary>Whether the repair gave <paramref name="jump"/> (or the jump it was cut from) back: a move made from it did not animate.</summary>
    private static bool Given(Jump jump, IReadOnlySet<(int From, int To)>? uncut) =>
        uncut is { Count: > 0 } && (uncut.Contains((jump.From.Id, jump.To.Id)) || jump.CutFrom.Any(uncut.Contains));

    /// <summary>The jumps a move replacing <paramref name="move"/> stands in for: its own cut, or the jump itself.</summary>
    private static IReadOnlyList<(int From, int To)> Cut(Move move) =>
        move.CutFrom.Count > 0 ? move.CutFrom : move is Jump ? [(move.From.Id, move.To.Id)] : [];

    /// <summary>
    /// Appends <paramref name="move"/> to <paramref name="result"/>, started from <paramref name="current"/> (where the
    /// path stands, which differs from the move's start only after a turned landing): steered again from there when
    /// it can be, else after a turn back into its own start. Returns where the path then stands.
    /// </summary>
    private RoadmapNode Continue(Move move, RoadmapNode current, List<Move> result, IReadOnlySet<(int From, int To)>? rejected)
    {
        if (current.Id == move.From.Id)
        {
            result.Add(move);
            return move.To;
        }

        IReadOnlyList<(int From, int To)> cut = Cut(result[^1]);
        if (Restart(move, current, rejected) is Move restarted)
        {
            result.Add(restarted with { CutFrom = [.. cut.Union(move.CutFrom)], HoppedFrom = move.HoppedFrom });
            return move.To;
        }

        result.AddRange(TurnBack(current, move.From, rejected, cut));
        result.Add(move);
        return move.To;
    }

    /// <summary>The walk from <paramref name="from"/> to <paramref name="to"/> (<see cref="Walking.WalkSteering.SteerRemembered"/>), or <c>null</c> when there is none or it passes ground the request no longer walks over.</summary>
    private Walk? SteerWalk(RoadmapNode from, RoadmapNode to) =>
        _scene.Walking.SteerRemembered(from, to).Walk is Walk walk && _barrier?.Bars(walk) != true ? walk : null;

    /// <summary><paramref name="move"/> steered again from <paramref name="from"/> to its own end, or <c>null</c>.</summary>
    private Move? Restart(Move move, RoadmapNode from, IReadOnlySet<(int From, int To)>? rejected)
    {
        if (rejected?.Contains((from.Id, move.To.Id)) == true)
        {
            return null;
        }

        if (move is Walk walk)
        {
            return walk.Via.Count == 0 && !_hops && SteerWalk(from, walk.To) is Walk steered ? steered : null;
        }

        SteeringResult r = _scene.Steering.SteerRemembered(from.Pose, from.Cone, move.To.Pose, move.To.Cone);
        return r.Succeeded ? new Jump(from, move.To, r.Arc) : null;
    }

    /// <summary>
    /// Appends <paramref name="jump"/> facing its way, started from <paramref name="current"/>, with the turns into and
    /// out of it, and returns its landing; <c>null</c> (and <paramref name="result"/> unchanged) when no faced jump
    /// passes the checks.
    /// </summary>
    private RoadmapNode? FaceOne(Jump jump, RoadmapNode current, List<Move> result, IReadOnlySet<(int From, int To)>? rejected, Func<float, float[], RoadmapNode?>? placeStart, Func<float, float[], RoadmapNode?>? placeGoal, Move? next)
    {
        float facing = Way(jump.Arc);
        bool turnOff = Off(current, facing) > TakeoffTurn;
        bool turnOn = Off(jump.To, facing) > LandingTurn;
        if (!turnOff && !turnOn)
        {
            return null;
        }

        IReadOnlyList<(int From, int To)> cut = Cut(jump);

        // The landing: the goal placed again (no moves: the path ends there), else turned where the old one stands
        // (only if the path can turn back into the old one from it, or the jump after it can be steered from it
        // instead), else the old one. Each further landing is placed only when no takeoff steers to the ones before it.
        var landings = new Candidates(turnOn ? Ends(placeGoal, facing, () => Placements(jump.To, facing, -1f, node => Link(node, jump.To, rejected, cut)).Concat(GoingOn(jump.To, facing, next, rejected))) : []);

        // The takeoff: the start placed again (no moves: the path starts there), else turned where the old one stands
        // (or a little ahead, for a hop) such that the path can turn into it, else where the path stands.
        // Where no turned takeoff links (ground too steep to turn on) after a jump landing here, the jump before may
        // land turned part of the way instead, facing as far toward this jump as its own landing allows.
        _relanded = null;
        Jump? landed = result.Count > 0 && result[^1] is Jump b && Same(b.To, current) && (Far(b) || Searched(b)) ? b : null;
        var takeoffs = new Candidates(turnOff ? Ends(placeStart, facing, () => Placements(jump.From, facing, 1f, node => Link(current, node, rejected, cut)).Concat(Relandings(landed, current, facing, rejected, cut))) : []);

        // Steer the faced jump: the most turned pair first, a turned end given up only when no pair with it steers.
        Jump? faced = null;
        List<Move>? turnIn = null;
        List<Move>? turnBack = null;
        foreach (((RoadmapNode Node, List<Move>? Moves)? up, (RoadmapNode Node, List<Move>? Moves)? down) in Pairs(takeoffs, landings))
        {
            RoadmapNode from = up?.Node ?? current;
            RoadmapNode to = down?.Node ?? jump.To;
            if ((Same(from, current) && Same(to, jump.To)) || rejected?.Contains((from.Id, to.Id)) == true)
            {
                continue;
            }

            if (_scene.Steering.SteerRemembered(from.Pose, from.Cone, to.Pose, to.Cone) is { Succeeded: true } r)
            {
                faced = new Jump(from, to, r.Arc) { CutFrom = cut };
                turnIn = up?.Moves;
                turnBack = down?.Moves;
                break;
            }
        }

        // A landing that stays too far off its way (a tread too shallow to stand on facing up the flight) is met by
        // a jump swung round toward the way it faces: taken off from a stance walked to.
        if (!_hops && Off(faced?.To ?? jump.To, Way((faced ?? jump).Arc)) > StillOffLanding && Swung(jump, current, result, rejected, cut) is RoadmapNode swung)
        {
            return swung;
        }

        if (faced is null)
        {
            return null;
        }

        // Into the takeoff: the jump before landing on it (placed so), the walk before steered to it, else a turn in
        // place (none into the start placed again).
        if (_relanded is (RoadmapNode relanded, Jump landing) && ReferenceEquals(faced.From, relanded))
        {
            result[^1] = landing;
        }
        else if (!Same(faced.From, current) && turnIn is not null)
        {
            if (result.Count > 0 && result[^1] is Walk before && before.Via.Count == 0 && !_hops &&
                rejected?.Contains((before.From.Id, faced.From.Id)) != true &&
                SteerWalk(before.From, faced.From) is Walk steered)
            {
                result[^1] = steered with { CutFrom = [.. before.CutFrom.Union(cut)], HoppedFrom = before.HoppedFrom };
            }
            else
            {
                // Checked when the takeoff was placed.
                result.AddRange(turnIn);
            }
        }

        // The turn out of a new landing comes with whatever follows (Continue, or the path's end), unless it is the goal.
        _placedGoal = !Same(faced.To, jump.To) && turnBack is null ? faced.To : null;
        _turnBack = turnBack is not null ? (faced.To, turnBack) : null;
        result.Add(faced);
        return faced.To;
    }

    /// <summary>
    /// The path's end placed again facing <paramref name="facing"/> (within <see cref="Yaws"/>, then within
    /// <see cref="WideYaws"/>), with no moves, when <paramref name="place"/> is given and the pose is not refused
    /// (<see cref="QuerySettings.RefusedTurns"/>); then the stances of <paramref name="turned"/> (the path turning in
    /// place at its end).
    /// </summary>
    private IEnumerable<(RoadmapNode Node, List<Move>? Moves)> Ends(Func<float, float[], RoadmapNode?>? place, float facing, Func<IEnumerable<(RoadmapNode Node, List<Move>? Moves)>> turned)
    {
        foreach (float[] yaws in place is null ? [] : YawSets)
        {
            if (place!(facing, yaws) is { } end && !Refused(end.Pose))
            {
                yield return (end, null);
            }
        }

        foreach ((RoadmapNode Node, List<Move>? Moves) stance in turned())
        {
            yield return stance;
        }
    }

    /// <summary>
    /// The pairs of takeoff and landing tried (<c>null</c>: the old one), most turned first: each turned takeoff with
    /// each turned landing and then the old landing, then the old takeoff with each turned landing. Further turned
    /// ends are only placed while no pair with the ones before them has been tried in vain.
    /// </summary>
    private static IEnumerable<((RoadmapNode, List<Move>?)? Up, (RoadmapNode, List<Move>?)? Down)> Pairs(Candidates takeoffs, Candidates landings)
    {
        for (int t = 0; takeoffs.Has(t); t++)
        {
            for (int l = 0; landings.Has(l); l++)
            {
                yield return (takeoffs[t], landings[l]);
            }

            yield return (takeoffs[t], null);
        }

        for (int l = 0; landings.Has(l); l++)
        {
            yield return (null, landings[l]);
        }
    }

    /// <summary>Stances placed lazily, in order, each kept once placed.</summary>
    private sealed class Candidates(IEnumerable<(RoadmapNode Node, List<Move>? Moves)> source)
    {
        private readonly IEnumerator<(RoadmapNode Node, List<Move>? Moves)> _source = source.GetEnumerator();
        private readonly List<(RoadmapNode Node, List<Move>? Moves)> _placed = [];
        private bool _done;

        /// <summary>Whether a stance <paramref name="index"/> exists (placed now when needed).</summary>
        public bool Has(int index)
        {
            while (_placed.Count <= index && !_done)
            {
                if (_source.MoveNext())
                {
                    _placed.Add(_source.Current);
                }
                else
                {
                    _done = true;
                }
            }

            return index < _placed.Count;
        }

        /// <summary>The stance <paramref name="index"/>, already placed.</summary>
        public (RoadmapNode Node, List<Move>? Moves) this[int index] => _placed[index];
    }

    /// <summary>
    /// Stances facing <paramref name="facing"/> (within <see cref="Yaws"/>, then within <see cref="WideYaws"/>)
    /// placed where <paramref name="old"/> stands, or one or two <see cref="HopShift"/> from there along the facing
    /// (times <paramref name="side"/>: ahead for a takeoff, behind for a landing), then as far the other way, for a hop
    /// to turn by, each with the moves <paramref name="link"/> finds for it: walkers try the spot first, others one
    /// shift ahead; stances <paramref name="link"/> refuses (<c>null</c>) are skipped. On a slope a hop ahead downhill
    /// may land outside its cone and one on the spot has no parabola, where a hop back up the slope passes. At most
    /// ten are placed, lazily: the later spots only when no earlier stance links.
    /// </summary>
    private IEnumerable<(RoadmapNode Node, List<Move>? Moves)> Placements(RoadmapNode old, float facing, float side, Func<RoadmapNode, List<Move>?> link)
    {
        Vector3 centre = Standing(old);
        float height = Height(_scene.Sampler, old);
        bool leans = Leans(old);
        Vector3 ahead = side * HopShift * new Vector3(MathF.Sin(facing), 0f, MathF.Cos(facing));
        foreach (Vector3 point in _hops ? [centre + ahead, centre + (2f * ahead), centre, centre - ahead, centre - (2f * ahead)] : (Vector3[])[centre, centre + ahead, centre + (2f * ahead), centre - ahead, centre - (2f * ahead)])
        {
            foreach (float[] yaws in YawSets)
            {
                EndpointPlacement placed = _scene.Sampler.PlaceFacingWithin(point, Placement, facing, yaws, _canStand, height, leans);
                if (placed.Pose is { } pose && !Refused(pose.Pose))
                {
                    var node = new RoadmapNode(_nextId++, pose.Pose, pose.Cone, pose.Contacts);
                    if (link(node) is { } moves)
                    {
                        yield return (node, moves);
                    }
                }
            }
        }
    }

    /// <summary>Yaws (radians, from a jump's direction toward the way of the jump before) a takeoff the jump before lands on is tried at, in order (<see cref="Relandings"/>): within the eye's 30° at takeoff, turned as far toward the landing as that allows first.</summary>
    private static readonly float[] RelandYaws = [25f * MathF.PI / 180f, 20f * MathF.PI / 180f, 10f * MathF.PI / 180f, 0f];

    /// <summary>The last takeoff placed by <see cref="Relandings"/> and the jump before steered to land on it.</summary>
    private (RoadmapNode Node, Jump Landing)? _relanded;

    /// <summary>
    /// Takeoffs for a jump whose own turned takeoffs do not link, when the jump <paramref name="before"/> it (one
    /// travelling <see cref="MinDistance"/> or more, or a shorter one of the searched path, not a turn hop, which has
    /// checks of its own) lands where the path stands (<paramref name="current"/>): stances placed there facing the
    /// jump's way (<paramref name="facing"/>) turned toward <paramref name="before"/>'s own way
    /// (<see cref="RelandYaws"/>; after a short hop, whose own way no viewer judges, nearest the jump's way first:
    /// <see cref="Yaws"/>, then <see cref="WideYaws"/>), to which <paramref name="before"/> is steered again and lands
    /// at most <see cref="StillOffLanding"/> off its way and, when it then travels <see cref="MinDistance"/> or more,
    /// takes off at most <see cref="StillOffTakeoff"/> off it unless it did before (a short hop steered onto a stance
    /// a little farther must not become a jump leaving backwards); each with no turn in (the jump before lands on it:
    /// <see cref="_relanded"/>), made from both jumps (<paramref name="cut"/>: the jump being faced), so that a repair
    /// giving it back gives back the turn too, not only the jump before. The two jumps then turn the body between them
    /// (a quadruped hopping onto a stair's tread lands facing up the flight, where it could not turn round on the tread).
    /// </summary>
    private IEnumerable<(RoadmapNode Node, List<Move>? Moves)> Relandings(Jump? before, RoadmapNode current, float facing, IReadOnlySet<(int From, int To)>? rejected, IReadOnlyList<(int From, int To)> cut)
    {
        if (before is null)
        {
            yield break;
        }

        float toward = MathF.IEEERemainder(Way(before.Arc) - facing, 2f * MathF.PI);
        float sign = toward >= 0f ? 1f : -1f;
        float[] yaws = Far(before) ? [.. RelandYaws.Select(y => y * sign)] : [.. Yaws, .. WideYaws];
        EndpointPlacement placed = _scene.Sampler.PlaceFacingWithin(Standing(current), Placement, facing, yaws, _canStand, Height(_scene.Sampler, current), Leans(current));
        if (placed.Pose is not { } pose || Refused(pose.Pose))
        {
            yield break;
        }

        var node = new RoadmapNode(_nextId++, pose.Pose, pose.Cone, pose.Contacts);
        if (rejected?.Contains((before.From.Id, node.Id)) == true
            || _scene.Steering.SteerRemembered(before.From.Pose, before.From.Cone, node.Pose, node.Cone) is not { Succeeded: true } r
            || Off(node, Way(r.Arc)) > StillOffLanding
            || (Far(r.Arc) && Off(before.From, Way(r.Arc)) > StillOffTakeoff && Faces(before.From, before.To, before.Arc)))
        {
            // Not made: a jump landing off its way, or a hop (any way) lengthened into a jump taking off off its way.
            yield break;
        }

        IReadOnlyList<(int From, int To)> own = before.CutFrom.Count > 0 ? before.CutFrom : [(before.From.Id, before.To.Id)];
        Jump landing = new Jump(before.From, node, r.Arc) { CutFrom = [.. own.Union(cut)], HoppedFrom = before.HoppedFrom };

        _relanded = (node, landing);
        yield return (node, []);
    }

    /// <summary>Angles (radians) between a landing's heading and the way of a jump swung to meet it (<see cref="Swing"/>), tried in order: within the eye's 45°, nearest the jump's own way first.</summary>
    private static readonly float[] SwingYaws = [40f * MathF.PI / 180f, 30f * MathF.PI / 180f];

    /// <summary>Lengths across (shares of the jump's own, between contact centres) of a jump swung to meet its landing, tried in order.</summary>
    private static readonly float[] SwingReach = [1f, 0.8f, 1.25f];

    /// <summary>The first id the last <see cref="Face"/> gave a stance it placed.</summary>
    private int _firstPlaced;

    /// <summary>Whether a jump from a stance this facer places onto <paramref name="jump"/>'s landing was set aside already (a swung jump that did not animate): not swung again.</summary>
    private bool SwungBefore(Jump jump, IReadOnlySet<(int From, int To)>? rejected) =>
        rejected is { Count: > 0 } && rejected.Any(r => r.To == jump.To.Id && r.From >= _firstPlaced);

    /// <summary>
    /// Appends <see cref="Swing"/>'s jump onto <paramref name="jump"/>'s landing to <paramref name="result"/> with the
    /// walk into its takeoff (the walk before steered again, or a new one from <paramref name="current"/>) and returns
    /// that landing; <c>null</c> (and <paramref name="result"/> unchanged) for a request that does not walk or when none steers.
    /// </summary>
    private RoadmapNode? Swung(Jump jump, RoadmapNode current, List<Move> result, IReadOnlySet<(int From, int To)>? rejected, IReadOnlyList<(int From, int To)> cut)
    {
        if (!_walking || Swing(jump, current, result, rejected, cut) is not var (swung, into, replaces))
        {
            return null;
        }

        if (replaces)
        {
            result[^1] = into;
        }
        else
        {
            result.Add(into);
        }

        _placedGoal = null;
        _turnBack = null;
        result.Add(swung);
        return swung.To;
    }

    /// <summary>
    /// A jump onto <paramref name="jump"/>'s own landing swung round toward the way that landing faces, when it cannot
    /// be turned to face the jump (a stance across a stair's tread): its way at most <see cref="SwingYaws"/> off the
    /// landing's heading, on the side of the jump's own way, as long across as the jump (<see cref="SwingReach"/>);
    /// taken off from a stance placed facing that way (<see cref="Yaws"/>) at the takeoff's height, to which the walk
    /// before the jump is steered again (<c>Replaces</c>), or a walk from <paramref name="current"/> leads. Steered
    /// like any jump (cones, speed limits, trunk sweep), and taken only when it takes off and lands within the eye's
    /// bounds (<see cref="StillOff(Jump)"/>); <c>null</c> when none is.
    /// </summary>
    private (Jump Jump, Walk Into, bool Replaces)? Swing(Jump jump, RoadmapNode current, List<Move> result, IReadOnlySet<(int From, int To)>? rejected, IReadOnlyList<(int From, int To)> cut)
    {
        RoadmapNode landing = jump.To;
        Vector3 forward = landing.Pose.Forward;
        float heading = MathF.Atan2(forward.X, forward.Z);
        float side = MathF.IEEERemainder(Way(jump.Arc) - heading, 2f * MathF.PI) >= 0f ? 1f : -1f;
        Vector3 landed = Standing(landing);
        Vector3 stood = Standing(jump.From);
        float height = Height(_scene.Sampler, jump.From);
        bool leans = Leans(jump.From);
        Vector3 across = landed - stood;
        float length = new Vector2(across.X, across.Z).Length();
        Walk? before = result.Count > 0 && result[^1] is Walk w && w.Via.Count == 0 ? w : null;
        foreach (float swing in SwingYaws)
        {
            float yaw = heading + (side * swing);
            var way = new Vector3(MathF.Sin(yaw), 0f, MathF.Cos(yaw));
            foreach (float reach in SwingReach)
            {
                Vector3 point = landed - (way * (reach * length));
                point.Y = stood.Y;
                EndpointPlacement placed = _scene.Sampler.PlaceFacingWithin(point, Placement, yaw, Yaws, _canStand, height, leans);
                if (placed.Pose is not { } pose || Refused(pose.Pose))
                {
                    continue;
                }

                var node = new RoadmapNode(_nextId++, pose.Pose, pose.Cone, pose.Contacts);
                if (rejected?.Contains((node.Id, landing.Id)) == true
                    || _scene.Steering.SteerRemembered(node.Pose, node.Cone, landing.Pose, landing.Cone) is not { Succeeded: true } r)
                {
                    continue;
                }

                Jump swung = new Jump(node, landing, r.Arc) { CutFrom = cut };
                if (StillOff(swung))
                {
                    continue;
                }

                if (before is not null && rejected?.Contains((before.From.Id, node.Id)) != true
                    && SteerWalk(before.From, node) is Walk steered)
                {
                    return (swung, steered with { CutFrom = [.. before.CutFrom.Union(cut)], HoppedFrom = before.HoppedFrom }, true);
                }

                if (rejected?.Contains((current.Id, node.Id)) != true && SteerWalk(current, node) is Walk walk)
                {
                    return (swung, walk with { CutFrom = cut }, false);
                }
            }
        }

        return null;
    }

    /// <summary>Whether <paramref name="pose"/> is where the body could not crouch or absorb for a faced jump before (<see cref="QuerySettings.RefusedTurns"/>).</summary>
    private bool Refused(RootPose pose)
    {
        // A loop, not Any with a lambda: a closure per call, on every placement the facer recalls.
        for (int i = 0; i < _refused.Count; i++)
        {
            if (JumpRepair.IsRefused(_refused[i], pose))
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>Yaws (radians, from the jump's direction) a new stance is tried at when none at <see cref="Yaws"/> steers: still within the eye's 30° at takeoff.</summary>
    internal static readonly float[] WideYaws = [20f * MathF.PI / 180f, -20f * MathF.PI / 180f];

    /// <summary><see cref="Yaws"/>, then <see cref="WideYaws"/>: the yaw sets a new stance is placed at, in order (declared after both, so that both are set).</summary>
    private static readonly float[][] YawSets = [Yaws, WideYaws];

    /// <summary>The trunk's height (metres) above where <paramref name="node"/> stands (<see cref="TrunkSampler.StandingCentre"/>): a stance replacing it stands as high (a cave's ceiling, a doorway).</summary>
    internal static float Height(TrunkSampler sampler, RoadmapNode node) => node.Pose.Position.Y - sampler.StandingCentre(node.Contacts, node.Pose.Position).Y;

    /// <summary>
    /// Where <paramref name="node"/> stands (world metres, <see cref="TrunkSampler.StandingCentre"/>: the centre of its
    /// contacts but a hand leaning on something higher than a step above its feet). A stance turned in the place of
    /// one that leans so stands within <see cref="Placement"/> of it, measured the same way (<see cref="Leans"/>); of
    /// one that does not, its contacts' centre does, as before. Measured by all its contacts, a stance leaning a hand
    /// on a block's top beside its feet stood a third of the block's height above the ground, where no stance on its
    /// feet alone came within the tolerance: of the 916 turned stances 2,000 new node-to-node requests on the desert
    /// placed in vain, each after trying every spot, yaw and lift, 568 had stood within it across but not up and down
    /// (two fifths of the requests' time went to those 568).
    /// </summary>
    private Vector3 Standing(RoadmapNode node) => _scene.Sampler.StandingCentre(node.Contacts, node.Pose.Position);

    /// <summary>
    /// Whether <paramref name="node"/> leans a hand on something (<see cref="Standing"/> is not its contacts' centre):
    /// then its turned stances are measured by where they stand, a turn leaning on the block as well as one on its feet
    /// alone. A stance that leans on nothing is turned as before, into a stance whose contacts' centre stands where its
    /// did: measured where it stands, a turn leaning a hand on a block beside it was taken first (the skeleton's jump up
    /// onto the block level's block), and that turn could not take off.
    /// </summary>
    private bool Leans(RoadmapNode node) => Standing(node) != node.ContactCentre;

    /// <summary>How far (metres) from a stance a stance turned by a hop is placed, along the jump: a hop in place needs some ground to cover to stay long enough in the air.</summary>
    public const float HopShift = 0.15f;

    /// <summary>The shortest flight (seconds) of a hop in place: time for the limbs to leave and land again.</summary>
    public const float MinHopFlight = 0.2f;

    /// <summary>
    /// The moves turning in place from <paramref name="from"/> to <paramref name="to"/> (two stances at nearly the
    /// same spot): a turn walk for a walking request where the ground is walked, else a hop in place; <c>null</c>
    /// when neither passes its checks.
    /// </summary>
    private List<Move>? Link(RoadmapNode from, RoadmapNode to, IReadOnlySet<(int From, int To)>? rejected, IReadOnlyList<(int From, int To)> cut)
    {
        if (from.Id == to.Id)
        {
            return [];
        }

        if (rejected?.Contains((from.Id, to.Id)) == true)
        {
            return null;
        }

        if (!_hops && _scene.Walking.Turn(from, to, MaxTurnShift) is Walk turn)
        {
            return [turn with { CutFrom = cut }];
        }

        // A hop the body cannot push off for or absorb (its arc is the steepest the cones allow, at their edge) is no turn.
        SteeringResult hop = _scene.Steering.SteerRemembered(from.Pose, from.Cone, to.Pose, to.Cone, steep: true);
        return hop.Succeeded && hop.Arc.FlightTime >= MinHopFlight
            && _canPush?.Invoke(from.Pose, from.Contacts, hop.Arc.TakeoffVelocity) != false
            && _canPush?.Invoke(to.Pose, to.Contacts, -hop.Arc.LandingVelocity) != false
            ? [new Jump(from, to, hop.Arc) { CutFrom = cut }]
            : null;
    }

    /// <summary>
    /// No moves (<c>[]</c>) when <paramref name="next"/>, the jump after one whose landing is turned to
    /// <paramref name="landing"/>, can be steered from there instead of from its own takeoff
    /// (<see cref="Restart"/>: cones, speed limits, trunk sweep) and then reads as facing its way
    /// (<see cref="Faces"/>): the path goes on from the turned landing without turning back. Otherwise <c>null</c>.
    /// A landing at a brink may be one the body cannot absorb a hop in place onto, where the jump on from it passes.
    /// </summary>
    private List<Move>? GoOn(RoadmapNode landing, Jump next, IReadOnlySet<(int From, int To)>? rejected) =>
        Restart(next, landing, rejected) is Jump restarted && Faces(landing, next.To, restarted.Arc) ? [] : null;

    /// <summary>
    /// Landings placed where <paramref name="old"/> stands (<see cref="Placements"/>) from which the jump after,
    /// <paramref name="next"/>, goes on (<see cref="GoOn"/>), when that jump travels <see cref="MinDistance"/> or more
    /// and would take off from <paramref name="old"/> more than <see cref="StillOffTakeoff"/> off its way: a landing
    /// turned to face this jump then also serves the next. Tried once no landing that turns back into the old one
    /// steers, since a jump going on from a new stance may not animate where the turn back would.
    /// </summary>
    private IEnumerable<(RoadmapNode Node, List<Move>? Moves)> GoingOn(RoadmapNode old, float facing, Move? next, IReadOnlySet<(int From, int To)>? rejected) =>
        next is Jump after && Far(after) && Off(old, Way(after.Arc)) > StillOffTakeoff ? Placements(old, facing, -1f, node => GoOn(node, after, rejected)) : [];

    /// <summary>
    /// The moves turning from the turned landing <paramref name="from"/> back into the stance <paramref name="to"/> it
    /// replaced: those found when it was placed (it was only placed when they passed their checks).
    /// </summary>
    private List<Move> TurnBack(RoadmapNode from, RoadmapNode to, IReadOnlySet<(int From, int To)>? rejected, IReadOnlyList<(int From, int To)> cut) =>
        _turnBack is { } back && ReferenceEquals(back.From, from) ? back.Moves : Link(from, to, rejected, cut)!;

    /// <summary>Whether <paramref name="jump"/> joins two stances this facer did not place (a jump of the searched path, not a turn hop).</summary>
    private bool Searched(Jump jump) => jump.From.Id < _firstPlaced && jump.To.Id < _firstPlaced;

    /// <summary>Whether two stances are the same one (a goal placed again keeps its id, not its pose).</summary>
    private static bool Same(RoadmapNode a, RoadmapNode b) => a.Id == b.Id && a.Pose == b.Pose;

    /// <summary>The angle (radians, 0 to π) between a stance's heading and the yaw <paramref name="facing"/>.</summary>
    private static float Off(RoadmapNode node, float facing)
    {
        Vector3 f = node.Pose.Forward;
        float yaw = MathF.Atan2(f.X, f.Z);
        float d = MathF.Abs(yaw - facing) % (2f * MathF.PI);
        return d > MathF.PI ? (2f * MathF.PI) - d : d;
    }
}
