using System.Numerics;
using System.Text.Json.Nodes;
using Ballistic.Authoring.Reports;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Reports;

/// <summary>The <c>ballistic.plan/2</c> report: moves in order, jumps identical in both arrays, walks with their poses and dense ground paths, a summary.</summary>
public sealed class PlanReportWriterTests
{
    private static JsonObject Write(PlanReport report) => JsonNode.Parse(PlanReportWriter.ToJson(report))!.AsObject();

    private static Vector3 Vec(JsonNode? node) => new(node![0]!.GetValue<float>(), node[1]!.GetValue<float>(), node[2]!.GetValue<float>());

    [Test]
    public void MovesAreWrittenInOrderAndEachJumpIsItsJumpsEntry()
    {
        PlanResult result = WalkPlans.WalkAndJump;
        JsonObject json = Write(WalkPlans.Report(result));
        JsonArray moves = json["moves"]!.AsArray();
        JsonArray jumps = json["jumps"]!.AsArray();
        Assert.That((string?)json["schema"], Is.EqualTo("ballistic.plan/2"));
        Assert.That(moves.Select(m => (string?)m!["kind"]), Is.EqualTo(result.Moves.Select(m => m is Walk ? "walk" : "jump")));
        Assert.That(result.Moves[0], Is.InstanceOf<Walk>());
        Assert.That(result.Moves[^1], Is.InstanceOf<Walk>());

        JsonNode[] jumpMoves = [.. moves.Select(m => m!).Where(m => (string?)m["kind"] == "jump")];
        Assert.That(jumps, Has.Count.EqualTo(result.Jumps.Count).And.Count.EqualTo(jumpMoves.Length));
        for (int j = 0; j < jumps.Count; j++)
        {
            Assert.That(jumpMoves[j].ToJsonString(), Is.EqualTo(jumps[j]!.ToJsonString()), $"jump {j}");
            Assert.That(Vec(jumps[j]!["takeoff"]!["position"]), Is.EqualTo(result.Jumps[j].Takeoff.Pose.Position));
            Assert.That(jumps[j]!["duration"]!.GetValue<float>(), Is.EqualTo(result.Jumps[j].Arc.FlightTime));
        }

        // A walk's stances are written as a jump's: the walk after the last jump starts with that jump's landing, byte for byte.
        Assert.That(moves[^1]!["from"]!.ToJsonString(), Is.EqualTo(moves[^2]!["landing"]!.ToJsonString()));
        Assert.That(moves[0]!["to"]!.ToJsonString(), Is.EqualTo(moves[1]!["takeoff"]!.ToJsonString()));
        var first = (Walk)result.Moves[0];
        Assert.That(Vec(moves[0]!["from"]!["position"]), Is.EqualTo(first.From.Pose.Position));
        Assert.That(moves[0]!["from"]!["contacts"]!.AsArray(), Has.Count.EqualTo(first.From.Contacts.Count));
        Assert.That(moves[0]!["from"]!.AsObject().Select(p => p.Key), Is.EqualTo(moves[1]!["takeoff"]!.AsObject().Select(p => p.Key)));
    }

