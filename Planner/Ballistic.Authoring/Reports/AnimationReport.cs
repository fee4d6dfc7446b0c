using Ballistic.Planner.Animation;

namespace Ballistic.Authoring.Reports;

/// <summary>The animation part of a plan report.</summary>
/// <param name="GlbPath">The animated GLB, relative to the report's folder.</param>
/// <param name="Clip">Name of the clip in the GLB.</param>
/// <param name="Animation">The animation.</param>
public sealed record AnimationReport(string GlbPath, string Clip, JumpAnimation Animation);
