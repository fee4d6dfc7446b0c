using System.Diagnostics;
using System.Numerics;
using System.Text;
using Ballistic.Authoring.Animation;
using Ballistic.Authoring.Reports;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Characters;
using Ballistic.Planner.IO;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;

namespace Ballistic.Cli;

/// <summary>
/// The plan job shared by <c>plan</c> and <c>demo</c>: load or bake a roadmap, plan and animate with lazy repair
/// (<see cref="AnimatedPlanner"/>), write the report.
/// </summary>
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

    /// <summary>Walk where the ground allows and jump where it must (the default), or jump only (the paper).</summary>
    public Locomotion Locomotion { get; init; } = Locomotion.WalkAndJump;

    /// <summary>Seconds of walking every jump costs beyond its flight time (<see cref="QuerySettings.JumpEffort"/>).</summary>
    public float JumpEffort { get; init; } = QuerySettings.DefaultJumpEffort;

    /// <summary>Seconds of walking per metre of a jump's energy height (<see cref="QuerySettings.JumpHeightEffort"/>).</summary>
    public float JumpHeightEffort { get; init; } = QuerySettings.DefaultJumpHeightEffort;

    /// <summary>Bakes on past the first connection while a cheaper route may exist (<see cref="BakeSettings.Refine"/>; <c>true</c> by default); without a roadmap only.</summary>
    public bool Refine { get; init; } = true;

    /// <summary>Cancels the bake or the plan (Ctrl-C, SIGTERM): the report then has status cancelled.</summary>
    public CancellationToken Cancellation { get; init; }

    public PlanningScene? Scene { get; init; }

    public IDictionary<string, double> Timings { get; } = new Dictionary<string, double>();

    /// <summary>Runs the job; the report and the roadmap it used.</summary>
    public (PlanReport Report, Roadmap Roadmap) Run(TextWriter error)
    {
        var clock = Stopwatch.StartNew();
        PlanningScene scene = Scene ?? PlanningScene.Create(Level, Character);
        Timings["prepareScene"] = clock.Elapsed.TotalSeconds;

        clock.Restart();
        var planner = new AnimatedPlanner(scene, new JumpAnimator(scene, Model));
        Timings["prepareAnimator"] = clock.Elapsed.TotalSeconds;
        clock.Restart();
        Roadmap roadmap;
        double bakeSeconds = 0;
        AnimatedPlan plan;
        if (RoadmapPath is not null)
        {
            CliInputs.CheckPath(RoadmapPath, "Roadmap file");
            roadmap = RoadmapFile.Load(RoadmapPath, Level, Character);
            Timings["loadRoadmap"] = clock.Elapsed.TotalSeconds;
            clock.Restart();
            plan = planner.Plan(roadmap, From, To, Query(), termination: TerminationCondition.Cancellation(Cancellation));
            Timings["planAndAnimate"] = clock.Elapsed.TotalSeconds;
        }
        else
        {
            var settings = new BakeSettings { Seed = Seed, Threads = Threads, MaxNodes = MaxNodes, TimeLimit = TimeLimit, Tolerance = Tolerance, Locomotion = Locomotion, Refine = Refine };
            ConsoleProgress progress = ConsoleProgress.For(error, MaxNodes);
            (plan, BakeResult bake) = planner.BakeAndPlan(From, To, settings, TerminationCondition.Cancellation(Cancellation), progress, Query());
            progress.Finish();
            roadmap = bake.Roadmap;
            bakeSeconds = bake.Elapsed.TotalSeconds;
            Timings["bakeAndPlan"] = clock.Elapsed.TotalSeconds;
        }

        Animation = plan.Animation;
        return (Report(scene, roadmap, bakeSeconds, plan.Result) with { Rejected = plan.Rejected }, roadmap);
    }

    /// <summary>The query's settings: the tolerance, locomotion and jump costs given.</summary>
    private QuerySettings Query() => new() { Tolerance = Tolerance, Locomotion = Locomotion, JumpEffort = JumpEffort, JumpHeightEffort = JumpHeightEffort };

    /// <summary>The clean whole-body animation of the last plan, when it has one.</summary>
    public JumpAnimation? Animation { get; private set; }

    private PlanReport Report(PlanningScene scene, Roadmap roadmap, double bakeSeconds, PlanResult result) =>
        new(LevelPath, scene, From, To, roadmap.Nodes.Count, roadmap.Edges.Count, roadmap.Seed, bakeSeconds, result, new Dictionary<string, double>(Timings)) { Tolerance = Tolerance, Locomotion = Locomotion };

    /// <summary>Writes the report (and SVG) and prints a summary.</summary>
    public void Write(PlanReport report, Roadmap roadmap, string reportPath, string? svgPath, TextWriter output, string? glbPath = null)
    {
        // Every file is rendered first and then written as one set, the report last (OutputFile.WriteAll): a failure
        // replaces none of them, and a kill cannot leave a new animation beside an old report.
        var files = new List<(string Path, byte[] Bytes)>();
        string? animationLine = null;
        if (glbPath is not null && Animation is { } animation)
        {
            var clock = Stopwatch.StartNew();
            files.Add((glbPath, AnimatedGlbWriter.ToBytes(animation, "jumps")));
            var timings = new Dictionary<string, double>(report.Timings) { ["writeGlb"] = clock.Elapsed.TotalSeconds };
            string relative = Path.GetRelativePath(Path.GetDirectoryName(Path.GetFullPath(reportPath))!, Path.GetFullPath(glbPath));
            report = report with { Timings = timings, Animation = new AnimationReport(relative, "jumps", animation) };
            animationLine = $"animation: {animation.Duration:0.00} s ({animation.Stances.Sum():0.00} s of stances between moves), {animation.Frames.Count} frames, {animation.ContactPhases.Count} contact phases; {glbPath}";
        }

        string? phasesPath = null;
        if (svgPath is not null)
        {
            var utf8 = new UTF8Encoding(false);
            files.Add((svgPath, utf8.GetBytes(SvgPlanRenderer.Render(report, roadmap))));
            if (Animation is { } animated && PhaseStripRenderer.Render(animated) is { } strip)
            {
                string stem = svgPath.EndsWith(".svg", StringComparison.OrdinalIgnoreCase) ? svgPath[..^4] : svgPath;
                phasesPath = stem + "-phases.svg";
                files.Add((phasesPath, utf8.GetBytes(strip)));
            }
        }

        files.Add((reportPath, new UTF8Encoding(false).GetBytes(PlanReportWriter.ToJsonString(report))));
        OutputFile.WriteAll(files);

        PlanResult r = report.Result;
        output.WriteLine($"status: {PlanReportWriter.StatusName(r.Status)} ({r.Reason})");
        output.WriteLine($"roadmap: {report.RoadmapNodes} nodes, {report.RoadmapEdges} jumps, {roadmap.Walks.Count} walks, seed {report.Seed}");
        foreach ((string name, EndpointPlacement? placement) in new[] { ("start", r.StartPlacement), ("goal", r.GoalPlacement) })
        {
            if (placement is { Placed: true })
            {
                output.WriteLine($"{name}: stance {placement.Across:0.00} m across and {placement.UpDown:0.00} m up/down from the requested point");
            }
        }

        if (report.Rejected.Count > 0)
        {
            output.WriteLine($"set aside: {report.Rejected.Count} {(report.Rejected.Count == 1 ? "move" : "moves")} the body could not perform (first: {report.Rejected[0].Reason})");
        }

        if (r.Moves.Count > 0)
        {
            int walks = r.Walks.Count();
            output.WriteLine($"path: {r.Jumps.Count} jumps ({r.TotalFlightTime:0.00} s of flight, {r.Jumps.Sum(j => j.Arc.ArcLength):0.0} m of arcs) and {walks} walks ({r.Walks.Sum(w => w.Length):0.0} m, {r.Walks.Sum(w => w.Duration):0.00} s): {r.TotalDuration:0.00} s of moves");
        }

        if (report.Locomotion != Locomotion.Jump && r.Jumps.Count > 0)
        {
            var kinds = WalkRefusals.Of(report.Scene, r.Moves).GroupBy(n => WalkRefusals.Name(n.Failure)).Select(g => $"{g.Key} {g.Count()}");
            output.WriteLine($"not walked: {r.Jumps.Count} {(r.Jumps.Count == 1 ? "jump" : "jumps")} ({string.Join(", ", kinds)}; the report's notWalked says why)");
        }

        if (animationLine is not null)
        {
            output.WriteLine(animationLine);
        }

        output.WriteLine("timings: " + string.Join(", ", report.Timings.Select(t => $"{t.Key} {t.Value * 1000:0.#} ms")));
        output.WriteLine($"report: {reportPath}" + (svgPath is null ? "" : $"; picture: {svgPath}") + (phasesPath is null ? "" : $"; phases of its longest jump: {phasesPath}"));
    }
}
