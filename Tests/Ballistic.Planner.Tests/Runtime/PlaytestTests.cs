using System.Numerics;
using System.Text.Json.Nodes;
using Ballistic.Authoring.Playtest;
using Ballistic.Authoring.Reports;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>
/// The headless playtest: deterministic, its jumps pass the plan tests' physics checks and its walks the plan audit,
/// its report reads like a plan report. Its paths walk and jump (the planner's default) and are animated by
/// <see cref="SimpleMoveAnimator"/>, which animates walks.
/// </summary>
public sealed class PlaytestTests
{
    private static readonly Lazy<PlaytestResult> Run = new(() =>
        PlaytestRunner.Run(WalkingPaths.Kind, new PlaytestSettings { Agents = 5, Seconds = 50, Seed = 4, AnimationThreads = 2, ReachabilityPairs = 100, Locomotion = Locomotion.WalkAndJump }));

    [Test]
    public void EveryExecutedMovePassesThePhysicsChecks()
    {
        PlaytestResult result = Run.Value;
        Assert.That(result.Agents, Has.Count.EqualTo(5));
        Assert.That(result.TargetsReached, Is.GreaterThanOrEqualTo(5), "agents got somewhere");
        Assert.That(result.JumpsTaken + result.WalksTaken, Is.GreaterThan(15));
        Assert.That(result.JumpsTaken, Is.GreaterThan(0), "agents jumped");
        Assert.That(result.WalksTaken, Is.GreaterThan(0), "agents walked");
        Assert.That(result.WalkedMetres, Is.GreaterThan(result.WalksTaken * 0.05));
        foreach (PlaytestAgent agent in result.Agents)
        {
            // The agent's moves in the order it made them: each starts where the agent stood (no teleport between
            // moves, or between paths).
            Vector3 at = agent.Spawn;
            var moves = agent.Jumps.Select(j => (Time: j.TakeoffTime, Move: (Move)j.Jump)).Concat(agent.Walks.Select(w => (Time: w.StartTime, Move: (Move)w.Walk))).OrderBy(m => m.Time);
            foreach ((double time, Move move) in moves)
            {
                Assert.That(Vector3.Distance(move.From.Pose.Position, at), Is.LessThan(1e-4f), $"agent {agent.Index} started a move {Vector3.Distance(move.From.Pose.Position, at):0.###} m from where it stood at {time:0.###} s");
                at = move.To.Pose.Position;
                if (move is Jump jump)
                {
                    PhysicsChecks.AssertJump(RuntimeWorlds.DesertSkeleton.Scene, jump.Takeoff, jump.Landing, jump.Arc, $"agent {agent.Index} at {time:0.###} s");
                    PhysicsChecks.AssertNode(RuntimeWorlds.DesertSkeleton.Scene, jump.Landing, $"agent {agent.Index} landing at {time:0.###} s");
                    Assert.That(jump.Arc.Start, Is.EqualTo(jump.Takeoff.Pose.Position).Using<Vector3>((x, y) => Vector3.Distance(x, y) < 1e-4f));
                }
                else
                {
                    var walk = (Walk)move;
                    var plan = new Planner.Query.PlanResult(Planner.Planning.PlannerStatus.Exact, "executed", walk.From, walk.To, [walk], TimeSpan.Zero);
                    AuditReport audit = PlanAudit.Check($"agent {agent.Index} walk at {time:0.###} s", WalkingPaths.Kind.Scene, WalkingPaths.Centre(walk.From), WalkingPaths.Centre(walk.To), plan, null);
                    Assert.That(audit.Violations, Is.Empty, audit.ToString());
                }
            }
        }
    }

    [Test]
    public void TheTicksCostIsMeasuredAsAFrameFeelsIt()
    {
        PlaytestResult result = Run.Value;
        PlaytestTickTimes cost = result.TickTimes!;
        Assert.That(cost, Is.Not.Null);
        Assert.That(cost.MedianMilliseconds, Is.GreaterThan(0));
        Assert.That(cost.P95Milliseconds, Is.GreaterThanOrEqualTo(cost.MedianMilliseconds));
        Assert.That(cost.WorstMilliseconds, Is.GreaterThanOrEqualTo(cost.P95Milliseconds));
        Assert.That(cost.WorstMilliseconds, Is.LessThanOrEqualTo(result.WallSeconds * 1000.0), "no tick longer than the whole run");
        Assert.That(cost.CpuMillisecondsPerTick, Is.GreaterThan(0));
        Assert.That(cost.BytesAllocatedPerTick, Is.GreaterThanOrEqualTo(0));

        // The figures themselves: the median and the 95th percentile of the ticks given, the worst, and the sums per tick.
        PlaytestTickTimes made = PlaytestTickTimes.From([.. Enumerable.Range(1, 100).Select(i => (double)i).Reverse()], TimeSpan.FromMilliseconds(250), 1_000)!;
        Assert.That(made, Is.EqualTo(new PlaytestTickTimes(51, 95, 100, 2.5, 10, 84)), "ticks of 17 to 100 ms are longer than a frame");
        Assert.That(cost.OverFrame, Is.InRange(0, (int)result.Ticks));
        Assert.That(PlaytestTickTimes.From([], TimeSpan.Zero, 0), Is.Null);
    }

