using System.Numerics;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Tests.Geometry;

public sealed class OrientedBoxTests
{
    [Test]
    public void TriangleOverlapAgreesWithPolygonClipping()
    {
        // The separating-axis test against an independent exact method: clip the triangle by the box's six slabs
        // (Sutherland–Hodgman); they overlap exactly when something is left. A margin keeps float ties out:
        // overlap with the shrunk box implies clipping is non-empty, and clipping by a shrunk box implies overlap.
        var random = new RandomGeometry(seed: 20161016);
        const float margin = 1e-3f;
        int overlaps = 0;
        int separations = 0;
        for (int i = 0; i < 20_000; i++)
        {
            OrientedBox box = random.Box(extent: 1f, maxHalf: 1.2f);
            Triangle triangle = random.Triangle(extent: 2f, size: 1.5f);
            OrientedBox shrunk = new(box.Center, box.HalfExtents - new Vector3(margin), box.Rotation);

            if (shrunk.Intersects(triangle))
            {
                Assert.That(ClipsNonEmpty(box, triangle), Is.True, $"case {i}: SAT overlap but clipping is empty");
            }

            if (ClipsNonEmpty(shrunk, triangle))
            {
                Assert.That(box.Intersects(triangle), Is.True, $"case {i}: clipping non-empty but SAT separates");
            }

            if (box.Intersects(triangle))
            {
                overlaps++;
            }
            else
            {
                separations++;
            }
        }

        // Both outcomes must be well represented, or the property above proves little.
        Assert.That(overlaps, Is.GreaterThan(2_000));
        Assert.That(separations, Is.GreaterThan(2_000));
    }

    [Test]
    public void ThinTriangleThroughTheBoxOverlapsThoughNoVertexIsInside()
    {
        var box = new OrientedBox(Vector3.Zero, new Vector3(0.5f, 0.5f, 0.5f), Quaternion.CreateFromAxisAngle(Vector3.UnitY, 0.7f));
        var sliver = new Triangle(new Vector3(-5f, 0f, 0f), new Vector3(5f, 0.01f, 0f), new Vector3(5f, -0.01f, 0f));
        Assert.Multiple(() =>
        {
            Assert.That(box.Contains(sliver.A) || box.Contains(sliver.B) || box.Contains(sliver.C), Is.False);
            Assert.That(box.Intersects(sliver), Is.True);
        });
    }

