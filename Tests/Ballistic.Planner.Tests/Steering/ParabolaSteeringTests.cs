using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Steering;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Steering;

public sealed class ParabolaSteeringTests
{
    private const float G = 9.81f;
    private static readonly Vector3 Trunk = new(0.2f, 0.3f, 0.15f);

    [Test]
    public void ARememberedSteerIsTheSteerItselfAskedOnce()
    {
        var random = new Random(7);
        var validator = new CountingValidator();
        var steering = new ParabolaSteering(new SteeringLimits(8f, 10f), Trunk, validator);
        var fresh = new ParabolaSteering(new SteeringLimits(8f, 10f), Trunk, new CountingValidator());
        int succeeded = 0;
        for (int i = 0; i < 300; i++)
        {
            RootPose a = RandomPose(random, 4f);
            RootPose b = RandomPose(random, 4f);
            FrictionCone ca = RandomCone(random);
            FrictionCone cb = RandomCone(random);
            foreach (bool steep in new[] { false, true })
            {
                SteeringResult expected = steep ? fresh.SteerSteep(a, ca, b, cb) : fresh.Steer(a, ca, b, cb);
                SteeringResult first = steering.SteerRemembered(a, ca, b, cb, steep);
                int asked = validator.Calls;
                SteeringResult again = steering.SteerRemembered(a, ca, b, cb, steep);
                Assert.That(first, Is.EqualTo(expected), $"case {i}, steep {steep}: the steer itself");
                Assert.That(again, Is.EqualTo(first), $"case {i}, steep {steep}");
                Assert.That(validator.Calls, Is.EqualTo(asked), $"case {i}, steep {steep}: asked again is remembered, no arc checked");
                succeeded += first.Succeeded ? 1 : 0;
            }
        }

        Assert.That(succeeded, Is.GreaterThan(30), "arcs found, not only failures remembered");
        Assert.That(validator.Calls, Is.GreaterThan(0));
    }

    private sealed class CountingValidator : IArcValidator
    {
        public int Calls { get; private set; }

        public bool IsValid(in BallisticArc arc)
        {
            Calls++;
            return arc.Apex.Y - arc.Start.Y < 1.5f;
        }
    }

    [Test]
    public void EverySuccessfulJumpObeysThePhysics()
    {
        var random = new Random(2016);
        int successes = 0;
        var failures = new Dictionary<SteeringFailure, int>();
        for (int i = 0; i < 20_000; i++)
        {
            var limits = new SteeringLimits(Range(random, 3f, 12f), Range(random, 3f, 14f));
            var steering = new ParabolaSteering(limits, Trunk, world: null);
            RootPose a = RandomPose(random, 6f);
            RootPose b = RandomPose(random, 6f);
            FrictionCone ca = RandomCone(random);
            FrictionCone cb = RandomCone(random);

            SteeringResult result = steering.Steer(a, ca, b, cb);
            if (!result.Succeeded)
            {
                failures[result.Failure] = failures.GetValueOrDefault(result.Failure) + 1;
                continue;
            }

            successes++;
            BallisticArc arc = result.Arc;
            string c = $"case {i}";
            float x = new Vector2(b.Position.X - a.Position.X, b.Position.Z - a.Position.Z).Length();
            Assert.That(Vector3.Distance(arc.PositionAt(0f), a.Position), Is.LessThan(1e-5f), c);
            Assert.That(Vector3.Distance(arc.PositionAt(arc.FlightTime), b.Position), Is.LessThan(2e-3f), c);
            Assert.That(ca.AngleTo(arc.TakeoffVelocity), Is.LessThanOrEqualTo(ca.HalfAngle + 1e-4f), $"{c}: takeoff velocity outside the takeoff cone");
            Assert.That(cb.AngleTo(-arc.LandingVelocity), Is.LessThanOrEqualTo(cb.HalfAngle + 1e-4f), $"{c}: reversed landing velocity outside the landing cone");
            Assert.That(arc.TakeoffVelocity.Length(), Is.LessThanOrEqualTo(limits.TakeoffSpeedMax * 1.0001f), $"{c}: takeoff speed");
            Assert.That(arc.LandingVelocity.Length(), Is.LessThanOrEqualTo(limits.LandingSpeedMax * 1.0001f), $"{c}: landing speed");
            Assert.That(arc.FlightTime, Is.EqualTo(x / arc.HorizontalSpeed).Within(1e-4f * arc.FlightTime), $"{c}: T = X / ẋ");
            Assert.That(x, Is.LessThanOrEqualTo(limits.MaxReach(a.Position.Y - b.Position.Y) * 1.0001f), $"{c}: beyond the reach bound");

            // Energy: |V_imp|² = |V₀|² − 2 g Z.
            float rise = b.Position.Y - a.Position.Y;
            Assert.That(arc.LandingVelocity.LengthSquared(), Is.EqualTo(arc.TakeoffVelocity.LengthSquared() - (2f * G * rise)).Within(1e-2f), c);
        }

        // Both outcomes must be common, and several distinct rejection reasons exercised.
        Assert.That(successes, Is.GreaterThan(500));
        Assert.That(failures.Keys, Has.Count.GreaterThanOrEqualTo(5), string.Join(", ", failures));
    }

