using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using Ballistic.Planner.Geometry;
using MathNet.Numerics.LinearAlgebra;
using DenseVector = MathNet.Numerics.LinearAlgebra.Vector<double>;

namespace Ballistic.Planner.Rigs;

/// <summary>
/// Damped-least-squares inverse kinematics for one limb with the root locked: moves only the limb chain's angles,
/// within their limits, to put the effector's contact point on a target and, optionally, its contact normal along a
/// target normal. Δq = Jᵀ (J Jᵀ + λ² I)⁻¹ e, clamped, repeated; with <see cref="IkSettings.ReleaseLimits"/>, a
/// joint at a limit the step would push it past is left out of that step (so the others make up for it instead of
/// the solver stalling against the limit); restarts from other configurations when stuck.
/// A target it cannot reach is reported as a failure and leaves the configuration untouched.
/// </summary>
internal sealed class LimbIk
{
    private const int MaxRows = 5;

    /// <summary>Radians within which an angle counts as at its limit.</summary>
    private const float LimitSlack = 1e-5f;

    /// <summary>Creates a solver for a rig.</summary>
    public LimbIk(Rig rig, IkSettings? settings = null)
    {
        ArgumentNullException.ThrowIfNull(rig);
        Rig = rig;
        Settings = settings ?? new IkSettings();
    }

    /// <summary>The rig.</summary>
    public Rig Rig { get; }

    /// <summary>Solver parameters.</summary>
    public IkSettings Settings { get; }

    /// <summary>
    /// Moves <paramref name="limb"/>'s angles in <paramref name="q"/> so that its contact point reaches
    /// <paramref name="target"/> (world metres) and, when given, its contact normal points along
    /// <paramref name="targetNormal"/>.
    /// </summary>
    /// <param name="root">Root pose, fixed.</param>
    /// <param name="q">Configuration: read as the starting point, updated only on success.</param>
    /// <param name="limb">The limb to move.</param>
    /// <param name="target">Target contact point, world metres.</param>
    /// <param name="targetNormal">Target contact normal (unit, world), or <c>null</c> for position only.</param>
    /// <param name="seed">Seed of the restarts' starting configurations.</param>
    public IkResult Solve(in RootPose root, Span<float> q, RigLimb limb, Vector3 target, Vector3? targetNormal, int seed = 0) =>
        Solve(root, q, limb, target, targetNormal, seed, []);

    /// <summary>
    /// As <see cref="Solve(in RootPose, Span{float}, RigLimb, Vector3, Vector3?, int)"/>; on failure, when
    /// <paramref name="nearest"/> is as long as <paramref name="q"/>, it receives the configuration of the attempt that
    /// ended nearest its target (where a stalled solve stopped, its face already turned toward the normal).
    /// </summary>
    internal IkResult Solve(in RootPose root, Span<float> q, RigLimb limb, Vector3 target, Vector3? targetNormal, int seed, Span<float> nearest) =>
        Solve(root, q, limb, target, targetNormal, seed, nearest, giveUpOutOfReach: false);

    /// <summary>
    /// Whether <see cref="Solve(in RootPose, Span{float}, RigLimb, Vector3, Vector3?, int)"/> succeeds, moving
    /// <paramref name="q"/> as it does; for callers that need nothing else of a failure. A target farther from the
    /// limb's first joint (which the limb's own angles do not move) than the chain reaches, with the tolerance and
    /// <see cref="ReachSlack"/> to spare, fails at once: no pose of the chain holds it, so the solve would fail too,
    /// after all its iterations (a fifth of a walk's failed solves on the desert, a sixth of its IK's iterations).
    /// </summary>
    internal bool Reaches(in RootPose root, Span<float> q, RigLimb limb, Vector3 target, Vector3? targetNormal, int seed = 0) =>
        Solve(root, q, limb, target, targetNormal, seed, [], giveUpOutOfReach: true).Success;

    /// <summary>How much farther (metres) than the chain reaches plus the tolerance a target must be to fail without iterating: far more than rounding.</summary>
    internal const float ReachSlack = 1e-3f;

