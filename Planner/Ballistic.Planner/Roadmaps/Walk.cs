using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Roadmaps;

/// <summary>
/// One walk of a planned path: the trunk moves along a path on the ground from one stance to the next while the legs
/// step. The ground path runs from the first stance's contact centre to the second's; the trunk keeps its stance
/// offset above the ground (blended from the first stance's to the second's) and faces the way it walks. In time:
/// the trunk first turns in place from the first stance's orientation to the walking heading (at
/// <see cref="TurnRate"/> on average, the character's <see cref="WalkingLimits.TurnRate"/>, in <see cref="MinTurnTime"/> at least), speeds up from rest to <see cref="Speed"/> over <see cref="RampTime"/>, walks,
/// slows down to rest over <see cref="RampTime"/> (a shorter walk never reaches full speed), and turns in place to
/// the second stance's orientation. On stepped ground (stairs, a kerb: rises steeper than the walker's
/// <see cref="MaxGrade"/>) it slows so that the trunk climbs or descends the steps no faster than
/// <see cref="ClimbShare"/> of the walking speed, as people slow on stairs, climbing from a quarter of a step cycle
/// before the first step (<see cref="ClimbLead"/>: the foot set down on it is the first step taken slowly). Immutable.
/// </summary>
public sealed record Walk : Move
{
    /// <summary>Least time (seconds) of a turn in place: even a small turn takes two steps' time, one for each group of feet.</summary>
    public const float MinTurnTime = 0.4f;

    /// <summary>Largest difference (radians, 0.06°) between a stance's heading and the walk's that is no turn in place: rounding, not a turn.</summary>
    private const float NoTurn = 1e-3f;

    /// <summary>Time (seconds) the trunk takes to speed up from rest to the walking speed, and to slow down to rest.</summary>
    public const float RampTime = 0.5f;

    /// <summary>
    /// Most the trunk climbs or descends steps along a walk, as a share of the walking speed (0.25: on stairs with
    /// 17 cm risers and 30 cm treads a 1.5 m/s walk goes at about 0.75 m/s along the path, and the gait's steps
    /// shorten by as much: a tread a step at the cadence of the level). The steps' rise is measured over
    /// <see cref="ClimbWindow"/> of path either way; slopes the walker walks (no steeper than <see cref="MaxGrade"/>) do not slow it.
    /// </summary>
    public const float ClimbShare = 0.25f;

    /// <summary>Path distance (metres) either way over which the steps' rise that slows a walk (<see cref="ClimbShare"/>) is measured: two treads and risers of a stair.</summary>
    public const float ClimbWindow = 0.5f;

    /// <summary>
    /// Time (seconds at the walking speed) before a flight of steps from which the walk already goes at the flight's
    /// pace (<see cref="ClimbShare"/>): about the time the trunk takes to follow its leading foot's half step (a
    /// quarter of a natural step cycle), so the step set down on the first tread is taken as slowly as it is
    /// shortened, like the steps up the flight, not at full speed.
    /// </summary>
    internal const float ClimbLead = 0.22f;

    private readonly Vector3[] _path;
    private RoadmapNode _from;
    private RoadmapNode _to;
    private readonly float[] _distances;

    /// <summary>The ground's rise per metre toward the walker's left at each path point (<see cref="CrossGrades"/>), or <c>null</c>: the trunk does not roll.</summary>
    private readonly float[]? _cross;

    /// <summary>Finds the segment under a distance in <see cref="_distances"/> (<see cref="PointAt(float)"/>).</summary>
    private readonly SortedLookup _lookup;

    private readonly Quaternion _startHeading;
    private readonly Quaternion _endHeading;

    /// <summary>The turns in place at the start (from <see cref="From"/>'s rotation to the start heading) and at the end, their angles worked out once.</summary>
    private readonly RotationBlend _startTurn;
    private readonly RotationBlend _endTurn;
    private readonly Vector3 _startUpright;
    private readonly Vector3 _endUpright;

    /// <summary>The trunk centre where the walk along the path starts and ends (<see cref="PoseAtDistance(float)"/> at 0 and <see cref="Length"/>), after and before the turns in place.</summary>
    private readonly Vector3 _startWalking;
    private readonly Vector3 _endWalking;
    private readonly float _acceleration;
    private readonly float _cruise;
    private readonly float _ramp;

    /// <summary>
    /// Path distances (metres, ascending, from 0 to <see cref="Length"/>) between which the pace is constant, where the
    /// walk slows somewhere (<see cref="ClimbShare"/>): the path points and, <see cref="ClimbLead"/> before each
    /// slower climbing stretch, where the trunk starts going at its pace; <c>null</c> where the walk never slows.
    /// </summary>
    private readonly float[]? _paceKeys;

    /// <summary>Per path segment (from its second point): the walk slows there for steps that climb (a flight up, not down); <c>null</c> where it never slows.</summary>
    private readonly bool[]? _climbing;

