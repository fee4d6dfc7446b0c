using System.Numerics;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Tests.Geometry;

public sealed class AabbTests
{
    [Test]
    public void EmptyIsTheIdentityOfUnion()
    {
        var box = new Aabb(new Vector3(-1f, 0f, 2f), new Vector3(3f, 1f, 4f));
        Assert.Multiple(() =>
        {
            Assert.That(Aabb.Empty.IsEmpty, Is.True);
            Assert.That(Aabb.Empty.SurfaceArea, Is.Zero);
            Assert.That(Aabb.Union(Aabb.Empty, box), Is.EqualTo(box));
            Assert.That(Aabb.FromPoints([]).IsEmpty, Is.True);
            Assert.That(box.SurfaceArea, Is.EqualTo(2f * ((4f * 1f) + (1f * 2f) + (2f * 4f))));
        });
    }

    [Test]
    public void SegmentTestAgreesWithDenseSampling()
    {
        // Any sampled point of the segment inside the box forces a hit; a reported hit must enter the box at tEnter.
        var random = new RandomGeometry(seed: 5);
        int hits = 0;
        for (int i = 0; i < 5_000; i++)
        {
            Vector3 a = random.Point(1f);
            Vector3 b = a + random.Point(1f);
            var box = new Aabb(Vector3.Min(a, b), Vector3.Max(a, b));
            Vector3 origin = random.Point(2f);
            // Half the segments aim near the box so that hits and misses are both common.
            Vector3 direction = i % 2 == 0 ? random.Point(4f) : (box.Center + random.Point(1f) - origin) * random.Range(0.5f, 2f);
            if (i % 10 == 0)
            {
                direction.Y = 0f; // zero components exercise the ±∞ reciprocal path
            }

            Vector3 inverse = new(1f / direction.X, 1f / direction.Y, 1f / direction.Z);
            bool hit = box.IntersectsRay(origin, inverse, 0f, 1f, out float tEnter);

            bool sampledInside = false;
            for (int s = 0; s <= 400 && !sampledInside; s++)
            {
                sampledInside = box.Inflate(-1e-4f).Contains(origin + (direction * (s / 400f)));
            }

            if (sampledInside)
            {
                Assert.That(hit, Is.True, $"case {i}");
            }

            if (hit)
            {
                hits++;
                Assert.That(tEnter, Is.InRange(0f, 1f), $"case {i}");
                Assert.That(box.Inflate(1e-3f).Contains(origin + (direction * tEnter)), Is.True, $"case {i}");
            }
        }

        Assert.That(hits, Is.GreaterThan(200));
    }

    [Test]
    public void IntersectsCountsTouching()
    {
        var a = new Aabb(Vector3.Zero, Vector3.One);
        Assert.Multiple(() =>
        {
            Assert.That(a.Intersects(new Aabb(Vector3.One, new Vector3(2f))), Is.True);
            Assert.That(a.Intersects(new Aabb(new Vector3(1.01f, 0f, 0f), new Vector3(2f))), Is.False);
        });
    }
}
