using System.CommandLine;
using System.Globalization;
using Ballistic.Authoring.Characters;
using Ballistic.Authoring.Playtest;
using Ballistic.Authoring.Reports;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Characters;
using Ballistic.Planner.IO;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Cli;

/// <summary>
/// <c>ballistic playtest</c>: many agents navigate a level headless with the runtime's systems; writes a JSON report
/// (<c>ballistic.playtest/1</c>) and a map of where agents went and failed (SVG and PNG).
/// </summary>
internal static class PlaytestCommand
{
    public static Command Create(CancellationToken cancellation = default)
    {
        Option<string> level = new("--level") { Description = "Level file (.glb or .gltf), Y up, metres.", Required = true };
        Option<string> character = new("--character") { Description = $"Character preset ({string.Join(", ", CharacterPresets.Names)}), or a limb spec NAME.limbs.json with its rigged NAME.glb beside it.", Required = true };
        Option<int> agents = new("--agents") { Description = "Agents spawned on random stances.", DefaultValueFactory = _ => 8 };
        Option<double> seconds = new("--seconds") { Description = "Simulated seconds.", DefaultValueFactory = _ => 60, CustomParser = r => CliCommands.Number(r, "--seconds") };
        Option<int> seed = new("--seed") { Description = "Seed of the spawns, the targets and (without --roadmap) the bake.", DefaultValueFactory = _ => 1 };
        Option<string?> roadmap = new("--roadmap") { Description = "Roadmap file from 'bake'; without it the tool bakes one first." };
        Option<int> maxNodes = new("--max-nodes") { Description = "Nodes of the roadmap baked without --roadmap.", DefaultValueFactory = _ => 600 };
        Option<int> threads = new("--threads") { Description = "Worker threads (the results do not depend on it).", DefaultValueFactory = _ => Environment.ProcessorCount };
        Option<string> output = new("--out") { Description = "Folder for LEVEL-CHARACTER-playtest.json, .svg and .png.", DefaultValueFactory = _ => "out" };
        Option<string> locomotion = CliCommands.LocomotionOption();
        Option<double> jumpEffort = CliCommands.JumpEffortOption();
        Option<double> jumpHeightEffort = CliCommands.JumpHeightEffortOption();
        Option<bool> realTime = new("--real-time") { Description = "Step the world as a game does: each tick at its moment on the wall clock, a tick waiting at most 0.25 s for a late request (the Godot server's world). The tick times are then what a game's main thread pays; the run then depends on the machine." };
        var command = new Command("playtest", "Many agents navigate the level by walks and jumps, headless, toward random targets; writes a report and a map of where they failed.")
        {
            level, character, agents, seconds, seed, roadmap, maxNodes, threads, output, locomotion, jumpEffort, jumpHeightEffort, realTime,
        };
        command.SetAction(parse => CliCommands.Guard(parse, () =>
        {
            TextWriter stdout = parse.InvocationConfiguration.Output;
            TextWriter stderr = parse.InvocationConfiguration.Error;
            string levelPath = parse.GetValue(level)!;
            int threadCount = parse.GetValue(threads) is int t and >= 1 and <= 1024 ? t : throw new CliException($"--threads takes 1 to 1024 threads, not {parse.GetValue(threads)}.");
            var settings = new PlaytestSettings
            {
                Agents = parse.GetValue(agents),
                Seconds = parse.GetValue(seconds),
                Seed = parse.GetValue(seed),
                AnimationThreads = Math.Max(1, threadCount - 1),
                Locomotion = CliCommands.ParseLocomotion(parse.GetValue(locomotion)!),
                JumpEffort = CliCommands.Effort(parse.GetValue(jumpEffort), "--jump-effort"),
                JumpHeightEffort = CliCommands.Effort(parse.GetValue(jumpHeightEffort), "--jump-height-effort", "seconds per metre"),
                RealTime = parse.GetValue(realTime),
            };
            if (settings.Problem() is { } problem)
            {
                throw new CliException(problem + ".");
            }

            int nodes = parse.GetValue(maxNodes) is int n and >= 1 and <= 1_000_000 ? n : throw new CliException($"--max-nodes takes 1 to 1,000,000 nodes, not {parse.GetValue(maxNodes)}.");
            Level lvl = CliInputs.LoadLevel(levelPath, parse.InvocationConfiguration.Error);
            (ReducedCharacter reduced, CharacterModel model) = CliInputs.Character(parse.GetValue(character)!, parse.InvocationConfiguration.Error);
            // The character's name comes from its spec (a mod's file): a slug, never a path. The outputs are checked
            // before the bake and the simulation, which may take minutes.
            string folder = parse.GetValue(output)!;
            string stem = Path.Combine(folder, $"{OutputName.Slug(Path.GetFileNameWithoutExtension(levelPath), "level")}-{OutputName.Slug(reduced.Name, "character")}-playtest");
            foreach (string extension in (string[])[".json", ".svg", ".png"])
            {
                OutputFile.Check(stem + extension);
            }

            var scene = PlanningScene.Create(lvl, reduced);
            Roadmap map;
            if (parse.GetValue(roadmap) is { } roadmapPath)
            {
                map = RoadmapFile.Load(roadmapPath, lvl, reduced);
                stdout.WriteLine($"roadmap: {roadmapPath}: {map.Nodes.Count} nodes, {map.Edges.Count} jumps");
            }
            else
            {
                ConsoleProgress bakeProgress = ConsoleProgress.For(stderr, nodes);
                BakeResult bake = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = settings.Seed, MaxNodes = nodes, Threads = threadCount, Locomotion = settings.Locomotion }, TerminationCondition.Cancellation(cancellation), bakeProgress);
                bakeProgress.Finish();
                if (bake.Status == PlannerStatus.Cancelled)
                {
                    stderr.WriteLine("cancelled: nothing written.");
                    return ExitCode.Cancelled;
                }

                map = bake.Roadmap;
                stdout.WriteLine($"roadmap: baked {map.Nodes.Count} nodes, {map.Edges.Count} jumps, {map.Walks.Count} walks in {bake.Elapsed.TotalSeconds:0.##} s (seed {settings.Seed})");
                if (map.Nodes.Count == 0)
                {
                    stderr.WriteLine($"error: no roadmap to playtest on: {bake.Reason}.");
                    return ExitCode.NotFound;
                }
            }

            var kind = new CharacterKind(scene, map, new JumpAnimator(scene, model));
            TickProgress? progress = ConsoleProgress.IsInteractive(stderr) ? new TickProgress(stderr, settings.Seconds) : null;
            PlaytestResult result = PlaytestRunner.Run(kind, settings, progress, cancellation);
            progress?.Finish();

            // Written even when cancelled (what was simulated is kept; the report says it was cut short), as one set.
            string picture = PlaytestMapRenderer.Svg(result);
            OutputFile.WriteAll(
            [
                (stem + ".svg", System.Text.Encoding.UTF8.GetBytes(picture)),
                (stem + ".png", PlaytestMapRenderer.Png(picture)),
                (stem + ".json", PlaytestReportWriter.ToJson(result, levelPath.Replace('\\', '/'))),
            ]);
            IReadOnlyList<double> times = result.TimesToReach;
            stdout.WriteLine($"agents: {result.Agents.Count} for {result.Ticks / (double)settings.TickRate:0.#} s ({result.Ticks} ticks) in {result.WallSeconds:0.##} s wall time{(result.Cancelled ? ", cancelled" : "")}");
            if (result.TickTimes is { } cost)
            {
                stdout.WriteLine(string.Create(CultureInfo.InvariantCulture, $"ticks: median {cost.MedianMilliseconds:0.###} ms, p95 {cost.P95Milliseconds:0.###} ms, worst {cost.WorstMilliseconds:0.###} ms on the tick thread ({cost.OverFrame} longer than a 60 Hz frame); {cost.CpuMillisecondsPerTick:0.###} ms of CPU per tick on all threads; {cost.BytesAllocatedPerTick:0} bytes allocated per tick on the tick thread"));
            }

            if (settings.RealTime)
            {
                stdout.WriteLine($"real time: {result.LateRequests} requests delivered after their due tick (a tick waits at most {WorldSettings.RealTimeAnimationWait.TotalSeconds:0.##} s for one)");
            }

            stdout.WriteLine($"targets: {result.TargetsReached} reached, {result.TargetsFailed} failed; {result.JumpsTaken} jumps and {result.WalksTaken} walks ({result.WalkedMetres:0.#} m) taken");
            if (times.Count > 0)
            {
                stdout.WriteLine($"time to reach: median {times[times.Count / 2]:0.##} s, max {times[^1]:0.##} s");
            }

            stdout.WriteLine($"roadmap connectivity: {result.PairsConnected} of {result.PairsSampled} random node pairs connected");
            foreach (IGrouping<string, PlaytestTarget> failure in result.Agents.SelectMany(a => a.Targets).Where(x => x.Failed).GroupBy(x => PlanReportWriter.StatusName(x.FailureStatus!.Value)))
            {
                stdout.WriteLine($"failed ({failure.Key}): {failure.Count()}, e.g. {failure.First().FailureReason}");
            }

            foreach (PlaytestAgent stuck in result.Stuck)
            {
                PlaytestTarget first = stuck.Targets.First(t => t.Failed);
                stdout.WriteLine(string.Create(CultureInfo.InvariantCulture, $"stuck: agent {stuck.Index} at ({first.From.X:0.##}, {first.From.Y:0.##}, {first.From.Z:0.##}) failed all {stuck.Targets.Count(t => t.Failed)} of its targets from there (first: {first.FailureReason})"));
            }

            stdout.WriteLine($"written: {stem}.json, {stem}.svg, {stem}.png");
            return result.Cancelled ? ExitCode.Cancelled : ExitCode.Success;
        }));
        return command;
    }

    /// <summary>A one-line progress bar of simulated time, on an interactive terminal.</summary>
    private sealed class TickProgress(TextWriter writer, double seconds) : IProgress<double>
    {
        private DateTime _last = DateTime.MinValue;

        public void Report(double value)
        {
            if (DateTime.UtcNow - _last < TimeSpan.FromMilliseconds(100))
            {
                return;
            }

            _last = DateTime.UtcNow;
            const int width = 30;
            writer.Write($"\r[{new string('#', (int)(width * Math.Clamp(value, 0, 1))).PadRight(width, '.')}] {value * seconds:0.0} of {seconds:0.#} s simulated ");
            writer.Flush();
        }

        public void Finish()
        {
            writer.Write("\r" + new string(' ', 78) + "\r");
            writer.Flush();
        }
    }
}
