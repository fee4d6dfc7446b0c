using System.Globalization;
using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Walking;

/// <summary>
/// A walker whose feet stand ahead of and behind its trunk (a quadruped, a spider) walks with its trunk pitched at the
/// ground's grade over its feet's span (<see cref="Walk.PitchSpan"/>, derived by <see cref="ReducedModelBuilder.PitchSpan"/>),
/// so that up a ramp its front and hind hips stand as high above the ground under them as on the level; a biped
/// walks upright.
/// </summary>
public sealed class WalkPitchTests
{
    private const float Speed = 1.2f;
    private const float Span = 0.3f;

    /// <summary>Standing height (metres) of the trunk's centre above the ground point under its contacts.</summary>
    private const float Height = 0.5f;

    /// <summary>
    /// A walk along +X over ground points every 5 cm of <paramref name="ground"/> (height at x) from x = 0 to 4, its
    /// stances <see cref="Height"/> above its ends and <paramref name="behind"/> metres behind them, facing +X upright.
    /// </summary>
    private static Walk Along(Func<float, float> ground, float pitchSpan, float behind = 0f)
    {
        Vector3[] path = [.. Enumerable.Range(0, 81).Select(i => new Vector3(i * 0.05f, ground(i * 0.05f), 0f))];
        var cone = new FrictionCone(Vector3.UnitY, 1f);
        Quaternion facing = Quaternion.CreateFromAxisAngle(Vector3.UnitY, MathF.PI / 2f);
        Vector3 offset = new(-behind, Height, 0f);
        var from = new RoadmapNode(0, new RootPose(path[0] + offset, facing), cone, []);
        var to = new RoadmapNode(1, new RootPose(path[^1] + offset, facing), cone, []);
        return new Walk(from, to, path, Speed, pitchSpan: pitchSpan);
    }

    private static Func<float, float> Ramp(float degrees) => x => x * MathF.Tan(degrees * MathF.PI / 180f);

    /// <summary>The trunk's forward axis's angle above the horizontal, degrees.</summary>
    private static float Pitch(RootPose pose)
    {
        Vector3 forward = Vector3.Transform(Vector3.UnitZ, pose.Rotation);
        return MathF.Atan2(forward.Y, new Vector2(forward.X, forward.Z).Length()) * 180f / MathF.PI;
    }

    [TestCase(10f, 0f)]
    [TestCase(-15f, 0f)]
    [TestCase(10f, 0.2f)]
    public void OnARampTheTrunkPitchesAtItsGradeAndItsHipsStandAsHighAsOnTheLevel(float degrees, float behind)
    {
        Func<float, float> ground = Ramp(degrees);
        Walk walk = Along(ground, Span, behind);
        Walk level = Along(_ => 0f, Span, behind);
        float middle = 0.5f * walk.Length;
        RootPose pose = walk.PoseAtDistance(middle);
        RootPose flat = level.PoseAtDistance(0.5f * level.Length);
        Assert.Multiple(() =>
        {
            Assert.That(Pitch(pose), Is.EqualTo(degrees).Within(0.01f), "the trunk's pitch mid-ramp");
            Assert.That(Pitch(flat), Is.Zero, "on the level");

            // Hips at the feet's span ahead and behind, 5 cm under the trunk's centre: each stands as high above the
            // ramp under it as on the level, but for the tilt of those 5 cm (0.05 / cos θ: 1.8 mm at 15°).
            foreach (float along in new[] { Span, -Span })
            {
                Vector3 hip = new(0f, -0.05f, along);
                Vector3 onRamp = pose.Position + Vector3.Transform(hip, pose.Rotation);
                Vector3 onLevel = flat.Position + Vector3.Transform(hip, flat.Rotation);
                float tilt = 0.05f * ((1f / MathF.Cos(degrees * MathF.PI / 180f)) - 1f);
                Assert.That(onRamp.Y - ground(onRamp.X), Is.EqualTo(onLevel.Y - tilt).Within(1e-4f), $"the hip {along} m along the trunk above the ground under it");
            }
        });
    }

    [Test]
    public void ABipedWithNoSpanWalksUprightUpTheSameRamp()
    {
        Walk walk = Along(Ramp(10f), pitchSpan: 0f);
        for (int i = 0; i <= 40; i++)
        {
            Assert.That(Pitch(walk.PoseAtDistance(walk.Length * i / 40f)), Is.Zero, $"at {i}/40 of the path");
        }
    }

    [Test]
    public void OnTheLevelASpanChangesNoPose()
    {
        // The same to rounding (a path point between two at the same height may differ from them in the last bit).
        Walk pitched = Along(_ => 0.3f, Span, behind: 0.2f);
        Walk upright = Along(_ => 0.3f, pitchSpan: 0f, behind: 0.2f);
        Assert.That(pitched.Duration, Is.EqualTo(upright.Duration));
        for (int i = 0; i <= 200; i++)
        {
            float t = pitched.Duration * i / 200f;
            (RootPose a, RootPose b) = (pitched.PoseAt(t), upright.PoseAt(t));
            Assert.That(Vector3.Distance(a.Position, b.Position), Is.LessThan(1e-5f), $"the trunk's centre at {t} s");
            Assert.That(Rotations.AngleBetween(a.Rotation, b.Rotation), Is.LessThan(1e-5f), $"the trunk's rotation at {t} s");
        }
    }

