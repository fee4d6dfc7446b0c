using System.Numerics;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Sampling;

namespace Ballistic.Planner.Query;

/// <summary>Parameters of a path query.</summary>
public sealed record QuerySettings
{
    /// <summary>How close the start and goal stances' contacts must come to the requested points (<see cref="TrunkSampler.Place"/>).</summary>
    public EndpointTolerance Tolerance { get; init; } = new();

    /// <summary>
    /// An extra check the start and goal stances must pass (the whole body can stand there), or <c>null</c>.
    /// <see cref="Query.AnimatedPlanner"/> sets it to its animator's <see cref="Animation.IJumpAnimator.CanStand"/>, for
    /// the bake and the query alike, so that both place the same stances. A function of the pose alone (the same
    /// pose, the same answer): the stances a query places facing a way are remembered by the scene, per delegate, and
    /// served again to later queries with an equal one.
    /// </summary>
    public Func<Contacts.PoseEvaluation, bool>? CanStand { get; init; }

    /// <summary>
    /// An extra check a hop turning the character in place to face a jump (<see cref="FaceJumps"/>) must pass at both
    /// ends: whether the whole body, its root at the stance's pose, pushes off with the hop's takeoff velocity (absorbs
    /// its landing velocity, given reversed; m/s, world frame) on the stance's contacts; <c>null</c> for none.
    /// <see cref="Query.AnimatedPlanner"/> sets it to its animator's <see cref="Animation.IJumpAnimator.CanPush"/>: a
    /// turn hop the body cannot perform is not made, the next placement is tried instead.
    /// </summary>
    public Func<RootPose, IReadOnlyList<Contacts.Contact>, Vector3, bool>? CanPush { get; init; }

    /// <summary>Start and goal are steered to and from at most this many nearest roadmap nodes within reach.</summary>
    public int MaxNeighbours { get; init; } = 32;

    /// <summary>Steering to (from) nearer nodes stops once the start (goal) has this many jumps into the roadmap.</summary>
    public int Connections { get; init; } = 4;

    /// <summary>
    /// When true, a requested point with a roadmap node standing within <see cref="Tolerance"/> of it (the one
    /// <see cref="Roadmaps.Roadmap.FindNode"/> finds: contact centre nearest the point) that passes
    /// <see cref="CanStand"/> is served by that node, with no placement and no steering: the request then costs about
    /// what a request between roadmap nodes costs. Off by default, because the stance then depends on the roadmap
    /// rather than on the point alone (<see cref="TrunkSampler.Place"/>): a query given the points a bake was given
    /// may start or end on another node than the one the bake placed there.
    /// </summary>
    public bool PreferRoadmapNodes { get; init; }

    /// <summary>
    /// Which moves the path may use: <see cref="Locomotion.WalkAndJump"/> (the default; walks only for a character
    /// whose <see cref="Characters.ReducedCharacter.Walking"/> says it walks) or <see cref="Locomotion.Jump"/> (the
    /// paper's jump-only planner).
    /// </summary>
    public Locomotion Locomotion { get; init; } = Locomotion.WalkAndJump;

    /// <summary>The default <see cref="JumpEffort"/>, seconds.</summary>
    public const float DefaultJumpEffort = 3.5f;

    /// <summary>The default <see cref="JumpHeightEffort"/>, seconds per metre.</summary>
    public const float DefaultJumpHeightEffort = 0.25f;

    /// <summary>
    /// What every jump costs beyond its flight time when walking is allowed, in seconds of walking (getting set,
    /// landing); <see cref="JumpHeightEffort"/> adds what its push costs. 3.5 s by default (<see cref="DefaultJumpEffort"/>). Not negative. Unused in
    /// <see cref="Locomotion.Jump"/> mode.
    /// </summary>
    public float JumpEffort { get; init; } = DefaultJumpEffort;

