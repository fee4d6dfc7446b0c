namespace Ballistic.Runtime.Baking;

/// <summary>How a <see cref="BakeJob"/> ended.</summary>
public enum BakeJobStatus
{
    /// <summary>The roadmap was baked: the outcome holds its <see cref="RoadmapData"/> and frozen roadmap.</summary>
    Succeeded,

    /// <summary>The bake could not give a roadmap; the outcome says why in one line and holds no data.</summary>
    Failed,

    /// <summary>The bake was cancelled before it ended; the outcome holds no data.</summary>
    Cancelled,
}
