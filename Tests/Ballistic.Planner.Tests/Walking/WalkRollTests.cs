using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Walking;

/// <summary>
/// A walker whose legs sprawl out to its sides (a spider, an ant) walks with its trunk rolled at the ground's rise
/// across its way, over its feet's span (<see cref="WalkingLimits.RollSpan"/>, derived by
/// <see cref="ReducedModelBuilder.RollSpan"/>; <see cref="Walk.CrossGradeAt"/>), so that on a dune's side its downhill
/// feet reach the ground where they stand on the level instead of being drawn in under its body; a rig whose legs
/// stand under its hips keeps its trunk level across.
/// </summary>
public sealed class WalkRollTests
{
    private const float Span = 0.6f;

    /// <summary>Standing height (metres) of the trunk's centre above the ground point under its contacts.</summary>
    private const float Height = 0.3f;

    /// <summary>The ground of a side slope: rising <paramref name="grade"/> per metre toward −Z, level along X.</summary>
    private static float Ground(float grade, Vector3 p) => -p.Z * grade;

    /// <summary>
    /// A walk along +X from x = 0 to 4 over ground points every 5 cm at z = 0 of a side slope rising
    /// <paramref name="grade"/> per metre toward −Z (the walker's left), its stances <see cref="Height"/> above its
    /// ends facing +X upright, with the slope's cross grade at every point or none.
    /// </summary>
    private static Walk Across(float grade, bool rolls)
    {
        Vector3[] path = [.. Enumerable.Range(0, 81).Select(i => new Vector3(i * 0.05f, 0f, 0f))];
        var cone = new FrictionCone(Vector3.UnitY, 1f);
        Quaternion facing = Quaternion.CreateFromAxisAngle(Vector3.UnitY, MathF.PI / 2f);
        var from = new RoadmapNode(0, new RootPose(path[0] + new Vector3(0f, Height, 0f), facing), cone, []);
        var to = new RoadmapNode(1, new RootPose(path[^1] + new Vector3(0f, Height, 0f), facing), cone, []);
        return new Walk(from, to, path, 1f, pitchSpan: 0.3f, crossGrades: rolls ? [.. path.Select(_ => grade)] : null);
    }

    /// <summary>The trunk's left axis's angle above the horizontal, degrees (up to the left).</summary>
    private static float Roll(RootPose pose)
    {
        Vector3 left = Vector3.Transform(Vector3.UnitX, pose.Rotation);
        return MathF.Atan2(left.Y, new Vector2(left.X, left.Z).Length()) * 180f / MathF.PI;
    }

    [TestCase(20f)]
    [TestCase(-30f)]
    public void OnASideSlopeTheTrunkRollsAtItsGradeAndItsHipsStandAsHighAboveTheGroundAsOnTheLevel(float degrees)
    {
        float grade = MathF.Tan(degrees * MathF.PI / 180f);
        Walk walk = Across(grade, rolls: true);
        Walk level = Across(0f, rolls: true);
        RootPose pose = walk.PoseAtDistance(0.5f * walk.Length);
        RootPose flat = level.PoseAtDistance(0.5f * level.Length);
        Assert.Multiple(() =>
        {
            Assert.That(walk.CrossGradeAt(1.3f), Is.EqualTo(grade).Within(1e-6f));
            Assert.That(Roll(pose), Is.EqualTo(degrees).Within(0.01f), "the trunk's roll mid-walk");
            Assert.That(Roll(flat), Is.Zero.Within(1e-4f), "on the level");
            Vector3 forward = Vector3.Transform(Vector3.UnitZ, pose.Rotation);
            Assert.That(forward.Y, Is.Zero.Within(1e-5f), "the trunk rolls about its way: it does not pitch on a slope level along its way");

            // Hips out to either side at the feet's span, 5 cm under the trunk's centre: each stands as high above
            // the slope under it as on the level, but for the tilt of those 5 cm (0.05 / cos θ).
            foreach (float side in new[] { Span, -Span })
            {
                Vector3 hip = new(side, -0.05f, 0f);
                Vector3 onSlope = pose.Position + Vector3.Transform(hip, pose.Rotation);
                Vector3 onLevel = flat.Position + Vector3.Transform(hip, flat.Rotation);
                float tilt = 0.05f * ((1f / MathF.Cos(degrees * MathF.PI / 180f)) - 1f);
                Assert.That(onSlope.Y - Ground(grade, onSlope), Is.EqualTo(onLevel.Y - tilt).Within(1e-4f), $"the hip {side} m to the trunk's left above the ground under it");
            }
        });
    }

    [Test]
    public void WithoutCrossGradesTheTrunkWalksLevelAcrossTheSameSlope()
    {
        Walk walk = Across(MathF.Tan(20f * MathF.PI / 180f), rolls: false);
        Assert.That(walk.CrossGrades, Is.Empty);
        for (int i = 0; i <= 40; i++)
        {
            Assert.That(Roll(walk.PoseAtDistance(walk.Length * i / 40f)), Is.Zero.Within(1e-4f), $"at {i}/40 of the path");
        }
    }

