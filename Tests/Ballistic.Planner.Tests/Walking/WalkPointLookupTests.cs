using System.Numerics;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Tests.Walking;

/// <summary>
/// <see cref="Walk.PointAt(float)"/> finds the path's segment by slices of its length (it runs several times for every
/// walking agent every tick): on paths of uneven segments (long ones, short ones, repeated points, as planned walks
/// and their smoothing leave them) it returns exactly the point a binary search over the cumulative lengths gives, at
/// every path point, between them, at the ends and beyond them. Found from a hint (the segment of an agent's last
/// tick, <see cref="Walk.PoseAt(float, ref int)"/>), the points and poses are the same to the bit whatever the hint.
/// </summary>
public sealed class WalkPointLookupTests
{
    [Test]
    public void PointsAlongTheWalkAreThoseABinarySearchFinds()
    {
        var random = new Random(3);
        for (int walk = 0; walk < 20; walk++)
        {
            var path = new List<Vector3> { new((float)random.NextDouble(), 0f, (float)random.NextDouble()) };
            int count = 2 + random.Next(60);
            while (path.Count < count)
            {
                double roll = random.NextDouble();
                float step = roll < 0.1 ? 0f : roll < 0.3 ? 0.002f * (float)random.NextDouble() : roll < 0.4 ? 3f * (float)random.NextDouble() : 0.2f;
                float angle = (float)(random.NextDouble() * 2.0 * Math.PI);
                path.Add(path[^1] + new Vector3(step * MathF.Cos(angle), 0.3f * step * (float)(random.NextDouble() - 0.5), step * MathF.Sin(angle)));
            }

            var from = new RoadmapNode(0, new RootPose(path[0] + Vector3.UnitY, Quaternion.Identity), new FrictionCone(Vector3.UnitY, 1f), []);
            var to = new RoadmapNode(1, new RootPose(path[^1] + Vector3.UnitY, Quaternion.Identity), new FrictionCone(Vector3.UnitY, 1f), []);
            var subject = new Walk(from, to, path, 1.5f);

            // The reference: cumulative lengths as the walk sums them, a binary search over them.
            float[] distances = new float[path.Count];
            for (int i = 1; i < path.Count; i++)
            {
                distances[i] = distances[i - 1] + Vector3.Distance(path[i - 1], path[i]);
            }

            Vector3 Reference(float distance)
            {
                distance = Math.Clamp(distance, 0f, distances[^1]);
                int i = Array.BinarySearch(distances, distance);
                if (i >= 0)
                {
                    return path[i];
                }

                i = ~i;
                float span = distances[i] - distances[i - 1];
                return span > 0f ? Vector3.Lerp(path[i - 1], path[i], (distance - distances[i - 1]) / span) : path[i];
            }

            var probes = distances.Concat(distances.Zip(distances.Skip(1), (a, b) => 0.5f * (a + b)))
                .Concat(Enumerable.Range(0, 500).Select(_ => (float)((random.NextDouble() * 1.2 * distances[^1]) - (0.1 * distances[^1]))))
                .Append(-1f).Append(distances[^1] + 1f).Append(BitConverter.Int32BitsToSingle(BitConverter.SingleToInt32Bits(distances[^1]) - 1));
            Assert.Multiple(() =>
            {
                foreach (float d in probes)
                {
                    Assert.That(subject.PointAt(d), Is.EqualTo(Reference(d)), $"walk {walk} ({path.Count} points, {distances[^1]} m) at {d} m");
                }
            });
        }
    }

    [Test]
    public void PointsAndPosesFoundFromAnyHintAreThoseFoundWithout()
    {
        var random = new Random(5);
        for (int walk = 0; walk < 20; walk++)
        {
            var path = new List<Vector3> { Vector3.Zero };
            int count = 2 + random.Next(80);
            while (path.Count < count)
            {
                double roll = random.NextDouble();
                float step = roll < 0.1 ? 0f : roll < 0.3 ? 0.002f * (float)random.NextDouble() : 0.05f + (0.4f * (float)random.NextDouble());
                float angle = (float)(random.NextDouble() * 2.0 * Math.PI);
                path.Add(path[^1] + new Vector3(step * MathF.Cos(angle), 0.2f * step * (float)(random.NextDouble() - 0.5), step * MathF.Sin(angle)));
            }

            var from = new RoadmapNode(0, new RootPose(path[0] + Vector3.UnitY, Quaternion.Identity), new FrictionCone(Vector3.UnitY, 1f), []);
            var to = new RoadmapNode(1, new RootPose(path[^1] + Vector3.UnitY, Quaternion.Identity), new FrictionCone(Vector3.UnitY, 1f), []);
            var subject = new Walk(from, to, path, 1.5f);

            // A tick's walk: times in order, each searched from the last one's segment, and from hints of every kind.
            int carried = 0;
            int[] hints = [-1, 0, 1, count / 2, count - 1, count, count + 7, int.MaxValue, int.MinValue];
            Assert.Multiple(() =>
            {
                for (float t = -0.1f; t <= subject.Duration + 0.1f; t += 1f / 60f)
                {
                    RootPose pose = subject.PoseAt(t);
                    Assert.That(subject.PoseAt(t, ref carried), Is.EqualTo(pose), $"walk {walk} at {t} s, from the last tick's segment");
                    foreach (int h in hints.Append(random.Next(-3, count + 3)))
                    {
                        int hint = h;
                        Assert.That(subject.PoseAt(t, ref hint), Is.EqualTo(pose), $"walk {walk} at {t} s, from segment {h}");
                    }

                    float d = subject.DistanceAt(t) + (0.3f * (float)(random.NextDouble() - 0.5));
                    int near = carried;
                    Assert.That(subject.PointAt(d, ref near), Is.EqualTo(subject.PointAt(d)), $"walk {walk} at {d} m");
                }
            });
        }
    }
}