    /// <summary>
    /// A real-time playtest steps the world as a game does: each tick at its moment on the wall clock, so the run
    /// lasts at least the simulated time; its report says it ran in real time and how many requests arrived after
    /// their due tick. An offline run (the default) has none late and says so.
    /// </summary>
    [Test]
    public void ARealTimePlaytestStepsAtTheTickRateAndCountsLateRequests()
    {
        var settings = new PlaytestSettings { Agents = 3, Seconds = 1.5, Seed = 4, AnimationThreads = 1, ReachabilityPairs = 10, Locomotion = Locomotion.WalkAndJump, RealTime = true };
        PlaytestResult result = PlaytestRunner.Run(WalkingPaths.Kind, settings);
        JsonNode report = JsonNode.Parse(PlaytestReportWriter.ToJson(result, "Scenes/levels/desert.glb"))!;
        JsonNode offline = JsonNode.Parse(PlaytestReportWriter.ToJson(Run.Value, "Scenes/levels/desert.glb"))!;
        Assert.Multiple(() =>
        {
            Assert.That(result.Ticks, Is.EqualTo(90));
            Assert.That(result.WallSeconds, Is.GreaterThanOrEqualTo(89 / 60.0), "the last tick at 89/60 s on the wall clock, not sooner");
            Assert.That(result.LateRequests, Is.GreaterThanOrEqualTo(0));
            Assert.That((bool)report["settings"]!["realTime"]!, Is.True);
            Assert.That((long)report["summary"]!["lateRequests"]!, Is.EqualTo(result.LateRequests));
            Assert.That((bool)offline["settings"]!["realTime"]!, Is.False);
            Assert.That((long)offline["summary"]!["lateRequests"]!, Is.Zero, "offline, every request is waited for");
        });
    }

    [Test]
    public void TheSameSeedGivesTheSamePlaytestWhateverTheThreads()
    {
        PlaytestResult again = PlaytestRunner.Run(WalkingPaths.Kind, new PlaytestSettings { Agents = 5, Seconds = 50, Seed = 4, AnimationThreads = 0, Locomotion = Locomotion.WalkAndJump, ReachabilityPairs = 100 });
        string Trace(PlaytestResult r) => string.Join("\n", r.Agents.SelectMany(a => a.Jumps.Select(j => $"{a.Index} {j.TakeoffTime:R} {j.Jump.Arc.Start} {j.Jump.Arc.TakeoffVelocity}"))
            .Concat(r.Agents.SelectMany(a => a.Walks.Select(w => $"{a.Index} {w.StartTime:R} {w.Walk.From.Pose.Position} {w.Walk.To.Pose.Position} {w.Walk.Speed:R}")))
            .Concat(r.Agents.SelectMany(a => a.Targets.Select(t => $"{a.Index} {t.Target} {t.ReachedAt:R} {t.FailureReason}"))));
        Assert.That(Trace(again), Is.EqualTo(Trace(Run.Value)));
    }