    [Test]
    public void AngleIntervalAgreesWithBruteForceOverTakeoffAngles()
    {
        // Sample α finely and check each constraint directly on the velocities; the closed-form interval must hold
        // exactly the angles that pass (up to a small margin at its ends).
        var random = new Random(44);
        int nonEmpty = 0;
        for (int i = 0; i < 3_000; i++)
        {
            var limits = new SteeringLimits(Range(random, 3f, 12f), Range(random, 3f, 14f));
            var steering = new ParabolaSteering(limits, Trunk, world: null);
            Vector3 a = RandomPose(random, 5f).Position;
            Vector3 b = RandomPose(random, 5f).Position;
            FrictionCone ca = RandomCone(random);
            FrictionCone cb = RandomCone(random);
            SteeringFailure failure = steering.TryAngleInterval(a, ca, b, cb, out AngleInterval interval);

            double x = new Vector2(b.X - a.X, b.Z - a.Z).Length();
            double z = b.Y - a.Y;
            Vector3 heading = new((float)((b.X - a.X) / x), 0f, (float)((b.Z - a.Z) / x));
            const int n = 2_000;
            const double margin = 2e-3;
            for (int k = 1; k < n; k++)
            {
                double alpha = (-Math.PI / 2.0) + (Math.PI * k / n);
                bool passes = Feasible(alpha, x, z, heading, ca, cb, limits, tolerance: 0.0);
                bool passesLoosely = Feasible(alpha, x, z, heading, ca, cb, limits, tolerance: 1e-3);
                bool inside = failure == SteeringFailure.None && alpha > interval.Min + margin && alpha < interval.Max - margin;
                bool insideLoosely = failure == SteeringFailure.None && alpha >= interval.Min - margin && alpha <= interval.Max + margin;
                if (inside)
                {
                    Assert.That(passesLoosely, Is.True, $"case {i}: α = {alpha} inside [{interval.Min}, {interval.Max}] breaks a constraint");
                }

                if (passes && alpha > Math.Atan2(z, x) + margin && alpha < (Math.PI / 2) - margin)
                {
                    Assert.That(insideLoosely, Is.True, $"case {i}: α = {alpha} satisfies every constraint but lies outside the interval ({failure})");
                }
            }

            if (failure == SteeringFailure.None)
            {
                nonEmpty++;
            }
        }

        Assert.That(nonEmpty, Is.GreaterThan(100));
    }

