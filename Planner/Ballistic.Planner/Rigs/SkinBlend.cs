using System.Numerics;

namespace Ballistic.Planner.Rigs;

/// <summary>
/// One bone's share of a skinned vertex weighted to several bones: the bone (rig joint index), its weight (the
/// vertex's weights over its bones sum to 1) and the vertex's rest position in that bone's rest frame, metres. Posed,
/// the vertex lies at the weighted sum over its bones of each bone's world position plus its rotation applied to
/// <see cref="Point"/>: linear blend skinning, as an importer draws it.
/// </summary>
internal readonly record struct SkinBlend(int Joint, float Weight, Vector3 Point);
