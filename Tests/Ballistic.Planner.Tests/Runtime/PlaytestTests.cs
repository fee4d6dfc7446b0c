using System.Numerics;
using System.Text.Json.Nodes;
using Ballistic.Authoring.Playtest;
using Ballistic.Authoring.Reports;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>The headless playtest: deterministic, its jumps pass the plan tests' physics checks, its report reads like a plan report.</summary>
public sealed class PlaytestTests
{
    private static readonly Lazy<PlaytestResult> Run = new(() =>
        PlaytestRunner.Run(RuntimeWorlds.DesertSkeleton, new PlaytestSettings { Agents = 5, Seconds = 25, Seed = 4, AnimationThreads = 2, ReachabilityPairs = 100 }));

    [Test]
    public void EveryExecutedJumpPassesThePhysicsChecks()
    {
        PlaytestResult result = Run.Value;
        Assert.That(result.Agents, Has.Count.EqualTo(5));
        Assert.That(result.TargetsReached, Is.GreaterThanOrEqualTo(5), "agents got somewhere");
        Assert.That(result.JumpsTaken, Is.GreaterThan(20));
        foreach (PlaytestAgent agent in result.Agents)
        {
            Vector3 at = agent.Spawn;
            foreach (ExecutedJump executed in agent.Jumps)
            {
                Jump jump = executed.Jump;
                PhysicsChecks.AssertJump(RuntimeWorlds.DesertSkeleton.Scene, jump.Takeoff, jump.Landing, jump.Arc, $"agent {agent.Index} at {executed.TakeoffTime:0.###} s");
                PhysicsChecks.AssertNode(RuntimeWorlds.DesertSkeleton.Scene, jump.Landing, $"agent {agent.Index} landing at {executed.TakeoffTime:0.###} s");

                // Each takeoff is where the agent stood: no teleport between jumps, or between paths.
                Assert.That(Vector3.Distance(jump.Arc.Start, at), Is.LessThan(1e-4f), $"agent {agent.Index} took off {Vector3.Distance(jump.Arc.Start, at):0.###} m from where it stood");
                at = jump.Arc.End;
            }
        }
    }

    [Test]
    public void TheSameSeedGivesTheSamePlaytestWhateverTheThreads()
    {
        PlaytestResult again = PlaytestRunner.Run(RuntimeWorlds.DesertSkeleton, new PlaytestSettings { Agents = 5, Seconds = 25, Seed = 4, AnimationThreads = 0, ReachabilityPairs = 100 });
        string Trace(PlaytestResult r) => string.Join("\n", r.Agents.SelectMany(a => a.Jumps.Select(j => $"{a.Index} {j.TakeoffTime:R} {j.Jump.Arc.Start} {j.Jump.Arc.TakeoffVelocity}"))
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
    }
}
