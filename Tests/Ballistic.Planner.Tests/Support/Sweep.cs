using System.Numerics;
using Ballistic.Authoring.Animation;
using Ballistic.Authoring.Characters;
using Ballistic.Authoring.Levels;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;

namespace Ballistic.Planner.Tests.Support;

/// <summary>
/// Seeded sweeps of start/goal requests: each case plans (bake until connected, query), animates the whole body
/// and hands everything to <see cref="PlanAudit"/>, and the animated GLB to <see cref="AnimatorEye"/>.
/// </summary>
internal static class Sweep
{
    /// <summary>A scene and animator for one level and character, built once per sweep.</summary>
    public sealed record Setup(string LevelName, PlanningScene Scene, CharacterModel Model, AnimatedPlanner Planner);

    public static Setup Prepare(string levelName, Level level, string character) =>
        Prepare(levelName, level, CharacterPresets.Model(character), CharacterPresets.Get(character));

    /// <summary>
    /// A setup for a rig in another tool's shape (<see cref="ForeignCharacters"/>) on a level in another tool's shape
    /// (<see cref="ForeignLevels"/>), with that level's requests. The rig's files are written to and read from
    /// <paramref name="folder"/>, which must stay until the setup's animated GLBs are written (a .gltf's .png).
    /// </summary>
    public static (Setup Setup, (Vector3 From, Vector3 To)[] Requests) PrepareForeign(string levelName, string rig, string folder)
    {
        (Level level, (Vector3 From, Vector3 To)[] requests) = ForeignLevels.Get(levelName);
        (CharacterModel model, ReducedCharacter reduced) = ForeignCharacters.Named(rig).Load(folder);
        return (Prepare(levelName, level, model, reduced), requests);
    }

    /// <summary>A setup on a bundled level with a preset character, its scene from the suite's cache.</summary>
    public static Setup PrepareBundled(string levelName, string character) =>
        Prepare(levelName, SharedLevels.Scene(levelName, character), CharacterPresets.Model(character));

    /// <summary>A scene and animator for a character loaded from files (a rig made elsewhere).</summary>
    public static Setup Prepare(string levelName, Level level, CharacterModel model, ReducedCharacter reduced) =>
        Prepare(levelName, PlanningScene.Create(level, reduced), model);

    private static Setup Prepare(string levelName, PlanningScene scene, CharacterModel model) =>
        new(levelName, scene, model, new AnimatedPlanner(scene, new JumpAnimator(scene, model)));

    /// <summary>A request planned and animated: the plan, its audit (with the eye's look when exact) and the eye that read its GLB (<c>null</c> unless exact).</summary>
    public sealed record Planned(AnimatedPlan Plan, AuditReport Report, AnimatorEye? Eye);

    /// <summary>Plans (walking and jumping unless <paramref name="locomotion"/> says otherwise), animates and audits one request.</summary>
    public static AuditReport Run(Setup setup, Vector3 from, Vector3 to, int seed = 1, int maxNodes = 600, Locomotion locomotion = Locomotion.WalkAndJump) =>
        Plan(setup, from, to, seed, maxNodes, locomotion).Report;

    /// <summary>
    /// Plans the request as <see cref="Plan"/> does and asserts it fully right by the audit, with no snapping frame in its
    /// walks while the snapping limb is <paramref name="doing"/> ("free", "held", …; <see cref="AnimatorEye.Look.WalkSnaps"/>),
    /// as an importer plays the GLB at 60 frames a second; the snaps seen are the failure's message.
    /// </summary>
    public static void AssertNoWalkSnaps(Setup setup, Vector3 from, Vector3 to, string doing)
    {
        Planned planned = Plan(setup, from, to);
        Assert.That(planned.Report.FullyRight, Is.True, planned.Report.ToString());
        string[] snaps = planned.Report.Look!.WalkSnaps(doing);
        Assert.That(snaps, Is.Empty, string.Join(Environment.NewLine, snaps));
    }

    /// <summary>As <see cref="Run"/>, keeping the plan and the eye as well as the audit.</summary>
    public static Planned Plan(Setup setup, Vector3 from, Vector3 to, int seed = 1, int maxNodes = 600, Locomotion locomotion = Locomotion.WalkAndJump)
    {
        (AnimatedPlan plan, _) = setup.Planner.BakeAndPlan(from, to, new BakeSettings { Seed = seed, Threads = 2, MaxNodes = maxNodes, Locomotion = locomotion });
        return Audit(setup, from, to, plan);
    }

    /// <summary>Audits <paramref name="plan"/> (of the request from <paramref name="from"/> to <paramref name="to"/>, on a roadmap of the caller's) as <see cref="Plan"/> does: the audit, and the eye's look at its GLB when exact.</summary>
    public static Planned Audit(Setup setup, Vector3 from, Vector3 to, AnimatedPlan plan)
    {
        string name = $"{setup.LevelName}/{setup.Scene.Character.Name} ({from.X:0.#}, {from.Y:0.##}, {from.Z:0.#}) → ({to.X:0.#}, {to.Y:0.##}, {to.Z:0.#})";
        PlanningScene scene = setup.Scene;
        AuditReport report = PlanAudit.Check(name, scene, from, to, plan.Result, plan.Animation);
        AnimatorEye? eye = null;
        if (plan.Result.Status == PlannerStatus.Exact && plan.Animation is { } animation)
        {
            byte[] glb = AnimatedGlbWriter.ToBytes(animation);
            eye = AnimatorEye.Read(glb, setup.Model);
            report.Look = eye.Measure(animation, scene);
            Dump(setup, name, glb, animation);
        }

        return new Planned(plan, report, eye);
    }

