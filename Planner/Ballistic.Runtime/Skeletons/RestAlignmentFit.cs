using System.Numerics;

namespace Ballistic.Runtime.Skeletons;

/// <summary>
/// The rotation that best takes one set of vectors onto another in the least-squares sense (Wahba's problem), by
/// Horn's quaternion method: the unit eigenvector of the largest eigenvalue of a symmetric 4 × 4 matrix built from
/// the vectors' correlations (B. K. P. Horn, "Closed-form solution of absolute orientation using unit
/// quaternions", JOSA A 4(4), 1987). Double precision, Jacobi eigenvalue iterations.
/// </summary>
internal static class RestAlignmentFit
{
    /// <summary>
    /// The rotation q minimising Σ |q·from[i] − to[i]|² (longer vectors weigh more), or <c>null</c> when it is not
    /// unique: fewer than two non-parallel pairs.
    /// </summary>
    public static Quaternion? Fit(ReadOnlySpan<Vector3> from, ReadOnlySpan<Vector3> to)
    {
        // Correlations S[a, b] = Σ from_a · to_b, normalised so that the scale of either set does not matter.
        double fromScale = 0.0;
        double toScale = 0.0;
        for (int i = 0; i < from.Length; i++)
        {
            fromScale = Math.Max(fromScale, from[i].Length());
            toScale = Math.Max(toScale, to[i].Length());
        }

        if (!(fromScale > 0.0) || !(toScale > 0.0) || !double.IsFinite(fromScale * toScale))
        {
            return null;
        }

        double[,] s = new double[3, 3];
        for (int i = 0; i < from.Length; i++)
        {
            double[] a = [from[i].X / fromScale, from[i].Y / fromScale, from[i].Z / fromScale];
            double[] b = [to[i].X / toScale, to[i].Y / toScale, to[i].Z / toScale];
            for (int r = 0; r < 3; r++)
            {
                for (int c = 0; c < 3; c++)
                {
                    s[r, c] += a[r] * b[c];
                }
            }
        }

        double sxx = s[0, 0], sxy = s[0, 1], sxz = s[0, 2];
        double syx = s[1, 0], syy = s[1, 1], syz = s[1, 2];
        double szx = s[2, 0], szy = s[2, 1], szz = s[2, 2];
        double[,] n =
        {
            { sxx + syy + szz, syz - szy, szx - sxz, sxy - syx },
            { syz - szy, sxx - syy - szz, sxy + syx, szx + sxz },
            { szx - sxz, sxy + syx, -sxx + syy - szz, syz + szy },
            { sxy - syx, szx + sxz, syz + szy, -sxx - syy + szz },
        };

        (double[] values, double[,] vectors) = Jacobi(n);
        int best = 0;
        for (int k = 1; k < 4; k++)
        {
            if (values[k] > values[best])
            {
                best = k;
            }
        }

        double second = double.NegativeInfinity;
        for (int k = 0; k < 4; k++)
        {
            if (k != best)
            {
                second = Math.Max(second, values[k]);
            }
        }

        double spread = 0.0;
        foreach (double v in values)
        {
            spread = Math.Max(spread, Math.Abs(v));
        }

        if (!(values[best] - second > 1e-6 * spread))
        {
            return null;
        }

        var q = new Quaternion((float)vectors[1, best], (float)vectors[2, best], (float)vectors[3, best], (float)vectors[0, best]);
        return Quaternion.Normalize(q);
    }

    /// <summary>Eigenvalues and eigenvectors (columns) of a symmetric 4 × 4 matrix by cyclic Jacobi rotations.</summary>
    private static (double[] Values, double[,] Vectors) Jacobi(double[,] matrix)
    {
        const int N = 4;
        double[,] a = (double[,])matrix.Clone();
        double[,] v = new double[N, N];
        for (int i = 0; i < N; i++)
        {
            v[i, i] = 1.0;
        }

        for (int sweep = 0; sweep < 100; sweep++)
        {
            double off = 0.0;
            for (int p = 0; p < N; p++)
            {
                for (int q = p + 1; q < N; q++)
                {
                    off += a[p, q] * a[p, q];
                }
            }

            if (off < 1e-30)
            {
                break;
            }

            for (int p = 0; p < N; p++)
            {
                for (int q = p + 1; q < N; q++)
                {
                    if (Math.Abs(a[p, q]) < 1e-300)
                    {
                        continue;
                    }

                    double theta = (a[q, q] - a[p, p]) / (2.0 * a[p, q]);
                    double t = Math.Sign(theta) / (Math.Abs(theta) + Math.Sqrt((theta * theta) + 1.0));
                    if (theta == 0.0)
                    {
                        t = 1.0;
                    }

                    double c = 1.0 / Math.Sqrt((t * t) + 1.0);
                    double sn = t * c;
                    for (int k = 0; k < N; k++)
                    {
                        double akp = a[k, p];
                        double akq = a[k, q];
                        a[k, p] = (c * akp) - (sn * akq);
                        a[k, q] = (sn * akp) + (c * akq);
                    }

                    for (int k = 0; k < N; k++)
                    {
                        double apk = a[p, k];
                        double aqk = a[q, k];
                        a[p, k] = (c * apk) - (sn * aqk);
                        a[q, k] = (sn * apk) + (c * aqk);
                    }

                    for (int k = 0; k < N; k++)
                    {
                        double vkp = v[k, p];
                        double vkq = v[k, q];
                        v[k, p] = (c * vkp) - (sn * vkq);
                        v[k, q] = (sn * vkp) + (c * vkq);
                    }
                }
            }
        }

        double[] values = new double[N];
        for (int i = 0; i < N; i++)
        {
            values[i] = a[i, i];
        }

        return (values, v);
    }
}
