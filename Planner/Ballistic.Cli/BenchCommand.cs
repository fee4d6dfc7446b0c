using System.CommandLine;
using System.Diagnostics;
using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;

namespace Ballistic.Cli;

/// <summary>
/// <c>bench</c>: the paper's planning columns (roadmap construction time to its node counts, Table 1) on the
/// bundled levels, plus query time on a 1,000-node roadmap and the throughput of the two innermost operations.
/// Medians over several runs; one thread unless told otherwise, like the paper's single core.
/// </summary>
internal static class BenchCommand
{
    private static readonly (string Level, string Character, int Nodes, double PaperSeconds)[] Scenarios =
    [
        ("desert", "skeleton", 22, 0.51),
        ("pond", "frog", 47, 0.76),
        ("rooftops", "jumperman", 142, 44.93),
        ("rooftops", "skeleton", 1256, 107.13),
    ];

    private static readonly (string Level, string Character, Vector3 From, Vector3 To)[] AnimationPaths =
    [
        ("desert", "skeleton", new Vector3(-9.5f, 0f, -7.5f), new Vector3(9.5f, 0f, 7.5f)),
        ("pond", "frog", new Vector3(-0.5f, 0f, -5.8f), new Vector3(0.5f, 0f, 4.6f)),
        ("gap-course", "ant", new Vector3(-6f, 0f, 0f), new Vector3(11.5f, 1f, 0f)),
        ("gap-course", "skeleton", new Vector3(-6f, 0f, 0f), new Vector3(11.5f, 1f, 0f)),
    ];

    public static Command Create()
    {
        Option<int> runs = new("--runs") { Description = "Runs per measurement; the median is printed.", DefaultValueFactory = _ => 5 };
        Option<int> threads = new("--threads") { Description = "Bake threads (the paper used one core).", DefaultValueFactory = _ => 1 };
        Option<string?> only = new("--only") { Description = "Run only the scenarios whose level or character contains this text." };
        var command = new Command("bench", "Benchmark bakes to the paper's node counts, queries, steering and box queries; prints medians.") { runs, threads, only };
        command.SetAction(parse => CliCommands.Guard(parse, () =>
        {
            int n = parse.GetValue(runs);
            int t = parse.GetValue(threads);
            if (n is < 1 or > 1000)
            {
                throw new CliException($"--runs takes 1 to 1000 runs, not {n}.");
            }

            if (t is < 1 or > 1024)
            {
                throw new CliException($"--threads takes 1 to 1024 threads, not {t}.");
            }

            string? filter = parse.GetValue(only);
            if (filter is not null && !Scenarios.Any(s => Matches(filter, s.Level, s.Character)) && !AnimationPaths.Any(p => Matches(filter, p.Level, p.Character)))
            {
                string names = string.Join(", ", Scenarios.SelectMany(s => new[] { s.Level, s.Character }).Concat(AnimationPaths.SelectMany(p => new[] { p.Level, p.Character })).Distinct());
                throw new CliException($"--only '{filter}' matches no level or character of the bench ({names}).");
            }

            Run(parse.InvocationConfiguration.Output, n, t, filter);
            return 0;
        }));
        return command;
    }

    private static void Run(TextWriter output, int runs, int threads, string? only)
    {
        output.WriteLine($"Ballistic bench: median of {runs} runs, {threads} bake thread(s), .NET {Environment.Version}, {Environment.ProcessorCount} cores");
        output.WriteLine();
        output.WriteLine("| scenario | triangles | roadmap CT (s) | nodes | jumps | paper CT (s) |");
        output.WriteLine("|---|---:|---:|---:|---:|---:|");
        var levels = new Dictionary<string, Level>();
        foreach ((string levelName, string characterName, int nodes, double paper) in Scenarios)
        {
            if (!Matches(only, levelName, characterName))
            {
                continue;
            }

            Level level = levels.TryGetValue(levelName, out Level? cached) ? cached : levels[levelName] = LoadBundled(levelName);
            var scene = PlanningScene.Create(level, CharacterPresets.Get(characterName));
            var baker = new RoadmapBaker(scene);
            var times = new List<double>();
            BakeResult? last = null;
            baker.Bake(new BakeSettings { Locomotion = Locomotion.Jump, Seed = 1_000, MaxNodes = Math.Min(nodes, 50), Threads = threads }); // warm-up, not counted
            for (int r = 0; r < runs; r++)
            {
                last = baker.Bake(new BakeSettings { Locomotion = Locomotion.Jump, Seed = r + 1, MaxNodes = nodes, Threads = threads });
                times.Add(last.Elapsed.TotalSeconds);
            }

            output.WriteLine($"| {characterName} on {levelName} | {level.Triangles.Count:N0} | {Median(times):0.0000} | {last!.Roadmap.Nodes.Count} | {last.Roadmap.Edges.Count} | {paper} |");
        }

        if (Matches(only, "desert", "skeleton"))
        {
            DesertQueries(output, runs, levels);
        }

        Animation(output, runs, levels, only);
    }