    [Test]
    public void ConePlaneCutAgreesWithSampledDirections()
    {
        // The in-plane cut [β − δ, β + δ] of the closed form, seen through a horizontal-heading jump with a huge speed
        // budget: the admissible α on a flat jump with a vertical landing cone are exactly the takeoff cone's cut.
        var random = new Random(9);
        var limits = new SteeringLimits(1_000f, 1_000f) { MinConeCutHalfAngle = 0f };
        var steering = new ParabolaSteering(limits, Trunk, world: null);
        var down = new FrictionCone(Vector3.UnitY, 1e4f);
        int checkedCuts = 0;
        for (int i = 0; i < 2_000; i++)
        {
            FrictionCone cone = RandomCone(random);
            SteeringFailure failure = steering.TryAngleInterval(Vector3.Zero, cone, new Vector3(3f, -1e-6f, 0f), down, out AngleInterval interval);

            // Sampled directions in the plane spanned by +X and +Y, restricted to the forward half (cos γ > 0) and above
            // the straight line to the goal.
            double first = double.NaN;
            double last = double.NaN;
            for (int k = 0; k <= 20_000; k++)
            {
                double gamma = (-Math.PI / 2.0) + (Math.PI * k / 20_000);
                var v = new Vector3((float)Math.Cos(gamma), (float)Math.Sin(gamma), 0f);
                if (gamma > limits.AngleMargin && gamma < (Math.PI / 2.0) - limits.AngleMargin && cone.Contains(v))
                {
                    first = double.IsNaN(first) ? gamma : first;
                    last = gamma;
                }
            }

            if (double.IsNaN(first))
            {
                Assert.That(failure, Is.Not.EqualTo(SteeringFailure.None).Or.Property(nameof(AngleInterval.Max)).LessThan(1e-3), $"case {i}");
                continue;
            }

            Assert.That(failure, Is.EqualTo(SteeringFailure.None), $"case {i}");
            Assert.That(interval.Min, Is.EqualTo(first).Within(5e-4), $"case {i}: lower end");
            Assert.That(interval.Max, Is.EqualTo(last).Within(5e-4), $"case {i}: upper end");
            checkedCuts++;
        }

        Assert.That(checkedCuts, Is.GreaterThan(300));
    }

    [Test]
    public void OnFlatGroundTheLongestJumpIsVSquaredOverG()
    {
        const float v = 8f;
        var limits = new SteeringLimits(v, 2f * v);
        var steering = new ParabolaSteering(limits, Trunk, world: null);
        var up = new FrictionCone(Vector3.UnitY, 1.2f); // 50°: the 45° launch is admissible
        float range = v * v / G;
        RootPose a = new(Vector3.Zero, Quaternion.Identity);

        SteeringResult near = steering.Steer(a, up, new RootPose(new Vector3(0.995f * range, 0f, 0f), Quaternion.Identity), up);
        SteeringResult far = steering.Steer(a, up, new RootPose(new Vector3(1.005f * range, 0f, 0f), Quaternion.Identity), up);
        Assert.Multiple(() =>
        {
            Assert.That(near.Succeeded, Is.True);
            Assert.That(far.Failure, Is.EqualTo(SteeringFailure.TakeoffSpeed));
            Assert.That(limits.MaxReach(0f), Is.EqualTo(range).Within(1e-3f));
        });
    }

    [Test]
    public void ANarrowFrictionConeForbidsTheLongJump()
    {
        // With μ = 0.5 the takeoff must be within 26.6° of vertical: steep, so the flat range shrinks to V² sin 2α / g.
        const float v = 8f;
        var steering = new ParabolaSteering(new SteeringLimits(v, 2f * v), Trunk, world: null);
        var cone = new FrictionCone(Vector3.UnitY, 0.5f);
        float steepest = MathF.PI / 2f - MathF.Atan(0.5f);
        float range = v * v * MathF.Sin(2f * steepest) / G;
        RootPose a = new(Vector3.Zero, Quaternion.Identity);
        Assert.Multiple(() =>
        {
            Assert.That(steering.Steer(a, cone, new RootPose(new Vector3(0.98f * range, 0f, 0f), Quaternion.Identity), cone).Succeeded, Is.True);
            Assert.That(steering.Steer(a, cone, new RootPose(new Vector3(1.02f * range, 0f, 0f), Quaternion.Identity), cone).Succeeded, Is.False);
        });
    }

