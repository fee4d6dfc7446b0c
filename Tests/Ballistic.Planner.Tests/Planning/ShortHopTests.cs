using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Planning;

/// <summary>
/// The short hops a small jumper needs (issue 24's frog on a beam and on stair treads): a 1.7 m hop along a 0.3 m
/// beam is one jump between the placed stances, and end to end along the beam every hop lands on it; a
/// flight of eight 17.6 cm risers and 28 cm treads, 1.41 m high in all (above the frog's highest hop, 1.27 m at
/// 5 m/s), is hopped up tread by tread. Each plan's hops pass the physics checks.
/// </summary>
public sealed class ShortHopTests
{
    private const float Riser = 0.176f;
    private const float Tread = 0.28f;

    private static readonly Lazy<PlanningScene> Beam = new(() => BeamWith(b => b));

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
    /// From one end of the beam to the other (5.6 m) the frog hops along the beam, every hop landing on it, in three
    /// hops. Before, it hopped down to the floor (3.1 m), across it in short hops and back up, six hops in all: random
    /// samples are drawn by area, the 1.8 m² beam is under half a percent of this level's surfaces (4 of the first 82
    /// nodes, none between −2.8 and 1.9 m), and the bake stops at its first connection, which ran over the floor. Now
    /// the bake, once connected, adds the stances of the straight line from start to goal where it runs on open
    /// ground (<see cref="RoadmapBaker.LineStances"/>), and the hops along the beam cost less.
    /// </summary>
    [Test]
    public void ABeamIsHoppedAlongFromEndToEnd()
    {
        PlanResult plan = Plan(Beam.Value, new Vector3(-2.8f, 1f, 0f), new Vector3(2.8f, 1f, 0f));
        Assert.That(plan.Jumps.Select(j => j.Landing.ContactCentre), Has.All.Matches<Vector3>(c => c.Y > 0.9f && MathF.Abs(c.Z) < 0.2f), "every hop lands on the beam");
        Assert.That(plan.Jumps, Has.Count.InRange(3, 4), "hops of 1.4-1.9 m along 5.6 m of beam");
    }

    /// <summary>
    /// The straight line's stances (<see cref="RoadmapBaker.LineStances"/>): along the beam, one every neighbour cell
    /// of the frog, each on the beam and facing along it; none where the line does not run on open ground all along
    /// (a 0.4 m post standing on the beam's middle; the beam cut by a 0.4 m gap), and none on a line shorter than two cells.
    /// </summary>
    [Test]
    public void StancesAreAddedAlongAStraightLineOnlyWhereItRunsOnOpenGround()
    {
        var from = new Vector3(-2.8f, 1f, 0f);
        var to = new Vector3(2.8f, 1f, 0f);
        PoseEvaluation[] beam = LineStances(Beam.Value, from, to);
        Assert.That(beam, Has.Length.EqualTo(2), "5.6 m in spans of at most a cell");
        foreach (PoseEvaluation stance in beam)
        {
            Vector3 centre = Contact.Centre(stance.Contacts, stance.Pose.Position);
            Assert.That(centre.Y, Is.EqualTo(1f).Within(0.05f), "on the beam's top");
            Assert.That(MathF.Abs(centre.Z), Is.LessThan(0.15f), "on the beam");
            Assert.That(stance.Pose.Forward.X, Is.GreaterThan(0.95f), "facing along the line, toward the goal");
        }

        Assert.That(beam.Select(s => s.Pose.Position.X), Is.Ordered, "from start to goal");

        PlanningScene post = BeamWith(b => b.AddBox(new Vector3(-0.1f, 1f, -0.15f), new Vector3(0.1f, 1.4f, 0.15f)));
        Assert.That(LineStances(post, from, to), Is.Empty, "a post stands on the line");
        PlanningScene gap = PlanningScene.Create(new LevelBuilder("gap")
            .AddBox(new Vector3(-6f, 0f, -1.5f), new Vector3(-3f, 1f, 1.5f))
            .AddBox(new Vector3(3f, 0f, -1.5f), new Vector3(6f, 1f, 1.5f))
            .AddBox(new Vector3(-3f, 0.7f, -0.15f), new Vector3(-0.2f, 1f, 0.15f))
            .AddBox(new Vector3(0.2f, 0.7f, -0.15f), new Vector3(3f, 1f, 0.15f))
            .AddFloor(-10f, -10f, 10f, 10f, 0f)
            .Build(), CharacterPresets.Frog());
        Assert.That(LineStances(gap, from, to), Is.Empty, "a gap cuts the line");
        Assert.That(LineStances(Beam.Value, from, new Vector3(-1.5f, 1f, 0f)), Is.Empty, "1.3 m: under two cells");
    }