    /// <summary>The farthest <paramref name="limb"/>'s contact point can be from its first joint (metres): the lengths of the chain's links and of the contact offset.</summary>
    internal float ChainReach(RigLimb limb)
    {
        float reach = limb.EffectorOffset.Length();
        for (int i = 1; i < limb.Chain.Count; i++)
        {
            reach += Rig.Joints[limb.Chain[i]].Offset.Length();
        }

        return reach;
    }

    private IkResult Solve(in RootPose root, Span<float> q, RigLimb limb, Vector3 target, Vector3? targetNormal, int seed, Span<float> nearest, bool giveUpOutOfReach)
    {
        ArgumentNullException.ThrowIfNull(limb);
        if (q.Length != Rig.DofCount)
        {
            throw new ArgumentException($"The IK needs {Rig.DofCount} angles, not {q.Length}.", nameof(q));
        }

        float[] trial = s_trial is { } scratch && scratch.Length == q.Length ? scratch : s_trial = new float[q.Length];
        q.CopyTo(trial);
        int iterations = 0;
        IkResult best = new(false, float.PositiveInfinity, float.PositiveInfinity, 0);
        Random? random = null;
        for (int attempt = 0; attempt <= Settings.Restarts; attempt++)
        {
            if (attempt > 0)
            {
                random ??= new Random(seed);
                q.CopyTo(trial);
                foreach (int d in limb.ChainDofSpan)
                {
                    JointAxis axis = Rig.Dofs[d];
                    trial[d] = axis.Min + ((float)random.NextDouble() * (axis.Max - axis.Min));
                }
            }

            IkResult result = Iterate(root, trial, limb, target, targetNormal, giveUpOutOfReach, out bool outOfReach);
            iterations += result.Iterations;
            if (outOfReach)
            {
                return result; // the restarts move the chain only: out of its reach still
            }

            if (result.Success)
            {
                trial.CopyTo(q);
                return result with { Iterations = iterations };
            }

            if (result.PositionError < best.PositionError)
            {
                best = result;
                if (nearest.Length == trial.Length)
                {
                    trial.CopyTo(nearest);
                }
            }
        }

        return best with { Success = false, Iterations = iterations };
    }

