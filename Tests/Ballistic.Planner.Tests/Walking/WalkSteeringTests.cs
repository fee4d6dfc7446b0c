using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;
using Ballistic.Planner.Tests.Support;
using Ballistic.Planner.Walking;

namespace Ballistic.Planner.Tests.Walking;

/// <summary>The walking steering method on levels shaped as other tools make them: what it accepts, what it refuses and why.</summary>
public sealed class WalkSteeringTests
{
    private static readonly ReducedCharacter Skeleton = CharacterPresets.Skeleton();

    /// <summary>A stance placed at <paramref name="point"/> as a node (id <paramref name="id"/>).</summary>
    internal static RoadmapNode Stance(PlanningScene scene, Vector3 point, int id)
    {
        EndpointPlacement placement = scene.Sampler.Place(point, new EndpointTolerance());
        Assert.That(placement.Pose, Is.Not.Null, $"no stance at {point}: {placement.Failure("point", new EndpointTolerance())}");
        return new RoadmapNode(id, placement.Pose!.Pose, placement.Pose.Cone, placement.Pose.Contacts);
    }

    private static WalkResult Walk(Level level, Vector3 from, Vector3 to, ReducedCharacter? character = null)
    {
        var scene = PlanningScene.Create(level, character ?? Skeleton);
        return scene.Walking.Steer(Stance(scene, from, 0), Stance(scene, to, 1));
    }

    [Test]
    public void PresetsWalkAsTheirLegsSayAndTheFrogKeepsHopping()
    {
        Assert.Multiple(() =>
        {
            // A 0.95 m human leg: about 1.5 m/s and a 24 cm step; the ant is slower with a smaller step.
            Assert.That(Skeleton.Walking.Speed, Is.InRange(1.3f, 1.7f));
            Assert.That(Skeleton.Walking.StepHeight, Is.InRange(0.18f, 0.3f));
            Assert.That(CharacterPresets.Ant().Walking.Speed, Is.GreaterThan(0f).And.LessThan(Skeleton.Walking.Speed));
            Assert.That(CharacterPresets.Ant().Walking.StepHeight, Is.LessThan(Skeleton.Walking.StepHeight));
            Assert.That(CharacterPresets.Frog().Walking.CanWalk, Is.False, "the frog needs all four limbs down: it hops");
            Assert.That(CharacterPresets.Jumperman().Walking.CanWalk, Is.True);
        });
    }

    [Test]
    public void WalkingIsPartOfTheFingerprintOnlyForACharacterThatWalks()
    {
        ReducedCharacter frog = CharacterPresets.Frog();
        Assert.Multiple(() =>
        {
            Assert.That(frog.WithWalking(WalkingLimits.None).Fingerprint, Is.EqualTo(frog.Fingerprint));
            Assert.That(frog.WithWalking(new WalkingLimits(0.5f, 30f, 0.05f)).Fingerprint, Is.Not.EqualTo(frog.Fingerprint));
            Assert.That(Skeleton.WithWalking(Skeleton.Walking with { Speed = 1f }).Fingerprint, Is.Not.EqualTo(Skeleton.Fingerprint));
            Assert.That(() => Skeleton.WithWalking(new WalkingLimits(1f, 85f, 0.2f)), Throws.InstanceOf<CharacterException>().With.Message.Contains("80 degrees"));
            Assert.That(() => Skeleton.WithWalking(new WalkingLimits(1f, 30f, 0f)), Throws.InstanceOf<CharacterException>().With.Message.Contains("step height"));
            Assert.That(Skeleton.WithWalking(Skeleton.Walking with { MaxSlopeAlongDegrees = 30f }).Fingerprint, Is.Not.EqualTo(Skeleton.Fingerprint));
            Assert.That(frog.WithWalking(new WalkingLimits(0.5f, 30f, 0.05f) { MaxSlopeAlongDegrees = 30f }).Fingerprint, Is.EqualTo(frog.WithWalking(new WalkingLimits(0.5f, 30f, 0.05f)).Fingerprint), "the same limit every way, set or not");
            Assert.That(() => Skeleton.WithWalking(new WalkingLimits(1f, 30f, 0.2f) { MaxSlopeAlongDegrees = 20f }), Throws.InstanceOf<CharacterException>().With.Message.Contains("walked up or down"));
        });
    }