    /// <summary>
    /// Each jump of a path says why no walk stands in for it, and what it says is true of the level, checked apart
    /// from the walking steering: under the straight line between its stances' contact centres (every 5 cm) a
    /// `gap` has no ground within 2 m somewhere or drops by more than the step height, a `step_too_high` rises by
    /// more, and a `possible` walk has ground all the way; the gap course's gaps say `gap`.
    /// </summary>
    [Test]
    public void EachJumpSaysWhyItIsNotAWalkAndItIsTrueOfTheLevel()
    {
        PlanResult result = WalkPlans.JumpOnly;
        JsonArray notWalked = Write(WalkPlans.Report(result))["notWalked"]!.AsArray();
        Assert.That(notWalked.Select(n => n!["move"]!.GetValue<int>()), Is.EqualTo(Enumerable.Range(0, result.Moves.Count).Where(m => result.Moves[m] is Jump)));
        float step = WalkPlans.Scene.Character.Walking.StepHeight;
        var seen = new HashSet<string>();
        foreach (JsonNode? entry in notWalked)
        {
            Move jump = result.Moves[entry!["move"]!.GetValue<int>()];
            string walk = (string)entry["walk"]!;
            string reason = (string)entry["reason"]!;
            seen.Add(walk);
            Assert.That(Vec(entry["from"]), Is.EqualTo(jump.From.Pose.Position));
            Assert.That(Vec(entry["to"]), Is.EqualTo(jump.To.Pose.Position));

            Vector3 a = jump.From.ContactCentre;
            Vector3 b = jump.To.ContactCentre;
            var heights = new List<float>();
            bool missing = false;
            int samples = (int)MathF.Ceiling(new Vector2(b.X - a.X, b.Z - a.Z).Length() / 0.05f);
            for (int i = 0; i <= samples; i++)
            {
                Vector3 p = Vector3.Lerp(a, b, i / (float)Math.Max(1, samples));
                if (WalkPlans.Scene.Bvh.Raycast(p + (2f * Vector3.UnitY), -Vector3.UnitY, 4f, out RayHit hit))
                {
                    heights.Add(hit.Point.Y);
                }
                else
                {
                    missing = true;
                }
            }

            float biggestDrop = heights.Zip(heights.Skip(1), (x, y) => x - y).DefaultIfEmpty(0f).Max();
            float biggestRise = heights.Zip(heights.Skip(1), (x, y) => y - x).DefaultIfEmpty(0f).Max();
            switch (walk)
            {
                case "gap":
                    Assert.That(missing || biggestDrop > step, Is.True, $"{reason}: ground all the way, dropping {biggestDrop:0.00} m at most");
                    Assert.That(reason, Does.Contain($"({step:0.00} m)"));
                    break;
                case "step_too_high":
                    Assert.That(biggestRise, Is.GreaterThan(step), reason);
                    break;
                case "possible":
                    Assert.That(missing, Is.False, reason);
                    Assert.That(MathF.Max(biggestDrop, biggestRise), Is.LessThanOrEqualTo(step), reason);
                    break;
                default:
                    Assert.That(walk, Is.AnyOf("too_steep", "trunk_collides"), reason);
                    break;
            }
        }

        Assert.That(seen, Does.Contain("gap"), "the gap course's jumps cross gaps");

        // A request for jumps only says so by its locomotion, and lists nothing.
        Assert.That(Write(WalkPlans.Report(result) with { Locomotion = Locomotion.Jump }).ContainsKey("notWalked"), Is.False);
    }

    /// <summary>A character that does not walk (the frog: all four limbs down) says so for every jump.</summary>
    [Test]
    public void ACharacterThatDoesNotWalkSaysSoForEveryJump()
    {
        var frog = PlanningScene.Create(GapCourse.Build(), Authoring.Characters.CharacterPresets.Frog());
        IReadOnlyList<(int Move, Planner.Walking.WalkFailure Failure, string Reason)> refusals = Planner.Query.WalkRefusals.Of(frog, WalkPlans.JumpOnly.Moves);
        Assert.That(refusals, Has.Count.EqualTo(WalkPlans.JumpOnly.Jumps.Count));
        Assert.That(refusals.Select(r => r.Failure), Has.All.EqualTo(Planner.Walking.WalkFailure.NotWalking));
        Assert.That(refusals[0].Reason, Does.StartWith("the character does not walk"));
    }

    [Test]
    public void AWalkHasItsDenseGroundPathDurationLengthSpeedAndVia()
    {
        PlanResult result = WalkPlans.WalkAndJump;
        JsonArray moves = Write(WalkPlans.Report(result))["moves"]!.AsArray();
        for (int m = 0; m < result.Moves.Count; m++)
        {
            if (result.Moves[m] is not Walk walk)
            {
                continue;
            }

            JsonNode json = moves[m]!;
            Vector3[] path = [.. json["path"]!.AsArray().Select(Vec)];
            Assert.Multiple(() =>
            {
                Assert.That(path[0], Is.EqualTo(walk.Path[0]), "the first point exactly");
                Assert.That(path[^1], Is.EqualTo(walk.Path[^1]), "the last point exactly");
                Assert.That(path.Zip(path.Skip(1), Vector3.Distance), Has.All.LessThanOrEqualTo(PlanReportWriter.MaxWalkPointSpacing));
                Assert.That(path, Has.Length.GreaterThan((int)(walk.Length / 0.25f)), "resampled: the walk is longer than its points");
                Assert.That(json["duration"]!.GetValue<float>(), Is.EqualTo(walk.Duration));
                Assert.That(json["length"]!.GetValue<float>(), Is.EqualTo(walk.Length));
                Assert.That(json["speed"]!.GetValue<float>(), Is.EqualTo(WalkPlans.Speed));
                Assert.That(json["via"]!.AsArray().Select(v => v!.GetValue<int>()), Is.EqualTo(walk.Via.Select(v => v.Id)));
            });

            // Every point of the walk is kept, in order, and every point written lies on the walk's polyline.
            int at = 0;
            foreach (Vector3 p in walk.Path)
            {
                while (at < path.Length && path[at] != p)
                {
                    at++;
                }

                Assert.That(at, Is.LessThan(path.Length), $"walk point {p} written in order");
            }

            float along = path.Zip(path.Skip(1), Vector3.Distance).Sum();
            Assert.That(along, Is.EqualTo(walk.Length).Within(1e-4f), "the written path runs along the walk, no shortcut or detour");
        }

        Assert.That(((Walk)result.Moves[^1]).Via, Has.Count.EqualTo(1), "the fixture has a walk through a stance");
    }