    /// <summary>Finds the stretch under a path distance in <see cref="_paceKeys"/>.</summary>
    private readonly SortedLookup? _paceLookup;

    /// <summary>
    /// Paced distance (metres walked at full speed in the same time) at each of <see cref="_paceKeys"/>, where the
    /// walk slows somewhere (<see cref="ClimbShare"/>); <c>null</c> where it never does (then it is the path distance).
    /// </summary>
    private readonly float[]? _paced;

    /// <summary>Finds the segment under a paced distance in <see cref="_paced"/>.</summary>
    private readonly SortedLookup? _pacedLookup;

    /// <summary>Length walked at full speed in the walk's time at speed (metres): <see cref="Length"/> unless it slows.</summary>
    private readonly float _pacedLength;

    /// <summary>Creates a walk.</summary>
    /// <param name="from">The stance walked from.</param>
    /// <param name="to">The stance walked to.</param>
    /// <param name="path">Points on the ground, world metres, in order: the first under <paramref name="from"/>'s contacts, the last under <paramref name="to"/>'s (at least two).</param>
    /// <param name="speed">Walking speed along the path, m/s (positive).</param>
    /// <param name="via">
    /// The stances the walk passes through without stopping, in order, when it joins several walks of a search
    /// (their ground points lie on <paramref name="path"/>); <c>null</c> or empty for a walk straight from one stance to the next.
    /// </param>
    /// <param name="turnRate">Average rate at which the trunk turns in place at either end, radians per second (positive).</param>
    /// <param name="maxGrade">
    /// The walker's steepest grade (rise per metre across, <see cref="WalkingLimits.MaxGrade"/>): a path segment
    /// steeper than that is a step (a stair's riser, a kerb), where the walk slows (<see cref="ClimbShare"/>). By
    /// default none: the walk never slows.
    /// </param>
    /// <param name="pitchSpan">
    /// Half the distance (metres) between the walker's foremost and hindmost feet, over which its trunk pitches with
    /// the ground (<see cref="WalkingLimits.PitchSpan"/>, <see cref="PitchSpan"/>); 0 (the default): the trunk walks level.
    /// </param>
    /// <param name="crossGrades">
    /// For a walker whose trunk rolls with the ground (<see cref="WalkingLimits.RollSpan"/>): the ground's rise per
    /// metre toward the walker's left (across the path, level) at each path point, one per point; walking, the
    /// trunk's left axis rises at it (<see cref="PoseAtDistance(float)"/>). <c>null</c> (the default): the trunk does not roll.
    /// </param>
    /// <exception cref="ArgumentException">Fewer than two points, a point not finite, a speed or turn rate not positive, a negative grade or pitch span, or cross grades not one finite value per point.</exception>
    public Walk(RoadmapNode from, RoadmapNode to, IReadOnlyList<Vector3> path, float speed, IReadOnlyList<RoadmapNode>? via = null, float turnRate = WalkingLimits.DefaultTurnRate, float maxGrade = float.PositiveInfinity, float pitchSpan = 0f, IReadOnlyList<float>? crossGrades = null)
        : this(from, to, path, speed, via, turnRate, maxGrade, pitchSpan, crossGrades, [], 1f)
    {
    }

    /// <summary>
    /// This walk slowed to <paramref name="pace"/> (0 to 1) of its speed over <paramref name="stretches"/> (metres
    /// along its path, from and to), as well as for any steps it slows for: the gait shortens its steps there by as
    /// much, at the cadence of the rest of the walk (<see cref="PaceAt"/>). Same stances, path, speed and limits; it
    /// takes longer.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException">A pace not above 0 or above 1.</exception>
    internal Walk Slowed(IReadOnlyList<(float From, float To)> stretches, float pace)
    {
        if (!(pace > 0f && pace <= 1f))
        {
            throw new ArgumentOutOfRangeException(nameof(pace), pace, "A walk slows to a pace above 0 and at most 1.");
        }

        return new(From, To, _path, Speed, Via, TurnRate, MaxGrade, PitchSpan, _cross, stretches, pace);
    }

    /// <summary>
    /// This walk between other records of its two stances: the same root poses (the path, timing and poses are
    /// unchanged), other contacts (the stances an animation stands on: <see cref="Animation.JumpAnimator"/>).
    /// </summary>
    /// <exception cref="ArgumentException">A stance at another root pose.</exception>
    internal Walk Between(RoadmapNode from, RoadmapNode to)
    {
        ArgumentNullException.ThrowIfNull(from);
        ArgumentNullException.ThrowIfNull(to);
        if (from.Pose != From.Pose || to.Pose != To.Pose)
        {
            throw new ArgumentException("A walk's stances are replaced only by stances at the same root poses.");
        }

        Walk copy = this with { };
        copy._from = from;
        copy._to = to;
        return copy;
    }