    private IkResult Iterate(in RootPose root, float[] q, RigLimb limb, Vector3 target, Vector3? targetNormal, bool giveUpOutOfReach, out bool outOfReach)
    {
        int joints = Rig.Joints.Count;
        Span<Vector3> positions = joints <= 128 ? stackalloc Vector3[joints] : new Vector3[joints];
        Span<Quaternion> rotations = joints <= 128 ? stackalloc Quaternion[joints] : new Quaternion[joints];
        int n = limb.ChainDofs.Count;
        int rows = targetNormal is null ? 3 : 5;
        if (n > 64)
        {
            throw new RigException($"Limb '{limb.Name}' has {n} degrees of freedom; the IK handles at most 64.");
        }

        Span<double> jacobian = stackalloc double[rows * n];
        Span<double> error = stackalloc double[rows];
        Span<double> step = stackalloc double[n];
        Span<Vector3> axes = stackalloc Vector3[n];
        Span<Quaternion> turns = stackalloc Quaternion[n];
        ReadOnlySpan<int> chain = limb.ChainSpan;
        ReadOnlySpan<int> chainDofs = limb.ChainDofSpan;
        ReadOnlySpan<JointAxis> dofs = Rig.DofSpan;

        Vector3 goalNormal = targetNormal is Vector3 tn ? Vector3.Normalize(tn) : Vector3.UnitY;
        float positionError = float.PositiveInfinity;
        float normalError = 0f;
        // Only the chain's own joints and those that place it are read: the rest of the rig is not solved.
        Rig.SolveChain(root, limb.Lineage, q, positions, rotations);
        float beyond = giveUpOutOfReach ? Vector3.Distance(positions[limb.RootJoint], target) - ChainReach(limb) : 0f;
        outOfReach = beyond > Settings.PositionTolerance + ReachSlack;
        if (outOfReach)
        {
            return new IkResult(false, beyond, float.PositiveInfinity, 0);
        }
        for (int iteration = 0; iteration < Settings.MaxIterations; iteration++)
        {
            // Only the limb's own angles change from one iteration to the next: only its joints move. Each of their
            // turns is computed once, for the pose and for the axes.
            Rig.Turns(chain, q, turns);
            if (iteration > 0)
            {
                Rig.SolveChain(root, chain, turns, positions, rotations);
            }

            Vector3 p = limb.EffectorPosition(positions, rotations);
            Vector3 e = target - p;
            positionError = e.Length();
            Vector3 normal = limb.EffectorNormal(rotations);
            normalError = targetNormal is null ? 0f : MathF.Acos(Math.Clamp(Vector3.Dot(normal, goalNormal), -1f, 1f));
            bool positionOk = positionError <= Settings.PositionTolerance * 0.1f;
            bool normalOk = normalError <= Settings.NormalTolerance * 0.25f;
            if (positionOk && normalOk)
            {
                return new IkResult(true, positionError, normalError, iteration);
            }

            // Rows: position (3), then the normal's rotation error on two axes perpendicular to the current normal.
            Vector3 u = Vector3.Normalize(Vector3.Cross(normal, MathF.Abs(normal.X) < 0.9f ? Vector3.UnitX : Vector3.UnitY));
            Vector3 v = Vector3.Cross(normal, u);
            Vector3 omega = Vector3.Cross(normal, goalNormal);
            error[0] = e.X;
            error[1] = e.Y;
            error[2] = e.Z;
            if (rows == 5)
            {
                error[3] = Settings.NormalWeight * Vector3.Dot(omega, u);
                error[4] = Settings.NormalWeight * Vector3.Dot(omega, v);
            }

            Rig.WorldAxes(chain, turns, rotations, axes);
            for (int c = 0; c < n; c++)
            {
                int dof = chainDofs[c];
                Vector3 axis = axes[c];
                Vector3 linear = Vector3.Cross(axis, p - positions[Rig.JointOfDof(dof)]);
                jacobian[c] = linear.X;
                jacobian[n + c] = linear.Y;
                jacobian[(2 * n) + c] = linear.Z;
                if (rows == 5)
                {
                    jacobian[(3 * n) + c] = Settings.NormalWeight * Vector3.Dot(axis, u);
                    jacobian[(4 * n) + c] = Settings.NormalWeight * Vector3.Dot(axis, v);
                }
            }

            Solve(jacobian[..(rows * n)], error[..rows], step[..n], rows, n);

            // A joint held at a limit that the step pushes further cannot help: its column is dropped and the step
            // solved again, so that the other joints make up for it (else the solver stalls against the limit).
            bool dropped = false;
            for (int c = 0; c < n && Settings.ReleaseLimits; c++)
            {
                int dof = chainDofs[c];
                ref readonly JointAxis range = ref dofs[dof];
                if ((q[dof] <= range.Min + LimitSlack && step[c] < 0) || (q[dof] >= range.Max - LimitSlack && step[c] > 0))
                {
                    for (int r = 0; r < rows; r++)
                    {
                        jacobian[(r * n) + c] = 0;
                    }

                    dropped = true;
                }
            }

            if (dropped)
            {
                Solve(jacobian[..(rows * n)], error[..rows], step[..n], rows, n);
            }

            double largest = 0;
            for (int c = 0; c < n; c++)
            {
                largest = Math.Max(largest, Math.Abs(step[c]));
            }

            double scale = largest > Settings.MaxStep ? Settings.MaxStep / largest : 1.0;
            for (int c = 0; c < n; c++)
            {
                int dof = chainDofs[c];
                q[dof] = dofs[dof].Clamp(q[dof] + (float)(step[c] * scale));
            }
        }

        Rig.SolveChain(root, limb.Chain, q, positions, rotations);
        positionError = Vector3.Distance(target, limb.EffectorPosition(positions, rotations));
        normalError = targetNormal is null ? 0f : MathF.Acos(Math.Clamp(Vector3.Dot(limb.EffectorNormal(rotations), goalNormal), -1f, 1f));
        bool success = positionError <= Settings.PositionTolerance && normalError <= Settings.NormalTolerance;
        return new IkResult(success, positionError, normalError, Settings.MaxIterations);
    }

    /// <summary>The configuration a solve on this thread tries (one rig's degrees of freedom), kept between solves.</summary>
    [ThreadStatic]
    private static float[]? s_trial;