    /// <summary>
    /// What a jump costs on top of <see cref="JumpEffort"/> per metre of its takeoff's energy height
    /// (<see cref="Steering.BallisticArc.EnergyHeight"/>, |v|²/(2g): the apex's rise for a jump straight up, more for
    /// a long leap), in seconds of walking per metre: at 1 s/m a hop over a ditch (takeoff 3 m/s) costs half a second
    /// more, a vault whose trunk rises 2.4 m about three seconds more, so a path walks a moderate detour rather than
    /// vault. 0.25 s/m by default (<see cref="DefaultJumpHeightEffort"/>): with the default 3.5 s of
    /// <see cref="JumpEffort"/> a hop taking off at 3 m/s costs 3.6 s beyond its flight and a leap at 7 m/s 4.1 s (a
    /// flat 4 s each before 2026-12-02), so of two jumps that serve alike the lighter one is taken. Not negative.
    /// Unused in <see cref="Locomotion.Jump"/> mode.
    /// </summary>
    public float JumpHeightEffort { get; init; } = DefaultJumpHeightEffort;

    /// <summary>
    /// What a jump along <paramref name="arc"/> costs a search that walks, seconds: its flight time plus
    /// <see cref="JumpEffort"/> plus <see cref="JumpHeightEffort"/> per metre of its energy height.
    /// </summary>
    public float JumpCost(in Steering.BallisticArc arc) => JumpCost(arc, JumpEffort, JumpHeightEffort);

    /// <summary>A jump's cost with the efforts given (seconds, seconds per metre): the one formula every search uses.</summary>
    internal static float JumpCost(in Steering.BallisticArc arc, float effort, float heightEffort) =>
        arc.FlightTime + effort + (heightEffort * arc.EnergyHeight);

    /// <summary>A one-line problem with the jump costs (negative or not finite), or <c>null</c> when there is none.</summary>
    internal string? EffortProblem() => EffortProblem(JumpEffort, JumpHeightEffort);

    /// <summary>A one-line problem with the jump costs given (seconds, seconds per metre), or <c>null</c>: the one check the planner, the world and its kinds make.</summary>
    internal static string? EffortProblem(float effort, float heightEffort) =>
        !(effort >= 0f) || !float.IsFinite(effort) ? $"JumpEffort must be finite and not negative, not {effort} s"
        : !(heightEffort >= 0f) || !float.IsFinite(heightEffort) ? $"JumpHeightEffort must be finite and not negative, not {heightEffort} s/m"
        : null;

    /// <summary>
    /// A start or goal off the roadmap is linked by walks to and from roadmap nodes at most this far (metres,
    /// horizontally); <c>null</c> for the bake's default (<see cref="Planning.BakeSettings.DefaultMaxWalkDistance"/>).
    /// </summary>
    public float? MaxWalkDistance { get; init; }

    /// <summary>
    /// The longest walk (metres, horizontally) tried straight from the start to the goal and between the poses of a
    /// path when shortcutting it.
    /// </summary>
    public float MaxDirectWalk { get; init; } = 40f;

    /// <summary>
    /// When walking is allowed: after the search, replace stretches of the path by one direct walk (or jump) between
    /// non-adjacent poses when that takes less time (jump effort included), then join consecutive walks into one.
    /// </summary>
    public bool Shortcut { get; init; } = true;

    /// <summary>
    /// When walking is allowed: after the search (and shortcutting), cut each jump down to what the ground requires:
    /// its takeoff moves forward and its landing back along the jump's line, over ground the character can walk, and
    /// the path walks there instead (<see cref="JumpTightener"/>). The path then takes longer than the one searched
    /// (a metre walked is slower than a metre in the air) but jumps only over what cannot be walked. On by default.
    /// </summary>
    public bool TightenJumps { get; init; } = true;

    /// <summary>
    /// After the search (and cutting), turn each jump travelling about a metre or more to face the way it goes: a
    /// takeoff (landing) heading more than 20° (30°) off the jump's direction is replaced by a stance at the same spot
    /// facing the jump, which the character turns into in place (a turn walk, or a hop in place for a character that
    /// only jumps), each new stance and move checked like the roadmap's (<see cref="JumpFacer"/>). A jump whose turns
    /// do not pass is searched around when another path costs at most <see cref="PathQuery.FacingDetour"/> times the
    /// first (<see cref="PathQuery.FacingSearches"/>), else kept as searched. On by default; off for the paper's
    /// plans, whose stances face any way.
    /// </summary>
    public bool FaceJumps { get; init; } = true;

