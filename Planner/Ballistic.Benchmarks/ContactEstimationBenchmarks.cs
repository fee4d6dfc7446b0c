using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using BenchmarkDotNet.Attributes;

namespace Ballistic.Benchmarks;

/// <summary>
/// The paper's FINDCONTACTS and COMPUTECONE for the skeleton on the bundled desert (47,636 triangles of about 90 cm²
/// each: a foot's workspace meets a hundred): 3,200 trunk poses, those of the first 400 nodes of a 1,000-node jump
/// roadmap, each turned to eight yaws and raised or lowered 5 cm. Sampling, the facing of a query's jumps and the
/// placement of its ends spend most of their time here.
/// </summary>
[MemoryDiagnoser]
[MedianColumn]
public class ContactEstimationBenchmarks
{
    private const int Count = 3_200;
    private PlanningScene _scene = null!;
    private RootPose[] _poses = [];

    /// <summary>Bakes the roadmap and turns its stances.</summary>
    [GlobalSetup]
    public void Setup()
    {
        _scene = PlanningScene.Create(BundledLevels.Load("desert"), CharacterPresets.Skeleton());
        Roadmap roadmap = new RoadmapBaker(_scene).Bake(new BakeSettings { Locomotion = Locomotion.Jump, Seed = 7, MaxNodes = 1_000 }).Roadmap;
        _poses = [.. roadmap.Nodes.Take(Count / 8).SelectMany(n => Enumerable.Range(0, 8).Select(k =>
            new RootPose(n.Pose.Position + new Vector3(0f, (0.05f * (k % 3)) - 0.05f, 0f), n.Pose.Rotation * Quaternion.CreateFromAxisAngle(Vector3.UnitY, k * 0.7f))))];
    }

    /// <summary>One pose's contacts and cone (its trunk known to be free), averaged over the 3,200; returns the valid ones.</summary>
    [Benchmark(OperationsPerInvoke = Count)]
    public int EvaluateContacts()
    {
        int valid = 0;
        foreach (RootPose pose in _poses)
        {
            valid += _scene.Estimator.EvaluateContacts(pose).IsValid ? 1 : 0;
        }

        return valid;
    }
}
