using System.Numerics;
using Ballistic.Authoring.Rigs;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;
using BenchmarkDotNet.Attributes;

namespace Ballistic.Benchmarks;

/// <summary>Limb IK on the humanoid: the built-in small Cholesky against MathNet.Numerics for the damped systems.</summary>
[MemoryDiagnoser]
public class IkBenchmarks
{
    private CharacterModel _model = null!;
    private LimbIk _ik = null!;
    private (RigLimb Limb, Vector3 Target, Vector3 Normal)[] _targets = [];
    private int _next;

    /// <summary>Which linear solver the IK uses.</summary>
    [Params(false, true)]
    public bool UseMathNet { get; set; }

    /// <summary>Reachable targets: forward kinematics of random limb configurations.</summary>
    [GlobalSetup]
    public void Setup()
    {
        _model = HumanoidBuilder.Build("skeleton", handsOnWalls: false);
        _ik = new LimbIk(_model.Rig, new IkSettings { UseMathNet = UseMathNet });
        var random = new Random(5);
        var positions = new Vector3[_model.Rig.Joints.Count];
        var rotations = new Quaternion[_model.Rig.Joints.Count];
        var targets = new List<(RigLimb, Vector3, Vector3)>();
        for (int i = 0; i < 256; i++)
        {
            RigLimb limb = _model.Limbs[i % _model.Limbs.Count];
            float[] q = (float[])_model.ContactPose.Clone();
            foreach (int d in limb.ChainDofs)
            {
                q[d] = _model.Rig.Dofs[d].Min + ((float)random.NextDouble() * (_model.Rig.Dofs[d].Max - _model.Rig.Dofs[d].Min));
            }

            _model.Rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), q, positions, rotations);
            targets.Add((limb, limb.EffectorPosition(positions, rotations), limb.EffectorNormal(rotations)));
        }

        _targets = [.. targets];
    }

    /// <summary>One limb solve (position and normal) from the contact pose.</summary>
    [Benchmark]
    public bool SolveLimb()
    {
        (RigLimb limb, Vector3 target, Vector3 normal) = _targets[_next++ % _targets.Length];
        float[] q = (float[])_model.ContactPose.Clone();
        return _ik.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), q, limb, target, normal).Success;
    }
}
