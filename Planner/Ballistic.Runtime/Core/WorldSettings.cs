using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Sampling;

namespace Ballistic.Runtime.Core;

/// <summary>How a <see cref="JumpWorld"/> steps: tick rate, path-request budgets, background animation, replanning and the moves paths may use.</summary>
public sealed record WorldSettings
{
    /// <summary>Ticks per second (Godot's physics rate is 60 by default).</summary>
    public int TickRate { get; init; } = 60;

    /// <summary>
    /// Path requests started at most per tick; requests beyond wait in the queue, first come first served. A started
    /// request is searched and animated in the background (<see cref="AnimationThreads"/>), never on the tick.
    /// </summary>
    public int MaxSearchesPerTick { get; init; } = 16;

    /// <summary>
    /// Ticks from a request's start to the tick its outcome reaches its agent (the path it starts following, or why
    /// there is none). Meanwhile the search and the whole-body animation run in the background; with
    /// <see cref="WaitForAnimation"/> the tick at the end waits for them if need be, so that trajectories and events do
    /// not depend on thread count or machine speed.
    /// </summary>
    public int PathLatencyTicks { get; init; } = 6;

    /// <summary>
    /// True (deterministic, the default): a path starts exactly <see cref="PathLatencyTicks"/> after its search,
    /// waiting for its animation if it is late (at most <see cref="MaxAnimationWait"/> a tick). False: it starts at the first tick after that when its animation is
    /// ready, never waiting (smoother on slow machines, not reproducible).
    /// </summary>
    public bool WaitForAnimation { get; init; } = true;

    /// <summary>
    /// With <see cref="WaitForAnimation"/>, the most wall-clock time one tick waits, in all, for animations that are
    /// late on their due tick (a starved machine, hundreds of requests at once); <c>null</c> (the default) waits as long
    /// as it takes, so that a world stepped as fast as a loop can go (tests, tools, offline simulations) gives the
    /// same run on any machine; while it waits, the tick thread solves the requests no background thread has started
    /// yet (the one it waits for first, then those queued after it) instead of idling. Past it the tick goes on, and each request still animating is delivered at the first
    /// tick its animation is ready, as without <see cref="WaitForAnimation"/> (then trajectories depend on machine
    /// speed; each such request is counted in <see cref="JumpWorld.LateRequests"/>). A world stepped in real time
    /// should set one: the Godot server's world uses <see cref="RealTimeAnimationWait"/> (<see cref="RealTime"/>), so a game hitches, never
    /// freezes. Positive.
    /// </summary>
    public TimeSpan? MaxAnimationWait { get; init; }

    /// <summary>The <see cref="MaxAnimationWait"/> of worlds stepped in real time (the Godot server's): a quarter of a second.</summary>
    public static readonly TimeSpan RealTimeAnimationWait = TimeSpan.FromSeconds(0.25);

    /// <summary>The defaults of a world stepped in real time, as the Godot server's: <see cref="MaxAnimationWait"/> is <see cref="RealTimeAnimationWait"/>.</summary>
    public static WorldSettings RealTime => new() { MaxAnimationWait = RealTimeAnimationWait };

    /// <summary>
    /// True: whenever a kind gets a roadmap (<see cref="JumpWorld.AddKind"/>, <see cref="JumpWorld.ReplaceKind"/>), one
    /// background thread prepares its searches (<see cref="PathQuery.Prepare"/>, with the settings its requests
    /// use), so that requests over the roadmap recall the stances turned to face its jumps and the arcs linking them
    /// instead of working them out as they go; stopped when the kind is removed or replaced or the world disposed.
    /// Requests are served meanwhile. It changes no path, trajectory or event, only how soon a search ends. It costs
    /// a thread for seconds (with the kind's whole-body stance check, 10.6 s for the desert's 600-node skeleton
    /// roadmap on one core) and tens of megabytes while the kind lives, and a request's animation, not its search,
    /// is most of its cost: for a game that loads a level behind a loading screen on a machine with cores to spare.
    /// False by default.
    /// </summary>
    public bool PrepareSearches { get; init; }

    /// <summary>
    /// Threads searching and animating path requests in the background; 0 runs them on the tick (tests, single-threaded
    /// hosts). Without a <see cref="MaxAnimationWait"/> a tick waiting for a late request lends its thread too.
    /// </summary>
    public int AnimationThreads { get; init; } = Math.Max(1, Environment.ProcessorCount - 1);