    [TestCase(0f)]
    [TestCase(0.2f)]
    public void OverAHumpThePitchedTrunkMovesSmoothlyFromItsStanceAndBackToTheNext(float behind)
    {
        // Ground rising 12° for a metre and a half, level, then falling 8°: the stances upright at either end.
        Func<float, float> hump = x => x < 1.5f ? x * 0.2126f : x < 2.5f ? 0.3189f : 0.3189f - ((x - 2.5f) * 0.1405f);
        Walk walk = Along(hump, Span, behind);
        Assert.Multiple(() =>
        {
            Assert.That(walk.PoseAt(0f), Is.EqualTo(walk.From.Pose), "the first stance's pose");
            Assert.That(walk.PoseAt(walk.Duration), Is.EqualTo(walk.To.Pose), "the second stance's pose");
            Assert.That(walk.StartTurn, Is.GreaterThan(0f), "it pitches up as it sets off, as a turn in place does");

            // Sampled at 240 Hz: the trunk moves no faster than a little over its walking speed (its rise with the
            // ground included) and turns no faster than 60°/s, nowhere jumping.
            const float dt = 1f / 240f;
            RootPose previous = walk.PoseAt(0f);
            float fastest = 0f;
            float fastestTurn = 0f;
            for (float t = dt; t <= walk.Duration + 1e-6f; t += dt)
            {
                RootPose pose = walk.PoseAt(t);
                fastest = MathF.Max(fastest, Vector3.Distance(pose.Position, previous.Position) / dt);
                fastestTurn = MathF.Max(fastestTurn, Rotations.AngleBetween(pose.Rotation, previous.Rotation) * 180f / MathF.PI / dt);
                previous = pose;
            }

            Assert.That(fastest, Is.LessThan(1.3f * Speed), "the trunk's speed, m/s");
            Assert.That(fastestTurn, Is.LessThan(60f), "the trunk's turn rate, °/s");
            Assert.That(Pitch(walk.PoseAtDistance(0.75f)), Is.EqualTo(12f).Within(0.05f), "on the rise");
            Assert.That(Pitch(walk.PoseAtDistance(walk.Length - 0.7f)), Is.EqualTo(-8f).Within(0.05f), "on the fall");
        });
    }

    [Test]
    public void TheReadmeGivesTheDogsSpan()
    {
        string span = string.Create(CultureInfo.InvariantCulture, $"{ForeignCharacters.Dog().Load().Reduced.Walking.PitchSpan:0.00} m for the user's dog");
        string readme = string.Join(' ', File.ReadAllText(Path.Combine(RepositoryFiles.Root, "README.md")).Split((char[])[' ', '\n', '\r'], StringSplitOptions.RemoveEmptyEntries));
        Assert.That(readme.Contains(span, StringComparison.Ordinal), Is.True, $"the README says \"{span}\"");
    }

    [Test]
    public void BipedsWalkUprightAndRigsWithFeetAheadAndBehindPitch()
    {
        Assert.Multiple(() =>
        {
            foreach (string biped in new[] { "skeleton", "jumperman" })
            {
                Assert.That(CharacterPresets.Get(biped).Walking.PitchSpan, Is.Zero, biped);
            }

            Assert.That(ForeignCharacters.Human(zUpScene: false).Load().Reduced.Walking.PitchSpan, Is.Zero, "the user's human");

            // Half the distance between the foremost and hindmost feet, measured here from the contact pose.
            var rigs = new List<(string Name, CharacterModel Model, WalkingLimits Walking)> { ("ant", CharacterPresets.Model("ant"), CharacterPresets.Get("ant").Walking) };
            foreach (string name in new[] { "dog", "spider" })
            {
                (CharacterModel model, ReducedCharacter reduced) = ForeignCharacters.Named(name).Load();
                rigs.Add((name, model, reduced.Walking));
            }

            foreach ((string name, CharacterModel model, WalkingLimits walking) in rigs)
            {
                var positions = new Vector3[model.Rig.Joints.Count];
                var rotations = new Quaternion[model.Rig.Joints.Count];
                model.Rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), model.ContactPose, positions, rotations);
                float[] along = [.. model.Limbs.Where(l => l.Kind == LimbKind.Foot).Select(l => l.EffectorPosition(positions, rotations).Z)];
                Assert.That(walking.PitchSpan, Is.EqualTo(0.5f * (along.Max() - along.Min())).Within(1e-4f), name);
                Assert.That(walking.PitchSpan, Is.GreaterThan(0.1f), name);
            }
        });
    }
}
