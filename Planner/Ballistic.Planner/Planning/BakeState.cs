namespace Ballistic.Planner.Planning;

/// <summary>Where a bake stands, as termination conditions and progress reports see it.</summary>
/// <param name="Nodes">Nodes in the roadmap.</param>
/// <param name="Edges">Directed edges in the roadmap.</param>
/// <param name="Elapsed">Time since the bake started.</param>
/// <param name="StartReachesGoal">True when the roadmap's start node reaches its goal node; false when not, or when the bake has none.</param>
/// <param name="Batches">Sampling rounds completed.</param>
public readonly record struct BakeState(int Nodes, int Edges, TimeSpan Elapsed, bool StartReachesGoal, int Batches);