    /// <summary>
    /// With BALLISTIC_SWEEP_OUT set, writes each exact plan's animated GLB, its level (once per level) and its jumps'
    /// times (takeoff, flight's key pose, landing, and the jump's direction across) there, to look at in Blender.
    /// </summary>
    private static void Dump(Setup setup, string name, byte[] glb, JumpAnimation animation)
    {
        if (Environment.GetEnvironmentVariable("BALLISTIC_SWEEP_OUT") is not { Length: > 0 } folder)
        {
            return;
        }

        Directory.CreateDirectory(folder);
        string stem = Path.Combine(folder, string.Concat(name.Select(c => char.IsLetterOrDigit(c) || c is '-' or '.' ? c : '_')));
        File.WriteAllBytes(stem + ".glb", glb);
        string level = Path.Combine(folder, setup.LevelName + ".level.glb");
        if (!File.Exists(level))
        {
            Vector3[] points = [.. setup.Scene.Level.Triangles.SelectMany(t => new[] { t.A, t.B, t.C })];
            File.WriteAllBytes(level, GltfLevelWriter.ToBytes([new LevelMesh(setup.LevelName, points, [.. Enumerable.Range(0, points.Length)], new LevelMaterial("ground", null), new System.Numerics.Vector4(0.7f, 0.65f, 0.55f, 1f))]));
        }

        var lines = new List<string>();
        for (int j = 0; j < animation.Arcs.Count; j++)
        {
            var arc = animation.Arcs[j];
            float t = animation.JumpStart(j);
            Vector3 d = arc.End - arc.Start;
            lines.Add(FormattableString.Invariant($"{t} {t + JumpAnimator.ApexKeyTime(arc)} {t + arc.FlightTime} {d.X} {d.Z} {arc.Start.X} {arc.Start.Y} {arc.Start.Z}"));
        }

        File.WriteAllLines(stem + ".jumps", lines);
    }

    /// <summary>
    /// <paramref name="count"/> random pairs of points on surfaces a character stands on (normal within ~37° of up,
    /// in a contact surface), at most <paramref name="maxDistance"/> metres apart across.
    /// </summary>
    public static (Vector3 From, Vector3 To)[] RandomPairs(PlanningScene scene, int count, int seed, float maxDistance)
    {
        var triangles = new List<int>();
        var cumulative = new List<double>();
        double total = 0;
        for (int t = 0; t < scene.Level.Triangles.Count; t++)
        {
            Triangle tri = scene.Level.Triangles[t];
            if (tri.Normal.Y >= 0.8f && scene.Surfaces.SurfaceOf(t) >= 0)
            {
                total += tri.Area;
                triangles.Add(t);
                cumulative.Add(total);
            }
        }

        var random = new Random(seed);
        Vector3 Point()
        {
            double r = random.NextDouble() * total;
            int i = cumulative.BinarySearch(r);
            Triangle tri = scene.Level.Triangles[triangles[Math.Min(i < 0 ? ~i : i, triangles.Count - 1)]];
            float r1 = MathF.Sqrt((float)random.NextDouble());
            float r2 = (float)random.NextDouble();
            return (tri.A * (1f - r1)) + (tri.B * (r1 * (1f - r2))) + (tri.C * (r1 * r2));
        }

        var pairs = new List<(Vector3, Vector3)>();
        while (pairs.Count < count)
        {
            Vector3 a = Point();
            Vector3 b = Point();
            float across = new Vector2(a.X - b.X, a.Z - b.Z).Length();
            if (across <= maxDistance && across >= 1f)
            {
                pairs.Add((a, b));
            }
        }

        return [.. pairs];
    }

    /// <summary>One line of figures for a set of reports.</summary>
    public static string Summary(IReadOnlyList<AuditReport> reports)
    {
        int exact = reports.Count(r => r.Status == PlannerStatus.Exact);
        int right = reports.Count(r => r.FullyRight);
        int wrong = reports.Count(r => r.WrongAnswer);
        int animated = reports.Count(r => r.Animated);
        int clean = reports.Count(r => r.CleanAnimation);
        List<AuditReport> ex = [.. reports.Where(r => r.Status == PlannerStatus.Exact)];
        string Median(Func<AuditReport, float> f) => ex.Count == 0 ? "-" : $"{ex.Select(f).Order().ElementAt(ex.Count / 2):0.000}";
        string Max(Func<AuditReport, float> f) => ex.Count == 0 ? "-" : $"{ex.Max(f):0.000}";
        return $"{reports.Count} cases: {right} fully right ({100.0 * right / reports.Count:0}%), {exact} exact, {wrong} wrong answers, {clean}/{animated} clean animations; " +
            $"start distance across median {Median(r => r.StartAcross)} max {Max(r => r.StartAcross)} m, up/down median {Median(r => r.StartUpDown)} max {Max(r => r.StartUpDown)} m; " +
            $"goal across median {Median(r => r.GoalAcross)} max {Max(r => r.GoalAcross)} m, up/down median {Median(r => r.GoalUpDown)} max {Max(r => r.GoalUpDown)} m; " +
            $"contact off mesh median {Median(r => r.MaxContactOffMesh)} max {Max(r => r.MaxContactOffMesh)} m, normal error max {Max(r => r.MaxContactNormalError)}°";
    }
}