    [Test]
    public void TriangleJustOutsideAFaceDoesNotOverlap()
    {
        // A floor triangle 1 mm below a tilted box's lowest corner.
        var box = new OrientedBox(new Vector3(0f, 1f, 0f), new Vector3(0.3f, 0.4f, 0.2f), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.3f));
        float lowest = box.Bounds.Min.Y;
        var floor = new Triangle(new Vector3(-10f, lowest - 1e-3f, -10f), new Vector3(0f, lowest - 1e-3f, 10f), new Vector3(10f, lowest - 1e-3f, -10f));
        var raised = floor with { A = floor.A + new Vector3(0f, 2e-3f, 0f), B = floor.B + new Vector3(0f, 2e-3f, 0f), C = floor.C + new Vector3(0f, 2e-3f, 0f) };
        Assert.Multiple(() =>
        {
            Assert.That(box.Intersects(floor), Is.False);
            Assert.That(box.Intersects(raised), Is.True);
        });
    }

    [Test]
    public void BoundsHoldEveryCornerAndAreTight()
    {
        var random = new RandomGeometry(seed: 7);
        Span<Vector3> corners = stackalloc Vector3[8];
        for (int i = 0; i < 1_000; i++)
        {
            OrientedBox box = random.Box(extent: 10f, maxHalf: 3f);
            box.GetCorners(corners);
            Aabb bounds = box.Bounds;
            Aabb exact = Aabb.FromPoints(corners);
            Assert.That(Vector3.Distance(bounds.Min, exact.Min) + Vector3.Distance(bounds.Max, exact.Max), Is.LessThan(1e-4f), $"case {i}");
        }
    }

    [Test]
    public void ContainsMatchesTheLocalFrame()
    {
        var random = new RandomGeometry(seed: 11);
        for (int i = 0; i < 5_000; i++)
        {
            OrientedBox box = random.Box(extent: 2f, maxHalf: 1f);
            Vector3 p = random.Point(3f);
            Vector3 local = box.ToLocal(p);
            Assert.That(Vector3.Distance(box.ToWorld(local), p), Is.LessThan(1e-4f));

            // Away from the boundary the answer must follow the local coordinates.
            Vector3 slack = box.HalfExtents - Vector3.Abs(local);
            float closest = MathF.Min(MathF.Abs(slack.X), MathF.Min(MathF.Abs(slack.Y), MathF.Abs(slack.Z)));
            if (closest > 1e-4f)
            {
                bool inside = slack.X > 0f && slack.Y > 0f && slack.Z > 0f;
                Assert.That(box.Contains(p), Is.EqualTo(inside), $"case {i}");
            }
        }
    }

    [Test]
    public void AxesFollowTheRotation()
    {
        var box = new OrientedBox(Vector3.Zero, Vector3.One, Quaternion.CreateFromAxisAngle(Vector3.UnitY, MathF.PI / 2f));
        Assert.Multiple(() =>
        {
            // A quarter turn about +Y takes +X to −Z and +Z to +X (right-handed, Y up).
            Assert.That(Vector3.Distance(box.AxisX, -Vector3.UnitZ), Is.LessThan(1e-6f));
            Assert.That(Vector3.Distance(box.AxisY, Vector3.UnitY), Is.LessThan(1e-6f));
            Assert.That(Vector3.Distance(box.AxisZ, Vector3.UnitX), Is.LessThan(1e-6f));
        });
    }

    [Test]
    public void RejectsInvalidShapesWithTheParameterNamed()
    {
        Assert.Multiple(() =>
        {
            Assert.That(() => new OrientedBox(Vector3.Zero, new Vector3(1f, -0.1f, 1f), Quaternion.Identity),
                Throws.TypeOf<ArgumentOutOfRangeException>().With.Property(nameof(ArgumentException.ParamName)).EqualTo("halfExtents"));
            Assert.That(() => new OrientedBox(Vector3.Zero, new Vector3(float.NaN, 1f, 1f), Quaternion.Identity),
                Throws.TypeOf<ArgumentOutOfRangeException>().With.Property(nameof(ArgumentException.ParamName)).EqualTo("halfExtents"));
            Assert.That(() => new OrientedBox(Vector3.Zero, Vector3.One, default),
                Throws.TypeOf<ArgumentOutOfRangeException>().With.Property(nameof(ArgumentException.ParamName)).EqualTo("rotation"));
        });
    }

    [Test]
    public void RotationIsNormalised()
    {
        var box = new OrientedBox(Vector3.Zero, Vector3.One, new Quaternion(0f, 0f, 0f, 3f));
        Assert.That(box.Rotation, Is.EqualTo(Quaternion.Identity));
    }

    /// <summary>Clips the triangle, in the box frame, by the six slabs; true when a polygon of positive extent remains or any point does.</summary>
    private static bool ClipsNonEmpty(OrientedBox box, Triangle triangle)
    {
        var polygon = new List<Vector3> { box.ToLocal(triangle.A), box.ToLocal(triangle.B), box.ToLocal(triangle.C) };
        Vector3 h = box.HalfExtents;
        for (int axis = 0; axis < 3 && polygon.Count > 0; axis++)
        {
            float limit = axis == 0 ? h.X : axis == 1 ? h.Y : h.Z;
            polygon = ClipByPlane(polygon, axis, limit, keepBelow: true);
            polygon = ClipByPlane(polygon, axis, -limit, keepBelow: false);
        }

        return polygon.Count > 0;
    }

    private static List<Vector3> ClipByPlane(List<Vector3> polygon, int axis, float limit, bool keepBelow)
    {
        var result = new List<Vector3>();
        for (int i = 0; i < polygon.Count; i++)
        {
            Vector3 current = polygon[i];
            Vector3 next = polygon[(i + 1) % polygon.Count];
            float dc = Signed(current, axis, limit, keepBelow);
            float dn = Signed(next, axis, limit, keepBelow);
            if (dc <= 0f)
            {
                result.Add(current);
            }

            if ((dc < 0f && dn > 0f) || (dc > 0f && dn < 0f))
            {
                result.Add(current + ((next - current) * (dc / (dc - dn))));
            }
        }

        return result;
    }

    /// <summary>Signed distance past the plane: ≤ 0 is kept.</summary>
    private static float Signed(Vector3 p, int axis, float limit, bool keepBelow)
    {
        float value = axis == 0 ? p.X : axis == 1 ? p.Y : p.Z;
        return keepBelow ? value - limit : limit - value;
    }
}
