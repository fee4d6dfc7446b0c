using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;

namespace Ballistic.Authoring.Playtest;

/// <summary>A headless playtest: how many agents, for how long, from which seed.</summary>
public sealed record PlaytestSettings
{
    /// <summary>Agents spawned, each on a random stance of the roadmap.</summary>
    public int Agents { get; init; } = 8;

    /// <summary>Simulated time, seconds.</summary>
    public double Seconds { get; init; } = 60;

    /// <summary>Seed of the spawn stances and targets (the run is deterministic for a seed).</summary>
    public int Seed { get; init; } = 1;

    /// <summary>Ticks per second.</summary>
    public int TickRate { get; init; } = 60;

    /// <summary>Random start/goal node pairs sampled for the roadmap's connectivity share.</summary>
    public int ReachabilityPairs { get; init; } = 500;

    /// <summary>Threads solving animations in the background (the results do not depend on it).</summary>
    public int AnimationThreads { get; init; } = Math.Max(1, Environment.ProcessorCount - 1);

    /// <summary>Which moves paths may use (<see cref="Runtime.Core.WorldSettings.Locomotion"/>): walks and jumps by default.</summary>
    public Locomotion Locomotion { get; init; } = Locomotion.WalkAndJump;

    /// <summary>What a jump costs beyond its flight time, in seconds of walking (<see cref="Runtime.Core.WorldSettings.JumpEffort"/>).</summary>
    public float JumpEffort { get; init; } = QuerySettings.DefaultJumpEffort;

    /// <summary>What a jump costs on top of <see cref="JumpEffort"/> per metre of its takeoff's energy height, seconds per metre (<see cref="Runtime.Core.WorldSettings.JumpHeightEffort"/>).</summary>
    public float JumpHeightEffort { get; init; } = QuerySettings.DefaultJumpHeightEffort;

    /// <summary>
    /// Whether the world is stepped as a game steps it: each tick at its moment on the wall clock (1 / <see cref="TickRate"/>
    /// seconds apart; at once when behind), with a real-time world's wait for late requests
    /// (<see cref="Runtime.Core.WorldSettings.RealTime"/>, the Godot server's: a tick waits at most a quarter of a second
    /// for a request due on it, which then arrives at the first tick it is ready). The tick times are then what a
    /// game's main thread pays, and the run depends on the machine: a request late here arrives a tick later than on a
    /// faster machine (<see cref="PlaytestResult.LateRequests"/>). False (the default): offline, as fast as the
    /// machine goes, the tick thread solving requests while it waits, the same for a seed at any thread count.
    /// </summary>
    public bool RealTime { get; init; }

    /// <summary>The first invalid setting as one sentence, or <c>null</c>.</summary>
    public string? Problem() =>
        Agents is < 1 or > 100_000 ? $"--agents must be 1–100000, not {Agents}"
        : !(Seconds > 0) || Seconds > 86_400 ? $"--seconds must be positive and at most a day, not {Seconds}"
        : TickRate is < 1 or > 1_000 ? $"the tick rate must be 1–1000, not {TickRate}"
        : ReachabilityPairs < 0 ? "the reachability pair count must not be negative"
        : AnimationThreads < 0 ? "the animation thread count must not be negative"
        : !Enum.IsDefined(Locomotion) ? $"the locomotion must be WalkAndJump or Jump, not {Locomotion}"
        : !(JumpEffort >= 0f) || !float.IsFinite(JumpEffort) ? $"the jump effort must be finite and not negative, not {JumpEffort} s"
        : !(JumpHeightEffort >= 0f) || !float.IsFinite(JumpHeightEffort) ? $"the jump height effort must be finite and not negative, not {JumpHeightEffort} s/m"
        : null;
}
