using System.Numerics;
using System.Text.Json.Nodes;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Fuzz;

/// <summary>
/// The second fuzz lane's cases: a mutated level, limb spec or roadmap (checksum recomputed) that still loads is
/// baked with a small budget (or, a roadmap, loaded with its level) and planned on between two points of the level,
/// and every plan reported exact is audited by the independent checker (<see cref="PlanAudit"/>: arcs, cones, speed
/// limits, contacts on the mesh, ends where asked, the animation on the arcs). A refusal with an input error, at any
/// stage, passes; an exception of another kind, a wrong exact plan or more than <see cref="CaseTime"/> of CPU fails.
/// </summary>
internal static class DeepFuzz
{
    /// <summary>The most CPU time one deep case may take (load, bake, plan, animate, audit).</summary>
    public static readonly TimeSpan CaseTime = TimeSpan.FromSeconds(20);

    /// <summary>Nodes each bake stops at: enough for a plan or two jumps across the gap course.</summary>
    private const int BakeNodes = 40;

    /// <summary>How the cases that loaded ended, by the plan's status (or "nothing to stand on"), counted for the lane's summary.</summary>
    public static System.Collections.Concurrent.ConcurrentDictionary<string, int> Outcomes { get; } = new();

    private static readonly Lazy<Level> GapCourse = new(() => GltfLevelLoader.Load(RepositoryFiles.Level("gap-course")));

    /// <summary>A mutated level (<paramref name="write"/> writes it as level.glb); if it loads, the skeleton bakes and plans on it.</summary>
    public static Action Level(Mutator m, string folder, Func<Mutator, string, Action> write)
    {
        write(m, folder);
        string path = Path.Combine(folder, "level.glb");
        int seed = m.Random.Next();
        return () =>
        {
            Level level = GltfLevelLoader.Load(path);
            BakeAndPlan(level, CharacterPresets.Model("skeleton"), CharacterPresets.Get("skeleton"), seed);
        };
    }

    /// <summary>
    /// The frog's limb spec beside its rig, either mutated as the loader lane does (<paramref name="write"/>; most such
    /// specs are refused) or, half the time, with one to three of its numbers scaled by 0, 0.1, 0.5, 2 or 10 or negated
    /// (most of those load, so the bake and the plan see them); if it loads, it bakes and plans on the gap course.
    /// </summary>
    public static Action Spec(Mutator m, string folder, Func<Mutator, string, Action> write)
    {
        if (m.Random.Next(2) == 0)
        {
            write(m, folder);
        }
        else
        {
            File.WriteAllBytes(Path.Combine(folder, "frog.glb"), FuzzInputs.FrogGlb);
            JsonNode json = JsonNode.Parse(FuzzInputs.FrogSpec)!;
            List<JsonValue> numbers = [.. Numbers(json)];
            float[] factors = [0f, 0.1f, 0.5f, 2f, 10f, -1f];
            for (int k = 1 + m.Random.Next(3); k > 0 && numbers.Count > 0; k--)
            {
                JsonValue number = numbers[m.Random.Next(numbers.Count)];
                float factor = factors[m.Random.Next(factors.Length)];
                double value = number.GetValue<double>() * factor;
                m.Note($"{number.GetPath()} × {factor}");
                number.ReplaceWith(JsonValue.Create(value));
                numbers = [.. Numbers(json)];
            }

            File.WriteAllBytes(Path.Combine(folder, "frog.limbs.json"), m.Serialize(json));
        }

        string gltf = Path.Combine(folder, "frog.glb");
        string spec = Path.Combine(folder, "frog.limbs.json");
        int seed = m.Random.Next();
        return () =>
        {
            (CharacterModel model, ReducedCharacter reduced) = CharacterSpecFile.Load(gltf, spec);
            BakeAndPlan(GapCourse.Value, model, reduced, seed);
        };
    }