    [Test]
    public void TheSummaryCountsTheMovesAndTotalsTheirLengthAndTime()
    {
        PlanResult result = WalkPlans.WalkAndJump;
        JsonObject json = Write(WalkPlans.Report(result));
        JsonNode summary = json["summary"]!;
        Walk[] walks = [.. result.Walks];
        Assert.Multiple(() =>
        {
            Assert.That((int)summary["moves"]!, Is.EqualTo(result.Moves.Count));
            Assert.That((int)summary["jumps"]!, Is.EqualTo(result.Jumps.Count));
            Assert.That((int)summary["walks"]!, Is.EqualTo(2));
            Assert.That((float)summary["walkLength"]!, Is.EqualTo(walks.Sum(w => w.Length)).Within(1e-5f));
            Assert.That((float)summary["walkTime"]!, Is.EqualTo(walks.Sum(w => w.Duration)).Within(1e-4f));
            Assert.That((float)summary["flightTime"]!, Is.EqualTo((float)json["totalFlightTime"]!));
            Assert.That((float)summary["totalDuration"]!, Is.EqualTo(result.Jumps.Sum(j => j.Arc.FlightTime) + walks.Sum(w => w.Duration)).Within(1e-4f));
            Assert.That((float)json["totalFlightTime"]!, Is.EqualTo(result.Jumps.Sum(j => j.Arc.FlightTime)).Within(1e-5f));
        });
    }

    [Test]
    public void TheWrittenPathKeepsEveryPointAndSpacesThemAtMostAQuarterMetre()
    {
        Vector3[] path = [new(0f, 0f, 0f), new(1f, 0f, 0f), new(1.1f, 0f, 0f), new(1.1f, 0.3f, 2f), new(1.1f, 0.3f, 2f)];
        IReadOnlyList<Vector3> written = PlanReportWriter.ReportPath(path);
        Assert.That(written[0], Is.EqualTo(path[0]));
        Assert.That(written[^1], Is.EqualTo(path[^1]));
        Assert.That(written.Zip(written.Skip(1), Vector3.Distance), Has.All.LessThanOrEqualTo(0.25f));
        Assert.That(path.All(written.Contains), Is.True);
        Assert.That(written, Has.Count.EqualTo(1 + 5 + 1 + 9 + 1), "pieces of 1 m, 0.1 m, 2.02 m and 0 m cut into 5, 1, 9 and 1");

        Vector3[] dense = [.. Enumerable.Range(0, 11).Select(i => new Vector3(i * 0.2f, 0f, 0f))];
        Assert.That(PlanReportWriter.ReportPath(dense), Is.EqualTo(dense), "a path already dense enough is written as it is");
    }

