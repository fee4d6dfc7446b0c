using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Planning;

/// <summary>
/// A bake with a start and a goal samples a corridor between them first, widening it as it fills
/// (<see cref="BakeSettings.FocusOnRequest"/>): on a level much larger than the request, the nodes needed follow the
/// route, not the level's area; a wall across the corridor is walked around once it widens; a request spanning most
/// of a level bakes exactly as before.
/// </summary>
public sealed class RequestFocusTests
{
    private static readonly Lazy<(Level Level, (Vector3 From, Vector3 To)[] Requests)> Field = new(ForeignLevels.Field);
    private static readonly Lazy<PlanningScene> Skeleton = new(() => PlanningScene.Create(Field.Value.Level, CharacterPresets.Skeleton()));
    private static readonly Lazy<PlanningScene> Frog = new(() => PlanningScene.Create(Field.Value.Level, CharacterPresets.Frog()));

    private static BakeResult Bake(PlanningScene scene, Vector3 from, Vector3 to, int seed, bool focus = true, int maxNodes = 12_000, int threads = 2) =>
        new RoadmapBaker(scene).Bake(new BakeSettings { Seed = seed, Threads = threads, MaxNodes = maxNodes, Start = from, Goal = to, StopWhenConnected = true, FocusOnRequest = focus });

    /// <summary>
    /// Requests across the 120 m field connect within a node budget that follows the route (the frog's hops are
    /// 1–2 m: a hundred metres take it 700–850 nodes), each seed; sampled over the whole field, the first seed needs
    /// <paramref name="fewer"/> times as many at least (on an empty field the skeleton needed 530–1,154 nodes and the
    /// frog 2,354–3,474 whatever the distance, where focused they took 18–50 and 34–770; the frog's 100 m crossing,
    /// whose corridors widen to a third of the field, saves less).
    /// </summary>
    [TestCase("skeleton", 20f, 100, 5)]
    [TestCase("skeleton", 40f, 150, 5)]
    [TestCase("frog", 12f, 150, 5)]
    [TestCase("frog", 40f, 300, 5)]
    [TestCase("frog", 100f, 1200, 3)]
    public void RequestsOnAWideFieldConnectWithNodesThatFollowTheRoute(string character, float across, int budget, int fewer)
    {
        PlanningScene scene = character == "frog" ? Frog.Value : Skeleton.Value;
        var from = new Vector3(-across / 2f, 0f, 0f);
        var to = new Vector3(across / 2f, 0f, 0f);
        int first = 0;
        foreach (int seed in new[] { 1, 2, 3 })
        {
            BakeResult focused = Bake(scene, from, to, seed);
            Assert.That(focused.Status, Is.EqualTo(PlannerStatus.Exact), $"seed {seed}: {focused.Reason}");
            Assert.That(focused.Roadmap.Nodes, Has.Count.LessThanOrEqualTo(budget), $"seed {seed}");
            first = seed == 1 ? focused.Roadmap.Nodes.Count : first;
        }

        BakeResult whole = Bake(scene, from, to, 1, focus: false);
        Assert.That(whole.Status, Is.EqualTo(PlannerStatus.Exact), whole.Reason);
        Assert.That(whole.Roadmap.Nodes.Count, Is.GreaterThanOrEqualTo(fewer * first), "sampled over the whole field");
    }

    /// <summary>
    /// Until the first corridor has its nodes, every sample stands in it: within its half width (the skeleton's
    /// neighbour cell, 4.9 m, on a 40 m request) of the segment between start and goal, horizontally, give or take
    /// the pose's push out of the ground.
    /// </summary>
    [Test]
    public void TheFirstSamplesStandInTheCorridorBetweenStartAndGoal()
    {
        var from = new Vector3(-20f, 0f, -10f);
        var to = new Vector3(20f, 0f, 10f);
        BakeResult bake = new RoadmapBaker(Skeleton.Value).Bake(new BakeSettings { Seed = 4, Threads = 2, MaxNodes = 60, Start = from, Goal = to });
        float half = NodeIndex.CellSizeFor(Skeleton.Value.Steering.Limits);
        Assert.That(bake.Roadmap.Nodes, Has.Count.EqualTo(60));
        Assert.Multiple(() =>
        {
            foreach (RoadmapNode node in bake.Roadmap.Nodes.Skip(2))
            {
                Vector2 p = new(node.Pose.Position.X, node.Pose.Position.Z);
                Vector2 a = new(from.X, from.Z);
                Vector2 ab = new Vector2(to.X, to.Z) - a;
                float t = Math.Clamp(Vector2.Dot(p - a, ab) / ab.LengthSquared(), 0f, 1f);
                Assert.That(Vector2.Distance(p, a + (t * ab)), Is.LessThanOrEqualTo(half + 0.3f), $"node {node.Id}");
            }
        });

        // Sampled over the whole field, the same seed scatters them over it.
        BakeResult whole = new RoadmapBaker(Skeleton.Value).Bake(new BakeSettings { Seed = 4, Threads = 2, MaxNodes = 60, Start = from, Goal = to, FocusOnRequest = false });
        Assert.That(whole.Roadmap.Nodes.Skip(2).Count(n => new Vector2(n.Pose.Position.X, n.Pose.Position.Z).Length() > 30f), Is.GreaterThan(20));
    }

