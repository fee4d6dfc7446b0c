using System.Numerics;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;
using Ballistic.Planner.Characters;

namespace Ballistic.Planner.Planning;

/// <summary>
/// Where a bake with a start and a goal samples (<see cref="BakeSettings.FocusOnRequest"/>): first a corridor around
/// the segment between them (<see cref="SampleRegion"/>), its half width the larger of the character's neighbour cell
/// (half its jump reach, <see cref="NodeIndex.CellSizeFor"/>) and a tenth of the distance; each time the corridor has
/// received its share of nodes (<see cref="StageDensity"/> per cell of its area, at least <see cref="LeastStageNodes"/>)
/// without the bake stopping, it doubles in width; once it holds <see cref="WholeShare"/> of the level's surfaces, the
/// whole level. A request whose first corridor already holds <see cref="LevelShare"/> of the level is sampled over the
/// whole level from the start, as a bake without a request is. So a request on a large level costs what its route
/// costs, not what the level's area costs, and a detour the corridor misses is found as it widens. The stages follow
/// the node count alone: the same seed gives the same roadmap at any thread count.
/// </summary>
internal sealed class RequestFocus
{
    /// <summary>Share of the level's candidate surfaces from which a request's first corridor is not worth focusing on.</summary>
    public const double LevelShare = 0.25;

    /// <summary>Share of the level's candidate surfaces at which a widening corridor gives way to the whole level.</summary>
    public const double WholeShare = 0.5;

    /// <summary>Nodes a corridor receives at least before it widens.</summary>
    public const int LeastStageNodes = 64;

    /// <summary>Nodes a corridor receives per square neighbour cell of its area before it widens.</summary>
    public const float StageDensity = 4f;

    private readonly TrunkSampler _sampler;
    private readonly Vector3 _from;
    private readonly Vector3 _to;
    private readonly float _cell;
    private SampleRegion? _region;
    private int _stageEnd;

    private RequestFocus(TrunkSampler sampler, Vector3 from, Vector3 to, float cell, SampleRegion region, int nodes)
    {
        (_sampler, _from, _to, _cell, _region) = (sampler, from, to, cell, region);
        _stageEnd = nodes + StageNodes(region.Radius);
    }

    /// <summary>
    /// The focus of a bake from <paramref name="from"/> to <paramref name="to"/> (the start and goal stances' positions,
    /// world metres) that holds <paramref name="nodes"/> nodes so far, or <c>null</c> when its first corridor is
    /// already <see cref="LevelShare"/> of the level (sampled whole).
    /// </summary>
    public static RequestFocus? For(TrunkSampler sampler, SteeringLimits limits, Vector3 from, Vector3 to, int nodes)
    {
        float cell = NodeIndex.CellSizeFor(limits);
        float across = new Vector2(to.X - from.X, to.Z - from.Z).Length();
        SampleRegion region = sampler.Region(from, to, FirstRadius(cell, across));
        return region.Share >= LevelShare ? null : new RequestFocus(sampler, from, to, cell, region, nodes);
    }

    /// <summary>
    /// Half width (metres) of a request's first corridor: the larger of the neighbour cell <paramref name="cell"/> and a
    /// tenth of the distance <paramref name="across"/> (metres, seen from above) between its start and goal.
    /// </summary>
    public static float FirstRadius(float cell, float across) => MathF.Max(cell, 0.1f * across);

    /// <summary>The corridor the next round samples when the roadmap holds <paramref name="nodes"/> nodes, or <c>null</c> for the whole level.</summary>
    public SampleRegion? RegionAt(int nodes)
    {
        while (_region is not null && nodes >= _stageEnd)
        {
            SampleRegion wider = _sampler.Region(_from, _to, 2f * _region.Radius);
            _region = wider.Share >= WholeShare ? null : wider;
            _stageEnd = nodes + (_region is null ? 0 : StageNodes(_region.Radius));
        }

        return _region;
    }

    /// <summary>
    /// Ends the corridor's stage now: a round that drew no valid pose in it (a corridor under a low ceiling, over
    /// ground too steep to stand on) must not end the bake as if the character could stand nowhere; the next round
    /// samples a corridor twice as wide, or the whole level.
    /// </summary>
    public void Widen() => _stageEnd = 0;

    /// <summary>Nodes a corridor of half width <paramref name="radius"/> receives before it widens: <see cref="StageDensity"/> per square cell of its flat area.</summary>
    private int StageNodes(float radius)
    {
        float length = new Vector2(_to.X - _from.X, _to.Z - _from.Z).Length() + (2f * radius);
        float cells = length * 2f * radius / (_cell * _cell);
        return Math.Max(LeastStageNodes, (int)MathF.Ceiling(StageDensity * cells));
    }
}
