using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Query;

/// <summary>
/// The lazy-repair record of one path request: the jumps set aside because the whole body could not perform them,
/// the set a search must avoid, and the reasons a request that never animates cleanly reports. Shared by
/// <see cref="AnimatedPlanner"/> and the runtime's path requests so both repair and explain alike. A request that
/// walks and jumps falls back to jumps only once its walks failed to animate in <see cref="WalkRounds"/> rounds: walking
/// is an improvement of the route, never a reason for a request to fail where the jump planner alone succeeds. Likewise
/// a move cut from a jump (<see cref="Move.CutFrom"/>: cut down, or turned to face its way) that does not animate
/// gives the jump back whole and as searched, and after <see cref="CutRounds"/> such rounds no jump is cut or turned
/// (counted afresh once the request searches jumps only); but a walk between a stance placed for a turned jump and one
/// the search gave, failing only far from the placed one, hops over where it failed and keeps the jump turned
/// (the searched walk would step there alike). A walk whose problems the animator places on its path keeps
/// being walked but hops over those spots (<see cref="HopSpots"/>, <see cref="QuerySettings.HopSpots"/>), for
/// <see cref="HopRounds"/> rounds; a hop that does not animate either sets the walk aside. A walk failing again at a
/// spot in the round that would end walking (its hop failed there, or hopping is spent) bars that spot to walks
/// instead (<see cref="NoWalkSpots"/>, for <see cref="NoWalkRounds"/> rounds): the request jumps there and walks
/// everywhere else. A stance the body cannot
/// crouch on (or absorb a landing on), or where no limb reaches the level, is set aside as a takeoff (a landing) for
/// every jump, since each would have the same contact pose there (<see cref="NoTakeoffs"/>, <see cref="NoLandings"/>); walks still use it.
/// Such stances found by earlier requests can be set aside before the first search (<see cref="Remember"/>: the
/// runtime's worlds do). Not thread-safe.
/// </summary>
internal sealed class JumpRepair
{
    /// <summary>Rounds with a walk that did not animate cleanly after which a request searches jumps only.</summary>
    public const int WalkRounds = 2;

    /// <summary>Rounds with a move cut from a jump (<see cref="Move.CutFrom"/>) that did not animate cleanly after which jumps are no longer cut.</summary>
    public const int CutRounds = 4;

    /// <summary>Rounds that added spots to hop over (<see cref="HopSpots"/>) after which walk problems set walks aside again.</summary>
    public const int HopRounds = 4;

    /// <summary>Rounds that added ground no longer walked over (<see cref="NoWalkSpots"/>) after which a walk failing there counts toward <see cref="WalkRounds"/> again.</summary>
    public const int NoWalkRounds = 4;

    private readonly HashSet<(int From, int To)> _excluded = [];
    private readonly List<Vector3> _spots = [];
    private readonly List<Vector3> _noWalk = [];
    private int _walksSetAside;
    private readonly HashSet<(int From, int To)> _uncut = [];
    private readonly HashSet<(int From, int To)> _unfaced = [];
    private readonly List<RejectedJump> _setAside = [];
    private readonly HashSet<int> _noTakeoffs = [];
    private readonly HashSet<int> _noLandings = [];

    /// <summary>Why each stance of <see cref="_noTakeoffs"/> and <see cref="_noLandings"/> was set aside (the animator's first problem there), by node id.</summary>
    private readonly Dictionary<int, string> _takeoffReasons = [];
    private readonly Dictionary<int, string> _landingReasons = [];

    /// <summary>Stances set aside before the first search (<see cref="Remember"/>), in order: what the request knew from others.</summary>
    private readonly List<(int Node, ProblemStance Stance, string Reason)> _remembered = [];
    private readonly List<RootPose> _refusedTurns = [];
    private readonly int _placedFrom;

