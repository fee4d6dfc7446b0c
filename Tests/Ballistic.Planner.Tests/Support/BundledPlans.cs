using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;

namespace Ballistic.Planner.Tests.Support;

/// <summary>End-to-end plans on the bundled levels: roofs or ground near two (x, z) points, a bake until they connect, a query.</summary>
internal static class BundledPlans
{
    public static (PlanningScene Scene, BakeResult Bake, PlanResult Plan) Plan(string levelName, string characterName, float x0, float z0, float x1, float z1, int maxNodes = 800)
    {
        Level level = GltfLevelLoader.Load(RepositoryFiles.Level(levelName));
        var scene = PlanningScene.Create(level, CharacterPresets.Get(characterName));
        Vector3 from = LevelPoints.Highest(scene.Bvh, x0, z0);
        Vector3 to = LevelPoints.Highest(scene.Bvh, x1, z1);
        BakeResult bake = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 1, Threads = 2, MaxNodes = maxNodes, Start = from, Goal = to, StopWhenConnected = true });
        PlanResult plan = new PathQuery(scene, bake.Roadmap).Plan(from, to);
        return (scene, bake, plan);
    }
}
