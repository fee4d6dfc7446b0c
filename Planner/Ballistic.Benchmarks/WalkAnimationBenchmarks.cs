using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using BenchmarkDotNet.Attributes;

namespace Ballistic.Benchmarks;

/// <summary>
/// Whole-body synthesis of the skeleton's longest walk on the default walk-and-jump path across the generated desert
/// (the demo's request): the gait, its repairs and the hold refinement. Each invocation gets a fresh animator, so the
/// gait's remembered clips never answer it.
/// </summary>
[MemoryDiagnoser]
[MedianColumn]
public class WalkAnimationBenchmarks
{
    private PlanningScene _scene = null!;
    private Walk _walk = null!;
    private JumpAnimator _animator = null!;

    /// <summary>Plans the desert request with walks and keeps its longest walk.</summary>
    [GlobalSetup]
    public void Setup()
    {
        _scene = DesertCrossing.Scene();
        (Vector3 from, Vector3 to) = DesertCrossing.Ends(_scene);
        BakeResult bake = new RoadmapBaker(_scene).Bake(new BakeSettings { MaxNodes = 600, Start = from, Goal = to, StopWhenConnected = true });
        _walk = new PathQuery(_scene, bake.Roadmap).Plan(from, to).Moves.OfType<Walk>().MaxBy(w => w.Duration)
            ?? throw new InvalidOperationException("The desert request found no walk to animate.");
    }

    /// <summary>A fresh animator (its limb databases built, no clip remembered).</summary>
    [IterationSetup]
    public void FreshAnimator() => _animator = new JumpAnimator(_scene, CharacterPresets.Model("skeleton"));

    /// <summary>One walk animated: footholds, swings, hips, arms, repairs, hold refinement and bone checks.</summary>
    [Benchmark]
    [InvocationCount(1, 1)]
    public int AnimateWalk() => _animator.Animate([_walk]).Frames.Count;
}