    /// <summary>Creates the repair record of one request.</summary>
    /// <param name="placedFrom">
    /// The first node id of stances placed for the request after its search (the roadmap's node count plus two: the
    /// tightener's and the facer's), whose poses <see cref="RefusedTurns"/> may hold; by default none is refused.
    /// </param>
    public JumpRepair(int placedFrom = int.MaxValue)
    {
        _placedFrom = placedFrom;
    }

    /// <summary>Moves (jumps or walks: from node id, to node id) the next search must not use.</summary>
    public IReadOnlySet<(int From, int To)> Excluded => _excluded;

    /// <summary>Stances (node ids) no jump of the next searches takes off from: the body could not crouch on them.</summary>
    public IReadOnlySet<int> NoTakeoffs => _noTakeoffs;

    /// <summary>Stances (node ids) no jump of the next searches lands on: the body could not absorb a landing on them.</summary>
    public IReadOnlySet<int> NoLandings => _noLandings;

    /// <summary>
    /// Stances placed for the request after its search (root poses) on which the body could not crouch for a cut or
    /// faced jump's takeoff, or absorb its landing, or next to which a limb hit the level in flight (a spider's front
    /// leg, free against a face it jumps up): the next searches' facer places its next stance instead
    /// (<see cref="QuerySettings.RefusedTurns"/>).
    /// </summary>
    public IReadOnlyList<RootPose> RefusedTurns => _refusedTurns;

    /// <summary>The jumps set aside so far, in order, each with the animator's reason.</summary>
    public IReadOnlyList<RejectedJump> SetAside => _setAside;

    /// <summary>Rounds so far in which a walk of the path did not animate cleanly.</summary>
    public int WalkFailures { get; private set; }

    /// <summary>False once walks failed to animate in <see cref="WalkRounds"/> rounds: the next searches use jumps only.</summary>
    public bool WalksAllowed => WalkFailures < WalkRounds;

    /// <summary>Jumps (takeoff id, landing id, as searched) whose cut-down moves did not animate: the next searches keep them whole.</summary>
    public IReadOnlySet<(int From, int To)> Uncut => _uncut;

    /// <summary>
    /// Jumps (takeoff id, landing id, as searched) given back whole (<see cref="Uncut"/>) whose moves, turned by hops
    /// to face their way, did not animate either: the next searches fly them as searched.
    /// </summary>
    public IReadOnlySet<(int From, int To)> Unfaced => _unfaced;

    /// <summary>Rounds so far in which a move cut from a jump did not animate cleanly.</summary>
    public int CutFailures { get; private set; }

    /// <summary>
    /// False once moves cut from jumps failed to animate in <see cref="CutRounds"/> rounds: the next searches cut no
    /// jump. Rounds counted while the request still walked do not count once it searches jumps only
    /// (<see cref="WalksAllowed"/> false): its jumps are turned to face their way again, by hops, for as many rounds.
    /// </summary>
    public bool CuttingAllowed => CutFailures - _cutFailuresWalking < CutRounds;

    /// <summary>The rounds whose cut moves failed before the request searched jumps only (0 while it walks).</summary>
    private int _cutFailuresWalking;

    /// <summary>Ground points (world metres) where a walk's body could not walk, in the order found: the next searches hop over them.</summary>
    public IReadOnlyList<Vector3> HopSpots => _spots;

    /// <summary>Rounds so far that added spots to <see cref="HopSpots"/>.</summary>
    public int HopFailures { get; private set; }

    /// <summary>False once <see cref="HopRounds"/> rounds added spots: a walk's problems then set it aside.</summary>
    public bool HoppingAllowed => HopFailures < HopRounds;

    /// <summary>
    /// Ground points (world metres) where a walk failed again after a hop over them was tried (or hopping is spent):
    /// the next searches walk nowhere near them (<see cref="QuerySettings.NoWalkSpots"/>) and jump there instead,
    /// walking elsewhere, rather than give up walking everywhere.
    /// </summary>
    public IReadOnlyList<Vector3> NoWalkSpots => _noWalk;

