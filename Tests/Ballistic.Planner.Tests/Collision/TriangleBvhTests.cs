using System.Numerics;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Tests.Geometry;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Collision;

public sealed class TriangleBvhTests
{
    [Test]
    public void BoxQueriesAgreeWithBruteForce()
    {
        var random = new RandomGeometry(seed: 99);
        var triangles = new List<Triangle>();
        for (int i = 0; i < 3_000; i++)
        {
            triangles.Add(random.Triangle(extent: 20f, size: 1.5f));
        }

        var bvh = new TriangleBvh(triangles);
        var reference = new BruteForceWorld(triangles);
        var found = new List<int>();
        int hits = 0;
        for (int q = 0; q < 2_000; q++)
        {
            OrientedBox box = random.Box(extent: 20f, maxHalf: 2f);
            found.Clear();
            bvh.OverlappingTriangles(box, found);
            var expected = Enumerable.Range(0, triangles.Count).Where(i => box.Intersects(triangles[i])).ToList();
            Assert.That(found.Order(), Is.EqualTo(expected), $"query {q}");
            Assert.That(bvh.Overlaps(box), Is.EqualTo(reference.Overlaps(box)), $"query {q}");
            hits += expected.Count > 0 ? 1 : 0;
        }

        Assert.That(hits, Is.InRange(200, 1_800), "queries should both hit and miss");
    }

    [Test]
    public void RaycastFindsTheNearestHitLikeBruteForce()
    {
        var random = new RandomGeometry(seed: 123);
        var triangles = new List<Triangle>();
        for (int i = 0; i < 2_000; i++)
        {
            triangles.Add(random.Triangle(extent: 10f, size: 2f));
        }

        var bvh = new TriangleBvh(triangles);
        int hits = 0;
        for (int q = 0; q < 2_000; q++)
        {
            Vector3 origin = random.Point(12f);
            Vector3 direction = random.Point(1f) * 20f;
            bool hit = bvh.Raycast(origin, direction, 1f, out RayHit result);

            float best = float.PositiveInfinity;
            int bestIndex = -1;
            for (int i = 0; i < triangles.Count; i++)
            {
                if (SegmentHit(triangles[i], origin, direction, out float t) && t < best)
                {
                    best = t;
                    bestIndex = i;
                }
            }

            Assert.That(hit, Is.EqualTo(bestIndex >= 0), $"ray {q}");
            if (hit)
            {
                hits++;
                Assert.That(result.Distance, Is.EqualTo(best).Within(1e-5f), $"ray {q}");
                Assert.That(Vector3.Distance(result.Point, origin + (direction * best)), Is.LessThan(1e-3f), $"ray {q}");
                Assert.That(Vector3.Distance(result.Normal, triangles[result.Triangle].Normal), Is.LessThan(1e-5f), $"ray {q}");
            }
        }

        Assert.That(hits, Is.GreaterThan(200));
    }

    [Test]
    public void BuildIsDeterministicAndHandlesCoincidentTriangles()
    {
        // A thousand copies of one triangle: no split by position is possible, the tree must still be bounded.
        var same = Enumerable.Repeat(new Triangle(Vector3.Zero, Vector3.UnitX, Vector3.UnitZ), 1_000).ToList();
        var bvh = new TriangleBvh(same);
        var found = new List<int>();
        bvh.OverlappingTriangles(new OrientedBox(new Vector3(0.2f, 0f, 0.2f), new Vector3(0.1f), Quaternion.Identity), found);
        Assert.That(found, Has.Count.EqualTo(1_000));

        var random = new RandomGeometry(seed: 4);
        var soup = Enumerable.Range(0, 500).Select(_ => random.Triangle(5f, 1f)).ToList();
        var first = new TriangleBvh(soup);
        var second = new TriangleBvh(soup);
        var a = new List<int>();
        var b = new List<int>();
        var probe = new OrientedBox(Vector3.Zero, new Vector3(3f), Quaternion.Identity);
        first.OverlappingTriangles(probe, a);
        second.OverlappingTriangles(probe, b);
        Assert.Multiple(() =>
        {
            Assert.That(a, Is.Not.Empty);
            Assert.That(b, Is.EqualTo(a), "same input, same tree, same visiting order");
            Assert.That(second.NodeCount, Is.EqualTo(first.NodeCount));
        });
    }

    [Test]
    public void EmptyHierarchyAnswersNothing()
    {
        var bvh = new TriangleBvh([]);
        Assert.Multiple(() =>
        {
            Assert.That(bvh.Overlaps(new OrientedBox(Vector3.Zero, Vector3.One, Quaternion.Identity)), Is.False);
            Assert.That(bvh.Raycast(Vector3.Zero, Vector3.UnitY, 1f, out _), Is.False);
        });
    }

    private static bool SegmentHit(Triangle tri, Vector3 origin, Vector3 direction, out float t)
    {
        // Plane intersection, then an inside test by barycentric signs: independent of Möller–Trumbore.
        t = 0f;
        Vector3 n = tri.ScaledNormal;
        float denominator = Vector3.Dot(n, direction);
        if (MathF.Abs(denominator) < 1e-12f)
        {
            return false;
        }

        t = Vector3.Dot(n, tri.A - origin) / denominator;
        if (t < 0f || t > 1f)
        {
            return false;
        }

        Vector3 p = origin + (direction * t);
        float s0 = Vector3.Dot(Vector3.Cross(tri.B - tri.A, p - tri.A), n);
        float s1 = Vector3.Dot(Vector3.Cross(tri.C - tri.B, p - tri.B), n);
        float s2 = Vector3.Dot(Vector3.Cross(tri.A - tri.C, p - tri.C), n);
        return s0 >= 0f && s1 >= 0f && s2 >= 0f;
    }
}
