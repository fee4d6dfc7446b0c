using Ballistic.Planner.Collision;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Tests.Support;

/// <summary>Reference collision world: every triangle tested against the box, no acceleration structure.</summary>
internal sealed class BruteForceWorld(IReadOnlyList<Triangle> triangles) : ICollisionWorld
{
    public IReadOnlyList<Triangle> Triangles { get; } = triangles;

    public bool Overlaps(in OrientedBox box)
    {
        foreach (Triangle t in Triangles)
        {
            if (box.Intersects(t))
            {
                return true;
            }
        }

        return false;
    }
}