    [Test]
    public void TheReportHasThePlanReportsBlocksAndEveryJump()
    {
        PlaytestResult result = Run.Value;
        JsonNode report = JsonNode.Parse(PlaytestReportWriter.ToJson(result, "Scenes/levels/desert.glb"))!;
        Assert.That((string?)report["schema"], Is.EqualTo("ballistic.playtest/2"));
        Assert.That((string?)report["level"], Is.EqualTo("Scenes/levels/desert.glb"));

        // The character block is the plan report's, byte for byte.
        var plan = new PlanReport("Scenes/levels/desert.glb", RuntimeWorlds.DesertSkeleton.Scene, Vector3.Zero, Vector3.One, 0, 0, 0, 0,
            new Ballistic.Planner.Query.PlanResult(Ballistic.Planner.Planning.PlannerStatus.NoPath, "none", null, null, [], TimeSpan.Zero), new Dictionary<string, double>());
        JsonNode planJson = JsonNode.Parse(PlanReportWriter.ToJson(plan))!;
        Assert.That(report["character"]!.ToJsonString(), Is.EqualTo(planJson["character"]!.ToJsonString()));

        JsonArray agents = report["agents"]!.AsArray();
        Assert.That(agents.Sum(a => a!["jumps"]!.AsArray().Count), Is.EqualTo(result.JumpsTaken));
        Assert.That(agents.Sum(a => a!["walks"]!.AsArray().Count), Is.EqualTo(result.WalksTaken));
        JsonNode first = agents.First(a => a!["jumps"]!.AsArray().Count > 0)!["jumps"]![0]!;
        foreach (string key in new[] { "takeoff", "landing", "takeoffVelocity", "landingVelocity", "flightTime", "arcLength", "apex" })
        {
            Assert.That(first[key], Is.Not.Null, key);
        }

        JsonNode summary = report["summary"]!;
        Assert.That((int)summary["targetsReached"]!, Is.EqualTo(result.TargetsReached));
        Assert.That((double)summary["reachability"]!["pairsConnectedShare"]!, Is.InRange(0.0, 1.0));
        Assert.That(PlaytestMapRenderer.Svg(result), Does.StartWith("<svg").And.Contain("targets reached"));
        byte[] png = PlaytestMapRenderer.Png(result);
        Assert.That(png.AsSpan(1, 3).ToArray(), Is.EqualTo("PNG"u8.ToArray()));

        // The PNG is the SVG drawn, title and legend included: its size, and dark text in the band above the map.
        using SkiaSharp.SKBitmap image = SkiaSharp.SKBitmap.Decode(png);
        System.Xml.Linq.XElement svg = System.Xml.Linq.XElement.Parse(PlaytestMapRenderer.Svg(result));
        Assert.That((image.Width, image.Height), Is.EqualTo(((int)svg.Attribute("width")!, (int)svg.Attribute("height")!)));
        int Count(int top, int bottom, Func<SkiaSharp.SKColor, bool> ink) => Enumerable.Range(top, bottom - top).Sum(y => Enumerable.Range(0, image.Width).Count(x => ink(image.GetPixel(x, y))));
        static bool Black(SkiaSharp.SKColor c) => c.Red < 40 && c.Green < 40 && c.Blue < 40;
        static bool Grey(SkiaSharp.SKColor c) => c.Red is >= 70 and < 160 && c.Red == c.Green && c.Green == c.Blue;
        Assert.That(Count(4, 22, Black), Is.GreaterThan(200), "the title's black letters");
        Assert.That(Count(24, 38, Grey), Is.GreaterThan(200), "the legend's grey letters");
        Assert.That(Count(24, 38, Black), Is.Zero, "the legend is grey");
        Assert.That(Count(0, 3, c => c != SkiaSharp.SKColors.White), Is.Zero, "a white margin above the title");
    }

    /// <summary>
    /// An agent that reached nothing and failed three targets or more, every one from the same spot, is stuck there (a
    /// stance it cannot leave); one that failed as often but from two spots, or reached one target, or failed only
    /// twice, is not.
    /// </summary>
    [Test]
    public void AnAgentFailingEveryTargetFromOneSpotIsStuck()
    {
        var spot = new Vector3(1f, 0.5f, 2f);
        PlaytestAgent Agent(int index, int failures, Vector3? elsewhere = null, bool reached = false)
        {
            var agent = new PlaytestAgent(index, spot);
            for (int k = 0; k < failures; k++)
            {
                Vector3 from = k == failures - 1 && elsewhere is Vector3 other ? other : spot;
                agent.Targets.Add(new PlaytestTarget(new Vector3(k, 0f, 0f), from, k) { FailureStatus = PlannerStatus.AnimationFailed, FailureReason = "no path animates cleanly", FailedAt = k + 0.5 });
            }

            if (reached)
            {
                agent.Targets.Add(new PlaytestTarget(Vector3.Zero, spot, failures) { ReachedAt = failures + 3.0 });
            }

            return agent;
        }

        var settings = new PlaytestSettings { Agents = 5, Seconds = 6, AnimationThreads = 0 };
        var result = new PlaytestResult(settings, RuntimeWorlds.DesertSkeleton, [Agent(0, 5), Agent(1, 5, spot + new Vector3(0.5f, 0f, 0f)), Agent(2, 5, reached: true), Agent(3, 2), Agent(4, 3, spot + new Vector3(0.005f, 0f, 0f))], 360, 0.1, 0, 0, false);
        Assert.That(result.Stuck.Select(a => a.Index), Is.EqualTo(new[] { 0, 4 }));
    }

