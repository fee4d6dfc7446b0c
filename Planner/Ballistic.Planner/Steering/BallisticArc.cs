using System.Numerics;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Steering;

/// <summary>
/// One jump: the free flight of the trunk centre from <see cref="Start"/> to <see cref="End"/> under gravity
/// (0, −g, 0). World frame, metres, seconds. The trunk orientation is the spherical interpolation from
/// <see cref="StartRotation"/> to <see cref="EndRotation"/> over the flight time.
/// </summary>
public readonly record struct BallisticArc
{
    /// <summary>Creates an arc from its endpoints, takeoff velocity and flight time.</summary>
    public BallisticArc(RootPose takeoff, RootPose landing, Vector3 takeoffVelocity, float flightTime, float gravity)
    {
        Takeoff = takeoff;
        Landing = landing;
        TakeoffVelocity = takeoffVelocity;
        FlightTime = flightTime;
        Gravity = gravity;
        LandingVelocity = takeoffVelocity - new Vector3(0f, gravity * flightTime, 0f);
        ArcLength = ComputeLength(takeoffVelocity, flightTime, gravity);
        _turn = RotationBlend.Between(takeoff.Rotation, landing.Rotation);
    }

    /// <summary>The trunk's turn from <see cref="StartRotation"/> to <see cref="EndRotation"/>, its angle worked out once (read at every flight time).</summary>
    private readonly RotationBlend _turn;

    /// <summary>The root pose at takeoff (t = 0).</summary>
    public RootPose Takeoff { get; }

    /// <summary>The root pose at landing (t = <see cref="FlightTime"/>).</summary>
    public RootPose Landing { get; }

    /// <summary>Trunk centre at takeoff, world metres.</summary>
    public Vector3 Start => Takeoff.Position;

    /// <summary>Trunk centre at landing, world metres.</summary>
    public Vector3 End => Landing.Position;

    /// <summary>Trunk orientation at takeoff.</summary>
    public Quaternion StartRotation => Takeoff.Rotation;

    /// <summary>Trunk orientation at landing.</summary>
    public Quaternion EndRotation => Landing.Rotation;

    /// <summary>Velocity of the trunk centre just after takeoff, m/s.</summary>
    public Vector3 TakeoffVelocity { get; }

    /// <summary>Velocity of the trunk centre just before landing, m/s.</summary>
    public Vector3 LandingVelocity { get; }

    /// <summary>Duration of the flight, seconds.</summary>
    public float FlightTime { get; }

    /// <summary>Magnitude of gravity along −Y, m/s².</summary>
    public float Gravity { get; }

    /// <summary>Length of the trunk centre's path, metres.</summary>
    public float ArcLength { get; }

    /// <summary>Horizontal speed ẋ (constant during the flight), m/s.</summary>
    public float HorizontalSpeed => new Vector2(TakeoffVelocity.X, TakeoffVelocity.Z).Length();

    /// <summary>
    /// The height (metres) the takeoff speed |v| would lift the trunk straight up, |v|²/(2g): the takeoff's kinetic
    /// energy per unit mass over g. It is the apex's rise above the takeoff for a jump straight up, and more for a long
    /// leap to the same apex: what the legs put into the jump, in metres of climbing.
    /// </summary>
    public float EnergyHeight => TakeoffVelocity.LengthSquared() / (2f * Gravity);

    /// <summary>Time of the highest point, seconds, clamped to the flight.</summary>
    public float ApexTime => Math.Clamp(TakeoffVelocity.Y / Gravity, 0f, FlightTime);

    /// <summary>Highest point of the trunk centre along the flight, world metres.</summary>
    public Vector3 Apex => PositionAt(ApexTime);

    /// <summary>Trunk centre at time <paramref name="t"/> seconds after takeoff (world metres).</summary>
    public Vector3 PositionAt(float t) =>
        Start + (TakeoffVelocity * t) - new Vector3(0f, 0.5f * Gravity * t * t, 0f);

    /// <summary>Velocity of the trunk centre at time <paramref name="t"/>, m/s.</summary>
    public Vector3 VelocityAt(float t) => TakeoffVelocity - new Vector3(0f, Gravity * t, 0f);

    /// <summary>Trunk orientation at time <paramref name="t"/>: slerp from takeoff to landing over the flight.</summary>
    public Quaternion RotationAt(float t) =>
        _turn.At(StartRotation, EndRotation, FlightTime > 0f ? Math.Clamp(t / FlightTime, 0f, 1f) : 1f);

    /// <summary>The root pose at time <paramref name="t"/>.</summary>
    public RootPose PoseAt(float t) => new(PositionAt(t), RotationAt(t));

    /// <summary>
    /// Closed-form length of the parabola: with slope p = dy/ds over horizontal advance s,
    /// L = |F(p₀) − F(p₁)| ẋ² / g, F(p) = ½ (p √(1 + p²) + asinh p).
    /// </summary>
    private static float ComputeLength(Vector3 v0, float flightTime, float gravity)
    {
        double vx = Math.Sqrt(((double)v0.X * v0.X) + ((double)v0.Z * v0.Z));
        double vy = v0.Y;
        if (vx < 1e-9)
        {
            // Vertical flight: distance travelled up and down.
            double tApex = Math.Clamp(vy / gravity, 0.0, flightTime);
            double up = (vy * tApex) - (0.5 * gravity * tApex * tApex);
            double endHeight = (vy * flightTime) - (0.5 * gravity * flightTime * flightTime);
            return (float)(Math.Abs(up) + Math.Abs(up - endHeight));
        }

        double p0 = vy / vx;
        double p1 = (vy - (gravity * flightTime)) / vx;
        return (float)(Math.Abs(F(p0) - F(p1)) * vx * vx / gravity);

        static double F(double p) => 0.5 * ((p * Math.Sqrt(1.0 + (p * p))) + Math.Asinh(p));
    }
}
