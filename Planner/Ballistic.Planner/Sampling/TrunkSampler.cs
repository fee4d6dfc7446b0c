using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Surfaces;

namespace Ballistic.Planner.Sampling;

/// <summary>
/// VALIDTRUNKRANDOMSAMPLE: draws root poses near the level's contact surfaces: a triangle chosen by area, a uniform
/// point on it, the trunk's up axis along the triangle normal with a random yaw, lifted to a random height the
/// limbs can reach, pushed out of collision, and kept when the trunk is free and enough limbs touch. Thread-safe;
/// all randomness comes from the <see cref="Random"/> passed in.
/// </summary>
public sealed class TrunkSampler
{
    private readonly Level _level;
    private readonly TriangleBvh _bvh;
    private readonly SurfaceSet _surfaces;
    private readonly ReducedCharacter _character;
    private readonly ContactEstimator _estimator;
    private readonly int[] _candidates;
    private readonly double[] _cumulativeArea;
    private readonly bool[] _isCandidate;

    /// <summary>Creates a sampler.</summary>
    public TrunkSampler(Level level, TriangleBvh bvh, SurfaceSet surfaces, ReducedCharacter character, ContactEstimator estimator, SamplerSettings? settings = null)
    {
        ArgumentNullException.ThrowIfNull(level);
        ArgumentNullException.ThrowIfNull(bvh);
        ArgumentNullException.ThrowIfNull(surfaces);
        ArgumentNullException.ThrowIfNull(character);
        ArgumentNullException.ThrowIfNull(estimator);
        _level = level;
        _bvh = bvh;
        _surfaces = surfaces;
        _character = character;
        _estimator = estimator;
        Settings = settings ?? new SamplerSettings();

        // Triangles some limb could touch: in a contact surface and accepted by at least one limb's filter.
        var candidates = new List<int>();
        var cumulative = new List<double>();
        double total = 0;
        _isCandidate = new bool[level.Triangles.Count];
        for (int t = 0; t < level.Triangles.Count; t++)
        {
            _isCandidate[t] = IsCandidate(t);
            if (_isCandidate[t])
            {
                total += level.Triangles[t].Area;
                candidates.Add(t);
                cumulative.Add(total);
            }
        }

        _candidates = [.. candidates];
        _cumulativeArea = [.. cumulative];
        StanceLift = MathF.Max(
            character.TrunkHalfExtents.Y + 0.02f,
            character.Limbs.Select(l => -l.WorkspaceCenter.Y).OrderDescending().Take(character.RequiredContacts).Average());
    }

    /// <summary>Attempts and repair parameters.</summary>
    public SamplerSettings Settings { get; }

    /// <summary>Number of triangles poses are drawn on.</summary>
    public int CandidateTriangleCount => _candidates.Length;

    /// <summary>Draws a valid pose anywhere on the level, or <c>null</c> after <see cref="SamplerSettings.MaxAttempts"/> failures.</summary>
    public PoseEvaluation? Sample(Random random)
    {
        ArgumentNullException.ThrowIfNull(random);
        if (_candidates.Length == 0)
        {
            return null;
        }

        for (int attempt = 0; attempt < Settings.MaxAttempts; attempt++)
        {
            int triangle = PickByArea(random, _candidates, _cumulativeArea);
            PoseEvaluation? pose = TryAt(random, triangle, SamplePoint(random, _level.Triangles[triangle]));
            if (pose is not null)
            {
                return pose;
            }
        }

        return null;
    }

    /// <summary>
    /// Draws valid poses whose surface point lies within <paramref name="radius"/> metres of <paramref name="point"/>
    /// and returns the one whose trunk centre is closest to the point, or <c>null</c> when none is found.
    /// </summary>
    public PoseEvaluation? SampleNear(Random random, Vector3 point, float radius, int wanted = 2)
    {
        ArgumentNullException.ThrowIfNull(random);

        // Fast path: surfaces below points of the disc around the query point, found by vertical rays.
        PoseEvaluation? best = null;
        float bestDistance = float.PositiveInfinity;
        int found = 0;
        for (int ray = 0; ray < 32 && found < wanted; ray++)
        {
            float angle = (float)(random.NextDouble() * 2.0 * Math.PI);
            float distance = radius * MathF.Sqrt((float)random.NextDouble());
            Vector3 origin = point + new Vector3(distance * MathF.Cos(angle), radius, distance * MathF.Sin(angle));
            if (!_bvh.Raycast(origin, new Vector3(0f, -2f * radius, 0f), 1f, out RayHit hit) ||
                !_isCandidate[hit.Triangle] || Vector3.Distance(hit.Point, point) > radius)
            {
                continue;
            }

            PoseEvaluation? pose = TryAt(random, hit.Triangle, hit.Point, StanceLift * (0.9f + (0.2f * (float)random.NextDouble())));
            if (pose is not null)
            {
                found++;
                float d = Vector3.Distance(pose.Pose.Position, point);
                if (d < bestDistance)
                {
                    best = pose;
                    bestDistance = d;
                }
            }
        }

        return best ?? SampleNearAnySurface(random, point, radius, wanted);
    }

