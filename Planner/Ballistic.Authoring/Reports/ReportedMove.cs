using System.Numerics;

namespace Ballistic.Authoring.Reports;

/// <summary>One move of a plan report, as <see cref="PlanReportReader"/> reads it.</summary>
/// <param name="Kind">A jump or a walk.</param>
/// <param name="From">Trunk centre of the stance the move leaves (a jump's takeoff, a walk's <c>from</c>), world metres.</param>
/// <param name="To">Trunk centre of the stance the move reaches (a jump's landing, a walk's <c>to</c>), world metres.</param>
/// <param name="Duration">How long the move takes, seconds (a jump's flight time).</param>
/// <param name="Path">A walk's ground path as written (points on the ground, world metres, in order); empty for a jump.</param>
public sealed record ReportedMove(ReportedMoveKind Kind, Vector3 From, Vector3 To, float Duration, IReadOnlyList<Vector3> Path);
