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
/// point on it, the trunk's up axis along the triangle normal with a random yaw, lifted to a random height of the
/// character's stance range (<see cref="ReducedCharacter.StanceLift"/>, no squats), pushed out of collision, and kept
/// when the trunk is free and enough limbs touch. Also places requested start and goal points
/// (<see cref="Place"/>). Thread-safe; all randomness comes from the <see cref="Random"/> passed in.
/// </summary>
internal sealed class TrunkSampler
{
    private readonly Level _level;
    private readonly TriangleBvh _bvh;
    private readonly SurfaceSet _surfaces;
    private readonly ReducedCharacter _character;
    private readonly ContactEstimator _estimator;
    private readonly int[] _candidates;
    private readonly double[] _cumulativeArea;
    private readonly bool[] _isCandidate;
    private readonly HeightRange _lift;

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

        // Above the depth that as many workspaces as must touch reach, no pose is valid: the range is cut there, and
        // when even its bottom is out of reach it slides down, keeping its width, never into the trunk's half height.
        HeightRange stance = character.StanceLift;
        float reachable = character.Limbs
            .Select(l => -l.WorkspaceAt(new RootPose(Vector3.Zero, Quaternion.Identity)).Bounds.Min.Y)
            .OrderDescending()
            .ElementAt(character.RequiredContacts - 1);
        float floor = character.TrunkHalfExtents.Y + 0.02f;
        float high = MathF.Max(floor, MathF.Min(stance.Max, reachable));
        float low = stance.Min <= high ? MathF.Max(floor, stance.Min) : MathF.Max(floor, high - (stance.Max - stance.Min));
        _lift = new HeightRange(MathF.Min(low, high), high);
    }

    /// <summary>Heights (metres) of the trunk centre above the surface point at which poses are tried.</summary>
    public HeightRange Lift => _lift;

    /// <summary>Attempts and repair parameters.</summary>
    public SamplerSettings Settings { get; }

    /// <summary>Number of triangles poses are drawn on.</summary>
    public int CandidateTriangleCount => _candidates.Length;

    /// <summary>Draws a valid pose anywhere on the level, or <c>null</c> after <see cref="SamplerSettings.MaxAttempts"/> failures (fewer when their repairs have overlapped <see cref="MaxSampleWork"/> triangles).</summary>
    public PoseEvaluation? Sample(Random random) => Sample(random, out _);

    /// <summary>As <see cref="Sample(Random)"/>, saying how many triangles the attempts' trunks overlapped in all (<see cref="MaxSampleWork"/>).</summary>
    internal PoseEvaluation? Sample(Random random, out long work) => Sample(random, null, out work);

    /// <summary>
    /// As <see cref="Sample(Random, out long)"/>, the surface point drawn uniformly over <paramref name="region"/>'s
    /// surface (a triangle of it by area, then a point of it, drawn again up to <see cref="RegionRedraws"/> times while
    /// outside the region; an attempt whose points all fell outside fails); over the whole level when
    /// <paramref name="region"/> is <c>null</c> (the same draws as before regions existed: no redraw).
    /// </summary>
    internal PoseEvaluation? Sample(Random random, SampleRegion? region, out long work)
    {
        ArgumentNullException.ThrowIfNull(random);
        work = 0;
        (int[] candidates, double[] cumulative) = region is null ? (_candidates, _cumulativeArea) : (region.Candidates, region.Cumulative);
        if (candidates.Length == 0)
        {
            return null;
        }

        for (int attempt = 0; attempt < Settings.MaxAttempts && work <= MaxSampleWork; attempt++)
        {
            int triangle = PickByArea(random, candidates, cumulative);
            Vector3 point = SamplePoint(random, _level.Triangles[triangle]);
            for (int redraw = 0; redraw < RegionRedraws && region is not null && !region.Contains(point); redraw++)
            {
                triangle = PickByArea(random, candidates, cumulative);
                point = SamplePoint(random, _level.Triangles[triangle]);
            }

            if ((region is null || region.Contains(point)) && TryAt(random, triangle, point, ref work) is { } pose)
            {
                return pose;
            }
        }

        return null;
    }

    /// <summary>Times a point drawn outside a <see cref="SampleRegion"/> is drawn again within one attempt.</summary>
    private const int RegionRedraws = 8;

    /// <summary>
    /// The candidate triangles within <paramref name="radius"/> metres, horizontally, of the segment from
    /// <paramref name="from"/> to <paramref name="to"/> (by their horizontal bounds: those that may reach into it), as a
    /// <see cref="SampleRegion"/>.
    /// </summary>
    internal SampleRegion Region(Vector3 from, Vector3 to, float radius)
    {
        var a = new Vector2(from.X, from.Z);
        var b = new Vector2(to.X, to.Z);
        var inside = new List<int>();
        var cumulative = new List<double>();
        double total = 0;
        foreach (int t in _candidates)
        {
            Triangle triangle = _level.Triangles[t];
            Vector3 min = Vector3.Min(Vector3.Min(triangle.A, triangle.B), triangle.C);
            Vector3 max = Vector3.Max(Vector3.Max(triangle.A, triangle.B), triangle.C);
            if (SampleRegion.Reaches(new Vector2(min.X, min.Z), new Vector2(max.X, max.Z), a, b, radius))
            {
                total += triangle.Area;
                inside.Add(t);
                cumulative.Add(total);
            }
        }

        double all = _cumulativeArea.Length > 0 ? _cumulativeArea[^1] : 0.0;
        return new SampleRegion(from, to, radius, [.. inside], [.. cumulative], all > 0 ? total / all : 1.0);
    }

    /// <summary>
    /// Most triangles one <see cref="Sample(Random)"/> call may find its trunk overlapping, summed over its attempts'
    /// repair steps, before it gives up: 100,000, about a millisecond of work. A character that fits its level never
    /// comes near it (measured on 1,000-node bakes of every bundled level and character: at most 110 in one call,
    /// rooftops and jumperman); a trunk nearly as large as the level (bone radii of 3 m on the pond) overlaps every
    /// triangle at every step, and spent 35 s finding nothing before the bake gave up (1.6 s with this bound). A
    /// count, not a clock: the same seed gives the same samples on any machine.
    /// </summary>
    public const long MaxSampleWork = 100_000;

    /// <summary>Rings of the placement search inside the tolerance are this far apart, metres.</summary>
    private const float PlacementStep = 0.1f;

    /// <summary>Beyond the tolerance the search goes on this far (metres), coarser, only to say how far the nearest valid pose is.</summary>
    private const float PlacementBeyond = 1.5f;

    private static readonly float[] PlacementLifts = [0.5f, 0.25f, 0.75f, 0f, 1f];

    /// <summary>Lifts of <see cref="PlaceFacing"/>, highest first: a stance on a walker's way stands tall, as walking does.</summary>
    private static readonly float[] UprightLifts = [0.75f, 1f, 0.5f, 0.25f, 0f];

    /// <summary>
    /// Places a start or goal: searches valid poses standing on surfaces by increasing horizontal distance from
    /// <paramref name="point"/> (rings 10 cm apart, each surface point met by a vertical segment reaching
    /// <see cref="EndpointTolerance.UpDown"/> + 0.3 m above and below the point, eight yaws, five lifts in the stance
    /// range) and keeps, on the first ring that has any, the pose whose contacts' centre is nearest the point within
    /// the tolerance (the first one within a third of it is taken at once). Never a pose on another floor or step: the contact centre must lie within the tolerance.
    /// Deterministic: the same point, tolerance and check give the same pose. When none is found, the search goes on
    /// beyond the tolerance only to report how far the nearest valid pose stands.
    /// </summary>
    /// <param name="point">The requested point, world metres, on or near a surface.</param>
    /// <param name="tolerance">How close the stance's contacts' centre must come to the point.</param>
    /// <param name="canStand">
    /// An extra check a pose must pass to be placed (the whole body can stand there: <see cref="Animation.IJumpAnimator.CanStand"/>);
    /// <c>null</c> for none.
    /// </param>
    /// <exception cref="ArgumentException">The tolerance is not positive, or the point is not finite.</exception>
    public EndpointPlacement Place(Vector3 point, EndpointTolerance tolerance, Func<PoseEvaluation, bool>? canStand = null) =>
        PlaceNear(point, tolerance, canStand, facing: null, searchBeyond: true);

    /// <summary>
    /// Places a stance near <paramref name="point"/> as <see cref="Place(Vector3, EndpointTolerance, Func{PoseEvaluation, bool}?)"/>
    /// does, trying the yaw <paramref name="facing"/> first and then yaws turned from it by eighths of a turn (0, +45°,
    /// −45°, +90°, …), and the stance range's upper lifts first (three quarters up, then the top): the first pose found
    /// within the tolerance is taken, so the stance faces that way and stands tall, as a walker does, when it can. Used for the stances a plan adds on its
    /// way (a jump's takeoff moved forward along walkable ground). Does not search beyond the tolerance:
    /// <see cref="EndpointPlacement.Pose"/> is <c>null</c> when nothing stands within it.
    /// </summary>
    /// <param name="point">The point, world metres, on or near a surface.</param>
    /// <param name="tolerance">How close the stance's contacts' centre must come to the point.</param>
    /// <param name="facing">Yaw to try first, radians about +Y (0 faces +Z: <c>atan2(x, z)</c> of a horizontal heading).</param>
    /// <param name="canStand">An extra check a pose must pass, or <c>null</c>.</param>
    /// <exception cref="ArgumentException">The tolerance is not positive, or the point or the yaw is not finite.</exception>
    public EndpointPlacement PlaceFacing(Vector3 point, EndpointTolerance tolerance, float facing, Func<PoseEvaluation, bool>? canStand = null)
    {
        if (!float.IsFinite(facing))
        {
            throw new ArgumentException($"The yaw {facing} is not finite.", nameof(facing));
        }

        return PlaceNear(point, tolerance, canStand, facing, searchBeyond: false);
    }

    /// <summary>
    /// As <see cref="PlaceFacing"/>, but only the yaws <paramref name="facing"/> plus each of
    /// <paramref name="yawOffsets"/> (radians, tried in order) are tried: a stance that must face within a bound of a
    /// heading (a jump's takeoff) is never placed facing elsewhere. With <paramref name="height"/> (metres of the
    /// trunk above the surface: the stance it replaces stands that high, under a ceiling or in a cave, say), the trunk
    /// is tried at that height first, then at the stance range's lifts up to it, highest first; a stance lower than
    /// the whole range (a crouch) that stands nowhere within the tolerance at its own height is tried at the range's
    /// lowest lift. Without a height, at all the range's lifts, highest first. With <paramref name="standing"/>, a
    /// pose is measured by where it stands (<see cref="StandingCentre"/>: the centre of the contacts that hold it up),
    /// not by all its contacts' centre, and <see cref="EndpointPlacement.ContactCentre"/> is that point.
    /// </summary>
    internal EndpointPlacement PlaceFacingWithin(Vector3 point, EndpointTolerance tolerance, float facing, float[] yawOffsets, Func<PoseEvaluation, bool>? canStand, float? height = null, bool standing = false)
    {
        if (!float.IsFinite(facing))
        {
            throw new ArgumentException($"The yaw {facing} is not finite.", nameof(facing));
        }

        float[]? lifts = null;
        if (height is float h)
        {
            // The stance replaced's own height first (even below the range: a crouch a sample repaired into place),
            // then no taller than it (a taller trunk may hit what the old one cleared), the highest first.
            float own = _lift.Max > _lift.Min ? (h - _lift.Min) / (_lift.Max - _lift.Min) : 0f;
            lifts = [own, .. LiftsUpTo(h + LiftSlack)];
            if (lifts.Length == 1 && own < 0f)
            {
                // A crouch lower than the whole range has no such lift: turned, its feet often no longer reach the
                // ground its old heading reached (a trunk held low over a block's top has its feet's workspaces
                // inside the block). Where no pose of its own height stands within the tolerance, it is tried at the
                // range's lowest lift, the least taller it can stand. Without that, on the desert 644 of the 651
                // turned stances the first 256 node-to-node requests placed in vain were such crouches, and each
                // jump end tried up to ten such placements (JumpFacer).
                EndpointPlacement crouched = PlaceNear(point, tolerance, canStand, facing, searchBeyond: false, yawOffsets, lifts, standing);
                return crouched.Placed ? crouched : PlaceNear(point, tolerance, canStand, facing, searchBeyond: false, yawOffsets, [0f], standing);
            }
        }

        return PlaceNear(point, tolerance, canStand, facing, searchBeyond: false, yawOffsets, lifts, standing);
    }

    /// <summary><see cref="UprightLifts"/> highest first.</summary>
    private static readonly float[] DescendingLifts = [.. UprightLifts.OrderDescending()];

    /// <summary>
    /// The <see cref="UprightLifts"/> whose trunk stands no higher than <paramref name="height"/> (metres), highest
    /// first: a tail of <see cref="DescendingLifts"/>, whose heights do not rise.
    /// </summary>
    private ReadOnlySpan<float> LiftsUpTo(float height)
    {
        int first = 0;
        while (first < DescendingLifts.Length && !(_lift.Lerp(DescendingLifts[first]) <= height))
        {
            first++;
        }

        return DescendingLifts.AsSpan(first);
    }

    /// <summary>How much higher (metres) than the height asked a lift of <see cref="PlaceFacingWithin"/> may stand.</summary>
    private const float LiftSlack = 0.03f;

    /// <summary>Yaw offsets of <see cref="PlaceFacing"/>: 0, +45°, −45°, +90°, … (eighths of a turn).</summary>
    private static readonly float[] EighthTurns = [.. Enumerable.Range(0, 8).Select(y => (y % 2 == 1 ? (y + 1) / 2 : -(y / 2)) * MathF.PI / 4f)];

    /// <summary>Yaws of <see cref="Place(Vector3, EndpointTolerance, Func{PoseEvaluation, bool}?)"/>: eighths of a turn from 0.</summary>
    private static readonly float[] AllYaws = [.. Enumerable.Range(0, 8).Select(y => y * MathF.PI / 4f)];

    private EndpointPlacement PlaceNear(Vector3 point, EndpointTolerance tolerance, Func<PoseEvaluation, bool>? canStand, float? facing, bool searchBeyond, float[]? yawOffsets = null, float[]? liftOrder = null, bool standing = false)
    {
        // A request's start or goal (placed again by every request to the same point: agents sent to one spot), or a
        // stance placed facing a way (a jump turned to face it, a takeoff moved along walkable ground): remembered.
        return _placings.GetOrAdd(new Placing(point, tolerance, facing, searchBeyond, yawOffsets, liftOrder, canStand, standing), this, static (k, sampler) => k.PlaceWith(sampler));
    }

    /// <summary>
    /// Placements that each generation of the remembered ones keeps (<see cref="PlaceNear"/>,
    /// <see cref="RememberedResults{TKey, TValue}"/>). A placement is a function of what it is asked (the point,
    /// tolerance, facing, yaws, lifts, whether it searches beyond the tolerance and the stance check, which
    /// <see cref="Query.QuerySettings.CanStand"/> documents as a function of the pose), and queries place the same
    /// stances again and again (a roadmap jump turned to face its way in every query whose path takes it, a repair
    /// placing them anew, the start and goal of every request to the same points, which on the rooftops took up to
    /// 30 ms each where the point has no stance within the tolerance): what is remembered never changes a result,
    /// only how soon it comes.
    /// </summary>
    private const int RememberedPlacings = 8_192;

    private readonly RememberedResults<Placing, EndpointPlacement> _placings = new(RememberedPlacings);

    /// <summary>Placements kept for good (a prepared query's, <see cref="Query.PathQuery.Prepare"/>).</summary>
    internal int KeptCount => _placings.KeptCount;

    /// <summary>Gives back the spare room of the placements kept for good.</summary>
    internal void TrimKept() => _placings.TrimKept();

    /// <summary>What a placement is asked: the point (metres), tolerance, facing (radians, or none), whether it searches beyond the tolerance, yaw offsets and lifts tried (by content), the stance check (by delegate equality) and whether a pose is measured by where it stands.</summary>
    private sealed class Placing(Vector3 point, EndpointTolerance tolerance, float? facing, bool searchBeyond, float[]? yaws, float[]? lifts, Func<PoseEvaluation, bool>? canStand, bool standing) : IEquatable<Placing>
    {
        private readonly int _hash = HashCode.Combine(point, tolerance, facing, searchBeyond, yaws?.Length ?? -1, yaws is { Length: > 0 } ? yaws[^1] : 0f, lifts?.Length ?? -1, HashCode.Combine(lifts is { Length: > 0 } ? lifts[0] : 0f, standing));

        public bool Equals(Placing? other) =>
            other is not null && _hash == other._hash && point == other.Point && tolerance == other.Tolerance && facing == other.Facing
            && searchBeyond == other.SearchBeyond && standing == other.Standing && Same(yaws, other.Yaws) && Same(lifts, other.Lifts) && Equals(canStand, other.CanStand);

        public override bool Equals(object? obj) => Equals(obj as Placing);

        public override int GetHashCode() => _hash;

        /// <summary>The placement asked, made anew by <paramref name="sampler"/>.</summary>
        public EndpointPlacement PlaceWith(TrunkSampler sampler) => sampler.PlaceAnew(point, tolerance, canStand, facing, searchBeyond, yaws, lifts, standing);

        private Vector3 Point => point;

        private EndpointTolerance Tolerance => tolerance;

        private float? Facing => facing;

        private bool SearchBeyond => searchBeyond;

        private bool Standing => standing;

        private float[]? Yaws => yaws;

        private float[]? Lifts => lifts;

        private Func<PoseEvaluation, bool>? CanStand => canStand;

        private static bool Same(float[]? a, float[]? b) => a is null ? b is null : b is not null && a.AsSpan().SequenceEqual(b);
    }

    /// <summary><see cref="PlaceNear"/> without the remembered placements.</summary>
    private EndpointPlacement PlaceAnew(Vector3 point, EndpointTolerance tolerance, Func<PoseEvaluation, bool>? canStand, float? facing, bool searchBeyond, float[]? yawOffsets, float[]? liftOrder, bool standing)
    {
        float[] yaws = facing is null ? AllYaws : yawOffsets ?? EighthTurns;
        tolerance.Validate();
        if (!float.IsFinite(point.X) || !float.IsFinite(point.Y) || !float.IsFinite(point.Z))
        {
            throw new ArgumentException($"The point ({point.X}, {point.Y}, {point.Z}) is not finite.", nameof(point));
        }

        float window = tolerance.UpDown + 0.3f;
        float nearest = float.PositiveInfinity;
        PoseEvaluation? best = null;
        Vector3 bestCentre = default;
        float bestScore = float.PositiveInfinity;
        var hits = new List<RayHit>();
        float radius = 0f;
        float reach = tolerance.Across + (searchBeyond ? PlacementBeyond : 0f);
        for (int ring = 0; radius <= reach; ring++)
        {
            bool beyond = radius > tolerance.Across + PlacementStep;
            float spacing = beyond ? 2.5f * PlacementStep : PlacementStep;
            int count = ring == 0 ? 1 : Math.Max(6, (int)MathF.Ceiling(2f * MathF.PI * radius / spacing));
            for (int i = 0; i < count; i++)
            {
                float angle = (2f * MathF.PI * i / count) + (0.37f * ring);
                Vector3 column = point + new Vector3(radius * MathF.Cos(angle), 0f, radius * MathF.Sin(angle));
                VerticalHits(column, point.Y + window, point.Y - window, hits);
                foreach (RayHit hit in hits)
                {
                    if (!_isCandidate[hit.Triangle] || !(hit.Normal.Y > 0.05f))
                    {
                        continue; // nothing to stand on: a wall, a ceiling or a face no limb may touch
                    }

                    foreach (float offset in yaws)
                    {
                        // From the facing yaw: 0, +1, −1, +2, −2, … eighths of a turn (or the offsets asked for).
                        float yaw = (facing ?? 0f) + offset;
                        float[] lifts = liftOrder ?? (facing is null ? PlacementLifts : UprightLifts);
                        foreach (float lift in beyond ? lifts.AsSpan(0, 1) : lifts)
                        {
                            PoseEvaluation? pose = TryPose(hit.Triangle, hit.Point, yaw, _lift.Lerp(lift));
                            if (pose is null)
                            {
                                continue;
                            }

                            Vector3 centre = standing ? StandingCentre(pose.Contacts, pose.Pose.Position) : ContactCentre(pose);
                            float across = new Vector2(centre.X - point.X, centre.Z - point.Z).Length();
                            float upDown = MathF.Abs(centre.Y - point.Y);
                            if (across <= tolerance.Across && upDown <= tolerance.UpDown)
                            {
                                float score = MathF.Sqrt(((across / tolerance.Across) * (across / tolerance.Across)) + ((upDown / tolerance.UpDown) * (upDown / tolerance.UpDown)));
                                if (score < bestScore && canStand?.Invoke(pose) != false)
                                {
                                    (best, bestCentre, bestScore) = (pose, centre, score);
                                    if (score <= (facing is null ? GoodEnough : 1f))
                                    {
                                        return Placed();
                                    }
                                }
                            }
                            else
                            {
                                nearest = MathF.Min(nearest, Vector3.Distance(centre, point));
                            }
                        }
                    }
                }
            }

            if (best is not null)
            {
                return Placed();
            }

            radius += beyond ? 2.5f * PlacementStep : PlacementStep;
        }

        return new EndpointPlacement(point, null, point, float.PositiveInfinity, float.PositiveInfinity, float.IsFinite(nearest) ? nearest : null);

        EndpointPlacement Placed() =>
            new(point, best, bestCentre, new Vector2(bestCentre.X - point.X, bestCentre.Z - point.Z).Length(), MathF.Abs(bestCentre.Y - point.Y), null);
    }

    /// <summary>A placement whose contact centre is within this share of the tolerance (in the scaled norm) is taken at once.</summary>
    private const float GoodEnough = 0.35f;

    /// <summary>The centre of a pose's contacts, world metres.</summary>
    public static Vector3 ContactCentre(PoseEvaluation pose)
    {
        ArgumentNullException.ThrowIfNull(pose);
        return Contact.Centre(pose.Contacts, pose.Pose.Position);
    }

    /// <summary>
    /// Where a stance stands (world metres): the centre of the contacts that hold it up, not of hands resting higher
    /// than the character's step height (<see cref="ReducedCharacter.StepReach"/>) above its feet's centre, which lean
    /// on something: a hand on a block's top beside the feet raises the contacts' centre by a third of the block's
    /// height and draws it toward the block. A stance with no foot on the level, or no hand that high, stands at its
    /// contacts' centre (<paramref name="none"/> when it has no contact).
    /// </summary>
    internal Vector3 StandingCentre(IReadOnlyList<Contact> contacts, Vector3 none)
    {
        ArgumentNullException.ThrowIfNull(contacts);
        float feet = 0f;
        int footCount = 0;
        for (int i = 0; i < contacts.Count; i++) // indexed: a foreach over the interface boxes its enumerator, on a query's hot path
        {
            if (_character.Limbs[contacts[i].Limb].Kind == LimbKind.Foot)
            {
                feet += contacts[i].Position.Y;
                footCount++;
            }
        }

        if (footCount == 0)
        {
            return Contact.Centre(contacts, none);
        }

        float lean = (feet / footCount) + _character.StepReach;
        Vector3 sum = Vector3.Zero;
        int count = 0;
        for (int i = 0; i < contacts.Count; i++)
        {
            Contact contact = contacts[i];
            if (_character.Limbs[contact.Limb].Kind == LimbKind.Foot || !(contact.Position.Y > lean))
            {
                sum += contact.Position;
                count++;
            }
        }

        return count == contacts.Count ? Contact.Centre(contacts, none) : sum / count;
    }

    /// <summary>Every triangle met by the vertical segment at (x, z) of <paramref name="column"/> from <paramref name="top"/> down to <paramref name="bottom"/>, top first.</summary>
    private void VerticalHits(Vector3 column, float top, float bottom, List<RayHit> hits)
    {
        hits.Clear();
        var origin = new Vector3(column.X, top, column.Z);
        float remaining = top - bottom;
        for (int guard = 0; guard < 16 && remaining > 0f; guard++)
        {
            if (!_bvh.Raycast(origin, new Vector3(0f, -remaining, 0f), 1f, out RayHit hit))
            {
                break;
            }

            hits.Add(hit);
            float travelled = (remaining * hit.Distance) + 1e-4f;
            origin.Y -= travelled;
            remaining -= travelled;
        }
    }

    /// <summary>One attempt at a surface point of a triangle: orient with a random yaw, lift to a random height of the stance range, repair, evaluate.</summary>
    private PoseEvaluation? TryAt(Random random, int triangle, Vector3 surfacePoint, ref long work)
    {
        float yaw = (float)(random.NextDouble() * 2.0 * Math.PI);
        float lift = _lift.Lerp((float)random.NextDouble());
        return TryPose(triangle, surfacePoint, yaw, lift, ref work);
    }

    /// <summary>
    /// A pose standing on a surface point of a triangle: the trunk's up along the triangle normal turned by
    /// <paramref name="yaw"/> radians, the trunk centre <paramref name="lift"/> metres above the point, pushed out of
    /// collision; <c>null</c> unless it is valid.
    /// </summary>
    private PoseEvaluation? TryPose(int triangle, Vector3 surfacePoint, float yaw, float lift)
    {
        long work = 0;
        return TryPose(triangle, surfacePoint, yaw, lift, ref work);
    }

    /// <summary>As <see cref="TryPose(int, Vector3, float, float)"/>, adding to <paramref name="work"/> the triangles its trunk overlapped at each repair step.</summary>
    private PoseEvaluation? TryPose(int triangle, Vector3 surfacePoint, float yaw, float lift, ref long work)
    {
        Vector3 normal = _level.Triangles[triangle].Normal;
        Quaternion rotation = Rotations.AlignUp(normal) * Quaternion.CreateFromAxisAngle(Vector3.UnitY, yaw);
        Vector3 position = surfacePoint + (normal * lift);

        List<int> hits = s_overlapping ??= [];
        for (int step = 0; ; step++)
        {
            var trunk = new OrientedBox(position, _character.TrunkHalfExtents, rotation);
            hits.Clear();
            _bvh.OverlappingTriangles(trunk, hits);
            work += hits.Count;
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

        return _estimator.ValidOrNull(new RootPose(position, rotation));
    }

    /// <summary>The triangles a trial trunk overlaps (<see cref="TryPose(int, Vector3, float, float, ref long)"/>), kept per thread between trials.</summary>
    [ThreadStatic]
    private static List<int>? s_overlapping;

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
