using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using BenchmarkDotNet.Attributes;

namespace Ballistic.Benchmarks;

/// <summary>Whole-body synthesis of the skeleton on a path across the generated desert: one contact pose, one jump.</summary>
[MemoryDiagnoser]
public class AnimationBenchmarks
{
    private JumpAnimator _animator = null!;
    private Jump[] _jumps = [];
    private int _next;

    /// <summary>Plans a path across the desert and prepares the animator (its limb databases).</summary>
    [GlobalSetup]
    public void Setup()
    {
        PlanningScene scene = DesertCrossing.Scene();
        (Vector3 from, Vector3 to) = DesertCrossing.Ends(scene);
        BakeResult bake = new RoadmapBaker(scene).Bake(new BakeSettings { Locomotion = Locomotion.Jump, MaxNodes = 600, Start = from, Goal = to, StopWhenConnected = true });
        _jumps = [.. new PathQuery(scene, bake.Roadmap).Plan(from, to).Jumps];
        _animator = new JumpAnimator(scene, CharacterPresets.Model("skeleton"));
    }

    /// <summary>One takeoff contact pose (projection of the reference pose, IK, bone checks, cone test).</summary>
    [Benchmark]
    public bool GenerateContactPose()
    {
        Jump jump = _jumps[_next++ % _jumps.Length];
        return _animator.Contacts.Generate(jump.Arc.Takeoff, jump.Takeoff.Contacts, jump.Arc.TakeoffVelocity).Valid;
    }

    /// <summary>One whole jump: contact poses, held contacts, apex, interpolation and bone checks.</summary>
    [Benchmark]
    public int SynthesiseJump()
    {
        Jump jump = _jumps[_next++ % _jumps.Length];
        return _animator.Animate([jump]).Frames.Count;
    }
}
