using System.Numerics;
using System.Text.Json;
using Ballistic.Authoring.Reports;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Authoring.Playtest;

/// <summary>
/// Writes a playtest as the <c>ballistic.playtest/2</c> JSON report. The <c>level</c> and <c>character</c> blocks
/// and every executed jump (<c>agents[].jumps[]</c>) have exactly the form of a plan report's
/// (<see cref="PlanReportWriter"/>), so the checkers of plan reports verify them as they are. Positions are world
/// metres (Y up), velocities m/s, times seconds (world time from the start of the run).
/// </summary>
/// <remarks>
/// Version 2 (walking) adds to version 1: <c>settings.locomotion</c> ("walk_and_jump" or "jump") and
/// <c>settings.jumpEffort</c> (s) and <c>settings.jumpHeightEffort</c> (s/m); <c>summary.walksTaken</c> and <c>summary.walkedMetres</c>; and per agent a
/// <c>walks</c> array, each walk an object with <c>startTime</c> (s), <c>from</c> and <c>to</c> (<c>node</c>: the stance's id,
/// a roadmap node's, or −1 or an id past the roadmap's last for a stance placed off it; <c>position</c>: trunk centre), <c>via</c> (node ids passed through), <c>speed</c>
/// (m/s), <c>length</c> (m), <c>duration</c> (s) and <c>path</c> (the walk's ground points, [x, y, z] each). Everything of
/// version 1 is unchanged.
/// </remarks>
public static class PlaytestReportWriter
{
    /// <summary>The schema name written in every report.</summary>
    public const string Schema = "ballistic.playtest/2";