    /// <summary>
    /// A 4 m wall, 12 m long, across a 16 m request: no jump clears it, and the first corridors (the skeleton's 4.9 m,
    /// the frog's 2.3 m half width) hold no way around its ends; the corridor widens until one does.
    /// </summary>
    [TestCase("skeleton")]
    [TestCase("frog")]
    public void AWallAcrossTheCorridorIsGoneAroundAsTheCorridorWidens(string character)
    {
        PlanningScene scene = character == "frog" ? Frog.Value : Skeleton.Value;
        (Vector3 from, Vector3 to) = Field.Value.Requests[1];
        BakeResult bake = Bake(scene, from, to, 1, maxNodes: 3000);
        Assert.That(bake.Status, Is.EqualTo(PlannerStatus.Exact), bake.Reason);
        float half = NodeIndex.CellSizeFor(scene.Steering.Limits);
        Assert.That(bake.Roadmap.Nodes.Any(n => MathF.Abs(n.Pose.Position.Z) > 6f && MathF.Abs(n.Pose.Position.X - 30f) < 2f), Is.True, "a node beside the wall's end");
        Assert.That(bake.Roadmap.Nodes.Max(n => MathF.Abs(n.Pose.Position.Z)), Is.GreaterThan(half + 0.3f), "nodes beyond the first corridor");
    }

    /// <summary>
    /// A round that draws no valid pose in the corridor widens it at once (the bake asks with <see cref="RequestFocus.Widen"/>)
    /// instead of counting as a round in which the character could stand nowhere; otherwise the corridor keeps its
    /// width until it has its nodes.
    /// </summary>
    [Test]
    public void ACorridorWithNothingValidInItWidensAtOnce()
    {
        (Vector3 from, Vector3 to) = Field.Value.Requests[1];
        PlanningScene scene = Skeleton.Value;
        RequestFocus focus = RequestFocus.For(scene.Sampler, scene.Steering.Limits, from, to, 2)!;
        float first = focus.RegionAt(2)!.Radius;
        Assert.That(focus.RegionAt(3)!.Radius, Is.EqualTo(first), "not widened before its nodes");
        focus.Widen();
        Assert.That(focus.RegionAt(3)!.Radius, Is.EqualTo(2f * first));
    }

    /// <summary>The corridor's stages follow the node count alone: the same seed gives the same roadmap, byte for byte, on one thread and on four.</summary>
    [Test]
    public void AFocusedBakeIsTheSameOnOneThreadAndOnFour()
    {
        (Vector3 from, Vector3 to) = Field.Value.Requests[1];
        byte[] one = RoadmapFile.ToBytes(Bake(Frog.Value, from, to, 2, threads: 1).Roadmap);
        byte[] four = RoadmapFile.ToBytes(Bake(Frog.Value, from, to, 2, threads: 4).Roadmap);
        Assert.That(four, Is.EqualTo(one));
    }

    /// <summary>
    /// The demo's request spans most of the desert: its first corridor is more than a quarter of the level, so it is
    /// sampled whole from the start and bakes byte for byte as with focusing off (the demo and the sweep's small
    /// levels are unchanged).
    /// </summary>
    [Test]
    public void ARequestSpanningMostOfItsLevelBakesAsWithoutFocus()
    {
        PlanningScene scene = SharedLevels.Scene("desert", "skeleton");
        Vector3 from = LevelPoints.Ground(scene.Bvh, -9.5f, -7.5f)!.Value;
        Vector3 to = LevelPoints.Ground(scene.Bvh, 9.5f, 7.5f)!.Value;
        byte[] focused = RoadmapFile.ToBytes(Bake(scene, from, to, 1, maxNodes: 600).Roadmap);
        byte[] whole = RoadmapFile.ToBytes(Bake(scene, from, to, 1, focus: false, maxNodes: 600).Roadmap);
        Assert.That(focused, Is.EqualTo(whole));
    }
}