    [Test]
    public void OnFlatGroundTheWalkFollowsTheGroundAndTheTrunkStartsAndEndsOnTheStances()
    {
        var scene = PlanningScene.Create(GapCourse.Build(), Skeleton);
        RoadmapNode a = Stance(scene, new Vector3(-7f, 0f, -1f), 0);
        RoadmapNode b = Stance(scene, new Vector3(-3.6f, 0f, 1.2f), 1);
        WalkResult result = scene.Walking.Steer(a, b);
        Assert.That(result.Failure, Is.EqualTo(WalkFailure.None));
        Walk walk = result.Walk!;
        Assert.Multiple(() =>
        {
            Assert.That(walk.Path.Zip(walk.Path.Skip(1)).Select(p => Vector3.Distance(p.First, p.Second)), Has.All.LessThanOrEqualTo(WalkSteering.PathSpacing + 1e-4f));
            Assert.That(walk.Path.Select(p => p.Y), Has.All.EqualTo(0f).Within(1e-4f), "the platform's top is at y = 0");
            Assert.That(walk.WalkTime, Is.EqualTo((walk.Length / Skeleton.Walking.Speed) + global::Ballistic.Planner.Roadmaps.Walk.RampTime).Within(1e-5f), "at full speed but for speeding up and slowing down");
            Assert.That(walk.Duration, Is.EqualTo(walk.StartTurn + walk.WalkTime + walk.EndTurn).Within(1e-5f));
            Assert.That(walk.Length, Is.GreaterThan(3.4f));
            Assert.That(walk.PoseAt(0f), Is.EqualTo(a.Pose));
            Assert.That(walk.PoseAt(walk.Duration), Is.EqualTo(b.Pose));
            Assert.That(walk.PoseAt(-1f), Is.EqualTo(a.Pose), "clamped before the start");
        });

        // In between: upright-ish, facing the way it walks, at the stances' height, at constant ground speed.
        Vector3 heading = Vector3.Normalize(new Vector3(walk.Path[^1].X - walk.Path[0].X, 0f, walk.Path[^1].Z - walk.Path[0].Z));
        RootPose middle = walk.PoseAt(walk.Duration / 2f);
        Assert.Multiple(() =>
        {
            Assert.That(Vector3.Dot(middle.Forward, heading), Is.GreaterThan(0.99f));
            Assert.That(middle.Up.Y, Is.GreaterThan(0.99f));
            Assert.That(middle.Position.Y, Is.InRange(MathF.Min(a.Pose.Position.Y, b.Pose.Position.Y) - 1e-3f, MathF.Max(a.Pose.Position.Y, b.Pose.Position.Y) + 1e-3f));
            float cruising = walk.StartTurn + global::Ballistic.Planner.Roadmaps.Walk.RampTime;
            Assert.That(walk.DistanceAt(cruising + 1f) - walk.DistanceAt(cruising), Is.EqualTo(Skeleton.Walking.Speed).Within(1e-4f), "one second at full speed");
        });
    }

