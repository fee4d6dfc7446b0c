using System.Numerics;
using Ballistic.Planner.Sampling;

namespace Ballistic.Planner.Planning;

/// <summary>Parameters of a roadmap bake. The roadmap depends only on these and the scene, never on the thread count.</summary>
public sealed record BakeSettings
{
    /// <summary>Seed of every random choice.</summary>
    public int Seed { get; init; } = 1;

    /// <summary>Worker threads; 1 bakes on the calling thread.</summary>
    public int Threads { get; init; } = Environment.ProcessorCount;

    /// <summary>The roadmap stops growing at this many nodes; <c>null</c> for no node limit (another condition must stop the bake).</summary>
    public int? MaxNodes { get; init; } = 200;

    /// <summary>Time budget; <c>null</c> for none.</summary>
    public TimeSpan? TimeLimit { get; init; }

    /// <summary>Each new node is steered to and from at most this many nearest nodes within jump reach.</summary>
    public int MaxNeighbours { get; init; } = 24;

    /// <summary>Node samples drawn per round; termination is checked between rounds.</summary>
    public int BatchSize { get; init; } = 16;

    /// <summary>Optional start point (world metres): placed as node 0 before sampling (<see cref="TrunkSampler.Place"/>).</summary>
    public Vector3? Start { get; init; }

    /// <summary>Optional goal point (world metres): placed as the node after the start before sampling.</summary>
    public Vector3? Goal { get; init; }

    /// <summary>
    /// Stop as soon as the start reaches the goal (needs both). With <see cref="FocusOnRequest"/>, the bake first adds,
    /// once, stances along the straight line between them where it runs on open ground and along narrow surfaces (a
    /// beam, a ledge) that run their way, which random samples rarely reach; the roadmap keeps every node it had.
    /// </summary>
    public bool StopWhenConnected { get; init; }

    /// <summary>
    /// With a start and a goal, one of them raised above the other by more than the step height (up on a beam or a
    /// ledge): once they connect, add stances on the ground within a jump's reach of the raised one
    /// (<see cref="RoadmapBaker.ApproachStances"/>). Set by <see cref="Query.AnimatedPlanner.BakeAndPlan"/> when it
    /// bakes on for a wandering route.
    /// </summary>
    internal bool ApproachRaisedEnds { get; init; }

    /// <summary>
    /// For <see cref="Query.AnimatedPlanner.BakeAndPlan"/> only: once the start reaches the goal, bake on (to twice the
    /// nodes, up to <see cref="MaxNodes"/>) while the searched route jumps and costs (walking seconds, jump efforts
    /// included) more than walking 1.5 times the straight distance between its ends would, keeping a larger roadmap only
    /// when its route costs at least 5 % less; the route kept is then animated. A bake that stops at the first
    /// connection holds no walk round what that connection jumps: a maze's hedge would be vaulted whatever jump effort is
    /// set; refined, the skeleton walks round it. <c>true</c> by default; <c>false</c> plans on the first connection's
    /// roadmap. A roadmap baked for the whole level (<see cref="StopWhenConnected"/> off, as the editor bakes one) needs
    /// none of this.
    /// </summary>
    public bool Refine { get; init; } = true;

    /// <summary>
    /// With a start and a goal: sample a corridor between them first, widening it as it fills, then the whole level
    /// (on a level much larger than the request: a request on a large level costs what its route costs); the whole
    /// level from the start where the first corridor is a quarter of it or more. <c>true</c> by default; without a
    /// start and a goal the whole level is sampled either way.
    /// </summary>
    public bool FocusOnRequest { get; init; } = true;

    /// <summary>How close the start and goal nodes' contacts must come to the requested points (<see cref="TrunkSampler.Place"/>).</summary>
    public EndpointTolerance Tolerance { get; init; } = new();

    /// <summary>
    /// An extra check the start and goal stances must pass (the whole body can stand there), or <c>null</c>.
    /// <see cref="Query.AnimatedPlanner"/> sets it to its animator's <see cref="Animation.IJumpAnimator.CanStand"/>, for
    /// the bake and the query alike, so that both place the same stances.
    /// </summary>
    public Func<Contacts.PoseEvaluation, bool>? CanStand { get; init; }

    /// <summary>
    /// Which moves the roadmap holds: <see cref="Locomotion.WalkAndJump"/> (the default) adds walks between
    /// nearby nodes when the character walks; <see cref="Locomotion.Jump"/> bakes jumps only, exactly as the paper.
    /// </summary>
    public Locomotion Locomotion { get; init; } = Locomotion.WalkAndJump;

    /// <summary>
    /// The longest walk edge baked, metres (horizontal distance between the nodes' contact centres); <c>null</c>
    /// for <see cref="DefaultMaxWalkDistance"/>. Longer walks still appear in paths, joined from several edges or
    /// by the shortcutting after a search.
    /// </summary>
    public float? MaxWalkDistance { get; init; }

    /// <summary>Each new node is linked by walks to and from at most this many nearest nodes within <see cref="MaxWalkDistance"/>.</summary>
    public int MaxWalkNeighbours { get; init; } = 8;

    /// <summary>The longest walk edge baked by default for a character: twelve step heights, between 0.5 and 4 m.</summary>
    public static float DefaultMaxWalkDistance(Characters.WalkingLimits walking)
    {
        ArgumentNullException.ThrowIfNull(walking);
        return Math.Clamp(12f * walking.StepHeight, 0.5f, 4f);
    }

    /// <summary>Checks the values.</summary>
    /// <exception cref="ArgumentException">A value is out of range, or no condition would ever stop the bake.</exception>
    public void Validate()
    {
        if (Threads < 1)
        {
            throw new ArgumentException($"Threads must be at least 1, not {Threads}.");
        }

        if (MaxNodes is < 1)
        {
            throw new ArgumentException($"MaxNodes must be at least 1, not {MaxNodes}.");
        }

        if (TimeLimit is { } limit && limit <= TimeSpan.Zero)
        {
            throw new ArgumentException($"TimeLimit must be positive, not {limit}.");
        }

        if (MaxNeighbours < 1 || BatchSize < 1)
        {
            throw new ArgumentException("MaxNeighbours and BatchSize must be at least 1.");
        }

        Tolerance.Validate();

        if (MaxWalkDistance is float walk && !(walk > 0f && float.IsFinite(walk)))
        {
            throw new ArgumentException($"MaxWalkDistance must be positive and finite, not {walk}.");
        }

        if (MaxWalkNeighbours < 0)
        {
            throw new ArgumentException($"MaxWalkNeighbours must not be negative, not {MaxWalkNeighbours}.");
        }

        if (StopWhenConnected && (Start is null || Goal is null))
        {
            throw new ArgumentException("StopWhenConnected needs both Start and Goal.");
        }
    }
}