    /// <summary>A mutated roadmap of the skeleton on the gap course, checksum recomputed; if it loads with the level, the skeleton plans on it.</summary>
    public static Action Roadmap(Mutator m, string folder, Func<Mutator, string, Action> write)
    {
        write(m, folder);
        string path = Path.Combine(folder, "level.roadmap");
        int seed = m.Random.Next();
        return () =>
        {
            ReducedCharacter skeleton = FuzzInputs.Roadmap.Character;
            Roadmap roadmap = RoadmapFile.Load(path, GapCourse.Value, skeleton);
            PlanningScene scene = PlanningScene.Create(GapCourse.Value, skeleton);
            var planner = new AnimatedPlanner(scene, new JumpAnimator(scene, CharacterPresets.Model("skeleton")));
            if (Pair(scene, seed) is (Vector3 from, Vector3 to))
            {
                Audit(scene, from, to, planner.Plan(roadmap, from, to));
            }
            else
            {
                Outcomes.AddOrUpdate("nothing to stand on", 1, (_, n) => n + 1);
            }
        };
    }

    /// <summary>Every number of a JSON document.</summary>
    private static IEnumerable<JsonValue> Numbers(JsonNode? node) => node switch
    {
        JsonObject o => o.SelectMany(p => Numbers(p.Value)),
        JsonArray a => a.SelectMany(Numbers),
        JsonValue v when v.GetValueKind() == System.Text.Json.JsonValueKind.Number => [v],
        _ => [],
    };

    private static void BakeAndPlan(Level level, CharacterModel model, ReducedCharacter reduced, int seed)
    {
        PlanningScene scene = PlanningScene.Create(level, reduced);
        if (Pair(scene, seed) is not (Vector3 from, Vector3 to))
        {
            Outcomes.AddOrUpdate("nothing to stand on", 1, (_, n) => n + 1);
            return; // nothing to stand on: loaded, nothing to plan
        }

        var planner = new AnimatedPlanner(scene, new JumpAnimator(scene, model));
        (AnimatedPlan plan, _) = planner.BakeAndPlan(from, to, new BakeSettings { Seed = seed, Threads = 1, MaxNodes = BakeNodes });
        Audit(scene, from, to, plan);
    }

    /// <summary>Throws (a failure of the case) when a plan reported exact breaks what the checker asserts.</summary>
    private static void Audit(PlanningScene scene, Vector3 from, Vector3 to, AnimatedPlan plan)
    {
        AuditReport report = PlanAudit.Check("deep fuzz case", scene, from, to, plan.Result, plan.Animation);
        Outcomes.AddOrUpdate(plan.Result.Status.ToString(), 1, (_, n) => n + 1);
        if (report.WrongAnswer)
        {
            throw new InvalidOperationException($"an exact plan from {from} to {to} breaks its promises: {string.Join("; ", report.Violations.Take(3))}");
        }
    }

    /// <summary>
    /// Two points on surfaces facing up (found by vertical rays at random spots of the level's bounds, at most 400
    /// tries), a metre or more apart across; <c>null</c> when the level offers none.
    /// </summary>
    private static (Vector3 From, Vector3 To)? Pair(PlanningScene scene, int seed)
    {
        var random = new Random(seed);
        Aabb bounds = scene.Level.Bounds;
        TriangleBvh bvh = scene.Bvh;
        Vector3? first = null;
        for (int attempt = 0; attempt < 400; attempt++)
        {
            var top = new Vector3(
                float.Lerp(bounds.Min.X, bounds.Max.X, (float)random.NextDouble()),
                bounds.Max.Y + 1f,
                float.Lerp(bounds.Min.Z, bounds.Max.Z, (float)random.NextDouble()));
            if (!bvh.Raycast(top, new Vector3(0f, bounds.Min.Y - bounds.Max.Y - 2f, 0f), 1f, out RayHit hit) || hit.Normal.Y < 0.8f)
            {
                continue;
            }

            if (first is not Vector3 a)
            {
                first = hit.Point;
            }
            else if (new Vector2(hit.Point.X - a.X, hit.Point.Z - a.Z).Length() >= 1f)
            {
                return (a, hit.Point);
            }
        }

        return null;
    }
}