    [Test]
    public void TheReportListsEveryWalkAndTheMapDrawsThemDashed()
    {
        // A playtest result with one agent that walked, jumped and walked (until the planner makes walks on the desert).
        IReadOnlyList<Move> moves = WalkingPaths.WalkJumpWalk();
        var agent = new PlaytestAgent(0, moves[0].From.Pose.Position);
        agent.Targets.Add(new PlaytestTarget(WalkingPaths.Centre(moves[2].To), moves[0].From.Pose.Position, 0.0) { ReachedAt = 5.0 });
        agent.Walks.Add(new ExecutedWalk(0, 0.0, (Walk)moves[0]));
        agent.Jumps.Add(new ExecutedJump(0, 1.5, (Jump)moves[1]));
        agent.Walks.Add(new ExecutedWalk(0, 2.6, (Walk)moves[2]));
        var settings = new PlaytestSettings { Agents = 1, Seconds = 6, AnimationThreads = 0, Locomotion = Locomotion.WalkAndJump };
        var result = new PlaytestResult(settings, RuntimeWorlds.DesertSkeleton, [agent], 360, 0.1, 0, 0, false);
        Assert.That(result.WalksTaken, Is.EqualTo(2));
        Assert.That(result.WalkedMetres, Is.EqualTo(((Walk)moves[0]).Length + (double)((Walk)moves[2]).Length).Within(1e-5));

        JsonNode report = JsonNode.Parse(PlaytestReportWriter.ToJson(result, "Scenes/levels/desert.glb"))!;
        Assert.That((string?)report["schema"], Is.EqualTo("ballistic.playtest/2"));
        Assert.That((string?)report["settings"]!["locomotion"], Is.EqualTo("walk_and_jump"));
        Assert.That((double)report["settings"]!["jumpEffort"]!, Is.EqualTo(settings.JumpEffort));
        Assert.That((int)report["summary"]!["walksTaken"]!, Is.EqualTo(2));
        Assert.That((int)report["summary"]!["jumpsTaken"]!, Is.EqualTo(1));
        JsonArray walks = report["agents"]![0]!["walks"]!.AsArray();
        Assert.That(walks, Has.Count.EqualTo(2));
        for (int w = 0; w < 2; w++)
        {
            var walk = (Walk)moves[2 * w];
            JsonNode json = walks[w]!;
            Assert.That((double)json["startTime"]!, Is.EqualTo(agent.Walks[w].StartTime));
            Assert.That((int)json["from"]!["node"]!, Is.EqualTo(walk.From.Id));
            Assert.That((int)json["to"]!["node"]!, Is.EqualTo(walk.To.Id));
            Assert.That(Vector(json["from"]!["position"]!), Is.EqualTo(walk.From.Pose.Position));
            Assert.That(Vector(json["to"]!["position"]!), Is.EqualTo(walk.To.Pose.Position));
            Assert.That((float)json["speed"]!, Is.EqualTo(walk.Speed));
            Assert.That((float)json["length"]!, Is.EqualTo(walk.Length));
            Assert.That((float)json["duration"]!, Is.EqualTo(walk.Duration));
            Assert.That(json["via"]!.AsArray(), Is.Empty);
            Assert.That(json["path"]!.AsArray().Select(p => Vector(p!)), Is.EqualTo(walk.Path));
        }

        string svg = PlaytestMapRenderer.Svg(result);
        Assert.That(svg.Split("<polyline class=\"walk\"").Length - 1, Is.EqualTo(2), "one dashed polyline per walk");
        Assert.That(svg, Does.Contain("stroke-dasharray=\"5 3\"").And.Contain("2 walks"));
        var jumpOnly = new PlaytestAgent(0, agent.Spawn);
        jumpOnly.Targets.AddRange(agent.Targets);
        jumpOnly.Jumps.AddRange(agent.Jumps);
        byte[] without = PlaytestMapRenderer.Png(result with { Agents = [jumpOnly] });
        Assert.That(PlaytestMapRenderer.Png(result), Is.Not.EqualTo(without), "the walks are drawn on the PNG");
    }

    private static Vector3 Vector(JsonNode node) => new((float)node[0]!, (float)node[1]!, (float)node[2]!);
}
