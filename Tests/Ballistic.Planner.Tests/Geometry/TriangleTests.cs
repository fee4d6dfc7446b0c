using System.Numerics;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Tests.Geometry;

public sealed class TriangleTests
{
    [Test]
    public void ClosestPointIsOnTheTriangleAndNoSampledPointIsCloser()
    {
        var random = new RandomGeometry(seed: 3);
        for (int i = 0; i < 500; i++)
        {
            Triangle t = random.Triangle(extent: 1f, size: 1f);
            Vector3 p = random.Point(2f);
            Vector3 q = t.ClosestPoint(p);

            Vector3 bary = Barycentric(t, q);
            Assert.That(Math.Min(bary.X, Math.Min(bary.Y, bary.Z)), Is.GreaterThan(-1e-3f), $"case {i}: closest point outside the triangle");
            Assert.That(MathF.Abs(Vector3.Dot(q - t.A, t.Normal)), Is.LessThan(1e-4f), $"case {i}: closest point off the plane");

            float best = float.PositiveInfinity;
            const int n = 60;
            for (int a = 0; a <= n; a++)
            {
                for (int b = 0; a + b <= n; b++)
                {
                    Vector3 s = t.A + ((t.B - t.A) * (a / (float)n)) + ((t.C - t.A) * (b / (float)n));
                    best = MathF.Min(best, Vector3.Distance(s, p));
                }
            }

            Assert.That(Vector3.Distance(q, p), Is.LessThanOrEqualTo(best + 1e-4f), $"case {i}");
        }
    }

    [Test]
    public void ClosestPointOnADegenerateTriangleLiesOnItsSegment()
    {
        var line = new Triangle(Vector3.Zero, new Vector3(1f, 0f, 0f), new Vector3(2f, 0f, 0f));
        Vector3 q = line.ClosestPoint(new Vector3(1.5f, 3f, 0f));
        Assert.That(Vector3.Distance(q, new Vector3(1.5f, 0f, 0f)), Is.LessThan(1e-5f));
    }

    [Test]
    public void NormalAreaAndFiniteness()
    {
        // Counter-clockwise seen from above (+Y): the front face points up.
        var floor = new Triangle(Vector3.Zero, new Vector3(0f, 0f, 2f), new Vector3(2f, 0f, 0f));
        var bad = floor with { B = new Vector3(float.NaN, 0f, 0f) };
        var degenerate = new Triangle(Vector3.One, Vector3.One, Vector3.One);
        Assert.Multiple(() =>
        {
            Assert.That(Vector3.Distance(floor.Normal, Vector3.UnitY), Is.LessThan(1e-6f));
            Assert.That(floor.Area, Is.EqualTo(2f).Within(1e-6f));
            Assert.That(floor.IsFinite, Is.True);
            Assert.That(bad.IsFinite, Is.False);
            Assert.That(degenerate.Normal, Is.EqualTo(Vector3.Zero));
            Assert.That(degenerate.Area, Is.Zero);
        });
    }

    private static Vector3 Barycentric(Triangle t, Vector3 p)
    {
        Vector3 v0 = t.B - t.A;
        Vector3 v1 = t.C - t.A;
        Vector3 v2 = p - t.A;
        float d00 = Vector3.Dot(v0, v0);
        float d01 = Vector3.Dot(v0, v1);
        float d11 = Vector3.Dot(v1, v1);
        float d20 = Vector3.Dot(v2, v0);
        float d21 = Vector3.Dot(v2, v1);
        float denominator = (d00 * d11) - (d01 * d01);
        float v = ((d11 * d20) - (d01 * d21)) / denominator;
        float w = ((d00 * d21) - (d01 * d20)) / denominator;
        return new Vector3(1f - v - w, v, w);
    }
}