    [Test]
    public void ARememberedWalkIsTheWalkSteeredAnewOnTheStancesAsked()
    {
        var scene = PlanningScene.Create(GapCourse.Build(), Skeleton);
        var fresh = PlanningScene.Create(GapCourse.Build(), Skeleton);
        var random = new Random(5);
        var stances = new List<RoadmapNode>();
        while (stances.Count < 14)
        {
            // Points over the platforms and the gaps between them: those with a stance within the tolerance are taken.
            EndpointPlacement placed = scene.Sampler.Place(new Vector3(Range(random, -7.5f, 12f), 0f, Range(random, -1.5f, 1.5f)), new EndpointTolerance());
            if (placed.Pose is { } pose)
            {
                stances.Add(new RoadmapNode(stances.Count, pose.Pose, pose.Cone, pose.Contacts));
            }
        }

        var failures = new HashSet<WalkFailure>();
        int walked = 0;
        foreach (RoadmapNode a in stances)
        {
            foreach (RoadmapNode b in stances.Where(b => b != a))
            {
                foreach (float limit in new[] { float.PositiveInfinity, 4f })
                {
                    WalkResult expected = fresh.Walking.Steer(a, b, limit);
                    foreach (RoadmapNode from in new[] { a, a with { Id = a.Id + 100 } })
                    {
                        // Asked twice, the second time for stances of the same poses under other ids: the walk is made on those.
                        WalkResult remembered = scene.Walking.SteerRemembered(from, b, limit);
                        string pair = $"{a.Id} -> {b.Id} (as {from.Id}), limit {limit}";
                        Assert.That(remembered.Failure, Is.EqualTo(expected.Failure), pair);
                        Assert.That(remembered.Walk is null, Is.EqualTo(expected.Walk is null), pair);
                        if (remembered.Walk is { } walk)
                        {
                            Assert.That(walk.From, Is.SameAs(from), pair);
                            Assert.That(walk.To, Is.SameAs(b), pair);
                            Assert.That(walk.Path, Is.EqualTo(expected.Walk!.Path), pair);
                            Assert.That(walk.Duration, Is.EqualTo(expected.Walk.Duration), pair);
                            Assert.That(walk.PoseAt(0.37f * walk.Duration), Is.EqualTo(expected.Walk.PoseAt(0.37f * walk.Duration)), pair);
                        }
                    }

                    walked += expected.Walk is null ? 0 : 1;
                    failures.Add(expected.Failure);
                }
            }
        }

        Assert.That(walked, Is.GreaterThan(20), "walks found");
        Assert.That(failures, Is.SupersetOf(new[] { WalkFailure.None, WalkFailure.TooFar }), "and refused, for the same reasons");
        Assert.That(failures.Count, Is.GreaterThanOrEqualTo(3), string.Join(", ", failures));
    }

    private static float Range(Random random, float min, float max) => min + ((float)random.NextDouble() * (max - min));

    /// <summary>Two upright stances 3.7 m apart on the gap course's first platform and the walk steered between them.</summary>
    private static (PlanningScene Scene, RoadmapNode A, RoadmapNode B, Walk Walk) TwoStancesOnTheGapCourse()
    {
        var scene = PlanningScene.Create(GapCourse.Build(), Skeleton);
        RoadmapNode a = Stance(scene, new Vector3(-7f, 0f, -1f), 0);
        RoadmapNode b = Stance(scene, new Vector3(-3.6f, 0f, 1.2f), 1);
        return (scene, a, b, scene.Walking.Steer(a, b).Walk!);
    }