    private Walk(RoadmapNode from, RoadmapNode to, IReadOnlyList<Vector3> path, float speed, IReadOnlyList<RoadmapNode>? via, float turnRate, float maxGrade, float pitchSpan, IReadOnlyList<float>? crossGrades, IReadOnlyList<(float From, float To)> slowed, float slowPace)
    {
        ArgumentNullException.ThrowIfNull(from);
        ArgumentNullException.ThrowIfNull(to);
        ArgumentNullException.ThrowIfNull(path);
        if (path.Count < 2)
        {
            throw new ArgumentException($"A walk needs at least two path points, not {path.Count}.", nameof(path));
        }

        if (!(speed > 0f) || !float.IsFinite(speed))
        {
            throw new ArgumentException($"The walking speed must be positive, not {speed}.", nameof(speed));
        }

        if (!(turnRate > 0f) || !float.IsFinite(turnRate))
        {
            throw new ArgumentException($"The turn rate must be positive, not {turnRate}.", nameof(turnRate));
        }

        if (!(maxGrade >= 0f))
        {
            throw new ArgumentException($"The steepest grade must not be negative, not {maxGrade}.", nameof(maxGrade));
        }

        if (!(pitchSpan >= 0f) || !float.IsFinite(pitchSpan))
        {
            throw new ArgumentException($"The span over which the trunk pitches must be finite and not negative, not {pitchSpan}.", nameof(pitchSpan));
        }

        if (crossGrades is not null && (crossGrades.Count != path.Count || crossGrades.Any(g => !float.IsFinite(g))))
        {
            throw new ArgumentException($"A walk's cross grades must be one finite value per path point ({path.Count}), not {crossGrades.Count}{(crossGrades.Any(g => !float.IsFinite(g)) ? " with one not finite" : "")}.", nameof(crossGrades));
        }

        _cross = crossGrades is null ? null : [.. crossGrades];
        _path = [.. path];
        _distances = new float[_path.Length];
        for (int i = 0; i < _path.Length; i++)
        {
            Vector3 p = _path[i];
            if (!float.IsFinite(p.X) || !float.IsFinite(p.Y) || !float.IsFinite(p.Z))
            {
                throw new ArgumentException($"Walk path point {i} is not finite.", nameof(path));
            }

            _distances[i] = i == 0 ? 0f : _distances[i - 1] + Vector3.Distance(_path[i - 1], p);
        }

        _from = from;
        _to = to;
        Via = via is null ? [] : [.. via];
        Speed = speed;
        TurnRate = turnRate;
        MaxGrade = maxGrade;
        PitchSpan = pitchSpan;
        Length = _distances[^1];
        _lookup = new SortedLookup(_distances);
        float[]? stepped = Stepped();
        bool slowedSomewhere = slowPace < 1f && slowed.Any(s => s.To > 0f && s.From < Length && s.To > s.From);
        (_paceKeys, _paced, _climbing, SlowsForSteps) = stepped is not null || slowedSomewhere ? Paced(stepped, slowedSomewhere ? slowed : [], slowPace) : (null, null, null, false);
        _paceLookup = _paceKeys is null ? null : new SortedLookup(_paceKeys);
        _pacedLookup = _paced is null ? null : new SortedLookup(_paced);
        _pacedLength = _paced is null ? Length : _paced[^1];
        StartOffset = from.Pose.Position - _path[0];
        EndOffset = to.Pose.Position - _path[^1];
        _startHeading = Facing(HeadingAt(0f), GradeAt(0f), CrossGradeAt(0f));
        _endHeading = Facing(HeadingAt(Length), GradeAt(Length), CrossGradeAt(Length));
        _startTurn = RotationBlend.Between(from.Pose.Rotation, _startHeading);
        _endTurn = RotationBlend.Between(_endHeading, to.Pose.Rotation);
        StartTurn = TurnTime(Rotations.AngleBetween(from.Pose.Rotation, _startHeading));
        EndTurn = TurnTime(Rotations.AngleBetween(_endHeading, to.Pose.Rotation));
        _startUpright = StoodUp(StartOffset, from.Pose.Rotation);
        _endUpright = StoodUp(EndOffset, to.Pose.Rotation);
        _startWalking = PoseAtDistance(0f).Position;
        _endWalking = PoseAtDistance(Length).Position;

        // Constant acceleration Speed / RampTime up and down; a walk too short to reach the speed peaks halfway. In
        // paced distance: where the walk slows, the same time covers less of the path.
        _acceleration = speed / RampTime;
        _cruise = _pacedLength >= speed * RampTime ? speed : MathF.Sqrt(_acceleration * _pacedLength);
        _ramp = _cruise / _acceleration;
        WalkTime = _cruise >= speed ? (_pacedLength / speed) + RampTime : 2f * _ramp;
    }