    /// <summary>Query, steering and box queries on the desert with the skeleton.</summary>
    private static void DesertQueries(TextWriter output, int runs, Dictionary<string, Level> levels)
    {
        Level desert = levels.TryGetValue("desert", out Level? d) ? d : LoadBundled("desert");
        var desertScene = PlanningScene.Create(desert, CharacterPresets.Skeleton());
        Roadmap roadmap = new RoadmapBaker(desertScene).Bake(new BakeSettings { Locomotion = Locomotion.Jump, Seed = 7, MaxNodes = 1_000, Threads = Environment.ProcessorCount }).Roadmap;
        var query = new PathQuery(desertScene, roadmap);
        var random = new Random(3);
        const int warmUp = 100;
        int count = Math.Max(100, runs * 40);

        // Each request between two new random nodes (jump only, the jumps turned to face their way), timed one by one:
        // from the nodes' first contacts (both ends placed and steered into the roadmap), then between other nodes
        // (their own random pairs, so that the steering pairs below stay those drawn before).
        (List<double> pointTimes, int pointFound) = TimeQueries(roadmap, random, warmUp, count, (a, b) =>
            query.Plan(a.Contacts.Count > 0 ? a.Contacts[0].Position : a.Pose.Position, b.Contacts.Count > 0 ? b.Contacts[0].Position : b.Pose.Position, new QuerySettings { Locomotion = Locomotion.Jump }));
        (List<double> nodeTimes, int nodeFound) = TimeQueries(roadmap, new Random(4), warmUp, count, (a, b) => query.Plan(a, b, new QuerySettings { Locomotion = Locomotion.Jump }));

        // The same requests again, in the same order (the same seeds draw the same pairs): routes taken before, as a
        // game's agents take them again, with the placements and arcs the scene remembered from the first time.
        (List<double> pointAgain, int pointFoundAgain) = TimeQueries(roadmap, new Random(3), warmUp, count, (a, b) =>
            query.Plan(a.Contacts.Count > 0 ? a.Contacts[0].Position : a.Pose.Position, b.Contacts.Count > 0 ? b.Contacts[0].Position : b.Pose.Position, new QuerySettings { Locomotion = Locomotion.Jump }));
        (List<double> nodeAgain, int nodeFoundAgain) = TimeQueries(roadmap, new Random(4), warmUp, count, (a, b) => query.Plan(a, b, new QuerySettings { Locomotion = Locomotion.Jump }));

        output.WriteLine();
        output.WriteLine($"query on a {roadmap.Nodes.Count}-node, {roadmap.Edges.Count}-jump desert roadmap: median {Median(pointTimes):0.000} ms, p95 {Percentile(pointTimes, 0.95):0.000} ms over {pointTimes.Count} queries after {warmUp} warm-up queries ({pointFound} found a path)");
        output.WriteLine($"node to node on it: median {Median(nodeTimes):0.000} ms, p95 {Percentile(nodeTimes, 0.95):0.000} ms over {nodeTimes.Count} queries after {warmUp} warm-up queries ({nodeFound} found a path)");
        output.WriteLine($"the same requests again (routes taken before): point to point median {Median(pointAgain):0.000} ms, p95 {Percentile(pointAgain, 0.95):0.000} ms ({pointFoundAgain} found a path); node to node median {Median(nodeAgain):0.000} ms, p95 {Percentile(nodeAgain, 0.95):0.000} ms ({nodeFoundAgain} found a path)");

        // The same new routes on a scene of their own whose query was prepared first (PathQuery.Prepare, as a game's
        // world does at a level's load): every roadmap jump planned once ahead of time, what it placed and steered kept.
        var preparedScene = PlanningScene.Create(desert, desertScene.Character);
        var prepared = new PathQuery(preparedScene, roadmap);
        GC.Collect();
        long heapBefore = GC.GetTotalMemory(forceFullCollection: true);
        var preparing = Stopwatch.StartNew();
        int preparedPairs = prepared.Prepare(new QuerySettings { Locomotion = Locomotion.Jump }, Environment.ProcessorCount);
        double prepareSeconds = preparing.Elapsed.TotalSeconds;
        double keptMegabytes = (GC.GetTotalMemory(forceFullCollection: true) - heapBefore) / 1e6;
        (List<double> pointPrepared, int pointFoundPrepared) = TimeQueries(roadmap, new Random(3), warmUp, count, (a, b) =>
            prepared.Plan(a.Contacts.Count > 0 ? a.Contacts[0].Position : a.Pose.Position, b.Contacts.Count > 0 ? b.Contacts[0].Position : b.Pose.Position, new QuerySettings { Locomotion = Locomotion.Jump }));
        (List<double> nodePrepared, int nodeFoundPrepared) = TimeQueries(roadmap, new Random(4), warmUp, count, (a, b) => prepared.Plan(a, b, new QuerySettings { Locomotion = Locomotion.Jump }));
        output.WriteLine($"new routes after preparing the query ({preparedPairs:N0} node pairs on {Environment.ProcessorCount} threads in {prepareSeconds:0.0} s, {preparedScene.KeptCount:N0} results kept, {keptMegabytes:0} MB): point to point median {Median(pointPrepared):0.000} ms, p95 {Percentile(pointPrepared, 0.95):0.000} ms ({pointFoundPrepared} found a path); node to node median {Median(nodePrepared):0.000} ms, p95 {Percentile(nodePrepared, 0.95):0.000} ms ({nodeFoundPrepared} found a path)");

        ParabolaSteering steering = desertScene.Steering;
        var pairs = new List<(RoadmapNode A, RoadmapNode B)>();
        for (int i = 0; i < 20_000; i++)
        {
            pairs.Add((roadmap.Nodes[random.Next(roadmap.Nodes.Count)], roadmap.Nodes[random.Next(roadmap.Nodes.Count)]));
        }

        var near = pairs.Where(p => Vector3.Distance(p.A.Pose.Position, p.B.Pose.Position) < 6f).Take(2_000).ToList();
        var steerRates = new List<double>();
        int valid = 0;
        for (int r = -1; r < runs; r++) // run −1 warms up
        {
            var clock = Stopwatch.StartNew();
            valid = 0;
            foreach ((RoadmapNode a, RoadmapNode b) in near)
            {
                valid += steering.Steer(a.Pose, a.Cone, b.Pose, b.Cone).Succeeded ? 1 : 0;
            }

            if (r >= 0)
            {
                steerRates.Add(near.Count / clock.Elapsed.TotalSeconds);
            }
        }

        output.WriteLine($"steering (pairs within 6 m, {valid} of {near.Count} valid, with collision checks): median {Median(steerRates):N0} pairs/s");

        var boxes = roadmap.Nodes.Select(node => new OrientedBox(node.Pose.Position - new Vector3(0f, 0.3f, 0f), desertScene.Character.TrunkHalfExtents, node.Pose.Rotation)).ToArray();
        var boxRates = new List<double>();
        int hits = 0;
        for (int r = -1; r < runs; r++) // run −1 warms up
        {
            var clock = Stopwatch.StartNew();
            hits = 0;
            for (int rep = 0; rep < 20; rep++)
            {
                foreach (OrientedBox box in boxes)
                {
                    hits += desertScene.Bvh.Overlaps(box) ? 1 : 0;
                }
            }

            if (r >= 0)
            {
                boxRates.Add(20.0 * boxes.Length / clock.Elapsed.TotalSeconds);
            }
        }

        output.WriteLine($"trunk box vs level ({desert.Triangles.Count:N0} triangles, {hits / 20} of {boxes.Length} touching): median {Median(boxRates):N0} queries/s");
    }