    /// <summary>
    /// A stance facing the walk's way does not turn in place, though its rotation (a quarter turn about +Y) is no unit
    /// quaternion in single precision: a 6 cm walk along +X between two such stances took 1.08 s, two 0.4 s turns of
    /// nothing, where the angle between a rotation and itself read 7·10⁻⁴ rad from the rounded cosine of their dot
    /// product. Within 0.03° is no turn either; a degree off is.
    /// </summary>
    [Test]
    public void AStanceFacingTheWalksWayDoesNotTurnInPlace()
    {
        (_, RoadmapNode a, RoadmapNode b, Walk walk) = TwoStancesOnTheGapCourse();
        Vector3 start = walk.Path[0];
        Vector3[] path = [start, start + new Vector3(0.06f, 0f, 0f)];
        RoadmapNode Facing(RoadmapNode node, Vector3 at, float yaw) => node with { Pose = new RootPose(at + (a.Pose.Position - start), Quaternion.CreateFromAxisAngle(Vector3.UnitY, yaw)) };
        Walk Between(float startYaw, float endYaw) => new(Facing(a, path[0], startYaw), Facing(b, path[1], endYaw), path, walk.Speed, turnRate: walk.TurnRate);
        float east = MathF.PI / 2f;
        Walk straight = Between(east, east);
        Walk nearly = Between(east + 5e-4f, east - 5e-4f);
        Walk off = Between(east + (MathF.PI / 180f), east);
        Assert.Multiple(() =>
        {
            Assert.That(straight.StartTurn + straight.EndTurn, Is.Zero, "facing the walk's way: no turn in place");
            Assert.That(straight.Duration, Is.LessThan(0.4f), "6 cm walked in well under a turn's time");
            Assert.That(nearly.StartTurn + nearly.EndTurn, Is.Zero, "0.03° off: no turn in place");
            Assert.That(off.StartTurn, Is.EqualTo(global::Ballistic.Planner.Roadmaps.Walk.MinTurnTime), "a degree off is turned");
        });
    }

    [Test]
    public void AStanceLeaningWithASlopeStandsUpOverItsContactsAsItTurnsToWalk()
    {
        // A stance whose trunk leans 20° sideways (as stances on a dune face are sampled): its trunk centre stands
        // about 0.4 m to the side of its contacts. The walking trunk is upright over them, not beside them (its feet
        // would cross under it), and it gets there while it turns in place, without a jump in its path.
        (_, RoadmapNode a, RoadmapNode b, Walk upright) = TwoStancesOnTheGapCourse();
        Vector3 centre = upright.Path[0];
        Quaternion lean = Quaternion.CreateFromAxisAngle(a.Pose.Forward, 20f * MathF.PI / 180f);
        RoadmapNode leaning = a with { Pose = new RootPose(centre + Vector3.Transform(a.Pose.Position - centre, lean), Quaternion.Normalize(lean * a.Pose.Rotation)) };
        var walk = new Walk(leaning, b, upright.Path, upright.Speed, turnRate: upright.TurnRate);
        static float Across(Vector3 v) => new Vector2(v.X, v.Z).Length();
        RootPose set = walk.PoseAt(walk.StartTurn);
        Assert.Multiple(() =>
        {
            Assert.That(Across(leaning.Pose.Position - centre), Is.GreaterThan(0.3f), "the leaning trunk stands beside its contacts");
            Assert.That(walk.PoseAt(0f), Is.EqualTo(leaning.Pose));
            Assert.That(set.Up.Y, Is.GreaterThan(0.9999f), "upright when it sets off");
            Assert.That(Across(set.Position - centre), Is.LessThanOrEqualTo(Across(a.Pose.Position - centre) + 1e-3f), "over its contacts as the upright stance is");
            Assert.That(set.Position.Y, Is.EqualTo(leaning.Pose.Position.Y).Within(1e-4f), "at the stance's height");
            Assert.That(walk.TurnTravel, Is.GreaterThanOrEqualTo(Across(leaning.Pose.Position - set.Position) - 1e-4f), "the trunk-collision check allows for the move");
            for (int k = 1; k <= 100; k++)
            {
                float t = walk.StartTurn * k / 100f;
                Assert.That(Vector3.Distance(walk.PoseAt(t).Position, walk.PoseAt(t - (walk.StartTurn / 100f)).Position), Is.LessThan(0.02f), $"no jump in the trunk's path at {t:0.00} s");
            }
        });
    }