    /// <summary>
    /// The stretches of constant pace and the paced distance at each stretch's start (<see cref="_paceKeys"/>,
    /// <see cref="_paced"/>): each path segment's pace is the most of 1 and <see cref="ClimbShare"/> over the steps'
    /// grade (their net rise or fall, from <paramref name="stepped"/>, over the whole 2 × <see cref="ClimbWindow"/>
    /// either way of its middle, also near either end: one step down off a crate as the walk starts is no flight of
    /// stairs; 1 without <paramref name="stepped"/>), and the walk already goes at a slower climbing segment's pace
    /// <see cref="ClimbLead"/> of its speed before it (going down, the gait's steps look ahead for it:
    /// <see cref="ClimbsAt"/>); times <paramref name="slowPace"/> within any of the <paramref name="slowed"/>
    /// stretches (metres along the path: <see cref="Slowed"/>). Each stretch counted 1 / pace times; whether each
    /// segment climbs; whether the steps slow the walk anywhere; <c>(null, null, null, false)</c> when every pace is 1.
    /// </summary>
    private (float[]? Keys, float[]? Paced, bool[]? Climbing, bool Stairs) Paced(float[]? stepped, IReadOnlyList<(float From, float To)> slowed, float slowPace)
    {
        var paces = new float[_distances.Length];
        var climbing = new bool[_distances.Length];
        bool slows = false;
        for (int i = 1; i < _distances.Length; i++)
        {
            if (stepped is null)
            {
                paces[i] = 1f;
                continue;
            }

            float middle = 0.5f * (_distances[i - 1] + _distances[i]);
            float rise = Along(_lookup, _distances, stepped, MathF.Min(Length, middle + ClimbWindow)) - Along(_lookup, _distances, stepped, MathF.Max(0f, middle - ClimbWindow));
            float grade = MathF.Abs(rise) / (2f * ClimbWindow);
            paces[i] = grade > ClimbShare ? ClimbShare / grade : 1f;
            climbing[i] = paces[i] < 1f && rise > 0f;
            slows |= paces[i] < 1f;
        }

        if (!slows && slowed.Count == 0)
        {
            return (null, null, null, false);
        }

        // The stretches: the path points, the lead ahead of each climbing segment slower than the one before it, and
        // the ends of the stretches slowed for the gait.
        float lead = Speed * ClimbLead;
        var keys = new List<float>(_distances);
        foreach ((float from, float to) in slowed)
        {
            keys.Add(Math.Clamp(from, 0f, Length));
            keys.Add(Math.Clamp(to, 0f, Length));
        }

        for (int i = 2; i < _distances.Length; i++)
        {
            if (climbing[i] && paces[i] < paces[i - 1] && _distances[i - 1] - lead > 0f)
            {
                keys.Add(_distances[i - 1] - lead);
            }
        }

        keys.Sort();
        float[] k = [.. keys.Distinct()];
        var paced = new float[k.Length];
        int first = 1;
        for (int s = 1; s < k.Length; s++)
        {
            // The slowest segment the stretch overlaps or comes within the lead of.
            while (first < _distances.Length - 1 && _distances[first] <= k[s - 1])
            {
                first++;
            }

            float pace = 1f;
            for (int i = first; i < _distances.Length && _distances[i - 1] < k[s] + lead; i++)
            {
                pace = _distances[i - 1] < k[s] || climbing[i] ? MathF.Min(pace, paces[i]) : pace;
            }

            foreach ((float from, float to) in slowed)
            {
                if (k[s - 1] < to && k[s] > from)
                {
                    pace *= slowPace;
                    break;
                }
            }

            paced[s] = paced[s - 1] + ((k[s] - k[s - 1]) / pace);
        }

        return (k, paced, climbing, slows);
    }

    /// <summary>
    /// <paramref name="values"/> (one per path point) interpolated at <paramref name="at"/> on the ascending
    /// <paramref name="keys"/> (one per path point, indexed by <paramref name="lookup"/>), clamped to the ends: from
    /// path distance to paced distance or the steps' rise, and back.
    /// </summary>
    private static float Along(SortedLookup lookup, float[] keys, float[] values, float at)
    {
        int i = lookup.FirstAtOrAbove(at);
        if (i == 0 || keys[i] == at)
        {
            return values[i];
        }

        float span = keys[i] - keys[i - 1];
        return span > 0f ? float.Lerp(values[i - 1], values[i], Math.Clamp((at - keys[i - 1]) / span, 0f, 1f)) : values[i];
    }

    /// <summary>
    /// The steps' rise (metres, up positive, down negative: segments steeper than <see cref="MaxGrade"/>) summed up to
    /// each path point; <c>null</c> where the path has no step. A flight of stairs adds up, a crate stepped onto and
    /// off nets nothing.
    /// </summary>
    private float[]? Stepped()
    {
        if (!float.IsFinite(MaxGrade))
        {
            return null;
        }

        var stepped = new float[_path.Length];
        bool any = false;
        for (int i = 1; i < _path.Length; i++)
        {
            Vector3 d = _path[i] - _path[i - 1];
            float rise = MathF.Abs(d.Y);
            stepped[i] = stepped[i - 1] + (rise > (MaxGrade * Horizontal(d).Length()) + 1e-3f ? d.Y : 0f);
            any |= stepped[i] != stepped[i - 1];
        }

        return any ? stepped : null;
    }

