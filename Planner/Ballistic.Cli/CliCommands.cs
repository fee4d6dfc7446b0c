using System.CommandLine;
using System.CommandLine.Parsing;
using System.Diagnostics;
using System.Globalization;
using System.Numerics;
using System.Runtime.ExceptionServices;
using Ballistic.Authoring.Animation;
using Ballistic.Authoring.Characters;
using Ballistic.Authoring.Levels;
using Ballistic.Authoring.Reports;
using Ballistic.Planner.Characters;
using Ballistic.Planner.IO;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;
using Ballistic.Runtime.Baking;

namespace Ballistic.Cli;

/// <summary>The subcommands of the tool.</summary>
internal static class CliCommands
{
    public static readonly Option<bool> Verbose = new("--verbose") { Description = "Print stack traces with errors.", Recursive = true };

    private static Option<string> LevelOption() => new("--level") { Description = "Level file (.glb or .gltf), Y up, metres.", Required = true };

    private static Option<string> CharacterOption() => new("--character") { Description = $"Character preset ({string.Join(", ", CharacterPresets.Names)}), or a limb spec NAME.limbs.json with its rigged NAME.glb beside it.", Required = true };

    private static Option<int> SeedOption() => new("--seed") { Description = "Seed of every random choice.", DefaultValueFactory = _ => 1 };

    private static Option<int> ThreadsOption() => new("--threads") { Description = "Worker threads (the roadmap does not depend on it).", DefaultValueFactory = _ => Environment.ProcessorCount };

    internal static Option<string> LocomotionOption() => new("--locomotion") { Description = "walk+jump: walk where the ground allows, jump where it must; jump: jumps only (the paper's planner).", DefaultValueFactory = _ => "walk+jump" };

    /// <summary>The --jump-effort option: seconds of walking every jump costs beyond its flight time.</summary>
    internal static Option<double> JumpEffortOption() => new("--jump-effort")
    {
        Description = "Seconds of walking every jump costs beyond its flight time (walk+jump only).",
        DefaultValueFactory = _ => QuerySettings.DefaultJumpEffort,
        CustomParser = r => Number(r, "--jump-effort"),
    };

    /// <summary>The --jump-height-effort option: seconds per metre of a jump's energy height on top of --jump-effort.</summary>
    internal static Option<double> JumpHeightEffortOption() => new("--jump-height-effort")
    {
        Description = "Seconds of walking per metre of a jump's energy height |v|²/2g, on top of --jump-effort: raise it to walk round walls rather than vault them (walk+jump only).",
        DefaultValueFactory = _ => QuerySettings.DefaultJumpHeightEffort,
        CustomParser = r => Number(r, "--jump-height-effort"),
    };

    /// <summary>A jump cost given on the command line in <paramref name="unit"/>, checked: 0 to 3600.</summary>
    internal static float Effort(double value, string option, string unit = "seconds") =>
        value is >= 0 and <= 3600 ? (float)value : throw new CliException(string.Create(CultureInfo.InvariantCulture, $"{option} takes 0 to 3600 {unit}, not {value}."));

    internal static Locomotion ParseLocomotion(string value) => value switch
    {
        "walk+jump" => Locomotion.WalkAndJump,
        "jump" => Locomotion.Jump,
        _ => throw new CliException($"--locomotion must be 'walk+jump' or 'jump', not '{value}'."),
    };

    private static Option<double?> TimeLimitOption() => new("--time-limit") { Description = "Bake time budget in seconds.", CustomParser = r => Number(r, "--time-limit") };

    /// <summary>
    /// A number option's value read strictly: digits with a dot for decimals (and an exponent), invariant culture,
    /// no thousands separators, so that "1,5" is refused instead of read as 15; a refusal says what the option takes.
    /// </summary>
    internal static double Number(ArgumentResult result, string option)
    {
        string text = result.Tokens.Count > 0 ? result.Tokens[^1].Value : "";
        if (double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out double value) && double.IsFinite(value))
        {
            return value;
        }