    [Test]
    public void TheTrunkTurnsInPlaceThenSpeedsUpFromRestAndSlowsDownToRest()
    {
        (PlanningScene scene, RoadmapNode a, _, Walk walk) = TwoStancesOnTheGapCourse();
        Vector3 h = Vector3.Normalize(new Vector3(walk.Path[^1].X - walk.Path[0].X, 0f, walk.Path[^1].Z - walk.Path[0].Z));
        float turn = 2f * MathF.Acos(Math.Clamp(MathF.Abs(Quaternion.Dot(a.Pose.Rotation, Quaternion.CreateFromAxisAngle(Vector3.UnitY, MathF.Atan2(h.X, h.Z)))), 0f, 1f));
        float speed = Skeleton.Walking.Speed;
        Assert.Multiple(() =>
        {
            Assert.That(walk.StartTurn, Is.EqualTo(MathF.Max(turn / Skeleton.Walking.TurnRate, global::Ballistic.Planner.Roadmaps.Walk.MinTurnTime)).Within(0.02f), "the start turn takes its angle at the turn rate");
            Assert.That(walk.PoseAt(0.5f * walk.StartTurn).Position, Is.EqualTo(a.Pose.Position), "turning in place");
            Assert.That(Vector3.Dot(walk.PoseAt(walk.StartTurn).Forward, h), Is.GreaterThan(0.99f), "facing the way it walks when it sets off");
            Assert.That(walk.SpeedAt(0.5f * walk.StartTurn), Is.Zero);
            Assert.That(walk.SpeedAt(walk.StartTurn + (0.5f * global::Ballistic.Planner.Roadmaps.Walk.RampTime)), Is.EqualTo(0.5f * speed).Within(1e-4f), "half speed halfway up the ramp");
            Assert.That(walk.SpeedAt(walk.StartTurn + (0.5f * walk.WalkTime)), Is.EqualTo(speed).Within(1e-5f));
            Assert.That(walk.SpeedAt(walk.StartTurn + walk.WalkTime - (0.25f * global::Ballistic.Planner.Roadmaps.Walk.RampTime)), Is.EqualTo(0.25f * speed).Within(1e-4f), "slowing down");
            Assert.That(walk.DistanceAt(walk.StartTurn + walk.WalkTime), Is.EqualTo(walk.Length));
        });

        // The distance is the integral of the speed, which never exceeds the walking speed.
        float travelled = 0f;
        const float dt = 1e-3f;
        for (float t = 0f; t < walk.Duration; t += dt)
        {
            Assert.That(walk.SpeedAt(t), Is.LessThanOrEqualTo(speed + 1e-5f));
            travelled += 0.5f * (walk.SpeedAt(t) + walk.SpeedAt(t + dt)) * dt;
        }

        Assert.That(travelled, Is.EqualTo(walk.Length).Within(0.01f));

        // A walk shorter than the ramps never reaches full speed, and still ends at rest on the stance.
        RoadmapNode c = Stance(scene, new Vector3(-6.7f, 0f, -1f), 1);
        Walk shortWalk = scene.Walking.Steer(a, c).Walk!;
        Assert.That(Enumerable.Range(0, 101).Select(k => shortWalk.SpeedAt(shortWalk.Duration * k / 100f)), Has.All.LessThan(speed));
        Assert.That(shortWalk.PoseAt(shortWalk.Duration), Is.EqualTo(c.Pose));
    }

    [Test]
    public void AGapALowWallAndAStepTooHighAreRefusedWithTheirReasons()
    {
        Level course = GapCourse.Build();
        Assert.Multiple(() =>
        {
            Assert.That(Walk(course, new Vector3(-4f, 0f, 0f), new Vector3(-1f, 0f, 0f)).Failure, Is.EqualTo(WalkFailure.Gap), "1.5 m gap between the first two platforms");
            Assert.That(Walk(course, new Vector3(4.5f, 0f, 0f), new Vector3(6.5f, 0f, 0f)).Failure, Is.EqualTo(WalkFailure.StepTooHigh), "a 0.5 m wall across the third platform");
            Assert.That(Walk(course, new Vector3(7.5f, 0f, 0f), new Vector3(10.2f, 1f, 0f)).Failure, Is.Not.EqualTo(WalkFailure.None), "a 1 m rise and a gap to the last platform");
        });
    }

