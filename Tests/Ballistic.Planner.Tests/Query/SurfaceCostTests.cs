using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Query;

/// <summary>
/// Costs per surface, as navigation areas have them (<see cref="LevelMaterial.TravelCost"/>,
/// <see cref="LevelMaterial.EnterCost"/>): a walk costs its time on each material times that material's travel cost
/// plus the enter cost of each material it steps onto; a jump adds the enter cost of a material it lands on from
/// another. They change routes, never the roadmap.
/// </summary>
public sealed class SurfaceCostTests
{
    /// <summary>A 12 × 12 m floor whose middle strip (x from −1 to 1, z from −4 to 4) is <paramref name="mud"/>, the rest plain; open past the strip's ends.</summary>
    private static Level MudFloor(LevelMaterial mud) => new LevelBuilder("mud floor")
        .AddFloor(-6f, -6f, -1f, 6f, 0f, n: 6)
        .AddFloor(1f, -6f, 6f, 6f, 0f, n: 6)
        .AddFloor(-1f, 4f, 1f, 6f, 0f, n: 2)
        .AddFloor(-1f, -6f, 1f, -4f, 0f, n: 2)
        .AddFloor(-1f, -4f, 1f, 4f, 0f, n: 4, material: mud)
        .Build();

    private static bool InMud(Vector3 p) => p.X is > -0.95f and < 0.95f && p.Z is > -3.95f and < 3.95f;

    [Test]
    public void AWalkCostsItsTimeOnEachMaterialTimesItsTravelCostPlusWhatItEnters()
    {
        Level level = MudFloor(new LevelMaterial("mud", null) { TravelCost = 3f, EnterCost = 2f });
        var costs = new SurfaceCosts(level, level.Bvh);

        // 6 m in 4 s, 2 m of them on the mud: 4 s × (4 + 2 × 3) / 6, plus 2 s for stepping onto the mud.
        float across = costs.Walk([new Vector3(-3f, 0f, 0f), new Vector3(3f, 0f, 0f)], 4f, costs.MaterialBelow(new Vector3(-3f, 0f, 0f)));
        Assert.That(across, Is.EqualTo((4f * 10f / 6f) + 2f).Within(1e-3f));

        // Beside the strip: plain ground all the way, the walk's own time.
        Assert.That(costs.Walk([new Vector3(-3f, 0f, 5f), new Vector3(3f, 0f, 5f)], 4f, costs.MaterialBelow(new Vector3(-3f, 0f, 5f))), Is.EqualTo(4f).Within(1e-5f));

        // Starting on the mud: no enter cost for it, only its travel cost (1 m of 2 on it).
        Assert.That(costs.Walk([new Vector3(0f, 0f, 0f), new Vector3(2f, 0f, 0f)], 1f, costs.MaterialBelow(Vector3.Zero)), Is.EqualTo(1f * (3f + 1f) / 2f).Within(1e-3f));
    }

    [Test]
    public void AJumpPaysTheEnterCostOfTheMaterialItLandsOnFromAnother()
    {
        Level level = MudFloor(new LevelMaterial("mud", null) { EnterCost = 5f });
        var costs = new SurfaceCosts(level, level.Bvh);
        static RoadmapNode Standing(int id, Vector3 at) =>
            new(id, new RootPose(at + new Vector3(0f, 0.9f, 0f), Quaternion.Identity), new FrictionCone(Vector3.UnitY, 0.5f), [new Contact(0, at, Vector3.UnitY, 0.5f, 0)]);
        RoadmapNode plain = Standing(0, new Vector3(-3f, 0f, 0f));
        RoadmapNode mud = Standing(1, new Vector3(0f, 0f, 0f));
        RoadmapNode mudToo = Standing(2, new Vector3(0.5f, 0f, 2f));
        RoadmapNode plainToo = Standing(3, new Vector3(3f, 0f, 0f));
        Assert.Multiple(() =>
        {
            Assert.That(costs.Jump(plain, mud), Is.EqualTo(5f), "landing on the mud from plain ground");
            Assert.That(costs.Jump(mud, mudToo), Is.Zero, "mud to mud enters nothing");
            Assert.That(costs.Jump(mud, plainToo), Is.Zero, "plain ground costs nothing to enter");
            Assert.That(costs.Jump(plain, plainToo), Is.Zero);
        });
    }