    /// <summary>Whether a scenario on <paramref name="level"/> with <paramref name="character"/> runs under <c>--only</c>.</summary>
    private static bool Matches(string? only, string level, string character) =>
        only is null || level.Contains(only, StringComparison.OrdinalIgnoreCase) || character.Contains(only, StringComparison.OrdinalIgnoreCase);

    /// <summary>Whole-body synthesis on a path across each bundled level: contact generation time and success, time per jump.</summary>
    private static void Animation(TextWriter output, int runs, Dictionary<string, Level> levels, string? only)
    {
        (string Level, string Character, Vector3 From, Vector3 To)[] paths = AnimationPaths.Where(p => Matches(only, p.Level, p.Character)).ToArray();
        if (paths.Length == 0)
        {
            return;
        }

        output.WriteLine();
        output.WriteLine("| path | jumps | contact generation (ms, median) | contact poses valid | synthesis per jump (ms, median) |");
        output.WriteLine("|---|---:|---:|---:|---:|");
        int valid = 0;
        int total = 0;
        foreach ((string levelName, string characterName, Vector3 from, Vector3 to) in paths)
        {
            Level level = levels.TryGetValue(levelName, out Level? cached) ? cached : levels[levelName] = LoadBundled(levelName);
            var scene = PlanningScene.Create(level, CharacterPresets.Get(characterName));
            Vector3 start = CliInputs.OnGround(scene.Bvh, from.X, from.Z, from.Y);
            Vector3 goal = CliInputs.OnGround(scene.Bvh, to.X, to.Z, to.Y);
            BakeResult bake = new RoadmapBaker(scene).Bake(new BakeSettings { Locomotion = Locomotion.Jump, MaxNodes = 600, Start = start, Goal = goal, StopWhenConnected = true });
            PlanResult plan = new PathQuery(scene, bake.Roadmap).Plan(start, goal, new QuerySettings { Locomotion = Locomotion.Jump });
            if (plan.Status != PlannerStatus.Exact)
            {
                output.WriteLine($"| {characterName} on {levelName} | no path: {plan.Reason} | | | |");
                continue;
            }

            var animator = new JumpAnimator(scene, CharacterPresets.Model(characterName));
            var generation = new List<double>();
            int pathValid = 0;
            for (int r = -1; r < runs; r++)
            {
                foreach (Jump jump in plan.Jumps)
                {
                    var clock = Stopwatch.StartNew();
                    var takeoff = animator.Contacts.Generate(jump.Arc.Takeoff, jump.Takeoff.Contacts, jump.Arc.TakeoffVelocity);
                    double first = clock.Elapsed.TotalMilliseconds;
                    clock.Restart();
                    var landing = animator.Contacts.Generate(jump.Arc.Landing, jump.Landing.Contacts, -jump.Arc.LandingVelocity);
                    if (r >= 0)
                    {
                        generation.Add(first);
                        generation.Add(clock.Elapsed.TotalMilliseconds);
                    }

                    if (r == 0)
                    {
                        pathValid += (takeoff.Valid ? 1 : 0) + (landing.Valid ? 1 : 0);
                    }
                }
            }

            var synthesis = new List<double>();
            for (int r = -1; r < runs; r++)
            {
                var clock = Stopwatch.StartNew();
                animator.Animate(plan.Jumps);
                if (r >= 0)
                {
                    synthesis.Add(clock.Elapsed.TotalMilliseconds / plan.Jumps.Count);
                }
            }

            valid += pathValid;
            total += 2 * plan.Jumps.Count;
            output.WriteLine($"| {characterName} on {levelName} | {plan.Jumps.Count} | {Median(generation):0.000} | {pathValid} of {2 * plan.Jumps.Count} | {Median(synthesis):0.00} |");
        }

        output.WriteLine($"contact generation success over these paths: {valid} of {total} ({100.0 * valid / Math.Max(1, total):0.0}%)");
    }

