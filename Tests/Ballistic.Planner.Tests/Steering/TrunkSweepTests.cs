using System.Numerics;
using Ballistic.Authoring.Levels;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Steering;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Steering;

/// <summary>
/// The trunk sweep tests runs of steps in one box before testing them one by one: its verdict must be exactly the
/// one-by-one verdict of its documented method (the flight cut into equal steps, each mid-step trunk grown by what a
/// point moves in half a step and halved where it touches, down to the tolerance), written here on its own.
/// </summary>
public sealed class TrunkSweepTests
{
    private static readonly Vector3 Trunk = new(0.12f, 0.3f, 0.08f);
    private const float Tolerance = 0.01f;

    [TestCase("rooftops", 1)]
    [TestCase("desert", 2)]
    [TestCase("stairs", 3)]
    [TestCase("holes-debris", 4)]
    public void RunsOfStepsGiveExactlyTheOneByOneVerdict(string levelName, int seed)
    {
        Level level = ForeignLevels.Names.Contains(levelName) ? ForeignLevels.Get(levelName).Level : LevelGenerator.BuildLevel(levelName);
        TriangleBvh bvh = level.Bvh;
        var sweep = new TrunkSweepValidator(bvh, Trunk, Tolerance);
        var random = new Random(seed);
        Aabb bounds = bvh.Bounds;
        int free = 0;
        int hit = 0;
        for (int n = 0; n < 1500; n++)
        {
            // Arcs from just above the level's surfaces, long and short, turning or not: most graze something.
            Vector3 start = Above(bvh, bounds, random);
            Vector3 end = Above(bvh, bounds, random);
            float flight = 0.3f + (1.7f * random.NextSingle());
            Vector3 velocity = ((end - start) / flight) + new Vector3(0f, 0.5f * 9.81f * flight, 0f);
            Quaternion turn = Quaternion.CreateFromAxisAngle(Vector3.UnitY, random.NextSingle() < 0.3f ? 0f : (random.NextSingle() - 0.5f) * MathF.PI);
            var arc = new BallisticArc(new RootPose(start, Quaternion.Identity), new RootPose(end, turn), velocity, flight, 9.81f);
            bool expected = OneByOne(bvh, arc);
            Assert.That(sweep.IsValid(arc), Is.EqualTo(expected), $"arc {n}: {start} → {end} in {flight} s");
            (free, hit) = expected ? (free + 1, hit) : (free, hit + 1);
        }

        Assert.That(free, Is.GreaterThan(100), "arcs the sweep finds free");
        Assert.That(hit, Is.GreaterThan(30), "arcs the sweep finds touching the level");
    }

    /// <summary>A point up to a metre above the highest surface at a random spot of the level (its bounds' centre height where there is none).</summary>
    private static Vector3 Above(TriangleBvh bvh, Aabb bounds, Random random)
    {
        float x = float.Lerp(bounds.Min.X, bounds.Max.X, random.NextSingle());
        float z = float.Lerp(bounds.Min.Z, bounds.Max.Z, random.NextSingle());
        float y = bvh.Raycast(new Vector3(x, bounds.Max.Y + 1f, z), -Vector3.UnitY, bounds.Max.Y - bounds.Min.Y + 2f, out RayHit ground) ? ground.Point.Y : 0.5f * (bounds.Min.Y + bounds.Max.Y);
        return new Vector3(x, y + Trunk.Y + (random.NextSingle() * 1f), z);
    }

    /// <summary>The documented method, step by step.</summary>
    private static bool OneByOne(TriangleBvh bvh, in BallisticArc arc)
    {
        float spacing = MathF.Min(Trunk.X, MathF.Min(Trunk.Y, Trunk.Z));
        float speed = MathF.Max(arc.TakeoffVelocity.Length(), arc.LandingVelocity.Length());
        float turn = 2f * MathF.Acos(MathF.Min(1f, MathF.Abs(Quaternion.Dot(arc.StartRotation, arc.EndRotation))));
        float pointSpeed = speed + (arc.FlightTime > 0f ? turn / arc.FlightTime * Trunk.Length() : 0f);
        int steps = Math.Max(1, (int)MathF.Ceiling(arc.FlightTime * pointSpeed / spacing));
        for (int i = 0; i < steps; i++)
        {
            if (!Free(bvh, arc, arc.FlightTime * i / steps, arc.FlightTime * (i + 1) / steps, pointSpeed, 0))
            {
                return false;
            }
        }

        return true;
    }

    private static bool Free(TriangleBvh bvh, in BallisticArc arc, float t0, float t1, float pointSpeed, int depth)
    {
        float mid = 0.5f * (t0 + t1);
        float growth = pointSpeed * 0.5f * (t1 - t0);
        RootPose pose = arc.PoseAt(mid);
        if (!bvh.Overlaps(new OrientedBox(pose.Position, Trunk + new Vector3(growth), pose.Rotation)))
        {
            return true;
        }

        return growth > Tolerance && depth < 24 && Free(bvh, arc, t0, mid, pointSpeed, depth + 1) && Free(bvh, arc, mid, t1, pointSpeed, depth + 1);
    }
}
