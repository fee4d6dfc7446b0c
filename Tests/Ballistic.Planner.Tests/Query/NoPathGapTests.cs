using System.Numerics;
using System.Text.RegularExpressions;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Query;

/// <summary>
/// A request with no path says why in words a designer acts on (<see cref="NoPathGap"/>): how many stances each side
/// holds and, for a side closed in, how far they spread; the easiest jump between the two sides with the least takeoff
/// speed it needs, and the character's limit or what else refuses it. Before, every such request read only "the
/// roadmap holds no sequence of moves from the start to the goal" (the sweep's start inside a closed house on the
/// rooftops, the spider under a block 1.2 m high).
/// </summary>
public sealed class NoPathGapTests
{
    /// <summary>
    /// A start inside a closed shed (3 × 3 m, walls and roof 0.2 m thick, 2.5 m inside), the goal outside: the start
    /// reaches only the stances inside the shed (within its 3 m), every stance outside reaches the goal, and the easiest
    /// jump out is refused because the trunk would hit the level.
    /// </summary>
    [Test]
    public void AStartClosedInSaysItsSideIsSmallAndTheWayOutHitsTheLevel()
    {
        Level level = new LevelBuilder("shed")
            .AddFloor(-8f, -8f, 8f, 8f, 0f)
            .AddBox(new Vector3(-1.7f, 0f, -1.7f), new Vector3(1.7f, 2.7f, -1.5f))
            .AddBox(new Vector3(-1.7f, 0f, 1.5f), new Vector3(1.7f, 2.7f, 1.7f))
            .AddBox(new Vector3(-1.7f, 0f, -1.5f), new Vector3(-1.5f, 2.7f, 1.5f))
            .AddBox(new Vector3(1.5f, 0f, -1.5f), new Vector3(1.7f, 2.7f, 1.5f))
            .AddBox(new Vector3(-1.7f, 2.5f, -1.7f), new Vector3(1.7f, 2.7f, 1.7f))
            .Build();
        string reason = NoPath(level, new Vector3(0f, 0f, 0f), new Vector3(5f, 0f, 5f));
        Match side = Regex.Match(reason, @"the start reaches (no stance of the roadmap|(\d+) stances? \(all within ([\d.]+) m of it\)) and (\d+) stances reach the goal");
        Assert.That(side.Success, Is.True, reason);
        if (side.Groups[3].Success)
        {
            Assert.That(float.Parse(side.Groups[3].Value, System.Globalization.CultureInfo.InvariantCulture), Is.LessThanOrEqualTo(3f), reason);
        }

        Assert.That(int.Parse(side.Groups[4].Value, System.Globalization.CultureInfo.InvariantCulture), Is.GreaterThan(50), "the open floor's stances reach the goal");
        Assert.That(reason, Does.Contain("is refused: the trunk would hit the level in flight"));
    }

    /// <summary>
    /// A goal on a pillar 4 m high: the skeleton's trunk would rise 4 m, which needs a takeoff of at least
    /// √(2 g · 4) ≈ 8.9 m/s, above its 8 m/s: the reason gives the least speed the easiest jump needs and the limit.
    /// </summary>
    [Test]
    public void AGoalTooHighToJumpOntoSaysTheSpeedItNeedsAndTheLimit()
    {
        Level level = new LevelBuilder("pillar")
            .AddFloor(-8f, -8f, 8f, 8f, 0f)
            .AddBox(new Vector3(1f, 0f, -1f), new Vector3(3f, 4f, 1f))
            .Build();
        string reason = NoPath(level, new Vector3(-4f, 0f, 0f), new Vector3(2f, 4f, 0f));
        Match gap = Regex.Match(reason, @"the easiest jump between them, from \([^)]*\) to \(([-\d.]+), ([-\d.]+), ([-\d.]+)\) \(([\d.]+) m across, ([\d.]+) m up\), needs a takeoff of at least ([\d.]+) m/s, above the character's 8\.00 m/s");
        Assert.That(gap.Success, Is.True, reason);
        float At(int group) => float.Parse(gap.Groups[group].Value, System.Globalization.CultureInfo.InvariantCulture);
        Assert.Multiple(() =>
        {
            Assert.That(At(2), Is.EqualTo(4f).Within(0.05f), "the gap ends on the pillar's top");
            Assert.That(At(5), Is.EqualTo(4f).Within(0.1f), "4 m up");
            Assert.That(At(6), Is.GreaterThan(8.8f), "at least √(2 g · 4) m/s");
            Assert.That(reason, Does.Contain("the start reaches ").And.Contain(" reach the goal"));
        });

        // The README quotes this reason from "the start reaches" on.
        string readme = File.ReadAllText(Path.Combine(RepositoryFiles.Root, "README.md")).ReplaceLineEndings(" ");
        Assert.That(readme, Does.Contain(reason[reason.IndexOf("the start reaches", StringComparison.Ordinal)..]), "the README's no_path example (this test's reason is the one to paste)");
    }

