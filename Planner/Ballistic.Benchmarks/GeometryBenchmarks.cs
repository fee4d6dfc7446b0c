using System.Numerics;
using Ballistic.Planner.Geometry;
using BenchmarkDotNet.Attributes;

namespace Ballistic.Benchmarks;

/// <summary>The innermost collision test of the planner: trunk or workspace box against one level triangle.</summary>
[MemoryDiagnoser]
public class GeometryBenchmarks
{
    private const int Count = 4096;
    private readonly OrientedBox[] _boxes = new OrientedBox[Count];
    private readonly Triangle[] _triangles = new Triangle[Count];

    /// <summary>Seeded boxes and triangles, about half of the pairs overlapping.</summary>
    [GlobalSetup]
    public void Setup()
    {
        var random = new Random(42);
        float R(float e) => (float)((random.NextDouble() * 2.0) - 1.0) * e;
        for (int i = 0; i < Count; i++)
        {
            var rotation = Quaternion.Normalize(new Quaternion(R(1f), R(1f), R(1f), R(1f) + 1.5f));
            _boxes[i] = new OrientedBox(new Vector3(R(1f), R(1f), R(1f)), new Vector3(0.3f, 0.5f, 0.2f), rotation);
            Vector3 c = new(R(1.2f), R(1.2f), R(1.2f));
            _triangles[i] = new Triangle(c + new Vector3(R(0.8f), R(0.8f), R(0.8f)), c + new Vector3(R(0.8f), R(0.8f), R(0.8f)), c + new Vector3(R(0.8f), R(0.8f), R(0.8f)));
        }
    }

    /// <summary>4,096 box–triangle separating-axis tests.</summary>
    [Benchmark(OperationsPerInvoke = Count)]
    public int BoxTriangleOverlap()
    {
        int hits = 0;
        for (int i = 0; i < Count; i++)
        {
            if (_boxes[i].Intersects(_triangles[i]))
            {
                hits++;
            }
        }

        return hits;
    }
}
