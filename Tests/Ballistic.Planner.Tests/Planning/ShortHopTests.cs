using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Planning;

/// <summary>
/// The short hops a small jumper needs (issue 24's frog on a beam and on stair treads): a 1.7 m hop along a 0.3 m
/// beam is one jump between the placed stances (end to end along the beam, not yet: see the test); a
/// flight of eight 17.6 cm risers and 28 cm treads, 1.41 m high in all (above the frog's highest hop, 1.27 m at
/// 5 m/s), is hopped up tread by tread. Each plan's hops pass the physics checks.
/// </summary>
public sealed class ShortHopTests
{
    private const float Riser = 0.176f;
    private const float Tread = 0.28f;

    private static readonly Lazy<PlanningScene> Beam = new(() => PlanningScene.Create(new LevelBuilder("beam")
        .AddBox(new Vector3(-6f, 0f, -1.5f), new Vector3(-3f, 1f, 1.5f))
        .AddBox(new Vector3(3f, 0f, -1.5f), new Vector3(6f, 1f, 1.5f))
        .AddBox(new Vector3(-3f, 0.7f, -0.15f), new Vector3(3f, 1f, 0.15f))
        .AddFloor(-10f, -10f, 10f, 10f, 0f)
        .Build(), CharacterPresets.Frog()));

    private static readonly Lazy<PlanningScene> Stairs = new(() =>
    {
        var builder = new LevelBuilder("stairs").AddFloor(-6f, -4f, 10f, 4f, 0f);
        for (int i = 0; i < 8; i++)
        {
            builder.AddBox(new Vector3(i * Tread, 0f, -0.6f), new Vector3((i + 1) * Tread, (i + 1) * Riser, 0.6f));
        }

        builder.AddBox(new Vector3(8 * Tread, 0f, -0.6f), new Vector3(5f, 8 * Riser, 0.6f));
        return PlanningScene.Create(builder.Build(), CharacterPresets.Frog());
    });

    private static PlanResult Plan(PlanningScene scene, Vector3 from, Vector3 to)
    {
        BakeResult bake = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 1, Threads = 2, MaxNodes = 3000, Start = from, Goal = to, StopWhenConnected = true });
        Assert.That(bake.Status, Is.EqualTo(PlannerStatus.Exact), bake.Reason);
        PlanResult plan = new PathQuery(scene, bake.Roadmap).Plan(from, to);
        Assert.That(plan.Status, Is.EqualTo(PlannerStatus.Exact), plan.Reason);
        foreach (Jump jump in plan.Jumps)
        {
            PhysicsChecks.AssertJump(scene, jump.Takeoff, jump.Landing, jump.Arc, $"hop {jump.Takeoff.Id}→{jump.Landing.Id}");
        }

        return plan;
    }

    [Test]
    public void AHopAlongABeamIsOneJump()
    {
        PlanResult plan = Plan(Beam.Value, new Vector3(-1.7f, 1f, 0f), new Vector3(0f, 1f, 0f));
        Assert.That(plan.Jumps, Has.Count.EqualTo(1));
        Assert.That(Vector3.Distance(plan.Jumps[0].Arc.Start, plan.Jumps[0].Arc.End), Is.InRange(1.5f, 1.9f));
    }

    /// <summary>
    /// Not yet: from one end of the beam to the other (5.6 m) the frog hops down to the floor (3.1 m), across it in
    /// short hops and back up, though hops along the beam exist (<see cref="AHopAlongABeamIsOneJump"/>): samples are
    /// drawn by area, the 1.8 m² beam is under half a percent of this level's surfaces, and the bake stops at its
    /// first connection, which runs over the floor. (Tried: half of a focused corridor's samples drawn per contact
    /// surface, the beam as often as the floor: the first connection still ran over the floor.) This test fails once
    /// every hop lands on the beam: then make it assert that.
    /// </summary>
    [Test]
    public void NotYetABeamIsHoppedAlongFromEndToEnd()
    {
        PlanResult plan = Plan(Beam.Value, new Vector3(-2.8f, 1f, 0f), new Vector3(2.8f, 1f, 0f));
        bool onBeam = plan.Jumps.All(j => j.Landing.ContactCentre.Y > 0.9f && MathF.Abs(j.Landing.ContactCentre.Z) < 0.2f);
        Assert.That(onBeam, Is.False, "every hop lands on the beam now: assert it instead");
        Assert.That(plan.Jumps.Min(j => j.Landing.ContactCentre.Y), Is.LessThan(0.1f), "down to the floor, as measured");
    }

    [Test]
    public void AFlightTooHighForOneHopIsHoppedUpTreadByTread()
    {
        PlanResult plan = Plan(Stairs.Value, new Vector3(-1.5f, 0f, 0f), new Vector3(4f, 8 * Riser, 0f));
        Vector3[] treads = [.. plan.Jumps.Select(j => j.Landing.ContactCentre).Where(c => c.X is > 0f and < 8 * Tread)];
        Assert.That(treads, Is.Not.Empty, "a hop lands on a tread");
        Assert.That(plan.Jumps.Select(j => j.Landing.ContactCentre.Y - j.Takeoff.ContactCentre.Y), Has.All.LessThan(1.27f), "no hop climbs more than the frog's highest");

        // And from one tread to another four risers up: hops from tread to tread, none back down to the floor.
        PlanResult up = Plan(Stairs.Value, new Vector3(0.5f * Tread, Riser, 0f), new Vector3(4.5f * Tread, 5 * Riser, 0f));
        Assert.That(up.Jumps, Has.Count.InRange(1, 2));
        Assert.That(up.Jumps.Select(j => j.Landing.ContactCentre.Y), Has.All.GreaterThan(Riser));
    }
}