    [Test]
    public void RejectionsNameTheirReason()
    {
        var limits = new SteeringLimits(8f, 12f) { MaxApexHeight = 1.0f };
        var steering = new ParabolaSteering(limits, Trunk, world: null);
        var up = new FrictionCone(Vector3.UnitY, 1.2f);
        RootPose origin = new(Vector3.Zero, Quaternion.Identity);
        RootPose Pose(float x, float y, float z) => new(new Vector3(x, y, z), Quaternion.Identity);

        Assert.Multiple(() =>
        {
            Assert.That(steering.Steer(origin, up, Pose(0f, 1f, 0f), up).Failure, Is.EqualTo(SteeringFailure.TooClose));
            // A wall cone facing +Z, jumping along +X: the plane only grazes it.
            Assert.That(steering.Steer(origin, new FrictionCone(Vector3.UnitZ, 0.3f), Pose(2f, 0f, 0f), up).Failure,
                Is.EqualTo(SteeringFailure.TakeoffConeMissesPlane));
            Assert.That(steering.Steer(origin, up, Pose(2f, 0f, 0f), new FrictionCone(Vector3.UnitZ, 0.3f)).Failure,
                Is.EqualTo(SteeringFailure.LandingConeMissesPlane));
            Assert.That(steering.Steer(origin, up, Pose(30f, 0f, 0f), up).Failure, Is.EqualTo(SteeringFailure.TakeoffSpeed));
            // Landing 20 m below: even the gentlest launch lands faster than 12 m/s.
            Assert.That(steering.Steer(origin, up, Pose(1f, -20f, 0f), up).Failure, Is.EqualTo(SteeringFailure.LandingSpeed));
            // A landing surface facing away from the jumper (the back of a wall) cannot stop a forward-moving landing.
            Assert.That(steering.Steer(origin, up, Pose(2f, 0f, 0f), new FrictionCone(Vector3.UnitX, 0.3f)).Failure,
                Is.EqualTo(SteeringFailure.LandingCone));
            // Takeoff cone tilted backwards, landing cone tilted forwards: each admits angles, never the same ones.
            Assert.That(steering.Steer(origin, new FrictionCone(new Vector3(-1f, 1f, 0f), 0.4f), Pose(2f, 0f, 0f), new FrictionCone(new Vector3(-1f, 1f, 0f), 0.4f)).Failure,
                Is.EqualTo(SteeringFailure.EmptyAngleInterval));
            Assert.That(steering.Steer(origin, up, Pose(3f, 0.8f, 0f), up).Failure, Is.EqualTo(SteeringFailure.ApexTooHigh));
        });
    }

    [Test]
    public void AThinWallIsNeverSteppedOver()
    {
        // A single-triangle wall, zero thickness, between two poses 5 m apart. Jumps must clear it or fail.
        var up = new FrictionCone(Vector3.UnitY, 1.2f);
        RootPose a = new(new Vector3(0f, 0.5f, 0f), Quaternion.Identity);
        RootPose b = new(new Vector3(5f, 0.5f, 0f), Quaternion.Identity);
        var limits = new SteeringLimits(9f, 12f);
        for (float height = 0.5f; height <= 4f; height += 0.25f)
        {
            var wall = new Triangle(new Vector3(2.5f, -1f, -50f), new Vector3(2.5f, -1f, 50f), new Vector3(2.5f, height, 0f));
            var world = new BruteForceWorld([wall]);
            SteeringResult result = new ParabolaSteering(limits, Trunk, world).Steer(a, up, b, up);
            if (!result.Succeeded)
            {
                Assert.That(result.Failure, Is.EqualTo(SteeringFailure.Collision), $"wall {height} m");
                continue;
            }

            // Densely check the returned arc: the trunk box never touches the wall.
            for (int k = 0; k <= 5_000; k++)
            {
                RootPose pose = result.Arc.PoseAt(result.Arc.FlightTime * k / 5_000f);
                Assert.That(new OrientedBox(pose.Position, Trunk, pose.Rotation).Intersects(wall), Is.False, $"wall {height} m, sample {k}");
            }
        }

        var low = new BruteForceWorld([new Triangle(new Vector3(2.5f, -1f, -50f), new Vector3(2.5f, -1f, 50f), new Vector3(2.5f, 0.6f, 0f))]);
        var high = new BruteForceWorld([new Triangle(new Vector3(2.5f, -1f, -50f), new Vector3(2.5f, -1f, 50f), new Vector3(2.5f, 40f, 0f))]);
        Assert.Multiple(() =>
        {
            Assert.That(new ParabolaSteering(limits, Trunk, low).Steer(a, up, b, up).Succeeded, Is.True, "a low wall is jumped over");
            Assert.That(new ParabolaSteering(limits, Trunk, high).Steer(a, up, b, up).Failure, Is.EqualTo(SteeringFailure.Collision), "a high wall blocks");
        });
    }

