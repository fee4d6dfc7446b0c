using System.Numerics;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Tests.Geometry;

/// <summary>Seeded random points, rotations, triangles and boxes for property tests.</summary>
internal sealed class RandomGeometry(int seed)
{
    private readonly Random _random = new(seed);

    public float Range(float min, float max) => min + ((float)_random.NextDouble() * (max - min));

    public Vector3 Point(float extent) => new(Range(-extent, extent), Range(-extent, extent), Range(-extent, extent));

    public Quaternion Rotation()
    {
        // Uniform random rotation (Shoemake).
        float u1 = (float)_random.NextDouble();
        float u2 = Range(0f, 2f * MathF.PI);
        float u3 = Range(0f, 2f * MathF.PI);
        float a = MathF.Sqrt(1f - u1);
        float b = MathF.Sqrt(u1);
        return Quaternion.Normalize(new Quaternion(a * MathF.Sin(u2), a * MathF.Cos(u2), b * MathF.Sin(u3), b * MathF.Cos(u3)));
    }

    public Triangle Triangle(float extent, float size)
    {
        Vector3 c = Point(extent);
        return new Triangle(c + Point(size), c + Point(size), c + Point(size));
    }

    public OrientedBox Box(float extent, float maxHalf) =>
        new(Point(extent), new Vector3(Range(0.05f, maxHalf), Range(0.05f, maxHalf), Range(0.05f, maxHalf)), Rotation());
}
