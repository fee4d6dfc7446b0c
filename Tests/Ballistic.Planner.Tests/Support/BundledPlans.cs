using System.Collections.Concurrent;
using System.Globalization;
using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;

namespace Ballistic.Planner.Tests.Support;

/// <summary>
/// End-to-end plans on the bundled levels: roofs or ground near two (x, z) points, planned and animated by the
/// library's one use case (bake until connected, query, animate with lazy repair).
/// </summary>
internal static class BundledPlans
{
    private static readonly ConcurrentDictionary<string, Lazy<(PlanningScene, BakeResult, AnimatedPlan)>> Plans = new(StringComparer.Ordinal);

    /// <summary>The plan of one request, made once per test run and shared by the tests that read it.</summary>
    public static (PlanningScene Scene, BakeResult Bake, AnimatedPlan Plan) Plan(string levelName, string characterName, float x0, float z0, float x1, float z1, int maxNodes = 800)
    {
        string key = string.Create(CultureInfo.InvariantCulture, $"{levelName}|{characterName}|{x0}|{z0}|{x1}|{z1}|{maxNodes}");
        return Plans.GetOrAdd(key, _ => new Lazy<(PlanningScene, BakeResult, AnimatedPlan)>(() => Make(levelName, characterName, x0, z0, x1, z1, maxNodes))).Value;
    }

    private static (PlanningScene Scene, BakeResult Bake, AnimatedPlan Plan) Make(string levelName, string characterName, float x0, float z0, float x1, float z1, int maxNodes)
    {
        PlanningScene scene = SharedLevels.Scene(levelName, characterName);
        Vector3 from = LevelPoints.Highest(scene.Bvh, x0, z0);
        Vector3 to = LevelPoints.Highest(scene.Bvh, x1, z1);
        var planner = new AnimatedPlanner(scene, new JumpAnimator(scene, CharacterPresets.Model(characterName)));
        (AnimatedPlan plan, BakeResult bake) = planner.BakeAndPlan(from, to, new BakeSettings { Seed = 1, Threads = 2, MaxNodes = maxNodes });
        return (scene, bake, plan);
    }
}
