using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Walking;

/// <summary>
/// The walking steering method: links two stances by a straight walk (in the horizontal plane) when the ground
/// allows it. From the first stance's contact centre to the second's, the ground is found every
/// <see cref="SampleSpacing"/> metres by a ray cast down from the trunk's lowest walking height; the walk is valid
/// when the ground is there at every sample (no gap), never rises or drops more than the character's step height
/// from one sample to the next beyond what its slope allows (stairs are fine, a ledge is not), is never steeper than
/// the character walks on in the walk's direction (<see cref="WalkingLimits.IsWalkable"/>, over two samples in a row,
/// so a ray grazing a stair's edge does not count), nothing stands between the ground and the
/// trunk, and the trunk box carried along the walk (<see cref="Walk.PoseAt(float)"/>, its turns in place included) never touches the level.
/// Deterministic and thread-safe.
/// </summary>
/// <remarks>
/// The trunk check is continuous like the jump sweep's: the walk is cut into intervals over which no trunk point
/// moves more than the trunk's smallest half extent; the mid-interval box grown by the most any point can move in
/// half the interval being free proves the interval free; otherwise the interval is halved down to the collision
/// tolerance.
/// </remarks>
internal sealed class WalkSteering
{
    /// <summary>Horizontal spacing of the ground samples, metres.</summary>
    public const float SampleSpacing = 0.05f;

    /// <summary>Largest spacing of the points of a walk's <see cref="Walk.Path"/>, metres.</summary>
    public const float PathSpacing = 0.25f;

    private readonly TriangleBvh _world;
    private readonly Vector3 _trunkHalfExtents;
    private readonly float _tolerance;
    private readonly float _legSpace;
    private readonly float _maxRise;
    private readonly GroundSlopeTest _slope;

    /// <summary>Creates the walking steering method for a character on a level.</summary>
    /// <param name="world">The level's collision geometry (rays and box overlaps).</param>
    /// <param name="character">The character: its walking limits, trunk box and stance heights.</param>
    /// <param name="collisionTolerance">Growth (metres) below which a touching interval counts as a collision; not negative.</param>
    public WalkSteering(TriangleBvh world, ReducedCharacter character, float collisionTolerance)
    {
        ArgumentNullException.ThrowIfNull(world);
        ArgumentNullException.ThrowIfNull(character);
        ArgumentOutOfRangeException.ThrowIfNegative(collisionTolerance);
        _world = world;
        _trunkHalfExtents = character.TrunkHalfExtents;
        _tolerance = collisionTolerance;
        Limits = character.Walking;
        _maxRise = Limits.StepHeight;
        _slope = new GroundSlopeTest(Limits);

        // Between the ground and the trunk's bottom in its lowest stance the legs move: only ground may be there.
        _legSpace = MathF.Max(character.StanceLift.Min - character.TrunkHalfExtents.Y, _maxRise) + 0.01f;
    }

    /// <summary>The character's walking limits.</summary>
    public WalkingLimits Limits { get; }

    /// <summary>
    /// The walk from <paramref name="from"/> to <paramref name="to"/>, or why there is none. The ground path runs
    /// straight (seen from above) between the stances' contact centres; its points are at most
    /// <see cref="PathSpacing"/> apart and lie on the ground found.
    /// </summary>
    /// <param name="from">The stance walked from, world frame.</param>
    /// <param name="to">The stance walked to, world frame.</param>
    /// <param name="maxDistance">The farthest (metres, horizontally between contact centres) a walk may go; +∞ for no limit.</param>
    public WalkResult Steer(RoadmapNode from, RoadmapNode to, float maxDistance = float.PositiveInfinity)
    {
        if (Refused(from, to, maxDistance) is WalkFailure refused)
        {
            return new WalkResult(null, refused);
        }

        var path = new List<Vector3>();
        WalkFailure ground = TraceGround(from.ContactCentre, to.ContactCentre, path, out _);
        if (ground != WalkFailure.None)
        {
            return new WalkResult(null, ground);
        }

        var walk = new Walk(from, to, path, Limits.Speed, turnRate: Limits.TurnRate, maxGrade: Limits.MaxGrade, pitchSpan: Limits.PitchSpan, crossGrades: CrossGrades(path, from.Pose));
        return TrunkIsFree(walk) ? new WalkResult(walk, WalkFailure.None) : new WalkResult(null, WalkFailure.TrunkCollides);
    }