    private static Level LoadBundled(string name)
    {
        string? path = CliInputs.FindBundledLevel(name);
        return path is null ? CliInputs.Generated(name) : CliInputs.LoadLevel(path);
    }

    /// <summary>
    /// Times (milliseconds) of <paramref name="count"/> requests between random nodes of <paramref name="roadmap"/>
    /// made by <paramref name="plan"/>, after <paramref name="warmUp"/> untimed ones, and how many found a path.
    /// </summary>
    private static (List<double> Times, int Found) TimeQueries(Roadmap roadmap, Random random, int warmUp, int count, Func<RoadmapNode, RoadmapNode, PlanResult> plan)
    {
        var times = new List<double>(count);
        int found = 0;
        for (int q = 0; q < warmUp + count; q++)
        {
            RoadmapNode a = roadmap.Nodes[random.Next(roadmap.Nodes.Count)];
            RoadmapNode b = roadmap.Nodes[random.Next(roadmap.Nodes.Count)];
            long start = Stopwatch.GetTimestamp();
            PlanResult result = plan(a, b);
            if (q >= warmUp)
            {
                times.Add(Stopwatch.GetElapsedTime(start).TotalMilliseconds);
                found += result.Status == PlannerStatus.Exact ? 1 : 0;
            }
        }

        return (times, found);
    }

    /// <summary>The value below which a share <paramref name="share"/> (0 to 1) of <paramref name="values"/> lies (nearest rank).</summary>
    private static double Percentile(List<double> values, double share)
    {
        var sorted = values.Order().ToList();
        return sorted[Math.Clamp((int)Math.Ceiling(share * sorted.Count) - 1, 0, sorted.Count - 1)];
    }

    private static double Median(List<double> values)
    {
        var sorted = values.Order().ToList();
        return sorted.Count % 2 == 1 ? sorted[sorted.Count / 2] : 0.5 * (sorted[(sorted.Count / 2) - 1] + sorted[sorted.Count / 2]);
    }
}