    /// <summary>One damped least-squares step, with the solver the settings choose.</summary>
    private void Solve(ReadOnlySpan<double> j, ReadOnlySpan<double> e, Span<double> dq, int m, int n)
    {
        if (Settings.UseMathNet)
        {
            SolveMathNet(j, e, dq, m, n, Settings.Damping);
        }
        else
        {
            SolveSmall(j, e, dq, m, n, Settings.Damping);
        }
    }

    /// <summary>
    /// Δq = Jᵀ (J Jᵀ + λ² I)⁻¹ e with a Cholesky factorisation of the small m × m system. The IK's two shapes (five
    /// rows: a position and a normal target; three: a position) are solved with every entry in a local
    /// (<see cref="SolveFive"/>, <see cref="SolveThree"/>): the same operations in the same order as the loops of
    /// <see cref="SolveRows"/>, so the same step to the last bit, without their index arithmetic and bounds checks.
    /// </summary>
    internal static void SolveSmall(ReadOnlySpan<double> j, ReadOnlySpan<double> e, Span<double> dq, int m, int n, double damping)
    {
        if (j.Length < m * n || e.Length < m || dq.Length < n || m > MaxRows)
        {
            throw new ArgumentException($"A {m} × {n} step needs a Jacobian of {m * n}, an error of {m} and a step of {n} values, at most {MaxRows} rows.");
        }

        // The products J Jᵀ by references into the rows (no bounds check per term: the lengths are checked above), each
        // sum in the same order as ever, so the step is the same to the last bit.
        ref double first = ref MemoryMarshal.GetReference(j);
        Span<double> a = stackalloc double[MaxRows * MaxRows];
        if (m == 5)
        {
            Products5(ref first, n, a, damping * damping);
            SolveFive(a, ref first, e, dq, n);
        }
        else if (m == 3)
        {
            Products(ref first, m, n, a, damping);
            SolveThree(a, ref first, e, dq, n);
        }
        else
        {
            Products(ref first, m, n, a, damping);
            SolveRows(a, j, e, dq, m, n);
        }
    }

    /// <summary>
    /// The small solver's loops (any number of rows up to <see cref="MaxRows"/>): the Cholesky factor L of
    /// <paramref name="a"/> (J Jᵀ + λ² I, its lower triangle, <paramref name="m"/> × <paramref name="m"/>) in place,
    /// then L Lᵀ x = e forward and back, then Δq = Jᵀ x. The reference the unrolled shapes are tested against.
    /// </summary>
    internal static void SolveRows(Span<double> a, ReadOnlySpan<double> j, ReadOnlySpan<double> e, Span<double> dq, int m, int n)
    {
        // Cholesky: A = L Lᵀ, in place in the lower triangle.
        for (int r = 0; r < m; r++)
        {
            for (int c = 0; c <= r; c++)
            {
                double sum = a[(r * m) + c];
                for (int k = 0; k < c; k++)
                {
                    sum -= a[(r * m) + k] * a[(c * m) + k];
                }

                a[(r * m) + c] = r == c ? Math.Sqrt(Math.Max(sum, 1e-18)) : sum / a[(c * m) + c];
            }
        }

        Span<double> x = stackalloc double[MaxRows];
        for (int r = 0; r < m; r++)
        {
            double sum = e[r];
            for (int k = 0; k < r; k++)
            {
                sum -= a[(r * m) + k] * x[k];
            }

            x[r] = sum / a[(r * m) + r];
        }

        for (int r = m - 1; r >= 0; r--)
        {
            double sum = x[r];
            for (int k = r + 1; k < m; k++)
            {
                sum -= a[(k * m) + r] * x[k];
            }

            x[r] = sum / a[(r * m) + r];
        }

        for (int c = 0; c < n; c++)
        {
            double sum = 0;
            for (int r = 0; r < m; r++)
            {
                sum += j[(r * n) + c] * x[r];
            }

            dq[c] = sum;
        }
    }

    /// <summary>The Cholesky factor's diagonal entry from what is left of the system's: never below √1e-18.</summary>
    private static double Diagonal(double rest) => Math.Sqrt(Math.Max(rest, 1e-18));