        result.AddError($"{option} takes a number (a dot for decimals), not '{MessageText.Printable(text)}'");
        return 0;
    }

    public static Command Bake(CancellationToken cancellation = default)
    {
        Option<string> level = LevelOption();
        Option<string> character = CharacterOption();
        Option<int> seed = SeedOption();
        Option<int> threads = ThreadsOption();
        Option<int?> maxNodes = new("--max-nodes") { Description = "Stop at this many nodes (default 200 unless --time-limit is given)." };
        Option<double?> timeLimit = TimeLimitOption();
        Option<string> output = new("--out") { Description = "Roadmap file to write.", Required = true };
        Option<string> locomotion = LocomotionOption();
        var command = new Command("bake", "Bake a roadmap of jumps (and walks) for a character on a level and save it.") { level, character, seed, threads, maxNodes, timeLimit, output, locomotion };
        command.SetAction(parse => Guard(parse, () =>
        {
            TextWriter stdout = parse.InvocationConfiguration.Output;
            TextWriter stderr = parse.InvocationConfiguration.Error;
            Level lvl = CliInputs.LoadLevel(parse.GetValue(level)!, parse.InvocationConfiguration.Error);
            ReducedCharacter chr = CliInputs.Character(parse.GetValue(character)!, parse.InvocationConfiguration.Error).Reduced;
            TimeSpan? limit = Seconds(parse.GetValue(timeLimit), "--time-limit");
            int? nodes = parse.GetValue(maxNodes) is int given ? Nodes(given, "--max-nodes") : (limit is null ? 200 : null);
            var settings = new BakeSettings { Seed = parse.GetValue(seed), Threads = Threads(parse.GetValue(threads)), MaxNodes = nodes, TimeLimit = limit, Locomotion = ParseLocomotion(parse.GetValue(locomotion)!) };
            ConsoleProgress progress = ConsoleProgress.For(stderr, nodes);
            // The editor's bake job classifies the ending: done, cancelled, or failed with the reason.
            BakeOutcome outcome = BakeJob.Run(lvl, chr, settings, cancellation, progress);
            progress.Finish();
            if (outcome.Error is { } refused)
            {
                ExceptionDispatchInfo.Capture(refused).Throw(); // an input the baker refused: its own exit code (Guard)
            }

            if (outcome.Result is { } result)
            {
                // A bake has no "exact": it ends done (its reason says which budget stopped it), cancelled or failed.
                string ending = result.Status == PlannerStatus.Exact ? "done" : PlanReportWriter.StatusName(result.Status);
                stdout.WriteLine($"bake: {ending} ({result.Reason})");
                stdout.WriteLine($"roadmap: {result.Roadmap.Nodes.Count} nodes, {result.Roadmap.Edges.Count} jumps, {result.Roadmap.Walks.Count} walks in {result.Elapsed.TotalSeconds:0.###} s ({result.SteeringCalls} steering calls, {settings.Threads} threads)");
                if (result.SteeringRejections.Count > 0)
                {
                    stdout.WriteLine("jump candidates refused: " + string.Join("; ", result.SteeringRejections.OrderByDescending(r => r.Value).ThenBy(r => r.Key).Select(r => $"{r.Value:N0} {SteeringFailureText.Describe(r.Key)}")));
                }
            }

            string path = parse.GetValue(output)!;
            switch (outcome.Status)
            {
                case BakeJobStatus.Cancelled:
                    if (outcome.Result is null)
                    {
                        stdout.WriteLine("bake: cancelled");
                    }

                    stderr.WriteLine($"cancelled: nothing written{(File.Exists(path) ? $"; {path} is unchanged" : "")}.");
                    return ExitCode.Cancelled;
                case BakeJobStatus.Failed:
                    stderr.WriteLine($"error: nothing written: {outcome.Reason}.");
                    return ExitCode.NotFound;
            }

            RoadmapFile.Save(outcome.Roadmap!, path);
            stdout.WriteLine($"written: {path}");
            return 0;
        }));
        return command;
    }

    public static Command Plan(CancellationToken cancellation = default)
    {
        Option<string> level = LevelOption();
        Option<string> character = CharacterOption();
        Option<string?> roadmap = new("--roadmap") { Description = "Roadmap file from 'bake'; without it the tool bakes first." };
        Option<string> from = new("--from") { Description = "Start point x,y,z (metres), on or near a surface.", Required = true };
        Option<string> to = new("--to") { Description = "Goal point x,y,z (metres), on or near a surface.", Required = true };
        Option<int> seed = SeedOption();
        Option<int> threads = ThreadsOption();
        Option<int> maxNodes = new("--max-nodes") { Description = "When baking: the most nodes before giving up on connecting start and goal.", DefaultValueFactory = _ => 400 };
        Option<double?> timeLimit = TimeLimitOption();
        Option<string> report = new("--report") { Description = "JSON report to write (schema ballistic.plan/2).", Required = true };
        Option<string?> svg = new("--svg") { Description = "SVG picture to write: top view and side profile (with --animate, also NAME-phases.svg: the longest jump in five poses)." };
        Option<bool> animate = new("--animate") { Description = "Animate the whole body along the path and write an animated GLB." };
        Option<string?> glb = new("--glb") { Description = "Animated GLB to write with --animate (default: the report's name with .glb)." };
        Option<string> tolerance = new("--goal-tolerance") { Description = "How close (metres) the first and last stances' contacts must come to --from and --to: ACROSS[,UPDOWN], horizontally and vertically.", DefaultValueFactory = _ => "0.5,0.25" };
        Option<string> locomotion = LocomotionOption();
        Option<double> jumpEffort = JumpEffortOption();
        Option<double> jumpHeightEffort = JumpHeightEffortOption();
        Option<bool> noRefine = new("--no-refine") { Description = "When baking: plan on the roadmap as it stands when start and goal first connect, not baked on while the route jumps where a walk might cost less (without it, a maze's wall is walked round, not vaulted)." };
        var command = new Command("plan", "Plan walks and jumps from one point to another, animate the whole body and write a report.") { level, character, roadmap, from, to, seed, threads, maxNodes, timeLimit, report, svg, animate, glb, tolerance, locomotion, jumpEffort, jumpHeightEffort, noRefine };
        command.SetAction(parse => Guard(parse, () =>
        {
            if (parse.GetValue(noRefine) && parse.GetValue(roadmap) is not null)
            {
                throw new CliException("--no-refine is about baking from the request: it goes without --roadmap.");
            }

            string levelPath = parse.GetValue(level)!;
            (ReducedCharacter reduced, CharacterModel model) = CliInputs.Character(parse.GetValue(character)!, parse.InvocationConfiguration.Error);
            var pipeline = new PlanPipeline
            {
                LevelPath = levelPath,
                Level = CliInputs.LoadLevel(levelPath, parse.InvocationConfiguration.Error),
                Character = reduced,
                Model = model,
                From = CliInputs.ParsePoint(parse.GetValue(from)!, "--from"),
                To = CliInputs.ParsePoint(parse.GetValue(to)!, "--to"),
                RoadmapPath = parse.GetValue(roadmap),
                Seed = parse.GetValue(seed),
                Threads = Threads(parse.GetValue(threads)),
                MaxNodes = Nodes(parse.GetValue(maxNodes), "--max-nodes"),
                TimeLimit = Seconds(parse.GetValue(timeLimit), "--time-limit"),
                Cancellation = cancellation,
                Tolerance = CliInputs.ParseTolerance(parse.GetValue(tolerance)!, "--goal-tolerance"),
                Locomotion = ParseLocomotion(parse.GetValue(locomotion)!),
                JumpEffort = Effort(parse.GetValue(jumpEffort), "--jump-effort"),
                JumpHeightEffort = Effort(parse.GetValue(jumpHeightEffort), "--jump-height-effort", "seconds per metre"),
                Refine = !parse.GetValue(noRefine),
            };
            string reportPath = parse.GetValue(report)!;
            string? glbPath = parse.GetValue(glb);
            if (glbPath is not null && !parse.GetValue(animate))
            {
                throw new CliException("--glb goes with --animate.");
            }

            if (parse.GetValue(animate))
            {
                glbPath ??= Path.ChangeExtension(reportPath, ".glb");
            }

            (PlanReport result, Roadmap used) = pipeline.Run(parse.InvocationConfiguration.Error);
            if (result.Result.Status == PlannerStatus.Cancelled)
            {
                parse.InvocationConfiguration.Error.WriteLine("cancelled: nothing written.");
                return ExitCode.Cancelled;
            }

            pipeline.Write(result, used, reportPath, parse.GetValue(svg), parse.InvocationConfiguration.Output, glbPath);
            return result.Result.Status == PlannerStatus.Exact ? ExitCode.Success : ExitCode.NotFound;
        }));
        return command;
    }

    public static Command Demo(CancellationToken cancellation = default)
    {
        Option<string> output = new("--out") { Description = "Folder for the report, picture and roadmap.", DefaultValueFactory = _ => "out" };
        Option<int> threads = ThreadsOption();
        Option<string> locomotion = LocomotionOption();
        var command = new Command("demo", "The main job: the skeleton crosses the bundled desert; writes a report, an SVG, an animated GLB and the roadmap.") { output, threads, locomotion };
        command.SetAction(parse => Guard(parse, () =>
        {
            TextWriter stdout = parse.InvocationConfiguration.Output;
            var clock = Stopwatch.StartNew();
            string? path = CliInputs.FindBundledLevel("desert");
            Level level = path is null ? CliInputs.Generated("desert") : CliInputs.LoadLevel(path, parse.InvocationConfiguration.Error);
            double loadSeconds = clock.Elapsed.TotalSeconds;
            ReducedCharacter skeleton = CharacterPresets.Skeleton();
            var scene = PlanningScene.Create(level, skeleton);
            Vector3 from = CliInputs.OnGround(scene.Bvh, -9.5f, -7.5f, 0f);
            Vector3 to = CliInputs.OnGround(scene.Bvh, 9.5f, 7.5f, 0f);
            stdout.WriteLine($"level: {path ?? level.Source}: {level.Triangles.Count} triangles, {scene.Surfaces.Surfaces.Count} contact surfaces");
            stdout.WriteLine($"character: {skeleton}");
            stdout.WriteLine($"from ({from.X:0.##}, {from.Y:0.##}, {from.Z:0.##}) to ({to.X:0.##}, {to.Y:0.##}, {to.Z:0.##})");
            var pipeline = new PlanPipeline
            {
                LevelPath = path ?? "desert (generated)",
                Level = level,
                Character = skeleton,
                Model = CharacterPresets.Model("skeleton"),
                Scene = scene,
                From = from,
                To = to,
                Threads = Threads(parse.GetValue(threads)),
                MaxNodes = 600,
                Cancellation = cancellation,
                Locomotion = ParseLocomotion(parse.GetValue(locomotion)!),
            };
            pipeline.Timings["loadLevel"] = loadSeconds;
            (PlanReport report, Roadmap roadmap) = pipeline.Run(parse.InvocationConfiguration.Error);
            if (report.Result.Status == PlannerStatus.Cancelled)
            {
                parse.InvocationConfiguration.Error.WriteLine("cancelled: nothing written.");
                return ExitCode.Cancelled;
            }

            string folder = parse.GetValue(output)!;
            RoadmapFile.Save(roadmap, Path.Combine(folder, "desert-skeleton.roadmap"));
            pipeline.Write(report, roadmap, Path.Combine(folder, "desert-skeleton.json"), Path.Combine(folder, "desert-skeleton.svg"), stdout, Path.Combine(folder, "desert-skeleton.glb"));
            return report.Result.Status == PlannerStatus.Exact ? ExitCode.Success : ExitCode.NotFound;
        }));
        return command;
    }

    public static Command Levels()
    {
        Option<string> output = new("--out") { Description = "Folder to write the levels to.", DefaultValueFactory = _ => Path.Combine("Scenes", "levels") };
        var generate = new Command("generate", $"Write the procedural levels ({string.Join(", ", LevelGenerator.Names)}) as GLB files.") { output };
        generate.SetAction(parse => Guard(parse, () =>
        {
            string folder = parse.GetValue(output)!;
            foreach (string name in LevelGenerator.Names)
            {
                IReadOnlyList<LevelMesh> meshes = LevelGenerator.Generate(name);
                string path = Path.Combine(folder, name + ".glb");
                GltfLevelWriter.Save(path, meshes);
                parse.InvocationConfiguration.Output.WriteLine($"{path}: {meshes.Sum(m => m.Indices.Length / 3)} triangles");
            }

            return 0;
        }));
        return new Command("levels", "Procedural levels.") { generate };
    }

    public static Command Characters()
    {
        Option<string> output = new("--out") { Description = "Folder to write the characters to.", DefaultValueFactory = _ => Path.Combine("Scenes", "characters") };
        var generate = new Command("generate", "Write the four characters as rigged GLB files with their limb specs (NAME.glb, NAME.limbs.json).") { output };
        generate.SetAction(parse => Guard(parse, () =>
        {
            string folder = parse.GetValue(output)!;
            foreach (string name in CharacterPresets.Names)
            {
                CharacterModel model = CharacterPresets.Model(name);
                string glb = Path.Combine(folder, name + ".glb");
                string spec = Path.Combine(folder, name + ".limbs.json");
                OutputFile.Write(glb, AnimatedGlbWriter.ToBytes(model));
                CharacterSpecFile.Save(model, CharacterPresets.Get(name), spec);
                parse.InvocationConfiguration.Output.WriteLine($"{glb}: {model.Rig.Joints.Count} bones, {model.Rig.DofCount} degrees of freedom, {model.Limbs.Count} limbs; {spec}");
            }

            return 0;
        }));
        return new Command("characters", "The characters' rigs.") { generate };
    }

    /// <summary>
    /// Runs a command body: the one error boundary of the tool. Every failure becomes one line on standard error
    /// (<c>--verbose</c> adds the stack trace) and an exit code by its class (<see cref="ExitCode"/>).
    /// </summary>
    internal static int Guard(ParseResult parse, Func<int> body)
    {
        TextWriter stderr = parse.InvocationConfiguration.Error;
        try
        {
            return body();
        }
        catch (Exception e)
        {
            (int code, string line) = e switch
            {
                CliException or ArgumentException => (ExitCode.Usage, e.Message),
                BallisticInputException => (ExitCode.Input, e.Message),
                OutputFileException => (ExitCode.Output, e.Message),
                OperationCanceledException => (ExitCode.Cancelled, "cancelled: nothing written."),
                IOException or UnauthorizedAccessException => (ExitCode.Input, e.Message),
                _ => (ExitCode.Internal, $"internal error ({e.GetType().Name}: {e.Message}); please report it (--verbose shows the details)"),
            };
            stderr.WriteLine(code == ExitCode.Cancelled ? line : $"error: {line}");
            if (parse.GetValue(Verbose))
            {
                stderr.WriteLine(e);
            }

            return code;
        }
    }

    /// <summary>The largest time budget an option takes, seconds (a week).</summary>
    private const double MaxSeconds = 7 * 24 * 3600;

    /// <summary>Least time budget (seconds) an option takes: a millisecond (a shorter one would round to no time at all).</summary>
    private const double MinSeconds = 0.001;

    /// <summary>The largest node budget an option takes.</summary>
    private const int MaxNodeBudget = 10_000_000;

    private static TimeSpan? Seconds(double? value, string option) => value switch
    {
        null => null,
        >= MinSeconds and <= MaxSeconds => TimeSpan.FromSeconds(value.Value),
        _ => throw new CliException(string.Create(CultureInfo.InvariantCulture, $"{option} takes {MinSeconds} to {MaxSeconds:0} seconds (a millisecond to a week), not {value}.")),
    };

    private static int Threads(int value) =>
        value is >= 1 and <= 1024 ? value : throw new CliException($"--threads takes 1 to 1024 threads, not {value}.");

    private static int Nodes(int value, string option) =>
        value is >= 1 and <= MaxNodeBudget ? value : throw new CliException($"{option} takes 1 to {MaxNodeBudget:N0} nodes, not {value}.");
}