    /// <summary>The least takeoff speed of a ballistic jump: √(2 g h) straight up, √(g d) across level ground, less going down.</summary>
    [Test]
    public void TheLeastTakeoffSpeedIsTheBallisticBound()
    {
        Assert.Multiple(() =>
        {
            Assert.That(NoPathGap.LeastSpeed(new Vector3(0f, 4f, 0f), 9.81f), Is.EqualTo(MathF.Sqrt(2f * 9.81f * 4f)).Within(1e-4f));
            Assert.That(NoPathGap.LeastSpeed(new Vector3(3f, 0f, 4f), 9.81f), Is.EqualTo(MathF.Sqrt(9.81f * 5f)).Within(1e-4f));
            Assert.That(NoPathGap.LeastSpeed(new Vector3(5f, -2f, 0f), 9.81f), Is.LessThan(MathF.Sqrt(9.81f * 5f)));
        });
    }

    /// <summary>
    /// Two large sides' easiest gap, found through a grid of one side, is the pair a scan of every pair finds, tie
    /// for tie: 40 seeded pairs of islands of 150 to 400 stances each (a side spread over a dune field or bunched on a
    /// roof, the islands apart, overlapping, one above the other, some stances of either side outside the other's
    /// bounds), every third with one side mirrored across a stance of the other, so that two pairs need exactly the least speed.
    /// </summary>
    [Test]
    public void TheEasiestGapBetweenTwoLargeSidesIsThePairEveryPairScanFinds()
    {
        var random = new Random(29);
        int tied = 0;
        for (int trial = 0; trial < 40; trial++)
        {
            List<Vector3> Island(int count, Vector3 centre, float spread, float height)
            {
                var points = new List<Vector3>(count);
                for (int i = 0; i < count; i++)
                {
                    points.Add(centre + new Vector3(((random.NextSingle() * 2f) - 1f) * spread, random.NextSingle() * height, ((random.NextSingle() * 2f) - 1f) * spread * (trial % 4 == 0 ? 0.05f : 1f)));
                }

                return points;
            }

            List<Vector3> from = Island(150 + random.Next(250), new Vector3(random.NextSingle() * 20f, 0f, random.NextSingle() * 20f), 2f + (random.NextSingle() * 30f), random.NextSingle() * 8f);
            List<Vector3> to = Island(150 + random.Next(250), new Vector3(random.NextSingle() * 40f, (random.NextSingle() * 10f) - 5f, random.NextSingle() * 40f), 1f + (random.NextSingle() * 20f), random.NextSingle() * 6f);
            if (trial % 3 == 0)
            {
                // Ties: the side's stances mirrored across the first stance of the other (the same speed from there to
                // the bit), listed after them; that stance the nearest one by far, the others 200 m off.
                Vector3 first = from[0];
                to.AddRange([.. to.Select(q => new Vector3((2f * first.X) - q.X, q.Y, q.Z))]);
                for (int i = 1; i < from.Count; i++)
                {
                    from[i] += new Vector3(200f, 0f, 200f);
                }
            }

            Assert.That((long)from.Count * to.Count, Is.GreaterThan(NoPathGap.PairsScanned), "sides large enough for the grid");
            (float Least, int From, int To) byGrid = NoPathGap.Easiest(from, to, 9.81f);
            (float Least, int From, int To) byPairs = NoPathGap.EasiestByEveryPair(from, to, 9.81f);
            Assert.That(byGrid, Is.EqualTo(byPairs), $"trial {trial}");
            tied += to.Count(q => NoPathGap.LeastSpeed(q - from[byPairs.From], 9.81f) == byPairs.Least) > 1 ? 1 : 0;
        }

        Assert.That(tied, Is.GreaterThan(5), "trials in which several stances need exactly the least speed");
    }

    private static string NoPath(Level level, Vector3 from, Vector3 to)
    {
        var scene = PlanningScene.Create(level, CharacterPresets.Skeleton());
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 1, Threads = 2, MaxNodes = 300 }).Roadmap;
        PlanResult result = new PathQuery(scene, roadmap).Plan(from, to);
        Assert.That(result.Status, Is.EqualTo(PlannerStatus.NoPath), result.Reason);
        TestContext.Out.WriteLine(result.Reason);
        return result.Reason;
    }
}
