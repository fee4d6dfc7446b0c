using System.Numerics;
using System.Text.Json.Nodes;
using Ballistic.Authoring.Animation;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Gltf;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Tests.Reports;

/// <summary>The animated GLB of a path with walks: keyed at every frame of the clip, the root on the walks as on the jumps.</summary>
public sealed class WalkGlbTests
{
    [Test]
    public void TheClipIsKeyedThroughTheWalksWithTheRootOnThem()
    {
        JumpAnimation animation = WalkPlans.Animation;
        GltfDocument document = GltfDocument.Parse(AnimatedGlbWriter.ToBytes(animation, "moves"), "skeleton.glb", null);
        var clip = (JsonObject)document.Array("animations")[0]!;
        Assert.That((string?)clip["name"], Is.EqualTo("moves"));
        var samplers = (JsonArray)clip["samplers"]!;
        float[] times = document.ReadFloats(samplers[0]!["input"]!.GetValue<int>(), 1);
        JsonNode rootChannel = ((JsonArray)clip["channels"]!).Single(c => c!["target"]!["node"]!.GetValue<int>() == 1 && (string?)c["target"]!["path"] == "translation")!;
        float[] root = document.ReadFloats(samplers[rootChannel["sampler"]!.GetValue<int>()]!["output"]!.GetValue<int>(), 3);

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
