using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.EndToEnd;

/// <summary>
/// A seeded sweep of start/goal requests on every bundled level and on levels in other tools' shapes, each plan
/// audited by an independent checker (<see cref="PlanAudit"/>): never a wrong answer (a success that breaks an
/// invariant), and at least 95 % of the requests fully right (exact, every invariant held, a clean animation).
/// </summary>
[Category("EndToEnd")]
[Category("Sweep")]
public sealed class SweepTests
{
    /// <summary>Bundled levels with their characters: random pairs of standing points (count, seed, greatest distance across).</summary>
    private static readonly (string Level, string Character, int Count, float MaxDistance)[] Bundled =
    [
        ("desert", "skeleton", 6, 25f),
        ("pond", "frog", 6, 8f),
        ("gap-course", "ant", 4, 20f),
        ("rooftops", "jumperman", 4, 120f),
    ];

    /// <summary>Levels in other tools' shapes, with the requests a user would make on them.</summary>
    private static readonly (string Level, string Character)[] Foreign =
    [
        ("thin-slabs", "skeleton"), ("curved", "skeleton"), ("stairs", "skeleton"), ("block", "skeleton"),
        ("holes-debris", "skeleton"), ("cave", "skeleton"), ("thin-slabs", "frog"), ("stairs", "ant"), ("curved", "ant"),
    ];

    /// <summary>Rigs exported in other tools' shapes (limbs-only specs), on levels with the requests a user would make.</summary>
    private static readonly (string Rig, string Level)[] ForeignRigs =
    [
        ("human", "block"), ("human", "stairs"), ("human-zup", "thin-slabs"), ("dog", "block"), ("dog", "curved"),
        ("tailed", "stairs"), ("tailed", "holes-debris"),
    ];

    [Test]
    public void NineteenRequestsInTwentyAreFullyRightAndNoneIsAWrongAnswer()
    {
        var all = new List<AuditReport>();
        string folder = Path.Combine(Path.GetTempPath(), $"ballistic-sweep-{Guid.NewGuid():N}");
        Directory.CreateDirectory(folder);
        foreach ((string levelName, string character, int count, float maxDistance) in Bundled)
        {
            Sweep.Setup setup = Sweep.Prepare(levelName, GltfLevelLoader.Load(RepositoryFiles.Level(levelName)), character);
            Record([.. Sweep.RandomPairs(setup.Scene, count, seed: 42, maxDistance).Select(p => Sweep.Run(setup, p.From, p.To))]);
        }

        foreach ((string levelName, string character) in Foreign)
        {
            (Level level, (Vector3 From, Vector3 To)[] requests) = ForeignLevels.Get(levelName);
            Sweep.Setup setup = Sweep.Prepare(levelName, level, character);
            Record([.. requests.Select(r => Sweep.Run(setup, r.From, r.To))]);
        }

        foreach ((string rigName, string levelName) in ForeignRigs)
        {
            ForeignCharacter rig = rigName switch
            {
                "human" => ForeignCharacters.Human(zUpScene: false),
                "human-zup" => ForeignCharacters.Human(zUpScene: true),
                "dog" => ForeignCharacters.Dog(),
                _ => ForeignCharacters.TailedQuadruped(),
            };
            (string gltf, string spec) = rig.Write(folder);
            (CharacterModel model, ReducedCharacter reduced) = CharacterSpecFile.Load(gltf, spec);
            (Level level, (Vector3 From, Vector3 To)[] requests) = ForeignLevels.Get(levelName);
            Sweep.Setup setup = Sweep.Prepare(levelName, level, model, reduced);
            Record([.. requests.Select(r => Sweep.Run(setup, r.From, r.To))]);
        }

        Directory.Delete(folder, recursive: true);
        TestContext.Out.WriteLine("sweep: " + Sweep.Summary(all));
        Assert.That(all.Where(r => r.WrongAnswer).Select(r => r.ToString()), Is.Empty, "a plan reported as exact breaks an invariant");
        Assert.That(all.Count(r => r.FullyRight), Is.GreaterThanOrEqualTo((int)MathF.Ceiling(0.95f * all.Count)), "fewer than 95 % of the requests are fully right");

        void Record(List<AuditReport> reports)
        {
            all.AddRange(reports);
            TestContext.Out.WriteLine(Sweep.Summary(reports));
            foreach (AuditReport r in reports)
            {
                TestContext.Out.WriteLine((r.FullyRight ? "  ok    " : r.WrongAnswer ? "  WRONG " : "  fail  ") + r);
            }
        }
    }
}