    /// <summary>Rounds so far that added spots to <see cref="NoWalkSpots"/>.</summary>
    public int NoWalkFailures { get; private set; }

    /// <summary>False once <see cref="NoWalkRounds"/> rounds added ground no longer walked over: a walk failing at a known spot then counts toward <see cref="WalkRounds"/>.</summary>
    public bool BarringAllowed => NoWalkFailures < NoWalkRounds;

    /// <summary>
    /// True when a request that has searched <paramref name="searches"/> times has no search left of
    /// <paramref name="limit"/>: the rounds whose walks failed (at most <see cref="WalkRounds"/>), whose cut moves
    /// failed (<see cref="CutRounds"/>) or that found spots to hop over (<see cref="HopRounds"/>) do not count, so the
    /// jumps-only fallback has every round.
    /// </summary>
    public bool IsExhausted(int searches, int limit) => searches - WalkFailures - CutFailures - HopFailures - NoWalkFailures >= limit;

    /// <summary>
    /// The settings of the next search: <paramref name="settings"/>, with <see cref="Locomotion.Jump"/> once
    /// <see cref="WalksAllowed"/> is false, the jumps in <see cref="Uncut"/> kept whole, no jump cut once
    /// <see cref="CuttingAllowed"/> is false, the walks hopping over <see cref="HopSpots"/>, and no jump from
    /// <see cref="NoTakeoffs"/> or to <see cref="NoLandings"/>.
    /// </summary>
    public QuerySettings Adjust(QuerySettings settings)
    {
        ArgumentNullException.ThrowIfNull(settings);
        if (!WalksAllowed && settings.Locomotion != Locomotion.Jump)
        {
            settings = settings with { Locomotion = Locomotion.Jump };
        }

        if (!CuttingAllowed && (settings.TightenJumps || settings.FaceJumps))
        {
            settings = settings with { TightenJumps = false, FaceJumps = false, PreferFacedJumps = true };
        }

        if (_spots.Count > 0)
        {
            settings = settings with { HopSpots = [.. _spots] };
        }

        if (_noWalk.Count > 0)
        {
            settings = settings with { NoWalkSpots = [.. _noWalk] };
        }

        if (_unfaced.Count > 0)
        {
            settings = settings with { UnfacedJumps = _unfaced };
        }

        if (_refusedTurns.Count > 0)
        {
            settings = settings with { RefusedTurns = [.. _refusedTurns] };
        }

        if (_noTakeoffs.Count > 0 || _noLandings.Count > 0)
        {
            settings = settings with { NoTakeoffs = _noTakeoffs, NoLandings = _noLandings };
        }

        return _uncut.Count == 0 ? settings : settings with { UncutJumps = _uncut };
    }

