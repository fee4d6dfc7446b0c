using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Steering;

/// <summary>
/// The closed-form parabola steering method (VALIDSTEER): links two root poses by a ballistic arc whose takeoff
/// velocity lies in the takeoff friction cone, whose reversed landing velocity lies in the landing cone, whose
/// speeds respect the character's limits, and which passes the arc validator (by default: the trunk box never touches
/// the level, <see cref="TrunkSweepValidator"/>).
/// </summary>
/// <remarks>
/// In the vertical plane through both poses, with horizontal distance X and rise Z, a takeoff angle α above the
/// horizontal fixes the parabola: ẋ² = g X² / (2 (X tan α − Z)). Every constraint is an interval of α, computed in
/// closed form; the midpoint of their intersection is tried first, then fixed fractions of it when the trunk
/// collides or the apex is too high (Campana et al. 2016; planning notes §1).
/// </remarks>
internal sealed class ParabolaSteering
{
    /// <summary>Fractions of the admissible angle interval tried in order.</summary>
    private static readonly double[] Fractions = [0.5, 0.25, 0.75, 0.125, 0.375, 0.625, 0.875];

    /// <summary>Creates a steering method whose arcs must keep the trunk clear of <paramref name="world"/>.</summary>
    /// <param name="limits">Speed limits, gravity and tolerances.</param>
    /// <param name="trunkHalfExtents">Half extents (metres) of the trunk box W0, in the trunk frame.</param>
    /// <param name="world">The level; <c>null</c> for an empty world (no collision checks).</param>
    public ParabolaSteering(SteeringLimits limits, Vector3 trunkHalfExtents, ICollisionWorld? world)
        : this(limits, trunkHalfExtents, arcValidator: world is null ? null : new TrunkSweepValidator(world, trunkHalfExtents, limits?.CollisionTolerance ?? 0f))
    {
    }

    /// <summary>Creates a steering method whose arcs must pass <paramref name="arcValidator"/>.</summary>
    /// <param name="limits">Speed limits, gravity and tolerances.</param>
    /// <param name="trunkHalfExtents">Half extents (metres) of the trunk box W0, in the trunk frame.</param>
    /// <param name="arcValidator">The check every candidate arc must pass (usually a <see cref="TrunkSweepValidator"/>); <c>null</c> for none.</param>
    public ParabolaSteering(SteeringLimits limits, Vector3 trunkHalfExtents, IArcValidator? arcValidator)
    {
        ArgumentNullException.ThrowIfNull(limits);
        if (!(MathF.Min(trunkHalfExtents.X, MathF.Min(trunkHalfExtents.Y, trunkHalfExtents.Z)) > 0f))
        {
            throw new ArgumentOutOfRangeException(nameof(trunkHalfExtents), trunkHalfExtents, "Trunk half extents must be positive.");
        }

        Limits = limits;
        TrunkHalfExtents = trunkHalfExtents;
        ArcValidator = arcValidator;
    }

    /// <summary>Speed limits, gravity and tolerances in force.</summary>
    public SteeringLimits Limits { get; }

    /// <summary>Half extents of the trunk box W0, metres.</summary>
    public Vector3 TrunkHalfExtents { get; }

    /// <summary>The check every candidate arc must pass; <c>null</c> when arcs are not checked against anything.</summary>
    public IArcValidator? ArcValidator { get; }

    /// <summary>Finds a jump from <paramref name="from"/> to <paramref name="to"/>, or the reason there is none.</summary>
    /// <param name="from">Takeoff root pose.</param>
    /// <param name="fromCone">Centroidal friction cone at takeoff; the takeoff velocity must lie in it.</param>
    /// <param name="to">Landing root pose.</param>
    /// <param name="toCone">Centroidal friction cone at landing; the reversed landing velocity must lie in it.</param>
    public SteeringResult Steer(in RootPose from, in FrictionCone fromCone, in RootPose to, in FrictionCone toCone) =>
        SteerTrying(from, fromCone, to, toCone, Fractions);

    /// <summary>
    /// As <see cref="Steer(in RootPose, in FrictionCone, in RootPose, in FrictionCone)"/>, the steepest admissible
    /// takeoff angles tried first: the arc that stays longest in the air, for a hop in place that must leave the
    /// limbs time to move.
    /// </summary>
    internal SteeringResult SteerSteep(in RootPose from, in FrictionCone fromCone, in RootPose to, in FrictionCone toCone) =>
        SteerTrying(from, fromCone, to, toCone, SteepFractions);

