using System.Numerics;

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

    /// <summary>Optional start point (world metres): projected to a node before sampling, as node 0.</summary>
    public Vector3? Start { get; init; }

    /// <summary>Optional goal point (world metres): projected to a node before sampling, as node 1.</summary>
    public Vector3? Goal { get; init; }

    /// <summary>Stop as soon as the start reaches the goal (needs both).</summary>
    public bool StopWhenConnected { get; init; }

    /// <summary>Radius (metres) around start and goal searched for a valid root pose: the pose stands on a surface point within this distance of the requested point.</summary>
    public float ProjectionRadius { get; init; } = 1.5f;

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

        if (!(ProjectionRadius > 0f))
        {
            throw new ArgumentException($"ProjectionRadius must be positive, not {ProjectionRadius}.");
        }

        if (StopWhenConnected && (Start is null || Goal is null))
        {
            throw new ArgumentException("StopWhenConnected needs both Start and Goal.");
        }
    }
}