    /// <summary>
    /// In a walking search whose jumps are not turned afterwards (<see cref="FaceJumps"/> off), a jump travelling about
    /// a metre or more whose stances do not face its way costs <see cref="PathQuery.UnfacedJumpCost"/> more, so the
    /// search takes the roadmap's jumps that already face their way where one costs at most that much more. Set by
    /// the repair (<see cref="JumpRepair.Adjust"/>) when it stops turning jumps because turned ones failed to animate;
    /// off otherwise.
    /// </summary>
    internal bool PreferFacedJumps { get; init; }

    /// <summary>
    /// The shortest walk (metres, horizontally) <see cref="TightenJumps"/> adds before or after a jump (a hop over a
    /// spot, <see cref="HopSpots"/>, leaves half of it before or after itself): a stance is not moved less than this. A walk turns in place at both ends, so a shorter one shuffles more than it walks.
    /// Positive; 1 m by default.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException">Set to a value that is not a finite positive number.</exception>
    public float MinCutWalk
    {
        get => _minCutWalk;
        init => _minCutWalk = value > 0f && float.IsFinite(value) ? value : throw new ArgumentOutOfRangeException(nameof(MinCutWalk), value, "The shortest walk a cut adds must be a finite positive number of metres.");
    }

    private readonly float _minCutWalk = 1f;

    /// <summary>
    /// Jumps (takeoff id, landing id, as searched) <see cref="TightenJumps"/> must leave whole: those whose cut-down
    /// moves did not animate (the animated planner's repair fills it); <c>null</c> for none.
    /// </summary>
    public IReadOnlySet<(int From, int To)>? UncutJumps { get; init; }

    /// <summary>
    /// Jumps (takeoff id, landing id, as searched) <see cref="FaceJumps"/> must leave as searched: those given back
    /// whole (<see cref="UncutJumps"/>) whose moves turned by hops did not animate either (the animated
    /// planner's repair fills it); <c>null</c> for none.
    /// </summary>
    public IReadOnlySet<(int From, int To)>? UnfacedJumps { get; init; }

    /// <summary>
    /// Stances placed for the request after its search (their root poses, world frame) on which the body could not
    /// crouch for a faced jump's takeoff or absorb its landing (the animated planner's repair fills it): the
    /// <see cref="FaceJumps"/> facer places its next stance instead (facing further round, or a little along the
    /// jump), not one within 2 cm and 2° of these. <c>null</c> for none.
    /// </summary>
    public IReadOnlyList<RootPose>? RefusedTurns { get; init; }

    /// <summary>
    /// Ground points (world metres) where the body could not walk: the animated planner's repair fills it from where the
    /// animator located a walk's problem. When walking is allowed, after the search (and cutting), a walk passing
    /// within <see cref="JumpTightener.SpotRadius"/> of one (seen from above) hops over it: it walks to a takeoff
    /// before the spot, jumps, and walks on from a landing after it, each move checked like the roadmap's. A walk
    /// for which no hop passes the checks is kept as it is. <c>null</c> for none.
    /// </summary>
    public IReadOnlyList<Vector3>? HopSpots { get; init; }

    /// <summary>
    /// Ground points (world metres) where the body could neither walk nor hop over (the animated planner's repair
    /// fills it: a walk failed again where a hop was tried): no walk passes within the body's half-width of one, seen
    /// from above (the farthest its contact pose holds a foot from the trunk, at least
    /// <see cref="JumpTightener.SpotRadius"/>), neither the roadmap's nor one the path's post-processing would make;
    /// the request jumps there instead, and walks everywhere else. <c>null</c> for none.
    /// </summary>
    public IReadOnlyList<Vector3>? NoWalkSpots { get; init; }

    /// <summary>
    /// Stances (node ids, as searched) no jump takes off from: the body cannot crouch on them (the animated
    /// planner's repair fills it); walks still leave them. <c>null</c> for none.
    /// </summary>
    public IReadOnlySet<int>? NoTakeoffs { get; init; }

    /// <summary>
    /// Stances (node ids, as searched) no jump lands on: the body cannot absorb a landing there (the
    /// animated planner's repair fills it); walks still reach them. <c>null</c> for none.
    /// </summary>
    public IReadOnlySet<int>? NoLandings { get; init; }
}