    /// <summary>
    /// <see cref="Steer(in RootPose, in FrictionCone, in RootPose, in FrictionCone)"/> (or, with
    /// <paramref name="steep"/>, <see cref="SteerSteep"/>) remembered, for a query's path post-processing: turning a
    /// jump to face its way, cutting it down or shortcutting steer the same stances in every query whose path takes
    /// that jump. A result is a function of the poses and cones alone (<see cref="RememberedResults{TKey, TValue}"/>,
    /// <see cref="RememberedSteers"/> a generation); the bake, whose pairs never repeat, steers without it.
    /// </summary>
    internal SteeringResult SteerRemembered(in RootPose from, in FrictionCone fromCone, in RootPose to, in FrictionCone toCone, bool steep = false) =>
        _remembered.GetOrAdd(new SteerKey(from, fromCone, to, toCone, steep), this, static (k, steering) =>
            k.Steep ? steering.SteerSteep(k.From, k.FromCone, k.To, k.ToCone) : steering.Steer(k.From, k.FromCone, k.To, k.ToCone));

    /// <summary>Steering results each generation of <see cref="SteerRemembered"/> keeps (about 200 bytes each).</summary>
    private const int RememberedSteers = 16_384;

    private readonly RememberedResults<SteerKey, SteeringResult> _remembered = new(RememberedSteers);

    /// <summary>Arcs kept for good (a prepared query's, <see cref="Query.PathQuery.Prepare"/>).</summary>
    internal int KeptCount => _remembered.KeptCount;

    /// <summary>Gives back the spare room of the arcs kept for good.</summary>
    internal void TrimKept() => _remembered.TrimKept();

    /// <summary>
    /// What a remembered steer was asked: both poses and cones, and whether the steepest arcs were tried first; its hash
    /// made once, when asked (a lookup that misses the kept results hashes it again in each generation).
    /// </summary>
    private readonly record struct SteerKey(RootPose From, FrictionCone FromCone, RootPose To, FrictionCone ToCone, bool Steep)
    {
        private readonly int _hash = HashCode.Combine(From, FromCone, To, ToCone, Steep);

        public bool Equals(SteerKey other) =>
            _hash == other._hash && From == other.From && FromCone == other.FromCone && To == other.To && ToCone == other.ToCone && Steep == other.Steep;

        public override int GetHashCode() => _hash;
    }

    /// <summary>Fractions of the admissible angle interval tried in order by <see cref="SteerSteep"/>.</summary>
    private static readonly double[] SteepFractions = [0.875, 0.75, 0.625, 0.5];

    private SteeringResult SteerTrying(in RootPose from, in FrictionCone fromCone, in RootPose to, in FrictionCone toCone, double[] fractions)
    {
        SteeringFailure failure = TryAngleInterval(from.Position, fromCone, to.Position, toCone, out AngleInterval interval);
        if (failure != SteeringFailure.None)
        {
            return SteeringResult.Fail(failure);
        }

        // The apex rises with α: if even the flattest admissible arc is too high, none will do.
        if (ApexHeight(from.Position, interval, interval.Min) > Limits.MaxApexHeight)
        {
            return SteeringResult.Fail(SteeringFailure.ApexTooHigh);
        }

        bool anyLowEnough = false;
        foreach (double fraction in fractions)
        {
            double alpha = interval.Min + (fraction * (interval.Max - interval.Min));
            if (ApexHeight(from.Position, interval, alpha) > Limits.MaxApexHeight)
            {
                continue;
            }

            anyLowEnough = true;
            BallisticArc arc = MakeArc(from, to, interval, alpha);
            if (ArcValidator is null || ArcValidator.IsValid(arc))
            {
                return new SteeringResult(SteeringFailure.None, arc);
            }
        }

        return SteeringResult.Fail(anyLowEnough ? SteeringFailure.Collision : SteeringFailure.ApexTooHigh);
    }