    [Test]
    public void CrossGradesThatDoNotMatchThePathAreRefused()
    {
        Walk walk = Across(0.2f, rolls: true);
        Assert.Multiple(() =>
        {
            Assert.That(() => new Walk(walk.From, walk.To, walk.Path, 1f, crossGrades: [0f, 0.1f]), Throws.ArgumentException.With.Message.Contains("one finite value per path point (81), not 2"));
            Assert.That(() => new Walk(walk.From, walk.To, walk.Path, 1f, crossGrades: [.. walk.Path.Select(_ => float.NaN)]), Throws.ArgumentException.With.Message.Contains("not finite"));
        });
    }

    [TestCase(20f)]
    [TestCase(-20f)]
    public void ASpidersWalkAcrossASideSlopeIsSteeredWithTheSlopesCrossGradeAndItsTrunkClearsIt(float degrees)
    {
        // Eight metres of ground, level along X, rising toward −Z (tilted about X): the spider walks along X.
        float grade = MathF.Tan(degrees * MathF.PI / 180f);
        Level slope = new LevelBuilder("side slope").AddFloor(-4f, -4f, 4f, 4f, 0f, n: 8, toWorld: Matrix4x4.CreateRotationX(degrees * MathF.PI / 180f)).Build();
        (_, ReducedCharacter spider) = ForeignCharacters.Named("spider").Load();
        Assert.That(spider.Walking.RollSpan, Is.GreaterThan(0.5f), "the spider's feet stand 0.66 m out to either side");
        var scene = PlanningScene.Create(slope, spider);
        RoadmapNode from = WalkSteeringTests.Stance(scene, new Vector3(-1.5f, 0f, 0f), 0);
        RoadmapNode to = WalkSteeringTests.Stance(scene, new Vector3(1.5f, 0f, 0f), 1);
        Walk? walk = scene.Walking.Steer(from, to).Walk;
        Assert.That(walk, Is.Not.Null, scene.Walking.Steer(from, to).Failure.ToString());
        Assert.Multiple(() =>
        {
            // Walking toward +X, the walker's left is −Z: the slope rises toward its left by the grade.
            Assert.That(walk!.CrossGrades, Has.Count.EqualTo(walk.Path.Count));
            Assert.That(walk.CrossGrades, Has.All.EqualTo(grade).Within(1e-3f));
            Assert.That(Roll(walk.PoseAtDistance(0.5f * walk.Length)), Is.EqualTo(degrees).Within(0.1f));
            Assert.That(scene.Walking.TrunkIsFree(walk), Is.True);

            // The skeleton, whose feet stand under its hips, keeps its trunk level across the same slope.
            var upright = PlanningScene.Create(slope, CharacterPresets.Skeleton());
            Walk? level = upright.Walking.Steer(WalkSteeringTests.Stance(upright, new Vector3(-1.5f, 0f, 0f), 0), WalkSteeringTests.Stance(upright, new Vector3(1.5f, 0f, 0f), 1)).Walk;
            Assert.That(level, Is.Not.Null, "the skeleton walks 22.5° any way");
            Assert.That(level!.CrossGrades, Is.Empty);
        });
    }

    [Test]
    public void OnlyRigsWhoseLegsSprawlRollAndTheirSpanIsHalfTheirFeetsWidth()
    {
        var rigs = new List<(string Name, CharacterModel Model, WalkingLimits Walking)>
        {
            ("ant", CharacterPresets.Model("ant"), CharacterPresets.Get("ant").Walking),
            ("skeleton", CharacterPresets.Model("skeleton"), CharacterPresets.Get("skeleton").Walking),
        };
        foreach (string name in new[] { "spider", "dog", "tailed", "rat", "panda", "human" })
        {
            (CharacterModel model, ReducedCharacter reduced) = ForeignCharacters.Named(name).Load();
            rigs.Add((name, model, reduced.Walking));
        }

        Assert.Multiple(() =>
        {
            foreach ((string name, CharacterModel model, WalkingLimits walking) in rigs)
            {
                var positions = new Vector3[model.Rig.Joints.Count];
                var rotations = new Quaternion[model.Rig.Joints.Count];
                model.Rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), model.ContactPose, positions, rotations);
                float[] across = [.. model.Limbs.Where(l => l.Kind == LimbKind.Foot).Select(l => l.EffectorPosition(positions, rotations).X)];
                if (name is "ant" or "spider")
                {
                    Assert.That(walking.RollSpan, Is.EqualTo(0.5f * (across.Max() - across.Min())).Within(1e-4f), name);
                    Assert.That(walking.RollSpan, Is.GreaterThan(0.2f), name);
                }
                else
                {
                    Assert.That(walking.RollSpan, Is.Zero, $"the {name}'s legs stand under its hips");
                }
            }
        });
    }
}
