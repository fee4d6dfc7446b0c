using System.Numerics;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Steering;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Steering;

/// <summary>
/// A long leap whose trunk passes through a wall mid-flight, taking off with the trunk just above the floor (the
/// sweep's first intervals graze it and are halved down to the tolerance): the trunk probed at an instant inside the
/// wall refuses the arc in a few box tests, before the sweep proves the grazing takeoff free; the verdicts stay the
/// sweep's (<see cref="TrunkSweepTests"/> compares them with the documented method on 6,000 arcs).
/// </summary>
public sealed class TrunkProbeTests
{
    private static readonly Vector3 Trunk = new(0.12f, 0.3f, 0.08f);

    [Test]
    public void AnArcThroughAWallIsRefusedAtAProbeNotAfterSweepingTheGrazingTakeoff()
    {
        Level level = new LevelBuilder("wall").AddFloor(-2f, -2f, 12f, 2f, 0f).AddBox(new Vector3(4.95f, 0f, -2f), new Vector3(5.05f, 6f, 2f)).Build();
        var counted = new CountingWorld(new TriangleBvh(level.Triangles));
        var sweep = new TrunkSweepValidator(counted, Trunk, 0.01f);

        // 10 m in 1 s from 1.5 cm above the floor: the trunk straddles the 10 cm wall at mid-flight, 5 m along and 1.2 m up.
        var start = new Vector3(0f, Trunk.Y + 0.015f, 0f);
        var end = new Vector3(10f, Trunk.Y + 0.015f, 0f);
        var through = new BallisticArc(new RootPose(start, Quaternion.Identity), new RootPose(end, Quaternion.Identity), new Vector3(10f, 4.905f, 0f), 1f, 9.81f);
        Assert.That(sweep.IsValid(through), Is.False, "the trunk passes through the wall");
        Assert.That(counted.Tests, Is.EqualTo(1), "refused by the probe at half the flight, inside the wall");

        // Without the wall the same arc is free: its probes all miss, then the sweep proves it free as before.
        Level open = new LevelBuilder("floor").AddFloor(-2f, -2f, 12f, 2f, 0f).Build();
        var openCounted = new CountingWorld(new TriangleBvh(open.Triangles));
        Assert.That(new TrunkSweepValidator(openCounted, Trunk, 0.01f).IsValid(through), Is.True, "the arc clears the floor");
        Assert.That(openCounted.Tests, Is.GreaterThan(31), "every probe, then the sweep");
    }

    [Test]
    public void AShortHopIsNotProbed()
    {
        // 0.3 m in 0.25 s: fewer than 8 steps, swept at once, so a hop through a post costs the sweep's own tests only.
        Level level = new LevelBuilder("post").AddFloor(-1f, -1f, 1f, 1f, 0f).AddBox(new Vector3(0.2f, 0f, -0.5f), new Vector3(0.25f, 2f, 0.5f)).Build();
        var counted = new CountingWorld(new TriangleBvh(level.Triangles));
        var start = new Vector3(0f, Trunk.Y + 0.3f, 0f);
        var end = new Vector3(0.3f, Trunk.Y + 0.3f, 0f);
        var hop = new BallisticArc(new RootPose(start, Quaternion.Identity), new RootPose(end, Quaternion.Identity), new Vector3(0.3f / 0.25f, 0.5f * 9.81f * 0.25f, 0f), 0.25f, 9.81f);
        Assert.That(new TrunkSweepValidator(counted, Trunk, 0.01f).IsValid(hop), Is.False, "the hop hits the post");
        Assert.That(counted.Tests, Is.GreaterThan(1), "swept from takeoff to the post, interval by interval");
    }

    /// <summary>A collision world that counts its box tests.</summary>
    private sealed class CountingWorld(ICollisionWorld inner) : ICollisionWorld
    {
        public int Tests { get; private set; }

        public bool Overlaps(in OrientedBox box)
        {
            Tests++;
            return inner.Overlaps(box);
        }
    }
}