    /// <summary>
    /// From one platform's far side to the other's (10 m, the straight line off the beam's ends) the frog crosses on
    /// the beam, every hop landing on a platform or on the beam, never on the floor 1 m below. Before, it hopped down,
    /// across the floor and back up, 11 hops: no random sample had landed on the beam's middle. Now the bake, once
    /// connected, adds stances along the narrow surfaces that run the request's way (<see cref="RoadmapBaker.NarrowStances"/>).
    /// </summary>
    [Test]
    public void FromPlatformToPlatformTheFrogCrossesOnTheBeam()
    {
        PlanResult plan = Plan(Beam.Value, new Vector3(-5f, 1f, 0.5f), new Vector3(5f, 1f, -0.5f));
        Assert.That(plan.Jumps.Select(j => j.Landing.ContactCentre.Y), Has.All.GreaterThan(0.9f), "no hop lands on the floor");
        Assert.That(plan.Jumps.Select(j => j.Landing.ContactCentre), Has.Some.Matches<Vector3>(c => MathF.Abs(c.X) < 2f && MathF.Abs(c.Z) < 0.2f), "a hop lands on the beam's middle");
    }

    /// <summary>
    /// The narrow surfaces' stances (<see cref="RoadmapBaker.NarrowStances"/>): for a request along the beam's way, on
    /// the beam's top along its middle (and a span beyond its ends, on the platforms), facing the goal's way; none for a request across it (its long axis 90° off the way), and
    /// none on a beam a post stands on.
    /// </summary>
    [Test]
    public void StancesAreAddedAlongANarrowSurfaceThatRunsTheRequestsWay()
    {
        PoseEvaluation[] along = NarrowStances(Beam.Value, new Vector3(-5f, 1f, 0.5f), new Vector3(5f, 1f, -0.5f));
        Vector3[] centres = [.. along.Select(a => Contact.Centre(a.Contacts, a.Pose.Position))];
        Assert.That(centres.Count(c => MathF.Abs(c.X) < 3f), Is.GreaterThanOrEqualTo(3), "6 m of beam, a stance every cell or closer");
        Assert.That(centres.Count(c => MathF.Abs(c.X) >= 3f), Is.InRange(1, 2), "and one a span beyond an end, on a platform");
        Assert.Multiple(() =>
        {
            foreach ((Vector3 centre, PoseEvaluation stance) in centres.Zip(along))
            {
                Assert.That(centre.Y, Is.EqualTo(1f).Within(0.05f), "on the beam's or a platform's top");
                Assert.That(MathF.Abs(centre.Z), Is.LessThan(0.15f), "along the beam's middle");
                Assert.That(stance.Pose.Forward.X, Is.GreaterThan(0.9f), "facing the goal's way");
            }
        });

        Assert.That(NarrowStances(Beam.Value, new Vector3(0f, 0f, -4f), new Vector3(0f, 0f, 4f)), Is.Empty, "a request across the beam");
        PlanningScene post = BeamWith(b => b.AddBox(new Vector3(-0.1f, 1f, -0.15f), new Vector3(0.1f, 1.4f, 0.15f)));
        Assert.That(NarrowStances(post, new Vector3(-5f, 1f, 0.5f), new Vector3(5f, 1f, -0.5f)), Is.Empty, "a post stands on the beam");
    }

    /// <summary>The stances <see cref="RoadmapBaker.NarrowStances"/> adds for a request between the stances placed at <paramref name="from"/> and <paramref name="to"/> in <paramref name="scene"/>.</summary>
    private static PoseEvaluation[] NarrowStances(PlanningScene scene, Vector3 from, Vector3 to)
    {
        var settings = new BakeSettings { Start = from, Goal = to, StopWhenConnected = true };
        PoseEvaluation start = scene.Sampler.Place(from, settings.Tolerance).Pose!;
        PoseEvaluation goal = scene.Sampler.Place(to, settings.Tolerance).Pose!;
        return new RoadmapBaker(scene).NarrowStances(start, goal, settings);
    }

    /// <summary>The stances <see cref="RoadmapBaker.LineStances"/> adds between the stances placed at <paramref name="from"/> and <paramref name="to"/> in <paramref name="scene"/>.</summary>
    private static PoseEvaluation[] LineStances(PlanningScene scene, Vector3 from, Vector3 to)
    {
        var settings = new BakeSettings { Start = from, Goal = to, StopWhenConnected = true };
        PoseEvaluation start = scene.Sampler.Place(from, settings.Tolerance).Pose!;
        PoseEvaluation goal = scene.Sampler.Place(to, settings.Tolerance).Pose!;
        return new RoadmapBaker(scene).LineStances(start, goal, settings);
    }

    /// <summary>The beam level with something more built on it.</summary>
    private static PlanningScene BeamWith(Func<LevelBuilder, LevelBuilder> more) => PlanningScene.Create(more(new LevelBuilder("beam")
        .AddBox(new Vector3(-6f, 0f, -1.5f), new Vector3(-3f, 1f, 1.5f))
        .AddBox(new Vector3(3f, 0f, -1.5f), new Vector3(6f, 1f, 1.5f))
        .AddBox(new Vector3(-3f, 0.7f, -0.15f), new Vector3(3f, 1f, 0.15f))
        .AddFloor(-10f, -10f, 10f, 10f, 0f))
        .Build(), CharacterPresets.Frog());

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