    [Test]
    public void StairsOfAnotherToolAreWalkedAndAStairTooHighIsNot()
    {
        (Level stairs, _) = ForeignLevels.Get("stairs"); // 0.17 m risers, below the skeleton's 0.24 m step
        WalkResult up = Walk(stairs, new Vector3(0f, 0f, 0f), new Vector3(6.5f, 1.36f, 0f));
        Assert.That(up.Failure, Is.EqualTo(WalkFailure.None));
        float[] heights = [.. up.Walk!.Path.Select(p => p.Y)];
        Assert.That(heights.Zip(heights.Skip(1)).Select(h => MathF.Abs(h.Second - h.First)), Has.All.LessThanOrEqualTo(0.17f + 1e-3f));

        ReducedCharacter shortStep = Skeleton.WithWalking(Skeleton.Walking with { StepHeight = 0.1f });
        Assert.That(Walk(stairs, new Vector3(0f, 0f, 0f), new Vector3(6.5f, 1.36f, 0f), shortStep).Failure, Is.EqualTo(WalkFailure.StepTooHigh));
    }

    /// <summary>A floor up to x = 0, a 3 m ramp of <paramref name="degrees"/> rising along +X (4 m wide, z from −2 to 2), and a floor on top.</summary>
    private static Level Ramp(float degrees)
    {
        float rise = 3f * MathF.Tan(degrees * MathF.PI / 180f);
        var material = new LevelMaterial("ramp", null);
        return new LevelBuilder($"ramp {degrees}°")
            .AddBox(new Vector3(-4f, -1f, -2f), new Vector3(0f, 0f, 2f))
            .AddTriangle(new Triangle(new Vector3(0f, 0f, -2f), new Vector3(0f, 0f, 2f), new Vector3(3f, rise, 2f)), material)
            .AddTriangle(new Triangle(new Vector3(0f, 0f, -2f), new Vector3(3f, rise, 2f), new Vector3(3f, rise, -2f)), material)
            .AddBox(new Vector3(3f, rise - 1f, -2f), new Vector3(7f, rise, 2f))
            .Build();
    }

    [Test]
    public void ASlopeIsWalkedStraightUpOrDownSteeperThanAcross()
    {
        // The skeleton walks 22.5° whichever way the ground falls and 25° straight up or down: a 24° ramp is walked up
        // and down its fall line and diagonally (it falls 17.5° across a heading 45° off its fall line), not across it;
        // a 30° ramp is walked no way.
        Assert.That(Skeleton.Walking.MaxSlopeDegrees, Is.EqualTo(22.5f));
        Assert.That(Skeleton.Walking.MaxSlopeAlongDegrees, Is.EqualTo(25f));
        float rise = 3f * MathF.Tan(24f * MathF.PI / 180f);
        WalkSteering ramp = PlanningScene.Create(Ramp(24f), Skeleton).Walking;
        WalkSteering steep = PlanningScene.Create(Ramp(30f), Skeleton).Walking;
        Assert.Multiple(() =>
        {
            Assert.That(ramp.WalkableDistance(new Vector3(-1f, 0f, 0f), new Vector3(4f, rise, 0f)), Is.EqualTo(5f).Within(1e-3f), "up the fall line");
            Assert.That(ramp.WalkableDistance(new Vector3(4f, rise, 0.5f), new Vector3(-1f, 0f, 0.5f)), Is.EqualTo(5f).Within(1e-3f), "down it");
            Assert.That(ramp.WalkableDistance(new Vector3(1.5f, rise / 2f, -1.8f), new Vector3(1.5f, rise / 2f, 1.8f)), Is.LessThan(0.1f), "across it");
            Assert.That(ramp.WalkableDistance(new Vector3(0.5f, rise / 6f, -1.5f), new Vector3(2.5f, 5f * rise / 6f, 0.5f)), Is.EqualTo(2f * MathF.Sqrt(2f)).Within(1e-3f), "diagonally");
            Assert.That(steep.WalkableDistance(new Vector3(-1f, 0f, 0f), new Vector3(4f, 3f * MathF.Tan(30f * MathF.PI / 180f), 0f)), Is.InRange(1f - (3f * WalkSteering.SampleSpacing), 1f + WalkSteering.SampleSpacing), "a 30° ramp stops the walk where it begins");
        });

        // The rule itself: a normal 24° from vertical, falling ahead, to the side, and 45° between.
        float a = 24f * MathF.PI / 180f;
        var ahead = new Vector3(MathF.Sin(a), MathF.Cos(a), 0f);
        var side = new Vector3(0f, MathF.Cos(a), MathF.Sin(a));
        var diagonal = new Vector3(MathF.Sin(a) * MathF.Sqrt(0.5f), MathF.Cos(a), MathF.Sin(a) * MathF.Sqrt(0.5f));
        WalkingLimits limits = Skeleton.Walking;
        Assert.Multiple(() =>
        {
            Assert.That(limits.IsWalkable(ahead, Vector3.UnitX), Is.True);
            Assert.That(limits.IsWalkable(-ahead with { Y = ahead.Y }, Vector3.UnitX), Is.True, "downhill");
            Assert.That(limits.IsWalkable(side, Vector3.UnitX), Is.False);
            Assert.That(limits.IsWalkable(diagonal, Vector3.UnitX), Is.True);
            Assert.That(limits.IsWalkable(ahead, Vector3.Zero), Is.False, "no heading: the any-way limit");
            Assert.That(limits.IsWalkable(Vector3.Normalize(new Vector3(0.3f, 1f, 0f)), Vector3.Zero), Is.True, "16.7° any way");
            Assert.That(limits.IsWalkable(-ahead, Vector3.UnitX), Is.True, "either side of a surface");
        });
    }