    /// <summary>
    /// From one side of the mud strip to the other: on plain ground the skeleton walks straight across it (one walk);
    /// with the mud's travel cost at 6 no walk of its route crosses the mud: it jumps the strip (walk, jump, walk), and
    /// when jumps cost 30 s of effort it walks round the strip's end. All on the same roadmap, baked before the cost
    /// was set (the level's fingerprint, which a roadmap records, leaves costs out).
    /// </summary>
    [Test]
    public void ARouteKeepsOffMudThatCostsSixTimesPlainGround()
    {
        Level plainLevel = MudFloor(new LevelMaterial("mud", null));
        Level mudLevel = MudFloor(new LevelMaterial("mud", null) { TravelCost = 6f });
        Assert.That(mudLevel.Fingerprint, Is.EqualTo(plainLevel.Fingerprint), "costs do not change the level's fingerprint");
        var plainScene = PlanningScene.Create(plainLevel, CharacterPresets.Skeleton());
        var mudScene = PlanningScene.Create(mudLevel, CharacterPresets.Skeleton());
        Roadmap roadmap = new RoadmapBaker(plainScene).Bake(new BakeSettings { Seed = 3, MaxNodes = 500, Threads = 2, Locomotion = Locomotion.WalkAndJump }).Roadmap;
        Vector3 from = new(-4f, 0f, 0f);
        Vector3 to = new(4f, 0f, 0f);
        PlanResult plain = new PathQuery(plainScene, roadmap).Plan(from, to);
        PlanResult mud = new PathQuery(mudScene, roadmap).Plan(from, to);
        PlanResult round = new PathQuery(mudScene, roadmap).Plan(from, to, new QuerySettings { JumpEffort = 30f });

        static int MudPoints(PlanResult plan) => plan.Moves.OfType<Walk>().Sum(w => w.Path.Count(InMud));
        TestContext.Out.WriteLine($"costly jumps: {string.Join(", ", round.Moves.Select(m => m.GetType().Name))}, {MudPoints(round)} walk points on the mud, farthest {round.Moves.OfType<Walk>().SelectMany(w => w.Path).Max(p => MathF.Abs(p.Z)):0.0} m off the straight line");
        TestContext.Out.WriteLine($"plain: {string.Join(", ", plain.Moves.Select(m => m.GetType().Name))}, {MudPoints(plain)} walk points on the mud; mud costed: {string.Join(", ", mud.Moves.Select(m => m.GetType().Name))}, {MudPoints(mud)}");
        Assert.Multiple(() =>
        {
            Assert.That(plain.Status, Is.EqualTo(PlannerStatus.Exact), plain.Reason);
            Assert.That(mud.Status, Is.EqualTo(PlannerStatus.Exact), mud.Reason);
            Assert.That(MudPoints(plain), Is.GreaterThan(0), "on plain ground the route walks straight across the strip");
            Assert.That(MudPoints(mud), Is.Zero, "with the mud costly no walk crosses it");
            Assert.That(mud.Jumps, Has.Count.EqualTo(1), "it jumps the strip");
            Assert.That(WalkRefusals.Of(mudScene, mud.Moves).Single().Reason, Does.Contain("over 'mud' (travel cost 6, enter cost 0 s)"), "the report says why the jump was not walked");
            Assert.That(WalkRefusals.Of(plainScene, mud.Moves).Single().Reason, Does.Not.Contain("over"), "no cost, no mention");
            Assert.That(round.Status, Is.EqualTo(PlannerStatus.Exact), round.Reason);
            Assert.That(round.Jumps, Is.Empty, "with jumps costly too, no jump");
            Assert.That(MudPoints(round), Is.Zero, "nor a walk through the mud");
            Assert.That(round.Moves.OfType<Walk>().SelectMany(w => w.Path).Max(p => MathF.Abs(p.Z)), Is.GreaterThan(4f), "round the strip's end");
        });

        foreach ((string name, PlanningScene scene, PlanResult plan) in new[] { ("plain", plainScene, plain), ("mud", mudScene, mud), ("round", mudScene, round) })
        {
            AuditReport audit = PlanAudit.Check($"mud floor {name}", scene, from, to, plan, null);
            Assert.That(audit.Violations, Is.Empty, string.Join("; ", audit.Violations));
        }
    }