    /// <summary>The distance along the path (metres) at paced distance <paramref name="paced"/> (clamped).</summary>
    private float FromPaced(float paced) => _paced is null ? paced : Along(_pacedLookup!, _paced, _paceKeys!, paced);

    /// <summary>The paced distance (metres) at <paramref name="distance"/> metres along the path (clamped).</summary>
    private float ToPaced(float distance) => _paced is null ? distance : Along(_paceLookup!, _paceKeys!, _paced, distance);


    /// <inheritdoc />
    public override RoadmapNode From => _from;

    /// <inheritdoc />
    public override RoadmapNode To => _to;

    /// <summary>The stances passed through without stopping, in order (empty for a walk from one stance straight to the next).</summary>
    public IReadOnlyList<RoadmapNode> Via { get; }

    /// <summary>The node pairs (from id, to id) of the walks this one joins: (From, To) alone, or through each of <see cref="Via"/>.</summary>
    public IEnumerable<(int From, int To)> Segments
    {
        get
        {
            RoadmapNode previous = From;
            foreach (RoadmapNode node in Via)
            {
                yield return (previous.Id, node.Id);
                previous = node;
            }

            yield return (previous.Id, To.Id);
        }
    }

    /// <summary>Points on the ground the walk follows, world metres, in order.</summary>
    public IReadOnlyList<Vector3> Path => _path;

    /// <summary>Walking speed along the path, m/s.</summary>
    public float Speed { get; }

    /// <summary>Average rate at which the trunk turns in place at either end, radians per second (<see cref="WalkingLimits.TurnRate"/>).</summary>
    public float TurnRate { get; }

    /// <summary>The walker's steepest grade (rise per metre across): steeper path segments are steps, where the walk slows (<see cref="ClimbShare"/>); infinite where it never does.</summary>
    public float MaxGrade { get; }

    /// <summary>
    /// Half the distance (metres) between the walker's foremost and hindmost feet, over which its trunk pitches with
    /// the ground (<see cref="WalkingLimits.PitchSpan"/>): walking, the trunk's forward axis rises at the ground's
    /// grade between the path points this far ahead and behind (<see cref="PoseAtDistance(float)"/>). 0: it walks level.
    /// </summary>
    public float PitchSpan { get; }

    /// <summary>
    /// The ground's rise per metre toward the walker's left at each path point, for a walker whose trunk rolls with
    /// the ground (<see cref="WalkingLimits.RollSpan"/>); empty for one whose trunk does not roll.
    /// </summary>
    internal IReadOnlyList<float> CrossGrades => _cross ?? [];

    /// <summary>Length of the ground path, metres (3D, along the polyline).</summary>
    public float Length { get; }

    /// <summary>Seconds: <see cref="StartTurn"/>, then <see cref="WalkTime"/>, then <see cref="EndTurn"/>.</summary>
    public override float Duration => StartTurn + WalkTime + EndTurn;

    /// <summary>Seconds the trunk turns in place at the start, from the first stance's orientation to the walking heading.</summary>
    public float StartTurn { get; }

    /// <summary>Seconds the trunk moves along the path, speeding up and slowing down included (length over speed plus <see cref="RampTime"/> for a walk that reaches full speed, longer where it slows on steep ground: <see cref="ClimbShare"/>).</summary>
    public float WalkTime { get; }

    /// <summary>Seconds the trunk turns in place at the end, from the walking heading to the second stance's orientation.</summary>
    public float EndTurn { get; }

    /// <summary>The trunk centre's offset from the path's first point at the start (the first stance's), world metres.</summary>
    public Vector3 StartOffset { get; }

    /// <summary>The trunk centre's offset from the path's last point at the end (the second stance's), world metres.</summary>
    public Vector3 EndOffset { get; }

    /// <summary>
    /// The horizontal distance (metres) the trunk centre moves while it turns in place at either end, summed: a stance
    /// whose trunk leans with a slope stands up over its contacts as it turns to walk (<see cref="PoseAt(float)"/>).
    /// </summary>
    internal float TurnTravel => Horizontal(StartOffset - _startUpright).Length() + Horizontal(EndOffset - _endUpright).Length();

    /// <summary>Distance walked along the path at <paramref name="time"/> seconds after the walk starts (clamped to the walk), metres.</summary>
    public float DistanceAt(float time)
    {
        float t = time - StartTurn;
        if (!(t > 0f))
        {
            return 0f;
        }

        if (t >= WalkTime)
        {
            return Length;
        }

        float left = WalkTime - t;
        float d = t <= _ramp ? 0.5f * _acceleration * t * t
            : left <= _ramp ? _pacedLength - (0.5f * _acceleration * left * left)
            : (0.5f * _cruise * _ramp) + (_cruise * (t - _ramp));
        return FromPaced(Math.Clamp(d, 0f, _pacedLength));
    }