    /// <summary>
    /// Sets aside every move (jump or walk) of <paramref name="path"/> that <paramref name="animation"/> reports a
    /// problem with; for a jump cut from jumps (<see cref="Move.CutFrom"/>) whose takeoff (landing) was placed for it
    /// and cannot crouch (absorb), refuses that stance instead, once (<see cref="RefusedTurns"/>), and a walk made from
    /// the same jumps into or out of that stance is not given back for failing with it; for any other move cut from
    /// jumps, keeps those jumps whole instead (and, for jumps already kept whole by an earlier animation, leaves them
    /// unturned: <see cref="Unfaced"/>; several moves of one jump failing in this animation are one failure); for a
    /// walk whose every problem has a place on its path, adds those places to <see cref="HopSpots"/> instead (while
    /// <see cref="HoppingAllowed"/>, and unless a spot is already known: the hop there did not pass); for a move of a
    /// hop (<see cref="Move.HoppedFrom"/>) that cannot, sets the walks it stands in for aside; for a searched jump whose
    /// every problem is its takeoff's crouch or its landing's absorption, sets that stance aside as a takeoff or a
    /// landing instead (<see cref="NoTakeoffs"/>, <see cref="NoLandings"/>).
    /// </summary>
    /// <param name="path">The path that was animated.</param>
    /// <param name="animation">Its animation; problems index moves of <paramref name="path"/>.</param>
    /// <returns>How many moves were newly set aside, kept whole or hopped over.</returns>
    public int Reject(IReadOnlyList<Move> path, JumpAnimation animation)
    {
        ArgumentNullException.ThrowIfNull(path);
        ArgumentNullException.ThrowIfNull(animation);
        int added = 0;
        bool walkFailed = false;
        bool cutFailed = false;
        bool hopped = false;
        bool barred = false;

        // Stances placed for a cut or faced jump on which the body cannot crouch (absorb), refused now: the next search
        // places another, and a walk made from the same jumps into (out of) one is made again with it.
        IGrouping<int, JumpProblem>[] groups = [.. animation.Problems.GroupBy(p => p.Jump)];
        var refusedNow = new HashSet<int>();
        var refusing = new HashSet<int>();
        var refusingCut = new HashSet<(int From, int To)>();
        foreach (IGrouping<int, JumpProblem> problems in groups)
        {
            Move move = path[problems.Key];
            if (move is Jump && move.CutFrom.Count > 0 && RefuseTurns(move, problems, refusedNow))
            {
                refusing.Add(problems.Key);
                refusingCut.UnionWith(move.CutFrom);
            }
        }

        // Jumps given back by this animation: several of the moves made from one jump failing are one failure of it.
        var givenNow = new HashSet<(int From, int To)>();
        foreach (IGrouping<int, JumpProblem> problems in groups)
        {
            Move move = path[problems.Key];
            if (move is Walk away && move.CutFrom.Count > 0 && HoppingAllowed && AwayFromTurn(away, problems) && AddSpots(away, problems))
            {
                // A walk made from a turned stance that fails far from it, toward a stance the search gave: the same
                // walk would fail there whatever the turn; it hops over the spot, and its jump stays turned.
                hopped = true;
                added++;
                continue;
            }

            if (move.CutFrom.Count > 0)
            {
                cutFailed = true;
                if (refusing.Contains(problems.Key))
                {
                    // The body cannot crouch (absorb) on a stance placed for this jump: the next search turns it another way.
                    Record(move, problems.First().Reason);
                    added++;
                    continue;
                }

                if (move is Walk && move.CutFrom.All(refusingCut.Contains) && (refusedNow.Contains(move.To.Id) || refusedNow.Contains(move.From.Id)))
                {
                    // A walk into (out of) a stance refused now, made from the same jumps: not given back for it.
                    continue;
                }

                bool kept = false;
                foreach ((int, int) jump in move.CutFrom)
                {
                    // Given back once (kept whole, turned by hops only); failing again, flown as searched.
                    if (givenNow.Contains(jump) || _uncut.Add(jump) || _unfaced.Add(jump))
                    {
                        kept |= givenNow.Add(jump);
                    }
                }

                if (kept)
                {
                    Record(move, problems.First().Reason);
                    added++;
                }

                continue;
            }

            if (move is Jump && move.CutFrom.Count == 0 && move.HoppedFrom.Count == 0 && problems.All(p => p.Stance != ProblemStance.None))
            {
                bool stance = false;
                foreach (JumpProblem p in problems)
                {
                    stance |= SetStanceAside(p.Stance == ProblemStance.Takeoff ? move.From.Id : move.To.Id, p.Stance, p.Reason);
                }

                if (stance)
                {
                    Record(move, problems.First().Reason);
                    added++;
                    continue;
                }
            }

            if (move is Walk walk && HoppingAllowed && problems.All(p => p.IsLocated) && AddSpots(walk, problems))
            {
                hopped = true;
                added++;
                continue;
            }

            // A walk failing where a hop was tried (or hopping is spent) in the round that would end walking: set aside
            // as any failed move, and no walk goes there any more, the request jumping there and walking elsewhere,
            // instead of giving up walking everywhere.
            bool barring = move is Walk again && move.HoppedFrom.Count == 0 && WalkFailures + 1 >= WalkRounds && BarringAllowed
                && problems.All(p => p.IsLocated) && Bar(again, problems);
            barred |= barring;
            walkFailed |= !barring && (move is Walk || move.HoppedFrom.Count > 0);
            bool any = barring;
            if (move.HoppedFrom.Count > 0)
            {
                foreach ((int, int) searched in move.HoppedFrom)
                {
                    any |= _excluded.Add(searched);
                }
            }
            else
            {
                any |= _excluded.Add((move.From.Id, move.To.Id));
                if (move is Walk segments)
                {
                    foreach ((int from, int to) in segments.Segments)
                    {
                        any |= _excluded.Add((from, to));
                    }
                }
            }

            if (any)
            {
                Record(move, problems.First().Reason);
                added++;
            }
        }

        bool walked = WalksAllowed;
        WalkFailures += walkFailed ? 1 : 0;
        CutFailures += cutFailed ? 1 : 0;
        if (walked && !WalksAllowed)
        {
            // From now on jumps only: the cut and turned moves that failed were made for walks.
            _cutFailuresWalking = CutFailures;
        }

        HopFailures += hopped ? 1 : 0;
        NoWalkFailures += barred ? 1 : 0;
        return added;
    }