    /// <summary>
    /// In a world with no background threads (<see cref="AnimationThreads"/> 0), the time each tick spends at most
    /// advancing started path requests on the tick thread, in request order, each in steps (the search's placements,
    /// steering calls, slices of 1,024 A* expansions and post-processing stages; the animation's jumps and walks), as
    /// Detour's path queue spends its iterations per update; a step begun is finished, so a tick may overrun by one
    /// step. A request not ended by its due tick is finished there (<see cref="WaitForAnimation"/>, within
    /// <see cref="MaxAnimationWait"/>), so outcomes and the ticks they arrive on do not depend on the budget.
    /// <c>null</c>: each request is solved whole on the tick it starts. 2 ms by default. Positive.
    /// </summary>
    public TimeSpan? PlanningTimePerTick { get; init; } = DefaultPlanningTimePerTick;

    /// <summary>The default <see cref="PlanningTimePerTick"/>: 2 ms, an eighth of a 60 Hz frame.</summary>
    public static readonly TimeSpan DefaultPlanningTimePerTick = TimeSpan.FromMilliseconds(2);

    /// <summary>Searches per request at most: a jump the body cannot perform is set aside and the search runs again (<see cref="AnimatedPlanner"/>).</summary>
    public int RepairRounds { get; init; } = AnimatedPlanner.DefaultRounds;

    /// <summary>A new target farther than this (metres) from the current path's target makes the agent replan; nearer ones keep the path.</summary>
    public float ReplanDistance { get; init; } = 0.5f;

    /// <summary>Frames per second of the solved animations (the pose is interpolated between them).</summary>
    public float AnimationFrameRate { get; init; } = 60f;

    /// <summary>How close a stance's contacts must come to a target or spawn point.</summary>
    public EndpointTolerance Tolerance { get; init; } = new();

    /// <summary>
    /// Which moves paths may use (<see cref="QuerySettings.Locomotion"/>): <see cref="Locomotion.WalkAndJump"/> (the
    /// default: walks where the ground allows, for characters that walk) or <see cref="Locomotion.Jump"/> (jumps only).
    /// </summary>
    public Locomotion Locomotion { get; init; } = Locomotion.WalkAndJump;

    /// <summary>
    /// What every jump costs beyond its flight time when walking is allowed, in seconds of walking
    /// (<see cref="QuerySettings.JumpEffort"/>; <see cref="QuerySettings.DefaultJumpEffort"/> by default); with
    /// <see cref="JumpHeightEffort"/>, a path jumps only where that saves more time than the jump's effort. Finite and
    /// not negative.
    /// </summary>
    public float JumpEffort { get; init; } = QuerySettings.DefaultJumpEffort;

    /// <summary>
    /// What a jump costs on top of <see cref="JumpEffort"/> per metre of its takeoff's energy height, in seconds of
    /// walking per metre (<see cref="QuerySettings.JumpHeightEffort"/>; <see cref="QuerySettings.DefaultJumpHeightEffort"/>
    /// by default): high vaults cost more than hops. Finite and not negative.
    /// </summary>
    public float JumpHeightEffort { get; init; } = QuerySettings.DefaultJumpHeightEffort;

    /// <summary>Seconds per tick.</summary>
    public double TickSeconds => 1.0 / TickRate;

    /// <summary>The first invalid setting as one sentence, or <c>null</c>.</summary>
    public string? Problem()
    {
        if (TickRate is < 1 or > 10_000)
        {
            return $"TickRate must be 1–10000 ticks per second, not {TickRate}";
        }

        if (MaxSearchesPerTick < 1)
        {
            return "MaxSearchesPerTick must be positive";
        }

        if (PathLatencyTicks < 0 || AnimationThreads < 0 || RepairRounds < 1)
        {
            return "PathLatencyTicks and AnimationThreads must not be negative and RepairRounds must be positive";
        }

        if (!(ReplanDistance >= 0f) || !float.IsFinite(ReplanDistance) || !(AnimationFrameRate > 0f) || !float.IsFinite(AnimationFrameRate))
        {
            return "ReplanDistance must be finite and not negative, and AnimationFrameRate finite and positive";
        }

        if (PlanningTimePerTick is { } slice && !(slice > TimeSpan.Zero))
        {
            return $"PlanningTimePerTick must be positive (or null: each request solved whole), not {slice.TotalSeconds} s";
        }

        if (MaxAnimationWait is { } wait && !(wait > TimeSpan.Zero))
        {
            return $"MaxAnimationWait must be positive (or null: no limit), not {wait.TotalSeconds} s";
        }

        if (!Enum.IsDefined(Locomotion))
        {
            return $"Locomotion must be WalkAndJump or Jump, not {Locomotion}";
        }

        return QuerySettings.EffortProblem(JumpEffort, JumpHeightEffort);
    }
}
