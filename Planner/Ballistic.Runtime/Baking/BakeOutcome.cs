using System.Globalization;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime.Core;

namespace Ballistic.Runtime.Baking;

/// <summary>
/// How a <see cref="BakeJob"/> ended, immutable. Only <see cref="BakeJobStatus.Succeeded"/> carries data: a failed or
/// cancelled bake never hands out a partial roadmap, so the caller keeps what it had.
/// </summary>
public sealed class BakeOutcome
{
    private BakeOutcome(BakeJobStatus status, string reason, RoadmapData? data, Roadmap? roadmap, double elapsedSeconds, BakeResult? result = null, Exception? error = null)
    {
        Result = result;
        Error = error;
        Status = status;
        Reason = reason;
        Data = data;
        Roadmap = roadmap;
        ElapsedSeconds = elapsedSeconds;
    }

    /// <summary>How the bake ended.</summary>
    public BakeJobStatus Status { get; }

    /// <summary>True when the bake succeeded and <see cref="Data"/> and <see cref="Roadmap"/> are set.</summary>
    public bool Succeeded => Status == BakeJobStatus.Succeeded;

    /// <summary>
    /// One line: on success why the bake stopped (e.g. "reached 200 nodes", "time budget of 30 s spent"); on failure
    /// the problem (for an error dialog); "cancelled" when cancelled.
    /// </summary>
    public string Reason { get; }

    /// <summary>The baked roadmap for the engine resource, or <c>null</c> unless <see cref="Succeeded"/>.</summary>
    public RoadmapData? Data { get; }

    /// <summary>The baked, frozen roadmap (what <see cref="RoadmapData.Load"/> would give back), or <c>null</c> unless <see cref="Succeeded"/>.</summary>
    public Roadmap? Roadmap { get; }

    /// <summary>Wall-clock seconds from the job's start to its end, preparing the level included.</summary>
    public double ElapsedSeconds { get; }

    /// <inheritdoc />
    public override string ToString() => Status switch
    {
        BakeJobStatus.Succeeded => string.Create(CultureInfo.InvariantCulture, $"baked {Data!.NodeCount} nodes and {Data.JumpCount} jumps in {ElapsedSeconds:0.0} s ({Reason})"),
        BakeJobStatus.Failed => $"bake failed: {Reason}",
        _ => "bake cancelled",
    };

    /// <summary>The baker's own result (counts, steering statistics) when the bake ran; <c>null</c> when it failed before or was cancelled before it began.</summary>
    internal BakeResult? Result { get; }

    /// <summary>The exception a failed bake ended on (an input the baker refused, or a defect), or <c>null</c>: the CLI maps it to its exit code.</summary>
    internal Exception? Error { get; }

    internal static BakeOutcome Success(RoadmapData data, BakeResult result, double elapsedSeconds) =>
        new(BakeJobStatus.Succeeded, result.Reason, data, result.Roadmap, elapsedSeconds, result);

    internal static BakeOutcome Failure(string reason, double elapsedSeconds, BakeResult? result = null, Exception? error = null) =>
        new(BakeJobStatus.Failed, OneLine.Of(reason), null, null, elapsedSeconds, result, error);

    internal static BakeOutcome Cancellation(double elapsedSeconds, BakeResult? result = null) =>
        new(BakeJobStatus.Cancelled, "cancelled", null, null, elapsedSeconds, result);
}
