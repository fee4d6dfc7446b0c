using System.Numerics;
using Ballistic.Planner.Planning;

namespace Ballistic.Authoring.Reports;

/// <summary>What <see cref="PlanReportReader"/> reads from a <c>ballistic.plan/1</c> or <c>ballistic.plan/2</c> report.</summary>
/// <param name="Schema">The report's schema name, <see cref="PlanReportWriter.SchemaV1"/> or <see cref="PlanReportWriter.Schema"/>.</param>
/// <param name="Status">The plan's status.</param>
/// <param name="Reason">The sentence explaining the status.</param>
/// <param name="From">The requested start point, world metres.</param>
/// <param name="To">The requested goal point, world metres.</param>
/// <param name="Moves">The path's moves in order (a <c>/1</c> report's jumps, as jump moves).</param>
public sealed record PlanReportSummary(string Schema, PlannerStatus Status, string Reason, Vector3 From, Vector3 To, IReadOnlyList<ReportedMove> Moves)
{
    /// <summary>How many of <see cref="Moves"/> are jumps.</summary>
    public int JumpCount => Moves.Count(m => m.Kind == ReportedMoveKind.Jump);

    /// <summary>How many of <see cref="Moves"/> are walks.</summary>
    public int WalkCount => Moves.Count(m => m.Kind == ReportedMoveKind.Walk);

    /// <summary>Total duration of the moves, seconds (flights and walks, without the stances between them).</summary>
    public float TotalDuration => Moves.Sum(m => m.Duration);
}
