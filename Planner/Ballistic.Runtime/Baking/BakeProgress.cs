namespace Ballistic.Runtime.Baking;

/// <summary>
/// Where a <see cref="BakeJob"/> stands: an immutable snapshot, safe to read from any thread (the editor polls it
/// each frame for a progress bar).
/// </summary>
/// <param name="Nodes">Nodes in the roadmap so far.</param>
/// <param name="Jumps">Jumps (directed edges) in the roadmap so far.</param>
/// <param name="NodeBudget">The node count at which the bake stops, or 0 when it has no node limit.</param>
/// <param name="Fraction">
/// How far the bake is, 0 to 1: the larger of nodes over the node budget and elapsed bake time over the time limit
/// (whichever ends the bake first). Never decreases during a bake; 1 once it has succeeded.
/// </param>
/// <param name="ElapsedSeconds">Wall-clock seconds since the job started (preparing the level included).</param>
/// <param name="Text">A short line for a progress bar, e.g. "37 of 200 nodes, 412 jumps".</param>
public sealed record BakeProgress(int Nodes, int Jumps, int NodeBudget, double Fraction, double ElapsedSeconds, string Text);