    /// <summary>
    /// Adds the ends of <paramref name="move"/> the animator blames (the takeoff or landing its stance problems name:
    /// the body cannot crouch or absorb there; or the one a limb hits the level next to, just after leaving it or
    /// just before reaching it, <see cref="JumpProblem.Near"/>) that were placed for the request after its search (by the facer or the
    /// tightener) to <see cref="RefusedTurns"/>, and the new ones' ids to <paramref name="refused"/>; true when one is new.
    /// </summary>
    private bool RefuseTurns(Move move, IEnumerable<JumpProblem> problems, HashSet<int> refused)
    {
        bool takeoff = problems.Any(p => p.Stance == ProblemStance.Takeoff || p.Near == ProblemStance.Takeoff);
        bool landing = problems.Any(p => p.Stance == ProblemStance.Landing || p.Near == ProblemStance.Landing);
        bool refusedTakeoff = takeoff && move.From.Id >= _placedFrom && RefuseTurn(move.From.Pose);
        bool refusedLanding = landing && move.To.Id >= _placedFrom && RefuseTurn(move.To.Pose);
        if (refusedTakeoff)
        {
            refused.Add(move.From.Id);
        }

        if (refusedLanding)
        {
            refused.Add(move.To.Id);
        }

        return refusedTakeoff || refusedLanding;
    }

    private bool RefuseTurn(RootPose pose)
    {
        if (_refusedTurns.Any(r => IsRefused(r, pose)))
        {
            return false;
        }

        _refusedTurns.Add(pose);
        return true;
    }

    /// <summary>Whether <paramref name="pose"/> is the refused turn <paramref name="refused"/>: within 2 cm and 2°.</summary>
    internal static bool IsRefused(RootPose refused, RootPose pose) =>
        Vector3.Distance(refused.Position, pose.Position) <= 0.02f && MathF.Abs(Quaternion.Dot(refused.Rotation, pose.Rotation)) >= MathF.Cos(1f * MathF.PI / 180f);

    /// <summary>Lists <paramref name="move"/> among the moves set aside, counting walks apart from jumps for the messages.</summary>
    private void Record(Move move, string reason)
    {
        _setAside.Add(new RejectedJump(move.From, move.To, reason) { IsWalk = move is Walk });
        _walksSetAside += move is Walk ? 1 : 0;
    }

