using System.Numerics;
using Ballistic.Planner.Characters;

namespace Ballistic.Planner.Roadmaps;

/// <summary>
/// The jump-reach test of the bake and the query (<see cref="NodeIndex.InReach"/>: horizontal distance at most
/// <see cref="SteeringLimits.MaxReach"/> at the height difference, either way), made cheap: a table of bounds on
/// the reach per 5 cm band of height difference decides almost every pair from its squared horizontal distance, and
/// only pairs within a hair of their band's bounds run the exact test. The answers are exactly the exact test's.
/// </summary>
/// <remarks>
/// With z the height gain, the reach² is min(T, Λ), T = V²(V² − 2gz)/g² (takeoff speed V) decreasing and
/// Λ = (L² + 2gz) L²/g² (landing speed L) increasing in z, zero where negative. Over a band of |z| both ends of T and
/// Λ bound the reach in that band from below and above, for a drop and a climb alike; the bounds keep a relative
/// margin of 10⁻⁴, far above the rounding of the float computations they stand for. Immutable and thread-safe.
/// </remarks>
internal sealed class ReachTest
{
    /// <summary>Height band of the table, metres.</summary>
    private const double Band = 0.05;

    private readonly float[] _accept;
    private readonly float[] _reject;
    private readonly float _inverseBand;

    /// <summary>Builds the table for <paramref name="limits"/>.</summary>
    public ReachTest(SteeringLimits limits)
    {
        ArgumentNullException.ThrowIfNull(limits);
        Limits = limits;
        Bound = NodeIndex.ReachBound(limits);
        double g = limits.Gravity;
        double v2 = (double)limits.TakeoffSpeedMax * limits.TakeoffSpeedMax;
        double l2 = (double)limits.LandingSpeedMax * limits.LandingSpeedMax;

        // Reach² at a drop d (height gain −d): takeoff bound rises with d, landing bound falls.
        double Takeoff(double drop) => v2 * (v2 + (2.0 * g * drop)) / (g * g);
        double Landing(double drop) => Math.Max(0.0, l2 - (2.0 * g * drop)) * l2 / (g * g);
        static double Root(double reach2) => reach2 > 0.0 ? Math.Sqrt(reach2) : 0.0;

        // Beyond this height difference no jump either way has any reach.
        double highest = Math.Max(v2, l2) / (2.0 * g);
        int bands = (int)Math.Ceiling(highest / Band) + 2;
        _accept = new float[bands];
        _reject = new float[bands];
        for (int i = 0; i < bands; i++)
        {
            double a = Math.Max(0.0, (i - 0.01) * Band);
            double b = i == bands - 1 ? double.PositiveInfinity : (i + 1.01) * Band;
            double low = Math.Max(Root(Math.Min(Takeoff(a), Landing(b))), Root(Math.Min(Takeoff(-b), Landing(-a))));
            double high = i == bands - 1 ? 0.0 : Math.Max(Root(Math.Min(Takeoff(b), Landing(a))), Root(Math.Min(Takeoff(-a), Landing(-b))));
            double accept = low * (1.0 - 1e-4);
            double reject = (high * (1.0 + 1e-4)) + 1e-6;
            _accept[i] = (float)(accept * accept);
            _reject[i] = (float)(reject * reject);
        }

        _inverseBand = (float)(1.0 / Band);
    }

    /// <summary>The limits tested.</summary>
    public SteeringLimits Limits { get; }

    /// <summary>An upper bound of the reach at any height difference, metres (<see cref="NodeIndex.ReachBound"/>).</summary>
    public float Bound { get; }

    /// <summary>Exactly <see cref="NodeIndex.InReach"/> for these limits.</summary>
    public bool InReach(Vector3 p, Vector3 q)
    {
        float dx = q.X - p.X;
        float dz = q.Z - p.Z;
        float x2 = (dx * dx) + (dz * dz);
        float dy = MathF.Abs(p.Y - q.Y);
        int band = dy < _accept.Length * (float)Band ? (int)(dy * _inverseBand) : _accept.Length - 1;
        band = Math.Min(band, _accept.Length - 1);
        if (x2 <= _accept[band])
        {
            return true;
        }

        if (x2 > _reject[band])
        {
            return false;
        }

        return NodeIndex.InReach(Limits, Bound, p, q);
    }
}
