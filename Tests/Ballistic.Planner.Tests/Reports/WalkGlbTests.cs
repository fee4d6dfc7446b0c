using System.Numerics;
using Ballistic.Authoring.Animation;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Reports;

/// <summary>The animated GLB of a path with walks: keyed at every frame of the clip, the root on the walks as on the jumps.</summary>
public sealed class WalkGlbTests
{
    [Test]
    public void TheClipIsKeyedThroughTheWalksWithTheRootOnThem()
    {
        JumpAnimation animation = WalkPlans.Animation;
        SharpGLTF.Schema2.Animation clip = SharpGLTF.Schema2.ModelRoot.ParseGLB(AnimatedGlbWriter.ToBytes(animation, "moves")).LogicalAnimations[0];
        Assert.That(clip.Name, Is.EqualTo("moves"));
        (float[] times, float[] root) = GlbChannels.Of(clip)[(1, "translation")];

        Assert.That(times, Has.Length.EqualTo(animation.Frames.Count));
        Assert.That(times[^1], Is.EqualTo(animation.Duration).Within(1f / 30f), "the clip runs to the end of the last walk");
        Rig rig = animation.Model.Rig;
        int walkFrames = 0;
        for (int f = 0; f < times.Length; f++)
        {
            AnimationFrame frame = animation.Frames[f];
            Assert.That(times[f], Is.EqualTo(frame.Time).Within(1e-6f));
            if (animation.Moves[animation.MoveIndex(frame.Time)] is Walk walk && frame.Time < animation.MoveEnd(animation.MoveIndex(frame.Time)))
            {
                walkFrames++;
                Vector3 expected = walk.PoseAt(frame.Time - animation.MoveStart(animation.MoveIndex(frame.Time))).ToWorld(rig.RootOffset + rig.Joints[0].Offset);
                Assert.That(Vector3.Distance(new Vector3(root[3 * f], root[(3 * f) + 1], root[(3 * f) + 2]), expected), Is.LessThan(1e-4f), $"root at {frame.Time:0.000} s");
            }
        }

        Assert.That(walkFrames, Is.GreaterThan(30), "frames during the walks");
    }
}