    /// <summary>
    /// <see cref="Steer"/> with the ground traced and the trunk checked from memory, for a query's path
    /// post-processing (cutting jumps down to walks, shortcuts, turns, steering into the roadmap), which asks for the
    /// same walks in every query whose path passes there. A walk's ground path and its trunk check are a function of
    /// its stances' poses and contact centres alone (<see cref="RememberedResults{TKey, TValue}"/>), so what is
    /// remembered never changes a result; the walk itself is made anew on <paramref name="from"/> and
    /// <paramref name="to"/>. The bake, whose pairs never repeat, steers without it.
    /// </summary>
    /// <param name="from">The stance walked from, world frame.</param>
    /// <param name="to">The stance walked to, world frame.</param>
    /// <param name="maxDistance">The farthest (metres, horizontally between contact centres) a walk may go; +∞ for no limit.</param>
    internal WalkResult SteerRemembered(RoadmapNode from, RoadmapNode to, float maxDistance = float.PositiveInfinity)
    {
        if (Refused(from, to, maxDistance) is WalkFailure refused)
        {
            return new WalkResult(null, refused);
        }

        (Vector3[]? path, float[]? cross, WalkFailure failure) = _traced.GetOrAdd(new WalkKey(from.Pose, from.ContactCentre, to.Pose, to.ContactCentre), this, static (k, steering) => steering.Trace(k));
        return path is null ? new WalkResult(null, failure) : new WalkResult(new Walk(from, to, path, Limits.Speed, turnRate: Limits.TurnRate, maxGrade: Limits.MaxGrade, pitchSpan: Limits.PitchSpan, crossGrades: cross), WalkFailure.None);
    }

    /// <summary>Why no walk is even traced from <paramref name="from"/> to <paramref name="to"/> (the character does not walk, or they lie farther apart than <paramref name="maxDistance"/>), or <c>null</c>.</summary>
    private WalkFailure? Refused(RoadmapNode from, RoadmapNode to, float maxDistance)
    {
        ArgumentNullException.ThrowIfNull(from);
        ArgumentNullException.ThrowIfNull(to);
        if (!Limits.CanWalk)
        {
            return WalkFailure.NotWalking;
        }

        Vector3 a = from.ContactCentre;
        Vector3 b = to.ContactCentre;
        return new Vector2(b.X - a.X, b.Z - a.Z).Length() <= maxDistance ? null : WalkFailure.TooFar;
    }

    /// <summary>Walks each generation of <see cref="SteerRemembered"/> keeps (a ground path of a few dozen points each).</summary>
    private const int RememberedWalks = 4_096;

    private readonly RememberedResults<WalkKey, (Vector3[]? Path, float[]? Cross, WalkFailure Failure)> _traced = new(RememberedWalks);

    /// <summary>Walks kept for good (a prepared query's, <see cref="Query.PathQuery.Prepare"/>).</summary>
    internal int KeptCount => _traced.KeptCount;

    /// <summary>Gives back the spare room of the walks kept for good.</summary>
    internal void TrimKept() => _traced.TrimKept();

    /// <summary>What a remembered walk depends on: its stances' root poses and contact centres (metres).</summary>
    private readonly record struct WalkKey(RootPose FromPose, Vector3 From, RootPose ToPose, Vector3 To);

