using System.Numerics;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Tests.Geometry;

public sealed class BoxClipperTests
{
    [Test]
    public void ClippedAreaAndCentroidMatchAClipInWorldSpace()
    {
        // Against an independent clip: the triangle cut in world space, in doubles, by the box's six face planes
        // (each a world normal and offset). Triangles wholly inside, crossing one face, crossing several, and
        // outside must all be well represented, and each must agree.
        var random = new RandomGeometry(seed: 20261206);
        int inside = 0;
        int oneAxis = 0;
        int severalAxes = 0;
        int empty = 0;
        for (int i = 0; i < 6_000; i++)
        {
            OrientedBox box = random.Box(extent: 0.5f, maxHalf: 0.8f);
            Triangle triangle = i % 3 == 0 ? random.Triangle(extent: 0.3f, size: 0.15f) : random.Triangle(extent: 1f, size: 0.8f);
            (float area, Vector3 centroid) = BoxClipper.ClipArea(box, triangle);
            (double expectedArea, Vector3 expectedCentroid) = ClipInWorld(box, triangle);

            Assert.That(area, Is.EqualTo(expectedArea).Within(1e-5 + (1e-4 * expectedArea)), $"case {i}: area");
            if (expectedArea > 1e-4)
            {
                Assert.That(Vector3.Distance(centroid, expectedCentroid), Is.LessThan(1e-4f), $"case {i}: centroid");
            }

            int crossed = AxesCrossed(box, triangle);
            if (expectedArea <= 0.0)
            {
                empty++;
            }
            else if (crossed == 0)
            {
                inside++;
            }
            else if (crossed == 1)
            {
                oneAxis++;
            }
            else
            {
                severalAxes++;
            }
        }

        TestContext.Out.WriteLine($"inside {inside}, one axis {oneAxis}, several {severalAxes}, outside {empty}");
        Assert.Multiple(() =>
        {
            Assert.That(inside, Is.GreaterThan(300), "wholly inside");
            Assert.That(oneAxis, Is.GreaterThan(300), "crossing one axis's faces");
            Assert.That(severalAxes, Is.GreaterThan(300), "crossing several axes' faces");
            Assert.That(empty, Is.GreaterThan(300), "outside");
        });
    }

    [Test]
    public void OverlapGivenTheBoxFrameAgreesWithTheSeparatingAxisTest()
    {
        // The shortcut (all three vertices inside) must never answer differently from the full test.
        var random = new RandomGeometry(seed: 61206);
        int wholly = 0;
        int overlapping = 0;
        for (int i = 0; i < 20_000; i++)
        {
            OrientedBox box = random.Box(extent: 0.5f, maxHalf: 0.8f);
            Triangle triangle = random.Triangle(extent: 1f, size: i % 2 == 0 ? 0.1f : 0.8f);
            Vector3 v0 = box.ToLocal(triangle.A);
            Vector3 v1 = box.ToLocal(triangle.B);
            Vector3 v2 = box.ToLocal(triangle.C);
            bool expected = box.Intersects(triangle);
            Assert.That(BoxClipper.Overlaps(box, v0, v1, v2), Is.EqualTo(expected), $"case {i}");
            overlapping += expected ? 1 : 0;
            wholly += box.Contains(triangle.A) && box.Contains(triangle.B) && box.Contains(triangle.C) ? 1 : 0;
        }

        Assert.Multiple(() =>
        {
            Assert.That(wholly, Is.GreaterThan(500));
            Assert.That(overlapping - wholly, Is.GreaterThan(2_000));
            Assert.That(20_000 - overlapping, Is.GreaterThan(2_000));
        });
    }

    /// <summary>How many of the box's axes have a face the triangle crosses (some vertex beyond it).</summary>
    private static int AxesCrossed(OrientedBox box, Triangle triangle)
    {
        Vector3 h = box.HalfExtents;
        Vector3 most = Vector3.Max(Vector3.Abs(box.ToLocal(triangle.A)), Vector3.Max(Vector3.Abs(box.ToLocal(triangle.B)), Vector3.Abs(box.ToLocal(triangle.C))));
        return (most.X > h.X ? 1 : 0) + (most.Y > h.Y ? 1 : 0) + (most.Z > h.Z ? 1 : 0);
    }

    /// <summary>The area and centroid of the triangle's part inside the box, cut in world space in doubles.</summary>
    private static (double Area, Vector3 Centroid) ClipInWorld(OrientedBox box, Triangle triangle)
    {
        var polygon = new List<(double X, double Y, double Z)> { Of(triangle.A), Of(triangle.B), Of(triangle.C) };
        (double X, double Y, double Z) centre = Of(box.Center);
        Vector3[] axes = [box.AxisX, box.AxisY, box.AxisZ];
        float[] halves = [box.HalfExtents.X, box.HalfExtents.Y, box.HalfExtents.Z];
        for (int k = 0; k < 3; k++)
        {
            foreach (double side in new[] { 1.0, -1.0 })
            {
                // Keep n·(p − c) ≤ h with n = ±axis.
                (double X, double Y, double Z) n = (side * axes[k].X, side * axes[k].Y, side * axes[k].Z);
                double Beyond((double X, double Y, double Z) p) => (n.X * (p.X - centre.X)) + (n.Y * (p.Y - centre.Y)) + (n.Z * (p.Z - centre.Z)) - halves[k];
                var kept = new List<(double X, double Y, double Z)>();
                for (int i = 0; i < polygon.Count; i++)
                {
                    var p = polygon[i];
                    var q = polygon[(i + 1) % polygon.Count];
                    double bp = Beyond(p);
                    double bq = Beyond(q);
                    if (bp <= 0.0)
                    {
                        kept.Add(p);
                    }

                    if (bp * bq < 0.0)
                    {
                        double t = bp / (bp - bq);
                        kept.Add((p.X + ((q.X - p.X) * t), p.Y + ((q.Y - p.Y) * t), p.Z + ((q.Z - p.Z) * t)));
                    }
                }

                polygon = kept;
            }
        }

        double twice = 0.0;
        (double X, double Y, double Z) moment = (0.0, 0.0, 0.0);
        for (int i = 1; i + 1 < polygon.Count; i++)
        {
            var (a, b, c) = (polygon[0], polygon[i], polygon[i + 1]);
            (double X, double Y, double Z) u = (b.X - a.X, b.Y - a.Y, b.Z - a.Z);
            (double X, double Y, double Z) v = (c.X - a.X, c.Y - a.Y, c.Z - a.Z);
            double cx = (u.Y * v.Z) - (u.Z * v.Y);
            double cy = (u.Z * v.X) - (u.X * v.Z);
            double cz = (u.X * v.Y) - (u.Y * v.X);
            double part = Math.Sqrt((cx * cx) + (cy * cy) + (cz * cz));
            twice += part;
            moment = (moment.X + ((a.X + b.X + c.X) * part / 3.0), moment.Y + ((a.Y + b.Y + c.Y) * part / 3.0), moment.Z + ((a.Z + b.Z + c.Z) * part / 3.0));
        }

        return twice > 0.0 ? (twice / 2.0, new Vector3((float)(moment.X / twice), (float)(moment.Y / twice), (float)(moment.Z / twice))) : (0.0, box.Center);
    }

    private static (double X, double Y, double Z) Of(Vector3 v) => (v.X, v.Y, v.Z);
}
