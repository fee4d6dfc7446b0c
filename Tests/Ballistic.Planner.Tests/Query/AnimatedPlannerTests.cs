using System.Numerics;
using System.Text.Json.Nodes;
using Ballistic.Authoring.Characters;
using Ballistic.Authoring.Reports;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Query;

/// <summary>Lazy repair: jumps the body cannot perform are set aside and the search goes on; failure is never success.</summary>
public sealed class AnimatedPlannerTests
{
    /// <summary>The gap course baked for a skeleton that only jumps (shared with <see cref="StanceRepairTests"/>).</summary>
    internal static readonly Lazy<(PlanningScene Scene, BakeResult Bake)> GapCourseBake = new(() =>
    {
        var scene = PlanningScene.Create(GapCourse.Build(), CharacterPresets.Skeleton().WithWalking(WalkingLimits.None)); // jump repair, on a skeleton that only jumps
        BakeResult bake = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 2, MaxNodes = 150, Threads = 2, Start = GapCourse.From, Goal = GapCourse.To });
        return (scene, bake);
    });

    /// <summary>An animator that refuses every jump longer than a limit (and counts its calls); a clean animation otherwise.</summary>
    private sealed class Picky(float longest) : IJumpAnimator
    {
        public int Calls { get; private set; }

        public JumpAnimation Animate(IReadOnlyList<Move> moves, float frameRate = 60f)
        {
            Calls++;
            Jump[] jumps = [.. moves.Cast<Jump>()];
            var problems = new List<JumpProblem>();
            for (int j = 0; j < jumps.Length; j++)
            {
                float across = new Vector2(jumps[j].Arc.End.X - jumps[j].Arc.Start.X, jumps[j].Arc.End.Z - jumps[j].Arc.Start.Z).Length();
                if (across > longest)
                {
                    problems.Add(new JumpProblem(j, $"jump of {across:0.00} m refused"));
                }
            }

            return new JumpAnimation(CharacterPresets.Model("skeleton"), jumps, new float[jumps.Length - 1], [], [], problems, 0, 0);
        }

        public bool CanStand(PoseEvaluation pose) => true;
    }

    [Test]
    public void JumpsTheBodyCannotPerformAreSetAsideAndTheSearchGoesOn()
    {
        (PlanningScene scene, BakeResult bake) = GapCourseBake.Value;
        PlanResult unconstrained = new PathQuery(scene, bake.Roadmap).Plan(GapCourse.From, GapCourse.To);
        Assume.That(unconstrained.Status, Is.EqualTo(PlannerStatus.Exact));
        float longest = unconstrained.Jumps.Max(j => new Vector2(j.Arc.End.X - j.Arc.Start.X, j.Arc.End.Z - j.Arc.Start.Z).Length());

        // Refuse the longest jump of the best path: the planner must find another way or say why not.
        var picky = new Picky(longest - 0.01f);
        AnimatedPlan plan = new AnimatedPlanner(scene, picky).Plan(bake.Roadmap, GapCourse.From, GapCourse.To, rounds: 20);
        Assert.That(plan.Rejected, Is.Not.Empty);
        Assert.That(plan.Rejected[0].Reason, Does.Contain("refused"));
        if (plan.Result.Status == PlannerStatus.Exact)
        {
            Assert.That(plan.Result.Jumps.Select(j => new Vector2(j.Arc.End.X - j.Arc.Start.X, j.Arc.End.Z - j.Arc.Start.Z).Length()), Has.All.LessThanOrEqualTo(longest - 0.01f));
            Assert.That(plan.Animation, Is.Not.Null);
            Assert.That(plan.Rounds, Is.GreaterThan(1));
        }
        else
        {
            Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.AnimationFailed));
            Assert.That(plan.Result.Jumps, Is.Empty);
        }
    }

    [Test]
    public void WhenNoPathAnimatesTheStatusIsAFailureWithEveryReason()
    {
        (PlanningScene scene, BakeResult bake) = GapCourseBake.Value;
        var refuseAll = new Picky(0f);
        AnimatedPlan plan = new AnimatedPlanner(scene, refuseAll).Plan(bake.Roadmap, GapCourse.From, GapCourse.To, rounds: 3);
        Assert.Multiple(() =>
        {
            Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.AnimationFailed));
            Assert.That(plan.Result.Jumps, Is.Empty, "a failure carries no path");
            Assert.That(plan.Animation, Is.Null);
            // Three searches, plus the rounds whose faced (cut) moves were refused: those never count (JumpRepair.CutRounds).
            Assert.That(plan.Rounds, Is.LessThanOrEqualTo(3 + JumpRepair.CutRounds));
            Assert.That(refuseAll.Calls, Is.LessThanOrEqualTo(3 + JumpRepair.CutRounds));
            Assert.That(plan.Rejected, Is.Not.Empty);
            Assert.That(plan.Result.Reason, Does.Contain("jumps set aside").And.Contain("refused"));
        });

        // The report names the status and every jump set aside with its reason.
        var report = new PlanReport("gap-course", scene, GapCourse.From, GapCourse.To, bake.Roadmap.Nodes.Count, bake.Roadmap.Edges.Count, 2, 0, plan.Result, new Dictionary<string, double>()) { Rejected = plan.Rejected };
        string json = PlanReportWriter.ToJsonString(report);
        Assert.That(json, Does.Contain("\"status\": \"animation_failed\""));
        var rejected = (JsonArray)JsonNode.Parse(json)!["rejectedJumps"]!;
        Assert.That(rejected, Has.Count.EqualTo(plan.Rejected.Count));
        Assert.That(rejected.Select(r => r!["reason"]!.GetValue<string>()), Has.All.Contain("refused"));
    }

    [Test]
    public void ACleanFirstPathIsExactInOneRound()
    {
        (PlanningScene scene, BakeResult bake) = GapCourseBake.Value;
        var lenient = new Picky(float.PositiveInfinity);
        AnimatedPlan plan = new AnimatedPlanner(scene, lenient).Plan(bake.Roadmap, GapCourse.From, GapCourse.To);
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact));
        Assert.That(plan.Rounds, Is.EqualTo(1));
        Assert.That(plan.Rejected, Is.Empty);
        Assert.That(lenient.Calls, Is.EqualTo(1));
    }
}