    [Test]
    public void TrunkOrientationIsSlerpedOverTheFlight()
    {
        var up = new FrictionCone(Vector3.UnitY, 1.2f);
        Quaternion qa = Quaternion.Identity;
        Quaternion qb = Quaternion.CreateFromAxisAngle(Vector3.UnitY, 1.2f);
        var steering = new ParabolaSteering(new SteeringLimits(8f, 12f), Trunk, world: null);
        BallisticArc arc = steering.Steer(new RootPose(Vector3.Zero, qa), up, new RootPose(new Vector3(3f, 0f, 1f), qb), up).Arc;
        Quaternion mid = arc.RotationAt(arc.FlightTime / 2f);
        Assert.Multiple(() =>
        {
            Assert.That(MathF.Abs(Quaternion.Dot(arc.RotationAt(0f), qa)), Is.EqualTo(1f).Within(1e-6f));
            Assert.That(MathF.Abs(Quaternion.Dot(arc.RotationAt(arc.FlightTime), qb)), Is.EqualTo(1f).Within(1e-6f));
            Assert.That(MathF.Abs(Quaternion.Dot(mid, Quaternion.CreateFromAxisAngle(Vector3.UnitY, 0.6f))), Is.EqualTo(1f).Within(1e-6f));
        });
    }

    [Test]
    public void ArcLengthMatchesNumericalIntegration()
    {
        var random = new Random(5);
        var up = new FrictionCone(Vector3.UnitY, 1.2f);
        var steering = new ParabolaSteering(new SteeringLimits(10f, 14f), Trunk, world: null);
        int measured = 0;
        for (int i = 0; i < 200; i++)
        {
            SteeringResult result = steering.Steer(RandomPose(random, 3f), up, RandomPose(random, 3f), up);
            if (!result.Succeeded)
            {
                continue;
            }

            double length = 0;
            const int n = 20_000;
            for (int k = 0; k < n; k++)
            {
                length += Vector3.Distance(result.Arc.PositionAt(result.Arc.FlightTime * k / n), result.Arc.PositionAt(result.Arc.FlightTime * (k + 1) / n));
            }

            Assert.That(result.Arc.ArcLength, Is.EqualTo(length).Within(1e-3 * length + 1e-4), $"case {i}");
            measured++;
        }

        Assert.That(measured, Is.GreaterThan(50));
    }

    private static bool Feasible(double alpha, double x, double z, Vector3 heading, FrictionCone ca, FrictionCone cb, SteeringLimits limits, double tolerance)
    {
        double u = Math.Tan(alpha);
        double denominator = 2.0 * ((x * u) - z);
        if (denominator <= 0.0)
        {
            return false;
        }

        double xDot = Math.Sqrt(limits.Gravity * x * x / denominator);
        double t = x / xDot;
        var v0 = new Vector3((float)(xDot * heading.X), (float)(xDot * u), (float)(xDot * heading.Z));
        var vImp = new Vector3(v0.X, (float)((xDot * u) - (limits.Gravity * t)), v0.Z);
        return ca.AngleTo(v0) <= ca.HalfAngle + tolerance &&
               cb.AngleTo(-vImp) <= cb.HalfAngle + tolerance &&
               v0.Length() <= limits.TakeoffSpeedMax * (1 + tolerance) &&
               vImp.Length() <= limits.LandingSpeedMax * (1 + tolerance);
    }

    private static float Range(Random random, float min, float max) => min + ((float)random.NextDouble() * (max - min));

    private static RootPose RandomPose(Random random, float extent) =>
        new(new Vector3(Range(random, -extent, extent), Range(random, -extent / 3f, extent / 3f), Range(random, -extent, extent)), Quaternion.Identity);

    private static FrictionCone RandomCone(Random random)
    {
        // Mostly upward axes (floors), some walls and a few overhangs.
        var axis = new Vector3(Range(random, -1f, 1f), Range(random, -0.4f, 1.6f), Range(random, -1f, 1f));
        return new FrictionCone(axis, Range(random, 0.2f, 1.5f));
    }
}
