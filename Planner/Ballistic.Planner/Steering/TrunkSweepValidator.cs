using System.Numerics;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Steering;

/// <summary>
/// The built-in arc check: the trunk box W0, carried along the arc (position on the parabola, rotation interpolated
/// from takeoff to landing), never touches the level. Thread-safe when the collision world is.
/// </summary>
/// <remarks>
/// Conservative and continuous: the flight is cut into intervals over which no point of the trunk moves more than its
/// smallest half extent (translation at the arc's top speed plus rotation of its farthest corner). Over an interval
/// every trunk position lies inside the mid-interval trunk grown by the largest distance a point can travel in half
/// the interval, so that grown box being free proves the whole interval free. Where it is not, the interval is halved,
/// down to a growth of the collision tolerance. A thin obstacle can therefore never be stepped over, and the trunk's
/// corners cannot clip one between samples. Runs of intervals are first tested in one box that holds all their grown
/// boxes, so an arc's stretch through open air costs one test; the verdict is the intervals' own, exactly. Before the
/// sweep, a long arc's trunk is probed at a few evenly spaced instants (<see cref="TouchesAtProbes"/>): most arcs a
/// bake tries pass through a wall or a roof somewhere, and a trunk touching the level at an instant is found in one
/// test there, instead of after the sweep has proved every grazing interval before it free.
/// </remarks>
internal sealed class TrunkSweepValidator : IArcValidator
{
    private readonly ICollisionWorld _world;

    /// <summary>Creates the check.</summary>
    /// <param name="world">The level's collision geometry.</param>
    /// <param name="trunkHalfExtents">Half extents (metres) of the trunk box W0, in the trunk frame; positive.</param>
    /// <param name="collisionTolerance">Growth (metres) below which a touching interval counts as a collision; not negative.</param>
    public TrunkSweepValidator(ICollisionWorld world, Vector3 trunkHalfExtents, float collisionTolerance)
    {
        ArgumentNullException.ThrowIfNull(world);
        if (!(MathF.Min(trunkHalfExtents.X, MathF.Min(trunkHalfExtents.Y, trunkHalfExtents.Z)) > 0f))
        {
            throw new ArgumentOutOfRangeException(nameof(trunkHalfExtents), trunkHalfExtents, "Trunk half extents must be positive.");
        }

        if (!(collisionTolerance >= 0f))
        {
            throw new ArgumentOutOfRangeException(nameof(collisionTolerance), collisionTolerance, "The collision tolerance must not be negative.");
        }

        _world = world;
        TrunkHalfExtents = trunkHalfExtents;
        CollisionTolerance = collisionTolerance;
    }

    /// <summary>Half extents of the trunk box W0, metres.</summary>
    public Vector3 TrunkHalfExtents { get; }

    /// <summary>Smallest growth (metres) to which a touching interval is refined before it counts as a collision.</summary>
    public float CollisionTolerance { get; }

    /// <inheritdoc/>
    public bool IsValid(in BallisticArc arc)
    {
        float spacing = MathF.Min(TrunkHalfExtents.X, MathF.Min(TrunkHalfExtents.Y, TrunkHalfExtents.Z));
        float speed = MathF.Max(arc.TakeoffVelocity.Length(), arc.LandingVelocity.Length());
        float dot = MathF.Min(1f, MathF.Abs(Quaternion.Dot(arc.StartRotation, arc.EndRotation)));
        float turn = 2f * MathF.Acos(dot);
        float cornerSpeed = arc.FlightTime > 0f ? turn / arc.FlightTime * TrunkHalfExtents.Length() : 0f;
        float pointSpeed = speed + cornerSpeed;
        int steps = Math.Max(1, (int)MathF.Ceiling(arc.FlightTime * pointSpeed / spacing));
        if (TouchesAtProbes(arc, Math.Min(MaxProbes, steps / StepsPerProbe)))
        {
            return false;
        }

        return new Sweep(this, arc, steps, pointSpeed, turn).RunIsFree(0, steps, grouped: steps >= GroupedArcSteps);
    }

    /// <summary>At most this many probes an arc (<see cref="TouchesAtProbes"/>): every 32nd of its flight.</summary>
    private const int MaxProbes = 31;

    /// <summary>One probe for every this many steps of an arc: a short hop, quick to sweep, is not probed.</summary>
    private const int StepsPerProbe = 8;

