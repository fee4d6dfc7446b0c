using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;
using Ballistic.Planner.Walking;

namespace Ballistic.Planner.Tests.Walking;

/// <summary>
/// A walk slows on stepped ground (stairs, rises steeper than the walker walks: <see cref="Walk.ClimbShare"/>) and
/// nowhere else: up a flight of 17 cm risers at about half its speed, at full speed on the floor before and the landing
/// after, on a ramp it walks, and over a crate it steps onto and off; and where the gait slows it to shorten its steps.
/// </summary>
public sealed class WalkPaceTests
{
    private const float Speed = 1.5f;

    /// <summary>The skeleton's steepest grade walked (tan 25°).</summary>
    private static readonly float MaxGrade = MathF.Tan(25f * MathF.PI / 180f);

    /// <summary>A walk along +X through <paramref name="path"/> (ground points), stances a metre above its ends.</summary>
    private static Walk Along(Vector3[] path, float maxGrade = float.PositiveInfinity)
    {
        var cone = new FrictionCone(Vector3.UnitY, 1f);
        Quaternion facing = Quaternion.CreateFromAxisAngle(Vector3.UnitY, MathF.PI / 2f);
        var from = new RoadmapNode(0, new RootPose(path[0] + Vector3.UnitY, facing), cone, []);
        var to = new RoadmapNode(1, new RootPose(path[^1] + Vector3.UnitY, facing), cone, []);
        return new Walk(from, to, path, Speed, maxGrade: maxGrade);
    }

    /// <summary>
    /// Ground points every 5 cm along +X: 3 m of floor, eight 17 cm risers 30 cm apart (sampled as a stair is, each
    /// riser a near-vertical segment), then 3 m of landing.
    /// </summary>
    private static Vector3[] Stairs()
    {
        var points = new List<Vector3>();
        for (float x = 0f; x <= 8.4f + 1e-4f; x += 0.05f)
        {
            int steps = x < 3f ? 0 : Math.Min(8, 1 + (int)MathF.Floor((x - 3f) / 0.3f + 1e-4f));
            points.Add(new Vector3(x, 0.17f * steps, 0f));
        }

        return [.. points];
    }

    /// <summary>The trunk's speed along the path where it is <paramref name="x"/> metres along X, m/s.</summary>
    private static float SpeedWhere(Walk walk, float x)
    {
        float distance = Enumerable.Range(0, 2001).Select(i => walk.Length * i / 2000f).MinBy(d => MathF.Abs(walk.PointAt(d).X - x));
        return walk.SpeedAt(walk.TimeAtDistance(distance));
    }

    [Test]
    public void AWalkUpAFlightOfStairsSlowsOnItAndNotOnTheFloorOrTheLanding()
    {
        Walk walk = Along(Stairs(), MaxGrade);
        Walk unpaced = Along(Stairs());
        Assert.Multiple(() =>
        {
            Assert.That(SpeedWhere(walk, 1.5f), Is.EqualTo(Speed).Within(1e-4f), "on the floor");
            Assert.That(SpeedWhere(walk, 6.5f), Is.EqualTo(Speed).Within(1e-4f), "on the landing");

            // Mid-flight it walks about half as fast, and over a metre of path there the trunk climbs at ClimbShare
            // of the walking speed.
            Assert.That(SpeedWhere(walk, 4.2f), Is.InRange(0.35f * Speed, 0.75f * Speed), "mid-flight");
            float middle = Enumerable.Range(0, 2001).Select(i => walk.Length * i / 2000f).MinBy(d => MathF.Abs(walk.PointAt(d).X - 4.2f));
            float climb = (walk.PointAt(middle + 0.5f).Y - walk.PointAt(middle - 0.5f).Y) / (walk.TimeAtDistance(middle + 0.5f) - walk.TimeAtDistance(middle - 0.5f));
            Assert.That(climb, Is.InRange(0.85f * Walk.ClimbShare * Speed, 1.05f * Walk.ClimbShare * Speed), "the climb rate mid-flight");

            // The trunk climbs the whole 1.36 m at about ClimbShare of the speed (a little faster at the flight's ends,
            // where the metre over which its steps are measured takes in some floor or landing).
            float start = walk.TimeAtDistance(Enumerable.Range(0, 2001).Select(i => walk.Length * i / 2000f).First(d => walk.PointAt(d).Y > 0f));
            float end = walk.TimeAtDistance(Enumerable.Range(0, 2001).Select(i => walk.Length * i / 2000f).First(d => walk.PointAt(d).Y >= 1.36f - 1e-4f));
            Assert.That(1.36f / (end - start), Is.InRange(0.85f * Walk.ClimbShare * Speed, 1.15f * Walk.ClimbShare * Speed), "the flight's climb rate");
            Assert.That(walk.Duration - unpaced.Duration, Is.GreaterThan(1f), "the flight takes longer than at full speed");

            // Distance and time stay each other's inverse, and the walk still ends where and when it says.
            foreach (float t in Enumerable.Range(1, 40).Select(i => walk.Duration * i / 41f))
            {
                Assert.That(walk.TimeAtDistance(walk.DistanceAt(t)), Is.EqualTo(t).Within(2e-3f), $"at {t} s");
            }

            Assert.That(walk.DistanceAt(walk.Duration), Is.EqualTo(walk.Length));
            Assert.That(walk.PoseAt(walk.Duration).Position, Is.EqualTo(walk.To.Pose.Position));
        });
    }