    [Test]
    public void ASlopeSteeperThanTheLimitIsRefusedAndAGentleOneIsWalked()
    {
        Level gentle = Ramp(15f);
        Level steep = Ramp(50f);
        Assert.Multiple(() =>
        {
            Assert.That(Walk(gentle, new Vector3(-2f, 0f, 0f), new Vector3(5f, 3f * MathF.Tan(15f * MathF.PI / 180f), 0f)).Failure, Is.EqualTo(WalkFailure.None));
            Assert.That(Walk(steep, new Vector3(-2f, 0f, 0f), new Vector3(5f, 3f * MathF.Tan(50f * MathF.PI / 180f), 0f)).Failure, Is.EqualTo(WalkFailure.TooSteep));
        });
    }

    [Test]
    public void TheWalkableDistanceEndsWhereTheGroundFailsAndRunsAllTheWayOnFlatGround()
    {
        // A floor up to x = 0, then a 1.5 m gap; another floor up to x = 0, then a 50° ramp.
        var material = new LevelMaterial("ramp", null);
        float rise = 2f * MathF.Tan(50f * MathF.PI / 180f);
        Level gap = new LevelBuilder("gap").AddBox(new Vector3(-5f, -1f, -2f), new Vector3(0f, 0f, 2f)).AddBox(new Vector3(1.5f, -1f, -2f), new Vector3(5f, 0f, 2f)).Build();
        Level ramp = new LevelBuilder("ramp")
            .AddBox(new Vector3(-5f, -1f, -2f), new Vector3(0f, 0f, 2f))
            .AddTriangle(new Triangle(new Vector3(0f, 0f, -2f), new Vector3(0f, 0f, 2f), new Vector3(2f, rise, 2f)), material)
            .AddTriangle(new Triangle(new Vector3(0f, 0f, -2f), new Vector3(2f, rise, 2f), new Vector3(2f, rise, -2f)), material)
            .Build();
        WalkSteering overGap = PlanningScene.Create(gap, Skeleton).Walking;
        WalkSteering upRamp = PlanningScene.Create(ramp, Skeleton).Walking;
        var ground = new List<Vector3>();
        Assert.Multiple(() =>
        {
            Assert.That(overGap.WalkableDistance(new Vector3(-3f, 0f, 0f), new Vector3(3f, 0f, 0f), ground), Is.InRange(3f - (2f * WalkSteering.SampleSpacing), 3f));
            Assert.That(ground[0].X, Is.EqualTo(-3f).Within(1e-4f));
            Assert.That(ground.Zip(ground.Skip(1)).Select(p => Vector3.Distance(p.First, p.Second)), Has.All.LessThanOrEqualTo(WalkSteering.PathSpacing + 1e-4f));
            Assert.That(ground.Select(p => p.X), Has.All.LessThanOrEqualTo(0f), "ground points stop at the edge");
            Assert.That(upRamp.WalkableDistance(new Vector3(-2f, 0f, 0f), new Vector3(2f, rise, 0f)), Is.InRange(2f - (3f * WalkSteering.SampleSpacing), 2f + WalkSteering.SampleSpacing));
            Assert.That(overGap.WalkableDistance(new Vector3(-4f, 0f, 1f), new Vector3(-1f, 0f, -1f)), Is.EqualTo(MathF.Sqrt(13f)).Within(1e-4f), "flat all the way");
            Assert.That(PlanningScene.Create(gap, CharacterPresets.Frog()).Walking.WalkableDistance(new Vector3(-3f, 0f, 0f), new Vector3(-1f, 0f, 0f)), Is.Zero, "the frog does not walk");
        });
    }