    /// <summary>
    /// The interval of takeoff angles α (radians above the horizontal, toward the landing) that satisfy the cone and
    /// speed constraints, ignoring collisions and the apex bound.
    /// </summary>
    public SteeringFailure TryAngleInterval(Vector3 from, in FrictionCone fromCone, Vector3 to, in FrictionCone toCone, out AngleInterval interval)
    {
        interval = default;
        double g = Limits.Gravity;
        double dx = (double)to.X - from.X;
        double dz = (double)to.Z - from.Z;
        double x = Math.Sqrt((dx * dx) + (dz * dz));
        double z = (double)to.Y - from.Y;
        if (!(x >= Limits.MinHorizontalDistance))
        {
            return SteeringFailure.TooClose;
        }

        Vector3 heading = new((float)(dx / x), 0f, (float)(dz / x));

        // Through the goal: tan α > Z / X.
        double lo = Math.Atan2(z, x) + Limits.AngleMargin;
        double hi = (Math.PI / 2.0) - Limits.AngleMargin;

        // Takeoff cone cut by the vertical plane: α ∈ [β₁ − δ₁, β₁ + δ₁].
        if (!TryCut(fromCone, heading, out double beta1, out double delta1))
        {
            return SteeringFailure.TakeoffConeMissesPlane;
        }

        lo = Math.Max(lo, beta1 - delta1);
        hi = Math.Min(hi, beta1 + delta1);

        // Landing cone: the reversed landing velocity at angle λ + π must lie in the cone, so λ lies in the cut of
        // the flipped axis; tan λ = 2Z/X − tan α decreases with α.
        if (!TryCut(toCone, heading, out double beta2, out double delta2))
        {
            return SteeringFailure.LandingConeMissesPlane;
        }

        double flipped = beta2 >= 0.0 ? beta2 - Math.PI : beta2 + Math.PI;
        double lambdaLo = Math.Max(flipped - delta2, -Math.PI / 2.0);
        double lambdaHi = Math.Min(flipped + delta2, Math.PI / 2.0);
        if (!(lambdaLo < lambdaHi))
        {
            return SteeringFailure.LandingCone;
        }

        double slope = 2.0 * z / x;
        if (lambdaHi < Math.PI / 2.0)
        {
            lo = Math.Max(lo, Math.Atan(slope - Math.Tan(lambdaHi)));
        }

        if (lambdaLo > -Math.PI / 2.0)
        {
            hi = Math.Min(hi, Math.Atan(slope - Math.Tan(lambdaLo)));
        }

        // Takeoff speed: g X² u² − 2 X V² u + g X² + 2 Z V² ≤ 0 with u = tan α.
        if (!TrySpeedBounds((double)Limits.TakeoffSpeedMax * Limits.TakeoffSpeedMax, g, x, z, out double uLo, out double uHi))
        {
            return SteeringFailure.TakeoffSpeed;
        }

        lo = Math.Max(lo, Math.Atan(uLo));
        hi = Math.Min(hi, Math.Atan(uHi));

        // Landing speed: |V_imp|² = |V₀|² − 2 g Z ≤ V_f², the same quadratic with W² = V_f² + 2 g Z.
        double w2 = ((double)Limits.LandingSpeedMax * Limits.LandingSpeedMax) + (2.0 * g * z);
        if (w2 <= 0.0 || !TrySpeedBounds(w2, g, x, z, out uLo, out uHi))
        {
            return SteeringFailure.LandingSpeed;
        }

        lo = Math.Max(lo, Math.Atan(uLo));
        hi = Math.Min(hi, Math.Atan(uHi));

        if (!(lo < hi))
        {
            return SteeringFailure.EmptyAngleInterval;
        }

        interval = new AngleInterval(lo, hi, x, z, heading);
        return SteeringFailure.None;
    }

    private BallisticArc MakeArc(in RootPose from, in RootPose to, in AngleInterval interval, double alpha)
    {
        double g = Limits.Gravity;
        double u = Math.Tan(alpha);
        double xDot = Math.Sqrt(g * interval.X * interval.X / (2.0 * ((interval.X * u) - interval.Z)));
        double flightTime = interval.X / xDot;
        Vector3 velocity = new(
            (float)(xDot * interval.Heading.X),
            (float)(xDot * u),
            (float)(xDot * interval.Heading.Z));
        return new BallisticArc(from, to, velocity, (float)flightTime, Limits.Gravity);
    }

    private double ApexHeight(Vector3 from, in AngleInterval interval, double alpha)
    {
        double g = Limits.Gravity;
        double u = Math.Tan(alpha);
        double xDot2 = g * interval.X * interval.X / (2.0 * ((interval.X * u) - interval.Z));
        double vy = Math.Sqrt(xDot2) * u;
        double flightTime = interval.X / Math.Sqrt(xDot2);
        double tApex = Math.Clamp(vy / g, 0.0, flightTime);
        return from.Y + (vy * tApex) - (0.5 * g * tApex * tApex);
    }

    /// <summary>
    /// Cuts the cone by the vertical plane spanned by the heading and +Y. With the axis at in-plane angle β and
    /// in-plane length ρ, directions at angle γ in the plane lie in the cone when |γ − β| ≤ δ = acos(cos φ / ρ).
    /// </summary>
    private bool TryCut(in FrictionCone cone, Vector3 heading, out double beta, out double delta)
    {
        double nTheta = Vector3.Dot(cone.Axis, heading);
        double nUp = cone.Axis.Y;
        double rho = Math.Sqrt((nTheta * nTheta) + (nUp * nUp));
        beta = Math.Atan2(nUp, nTheta);
        double cosPhi = 1.0 / Math.Sqrt(1.0 + ((double)cone.Mu * cone.Mu));
        if (rho <= cosPhi)
        {
            delta = 0.0;
            return false;
        }

        delta = Math.Acos(cosPhi / rho);
        return delta >= Limits.MinConeCutHalfAngle;
    }

    /// <summary>Roots of g X² u² − 2 X S u + g X² + 2 Z S ≤ 0 for the squared speed bound S.</summary>
    private static bool TrySpeedBounds(double speed2, double g, double x, double z, out double uLo, out double uHi)
    {
        double discriminant = (speed2 * speed2) - (g * ((g * x * x) + (2.0 * z * speed2)));
        if (discriminant < 0.0)
        {
            uLo = uHi = 0.0;
            return false;
        }

        double root = Math.Sqrt(discriminant);
        uLo = (speed2 - root) / (g * x);
        uHi = (speed2 + root) / (g * x);
        return true;
    }
}
