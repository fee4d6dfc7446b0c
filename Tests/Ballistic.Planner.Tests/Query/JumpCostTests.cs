using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Query;

/// <summary>
/// A jump's cost in a search that walks: its flight time, <see cref="QuerySettings.JumpEffort"/>, and
/// <see cref="QuerySettings.JumpHeightEffort"/> per metre of its takeoff's energy height, so that a designer can make
/// a character walk round a wall rather than vault it.
/// </summary>
public sealed class JumpCostTests
{
    /// <summary>A walled floor: a wall 0.8 m high and 10 m long across the middle, open at both ends.</summary>
    private static readonly Lazy<(PlanningScene Scene, Roadmap Roadmap)> Walled = new(() =>
    {
        Level level = new LevelBuilder("walled")
            .AddFloor(-4f, -7.5f, 4f, 7.5f, 0f, n: 8)
            .AddBox(new Vector3(-0.15f, 0f, -5f), new Vector3(0.15f, 0.8f, 5f))
            .Build();
        var scene = PlanningScene.Create(level, CharacterPresets.Skeleton());
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 3, MaxNodes = 500, Threads = 2, Locomotion = Locomotion.WalkAndJump }).Roadmap;
        return (scene, roadmap);
    });

    [Test]
    public void AJumpCostsItsFlightTheEffortAndTheHeightEffortPerMetreOfItsEnergyHeight()
    {
        // Straight up at √(2g) m/s: the takeoff's energy lifts the trunk 1 m, and that is the apex's rise.
        (BallisticArc vertical, BallisticArc leap) = SameFlight();
        Assert.That(vertical.EnergyHeight, Is.EqualTo(1f).Within(1e-4f));
        Assert.That(vertical.Apex.Y - vertical.Start.Y, Is.EqualTo(1f).Within(1e-4f));

        // A long leap to the same apex costs more: its horizontal speed is effort too.
        Assert.That(leap.EnergyHeight, Is.GreaterThan(vertical.EnergyHeight + 0.5f));

        var settings = new QuerySettings { JumpEffort = 1.5f, JumpHeightEffort = 2f };
        Assert.That(settings.JumpCost(vertical), Is.EqualTo(vertical.FlightTime + 1.5f + 2f).Within(1e-4f));
        Assert.That(settings.JumpCost(leap), Is.EqualTo(leap.FlightTime + 1.5f + (2f * leap.EnergyHeight)).Within(1e-4f));
        Assert.That(new QuerySettings().JumpCost(leap), Is.EqualTo(leap.FlightTime + QuerySettings.DefaultJumpEffort + (QuerySettings.DefaultJumpHeightEffort * leap.EnergyHeight)).Within(1e-4f));
    }

    [Test]
    public void ByDefaultAJumpCostsMoreTheHarderItPushes()
    {
        // Two jumps of the same flight time: the long leap pushes harder than the jump straight up and, by default,
        // costs more beyond its flight (issue 24: not a flat effort); a hop at 3 m/s costs about 3.6 s, a leap at 7 m/s
        // about 4.1 s, as the README says.
        (BallisticArc vertical, BallisticArc leap) = SameFlight();
        var defaults = new QuerySettings();
        Assert.That(defaults.JumpCost(leap) - leap.FlightTime, Is.GreaterThan(defaults.JumpCost(vertical) - vertical.FlightTime + 0.1f));
        Assert.That(Beyond(3f), Is.EqualTo(3.6f).Within(0.05f));
        Assert.That(Beyond(7f), Is.EqualTo(4.1f).Within(0.05f));

        // Seconds of walking a jump taking off at this speed costs beyond its flight.
        float Beyond(float speed)
        {
            var hop = new BallisticArc(new RootPose(Vector3.Zero, Quaternion.Identity), new RootPose(new Vector3(1f, 0f, 0f), Quaternion.Identity), new Vector3(speed * 0.6f, speed * 0.8f, 0f), 2f * speed * 0.8f / 9.81f, 9.81f);
            return defaults.JumpCost(hop) - hop.FlightTime;
        }
    }

    /// <summary>A jump straight up at √(2g) m/s (energy height 1 m) and a 6 m leap of the same flight time and apex.</summary>
    private static (BallisticArc Vertical, BallisticArc Leap) SameFlight()
    {
        float up = MathF.Sqrt(2f * 9.81f);
        float flight = 2f * up / 9.81f;
        var at = new RootPose(Vector3.Zero, Quaternion.Identity);
        return (new BallisticArc(at, at, new Vector3(0f, up, 0f), flight, 9.81f),
            new BallisticArc(at, new RootPose(new Vector3(6f, 0f, 0f), Quaternion.Identity), new Vector3(6f / flight, up, 0f), flight, 9.81f));
    }

    [Test]
    public void AHeightEffortMakesTheSkeletonWalkRoundAWallItVaultsWhenEveryJumpCostsTheSame()
    {
        (PlanningScene scene, Roadmap roadmap) = Walled.Value;
        var query = new PathQuery(scene, roadmap);
        Vector3 from = new(-1.6f, 0f, 0.3f);
        Vector3 to = new(1.6f, 0f, -0.2f);

        // Every jump 4 s beyond its flight: vaulting the wall (about a second in the air) beats 10 m of walking round it.
        PlanResult flat = query.Plan(from, to, new QuerySettings { JumpEffort = 4f, JumpHeightEffort = 0f });
        // Two seconds a metre of energy height: the vault's push (its trunk rises over the wall) costs more than the detour.
        PlanResult tuned = query.Plan(from, to, new QuerySettings { JumpEffort = 4f, JumpHeightEffort = 2f });

        static bool Vaults(Move move) => move is Jump jump && MathF.Sign(jump.Arc.Start.X) != MathF.Sign(jump.Arc.End.X) && MathF.Abs(jump.Arc.Start.Z + jump.Arc.End.Z) < 10f;
        Assert.Multiple(() =>
        {
            Assert.That(flat.Status, Is.EqualTo(PlannerStatus.Exact), flat.Reason);
            Assert.That(tuned.Status, Is.EqualTo(PlannerStatus.Exact), tuned.Reason);
            Assert.That(flat.Moves.Any(Vaults), Is.True, "with a flat effort the wall is vaulted");
            Assert.That(tuned.Moves.Any(Vaults), Is.False, "with a height effort the wall is walked round");
            Assert.That(tuned.Moves.OfType<Walk>().Sum(w => w.Length), Is.GreaterThan(8f), "round the wall's end, 5 m from the line between the points");
        });

        foreach ((string name, PlanResult plan) in new[] { ("flat", flat), ("tuned", tuned) })
        {
            AuditReport audit = PlanAudit.Check($"walled {name}", scene, from, to, plan, null);
            Assert.That(audit.Violations, Is.Empty, string.Join("; ", audit.Violations));
        }
    }

    /// <summary>
    /// A maze of two 0.8 m walls across a floor, each open past the other's end (issue 24: "a maze is walked through
    /// its corridors when the detour is moderate"): from one side to the other, 8 m straight across both walls, the
    /// corridor between them is about 10 m of walking. With the default costs (a jump of a metre's rise costs about
    /// 4 s beyond its flight, some 6 m of walking) the skeleton walks the corridor; with jumps free it vaults the
    /// walls, so the maze is one it could jump.
    /// </summary>
    [Test]
    public void AMazeIsWalkedThroughItsCorridorsWhenTheDetourIsModerate()
    {
        Level level = new LevelBuilder("maze")
            .AddFloor(-6f, -6f, 6f, 6f, 0f, n: 8)
            .AddBox(new Vector3(-6f, 0f, -1.65f), new Vector3(0.5f, 0.8f, -1.35f))
            .AddBox(new Vector3(-0.5f, 0f, 1.35f), new Vector3(6f, 0.8f, 1.65f))
            .Build();
        var scene = PlanningScene.Create(level, CharacterPresets.Skeleton());
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 3, MaxNodes = 500, Threads = 2, Locomotion = Locomotion.WalkAndJump }).Roadmap;
        var query = new PathQuery(scene, roadmap);
        Vector3 from = new(0f, 0f, -4f);
        Vector3 to = new(0f, 0f, 4f);
        PlanResult defaults = query.Plan(from, to, new QuerySettings());
        PlanResult free = query.Plan(from, to, new QuerySettings { JumpEffort = 0f, JumpHeightEffort = 0f });

        static bool Vaults(Move move) => move is Jump jump && (Across(jump, -1.5f) || Across(jump, 1.5f));
        static bool Across(Jump jump, float z) => (jump.Arc.Start.Z - z) * (jump.Arc.End.Z - z) < 0f;
        TestContext.Out.WriteLine($"defaults: {defaults.Moves.OfType<Walk>().Sum(w => w.Length):0.0} m walked, {defaults.Jumps.Count} jumps; free jumps: {free.Moves.OfType<Walk>().Sum(w => w.Length):0.0} m walked, {free.Jumps.Count} jumps");
        Assert.Multiple(() =>
        {
            Assert.That(defaults.Status, Is.EqualTo(PlannerStatus.Exact), defaults.Reason);
            Assert.That(free.Status, Is.EqualTo(PlannerStatus.Exact), free.Reason);
            Assert.That(defaults.Moves.Any(Vaults), Is.False, "with the default costs no wall is vaulted");
            Assert.That(defaults.Moves.OfType<Walk>().Sum(w => w.Length), Is.GreaterThan(9f), "the corridor walked, past both walls' open ends");
            Assert.That(free.Moves.Any(Vaults), Is.True, "with jumps free a wall is vaulted");
        });

        foreach ((string name, PlanResult plan) in new[] { ("defaults", defaults), ("free", free) })
        {
            AuditReport audit = PlanAudit.Check($"maze {name}", scene, from, to, plan, null);
            Assert.That(audit.Violations, Is.Empty, string.Join("; ", audit.Violations));
        }
    }

    [Test]
    public void NegativeOrNonFiniteJumpCostsAreRefusedWithOneLine()
    {
        (PlanningScene scene, Roadmap roadmap) = Walled.Value;
        var query = new PathQuery(scene, roadmap);
        Assert.That(() => query.Plan(new Vector3(-1f, 0f, 0f), new Vector3(1f, 0f, 0f), new QuerySettings { JumpHeightEffort = -1f }),
            Throws.ArgumentException.With.Message.Contains("JumpHeightEffort must be finite and not negative"));
        Assert.That(() => query.Plan(new Vector3(-1f, 0f, 0f), new Vector3(1f, 0f, 0f), new QuerySettings { JumpEffort = float.NaN }),
            Throws.ArgumentException.With.Message.Contains("JumpEffort must be finite and not negative"));
        Assert.That(new Ballistic.Runtime.Core.WorldSettings { JumpHeightEffort = float.PositiveInfinity }.Problem(), Does.Contain("JumpHeightEffort"));
        Assert.That(new Ballistic.Authoring.Playtest.PlaytestSettings { JumpHeightEffort = -0.5f }.Problem(), Does.Contain("jump height effort"));
    }
}
