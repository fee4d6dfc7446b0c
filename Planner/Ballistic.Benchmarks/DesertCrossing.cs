using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Authoring.Levels;
using Ballistic.Planner.Planning;

namespace Ballistic.Benchmarks;

/// <summary>The animation benchmarks' request: the skeleton on the generated desert, corner to corner (world metres, on the sand).</summary>
internal static class DesertCrossing
{
    /// <summary>The skeleton's scene on the generated desert.</summary>
    public static PlanningScene Scene() => PlanningScene.Create(LevelGenerator.BuildLevel("desert"), CharacterPresets.Skeleton());

    /// <summary>The request's start and goal: the sand under (−9.5, −7.5) and (9.5, 7.5).</summary>
    public static (Vector3 From, Vector3 To) Ends(PlanningScene scene)
    {
        Vector3 Ground(float x, float z)
        {
            scene.Bvh.Raycast(new Vector3(x, 10f, z), new Vector3(0f, -20f, 0f), 1f, out var hit);
            return hit.Point;
        }

        return (Ground(-9.5f, -7.5f), Ground(9.5f, 7.5f));
    }
}