    /// <summary>
    /// <see cref="SolveRows"/> for five rows (<paramref name="a"/> filled by <see cref="Products5"/>, the Jacobian's
    /// rows of <paramref name="n"/> from <paramref name="first"/>), every subtraction in the loops' order.
    /// </summary>
    private static void SolveFive(ReadOnlySpan<double> a, ref double first, ReadOnlySpan<double> e, Span<double> dq, int n)
    {
        double l00 = Diagonal(a[0]);
        double l10 = a[5] / l00;
        double l11 = Diagonal(a[6] - (l10 * l10));
        double l20 = a[10] / l00;
        double l21 = (a[11] - (l20 * l10)) / l11;
        double l22 = Diagonal(a[12] - (l20 * l20) - (l21 * l21));
        double l30 = a[15] / l00;
        double l31 = (a[16] - (l30 * l10)) / l11;
        double l32 = (a[17] - (l30 * l20) - (l31 * l21)) / l22;
        double l33 = Diagonal(a[18] - (l30 * l30) - (l31 * l31) - (l32 * l32));
        double l40 = a[20] / l00;
        double l41 = (a[21] - (l40 * l10)) / l11;
        double l42 = (a[22] - (l40 * l20) - (l41 * l21)) / l22;
        double l43 = (a[23] - (l40 * l30) - (l41 * l31) - (l42 * l32)) / l33;
        double l44 = Diagonal(a[24] - (l40 * l40) - (l41 * l41) - (l42 * l42) - (l43 * l43));

        double x0 = e[0] / l00;
        double x1 = (e[1] - (l10 * x0)) / l11;
        double x2 = (e[2] - (l20 * x0) - (l21 * x1)) / l22;
        double x3 = (e[3] - (l30 * x0) - (l31 * x1) - (l32 * x2)) / l33;
        double x4 = (e[4] - (l40 * x0) - (l41 * x1) - (l42 * x2) - (l43 * x3)) / l44;

        x4 /= l44;
        x3 = (x3 - (l43 * x4)) / l33;
        x2 = (x2 - (l32 * x3) - (l42 * x4)) / l22;
        x1 = (x1 - (l21 * x2) - (l31 * x3) - (l41 * x4)) / l11;
        x0 = (x0 - (l10 * x1) - (l20 * x2) - (l30 * x3) - (l40 * x4)) / l00;

        ref double r1 = ref Unsafe.Add(ref first, n);
        ref double r2 = ref Unsafe.Add(ref first, 2 * n);
        ref double r3 = ref Unsafe.Add(ref first, 3 * n);
        ref double r4 = ref Unsafe.Add(ref first, 4 * n);
        for (int c = 0; c < n; c++)
        {
            dq[c] = 0 + (Unsafe.Add(ref first, c) * x0) + (Unsafe.Add(ref r1, c) * x1) + (Unsafe.Add(ref r2, c) * x2) + (Unsafe.Add(ref r3, c) * x3) + (Unsafe.Add(ref r4, c) * x4);
        }
    }

    /// <summary><see cref="SolveFive"/> for three rows (a position target; <paramref name="a"/> filled by <see cref="Products"/>).</summary>
    private static void SolveThree(ReadOnlySpan<double> a, ref double first, ReadOnlySpan<double> e, Span<double> dq, int n)
    {
        double l00 = Diagonal(a[0]);
        double l10 = a[3] / l00;
        double l11 = Diagonal(a[4] - (l10 * l10));
        double l20 = a[6] / l00;
        double l21 = (a[7] - (l20 * l10)) / l11;
        double l22 = Diagonal(a[8] - (l20 * l20) - (l21 * l21));

        double x0 = e[0] / l00;
        double x1 = (e[1] - (l10 * x0)) / l11;
        double x2 = (e[2] - (l20 * x0) - (l21 * x1)) / l22;

        x2 /= l22;
        x1 = (x1 - (l21 * x2)) / l11;
        x0 = (x0 - (l10 * x1) - (l20 * x2)) / l00;

        ref double r1 = ref Unsafe.Add(ref first, n);
        ref double r2 = ref Unsafe.Add(ref first, 2 * n);
        for (int c = 0; c < n; c++)
        {
            dq[c] = 0 + (Unsafe.Add(ref first, c) * x0) + (Unsafe.Add(ref r1, c) * x1) + (Unsafe.Add(ref r2, c) * x2);
        }
    }

