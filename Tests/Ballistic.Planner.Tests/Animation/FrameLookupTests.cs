using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;

namespace Ballistic.Planner.Tests.Animation;

/// <summary>
/// The clip's samplers (<see cref="JumpAnimation.Sample(float, Span{float})"/>, <see cref="JumpAnimation.RootAt(float)"/>)
/// find the frames around a time by slices of the clip (they run for every moving agent every tick): on frames
/// spaced unevenly (clusters, gaps, repeated times, as re-sampling leaves them) they interpolate between exactly the
/// frames a scan from the first would find, at frame times, between them, before the first and after the last; and
/// the root found from a hint (the frame of an agent's last tick) is the same to the bit whatever the hint.
/// </summary>
public sealed class FrameLookupTests
{
    [Test]
    public void SamplingFindsTheFramesAroundEveryTimeOnUnevenFrames()
    {
        CharacterModel model = CharacterPresets.Model("frog");
        var random = new Random(11);
        var times = new List<float> { 0f };
        while (times.Count < 400)
        {
            // Mostly a 60th of a second apart; some clustered, some repeated, some a long gap.
            double roll = random.NextDouble();
            float gap = roll < 0.1 ? 0f : roll < 0.3 ? 0.001f * (float)random.NextDouble() : roll < 0.35 ? 0.5f * (float)random.NextDouble() : 1f / 60f;
            times.Add(times[^1] + gap);
        }

        float end = times[^1];
        var pose = new RootPose(new Vector3(0f, 1f, 0f), Quaternion.Identity);
        var frames = times.Select((t, k) =>
        {
            float[] angles = new float[model.Rig.DofCount];
            angles[0] = k;
            return new AnimationFrame(t, new RootPose(new Vector3(k, 1f, 0f), Quaternion.Identity), angles);
        }).ToList();

        // A "jump" of the middle third with lead-in and lead-out around it: the root away from the jump comes from the frames.
        var node = new RoadmapNode(0, pose, new FrictionCone(Vector3.UnitY, 1f), []);
        float leadIn = end / 3f;
        var animation = new JumpAnimation(model, [new Jump(node, node, new BallisticArc(pose, pose, Vector3.Zero, end / 3f, 0f))], [], frames, [], [], 0, 0, leadIn, end - leadIn - (end / 3f));

        float[] sampled = new float[model.Rig.DofCount];
        var probes = times.Concat(times.Zip(times.Skip(1), (a, b) => 0.5f * (a + b))).Concat(Enumerable.Range(0, 2_000).Select(_ => (float)((random.NextDouble() * 1.2 * end) - (0.1 * end)))).Append(-1f).Append(end + 1f).ToList();
        int carried = 0;
        Assert.Multiple(() =>
        {
            foreach (float t in probes)
            {
                RootPose root = animation.RootAt(t);
                Assert.That(animation.RootAt(t, ref carried), Is.EqualTo(root), $"the root at {t} s from the last probe's frame");
                foreach (int h in new[] { -1, 0, times.Count / 2, times.Count - 1, times.Count, int.MaxValue, random.Next(-2, times.Count + 2) })
                {
                    int hint = h;
                    Assert.That(animation.RootAt(t, ref hint), Is.EqualTo(root), $"the root at {t} s from frame {h}");
                }

                // The reference: the first frame at or after t by a scan (the last one when none is), and the one before it.
                int hi = times.FindIndex(f => f >= t);
                hi = hi < 0 ? times.Count - 1 : hi;
                int lo = Math.Max(0, hi - 1);
                float span = times[hi] - times[lo];
                float w = span > 0f ? Math.Clamp((t - times[lo]) / span, 0f, 1f) : 1f;
                float expected = float.Lerp(lo, hi, w);
                animation.Sample(t, sampled);
                Assert.That(sampled[0], Is.EqualTo(expected), $"the angle at {t} s (frames {lo} and {hi})");
                if (t < leadIn - 1e-3f || t > (2f * leadIn) + 1e-3f)
                {
                    Assert.That(animation.RootAt(t).Position.X, Is.EqualTo(expected), $"the root off the jump at {t} s");
                }
            }
        });
    }
}
