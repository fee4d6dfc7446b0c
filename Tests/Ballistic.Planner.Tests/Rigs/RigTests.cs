using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Authoring.Rigs;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;

namespace Ballistic.Planner.Tests.Rigs;

public sealed class RigTests
{
    internal static readonly Lazy<CharacterModel> Humanoid = new(() => HumanoidBuilder.Build("skeleton", handsOnWalls: false));

    [Test]
    public void HumanoidHasAboutFortyDegreesOfFreedomAndStandsOnItsFeet()
    {
        CharacterModel model = Humanoid.Value;
        Rig rig = model.Rig;
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), model.ContactPose, positions, rotations);
        RigLimb left = model.Limbs[0];
        Vector3 sole = left.EffectorPosition(positions, rotations);
        Assert.Multiple(() =>
        {
            Assert.That(rig.DofCount, Is.InRange(36, 44));
            Assert.That(model.Limbs.Select(l => l.Name), Is.EqualTo(new[] { "left_foot", "right_foot", "left_hand", "right_hand" }));
            Assert.That(sole.Y, Is.LessThan(-0.6f), "feet below the trunk centre");
            Assert.That(sole.X, Is.GreaterThan(0f), "the left foot is on +X");
            Assert.That(Vector3.Dot(left.EffectorNormal(rotations), -Vector3.UnitY), Is.GreaterThan(0.8f), "soles face down when standing");
        });
    }

    [Test]
    public void WorldAxesMatchFiniteDifferencesOfTheEffector()
    {
        CharacterModel model = Humanoid.Value;
        Rig rig = model.Rig;
        var random = new Random(8);
        var root = new RootPose(new Vector3(1f, 2f, 3f), Quaternion.CreateFromAxisAngle(Vector3.Normalize(new Vector3(0.3f, 1f, 0.2f)), 0.7f));
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        var moved = new Vector3[rig.Joints.Count];
        var movedRotations = new Quaternion[rig.Joints.Count];
        foreach (RigLimb limb in model.Limbs)
        {
            float[] q = RandomPose(rig, limb, random, model.ContactPose);
            rig.Solve(root, q, positions, rotations);
            Vector3 p = limb.EffectorPosition(positions, rotations);
            foreach (int d in limb.ChainDofs)
            {
                Vector3 predicted = Vector3.Cross(rig.WorldAxis(d, q, rotations), p - positions[rig.JointOfDof(d)]);
                const float h = 1e-3f;
                float[] q2 = (float[])q.Clone();
                q2[d] += h;
                rig.Solve(root, q2, moved, movedRotations);
                Vector3 measured = (limb.EffectorPosition(moved, movedRotations) - p) / h;
                Assert.That(Vector3.Distance(predicted, measured), Is.LessThan(2e-3f + (0.01f * predicted.Length())), $"{limb.Name}, dof {d}");
            }
        }
    }

    [Test]
    public void IkReachesReachableTargetsWithinAMillimetreAndKeepsLimits([Values] bool useMathNet)
    {
        CharacterModel model = Humanoid.Value;
        Rig rig = model.Rig;
        var ik = new LimbIk(rig, new IkSettings { UseMathNet = useMathNet });
        var random = new Random(21);
        var root = new RootPose(Vector3.Zero, Quaternion.CreateFromAxisAngle(Vector3.UnitY, 0.5f));
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        int solved = 0;
        const int cases = 200;
        for (int i = 0; i < cases; i++)
        {
            RigLimb limb = model.Limbs[i % model.Limbs.Count];
            float[] goal = RandomPose(rig, limb, random, model.ContactPose);
            rig.Solve(root, goal, positions, rotations);
            Vector3 target = limb.EffectorPosition(positions, rotations);
            Vector3 normal = limb.EffectorNormal(rotations);

            float[] q = (float[])model.ContactPose.Clone();
            IkResult result = ik.Solve(root, q, limb, target, normal, seed: i);
            if (!result.Success)
            {
                Assert.That(q, Is.EqualTo(model.ContactPose), "a failed solve leaves the configuration untouched");
                continue;
            }

            solved++;
            rig.Solve(root, q, positions, rotations);
            Assert.That(Vector3.Distance(limb.EffectorPosition(positions, rotations), target), Is.LessThanOrEqualTo(1e-3f), $"case {i}");
            Assert.That(MathF.Acos(Math.Clamp(Vector3.Dot(limb.EffectorNormal(rotations), normal), -1f, 1f)), Is.LessThanOrEqualTo(15f * MathF.PI / 180f), $"case {i}");
            Assert.That(rig.WithinLimits(q), Is.True, $"case {i}: joint limits");
            for (int d = 0; d < q.Length; d++)
            {
                if (!limb.ChainDofs.Contains(d))
                {
                    Assert.That(q[d], Is.EqualTo(model.ContactPose[d]), $"case {i}: dof {d} is not in the limb and must not move");
                }
            }
        }

        Assert.That(solved, Is.GreaterThanOrEqualTo(cases * 95 / 100), "reachable targets are reached");
    }

    [Test]
    public void IkReleasingLimitsTracksTargetsWithAJointAtItsLimit([Values] bool useMathNet)
    {
        // Holding a foot while the trunk moves: each target is a small step from where the limb is, and is reached by
        // a pose with one joint at its limit (an ankle that cannot bend further). A solver that keeps pushing that
        // joint into its limit stalls a millimetre or two short; one that lets the other joints make up for it does
        // not. Few iterations and no restarts, as when tracking.
        CharacterModel model = Humanoid.Value;
        Rig rig = model.Rig;
        var ik = new LimbIk(rig, new IkSettings { Restarts = 0, MaxIterations = 24, NormalTolerance = 5f * MathF.PI / 180f, UseMathNet = useMathNet, ReleaseLimits = true });
        var random = new Random(8);
        var root = new RootPose(Vector3.Zero, Quaternion.Identity);
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        int solved = 0;
        const int cases = 300;
        for (int i = 0; i < cases; i++)
        {
            RigLimb limb = model.Limbs[i % 2];
            float[] start = RandomPose(rig, limb, random, model.ContactPose);
            int pinned = limb.ChainDofs[random.Next(limb.ChainDofs.Count)];
            start[pinned] = random.Next(2) == 0 ? rig.Dofs[pinned].Min : rig.Dofs[pinned].Max;
            float[] goal = (float[])start.Clone();
            foreach (int d in limb.ChainDofs)
            {
                if (d != pinned)
                {
                    goal[d] = rig.Dofs[d].Clamp(goal[d] + (0.1f * ((2f * (float)random.NextDouble()) - 1f)));
                }
            }

            // The start leans into the limit: the pinned joint, left free, would go past it to reach the target.
            rig.Solve(root, goal, positions, rotations);
            Vector3 target = limb.EffectorPosition(positions, rotations);
            Vector3 normal = limb.EffectorNormal(rotations);
            float[] q = (float[])start.Clone();
            if (ik.Solve(root, q, limb, target, normal).Success)
            {
                solved++;
                rig.Solve(root, q, positions, rotations);
                Assert.That(Vector3.Distance(limb.EffectorPosition(positions, rotations), target), Is.LessThanOrEqualTo(1e-3f), $"case {i}");
                Assert.That(rig.WithinLimits(q), Is.True, $"case {i}: joint limits");
            }
        }

        TestContext.Out.WriteLine($"{solved} of {cases} tracked");
        Assert.That(solved, Is.GreaterThanOrEqualTo(cases * 98 / 100), "targets next to the limb, reached with a joint at its limit, are tracked");
    }

    [Test]
    public void IkReportsUnreachableTargetsAsFailures()
    {
        CharacterModel model = Humanoid.Value;
        var ik = new LimbIk(model.Rig);
        var root = new RootPose(Vector3.Zero, Quaternion.Identity);
        foreach (RigLimb limb in model.Limbs)
        {
            float[] q = (float[])model.ContactPose.Clone();
            IkResult far = ik.Solve(root, q, limb, new Vector3(0f, -3f, 2f), null);
            IkResult behindHead = ik.Solve(root, q, limb, new Vector3(0f, 0.5f, -0.9f), -Vector3.UnitY);
            Assert.Multiple(() =>
            {
                Assert.That(far.Success, Is.False, limb.Name);
                Assert.That(far.PositionError, Is.GreaterThan(1f), limb.Name);
                Assert.That(behindHead.Success, Is.False, limb.Name);
                Assert.That(q, Is.EqualTo(model.ContactPose), limb.Name);
            });
        }
    }

    [Test]
    public void SmallSolverAndMathNetAgree()
    {
        var random = new Random(4);
        for (int trial = 0; trial < 50; trial++)
        {
            int m = trial % 2 == 0 ? 3 : 5;
            int n = 3 + random.Next(8);
            double[] j = [.. Enumerable.Range(0, m * n).Select(_ => random.NextDouble() - 0.5)];
            double[] e = [.. Enumerable.Range(0, m).Select(_ => random.NextDouble() - 0.5)];
            double[] a = new double[n];
            double[] b = new double[n];
            LimbIk.SolveSmall(j, e, a, m, n, 0.03);
            LimbIk.SolveMathNet(j, e, b, m, n, 0.03);
            for (int k = 0; k < n; k++)
            {
                Assert.That(a[k], Is.EqualTo(b[k]).Within(1e-9 + (1e-7 * Math.Abs(b[k]))));
            }
        }
    }

    /// <summary>
    /// <see cref="LimbIk.Reaches"/> is <see cref="LimbIk.Solve(in RootPose, Span{float}, RigLimb, Vector3, Vector3?, int)"/>'s
    /// success, leaving the same angles, for targets on both sides of what a chain reaches (0.5 to 1.5 times its reach
    /// from the limb's first joint, with and without a normal, every limb of the humanoid and the ant, with the solver
    /// settings the walk's sole uses and the default ones); and no pose of a chain puts its contact point farther from
    /// its first joint than <see cref="LimbIk.ChainReach"/>, the bound past which <c>Reaches</c> fails at once.
    /// </summary>
    [Test]
    public void ReachesIsTheSolvesSuccessAndItsBoundHoldsEveryPose()
    {
        var random = new Random(31);
        var root = new RootPose(new Vector3(0.5f, 1f, -1f), Quaternion.CreateFromAxisAngle(Vector3.UnitY, 0.8f));
        int outOfReach = 0;
        int solved = 0;
        foreach (CharacterModel model in new[] { Humanoid.Value, CharacterPresets.Model("ant") })
        {
            Rig rig = model.Rig;
            var positions = new Vector3[rig.Joints.Count];
            var rotations = new Quaternion[rig.Joints.Count];
            foreach (IkSettings settings in new[] { new IkSettings(), new IkSettings { Restarts = 0, MaxIterations = 16, NormalTolerance = 0.1f, ReleaseLimits = true } })
            {
                var ik = new LimbIk(rig, settings);
                foreach (RigLimb limb in model.Limbs)
                {
                    float reach = ik.ChainReach(limb);
                    for (int trial = 0; trial < 24; trial++)
                    {
                        float[] pose = RandomPose(rig, limb, random, model.ContactPose);
                        rig.Solve(root, pose, positions, rotations);
                        Assert.That(Vector3.Distance(limb.EffectorPosition(positions, rotations), positions[limb.RootJoint]), Is.LessThanOrEqualTo(reach + 1e-4f), $"{model.Name}, {limb.Name}: a pose beyond the chain's reach");
                        Vector3 direction = Vector3.Normalize(new Vector3((float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.8f, (float)random.NextDouble() - 0.5f));
                        float share = 0.5f + (float)random.NextDouble();
                        Vector3 target = positions[limb.RootJoint] + (direction * (share * reach));
                        Vector3? normal = trial % 2 == 0 ? -Vector3.UnitY : null;
                        float[] solving = (float[])model.ContactPose.Clone();
                        float[] reaching = (float[])model.ContactPose.Clone();
                        bool success = ik.Solve(root, solving, limb, target, normal, seed: trial).Success;
                        bool reaches = ik.Reaches(root, reaching, limb, target, normal, seed: trial);
                        Assert.That(reaches, Is.EqualTo(success), $"{model.Name}, {limb.Name}, {share:0.00} of its reach");
                        Assert.That(reaching, Is.EqualTo(solving), $"{model.Name}, {limb.Name}: the angles left");
                        outOfReach += share * reach > reach + settings.PositionTolerance + LimbIk.ReachSlack ? 1 : 0;
                        solved += success ? 1 : 0;
                    }
                }
            }
        }

        Assert.Multiple(() =>
        {
            Assert.That(outOfReach, Is.GreaterThan(50), "targets out of reach");
            Assert.That(solved, Is.GreaterThan(50), "targets reached");
        });
    }

    /// <summary>The small solver reads its Jacobian by reference: spans too short for the step asked are refused, not read past.</summary>
    [Test]
    public void FiveRowProductsSideBySideAreTheRowByRowProductsBitForBit()
    {
        var random = new Random(17);
        for (int n = 1; n <= 12; n++)
        {
            for (int trial = 0; trial < 50; trial++)
            {
                // Values of very different sizes and signs, some exactly zero (a column dropped at its limit), so that
                // any other order of the sums would round differently somewhere.
                double[] j = [.. Enumerable.Range(0, 5 * n).Select(_ => random.Next(6) == 0 ? 0.0 : (random.NextDouble() - 0.5) * Math.Pow(10, random.Next(-6, 3)))];
                double damping = 0.03 * random.NextDouble();
                double[] byRows = new double[25];
                double[] sideBySide = new double[25];
                LimbIk.Products(ref j[0], 5, n, byRows, damping);
                LimbIk.Products5(ref j[0], n, sideBySide, damping * damping);
                Assert.That(sideBySide, Is.EqualTo(byRows).AsCollection, $"{n} columns, trial {trial}");
            }
        }
    }

    /// <summary>
    /// The small solver's unrolled shapes (five rows, three rows) give the step its loops give to the last bit:
    /// Jacobians of one to twelve columns whose values differ in size by up to nine orders and are sometimes exactly
    /// zero (a column dropped at its limit), dampings down to none (a system near singular, its diagonal floored).
    /// </summary>
    [Test]
    public void UnrolledSmallSolvesAreTheLoopsStepsBitForBit()
    {
        var random = new Random(23);
        int compared = 0;
        foreach (int m in new[] { 3, 5 })
        {
            for (int n = 1; n <= 12; n++)
            {
                for (int trial = 0; trial < 60; trial++)
                {
                    double[] j = [.. Enumerable.Range(0, m * n).Select(_ => random.Next(6) == 0 ? 0.0 : (random.NextDouble() - 0.5) * Math.Pow(10, random.Next(-6, 3)))];
                    double[] e = [.. Enumerable.Range(0, m).Select(_ => (random.NextDouble() - 0.5) * Math.Pow(10, random.Next(-4, 1)))];
                    double damping = trial % 10 == 0 ? 0.0 : 0.03 * random.NextDouble();
                    double[] unrolled = new double[n];
                    double[] looped = new double[n];
                    LimbIk.SolveSmall(j, e, unrolled, m, n, damping);
                    double[] a = new double[25];
                    LimbIk.Products(ref j[0], m, n, a, damping);
                    LimbIk.SolveRows(a, j, e, looped, m, n);
                    long[] unrolledBits = [.. unrolled.Select(BitConverter.DoubleToInt64Bits)];
                    long[] loopedBits = [.. looped.Select(BitConverter.DoubleToInt64Bits)];
                    Assert.That(unrolledBits, Is.EqualTo(loopedBits).AsCollection, $"{m} rows, {n} columns, trial {trial}");
                    compared += looped.Count(v => v != 0 && double.IsFinite(v));
                }
            }
        }

        Assert.That(compared, Is.GreaterThan(5000), "nonzero finite steps compared");
    }

    [Test]
    public void SmallSolverRefusesSpansTooShortForTheStep()
    {
        double[] e = [0.1, 0.2, 0.3];
        double[] dq = new double[4];
        Assert.Multiple(() =>
        {
            Assert.That(() => LimbIk.SolveSmall(new double[11], e, dq, 3, 4, 0.03), Throws.ArgumentException, "Jacobian of 11 for 3 × 4");
            Assert.That(() => LimbIk.SolveSmall(new double[12], e.AsSpan(0, 2), dq, 3, 4, 0.03), Throws.ArgumentException, "error of 2 for 3 rows");
            Assert.That(() => LimbIk.SolveSmall(new double[12], e, dq.AsSpan(0, 3), 3, 4, 0.03), Throws.ArgumentException, "step of 3 for 4 columns");
            Assert.That(() => LimbIk.SolveSmall(new double[24], new double[6], dq, 6, 4, 0.03), Throws.ArgumentException, "6 rows");
        });
    }

    [Test]
    public void DerivedReducedModelPutsFeetBelowAndHandsBesideTheTrunk()
    {
        ReducedCharacter reduced = ReducedModelBuilder.Derive(Humanoid.Value, 2, 8f, 12f, 0.5f);
        Limb foot = reduced.Limbs[0];
        Limb hand = reduced.Limbs[2];
        Assert.Multiple(() =>
        {
            Assert.That(reduced.TrunkHalfExtents.Y, Is.InRange(0.3f, 0.6f));
            Assert.That(foot.WorkspaceCenter.Y + foot.WorkspaceHalfExtents.Y, Is.LessThan(0f), "the feet's workspace lies below the trunk centre");
            Assert.That(foot.WorkspaceCenter.Y - foot.WorkspaceHalfExtents.Y, Is.LessThan(-0.9f), "legs reach about a metre down");
            Assert.That(hand.WorkspaceCenter.X, Is.GreaterThan(0.1f), "left hand on the left");
            Assert.That(reduced.TakeoffSpeedMax, Is.EqualTo(8f));
        });
    }

    [Test]
    public void SolvingOneLimbsChainGivesItsJointsWhatAFullSolveGivesBitForBit()
    {
        CharacterModel model = Humanoid.Value;
        Rig rig = model.Rig;
        var random = new Random(11);
        var root = new RootPose(new Vector3(-2f, 0.9f, 4f), Quaternion.CreateFromAxisAngle(Vector3.UnitY, 2.1f));
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        var full = new Vector3[rig.Joints.Count];
        var fullRotations = new Quaternion[rig.Joints.Count];
        foreach (RigLimb limb in model.Limbs)
        {
            float[] before = RandomPose(rig, limb, random, model.ContactPose);
            float[] after = RandomPose(rig, limb, random, before);
            rig.Solve(root, before, positions, rotations);
            rig.SolveChain(root, limb.Chain, after, positions, rotations);
            rig.Solve(root, after, full, fullRotations);
            Assert.Multiple(() =>
            {
                for (int j = 0; j < rig.Joints.Count; j++)
                {
                    if (j != limb.EffectorJoint && rig.IsAncestor(limb.EffectorJoint, j))
                    {
                        continue; // below the effector (toes): not the chain's, left as they were
                    }

                    Assert.That(positions[j], Is.EqualTo(full[j]), $"{limb.Name}: joint {rig.Joints[j].Name}'s position");
                    Assert.That(rotations[j], Is.EqualTo(fullRotations[j]), $"{limb.Name}: joint {rig.Joints[j].Name}'s rotation");
                }

                Assert.That(positions[limb.EffectorJoint], Is.Not.EqualTo(RigPositions(rig, root, before)[limb.EffectorJoint]), $"{limb.Name}: the chain moved");
            });
        }
    }

    [Test]
    public void ALimbsTurnsGiveItsPoseAndAxesWhatTheWholeRigsSolveGivesBitForBit()
    {
        // The humanoid's limbs, and a limb whose chain starts at the rig's root joint, itself turning on two axes.
        var crane = new Rig(
            [
                new Joint("base", -1, Vector3.Zero, Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.4f), [new JointAxis(Vector3.UnitY, -3f, 3f), new JointAxis(Vector3.UnitX, -1f, 1f)]),
                new Joint("arm", 0, new Vector3(0f, 0.5f, 0f), Quaternion.Identity, [new JointAxis(Vector3.UnitX, -2f, 2f)]),
                new Joint("hand", 1, new Vector3(0f, 0.4f, 0.1f), Quaternion.CreateFromAxisAngle(Vector3.UnitY, 1.2f), [new JointAxis(Vector3.UnitZ, -1f, 1f), new JointAxis(Vector3.UnitX, -1f, 1f), new JointAxis(Vector3.UnitY, -1f, 1f)]),
            ],
            new Vector3(0f, 0.1f, 0f));
        var craneHand = new RigLimb(crane, "hand", LimbKind.Hand, "base", "hand", new Vector3(0f, 0.1f, 0f), Vector3.UnitY, NormalFilter.None);
        CharacterModel model = Humanoid.Value;
        var random = new Random(5);
        var root = new RootPose(new Vector3(1f, 0.8f, -3f), Quaternion.CreateFromAxisAngle(Vector3.Normalize(new Vector3(0.2f, 1f, 0.1f)), 0.7f));
        foreach ((Rig rig, RigLimb limb, float[] basis) in model.Limbs.Select(l => (model.Rig, l, model.ContactPose)).Append((crane, craneHand, crane.Neutral())))
        {
            for (int trial = 0; trial < 5; trial++)
            {
                float[] q = RandomPose(rig, limb, random, basis);
                var full = new Vector3[rig.Joints.Count];
                var fullRotations = new Quaternion[rig.Joints.Count];
                rig.Solve(root, q, full, fullRotations);
                var positions = new Vector3[rig.Joints.Count];
                var rotations = new Quaternion[rig.Joints.Count];
                rig.SolveChain(root, limb.Lineage, q, positions, rotations);
                var turned = new Vector3[rig.Joints.Count];
                var turnedRotations = new Quaternion[rig.Joints.Count];
                ((Span<Vector3>)full).CopyTo(turned);
                ((Span<Quaternion>)fullRotations).CopyTo(turnedRotations);
                var turns = new Quaternion[limb.ChainDofs.Count];
                rig.Turns(limb.ChainSpan, q, turns);
                rig.SolveChain(root, limb.ChainSpan, turns, turned, turnedRotations);
                var axes = new Vector3[limb.ChainDofs.Count];
                rig.WorldAxes(limb.ChainSpan, turns, fullRotations, axes);
                Assert.Multiple(() =>
                {
                    Assert.That(limb.Lineage[^limb.Chain.Count..], Is.EqualTo(limb.Chain), $"{limb.Name}: the lineage ends with the chain");
                    Assert.That(limb.Lineage[0], Is.EqualTo(0), $"{limb.Name}: the lineage starts at the root joint");
                    foreach (int j in limb.Lineage)
                    {
                        Assert.That(positions[j], Is.EqualTo(full[j]), $"{limb.Name}: joint {rig.Joints[j].Name}'s position from the lineage");
                        Assert.That(rotations[j], Is.EqualTo(fullRotations[j]), $"{limb.Name}: joint {rig.Joints[j].Name}'s rotation from the lineage");
                    }

                    foreach (int j in limb.Chain)
                    {
                        Assert.That(turned[j], Is.EqualTo(full[j]), $"{limb.Name}: joint {rig.Joints[j].Name}'s position from the turns");
                        Assert.That(turnedRotations[j], Is.EqualTo(fullRotations[j]), $"{limb.Name}: joint {rig.Joints[j].Name}'s rotation from the turns");
                    }

                    for (int c = 0; c < axes.Length; c++)
                    {
                        Assert.That(axes[c], Is.EqualTo(rig.WorldAxis(limb.ChainDofs[c], q, fullRotations)), $"{limb.Name}: the axis of degree of freedom {limb.ChainDofs[c]}");
                    }
                });
            }
        }
    }

    [Test]
    public void LimbsNamingMissingBonesAreRejectedByName()
    {
        Rig rig = Humanoid.Value.Rig;
        Assert.Multiple(() =>
        {
            Assert.That(() => new RigLimb(rig, "tail", LimbKind.Foot, "tailbone", "left_ankle", Vector3.Zero, -Vector3.UnitY, NormalFilter.None),
                Throws.TypeOf<RigException>().With.Message.Contains("'tailbone'").And.Message.Contains("tail"));
            Assert.That(() => new RigLimb(rig, "odd", LimbKind.Foot, "left_hip", "right_ankle", Vector3.Zero, -Vector3.UnitY, NormalFilter.None),
                Throws.TypeOf<RigException>().With.Message.Contains("not an ancestor"));
            Assert.That(() => new RigLimb(rig, "stiff", LimbKind.Foot, "pelvis", "pelvis", Vector3.Zero, -Vector3.UnitY, NormalFilter.None),
                Throws.TypeOf<RigException>().With.Message.Contains("no joints that move"));
        });
    }

    private static Vector3[] RigPositions(Rig rig, RootPose root, float[] q)
    {
        var positions = new Vector3[rig.Joints.Count];
        rig.Solve(root, q, positions, new Quaternion[rig.Joints.Count]);
        return positions;
    }

    private static float[] RandomPose(Rig rig, RigLimb limb, Random random, float[] basis)
    {
        float[] q = (float[])basis.Clone();
        foreach (int d in limb.ChainDofs)
        {
            JointAxis axis = rig.Dofs[d];
            q[d] = axis.Min + ((float)random.NextDouble() * (axis.Max - axis.Min));
        }

        return q;
    }
}