    /// <summary>The ground path of the walk <paramref name="key"/> asks for (with its cross grades) and the trunk's check along it, as <see cref="Steer"/> makes them: the path, or why there is none.</summary>
    private (Vector3[]? Path, float[]? Cross, WalkFailure Failure) Trace(WalkKey key)
    {
        var path = new List<Vector3>();
        WalkFailure ground = TraceGround(key.From, key.To, path, out _);
        if (ground != WalkFailure.None)
        {
            return (null, null, ground);
        }

        // The trunk's check needs only the poses and the path: stances of those poses stand in for the real ones.
        float[]? cross = CrossGrades(path, key.FromPose);
        var walk = new Walk(new RoadmapNode(-1, key.FromPose, default, []), new RoadmapNode(-2, key.ToPose, default, []), path, Limits.Speed, turnRate: Limits.TurnRate, maxGrade: Limits.MaxGrade, pitchSpan: Limits.PitchSpan, crossGrades: cross);
        return TrunkIsFree(walk) ? ([.. path], cross, WalkFailure.None) : (null, null, WalkFailure.TrunkCollides);
    }

    /// <summary>
    /// For a walker whose trunk rolls with the ground (<see cref="WalkingLimits.RollSpan"/>), the ground's rise per
    /// metre toward its left at each point of <paramref name="path"/> (<see cref="Walk.CrossGradeAt(float)"/>); <c>null</c>
    /// for one whose trunk does not roll. At each point the ground is found <see cref="WalkingLimits.RollSpan"/> to
    /// either side, across the path's heading (the stance's own heading, <paramref name="from"/>, for a turn in
    /// place), within the rise the walkable slope across allows plus a step: the grade is the rise from the right
    /// side's ground to the left's, or from the path's point to the one side found (a kerb's top or a wall beyond
    /// the other), 0 where neither is; it is kept within that slope and averaged over the points within the span
    /// along the path, so that the trunk rolls as smoothly as it pitches.
    /// </summary>
    private float[]? CrossGrades(IReadOnlyList<Vector3> path, in RootPose from)
    {
        float span = Limits.RollSpan;
        if (!(span > 0f))
        {
            return null;
        }

        Vector3 heading = new(path[^1].X - path[0].X, 0f, path[^1].Z - path[0].Z);
        if (heading.LengthSquared() < 1e-8f)
        {
            heading = from.Forward with { Y = 0f };
        }

        heading = heading.LengthSquared() < 1e-8f ? Vector3.UnitZ : Vector3.Normalize(heading);
        var left = new Vector3(heading.Z, 0f, -heading.X);
        float steepest = MathF.Tan(Limits.MaxSlopeDegrees * MathF.PI / 180f);
        float window = (span * steepest) + _maxRise;
        var raw = new float[path.Count];
        for (int i = 0; i < path.Count; i++)
        {
            Vector3 p = path[i];
            float? up = Rise(p + (left * span));
            float? down = Rise(p - (left * span));
            float grade = (up, down) switch
            {
                (float l, float r) => (l - r) / (2f * span),
                (float l, null) => l / span,
                (null, float r) => -r / span,
                _ => 0f,
            };
            raw[i] = Math.Clamp(grade, -steepest, steepest);

            float? Rise(Vector3 q) =>
                _world.Raycast(new Vector3(q.X, p.Y + window, q.Z), -Vector3.UnitY, 2f * window, out RayHit hit) ? hit.Point.Y - p.Y : null;
        }

        var along = new float[path.Count];
        for (int i = 1; i < path.Count; i++)
        {
            along[i] = along[i - 1] + Vector3.Distance(path[i - 1], path[i]);
        }

        // The points within the span of each (a run, the distances along the path rising), summed in order.
        var grades = new float[path.Count];
        (int first, int last) = (0, 0);
        for (int i = 0; i < path.Count; i++)
        {
            while (along[i] - along[first] > span + 1e-4f)
            {
                first++;
            }

            while (last + 1 < path.Count && along[last + 1] - along[i] <= span + 1e-4f)
            {
                last++;
            }

            float sum = 0f;
            for (int j = first; j <= last; j++)
            {
                sum += raw[j];
            }

            grades[i] = sum / (last - first + 1);
        }

        return grades;
    }

