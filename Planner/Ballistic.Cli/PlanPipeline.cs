using System.Diagnostics;
using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Reports;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;

namespace Ballistic.Cli;

/// <summary>The plan job shared by <c>plan</c> and <c>demo</c>: load or bake a roadmap, query it, write the report.</summary>
internal sealed class PlanPipeline
{
    public required string LevelPath { get; init; }

    public required Level Level { get; init; }

    public required ReducedCharacter Character { get; init; }

    public required CharacterModel Model { get; init; }

    public required Vector3 From { get; init; }

    public required Vector3 To { get; init; }

    public string? RoadmapPath { get; init; }

    public int Seed { get; init; } = 1;

    public int Threads { get; init; } = Environment.ProcessorCount;

    public int MaxNodes { get; init; } = 400;

    public TimeSpan? TimeLimit { get; init; }

    public EndpointTolerance Tolerance { get; init; } = new();

    public PlanningScene? Scene { get; init; }

    public IDictionary<string, double> Timings { get; } = new Dictionary<string, double>();

    /// <summary>Runs the job; the report and the roadmap it used.</summary>
    public (PlanReport Report, Roadmap Roadmap) Run(TextWriter error)
    {
        var clock = Stopwatch.StartNew();
        PlanningScene scene = Scene ?? PlanningScene.Create(Level, Character);
        Timings["prepareScene"] = clock.Elapsed.TotalSeconds;

        Roadmap roadmap;
        double bakeSeconds = 0;
        if (RoadmapPath is not null)
        {
            clock.Restart();
            roadmap = RoadmapFile.Load(RoadmapPath, Level.Fingerprint, Character);
            Timings["loadRoadmap"] = clock.Elapsed.TotalSeconds;
        }
        else
        {
            var settings = new BakeSettings
            {
                Seed = Seed,
                Threads = Threads,
                MaxNodes = MaxNodes,
                TimeLimit = TimeLimit,
                Start = From,
                Goal = To,
                StopWhenConnected = true,
                Tolerance = Tolerance,
            };
            ConsoleProgress? progress = ConsoleProgress.IsInteractive(error) ? new ConsoleProgress(error, MaxNodes) : null;
            BakeResult bake = new RoadmapBaker(scene).Bake(settings, progress: progress);
            progress?.Finish();
            roadmap = bake.Roadmap;
            bakeSeconds = bake.Elapsed.TotalSeconds;
            Timings["bake"] = bakeSeconds;
            if (bake.Status is PlannerStatus.InvalidStart or PlannerStatus.InvalidGoal or PlannerStatus.Cancelled)
            {
                var failed = new PlanResult(bake.Status, bake.Reason, null, null, [], TimeSpan.Zero);
                return (Report(scene, roadmap, bakeSeconds, failed), roadmap);
            }
        }

        clock.Restart();
        PlanResult result = new PathQuery(scene, roadmap).Plan(From, To, new QuerySettings { Tolerance = Tolerance });
        Timings["query"] = clock.Elapsed.TotalSeconds;
        return (Report(scene, roadmap, bakeSeconds, result), roadmap);
    }

    private PlanReport Report(PlanningScene scene, Roadmap roadmap, double bakeSeconds, PlanResult result) =>
        new(LevelPath, scene, From, To, roadmap.Nodes.Count, roadmap.Edges.Count, roadmap.Seed, bakeSeconds, result, new Dictionary<string, double>(Timings));

    /// <summary>Writes the report (and SVG) and prints a summary.</summary>
    public void Write(PlanReport report, Roadmap roadmap, string reportPath, string? svgPath, TextWriter output, string? glbPath = null)
    {
        string? animationLine = null;
        if (glbPath is not null && report.Result.Status == PlannerStatus.Exact)
        {
            CharacterModel model = Model;
            var clock = Stopwatch.StartNew();
            JumpAnimation animation = new JumpAnimator(report.Scene, model).Animate(report.Result.Jumps);
            AnimatedGlbWriter.Save(animation, glbPath, "jumps");
            var timings = new Dictionary<string, double>(report.Timings) { ["animate"] = clock.Elapsed.TotalSeconds };
            string relative = Path.GetRelativePath(Path.GetDirectoryName(Path.GetFullPath(reportPath))!, Path.GetFullPath(glbPath));
            report = report with { Timings = timings, Animation = new AnimationReport(relative, "jumps", animation) };
            animationLine = $"animation: {animation.Duration:0.00} s, {animation.Frames.Count} frames, {animation.ContactPhases.Count} contact phases, {animation.FailedContactPoses} of {2 * animation.Arcs.Count} contact poses failing the no-slip test; {glbPath}";
        }

        PlanReportWriter.Save(report, reportPath);
        if (svgPath is not null)
        {
            SvgPlanRenderer.Save(report, roadmap, svgPath);
        }

        PlanResult r = report.Result;
        output.WriteLine($"status: {PlanReportWriter.StatusName(r.Status)} ({r.Reason})");
        output.WriteLine($"roadmap: {report.RoadmapNodes} nodes, {report.RoadmapEdges} jumps, seed {report.Seed}");
        if (r.Jumps.Count > 0)
        {
            output.WriteLine($"path: {r.Jumps.Count} jumps, {r.TotalFlightTime:0.00} s of flight, {r.Jumps.Sum(j => j.Arc.ArcLength):0.0} m of arcs");
        }

        if (animationLine is not null)
        {
            output.WriteLine(animationLine);
        }

        output.WriteLine("timings: " + string.Join(", ", report.Timings.Select(t => $"{t.Key} {t.Value * 1000:0.#} ms")));
        output.WriteLine($"report: {reportPath}" + (svgPath is null ? "" : $"; picture: {svgPath}"));
    }
}