    /// <summary>
    /// The walk goes at the flight's pace from <see cref="Walk.ClimbLead"/> of its speed before the first riser (the
    /// leading foot is set down on the first tread while the trunk is still on the floor: before, that step was
    /// shortened for the flight and taken at full speed, 0.26-0.32 s where the steps on the floor take 0.42-0.44 s),
    /// and at full speed before that.
    /// </summary>
    [Test]
    public void AWalkUpAFlightOfStairsSlowsAQuarterStepBeforeItsFirstRiser()
    {
        Walk walk = Along(Stairs(), MaxGrade);
        float lead = Speed * Walk.ClimbLead;
        Assert.Multiple(() =>
        {
            Assert.That(SpeedWhere(walk, 3f - lead - 0.1f), Is.EqualTo(Speed).Within(1e-4f), "before the lead");
            Assert.That(SpeedWhere(walk, 3f - (0.5f * lead)), Is.LessThan(0.8f * Speed), "within the lead, the trunk still on the floor");
        });
    }

    [Test]
    public void AWalkNeverSlowsOnARampItWalksOnACrateItStepsOverOrWithoutAGrade()
    {
        // A 20° ramp (within the 25° walked), sampled every 5 cm.
        Vector3[] ramp = [.. Enumerable.Range(0, 121).Select(i => new Vector3(0.05f * i, MathF.Max(0f, (0.05f * i) - 2f) * MathF.Tan(20f * MathF.PI / 180f), 0f))];

        // A 15 cm crate 40 cm long stepped onto and off: no flight of stairs.
        Vector3[] crate = [.. Enumerable.Range(0, 121).Select(i => new Vector3(0.05f * i, 0.05f * i is > 2.95f and < 3.4f ? 0.15f : 0f, 0f))];
        Assert.Multiple(() =>
        {
            foreach ((string name, Walk walk) in new[] { ("ramp", Along(ramp, MaxGrade)), ("crate", Along(crate, MaxGrade)), ("stairs without a grade", Along(Stairs())) })
            {
                float expected = walk.StartTurn + (walk.Length / Speed) + Walk.RampTime + walk.EndTurn;
                Assert.That(walk.Duration, Is.EqualTo(expected).Within(1e-4f), name);
                Assert.That(Enumerable.Range(0, 100).Select(i => walk.PaceAt(walk.Length * i / 99f)), Has.All.EqualTo(1f), name);
            }
        });

        Assert.That(() => Along(ramp, -1f), Throws.ArgumentException.With.Message.Contains("grade"));
    }

    /// <summary>
    /// A walk the gait slows where it shortens its steps (<see cref="Walk.Slowed"/>) goes at that pace there and at full
    /// speed elsewhere, takes as much longer as the stretch walked slower, and keeps its stances, path and speed.
    /// </summary>
    [Test]
    public void AWalkSlowedForShorterStepsGoesAtThatPaceThereAndTakesLongerByAsMuch()
    {
        Vector3[] floor = [.. Enumerable.Range(0, 201).Select(i => new Vector3(0.05f * i, 0f, 0f))];
        Walk walk = Along(floor, MaxGrade);
        Walk slowed = walk.Slowed([(4f, 6f)], 0.5f);
        Assert.Multiple(() =>
        {
            Assert.That(slowed.PaceAt(5f), Is.EqualTo(0.5f).Within(1e-5f), "in the stretch");
            Assert.That(slowed.PaceAt(2f), Is.EqualTo(1f), "before it");
            Assert.That(slowed.PaceAt(8f), Is.EqualTo(1f), "after it");
            Assert.That(SpeedWhere(slowed, 5f), Is.EqualTo(0.5f * Speed).Within(1e-3f), "speed in the stretch");
            Assert.That(SpeedWhere(slowed, 2f), Is.EqualTo(Speed).Within(1e-3f), "speed before it");
            Assert.That(Enumerable.Range(0, 400).Select(i => slowed.SpeedAt(slowed.Duration * i / 399f)).Max(), Is.LessThanOrEqualTo(Speed), "never faster than its speed");

            // Two metres at half speed take 2 / 1.5 s more than at full speed.
            Assert.That(slowed.Duration - walk.Duration, Is.EqualTo(2f / Speed).Within(1e-3f), "the time it adds");
            Assert.That(slowed.SlowsForSteps, Is.False, "no steps slow it");
            Assert.That((slowed.From, slowed.To, slowed.Speed, slowed.Length), Is.EqualTo((walk.From, walk.To, walk.Speed, walk.Length)));
            Assert.That(slowed.Path, Is.EqualTo(walk.Path));
            Assert.That(slowed.PoseAt(slowed.Duration).Position, Is.EqualTo(walk.To.Pose.Position));
            foreach (float t in Enumerable.Range(1, 40).Select(i => slowed.Duration * i / 41f))
            {
                Assert.That(slowed.TimeAtDistance(slowed.DistanceAt(t)), Is.EqualTo(t).Within(2e-3f), $"at {t} s");
            }
        });
    }