    /// <summary>
    /// A turn in place from <paramref name="from"/> to <paramref name="to"/>, two stances at (nearly) the same spot
    /// facing different ways: a walk whose ground path joins their contact centres (the feet re-step while the trunk
    /// turns), checked like <see cref="Steer"/>'s (ground, steps, slope, trunk); <c>null</c> when the character
    /// does not walk, the ground or the trunk fails, or the stances lie more than <paramref name="maxDistance"/> apart.
    /// </summary>
    /// <param name="from">The stance turned from, world frame.</param>
    /// <param name="to">The stance turned to, world frame.</param>
    /// <param name="maxDistance">The farthest (metres, horizontally between contact centres) the stances may lie apart.</param>
    internal Walk? Turn(RoadmapNode from, RoadmapNode to, float maxDistance)
    {
        ArgumentNullException.ThrowIfNull(from);
        ArgumentNullException.ThrowIfNull(to);
        Vector3 a = from.ContactCentre;
        Vector3 b = to.ContactCentre;
        if (!Limits.CanWalk || !(new Vector2(b.X - a.X, b.Z - a.Z).Length() <= maxDistance))
        {
            return null;
        }

        return SteerRemembered(from, to).Walk;
    }

    /// <summary>
    /// How far (metres, horizontally) the ground allows a walk from <paramref name="from"/> straight toward
    /// <paramref name="toward"/> (seen from above): the distance of the last ground sample before the first gap,
    /// step too high or steep stretch, by the same ground checks as <see cref="Steer"/> makes; the whole distance
    /// when the ground passes all the way. Only the ground is checked, not the trunk, nor the stance at either end.
    /// </summary>
    /// <param name="from">A point on the ground (such as a stance's contact centre), world metres.</param>
    /// <param name="toward">The point walked toward, world metres; only its horizontal position matters.</param>
    /// <param name="ground">
    /// When not <c>null</c>, cleared and filled with the ground points found along the way (world metres, at most
    /// <see cref="PathSpacing"/> apart, the first under <paramref name="from"/>), up to where the ground failed.
    /// </param>
    public float WalkableDistance(Vector3 from, Vector3 toward, List<Vector3>? ground = null)
    {
        ground?.Clear();
        if (!Limits.CanWalk)
        {
            return 0f;
        }

        List<Vector3> path = ground ?? [];
        Vector3 end = new(toward.X, from.Y, toward.Z);
        WalkFailure failure = TraceGround(from, end, path, out float passed, checkEnd: false);
        return failure == WalkFailure.None ? new Vector2(end.X - from.X, end.Z - from.Z).Length() : passed;
    }