    /// <summary>The lower triangle of J Jᵀ + λ² I (<paramref name="m"/> rows of <paramref name="n"/>, from <paramref name="first"/>) into <paramref name="a"/>, each sum over the columns in order.</summary>
    internal static void Products(ref double first, int m, int n, Span<double> a, double damping)
    {
        for (int r = 0; r < m; r++)
        {
            ref double row = ref Unsafe.Add(ref first, r * n);
            for (int c = 0; c <= r; c++)
            {
                ref double other = ref Unsafe.Add(ref first, c * n);
                double sum = 0;
                for (int k = 0; k < n; k++)
                {
                    sum += Unsafe.Add(ref row, k) * Unsafe.Add(ref other, k);
                }

                a[(r * m) + c] = sum + (r == c ? damping * damping : 0);
            }
        }
    }

    /// <summary>
    /// <see cref="Products"/> of five rows (a position and a normal target): the fifteen sums made side by side in one
    /// pass over the columns, each still over the columns in order (so the same to the last bit), instead of one after
    /// another: the IK's most frequent step, and its sums no longer wait on one another.
    /// </summary>
    internal static void Products5(ref double first, int n, Span<double> a, double dd)
    {
        double s00 = 0, s10 = 0, s11 = 0, s20 = 0, s21 = 0, s22 = 0, s30 = 0, s31 = 0, s32 = 0, s33 = 0, s40 = 0, s41 = 0, s42 = 0, s43 = 0, s44 = 0;
        ref double r0 = ref first;
        ref double r1 = ref Unsafe.Add(ref first, n);
        ref double r2 = ref Unsafe.Add(ref first, 2 * n);
        ref double r3 = ref Unsafe.Add(ref first, 3 * n);
        ref double r4 = ref Unsafe.Add(ref first, 4 * n);
        for (int k = 0; k < n; k++)
        {
            double j0 = Unsafe.Add(ref r0, k);
            double j1 = Unsafe.Add(ref r1, k);
            double j2 = Unsafe.Add(ref r2, k);
            double j3 = Unsafe.Add(ref r3, k);
            double j4 = Unsafe.Add(ref r4, k);
            s00 += j0 * j0;
            s10 += j1 * j0;
            s11 += j1 * j1;
            s20 += j2 * j0;
            s21 += j2 * j1;
            s22 += j2 * j2;
            s30 += j3 * j0;
            s31 += j3 * j1;
            s32 += j3 * j2;
            s33 += j3 * j3;
            s40 += j4 * j0;
            s41 += j4 * j1;
            s42 += j4 * j2;
            s43 += j4 * j3;
            s44 += j4 * j4;
        }

        // Off the diagonal the row-by-row loop adds 0 too: kept, so that each entry is made by the same operations.
        a[0] = s00 + dd;
        a[5] = s10 + 0;
        a[6] = s11 + dd;
        a[10] = s20 + 0;
        a[11] = s21 + 0;
        a[12] = s22 + dd;
        a[15] = s30 + 0;
        a[16] = s31 + 0;
        a[17] = s32 + 0;
        a[18] = s33 + dd;
        a[20] = s40 + 0;
        a[21] = s41 + 0;
        a[22] = s42 + 0;
        a[23] = s43 + 0;
        a[24] = s44 + dd;
    }

    /// <summary>The same step computed with MathNet.Numerics dense matrices and its Cholesky solver.</summary>
    internal static void SolveMathNet(ReadOnlySpan<double> j, ReadOnlySpan<double> e, Span<double> dq, int m, int n, double damping)
    {
        Matrix<double> jacobian = Matrix<double>.Build.Dense(m, n, (r, c) => 0);
        for (int r = 0; r < m; r++)
        {
            for (int c = 0; c < n; c++)
            {
                jacobian[r, c] = j[(r * n) + c];
            }
        }

        Matrix<double> system = (jacobian * jacobian.Transpose()) + Matrix<double>.Build.DenseIdentity(m).Multiply(damping * damping);
        DenseVector x = system.Cholesky().Solve(DenseVector.Build.DenseOfArray(e.ToArray()));
        DenseVector step = jacobian.TransposeThisAndMultiply(x);
        for (int c = 0; c < n; c++)
        {
            dq[c] = step[c];
        }
    }
}