    /// <summary>
    /// True when <paramref name="walk"/> leaves (reaches) a stance placed for the request and ends (starts) on one the
    /// search gave, and every one of its problems lies on its path at least <see cref="AwayShare"/> of its length and
    /// <see cref="AwayLeast"/> from the placed end: near the other end, where the walk steps as the searched one would.
    /// </summary>
    private bool AwayFromTurn(Walk walk, IEnumerable<JumpProblem> problems)
    {
        bool placedStart = walk.From.Id >= _placedFrom;
        bool placedEnd = walk.To.Id >= _placedFrom;
        if (placedStart == placedEnd)
        {
            return false;
        }

        float least = MathF.Max(AwayLeast, AwayShare * walk.Length);
        return problems.All(p => p.IsLocated && (placedStart ? p.Along : walk.Length - p.Along) >= least);
    }

    /// <summary>Least share of a walk's length between its problems and the placed stance it leaves or reaches, for <see cref="AwayFromTurn"/>.</summary>
    private const float AwayShare = 0.5f;

    /// <summary>Least distance (metres, along the walk) between its problems and the placed stance it leaves or reaches, for <see cref="AwayFromTurn"/>.</summary>
    private const float AwayLeast = 0.5f;

    /// <summary>Adds the ground points of <paramref name="problems"/> on <paramref name="walk"/> to <see cref="HopSpots"/>; true when each is new (none within <see cref="JumpTightener.SpotRadius"/> of a known one).</summary>
    private bool AddSpots(Walk walk, IEnumerable<JumpProblem> problems)
    {
        Vector3[] found = [.. problems.Select(p => walk.PointAt(p.Along))];
        if (found.Any(f => Known(_spots, f)))
        {
            return false;
        }

        _spots.AddRange(found);
        return true;
    }

    /// <summary>Adds the ground points of <paramref name="problems"/> on <paramref name="walk"/> to <see cref="NoWalkSpots"/>; true when one is new (none within <see cref="JumpTightener.SpotRadius"/> of a known one).</summary>
    private bool Bar(Walk walk, IEnumerable<JumpProblem> problems)
    {
        bool any = false;
        foreach (Vector3 found in problems.Select(p => walk.PointAt(p.Along)))
        {
            if (!Known(_noWalk, found))
            {
                _noWalk.Add(found);
                any = true;
            }
        }

        return any;
    }

    /// <summary>True when one of <paramref name="spots"/> lies within <see cref="JumpTightener.SpotRadius"/> of <paramref name="point"/>, seen from above.</summary>
    private static bool Known(List<Vector3> spots, Vector3 point) =>
        spots.Exists(s => new Vector2(s.X - point.X, s.Z - point.Z).Length() <= JumpTightener.SpotRadius);

    /// <summary>
    /// The reason of a request whose search failed with <paramref name="searchReason"/> after jumps were set aside;
    /// <c>null</c> when none were (the search's own status and reason then stand).
    /// </summary>
    public string? SearchFailed(string searchReason) =>
        _setAside.Count > 0 ? $"no path animates cleanly: {SetAsideCount()} set aside ({First()}) and then {searchReason}"
        : _remembered.Count > 0 ? $"no path animates cleanly: {Remembered()} and then {searchReason}"
        : null;

    /// <summary>
    /// Sets aside, before the first search, a stance an earlier request found the body cannot crouch on
    /// (<paramref name="stance"/> <see cref="ProblemStance.Takeoff"/>: no jump takes off from it) or absorb a landing on
    /// (<see cref="ProblemStance.Landing"/>), with the animator's <paramref name="reason"/>: the stance's contact pose
    /// is the same for every jump and every request, so the request need not animate a path to find it again. Only for
    /// stances of the roadmap searched (node ids below its node count), whose ids every request shares.
    /// </summary>
    /// <param name="node">The stance's node id.</param>
    /// <param name="stance">Set aside as a takeoff or as a landing.</param>
    /// <param name="reason">The animator's reason.</param>
    internal void Remember(int node, ProblemStance stance, string reason)
    {
        if (stance != ProblemStance.None && SetStanceAside(node, stance, reason))
        {
            _remembered.Add((node, stance, reason));
        }
    }