    /// <summary>
    /// Finds the ground under the straight line from <paramref name="a"/> to <paramref name="b"/> (seen from above)
    /// and checks it; fills <paramref name="path"/> with ground points at most <see cref="PathSpacing"/> apart.
    /// <paramref name="passed"/> is the horizontal distance from <paramref name="a"/> of the last sample before the
    /// ground failed (of the first of two steep samples). With <paramref name="checkEnd"/>, the last sample's ground
    /// must be within a step of <paramref name="b"/>'s height.
    /// </summary>
    private WalkFailure TraceGround(Vector3 a, Vector3 b, List<Vector3> path, out float passed, bool checkEnd = true)
    {
        passed = 0f;
        var horizontal = new Vector2(b.X - a.X, b.Z - a.Z);
        float across = horizontal.Length();
        int samples = Math.Max(1, (int)MathF.Ceiling(across / SampleSpacing));
        int keepEvery = Math.Max(1, (int)MathF.Floor(PathSpacing / SampleSpacing));
        float spacing = across / samples;
        float slopeRise = spacing * Limits.MaxGrade;
        var heading = new Vector3(b.X - a.X, 0f, b.Z - a.Z);
        float allowed = _maxRise + slopeRise;

        // The first sample's ground must be under the first stance's contacts.
        float previous = a.Y;
        bool steepBefore = false;
        for (int i = 0; i <= samples; i++)
        {
            float t = i / (float)samples;
            var point = new Vector3(float.Lerp(a.X, b.X, t), 0f, float.Lerp(a.Z, b.Z, t));
            float top = previous + _legSpace;
            if (!_world.Raycast(new Vector3(point.X, top, point.Z), -Vector3.UnitY, _legSpace + allowed, out RayHit hit))
            {
                return WalkFailure.Gap;
            }

            float y = hit.Point.Y;
            if (y - previous > allowed)
            {
                return WalkFailure.StepTooHigh;
            }

            if (previous - y > allowed)
            {
                return WalkFailure.Gap;
            }

            bool steep = !_slope.Accepts(hit.Normal, heading);
            if (steep && steepBefore)
            {
                passed = MathF.Max(0f, (i - 2) * spacing);
                return WalkFailure.TooSteep;
            }

            steepBefore = steep;
            passed = i * spacing;
            previous = y;
            if (i % keepEvery == 0 || i == samples)
            {
                path.Add(new Vector3(point.X, y, point.Z));
            }
        }

        // The last sample's ground must be under the second stance's contacts.
        if (checkEnd && MathF.Abs(previous - b.Y) > allowed)
        {
            return previous < b.Y ? WalkFailure.StepTooHigh : WalkFailure.Gap;
        }

        if (path.Count == 1)
        {
            path.Add(path[0]);
        }

        return WalkFailure.None;
    }

    /// <summary>
    /// True when the trunk box carried along <paramref name="walk"/> (<see cref="Walk.PoseAt(float)"/>: turning in place at
    /// both ends, walking between) never touches the level: the check <see cref="Steer"/> makes, for walks joined
    /// from several (their trunk follows the joined path, not each part's).
    /// </summary>
    public bool TrunkIsFree(Walk walk)
    {
        float spacing = MathF.Min(_trunkHalfExtents.X, MathF.Min(_trunkHalfExtents.Y, _trunkHalfExtents.Z));
        float travel = walk.Length + walk.TurnTravel + ((walk.StartTurn + walk.EndTurn) * walk.TurnRate * _trunkHalfExtents.Length());
        int steps = Math.Max(1, (int)MathF.Ceiling(travel / spacing));
        for (int i = 0; i < steps; i++)
        {
            if (!IntervalIsFree(walk, walk.Duration * i / steps, walk.Duration * (i + 1) / steps, 0))
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>True when the trunk is clear from <paramref name="t0"/> to <paramref name="t1"/> seconds into the walk (conservative bounding boxes, bisected).</summary>
    private bool IntervalIsFree(Walk walk, float t0, float t1, int depth)
    {
        float mid = 0.5f * (t0 + t1);
        RootPose p0 = walk.PoseAt(t0);
        RootPose pm = walk.PoseAt(mid);
        RootPose p1 = walk.PoseAt(t1);

        // The most any trunk point moves from the middle pose to either end: the centre's travel plus the corners' turn.
        float turn0 = Rotations.AngleBetween(p0.Rotation, pm.Rotation);
        float turn1 = Rotations.AngleBetween(pm.Rotation, p1.Rotation);
        float corner = _trunkHalfExtents.Length();
        float growth = MathF.Max(Vector3.Distance(p0.Position, pm.Position) + (turn0 * corner), Vector3.Distance(pm.Position, p1.Position) + (turn1 * corner));
        if (!_world.Overlaps(new OrientedBox(pm.Position, _trunkHalfExtents + new Vector3(growth), pm.Rotation)))
        {
            return true;
        }

        if (growth <= _tolerance || depth >= 24)
        {
            return false;
        }

        return IntervalIsFree(walk, t0, mid, depth + 1) && IntervalIsFree(walk, mid, t1, depth + 1);
    }
}