    /// <summary>The report as indented UTF-8 JSON.</summary>
    /// <param name="result">The playtest.</param>
    /// <param name="levelPath">The level file, as written in the report.</param>
    public static byte[] ToJson(PlaytestResult result, string levelPath)
    {
        ArgumentNullException.ThrowIfNull(result);
        ArgumentNullException.ThrowIfNull(levelPath);
        ReducedCharacter character = result.Kind.Scene.Character;
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true }))
        {
            w.WriteStartObject();
            w.WriteString("schema", Schema);
            w.WriteString("level", levelPath);
            PlanReportWriter.WriteCharacter(w, character);

            w.WriteStartObject("settings");
            w.WriteNumber("agents", result.Settings.Agents);
            w.WriteNumber("seconds", result.Settings.Seconds);
            w.WriteNumber("seed", result.Settings.Seed);
            w.WriteNumber("tickRate", result.Settings.TickRate);
            w.WriteString("locomotion", result.Settings.Locomotion == Locomotion.Jump ? "jump" : "walk_and_jump");
            w.WriteNumber("jumpEffort", result.Settings.JumpEffort);
            w.WriteNumber("jumpHeightEffort", result.Settings.JumpHeightEffort);
            w.WriteBoolean("realTime", result.Settings.RealTime);
            w.WriteEndObject();

            w.WriteStartObject("roadmap");
            w.WriteNumber("nodes", result.Kind.Roadmap.Nodes.Count);
            w.WriteNumber("edges", result.Kind.Roadmap.Edges.Count);
            w.WriteNumber("seed", result.Kind.Roadmap.Seed);
            w.WriteEndObject();

            IReadOnlyList<double> times = result.TimesToReach;
            w.WriteStartObject("summary");
            w.WriteNumber("ticks", result.Ticks);
            w.WriteBoolean("cancelled", result.Cancelled);
            w.WriteNumber("wallSeconds", Math.Round(result.WallSeconds, 3));
            w.WriteNumber("lateRequests", result.LateRequests);
            w.WriteNumber("agentsSpawned", result.Agents.Count);
            w.WriteNumber("targetsSet", result.Agents.Sum(a => a.Targets.Count));
            w.WriteNumber("targetsReached", result.TargetsReached);
            w.WriteNumber("targetsFailed", result.TargetsFailed);
            w.WriteNumber("jumpsTaken", result.JumpsTaken);
            w.WriteNumber("walksTaken", result.WalksTaken);
            w.WriteNumber("walkedMetres", Math.Round(result.WalkedMetres, 3));
            w.WriteStartObject("reachability");
            w.WriteNumber("targetsReachedShare", result.TargetsConcluded == 0 ? 0 : Math.Round((double)result.TargetsReached / result.TargetsConcluded, 4));
            w.WriteNumber("pairsSampled", result.PairsSampled);
            w.WriteNumber("pairsConnected", result.PairsConnected);
            w.WriteNumber("pairsConnectedShare", result.PairsSampled == 0 ? 0 : Math.Round((double)result.PairsConnected / result.PairsSampled, 4));
            w.WriteStartObject("secondsToReach");
            w.WriteNumber("count", times.Count);
            if (times.Count > 0)
            {
                w.WriteNumber("mean", Math.Round(times.Average(), 3));
                w.WriteNumber("median", Math.Round(times[times.Count / 2], 3));
                w.WriteNumber("max", Math.Round(times[^1], 3));
            }

            w.WriteEndObject();
            w.WriteEndObject();
            w.WriteStartObject("failures");
            foreach (IGrouping<string, PlaytestTarget> group in result.Agents.SelectMany(a => a.Targets).Where(t => t.Failed).GroupBy(t => StatusName(t)).OrderBy(g => g.Key, StringComparer.Ordinal))
            {
                w.WriteNumber(group.Key, group.Count());
            }

            w.WriteEndObject();
            w.WriteEndObject();

            w.WriteStartArray("agents");
            foreach (PlaytestAgent agent in result.Agents)
            {
                w.WriteStartObject();
                w.WriteNumber("index", agent.Index);
                PlanReportWriter.WriteVector(w, "spawn", agent.Spawn);
                w.WriteNumber("targetsReached", agent.Targets.Count(t => t.Reached));
                w.WriteNumber("targetsFailed", agent.Targets.Count(t => t.Failed));
                w.WriteStartArray("targets");
                foreach (PlaytestTarget target in agent.Targets)
                {
                    w.WriteStartObject();
                    PlanReportWriter.WriteVector(w, "target", target.Target);
                    PlanReportWriter.WriteVector(w, "from", target.From);
                    w.WriteNumber("setAt", Math.Round(target.SetAt, 6));
                    w.WriteString("outcome", target.Reached ? "reached" : target.Failed ? "failed" : "under_way");
                    if (target.ReachedAt is double reached)
                    {
                        w.WriteNumber("reachedAt", Math.Round(reached, 6));
                    }

                    if (target.Failed)
                    {
                        w.WriteString("status", StatusName(target));
                        w.WriteString("reason", target.FailureReason);
                        w.WriteNumber("failedAt", Math.Round(target.FailedAt ?? 0, 6));
                    }

                    w.WriteEndObject();
                }

                w.WriteEndArray();
                w.WriteStartArray("jumps");
                foreach (ExecutedJump jump in agent.Jumps)
                {
                    PlanReportWriter.WriteJump(w, jump.Jump, character);
                }

                w.WriteEndArray();
                w.WriteStartArray("takeoffTimes");
                foreach (ExecutedJump jump in agent.Jumps)
                {
                    w.WriteNumberValue(Math.Round(jump.TakeoffTime, 6));
                }

                w.WriteEndArray();
                w.WriteStartArray("walks");
                foreach (ExecutedWalk walk in agent.Walks)
                {
                    WriteWalk(w, walk);
                }

                w.WriteEndArray();
                w.WriteEndObject();
            }

            w.WriteEndArray();
            w.WriteEndObject();
        }

        return stream.ToArray();
    }

    /// <summary>Writes one executed walk as an object of an agent's <c>walks</c> array.</summary>
    private static void WriteWalk(Utf8JsonWriter w, ExecutedWalk executed)
    {
        Walk walk = executed.Walk;
        w.WriteStartObject();
        w.WriteNumber("startTime", Math.Round(executed.StartTime, 6));
        WriteStance(w, "from", walk.From);
        WriteStance(w, "to", walk.To);
        PlanReportWriter.WriteWalkFields(w, walk, walk.Path);
        w.WriteEndObject();
    }

    private static void WriteStance(Utf8JsonWriter w, string name, RoadmapNode node)
    {
        w.WriteStartObject(name);
        w.WriteNumber("node", node.Id);
        PlanReportWriter.WriteVector(w, "position", node.Pose.Position);
        w.WriteEndObject();
    }

    private static string StatusName(PlaytestTarget target) => target.FailureStatus is { } status ? PlanReportWriter.StatusName(status) : "none";

    /// <summary>Where failed targets are, for pictures: the target point and the point the agent stood at.</summary>
    internal static IEnumerable<(Vector3 Target, Vector3 From)> Failures(PlaytestResult result) =>
        result.Agents.SelectMany(a => a.Targets).Where(t => t.Failed).Select(t => (t.Target, t.From));
}