    /// <summary>The time (seconds after the walk starts) at which the trunk has walked <paramref name="distance"/> metres along the path (clamped): the inverse of <see cref="DistanceAt"/>, 0 for no distance.</summary>
    public float TimeAtDistance(float distance)
    {
        if (!(distance > 0f))
        {
            return 0f;
        }

        if (distance >= Length)
        {
            return StartTurn + WalkTime;
        }

        distance = ToPaced(distance);
        float rampDistance = 0.5f * _acceleration * _ramp * _ramp;
        float t = distance <= rampDistance ? MathF.Sqrt(2f * distance / _acceleration)
            : distance >= _pacedLength - rampDistance ? WalkTime - MathF.Sqrt(2f * (_pacedLength - distance) / _acceleration)
            : _ramp + ((distance - rampDistance) / _cruise);
        return StartTurn + Math.Clamp(t, 0f, WalkTime);
    }

    /// <summary>The trunk's speed along the path at <paramref name="time"/> seconds after the walk starts, m/s: 0 while it turns in place, at most <see cref="Speed"/>.</summary>
    public float SpeedAt(float time)
    {
        // Paced distance per second, times path per paced distance where the trunk is.
        float speed = RampSpeed(time);
        return _paced is null || !(speed > 0f) ? speed : speed * PaceAt(DistanceAt(time));
    }

    /// <summary>Paced distance per second at <paramref name="time"/> seconds after the walk starts (m/s): 0 while it turns in place, up to <see cref="Speed"/> as it speeds up and slows down.</summary>
    private float RampSpeed(float time)
    {
        float t = time - StartTurn;
        return !(t > 0f) || t >= WalkTime ? 0f : MathF.Min(_cruise, _acceleration * MathF.Min(t, WalkTime - t));
    }

    /// <summary>
    /// How far the walk has sped up from rest, or slowed toward it, at <paramref name="time"/> seconds after it
    /// starts: its speed over the walking speed at its pace there, 0 to 1 (0 while it turns in place), whatever
    /// slowing on stairs (<see cref="PaceAt"/>) does to its speed.
    /// </summary>
    internal float CruiseAt(float time) => RampSpeed(time) / Speed;

    /// <summary>
    /// The walk's pace at <paramref name="distance"/> metres along the path: its speed there over the speed it
    /// would have on level ground, 0 to 1 (1 but where steep ground slows it: <see cref="ClimbShare"/>). The gait
    /// shortens its steps by as much, so that its cadence stays that of the level.
    /// </summary>
    internal float PaceAt(float distance)
    {
        if (_paced is null)
        {
            return 1f;
        }

        int i = Math.Max(1, _paceLookup!.FirstAtOrAbove(distance));
        float paced = _paced[i] - _paced[i - 1];
        // At most 1: a stretch at full pace divides two sums of the same lengths, which rounding leaves 1e-5 apart
        // (the walk would go faster than its speed there).
        return paced > 0f ? MathF.Min(1f, (_paceKeys![i] - _paceKeys[i - 1]) / paced) : 1f;
    }

    /// <summary>True when the walk slows somewhere for steps (a flight of stairs, <see cref="ClimbShare"/>).</summary>
    internal bool SlowsForSteps { get; }