    /// <summary>
    /// A walk between other records of its stances (the stances an animation stands on) keeps its path, pace, timing
    /// and poses, and refuses a stance at another root pose.
    /// </summary>
    [Test]
    public void AWalkBetweenOtherRecordsOfItsStancesKeepsItsTimingAndRefusesOtherPoses()
    {
        Vector3[] floor = [.. Enumerable.Range(0, 101).Select(i => new Vector3(0.05f * i, 0f, 0f))];
        Walk walk = Along(floor, MaxGrade).Slowed([(1f, 2f)], 0.5f);
        var contact = new Contact(0, floor[^1], Vector3.UnitY, 1f, 0);
        RoadmapNode to = walk.To with { Contacts = [contact] };
        Walk between = walk.Between(walk.From, to);
        Assert.Multiple(() =>
        {
            Assert.That(between.To, Is.SameAs(to));
            Assert.That(between.From, Is.SameAs(walk.From));
            Assert.That(walk.To.Contacts, Is.Empty, "the walk itself is unchanged");
            Assert.That((between.Duration, between.Length, between.PaceAt(1.5f)), Is.EqualTo((walk.Duration, walk.Length, walk.PaceAt(1.5f))));
            foreach (float t in Enumerable.Range(0, 20).Select(i => walk.Duration * i / 19f))
            {
                Assert.That(between.PoseAt(t), Is.EqualTo(walk.PoseAt(t)), $"at {t} s");
            }

            RoadmapNode moved = walk.To with { Pose = new RootPose(walk.To.Pose.Position + Vector3.UnitX, walk.To.Pose.Rotation) };
            Assert.That(() => walk.Between(walk.From, moved), Throws.ArgumentException);
        });
    }

    /// <summary>On a flight of stairs the gait's slowing comes on top of the flight's pace: shorter steps there too keep the cadence.</summary>
    [Test]
    public void OnAFlightTheGaitsSlowingComesOnTopOfTheFlightsPace()
    {
        Walk walk = Along(Stairs(), MaxGrade);
        float middle = Enumerable.Range(0, 2001).Select(i => walk.Length * i / 2000f).MinBy(d => MathF.Abs(walk.PointAt(d).X - 4.2f));
        Walk slowed = walk.Slowed([(middle - 0.3f, middle + 0.3f)], 0.85f);
        Assert.Multiple(() =>
        {
            Assert.That(walk.PaceAt(middle), Is.LessThan(0.8f), "the flight slows the walk");
            Assert.That(slowed.PaceAt(middle), Is.EqualTo(0.85f * walk.PaceAt(middle)).Within(1e-4f), "both slow it");
            Assert.That(slowed.SlowsForSteps, Is.True, "the steps slow it still");
        });
    }

    [Test]
    public void TheWalkingSteeringGivesItsWalksTheWalkersGrade()
    {
        (Level stairs, _) = ForeignLevels.Get("stairs");
        var scene = PlanningScene.Create(stairs, CharacterPresets.Skeleton());
        WalkResult up = scene.Walking.Steer(WalkSteeringTests.Stance(scene, new Vector3(0f, 0f, 0f), 0), WalkSteeringTests.Stance(scene, new Vector3(6.5f, 1.36f, 0f), 1));
        Assert.That(up.Walk, Is.Not.Null);
        Assert.That(up.Walk!.MaxGrade, Is.EqualTo(scene.Character.Walking.MaxGrade));
        Assert.That(Enumerable.Range(0, 200).Select(i => up.Walk.PaceAt(up.Walk.Length * i / 199f)).Min(), Is.LessThan(0.7f), "the flight slows it");
    }
}