    [Test]
    public void WalkingContactPhasesAndMoveTimesAreInTheAnimationSection()
    {
        JumpAnimation animation = WalkPlans.Animation;
        JsonNode section = Write(WalkPlans.Report(WalkPlans.WalkAndJump, animation))["animation"]!;
        JsonArray moves = section["moves"]!.AsArray();
        Assert.That(moves, Has.Count.EqualTo(animation.Moves.Count));
        for (int m = 0; m < moves.Count; m++)
        {
            Assert.That((string?)moves[m]!["kind"], Is.EqualTo(animation.Moves[m] is Walk ? "walk" : "jump"));
            Assert.That((float)moves[m]!["start"]!, Is.EqualTo(animation.MoveStart(m)));
            Assert.That((float)moves[m]!["end"]!, Is.EqualTo(animation.MoveEnd(m)));
        }

        Assert.That((float)moves[^1]!["end"]!, Is.EqualTo((float)section["duration"]!).Within(1e-5f));

        // The feet's phases during the first walk are written like any other, with the limb's name.
        JsonArray phases = section["contactPhases"]!.AsArray();
        Assert.That(phases, Has.Count.EqualTo(animation.ContactPhases.Count));
        float walkEnd = animation.MoveEnd(0);
        JsonNode[] walking = [.. phases.Select(p => p!).Where(p => (float)p["to"]! <= walkEnd + 1e-5f)];
        ContactPhase[] expected = [.. animation.ContactPhases.Where(p => p.To <= walkEnd + 1e-5f)];
        Assert.That(walking, Has.Length.EqualTo(expected.Length).And.Length.GreaterThanOrEqualTo(3));
        Assert.That(walking.Select(p => (string?)p["limb"]), Is.EqualTo(expected.Select(p => animation.Model.Limbs[p.Limb].Name)));
        Assert.That(walking.Select(p => Vec(p["position"])), Is.EqualTo(expected.Select(p => p.Position)));
        Assert.That(walking.Select(p => (string?)p["limb"]).Distinct().Count(), Is.EqualTo(2), "both feet step");

        // A foot rolled onto its ball says so, and where the ball is on the foot (every other phase marked rolled, as
        // the gait marks a trailing foot on its ball: whether this plan's feet roll is the gait's business).
        Assert.That(phases.Select(p => (string?)p!["on"]), Is.EqualTo(animation.ContactPhases.Select(p => p.OnBall ? "ball" : null)));
        var rolled = new JumpAnimation(
            animation.Model, animation.Moves, animation.Stances, animation.Frames,
            [.. animation.ContactPhases.Select((p, i) => i % 2 == 0 ? p with { OnBall = true } : p)],
            animation.Problems, animation.FailedContactPoses, animation.CollidingFrames, animation.LeadIn, animation.LeadOut);
        JsonArray rolledPhases = Write(WalkPlans.Report(WalkPlans.WalkAndJump, rolled))["animation"]!["contactPhases"]!.AsArray();
        Assert.That(rolledPhases.Select(p => (string?)p!["on"]), Is.EqualTo(rolled.ContactPhases.Select(p => p.OnBall ? "ball" : null)));
        Assert.That(rolledPhases.Count(p => (string?)p!["on"] == "ball"), Is.GreaterThan(0));
        foreach (RigLimb foot in animation.Model.Limbs.Where(l => l.Ball is not null))
        {
            Assert.That(Vec(section["limbs"]![foot.Name]!["ballOffset"]), Is.EqualTo(foot.Ball!.EffectorOffset));
        }
    }

    [Test]
    public void TheLocomotionIsWrittenInTheRequestWhenGiven()
    {
        PlanReport report = WalkPlans.Report(WalkPlans.JumpOnly);
        Assert.That(Write(report)["request"]!["locomotion"], Is.Null);
        Assert.That((string?)Write(report with { Locomotion = Locomotion.Jump })["request"]!["locomotion"], Is.EqualTo("jump"));
        Assert.That((string?)Write(report with { Locomotion = Locomotion.WalkAndJump })["request"]!["locomotion"], Is.EqualTo("walk+jump"));
    }

    [Test]
    public void AJumpOnlyReportStillHoldsEveryKeyOfTheFirstSchema()
    {
        JsonObject v1 = JsonNode.Parse(File.ReadAllBytes(Path.Combine(RepositoryFiles.Root, "Tests", "Ballistic.Planner.Tests", "Reports", "plan-v1.json")))!.AsObject();
        PlanResult result = WalkPlans.JumpOnly;
        JsonObject v2 = Write(WalkPlans.Report(result, WalkPlans.Animate(result.Moves)));
        Assert.That((string?)v1["schema"], Is.EqualTo("ballistic.plan/1"));
        Assert.That(v1.Select(p => p.Key), Is.SubsetOf(v2.Select(p => p.Key)));
        foreach (string block in new[] { "character", "request", "start", "goal", "roadmap", "animation" })
        {
            Assert.That(v1[block]!.AsObject().Select(p => p.Key), Is.SubsetOf(v2[block]!.AsObject().Select(p => p.Key)), block);
        }

        Assert.That(v1["jumps"]![0]!.AsObject().Select(p => p.Key), Is.SubsetOf(v2["jumps"]![0]!.AsObject().Select(p => p.Key)));
        Assert.That(v1["jumps"]![0]!["takeoff"]!.AsObject().Select(p => p.Key), Is.EqualTo(v2["jumps"]![0]!["takeoff"]!.AsObject().Select(p => p.Key)));

        // Jumps only: the moves are the jumps.
        Assert.That(v2["moves"]!.ToJsonString(), Is.EqualTo(v2["jumps"]!.ToJsonString()));
        Assert.That((int)v2["summary"]!["walks"]!, Is.Zero);
        Assert.That((float)v2["summary"]!["walkLength"]!, Is.Zero);
    }
}
