using System.Numerics;
using Ballistic.Runtime.Skeletons;

namespace Ballistic.Planner.Tests.Skeletons;

/// <summary>The least-squares rotation between two sets of vectors (Horn's method) that aligns a skeleton's rest with a rig's.</summary>
public sealed class RestAlignmentFitTests
{
    [Test]
    public void ItRecoversARotationFromScaledNoisyVectors()
    {
        var random = new Random(11);
        for (int trial = 0; trial < 50; trial++)
        {
            Quaternion truth = SkeletonBindingTests.RandomRotation(random, MathF.PI);
            var from = new Vector3[12];
            var to = new Vector3[12];
            for (int i = 0; i < from.Length; i++)
            {
                from[i] = new Vector3(random.NextSingle() - 0.5f, random.NextSingle() - 0.5f, random.NextSingle() - 0.5f) * 100f;
                Vector3 noise = new Vector3(random.NextSingle() - 0.5f, random.NextSingle() - 0.5f, random.NextSingle() - 0.5f) * 1e-4f;
                to[i] = (Vector3.Transform(from[i], truth) * 0.01f) + noise;
            }

            Quaternion? fitted = RestAlignmentFit.Fit(from, to);
            Assert.That(fitted, Is.Not.Null);
            Assert.That(SkeletonBindingTests.Angle(fitted!.Value, truth), Is.LessThan(1e-3), $"trial {trial}");
        }
    }

    [Test]
    public void VectorsOnOneLineHaveNoUniqueRotation()
    {
        Vector3[] from = [new(0f, 1f, 0f), new(0f, 2f, 0f), new(0f, -0.5f, 0f)];
        Vector3[] to = [new(1f, 0f, 0f), new(2f, 0f, 0f), new(-0.5f, 0f, 0f)];
        Assert.Multiple(() =>
        {
            Assert.That(RestAlignmentFit.Fit(from, to), Is.Null);
            Assert.That(RestAlignmentFit.Fit([], []), Is.Null);
            Assert.That(RestAlignmentFit.Fit([Vector3.Zero], [Vector3.UnitX]), Is.Null);
        });
    }
}