    [Test]
    public void AnObstacleUnderTheTrunkOrALowCeilingStopsTheWalk()
    {
        Level Floor(Func<LevelBuilder, LevelBuilder> add) => add(new LevelBuilder("floor").AddBox(new Vector3(-5f, -1f, -3f), new Vector3(5f, 0f, 3f))).Build();

        // A 40 cm crate: not ground a leg can step on (above the step height), and below the trunk.
        Level crate = Floor(b => b.AddBox(new Vector3(-0.2f, 0f, -0.5f), new Vector3(0.2f, 0.4f, 0.5f)));

        // A beam at chest height: the ground is fine, the trunk is not.
        float chest = PlanningScene.Create(Floor(b => b), Skeleton).Character.StanceLift.Min;
        Level beam = Floor(b => b.AddBox(new Vector3(-0.2f, chest - 0.1f, -3f), new Vector3(0.2f, chest + 0.1f, 3f)));
        Assert.Multiple(() =>
        {
            Assert.That(Walk(crate, new Vector3(-3f, 0f, 0f), new Vector3(3f, 0f, 0f)).Failure, Is.EqualTo(WalkFailure.StepTooHigh));
            Assert.That(Walk(crate, new Vector3(-3f, 0f, 1.5f), new Vector3(3f, 0f, 1.5f)).Failure, Is.EqualTo(WalkFailure.None), "beside the crate");
            Assert.That(Walk(beam, new Vector3(-3f, 0f, 0f), new Vector3(3f, 0f, 0f)).Failure, Is.EqualTo(WalkFailure.TrunkCollides));
        });
    }

    [Test]
    public void ACharacterThatDoesNotWalkAndAWalkTooFarAreRefused()
    {
        var frogScene = PlanningScene.Create(GapCourse.Build(), CharacterPresets.Frog());
        RoadmapNode a = Stance(frogScene, new Vector3(-7f, 0f, 0f), 0);
        RoadmapNode b = Stance(frogScene, new Vector3(-4f, 0f, 0f), 1);
        var scene = PlanningScene.Create(GapCourse.Build(), Skeleton);
        Assert.Multiple(() =>
        {
            Assert.That(frogScene.Walking.Steer(a, b).Failure, Is.EqualTo(WalkFailure.NotWalking));
            Assert.That(scene.Walking.Steer(Stance(scene, new Vector3(-7f, 0f, 0f), 0), Stance(scene, new Vector3(-4f, 0f, 0f), 1), maxDistance: 2f).Failure, Is.EqualTo(WalkFailure.TooFar));
        });
    }
}
