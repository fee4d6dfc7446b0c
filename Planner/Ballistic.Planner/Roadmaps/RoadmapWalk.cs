namespace Ballistic.Planner.Roadmaps;

/// <summary>
/// A directed walk edge of the roadmap: the ground lets the character walk from one node to the other
/// (<see cref="Walking.WalkSteering"/>). The ground path itself is traced again when a path uses the walk.
/// </summary>
/// <param name="From">Node walked from.</param>
/// <param name="To">Node walked to.</param>
/// <param name="Length">Length of the ground path, metres.</param>
/// <param name="Duration">Length over the character's walking speed, seconds.</param>
internal readonly record struct RoadmapWalk(int From, int To, float Length, float Duration);
