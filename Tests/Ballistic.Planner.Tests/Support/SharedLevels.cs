using System.Collections.Concurrent;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;

namespace Ballistic.Planner.Tests.Support;

/// <summary>
/// The fixture cache of the suite: each bundled level loaded from its GLB once per test run, and each planning scene
/// of a bundled level and a preset character built once, shared by every test that only reads them (levels and
/// scenes are immutable; the planner queries one scene from many threads). Thread-safe: fixtures running in parallel
/// build an entry once between them.
/// </summary>
internal static class SharedLevels
{
    private static readonly ConcurrentDictionary<string, Lazy<Level>> Levels = new(StringComparer.Ordinal);
    private static readonly ConcurrentDictionary<(string Level, string Character), Lazy<PlanningScene>> Scenes = new();

    /// <summary>The bundled level <c>Scenes/levels/NAME.glb</c>, loaded on first use.</summary>
    public static Level Bundled(string name) =>
        Levels.GetOrAdd(name, n => new Lazy<Level>(() => GltfLevelLoader.Load(RepositoryFiles.Level(n)))).Value;

    /// <summary>The planning scene of bundled level <paramref name="level"/> and preset <paramref name="character"/>, built on first use.</summary>
    public static PlanningScene Scene(string level, string character) =>
        Scenes.GetOrAdd((level, character), k => new Lazy<PlanningScene>(() => PlanningScene.Create(Bundled(k.Level), CharacterPresets.Get(k.Character)))).Value;
}
