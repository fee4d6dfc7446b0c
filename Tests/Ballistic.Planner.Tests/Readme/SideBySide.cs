using System.Collections.Concurrent;
using System.Globalization;
using System.Numerics;
using Ballistic.Cli;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Readme;

/// <summary>
/// The README's side-by-side table (jump only against walk + jump), made the way the README says: per bundled level
/// an 800-node walking roadmap (seed 1, two threads), the level's demo request (the <c>bench</c> tool's path, where it
/// has one) and then node pairs drawn with seed 5, each planned by <see cref="PathQuery"/> both ways.
/// </summary>
internal static class SideBySide
{
    /// <summary>The levels of the table: label, bundled level, preset character, demo request (x, z pairs) or none, node pairs.</summary>
    public static readonly (string Label, string Level, string Character, (float X0, float Z0, float X1, float Z1)? Demo, int Pairs)[] Levels =
    [
        ("desert", "desert", "skeleton", (-9.5f, -7.5f, 9.5f, 7.5f), 2),
        ("gap course", "gap-course", "skeleton", (-6f, 0f, 11.5f, 0f), 2),
        ("pond", "pond", "frog", (-0.5f, -5.8f, 0.5f, 4.6f), 0),
        ("rooftops", "rooftops", "jumperman", null, 2),
    ];

    private static readonly ConcurrentDictionary<string, Lazy<(PlanningScene Scene, Roadmap Roadmap)>> Baked = new(StringComparer.Ordinal);

    /// <summary>The 800-node walking roadmap (seed 1) of a bundled level and preset character, baked once per test run.</summary>
    public static (PlanningScene Scene, Roadmap Roadmap) Roadmap(string level, string character) =>
        Baked.GetOrAdd($"{level}|{character}", _ => new Lazy<(PlanningScene, Roadmap)>(() =>
        {
            PlanningScene scene = SharedLevels.Scene(level, character);
            return (scene, new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 1, MaxNodes = 800, Threads = 2 }).Roadmap);
        })).Value;

    /// <summary>The requests of a level's rows: its demo request first (on the ground, as the tool places it), then the node pairs.</summary>
    public static IReadOnlyList<(Vector3 From, Vector3 To)> Requests(string label)
    {
        (_, string level, string character, (float X0, float Z0, float X1, float Z1)? demo, int pairs) = Levels.Single(l => l.Label == label);
        (PlanningScene scene, Roadmap roadmap) = Roadmap(level, character);
        var requests = new List<(Vector3, Vector3)>();
        if (demo is { } d)
        {
            requests.Add((CliInputs.OnGround(scene.Bvh, d.X0, d.Z0, 0f), CliInputs.OnGround(scene.Bvh, d.X1, d.Z1, 0f)));
        }

        var random = new Random(5);
        for (int i = 0; i < pairs; i++)
        {
            requests.Add((roadmap.ContactCentres[random.Next(roadmap.Nodes.Count)], roadmap.ContactCentres[random.Next(roadmap.Nodes.Count)]));
        }

        return requests;
    }

    /// <summary>The table rows of a level, as the README writes them.</summary>
    public static IReadOnlyList<string> Rows(string label)
    {
        (_, string level, string character, _, _) = Levels.Single(l => l.Label == label);
        (PlanningScene scene, Roadmap roadmap) = Roadmap(level, character);
        var query = new PathQuery(scene, roadmap);
        var rows = new List<string>();
        foreach ((Vector3 from, Vector3 to) in Requests(label))
        {
            PlanResult jumped = query.Plan(from, to, new QuerySettings { Locomotion = Locomotion.Jump });
            PlanResult walked = query.Plan(from, to, new QuerySettings { Locomotion = Locomotion.WalkAndJump });
            string jumpOnly = Cell(jumped);
            string both = Cell(walked);
            rows.Add($"| {label}, {character} | ({Number(from.X)}, {Number(from.Z)}) → ({Number(to.X)}, {Number(to.Z)}) | {jumpOnly} | {(both == jumpOnly ? "the same" : both)} |");
        }

        return rows;
    }

    private static string Cell(PlanResult plan)
    {
        if (plan.Status != PlannerStatus.Exact)
        {
            return $"no path ({plan.Status})";
        }

        int jumps = plan.Jumps.Count;
        Walk[] walks = [.. plan.Walks];
        string moves = (jumps, walks.Length) switch
        {
            (_, 0) => Count(jumps, "jump"),
            (0, _) => Count(walks.Length, "walk"),
            _ => $"{Count(jumps, "jump")} + {Count(walks.Length, "walk")} ({walks.Sum(w => w.Length).ToString("0.0", CultureInfo.InvariantCulture)} m)",
        };
        float length = plan.Jumps.Sum(j => j.Arc.ArcLength) + walks.Sum(w => w.Length);
        return string.Create(CultureInfo.InvariantCulture, $"{moves}, {plan.TotalDuration:0.0} s, {length:0.0} m");
    }

    private static string Count(int n, string what) => n == 1 ? $"1 {what}" : $"{n} {what}s";

    /// <summary>A coordinate as the README writes it: one decimal at most, a real minus sign.</summary>
    private static string Number(float value) => value.ToString("0.#", CultureInfo.InvariantCulture).Replace('-', '−');
}