    /// <summary>Sets stance <paramref name="node"/> aside as a takeoff or a landing (<paramref name="stance"/>) with the animator's first <paramref name="reason"/> there; false when it already was.</summary>
    private bool SetStanceAside(int node, ProblemStance stance, string reason)
    {
        bool takeoff = stance == ProblemStance.Takeoff;
        if (!(takeoff ? _noTakeoffs : _noLandings).Add(node))
        {
            return false;
        }

        (takeoff ? _takeoffReasons : _landingReasons)[node] = reason;
        return true;
    }

    /// <summary>The node id of the stance the request searches from (−1: unknown), named first among the stances it was told of (<see cref="Remember"/>) when it is one.</summary>
    internal int Start { get; set; } = -1;

    /// <summary>
    /// The stances this request set aside as takeoffs (<paramref name="stance"/> <see cref="ProblemStance.Takeoff"/>)
    /// or landings, by node id, with the animator's reason: those it found itself and those it was told
    /// (<see cref="Remember"/>). The record's own dictionary, for reading only (a concrete type, so that a caller
    /// enumerating it allocates nothing).
    /// </summary>
    internal Dictionary<int, string> StancesSetAside(ProblemStance stance) => stance == ProblemStance.Takeoff ? _takeoffReasons : _landingReasons;

    /// <summary>"no jump was searched from 1 stance the body cannot crouch on, as earlier requests found (stance 12: …)".</summary>
    private string Remembered()
    {
        int takeoffs = _remembered.Count(r => r.Stance == ProblemStance.Takeoff);
        int landings = _remembered.Count - takeoffs;
        string Stances(int n) => n == 1 ? "1 stance" : $"{n} stances";
        string which = takeoffs == 0 ? $"onto {Stances(landings)} the body cannot absorb a landing on"
            : landings == 0 ? $"from {Stances(takeoffs)} the body cannot crouch on"
            : $"from {Stances(takeoffs)} the body cannot crouch on or onto {Stances(landings)} it cannot absorb a landing on";
        // The request's own start first, when it is one: the reason its agent cannot leave.
        (int node, _, string reason) = _remembered.Find(r => r.Node == Start && r.Stance == ProblemStance.Takeoff) is { Reason: not null } own ? own : _remembered[0];
        return $"no jump was searched {which}, as earlier requests found (stance {node}: {reason}{(_remembered.Count > 1 ? "; …" : "")})";
    }

    /// <summary>The reason of a request whose every search, <paramref name="rounds"/> of them, gave a path that did not animate cleanly.</summary>
    public string RoundsExhausted(int rounds) => $"no path animated cleanly in {rounds} searches: {SetAsideCount()} set aside ({First()})";

    /// <summary>What to add to a success's reason: empty, or that some jumps were set aside first.</summary>
    public string SuccessNote() => _setAside.Count == 0 ? "" : $" after setting aside {SetAsideCount()} the body could not perform";

    /// <summary>"1 jump", "3 jumps".</summary>
    internal static string Jumps(int count) => count == 1 ? "1 jump" : $"{count} jumps";

    /// <summary>"2 jumps", "1 walk", "1 jump and 2 walks": the moves set aside so far.</summary>
    private string SetAsideCount()
    {
        int jumps = _setAside.Count - _walksSetAside;
        string walks = _walksSetAside == 1 ? "1 walk" : $"{_walksSetAside} walks";
        return _walksSetAside == 0 ? Jumps(jumps) : jumps == 0 ? walks : $"{Jumps(jumps)} and {walks}";
    }

    private string First() => _setAside.Count == 0 ? "none" : _setAside[0].Reason + (_setAside.Count > 1 ? "; …" : "");
}