    /// <summary>
    /// True when the trunk box itself (not grown) touches the level at one of <paramref name="probes"/> instants of the
    /// flight, taken coarse to fine (a half, a quarter, three quarters, an eighth...) up to the 32nds. Such an arc is
    /// one the sweep refuses too: the trunk at an instant lies inside the grown box of every interval holding that
    /// instant, at every depth, so each of them touches the level down to the tolerance. Only the work changes.
    /// </summary>
    private bool TouchesAtProbes(in BallisticArc arc, int probes)
    {
        for (int k = 1; k <= probes; k++)
        {
            // k's bits mirrored about the binary point: 1 → 1/2, 2 → 1/4, 3 → 3/4, 4 → 1/8, ... (van der Corput).
            float share = 0f;
            float bit = 0.5f;
            for (int rest = k; rest > 0; rest >>= 1, bit *= 0.5f)
            {
                share += (rest & 1) * bit;
            }

            RootPose pose = arc.PoseAt(share * arc.FlightTime);
            if (_world.Overlaps(new OrientedBox(pose.Position, TrunkHalfExtents, pose.Rotation)))
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>Runs of fewer steps than this are tested step by step.</summary>
    private const int GroupSteps = 4;

    /// <summary>Arcs of fewer steps than this are tested step by step (a short hop's runs all lie near the ground).</summary>
    private const int GroupedArcSteps = 16;

    /// <summary>
    /// Rotation (radians) always allowed for between a run's steps and its reference frame, above what the slerp
    /// gives: the float error of the interpolation (and its linear fallback for turns under a few milliradians).
    /// </summary>
    private const float AngleNoise = 2e-3f;

    /// <summary>Metres a run's box is grown by beyond what holds its steps' boxes, for the float error of the tests.</summary>
    private const float GroupMargin = 1e-4f;

    /// <summary>
    /// One arc's sweep, its flight cut into <c>steps</c> equal intervals, each tested by <see cref="IntervalIsFree"/>
    /// (the verdict is theirs). Runs of steps are tested in one box first: where a box holding every step's grown box
    /// of a run is free, each of them would be found free at once, so only the runs near the level are tested step by
    /// step; a step touching the level makes every run holding it touch it too, so the verdict is exactly the steps'.
    /// </summary>
    private readonly ref struct Sweep(TrunkSweepValidator validator, in BallisticArc arc, int steps, float pointSpeed, float turn)
    {
        private readonly BallisticArc _arc = arc;

        public bool RunIsFree(int from, int to, bool grouped = true)
        {
            if (!grouped || to - from < GroupSteps)
            {
                for (int i = from; i < to; i++)
                {
                    if (!validator.IntervalIsFree(_arc, _arc.FlightTime * i / steps, _arc.FlightTime * (i + 1) / steps, pointSpeed, depth: 0))
                    {
                        return false;
                    }
                }

                return true;
            }

            if (!validator._world.Overlaps(Holding(from, to)))
            {
                return true;
            }

            int middle = (from + to) / 2;
            return RunIsFree(from, middle) && RunIsFree(middle, to);
        }

        /// <summary>
        /// A box holding the grown boxes of steps <paramref name="from"/> to <paramref name="to"/> − 1: in the frame of
        /// the trunk mid-run, the range of the parabola between the first and last steps' middles (each coordinate a
        /// quadratic in time) plus each box's half extents, grown by what its rotation away from that frame (the slerp's
        /// constant rate times the time between them) can move a corner.
        /// </summary>
        private OrientedBox Holding(int from, int to)
        {
            float duration = _arc.FlightTime;
            float first = 0.5f * ((duration * from / steps) + (duration * (from + 1) / steps));
            float last = 0.5f * ((duration * (to - 1) / steps) + (duration * to / steps));
            float mid = 0.5f * (first + last);
            Quaternion frame = Quaternion.Normalize(_arc.RotationAt(mid));
            Quaternion inverse = Quaternion.Conjugate(frame);
            Vector3 centre = _arc.PositionAt(mid);

            // p(t) − centre = b·t + c·t² in the frame, t from the run's middle (centre = p(mid)).
            Vector3 b = Vector3.Transform(_arc.VelocityAt(mid), inverse);
            Vector3 c = Vector3.Transform(new Vector3(0f, -0.5f * _arc.Gravity, 0f), inverse);
            float t0 = first - mid;
            float t1 = last - mid;
            Vector3 low = Vector3.Min(Along(b, c, t0), Along(b, c, t1));
            Vector3 high = Vector3.Max(Along(b, c, t0), Along(b, c, t1));
            for (int axis = 0; axis < 3; axis++)
            {
                float ca = c[axis];
                if (MathF.Abs(ca) > 1e-12f)
                {
                    float vertex = -b[axis] / (2f * ca);
                    if (vertex > t0 && vertex < t1)
                    {
                        float value = (b[axis] * vertex) + (ca * vertex * vertex);
                        low[axis] = MathF.Min(low[axis], value);
                        high[axis] = MathF.Max(high[axis], value);
                    }
                }
            }

            Vector3 half = validator.TrunkHalfExtents + new Vector3((pointSpeed * 0.5f * duration / steps * 1.0001f) + 1e-6f);
            float angle = (duration > 0f ? turn * MathF.Max(-t0, t1) / duration : 0f) + AngleNoise + (turn < 0.01f ? turn : 0f);
            Vector3 reach = half + new Vector3((angle * half.Length()) + GroupMargin);
            low -= reach;
            high += reach;
            return new OrientedBox(centre + Vector3.Transform(0.5f * (low + high), frame), 0.5f * (high - low), frame);
        }

        private static Vector3 Along(Vector3 b, Vector3 c, float t) => (b * t) + (c * (t * t));
    }

    private bool IntervalIsFree(in BallisticArc arc, float t0, float t1, float pointSpeed, int depth)
    {
        float mid = 0.5f * (t0 + t1);
        float growth = pointSpeed * 0.5f * (t1 - t0);
        RootPose pose = arc.PoseAt(mid);
        if (!_world.Overlaps(new OrientedBox(pose.Position, TrunkHalfExtents + new Vector3(growth), pose.Rotation)))
        {
            return true;
        }

        if (growth <= CollisionTolerance || depth >= 24)
        {
            return false;
        }

        return IntervalIsFree(arc, t0, mid, pointSpeed, depth + 1) && IntervalIsFree(arc, mid, t1, pointSpeed, depth + 1);
    }
}
