using System.Globalization;
using System.Text;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Query;

/// <summary>
/// <see cref="PathQuery.Prepare"/>: every node pair a roadmap move links planned once ahead of time, and what those
/// requests place and steer kept in the scene for good. Counted through the game's validators, which are asked about
/// every stance placed and every arc steered anew: a prepared request asks them nothing, however many requests came
/// between, and no path changes.
/// </summary>
public sealed class QueryPreparationTests
{
    private static readonly QuerySettings JumpOnly = new() { Locomotion = Locomotion.Jump };

    [Test]
    public void APreparedRoadmapsMovesAreWorkedOutNeverAgainAndNoPathChanges()
    {
        // The desert's 1,000-node roadmap: its jumps turned to face their way place and steer far more than the
        // scene's bounded memory of recent results holds, so without keeping, the first requests' are forgotten.
        var counting = new CountingValidator();
        var scene = PlanningScene.Create(SharedLevels.Bundled("desert"), CharacterPresets.Skeleton(), poseValidator: counting, arcValidator: counting);
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Locomotion = Locomotion.Jump, Seed = 7, MaxNodes = 1_000, Threads = 2 }).Roadmap;
        var query = new PathQuery(scene, roadmap);
        List<(int From, int To)> pairs = [.. roadmap.Edges.Select(e => (e.From, e.To)).Distinct().Order()];

        int prepared = query.Prepare(JumpOnly, threads: 2);
        Assert.That(prepared, Is.EqualTo(pairs.Count), "every pair a roadmap jump links");
        Assert.That(scene.KeptCount, Is.GreaterThan(60_000), "more than the bounded memory holds");
        string readme = File.ReadAllText(Path.Combine(RepositoryFiles.Root, "README.md"));
        Assert.That(readme, Does.Contain(FormattableString.Invariant($"it plans\n{prepared:N0} pairs")).Or.Contain(FormattableString.Invariant($"it plans {prepared:N0} pairs")), "the README's count of pairs");
        Assert.That(readme, Does.Contain(FormattableString.Invariant($"keeps {scene.KeptCount:N0} placements and arcs")), "the README's count of what is kept");

        // Every prepared request again, first to last: nothing is placed or steered anew.
        counting.Calls = 0;
        foreach ((int from, int to) in pairs)
        {
            query.Plan(roadmap.Nodes[from], roadmap.Nodes[to], JumpOnly);
        }

        Assert.That(counting.Calls, Is.Zero, "a prepared request recalls every stance and arc");

        // The same requests and new ones on a scene never prepared give the same paths.
        var fresh = new PathQuery(PlanningScene.Create(scene.Level, scene.Character, poseValidator: counting, arcValidator: counting), roadmap);
        var random = new Random(11);
        var requests = new List<Func<PathQuery, PlanResult>>();
        for (int i = 0; i < 120; i++)
        {
            RoadmapNode a = roadmap.Nodes[random.Next(roadmap.Nodes.Count)], b = roadmap.Nodes[random.Next(roadmap.Nodes.Count)];
            requests.Add(i % 3 == 0 ? q => q.Plan(a.Contacts[0].Position, b.Contacts[0].Position, JumpOnly) : q => q.Plan(a, b, JumpOnly));
        }

        foreach ((int from, int to) in pairs.Where((_, k) => k % 400 == 0))
        {
            requests.Add(q => q.Plan(roadmap.Nodes[from], roadmap.Nodes[to], JumpOnly));
        }

        string[] expected = [.. requests.Select(r => Describe(r(fresh)))];
        string[] got = [.. requests.Select(r => Describe(r(query)))];
        Assert.That(expected.Count(e => e.Contains('>', StringComparison.Ordinal)), Is.GreaterThan(100), "most requests find a path");
        Assert.That(got, Is.EqualTo(expected));
    }

    [Test]
    public void OneThreadOrTwoPrepareTheSameAndAStoppedPreparationKeepsWhatItDid()
    {
        Roadmap Bake(PlanningScene s) => new RoadmapBaker(s).Bake(new BakeSettings { Seed = 4, MaxNodes = 150, Threads = 2 }).Roadmap;
        var one = PlanningScene.Create(GapCourse.Build(), CharacterPresets.Skeleton());
        var two = PlanningScene.Create(one.Level, one.Character);
        Roadmap roadmap = Bake(one);
        int pairs = roadmap.Edges.Select(e => (e.From, e.To)).Concat(roadmap.Walks.Select(w => (w.From, w.To))).Distinct().Count();
        var settings = new QuerySettings();
        Assert.That(new PathQuery(one, roadmap).Prepare(settings), Is.EqualTo(pairs), "every pair a jump or walk links");
        Assert.That(new PathQuery(two, roadmap).Prepare(settings, threads: 2), Is.EqualTo(pairs));
        Assert.Multiple(() =>
        {
            Assert.That(one.Walking.KeptCount, Is.GreaterThan(0), "walks kept too");
            Assert.That(two.Sampler.KeptCount, Is.EqualTo(one.Sampler.KeptCount).And.GreaterThan(0), "placements");
            Assert.That(two.Steering.KeptCount, Is.EqualTo(one.Steering.KeptCount).And.GreaterThan(0), "arcs");
            Assert.That(two.Walking.KeptCount, Is.EqualTo(one.Walking.KeptCount), "walks");
        });

        // Cancelled before it began: nothing prepared, nothing kept. Cancelled by the 40th arc: part of it, kept.
        var three = PlanningScene.Create(one.Level, one.Character);
        using var cancelled = new CancellationTokenSource();
        cancelled.Cancel();
        Assert.That(new PathQuery(three, roadmap).Prepare(settings, termination: TerminationCondition.Cancellation(cancelled.Token)), Is.Zero);
        Assert.That(three.KeptCount, Is.Zero);

        using var later = new CancellationTokenSource();
        var cancelling = new CountingValidator { CancelAt = 40, Cancel = later };
        var four = PlanningScene.Create(one.Level, one.Character, poseValidator: cancelling, arcValidator: cancelling);
        int part = new PathQuery(four, roadmap).Prepare(settings, termination: TerminationCondition.Cancellation(later.Token));
        Assert.That(part, Is.InRange(1, pairs - 1), "stopped part way");
        Assert.That(four.KeptCount, Is.InRange(1, one.KeptCount - 1), "what it did stays kept");
    }

    /// <summary>Every move of a result, its ends and timing to the bit.</summary>
    private static string Describe(PlanResult result)
    {
        var text = new StringBuilder(FormattableString.Invariant($"{result.Status} {result.Start?.Id} {result.Goal?.Id}:"));
        foreach (Move move in result.Moves)
        {
            text.Append(CultureInfo.InvariantCulture, $" {move.GetType().Name} {move.From.Id}>{move.To.Id} {move.Duration:R} {move.From.Pose.Position:R} {move.To.Pose.Position:R}");
        }

        return text.ToString();
    }

    /// <summary>A game's validators accepting everything and counting the stances and arcs they are asked about; optionally cancelling at a count.</summary>
    private sealed class CountingValidator : IPoseValidator, IArcValidator
    {
        private int _calls;

        public int CancelAt { get; init; } = int.MaxValue;

        public CancellationTokenSource? Cancel { get; init; }

        public int Calls
        {
            get => Volatile.Read(ref _calls);
            set => Volatile.Write(ref _calls, value);
        }

        public bool IsValid(PoseEvaluation evaluation) => Note();

        public bool IsValid(in BallisticArc arc) => Note();

        private bool Note()
        {
            if (Interlocked.Increment(ref _calls) == CancelAt)
            {
                Cancel?.Cancel();
            }

            return true;
        }
    }
}