    /// <summary>The general path of <see cref="SampleNear"/>: every candidate triangle near the point, chosen by area.</summary>
    private PoseEvaluation? SampleNearAnySurface(Random random, Vector3 point, float radius, int wanted)
    {
        var nearby = new List<int>();
        _bvh.TrianglesNear(new Aabb(point - new Vector3(radius), point + new Vector3(radius)), nearby);
        nearby.Sort();
        var candidates = new List<int>();
        var cumulative = new List<double>();
        double total = 0;
        foreach (int t in nearby)
        {
            if (_isCandidate[t])
            {
                // Weight by the part of the triangle near the point, approximated by its area.
                total += _level.Triangles[t].Area;
                candidates.Add(t);
                cumulative.Add(total);
            }
        }

        if (candidates.Count == 0)
        {
            return null;
        }

        int[] candidateArray = [.. candidates];
        double[] cumulativeArray = [.. cumulative];
        PoseEvaluation? best = null;
        float bestDistance = float.PositiveInfinity;
        int found = 0;
        for (int attempt = 0; attempt < Settings.MaxAttempts && found < wanted; attempt++)
        {
            int triangle = PickByArea(random, candidateArray, cumulativeArray);
            Triangle tri = _level.Triangles[triangle];

            // A point of the triangle within the radius: sample, or fall back to the closest point.
            Vector3 surfacePoint = SamplePoint(random, tri);
            if (Vector3.Distance(surfacePoint, point) > radius)
            {
                surfacePoint = tri.ClosestPoint(point);
                if (Vector3.Distance(surfacePoint, point) > radius)
                {
                    continue;
                }
            }

            PoseEvaluation? pose = TryAt(random, triangle, surfacePoint);
            if (pose is null)
            {
                continue;
            }

            found++;
            float distance = Vector3.Distance(pose.Pose.Position, point);
            if (distance < bestDistance)
            {
                best = pose;
                bestDistance = distance;
            }
        }

        return best;
    }

    /// <summary>
    /// The height above a surface at which the character stands naturally: the mean depth of the workspace centres of
    /// the lowest limbs it needs in contact (never inside its own trunk).
    /// </summary>
    public float StanceLift { get; }

    /// <summary>One attempt at a surface point of a triangle: orient, lift (randomly when <paramref name="lift"/> is null), repair, evaluate.</summary>
    private PoseEvaluation? TryAt(Random random, int triangle, Vector3 surfacePoint, float? lift = null)
    {
        Vector3 normal = _level.Triangles[triangle].Normal;
        float yaw = (float)(random.NextDouble() * 2.0 * Math.PI);
        Quaternion rotation = AlignUp(normal) * Quaternion.CreateFromAxisAngle(Vector3.UnitY, yaw);
        float low = _character.TrunkHalfExtents.Y + 0.02f;
        float high = MathF.Max(low, _character.Reach);
        Vector3 position = surfacePoint + (normal * (lift ?? (low + ((float)random.NextDouble() * (high - low)))));

        var hits = new List<int>();
        for (int step = 0; ; step++)
        {
            var trunk = new OrientedBox(position, _character.TrunkHalfExtents, rotation);
            hits.Clear();
            _bvh.OverlappingTriangles(trunk, hits);
            if (hits.Count == 0)
            {
                break;
            }

            if (step >= Settings.RepairSteps)
            {
                return null;
            }

            Vector3 push = Vector3.Zero;
            foreach (int t in hits)
            {
                push += _level.Triangles[t].Normal;
            }

            push = push.LengthSquared() > 1e-6f ? Vector3.Normalize(push) : normal;
            position += push * Settings.RepairStep;
        }

        PoseEvaluation evaluation = _estimator.EvaluateContacts(new RootPose(position, rotation));
        return evaluation.IsValid ? evaluation : null;
    }

    private bool IsCandidate(int triangle)
    {
        if (_surfaces.SurfaceOf(triangle) < 0)
        {
            return false;
        }

        Vector3 normal = _level.Triangles[triangle].Normal;
        foreach (Limb limb in _character.Limbs)
        {
            if (limb.Filter.Accepts(normal))
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>The shortest rotation taking +Y to <paramref name="up"/>.</summary>
    internal static Quaternion AlignUp(Vector3 up)
    {
        float dot = Math.Clamp(up.Y, -1f, 1f);
        if (dot > 0.999999f)
        {
            return Quaternion.Identity;
        }

        if (dot < -0.999999f)
        {
            return Quaternion.CreateFromAxisAngle(Vector3.UnitX, MathF.PI);
        }

        Vector3 axis = Vector3.Normalize(Vector3.Cross(Vector3.UnitY, up));
        return Quaternion.CreateFromAxisAngle(axis, MathF.Acos(dot));
    }

    private static int PickByArea(Random random, int[] candidates, double[] cumulative)
    {
        double r = random.NextDouble() * cumulative[^1];
        int index = Array.BinarySearch(cumulative, r);
        index = index < 0 ? ~index : index;
        return candidates[Math.Min(index, candidates.Length - 1)];
    }

    private static Vector3 SamplePoint(Random random, in Triangle t)
    {
        float r1 = MathF.Sqrt((float)random.NextDouble());
        float r2 = (float)random.NextDouble();
        return (t.A * (1f - r1)) + (t.B * (r1 * (1f - r2))) + (t.C * (r1 * r2));
    }
}
