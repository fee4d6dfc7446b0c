using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Collision;

/// <summary>The level as the planner's collision checks see it: exact overlap of oriented boxes with its triangles.</summary>
internal interface ICollisionWorld
{
    /// <summary>True when <paramref name="box"/> (world space) touches any triangle of the level.</summary>
    bool Overlaps(in OrientedBox box);
}