    /// <summary>The plan picture's top view tints the costly surfaces red (and only on a level with costs).</summary>
    [Test]
    public void TheTopViewTintsCostlySurfacesRed()
    {
        Level plain = MudFloor(new LevelMaterial("mud", null));
        Level mud = MudFloor(new LevelMaterial("mud", null) { EnterCost = 3f });
        const int size = 48;
        byte[] untinted = Ballistic.Authoring.Reports.SvgPlanRenderer.HeightMapRgb(plain.Bvh, plain.Bounds, size, size);
        byte[] plainToo = Ballistic.Authoring.Reports.SvgPlanRenderer.HeightMapRgb(plain.Bvh, plain.Bounds, size, size, plain);
        byte[] tinted = Ballistic.Authoring.Reports.SvgPlanRenderer.HeightMapRgb(mud.Bvh, mud.Bounds, size, size, mud);

        // Pixel columns run over x from −6 to 6 m, rows over z: the middle pixel lies on the mud, one at x = −4 m beside it.
        static (int R, int G, int B) At(byte[] rgb, float x, float z)
        {
            int i = (int)((x + 6f) / 12f * size);
            int j = (int)((z + 6f) / 12f * size);
            int p = 3 * ((j * size) + i);
            return (rgb[p], rgb[p + 1], rgb[p + 2]);
        }

        Assert.Multiple(() =>
        {
            Assert.That(Ballistic.Authoring.Playtest.PlaytestMapRenderer.Legend(mud), Does.EndWith(" · red ground: a travel or enter cost"), "the playtest map's legend says what red ground is");
            Assert.That(Ballistic.Authoring.Playtest.PlaytestMapRenderer.Legend(plain), Does.Not.Contain("red ground"));
            Assert.That(plainToo, Is.EqualTo(untinted), "a level without costs is drawn as before");
            Assert.That(At(tinted, 0f, 0f).R - At(tinted, 0f, 0f).G, Is.GreaterThan(At(untinted, 0f, 0f).R - At(untinted, 0f, 0f).G + 40), "the mud is drawn redder");
            Assert.That(At(tinted, -4f, 0f), Is.EqualTo(At(untinted, -4f, 0f)), "plain ground is drawn as before");
        });
    }

    [TestCase(0.5f, 0f, "travel cost 0.5 must be a number from 1 to 1000")]
    [TestCase(float.NaN, 0f, "travel cost NaN must be a number from 1 to 1000")]
    [TestCase(1f, -1f, "enter cost -1 must be a number of seconds from 0 to 10000")]
    [TestCase(1f, float.PositiveInfinity, "enter cost Infinity must be a number of seconds from 0 to 10000")]
    public void CostsOutOfRangeAreRefusedInOneLineNamingTheMaterial(float travel, float enter, string problem)
    {
        var builder = new LevelBuilder("costs");
        LevelException? refused = Assert.Throws<LevelException>(() => builder.AddFloor(0f, 0f, 1f, 1f, 0f, material: new LevelMaterial("lava", null) { TravelCost = travel, EnterCost = enter }));
        Assert.That(refused!.Message, Is.EqualTo($"Material 'lava' in costs: its {problem}."));
    }
}
