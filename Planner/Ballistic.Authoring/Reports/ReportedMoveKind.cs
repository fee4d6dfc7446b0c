namespace Ballistic.Authoring.Reports;

/// <summary>The kind of a move read from a plan report.</summary>
public enum ReportedMoveKind
{
    /// <summary>A ballistic jump (<c>"kind": "jump"</c>, or any entry of a <c>ballistic.plan/1</c> report's <c>jumps</c>).</summary>
    Jump,

    /// <summary>A walk along the ground (<c>"kind": "walk"</c>).</summary>
    Walk,
}