    /// <summary>
    /// True where the walk at <paramref name="distance"/> metres along the path goes at the pace of steps that climb
    /// (up a flight), on them or within <see cref="ClimbLead"/> of its speed before them (<see cref="PaceAt"/>).
    /// </summary>
    internal bool ClimbsAt(float distance)
    {
        if (_climbing is null)
        {
            return false;
        }

        float to = distance + (Speed * ClimbLead);
        for (int i = Math.Max(1, _lookup.FirstAtOrAbove(Math.Clamp(distance, 0f, Length))); i < _distances.Length && _distances[i - 1] < to; i++)
        {
            if (_climbing[i])
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>The ground point at <paramref name="distance"/> metres along the path (clamped), world metres.</summary>
    public Vector3 PointAt(float distance)
    {
        int segment = -1;
        return PointAt(distance, ref segment);
    }

    /// <summary>
    /// <see cref="PointAt(float)"/> found from <paramref name="segment"/>, the path index returned for a nearby
    /// distance (the same point whatever it is); set to this distance's.
    /// </summary>
    internal Vector3 PointAt(float distance, ref int segment)
    {
        distance = Math.Clamp(distance, 0f, Length);
        int i = _lookup.FirstAtOrAbove(distance, ref segment);
        if (_distances[i] == distance)
        {
            return _path[i];
        }

        float span = _distances[i] - _distances[i - 1];
        return span > 0f ? Vector3.Lerp(_path[i - 1], _path[i], (distance - _distances[i - 1]) / span) : _path[i];
    }

    /// <summary>
    /// The horizontal unit direction of travel at <paramref name="distance"/> metres along the path, smoothed over
    /// 0.25 m either way; the first stance's facing when the path has no horizontal extent.
    /// </summary>
    public Vector3 HeadingAt(float distance)
    {
        int segment = -1;
        return HeadingAt(distance, segment);
    }

    /// <summary><see cref="HeadingAt(float)"/> with its points found from <paramref name="segment"/> (the path index near <paramref name="distance"/>).</summary>
    private Vector3 HeadingAt(float distance, int segment)
    {
        const float window = 0.25f;
        int ahead = segment;
        Vector3 d = PointAt(distance + window, ref ahead) - PointAt(distance - window, ref segment);
        d.Y = 0f;
        if (d.LengthSquared() < 1e-8f)
        {
            d = PointAt(Length) - PointAt(0f);
            d.Y = 0f;
        }

        if (d.LengthSquared() < 1e-8f)
        {
            d = From.Pose.Forward;
            d.Y = 0f;
        }

        return d.LengthSquared() < 1e-8f ? Vector3.UnitZ : Vector3.Normalize(d);
    }

    /// <summary>
    /// The trunk's walking pose <paramref name="distance"/> metres along the path (clamped): the ground point plus the
    /// upright trunk's offset (blended smoothly from the start's to the end's), facing <see cref="HeadingAt(float)"/> upright;
    /// for a walker whose trunk pitches with the ground (<see cref="PitchSpan"/>), facing it pitched up or down at the
    /// ground's grade over the span, its centre raised by that grade times its offset ahead of the ground point, so
    /// that its front and hind hips stand as high above the ground under them as on the level.
    /// The upright offset of a stance is its own offset turned as the stance's trunk stands up (the shortest rotation
    /// bringing its up axis to the world's), at the stance's height above the ground point: a trunk leaning with a
    /// slope stands over its contacts to walk, not beside them. It is the stance's offset itself when the trunk does
    /// not lean, so the position is exactly <see cref="From"/>'s at 0 and <see cref="To"/>'s at the end of a walk
    /// between such stances. Turns in place are in <see cref="PoseAt(float)"/>.
    /// </summary>
    public RootPose PoseAtDistance(float distance)
    {
        int segment = -1;
        return PoseAtDistance(distance, ref segment);
    }

    /// <summary><see cref="PoseAtDistance(float)"/> with its points found from <paramref name="segment"/>, the path index near <paramref name="distance"/>; set to this distance's.</summary>
    private RootPose PoseAtDistance(float distance, ref int segment)
    {
        distance = Math.Clamp(distance, 0f, Length);
        float u = Length > 0f ? distance / Length : 1f;
        Vector3 offset = Vector3.Lerp(_startUpright, _endUpright, Smooth(u));
        Vector3 position = PointAt(distance, ref segment) + offset;
        if (PitchSpan > 0f || _cross is not null)
        {
            Vector3 heading = HeadingAt(distance, segment);
            float grade = GradeAt(distance);
            float cross = CrossGradeAt(distance, segment);
            Quaternion facing = distance <= 0f ? _startHeading : distance >= Length ? _endHeading : Facing(heading, grade, cross);
            Vector3 flat = Horizontal(offset);
            float rise = (grade * Vector3.Dot(flat, heading)) + (cross * Vector3.Dot(flat, LeftOf(heading)));
            return new RootPose(position + new Vector3(0f, rise, 0f), facing);
        }

        Quaternion rotation = distance <= 0f ? _startHeading : distance >= Length ? _endHeading : Upright(HeadingAt(distance, segment));
        return new RootPose(position, rotation);
    }

    /// <summary>
    /// The trunk's pose <paramref name="time"/> seconds after the walk starts (clamped to the walk): turning in place
    /// during <see cref="StartTurn"/> from <see cref="From"/>'s pose to <see cref="PoseAtDistance(float)"/> at 0 (standing
    /// up over the contacts as it turns), then <see cref="PoseAtDistance(float)"/> at <see cref="DistanceAt"/>, then turning
    /// in place to <see cref="To"/>'s pose. Exactly <see cref="From"/>'s pose at 0 and <see cref="To"/>'s at
    /// <see cref="Duration"/>.
    /// </summary>
    public RootPose PoseAt(float time)
    {
        int segment = -1;
        return PoseAt(time, ref segment);
    }

    /// <summary>
    /// <see cref="PoseAt(float)"/> with its points found from <paramref name="segment"/>, the path index returned for
    /// a moment before (an agent's last tick): the same pose to the bit whatever it is; set to this moment's.
    /// </summary>
    internal RootPose PoseAt(float time, ref int segment)
    {
        if (!(time > 0f))
        {
            return From.Pose;
        }

        if (time >= Duration)
        {
            return To.Pose;
        }

        if (time < StartTurn)
        {
            float s = Smooth(time / StartTurn);
            return new RootPose(Vector3.Lerp(From.Pose.Position, _startWalking, s), Quaternion.Normalize(_startTurn.At(From.Pose.Rotation, _startHeading, s)));
        }

        float end = StartTurn + WalkTime;
        if (time > end && EndTurn > 0f)
        {
            float s = Smooth((time - end) / EndTurn);
            return new RootPose(Vector3.Lerp(_endWalking, To.Pose.Position, s), Quaternion.Normalize(_endTurn.At(_endHeading, To.Pose.Rotation, s)));
        }

        return PoseAtDistance(DistanceAt(time), ref segment);
    }

    /// <summary>
    /// The offset <paramref name="offset"/> (world metres) of a trunk turned <paramref name="rotation"/> from the
    /// ground point under its contacts, once the trunk stands up: turned by the shortest rotation that brings the
    /// trunk's up axis to the world's, at the same height. The offset itself for a trunk that does not lean.
    /// </summary>
    private static Vector3 StoodUp(Vector3 offset, Quaternion rotation)
    {
        Vector3 v = Vector3.Transform(offset, Quaternion.Conjugate(Rotations.AlignUp(Vector3.Transform(Vector3.UnitY, rotation))));
        return new Vector3(v.X, offset.Y, v.Z);
    }

    private static Vector3 Horizontal(Vector3 v) => new(v.X, 0f, v.Z);

    /// <summary>
    /// The ground's grade (rise per horizontal metre) along the path at <paramref name="distance"/>, between its points
    /// <see cref="PitchSpan"/> ahead and behind (each within the path): the trunk's forward axis rises at it
    /// (<see cref="PoseAtDistance(float)"/>). 0 without a span: the trunk walks level.
    /// </summary>
    internal float GradeAt(float distance)
    {
        if (!(PitchSpan > 0f))
        {
            return 0f;
        }

        Vector3 ahead = PointAt(MathF.Min(Length, distance + PitchSpan));
        Vector3 behind = PointAt(MathF.Max(0f, distance - PitchSpan));
        float run = Horizontal(ahead - behind).Length();
        return run > 1e-3f ? (ahead.Y - behind.Y) / run : 0f;
    }

    /// <summary>
    /// The ground's rise per metre toward the walker's left at <paramref name="distance"/> along the path, between
    /// the path points' <see cref="CrossGrades"/>: the trunk's left axis rises at it (<see cref="PoseAtDistance(float)"/>).
    /// 0 for a walker whose trunk does not roll.
    /// </summary>
    internal float CrossGradeAt(float distance) => CrossGradeAt(distance, -1);

    /// <summary><see cref="CrossGradeAt(float)"/> with its path points found from <paramref name="segment"/>, the path index near <paramref name="distance"/> (the same grade whatever it is).</summary>
    private float CrossGradeAt(float distance, int segment)
    {
        if (_cross is null)
        {
            return 0f;
        }

        distance = Math.Clamp(distance, 0f, Length);
        int i = _lookup.FirstAtOrAbove(distance, ref segment);
        if (i == 0 || _distances[i] == distance)
        {
            return _cross[i];
        }

        float span = _distances[i] - _distances[i - 1];
        return span > 0f ? float.Lerp(_cross[i - 1], _cross[i], Math.Clamp((distance - _distances[i - 1]) / span, 0f, 1f)) : _cross[i];
    }

    /// <summary>
    /// The trunk's rotation facing the horizontal direction <paramref name="heading"/>, its forward axis pitched up
    /// at <paramref name="grade"/> (rise per metre; down where negative) and its left axis rolled up at
    /// <paramref name="cross"/> (rise per metre toward its left): <see cref="Upright"/> on the level.
    /// </summary>
    private static Quaternion Facing(Vector3 heading, float grade, float cross)
    {
        Quaternion rotation = Upright(heading);
        if (grade != 0f)
        {
            rotation *= Quaternion.CreateFromAxisAngle(Vector3.UnitX, -MathF.Atan(grade));
        }

        return cross != 0f ? rotation * Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.Atan(cross)) : rotation;
    }

    /// <summary>The walker's left (level, unit) when it faces the horizontal direction <paramref name="heading"/>: the trunk's +X turned as <see cref="Upright"/> turns it.</summary>
    private static Vector3 LeftOf(Vector3 heading) => new(heading.Z, 0f, -heading.X);

    /// <summary>Upright rotation facing the horizontal direction <paramref name="heading"/>.</summary>
    private static Quaternion Upright(Vector3 heading) => Quaternion.CreateFromAxisAngle(Vector3.UnitY, MathF.Atan2(heading.X, heading.Z));

    /// <summary>Seconds to turn in place by <paramref name="angle"/> radians: at <see cref="TurnRate"/>, at least <see cref="MinTurnTime"/> (none for no turn: <see cref="NoTurn"/> or less).</summary>
    private float TurnTime(float angle) => angle > NoTurn ? MathF.Max(angle / TurnRate, MinTurnTime) : 0f;

    private static float Smooth(float x) => Easing.Smooth(x);
}
