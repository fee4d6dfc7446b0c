using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Animation;

/// <summary>One frame of a jump animation.</summary>
/// <param name="Time">Clip time, seconds.</param>
/// <param name="Root">Root pose: on the jump's parabola.</param>
/// <param name="Angles">One angle per degree of freedom of the rig, radians.</param>
internal sealed record AnimationFrame(float Time, RootPose Root, float[] Angles);
