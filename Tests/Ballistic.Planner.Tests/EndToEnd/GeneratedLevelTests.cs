using Ballistic.Authoring.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.EndToEnd;

[Category("EndToEnd")]
public sealed class GeneratedLevelTests
{
    [TestCase("desert", "skeleton", -9.5f, -7.5f, 9.5f, 7.5f)]
    [TestCase("pond", "frog", -0.5f, -5.8f, 0.5f, 4.6f)]
    [TestCase("gap-course", "skeleton", -6f, 0f, 11.5f, 0f)]
    [TestCase("rooftops", "jumperman", -130f, -70f, 96f, 41f)]
    public void PlansAcrossTheBundledLevelsObeyThePhysics(string levelName, string characterName, float x0, float z0, float x1, float z1)
    {
        (PlanningScene scene, BakeResult bake, AnimatedPlan animated) = BundledPlans.Plan(levelName, characterName, x0, z0, x1, z1);
        PlanResult plan = animated.Result;
        Assert.That(bake.Status, Is.EqualTo(PlannerStatus.Exact), bake.Reason);
        Assert.That(plan.Status, Is.EqualTo(PlannerStatus.Exact), plan.Reason);
        Assert.That(plan.Moves, Is.Not.Empty);
        PhysicsChecks.AssertNode(scene, plan.Start!, "start");
        PhysicsChecks.AssertNode(scene, plan.Goal!, "goal");
        for (int k = 0; k < plan.Moves.Count; k++)
        {
            Move move = plan.Moves[k];
            PhysicsChecks.AssertNode(scene, move.To, $"end of move {k}");
            if (move is Jump jump)
            {
                PhysicsChecks.AssertJump(scene, jump.Takeoff, jump.Landing, jump.Arc, $"{levelName} move {k}");
            }

            if (k > 0)
            {
                Assert.That(move.From, Is.SameAs(plan.Moves[k - 1].To));
            }
        }

        // Every move and the whole animation as an independent checker sees them, sampled between frames as a player
        // interpolates them (a toe dipped into a roof between two frames of a fast push-off once passed as clean).
        AuditReport audit = PlanAudit.Check($"{levelName} {characterName}", scene, plan.Moves[0].From.Pose.Position, plan.Moves[^1].To.Pose.Position, plan, animated.Animation);
        Assert.That(audit.Violations.Where(v => v.StartsWith("move", StringComparison.Ordinal) || v.StartsWith("animation", StringComparison.Ordinal)), Is.Empty);
    }

    [TestCase("desert")]
    [TestCase("pond")]
    [TestCase("gap-course")]
    [TestCase("rooftops")]
    public void CommittedLevelFilesAreWhatTheGeneratorWrites(string name)
    {
        byte[] expected = GltfLevelWriter.ToBytes(LevelGenerator.Generate(name));
        byte[] committed = File.ReadAllBytes(RepositoryFiles.Level(name));
        Assert.That(committed.SequenceEqual(expected), Is.True, $"Scenes/levels/{name}.glb differs from the generator: run 'ballistic levels generate'.");
    }

    [Test]
    public void GeneratedLevelsHaveThePapersTriangleCounts()
    {
        int Count(string name) => LevelGenerator.Generate(name).Sum(m => m.Indices.Length / 3);
        Assert.Multiple(() =>
        {
            Assert.That(Count("desert"), Is.EqualTo(47_733).Within(2).Percent);
            Assert.That(Count("pond"), Is.EqualTo(6_994).Within(5).Percent);
            Assert.That(Count("rooftops"), Is.EqualTo(449_267).Within(5).Percent);
        });
    }
}
