using System.Diagnostics;
using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Walking;

namespace Ballistic.Planner.Animation;

/// <summary>
/// The procedural gait of one walk (issue 11). The root follows <see cref="Walk.PoseAt(float)"/> (turning in place,
/// speeding up, walking, slowing down, turning in place), raised while walking by an upright walk's lift (issue 21:
/// see <see cref="Animate"/>); the feet (<see cref="LimbKind.Foot"/> limbs) form two
/// groups that alternate, split by side and rank front to back (a biped's left and right, a quadruped's diagonal
/// pairs: a trot, a hexapod's tripods). The walk is cut into half-cycles in time; in each one group swings while the
/// other holds, both holding for <see cref="Overlap"/> of the half-cycle at each of its ends. The trunk's motion is
/// costed in steps (<see cref="StepShare"/> of the leg, shortened to <see cref="ReachMargin"/> of what the legs reach
/// by IK with the sole flat), a turn adding what it moves the farthest foot under the trunk (never more than a step
/// per <see cref="MaxTurn"/>), no half-cycle turning more than <see cref="MaxTurn"/> in place, <see cref="MaxWalkingTurn"/> at full speed (less for a rig whose feet stand
/// far ahead of or behind its trunk: <see cref="TurnDrift"/>); a half-cycle covers at most one step and lasts at least
/// <see cref="MinHalfCycle"/>, so no swing is shorter than <see cref="MinSwing"/>. The first lasts as long as the
/// feet left on the start contacts can hold them (probed by IK), the last starts once the feet can hold the end
/// contacts. A foothold is the foot's stance offset (from the start and end contact poses, centred in the range its
/// leg reaches, blended) at the trunk pose midway (in cost) through the time it is held, dropped onto the ground by
/// a ray, and moved toward the walk's centre line when the ground there is missing, off the path's height by more
/// than a step, or the leg cannot hold it. The feet start on the contacts the walk starts from and the last two
/// half-cycles plant them on the contacts it ends on. Held feet are kept on their footholds by IK at every fine step
/// with the sole flat on the ground; a swinging foot follows a lifted curve (a cubic Bézier leaving one foothold and
/// reaching the next along the ground's normal), raised when a bone would touch the level. Other limbs (hands) let
/// go during the first half-cycle, hang, and take the end's contacts during the last. Whatever cannot be done (no
/// foothold, a foot that cannot hold or follow its swing, a step faster than <see cref="JumpAnimator.MinAirTime"/>,
/// a bone in the level) is reported: a walk is never animated with a foot sliding or jumping to its next foothold.
/// </summary>
internal sealed class WalkGait
{
    /// <summary>Share of each half-cycle at each of its ends during which both groups of feet hold.</summary>
    public const float Overlap = 0.1f;

    /// <summary>The distance the trunk walks in one full half-cycle (a step), as a share of the leg length, at most.</summary>
    public const float StepShare = 0.7f;

    /// <summary>Share of the range a held foot's leg reaches (along the trunk's forward axis) that a step may use.</summary>
    public const float ReachMargin = 0.7f;

    /// <summary>
    /// Height of the hips above the held feet (in rest leg lengths) an upright walk rises to at full speed: a walker's
    /// stance knee is nearly straight at mid-stance, the hip joints at 0.93–0.98 L.
    /// </summary>
    public const float UprightHips = 0.96f;

    /// <summary>
    /// Share of the rest leg the hips cruise at, over the held feet, before the bob lifts them over each foot: the
    /// height at which an upright walk's step is measured, the feet ahead and behind the hips, legs nearly straight.
    /// </summary>
    public const float CruiseHips = 0.88f;

    /// <summary>
    /// Share of the rest leg the hips stand at above the ground a two-footed walk crosses between its stances, before
    /// the bob lifts them over each foot: a little over <see cref="CruiseHips"/>, so that over whole steps, the dips
    /// as the feet change over included, the hips stand at least that high.
    /// </summary>
    public const float GroundHips = 0.89f;

    /// <summary>
    /// Share of the leg the hips of a rig with more than two feet keep at the ends of every foot's range: some foot is
    /// always near the end of its range, so the steps are no longer than the legs reach holding the hips this high.
    /// </summary>
    public const float ManyFeetHips = 0.92f;

    /// <summary>Least share of the step <see cref="ManyFeetHips"/> leaves for it to apply.</summary>
    private const float ManyFeetShare = 0.75f;

    /// <summary>Grade (rise over run) up to which the ground counts as level for cruising: the steps' length (tan 5°).</summary>
    private const float LevelGrade = 0.0875f;

    /// <summary>Grade from which the steps are those of the stances' height (tan 12°).</summary>
    private const float SteepGrade = 0.2126f;

    /// <summary>
    /// Grade up to which the hips cruise at their full lift (tan 7°): wider than the steps' <see cref="LevelGrade"/>, so
    /// the hips stay up over the gentle rolls of a dune field (the desert demo's last walk cruised 0.868 L on ground of
    /// 5-7°, the steps there at their level length). Where that keeps a foot from reaching its foothold, the walk
    /// slows there and its steps shorten (<see cref="Run"/>), at the same cadence.
    /// </summary>
    private const float HipsLevelGrade = 0.1228f;

    /// <summary>Grade from which the hips do not cruise at all (tan 13°).</summary>
    private const float HipsSteepGrade = 0.2309f;

    /// <summary>Distance (metres) along the path either way over which the ground's grade is measured.</summary>
    private const float LevelWindow = 0.5f;

    /// <summary>
    /// Distance (metres) along the path either way over which the level share that lengthens the steps is averaged:
    /// half the hips' (<see cref="LevelWindow"/>), so the steps shorten for a dune face or a stair within about half
    /// a metre of it, not a metre (measured: the desert skeleton's hips then stand at least 0.88 L on the level sand
    /// before a dune face, where they stood 0.879 L; its cadence there is unchanged).
    /// </summary>
    public const float StepAveraging = 0.5f * LevelWindow;

    /// <summary>Samples either side over which the cruise's level share is averaged (<see cref="LevelWindow"/> of travel, <see cref="StepAveraging"/> for the step).</summary>
    private const int LevelSamples = 4;

    /// <summary>Share of a leg's full length (hip to ankle along its bones) the hips rise to at most over a held foot: the knee stays a little bent.</summary>
    public const float KneeMargin = 0.99f;

    /// <summary>Share of the range a held foot's leg reaches that an upright walk's step may use (the hips dip between steps to let it).</summary>
    public const float UprightReachMargin = 0.95f;

    /// <summary>Amplitude of the arms' swing about the shoulders in an upright walk at full speed, radians (20°), opposite the legs.</summary>
    public const float ArmSwing = MathF.PI / 9f;

    /// <summary>Time (seconds) over which a hand drops from its hanging pose to beside the thigh as an upright walk starts, and back as it ends.</summary>
    private const float ArmDrop = 0.4f;

    /// <summary>Share of a swing at each end during which the lift keeps the swinging foot within reach of the foothold it leaves or reaches.</summary>
    private const float SwingNearFoothold = 0.1f;

    /// <summary>Heel rises tried when the hips' lift allows for a trailing foot rolling onto its ball (even steps up to <see cref="SoleHold.MostRoll"/>).</summary>
    private const int RollTries = 6;

    /// <summary>Most the hips rise above their lowest within a step either way in an upright walk, in rest leg lengths: a walker's pelvis bobs about 0.05 L.</summary>
    public const float MostBob = 0.06f;

    /// <summary>Least the hips dip (in rest leg lengths) as the feet change over, below their height mid-step: the bob of a walker who does not glide.</summary>
    public const float LeastBob = 0.05f;

    /// <summary>
    /// Time (seconds) over which the hips' lift is smoothed: no abrupt rise or fall. Shortened in proportion where short
    /// legs shorten the half-cycle (<see cref="FullSizeLeg"/>): smoothed over 0.03 s, a rat's 0.04 s half-cycles lost
    /// their bob.
    /// </summary>
    private const float LiftSmoothing = 0.03f;

    /// <summary>
    /// Least share of a half-cycle over which the hips' lift rises or falls by <see cref="MostBob"/>: a walker's hips
    /// rise and fall with its steps (about 0.3 m/s at most for a person: a 5 cm bob at two steps a second), never
    /// faster.
    /// </summary>
    private const float LiftRise = 0.25f;

    /// <summary>Half a sole's length, as a share of the rest leg (0.15: a 27 cm foot for a 0.9 m leg), fitted wholly on a stair's tread (<see cref="Run"/>).</summary>
    private const float HalfSole = 0.15f;

    /// <summary>Half a sole's width, as a share of <see cref="HalfSole"/> (0.35: 9.5 cm wide for a 27 cm foot), fitted wholly on a stair's tread where the foot is set down turned along it (<see cref="Run"/>).</summary>
    private const float HalfSoleWidth = 0.35f;

    /// <summary>Most the trunk turns during one half-cycle in place, radians (20°): half-cycles are shortened where the walk turns.</summary>
    public const float MaxTurn = MathF.PI / 9f;

    /// <summary>
    /// Most the trunk turns during one half-cycle at full walking speed, radians (40°; between the two, in proportion
    /// to the speed): a walker rounding a bend sets each swinging foot down turned on its way, at the cadence of the
    /// straight (the user's human rig, bending 22° through a doorway over half a metre, stepped 3.4 times a second
    /// there, at a 20° limit).
    /// </summary>
    public const float MaxWalkingTurn = 2f * MaxTurn;

    /// <summary>Share of the upright step taken near where a first run met trouble (<see cref="Animate"/>).</summary>
    private const float ShortStep = 0.85f;

    /// <summary>Least share of the upright step that repeated shortening at the same troubles goes down to.</summary>
    private const float LeastShortStep = 0.45f;

    /// <summary>Most times an upright walk that met trouble is walked again with its steps shortened there (<see cref="Animate"/>).</summary>
    private const int ShortenRounds = 4;

    /// <summary>Steps either side of a trouble over which the upright step is shortened (after <see cref="NarrowSpan"/> did not clear the walk).</summary>
    private const float ShortSpan = 1f;

    /// <summary>
    /// Steps either side of a trouble over which the upright step is shortened first: a stair or a dune face ahead
    /// shortens only the level steps just before it, not a window of them, and a biped's cadence on the level stays
    /// natural. Kept only where it clears the walk; else the walk is shortened over <see cref="ShortSpan"/>.
    /// </summary>
    private const float NarrowSpan = 0.5f;

    /// <summary>Least duration of a swing, seconds: a foot never steps to a new foothold faster (a contact that moves within a tenth of a second reads as a slide).</summary>
    public const float MinSwing = 0.16f;

    /// <summary>Least duration of a half-cycle, seconds: its swing lasts at least <see cref="MinSwing"/>.</summary>
    public const float MinHalfCycle = MinSwing / (1f - (2f * Overlap));

    /// <summary>
    /// Leg length (metres) at and above which <see cref="MinHalfCycle"/> holds whatever the speed. A shorter leg whose
    /// walk would carry the feet farther in <see cref="MinHalfCycle"/> than they reach steps faster, down to
    /// <see cref="MinHalfCycle"/> × √(leg ÷ this): walks at equal Froude numbers last in proportion to √(leg ÷ g),
    /// so a 4.5 cm rat's half-cycle may be as short as 0.04 s (walking its 0.33 m/s, each of its feet steps about 9
    /// times a second, 3.8 cm each time).
    /// </summary>
    public const float FullSizeLeg = 1f;

    /// <summary>
    /// Most a held foot drifts sideways under its hip as the trunk turns over it during one half-cycle, in its own
    /// leg's lengths: a rig whose feet stand far ahead of or behind its trunk's centre (an ant's front and hind legs)
    /// turns less than <see cref="MaxTurn"/> per half-cycle (its turns in place are slower too:
    /// <see cref="ReducedModelBuilder.TurnSweep"/>).
    /// </summary>
    public const float TurnDrift = 0.4f;

    /// <summary>Interval (seconds) at which how long the feet can stay on the walk's start and end contacts is probed.</summary>
    private const float HoldProbe = 0.02f;

    /// <summary>
    /// Fastest a swinging leg's joint turns from one fine step to the next with its sole held flat on its curve, radians
    /// per second (3,600°/s, 15° a fine step at 60 frames a second, 60° a frame): a flat-sole solve that turns one
    /// faster has jumped to another solution of the leg (a hip held at its limit let go and twisting 42° in 1/240 s),
    /// and the sole held along the curve's normal within its looser tolerance is taken instead when that solve does
    /// not. Slower turns are left to the flat sole: preferring the looser sole from 1,200°/s halved such turns on the
    /// desert's walks but left a user's human rig unable to walk down a staircase.
    /// </summary>
    public const float MaxJointTurn = 20f * MathF.PI;

    /// <summary>
    /// A swinging leg's solve that turns a joint faster than this (radians per second, 900°/s) and more than
    /// <see cref="SwingTurnRatio"/> times as fast as the fine step before has jumped too (<see cref="MaxJointTurn"/>):
    /// a hip whose abduction reached its limit as the foot left the ground turned its roll 18° in two fine steps, 23° in a
    /// displayed frame between frames of 2°, which the eye sees snap. Turning faster but accelerating no more sharply
    /// (a swing under way) is no jump.
    /// </summary>
    private const float SwingTurnFloor = 5f * MathF.PI;

    /// <summary>How many times faster than in the fine step before a swinging leg's joint may turn beyond <see cref="SwingTurnFloor"/>: the eye's ratio for a snap (three).</summary>
    private const float SwingTurnRatio = 3f;

    /// <summary>Fine steps per frame interval on which the feet are solved; each becomes a frame.</summary>
    public const int Substeps = 4;

    /// <summary>Distance (metres) within which an effector still or already touches its contact point: a swing's first and last moments count in the contact phases around it.</summary>
    public const float Touch = 0.8f * BodyCollision.ContactClearance;

    /// <summary>Most a swinging effector moves in the fine step after lifting off or before touching down, metres.</summary>
    private const float FirstMove = 0.005f;

    /// <summary>How closely a swinging effector follows its curve between its first and last fine steps, metres.</summary>
    public const float SwingTolerance = 0.005f;

    /// <summary>How far a held sole may tilt from the ground, radians (5°).</summary>
    public const float SoleTolerance = SoleHold.FlatTolerance;

    /// <summary>Lifts of a swinging foot above the higher of its two footholds, as shares of the step height, tried in order.</summary>
    private static readonly float[] Lifts = [0.35f, 0.6f, 1f, 1.5f, 2.2f];

    /// <summary>
    /// Farthest a foothold is first looked for sideways of where the contact pose holds the foot under the trunk, in
    /// rest legs (<c>Run.InPlace</c>): farther, a foot stands under the body or splayed out, not under its hip.
    /// </summary>
    public const float OutOfPlace = 0.35f;

    /// <summary>Shares of a foothold's sideways offset from the walk's path tried, nominal first.</summary>
    private static readonly float[] Inward = [1f, 0.75f, 0.5f, 0.25f, 0f];

    /// <summary>
    /// Shifts of a foothold along the walk tried at each sideways share, as shares of the step, nearest first: on
    /// rippled ground the nominal spot is often a hollow or a bump the leg cannot hold, and one a half to a whole step
    /// away may be held (on the desert, 37 of 58 planned walks animate with shifts up to a whole step, 31 with the
    /// first four).
    /// </summary>
    private static readonly float[] Along = [0f, -0.25f, 0.25f, -0.5f, 0.5f, -0.75f, 0.75f, -1f];

    /// <summary>
    /// Shifts along the walk (shares of the step) tried at each sideways share when none of <see cref="Along"/>'s
    /// is held: a leg reaching far ahead of or behind its hip (a spider's) stands with its trunk a short way from a
    /// ledge's edge, its nominal foothold over the drop, and is set down up to two steps nearer the hip, on the ledge.
    /// </summary>
    private static readonly float[] FarAlong = [1f, 1.25f, -1.25f, 1.5f, -1.5f, 2f, -2f];

    /// <summary>The (sideways share, shift along) pairs a foothold is tried at, in order.</summary>
    private static readonly (float Share, float Shift)[] FootholdTries =
        [.. Inward.SelectMany(i => Along.Select(a => (i, a))), .. Inward.SelectMany(i => FarAlong.Select(a => (i, a)))];

    /// <summary>Fine steps between the checks that a candidate foothold can be held, clear of the level, over the time it is held.</summary>
    private const int HoldCheck = 2 * Substeps;

    /// <summary>Probes of how far a held foot reaches: this many increments up to the leg length.</summary>
    private const int ProbeSteps = 40;

    private readonly PlanningScene _scene;
    private readonly CharacterModel _model;
    private readonly ContactGenerator _contacts;
    private readonly SoleHold _sole;
    private readonly Func<Vector3, Vector3?> _groundUnder;
    private readonly LimbIk _swingIk;
    private readonly BodyCollision _collision;
    private readonly FreeBones _free;

    /// <summary>The clearance of the rig's free bones (a tail) this gait bends, shared with the animator.</summary>
    public FreeBones FreeBones => _free;

    /// <summary>The rest pose's leg (metres): a hip's greatest height above its sole with every angle at rest.</summary>
    private readonly float _restLeg;

    /// <summary>
    /// With more than two feet, the half range (metres) each foot holds on level ground with the hips
    /// <see cref="ManyFeetHips"/> of the leg up, each leg's own (<see cref="FlatReach"/>); infinite for a biped.
    /// </summary>
    private readonly float _manyFeetReach;

    /// <summary>The farthest any foot stands from the trunk's centre horizontally in the contact pose (metres): how far a turn moves it per radian.</summary>
    private readonly float _footRadius;

    /// <summary>Most this rig's trunk turns during one half-cycle in place, radians: <see cref="MaxTurn"/>, less for feet far ahead of or behind the trunk's centre (<see cref="TurnDrift"/>).</summary>
    private readonly float _maxTurn;

    /// <summary>Most this rig's trunk turns during one half-cycle at full walking speed, radians: <see cref="MaxWalkingTurn"/>, less for feet far ahead of or behind the trunk's centre (<see cref="TurnDrift"/>).</summary>
    private readonly float _maxWalkingTurn;

    /// <summary>Per limb: where the contact pose holds its effector's contact point in the trunk's frame (metres, +X the trunk's left, +Z its forward): where a cruising foot is set down.</summary>
    private readonly Vector3[] _poseFeet;

    /// <summary>Per limb: the length of its bones from root joint to effector joint (metres), in the rest pose.</summary>
    private readonly float[] _bones;

    /// <summary>Per limb: its contact point's offset from its effector joint in the rest pose, model frame (metres).</summary>
    private readonly Vector3[] _soles;

    /// <summary>Per limb: its ball's offset from its effector joint in the rest pose, model frame (metres); <c>null</c> for a limb that does not roll (<see cref="RigLimb.Ball"/>).</summary>
    private readonly Vector3?[] _balls;

    /// <summary>Creates the gait of <paramref name="model"/> on <paramref name="scene"/>, using the animator's contact generator.</summary>
    public WalkGait(PlanningScene scene, CharacterModel model, ContactGenerator contacts)
    {
        _scene = scene;
        _model = model;
        _contacts = contacts;
        _sole = new SoleHold(model.Rig);
        _groundUnder = GroundUnder;
        _swingIk = new LimbIk(model.Rig, new IkSettings { Restarts = 0, MaxIterations = 24, PositionTolerance = SwingTolerance, NormalTolerance = MathF.PI / 6f });
        _collision = contacts.Collision;
        _free = new FreeBones(model, _collision);

        var positions = new Vector3[model.Rig.Joints.Count];
        var rotations = new Quaternion[model.Rig.Joints.Count];
        model.Rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), model.Rig.Neutral(), positions, rotations);
        _bones = new float[model.Limbs.Count];
        _soles = new Vector3[model.Limbs.Count];
        _balls = new Vector3?[model.Limbs.Count];
        for (int l = 0; l < model.Limbs.Count; l++)
        {
            RigLimb limb = model.Limbs[l];
            for (int k = 1; k < limb.Chain.Count; k++)
            {
                _bones[l] += Vector3.Distance(positions[limb.Chain[k - 1]], positions[limb.Chain[k]]);
            }

            _soles[l] = limb.EffectorPosition(positions, rotations) - positions[limb.EffectorJoint];
            _balls[l] = limb.Ball?.EffectorPosition(positions, rotations) - positions[limb.EffectorJoint];
        }

        _restLeg = StanceDip.RestLegLength(model);

        // How far from the trunk's centre the contact pose holds the farthest foot, horizontally: a turn of the trunk
        // moves that foot this far per radian under it.
        model.Rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), model.ContactPose, positions, rotations);
        _footRadius = model.Limbs.Where(l => l.Kind == LimbKind.Foot).Select(l => l.EffectorPosition(positions, rotations))
            .Select(p => new Vector2(p.X, p.Z).Length()).DefaultIfEmpty(0f).Max();
        _poseFeet = Paired(model, [.. model.Limbs.Select(l => l.EffectorPosition(positions, rotations))]);

        _maxTurn = model.TurnLimit(TurnDrift, MaxTurn);
        _maxWalkingTurn = model.TurnLimit(TurnDrift, MaxWalkingTurn);

        _manyFeetReach = model.Limbs.Count(l => l.Kind == LimbKind.Foot) > 2 ? FlatReach(ManyFeetHips) : float.PositiveInfinity;
    }

    /// <summary>
    /// The least half range (metres) over the feet that the trunk can move along its forward axis on level ground
    /// with the trunk lifted, level, until some foot's hip stands <paramref name="share"/> of that foot's own leg
    /// (<see cref="CharacterModel.LegLengths"/>) above it, while each foot holds where the contact pose puts it, sole flat
    /// (IK only: the rig's own reach, not a level's); 0 when a foot cannot stand there. Each leg's own length, not
    /// the longest: a rig whose hind legs are shorter than its front ones (a dog, a lizard) lifts its trunk as far as
    /// the hind legs allow, and the front ones then stand less straight.
    /// </summary>
    private float FlatReach(float share)
    {
        if (!(share > 0f))
        {
            return 0f;
        }

        Rig rig = _model.Rig;
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        float increment = _restLeg / ProbeSteps;
        float reach = float.PositiveInfinity;
        float[] legs = _model.LegLengths();
        rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), _model.ContactPose, positions, rotations);
        float lift = float.PositiveInfinity;
        for (int l = 0; l < _model.Limbs.Count; l++)
        {
            RigLimb limb = _model.Limbs[l];
            if (limb.Kind == LimbKind.Foot)
            {
                lift = MathF.Min(lift, (share * legs[l]) - (positions[limb.RootJoint].Y - limb.EffectorPosition(positions, rotations).Y));
            }
        }

        foreach (RigLimb limb in _model.Limbs.Where(l => l.Kind == LimbKind.Foot))
        {
            Vector3 foot = limb.EffectorPosition(positions, rotations);
            float[] reached = new float[2];
            for (int side = 0; side < 2; side++)
            {
                float[] q = (float[])_model.ContactPose.Clone();
                for (int k = 0; k <= ProbeSteps; k++)
                {
                    var root = new RootPose(new Vector3(0f, lift, (side == 0 ? -1f : 1f) * k * increment), Quaternion.Identity);
                    float[] trial = (float[])q.Clone();
                    bool held = _sole.Hold(root, trial, limb, foot, Vector3.UnitY);
                    if (!held && k == 0)
                    {
                        // A leg standing straight in its contact pose gives the IK no bend to follow: start from the flexion pose.
                        trial = (float[])_model.FlexionPose.Clone();
                        held = _sole.Hold(root, trial, limb, foot, Vector3.UnitY);
                    }

                    if (!held)
                    {
                        if (k == 0)
                        {
                            return 0f;
                        }

                        break;
                    }

                    q = trial;
                    reached[side] = k * increment;
                }
            }

            reach = MathF.Min(reach, (reached[0] + reached[1]) * 0.5f);
        }

        return reach;
    }

    /// <summary>A walk animated on its own: frames and contact phases on the walk's clock (0 to its duration), problems, frames with a bone in the level, the step length (metres) and half-cycle count chosen.</summary>
    public sealed record Clip(AnimationFrame[] Frames, List<ContactPhase> Phases, int CollidingFrames, List<JumpProblem> Problems, float Step, int HalfCycles)
    {
        /// <summary>Times (seconds on the walk's clock) at which something went wrong: where a second run shortens its steps.</summary>
        public float[] Troubles { get; init; } = [];

        /// <summary>How far (metres, world up) the run lifted its roots at each fine step: where a run walked again judges its footholds.</summary>
        public float[] Lifts { get; init; } = [];

        /// <summary>Stretches (metres along the walk, from and to) where the walk animated slows so that its shortened steps keep its cadence (<see cref="Walk.Slowed"/>); empty where it does not.</summary>
        public (float From, float To)[] SlowedAt { get; init; } = [];

        /// <summary>The pace (0 to 1) the walk slows to over <see cref="SlowedAt"/>.</summary>
        public float SlowedPace { get; init; } = 1f;

        /// <summary><paramref name="walk"/> (the walk this clip was asked to animate, or one the same) as animated: slowed where <see cref="SlowedAt"/> says.</summary>
        public Walk Walked(Walk walk) => SlowedAt.Length > 0 ? walk.Slowed(SlowedAt, SlowedPace) : walk;
    }

    /// <summary>
    /// <paramref name="feet"/> (where the contact pose holds each limb, trunk frame) with each foot moved along the
    /// trunk's forward axis to halfway between where it stands and where its partner on the other side (the foot across
    /// nearest it front to back) stands: a rig modelled mid-stride (a Rigify quadruped with one front and the other hind
    /// foot ahead) cruises with each pair of feet level under its hips or shoulders, not one foot of each pair a
    /// stride ahead of its reach. A rig modelled standing (its pairs level already) is unchanged.
    /// </summary>
    private static Vector3[] Paired(CharacterModel model, Vector3[] feet)
    {
        var paired = (Vector3[])feet.Clone();
        for (int l = 0; l < feet.Length; l++)
        {
            if (model.Limbs[l].Kind != LimbKind.Foot)
            {
                continue;
            }

            int partner = -1;
            for (int o = 0; o < feet.Length; o++)
            {
                if (o != l && model.Limbs[o].Kind == LimbKind.Foot && feet[o].X * feet[l].X < 0f
                    && (partner < 0 || MathF.Abs(feet[o].Z - feet[l].Z) < MathF.Abs(feet[partner].Z - feet[l].Z)))
                {
                    partner = o;
                }
            }

            if (partner >= 0 && feet[partner].Z != feet[l].Z)
            {
                paired[l].Z = 0.5f * (feet[l].Z + feet[partner].Z);
            }
        }

        return paired;
    }

    /// <summary>How a limb is moved over a span of fine steps (both ends included).</summary>
    private abstract record Segment(int From, int To);

    /// <summary>
    /// The limb holds a point by IK; <see cref="Settle"/>: its angles end on the walk's end pose; <see cref="Seed"/>:
    /// angles known to hold it at <see cref="Segment.From"/>, or <c>null</c>.
    /// </summary>
    private sealed record Holding(int From, int To, Vector3 Point, Vector3 Normal, bool Settle, float[]? Seed = null) : Segment(From, To);

    /// <summary>The limb is free, its angles going from <see cref="Start"/> to <see cref="End"/> (smoothly).</summary>
    private sealed record Free(int From, int To, float[] Start, float[] End) : Segment(From, To);

    /// <summary>The limb swings from the state before it to the state after it.</summary>
    private sealed record Swinging(int From, int To) : Segment(From, To);

    /// <summary>
    /// Animates <paramref name="walk"/> from the contact pose <paramref name="start"/> to <paramref name="end"/>,
    /// upright where the body can: steps from the rest leg and speed (stride 2.3·L·Fr^0.3) within
    /// <see cref="UprightReachMargin"/> of the held legs' reach, the trunk lifted toward <see cref="UprightHips"/> as
    /// far as the held feet allow (<see cref="KneeMargin"/>), the hands down beside the thighs swinging
    /// <see cref="ArmSwing"/> against the legs. Where that walk has problems: walked again with steps shortened to
    /// <see cref="ShortStep"/> only around them (first within <see cref="NarrowSpan"/> of them, kept where that clears the walk; then within
    /// <see cref="ShortSpan"/>, further where the same troubles come back), the walk slowed there by as much so that
    /// they keep its cadence (<see cref="Clip.Walked"/>: it then takes longer; a walker picks its way over rough
    /// ground, it does not scurry), then lifted with the classic steps, then at the
    /// stances' own height; the first clean one is kept, else the one with the fewest problems.
    /// </summary>
    /// <param name="move">Index of the walk in the path, for problems.</param>
    /// <param name="walk">The walk.</param>
    /// <param name="start">Where the previous move left the body (a landing contact pose, or the first stance's).</param>
    /// <param name="end">The pose the next move needs (a takeoff contact pose, or the last stance's).</param>
    /// <param name="frameRate">Frames per second.</param>
    public Clip Animate(int move, Walk walk, ContactConfiguration start, ContactConfiguration end, float frameRate)
    {
        ArgumentNullException.ThrowIfNull(walk);
        ArgumentNullException.ThrowIfNull(start);
        ArgumentNullException.ThrowIfNull(end);
        // Animated once: a walk asked for while another thread animates it is waited for; one that throws is forgotten.
        Clip clip = _animated.GetOrSolve(
            new WalkKey(walk, start, end, frameRate),
            (Gait: this, Move: move, Walk: walk, Start: start, End: end, FrameRate: frameRate),
            static s => s.Gait.AnimateAnew(s.Move, s.Walk, s.Start, s.End, s.FrameRate),
            ref _solved,
            out _);
        return Copy(clip, move);
    }

    /// <summary>
    /// How many walks' clips each generation of <see cref="Animate"/>'s memory keeps (64 to 128 in all, those asked for
    /// last): a plan's repair animates the same walk between the same poses again, and agents of one kind walk the
    /// same moves.
    /// </summary>
    private const int Remembered = 64;

    /// <summary>Clips animated or being animated, by everything they are animated from (the gait is a function of those): a walk asked for while another thread animates it is waited for, not animated twice.</summary>
    private readonly RememberedResults<WalkKey, Lazy<Clip>> _animated = new(Remembered);

    private int _solved;

    /// <summary>Walks animated anew (not found among those remembered or being animated) since this gait was made.</summary>
    internal int Solved => Volatile.Read(ref _solved);

    private int _runsStopped;

    /// <summary>Runs stopped early since this gait was made, as of no use (<see cref="AnimateAnew"/>).</summary>
    internal int RunsStopped => Volatile.Read(ref _runsStopped);

    /// <summary>Whether runs kept only with fewer problems than the best so far stop once they have as many (the default; off, every run is finished, for tests: the clips are the same).</summary>
    internal bool StopsRunsOfNoUse { get; init; } = true;

    /// <summary>Whether the runs of one walk share what they measure on its stances (<see cref="Stances"/>; the default; off, each run measures them itself, for tests: the clips are the same).</summary>
    internal bool SharesStanceMeasures { get; init; } = true;

    private int _stanceMeasures;

    /// <summary>Stance measures (a cruise or a foot's reach on a walk's start or end stance) made since this gait was made.</summary>
    internal int StanceMeasures => Volatile.Read(ref _stanceMeasures);

    /// <summary>A run kept only with fewer problems than <paramref name="best"/> animated, or <c>null</c> when it stopped with as many (<see cref="StopsRunsOfNoUse"/>).</summary>
    private Clip? Unless(Run run, Clip best)
    {
        if (!StopsRunsOfNoUse)
        {
            return run.Animate();
        }

        Clip? clip = run.AnimateWithFewer(best.Problems.Count);
        if (clip is null)
        {
            Interlocked.Increment(ref _runsStopped);
        }

        return clip;
    }

    /// <summary><paramref name="clip"/> with its own frames' angles (callers may change them in place) and its problems placed on move <paramref name="move"/>.</summary>
    private static Clip Copy(Clip clip, int move) => clip with
    {
        Frames = [.. clip.Frames.Select(f => f with { Angles = (float[])f.Angles.Clone() })],
        Phases = [.. clip.Phases],
        Problems = [.. clip.Problems.Select(p => p with { Jump = move })],
    };

    /// <summary>What a walk's clip is animated from: the walk's ground path, speed, pitch span and stances' poses (all <see cref="Walk.PoseAt(float)"/> depends on), the poses it starts and ends in, and the frame rate.</summary>
    private sealed record WalkKey(Walk Walk, ContactConfiguration Start, ContactConfiguration End, float FrameRate)
    {
        private readonly int _hash = HashCode.Combine(Walk.Speed, Walk.Path.Count, Walk.Path[0], Walk.Path[^1], Start.Root, End.Root, FrameRate);

        public bool Equals(WalkKey? other) =>
            other is not null && _hash == other._hash && Walk.Speed == other.Walk.Speed && Walk.PitchSpan == other.Walk.PitchSpan && FrameRate == other.FrameRate
            && Walk.From.Pose == other.Walk.From.Pose && Walk.To.Pose == other.Walk.To.Pose && Walk.Path.SequenceEqual(other.Walk.Path) && Walk.CrossGrades.SequenceEqual(other.Walk.CrossGrades)
            && Same(Start, other.Start) && Same(End, other.End);

        public override int GetHashCode() => _hash;

        private static bool Same(ContactConfiguration a, ContactConfiguration b) =>
            a.Root == b.Root && a.Valid == b.Valid && a.Angles.AsSpan().SequenceEqual(b.Angles) && a.Contacts.SequenceEqual(b.Contacts);
    }

    /// <summary><see cref="Animate"/> without the remembered clips.</summary>
    private Clip AnimateAnew(int move, Walk walk, ContactConfiguration start, ContactConfiguration end, float frameRate)
    {
        // Upright first (cruising with the hips CruiseHips of the leg up, the step from the leg and speed, the hips
        // lifted toward UprightHips over each foot, as far as a trailing foot reaches rolled onto its ball, else as far
        // as it reaches flat); where the body cannot walk so on this ground, the step measured
        // at the stances' height; then lifted with steps the legs reach easily; then at the stances' own height. The
        // first without problems is kept, else the one with fewest. A run whose clip is kept only when it has fewer
        // problems than the best so far, and is otherwise of no use (not the shortening and lowering rounds, which
        // go on from the places each run met trouble), stops as soon as it has as many (Unless).
        var stances = new Stances(this); // measured once for all the runs below
        Clip best = new Run(this, move, walk, start, end, frameRate, lift: true, longSteps: true, cruise: true, stances: stances).Animate();
        // How the best run so far was made (rolling, shortened and lowered where), to walk it again below.
        (bool Roll, float[]? ShortAt, float[]? LowAt, float Share) made = (true, null, null, ShortStep);
        bool roll = true;
        if (best.Problems.Count > 0 && _balls.Any(b => b is not null))
        {
            // The hips lifted as far as a trailing foot reaches rolled onto its ball, where the rig's foot cannot roll
            // so (its toes would go into the ground): lifted as far as the feet reach flat.
            Clip? flat = Unless(new Run(this, move, walk, start, end, frameRate, lift: true, longSteps: true, cruise: true, roll: false, stances: stances), best);
            (best, roll) = flat is not null && flat.Problems.Count < best.Problems.Count ? (flat, false) : (best, true);
            made = made with { Roll = roll };
        }

        // Where the upright walk met trouble, it is walked again with shorter steps there (ShortenRounds times at
        // most), the rest of it unchanged: one hollow or a cramped end stance does not shorten every step. The walk
        // slows there by as much (Run), so the steps keep their cadence: shortened at full speed, the skeleton's steps
        // came 3.0 a second over the debris of a foreign level, and they now come 2.5, a person's 1.9 to 2.6. Shortening
        // steps moves the footholds after them, so a walk may meet a new trouble further on: it is shortened there
        // too, the earlier places kept, until a walk does worse than the best yet. A walk that meets only the same
        // troubles again is shortened further there (ShortStep again each time, down to LeastShortStep: a foot
        // going down two stair treads at once takes one), and stops when that no longer helps.
        // First over NarrowSpan, ShortStep only, shortened too where new troubles come up: kept if that clears the walk.
        float[] narrowAt = best.Troubles;
        for (int again = 0; again < ShortenRounds && best.Problems.Count > 0 && _restLeg > 0f && narrowAt.Length > 0; again++)
        {
            Clip narrow = new Run(this, move, walk, start, end, frameRate, lift: true, longSteps: true, cruise: true, roll, narrowAt, shortSpan: NarrowSpan, stances: stances).Animate();
            if (narrow.Problems.Count == 0)
            {
                return narrow;
            }

            float[] more = [.. narrowAt, .. narrow.Troubles];
            if (Run.Places(more) == Run.Places(narrowAt))
            {
                break;
            }

            narrowAt = more;
        }

        float[] shortAt = best.Troubles;
        float share = ShortStep;
        float bestShare = ShortStep;
        for (int again = 0; again < ShortenRounds && best.Problems.Count > 0 && _restLeg > 0f && best.Troubles.Length > 0; again++)
        {
            float[] used = shortAt;
            Clip clip = new Run(this, move, walk, start, end, frameRate, lift: true, longSteps: true, cruise: true, roll, used, shortShare: share, stances: stances).Animate();
            float[] more = [.. shortAt, .. clip.Troubles];
            bool news = Run.Places(more) > Run.Places(shortAt);
            shortAt = more;
            if (clip.Problems.Count < best.Problems.Count)
            {
                best = clip;
                bestShare = share;
                made = (roll, used, null, share);
            }
            else if (again > 0 && clip.Problems.Count > best.Problems.Count)
            {
                break;
            }

            if (!news)
            {
                if (share * ShortStep < LeastShortStep)
                {
                    break;
                }

                // The same troubles again: shorter steps still around them.
                share *= ShortStep;
            }
        }

        // Where shorter steps do not clear a trouble either, the hips come down to the stances' height there only (a
        // step either side of it, Lowered), the rest of the walk upright: one hollow does not crouch the whole walk.
        float[] lowAt = shortAt;
        for (int again = 0; again < ShortenRounds && best.Problems.Count > 0 && _restLeg > 0f && lowAt.Length > 0; again++)
        {
            float[] used = lowAt;
            Clip clip = new Run(this, move, walk, start, end, frameRate, lift: true, longSteps: true, cruise: true, roll, shortAt, used, bestShare, stances: stances).Animate();
            float[] more = [.. lowAt, .. clip.Troubles];
            bool news = Run.Places(more) > Run.Places(lowAt);
            lowAt = more;
            if (clip.Problems.Count < best.Problems.Count)
            {
                best = clip;
                made = (roll, shortAt, used, bestShare);
            }

            if (!news)
            {
                break;
            }
        }

        if (best.Problems.Count == 0 || !(_restLeg > 0f))
        {
            return best;
        }

        // Going down stairs, a foot set down on the tread above is judged at the unlifted hips, which follow the
        // flight's ground line: a riser below that tread, too low for the foot to hold behind the hip, so the foot is
        // set down at the nosing, where it cannot roll onto its ball (its ball is past the edge) once the lift raises
        // the hips. Judged where the lift holds the hips, the foot lands back on the tread and rolls there.
        if (best.Lifts.Length > 0)
        {
            Clip? raisedClip = Unless(new Run(this, move, walk, start, end, frameRate, lift: true, longSteps: true, cruise: true, made.Roll, made.ShortAt, made.LowAt, made.Share, raised: best.Lifts, stances: stances), best);
            if (raisedClip is not null && raisedClip.Problems.Count < best.Problems.Count)
            {
                best = raisedClip;
            }

            if (best.Problems.Count == 0)
            {
                return best;
            }
        }

        foreach ((bool lift, bool longSteps) in ((bool, bool)[])[(true, true), (true, false), (false, false)])
        {
            Clip? clip = Unless(new Run(this, move, walk, start, end, frameRate, lift, longSteps, cruise: false, stances: stances), best);
            if (clip is not null && clip.Problems.Count < best.Problems.Count)
            {
                best = clip;
            }

            if (best.Problems.Count == 0)
            {
                break;
            }
        }

        return best;
    }

    /// <summary>
    /// IK putting <paramref name="limb"/>'s contact point on <paramref name="point"/>, its contact face against a
    /// surface of normal <paramref name="normal"/>, or rolled onto its ball where it cannot lie flat
    /// (<see cref="SoleHold"/>); a loaded rig's foot held up to <see cref="MostRaised"/> higher where its skin would
    /// sink, and not held at all (false) where its skin would still sink deeper than <see cref="SinkAllowed"/>.
    /// </summary>
    private bool Hold(in RootPose root, float[] q, RigLimb limb, Vector3 point, Vector3 normal, Vector3? ball = null)
    {
        if (!_sole.Hold(root, q, limb, point, normal, _groundUnder, ball))
        {
            return false;
        }

        if (ball is not null || !_collision.HasSoleSkin(limb))
        {
            return true;
        }

        // A loaded rig's foot skin blended with the shin sinks below the sole as the shin leans: the foot is held
        // that much higher (SkinSettle of it left below, MostRaised at most), so that the skin the GLB draws stands on
        // the ground, not in it.
        Span<Vector3> positions = _model.Rig.Joints.Count <= 128 ? stackalloc Vector3[_model.Rig.Joints.Count] : new Vector3[_model.Rig.Joints.Count];
        Span<Quaternion> rotations = _model.Rig.Joints.Count <= 128 ? stackalloc Quaternion[_model.Rig.Joints.Count] : new Quaternion[_model.Rig.Joints.Count];
        _model.Rig.Solve(root, q, positions, rotations);
        Vector3 up = Vector3.Normalize(normal);
        float sink = _collision.SoleSink(limb, positions, rotations, point, up);
        if (!(sink > SinkAllowed))
        {
            return true;
        }

        // Where the leg cannot hold it that high, or even MostRaised leaves the skin deeper than SinkAllowed (a Rigify
        // panda's hind foot on a debris slab, its shin leaning: 2.4 cm), the foot cannot hold there: the GLB would draw
        // its sole in the ground.
        float[] raised = (float[])q.Clone();
        if (!_sole.Hold(root, raised, limb, point + (up * MathF.Min(sink - SkinSettle, MostRaised)), normal, _groundUnder))
        {
            return false;
        }

        Array.Copy(raised, q, q.Length);
        _model.Rig.Solve(root, q, positions, rotations);
        return !(_collision.SoleSink(limb, positions, rotations, point, up) > SinkAllowed);
    }

    /// <summary>How far (metres) a loaded rig's foot skin may sink below a held sole before the foot is held higher (<see cref="BodyCollision.SoleSink"/>): as deep as any skin may lie inside the level (<see cref="BodyCollision.SkinDepth"/>).</summary>
    private const float SinkAllowed = BodyCollision.SkinDepth;

    /// <summary>How far (metres) below the ground a foot held higher for its sinking skin leaves that skin (the sole's own tolerance).</summary>
    private const float SkinSettle = 0.003f;

    /// <summary>The most (metres) a foot is held above its contact for its sinking skin: within a centimetre of the contact the plan reports, as every held effector is.</summary>
    private const float MostRaised = 0.008f;

    /// <summary>The level's surface under a point (world metres) within <see cref="Touch"/> of it, straight down; <c>null</c> where there is none there (a rolling foot's ball never rests on air).</summary>
    private Vector3? GroundUnder(Vector3 point) =>
        _scene.Bvh.Raycast(point + (Vector3.UnitY * Touch), -Vector3.UnitY, 2f * Touch, out RayHit hit) && _scene.Surfaces.SurfaceOf(hit.Triangle) >= 0 ? hit.Point : null;

    private static float Smooth(float x) => Easing.Smooth(x);

    /// <summary>
    /// How far (metres) <paramref name="heights"/> (the hips' world height at each fine step) rise and fall within
    /// <paramref name="window"/> steps of step <paramref name="i"/> (itself measured), about the straight line fitted
    /// through the measured ones there, as the eye sees a bob: a steady rise or sink (a lift ramping up, the walk's
    /// own grade) is no bob. Steps not <paramref name="measured"/> are left out.
    /// </summary>
    internal static float HipSwing(float[] heights, bool[] measured, int i, int window)
    {
        (float at, float slope) = FitLine(heights, measured, i, window);
        (float low, float high) = (float.PositiveInfinity, float.NegativeInfinity);
        for (int j = Math.Max(0, i - window); j <= Math.Min(heights.Length - 1, i + window); j++)
        {
            if (measured[j])
            {
                float off = heights[j] - (at + (slope * (j - i)));
                (low, high) = (MathF.Min(low, off), MathF.Max(high, off));
            }
        }

        return high - low;
    }

    /// <summary>
    /// The least-squares line through the <paramref name="measured"/> <paramref name="heights"/> (metres, one per fine
    /// step) within <paramref name="window"/> steps of step <paramref name="i"/> (itself measured): its height at
    /// <paramref name="i"/> and its slope (metres per step; 0 where the steps span no length).
    /// </summary>
    private static (float At, float Slope) FitLine(float[] heights, bool[] measured, int i, int window)
    {
        (float n, float sx, float sy, float sxx, float sxy) = (0f, 0f, 0f, 0f, 0f);
        for (int j = Math.Max(0, i - window); j <= Math.Min(heights.Length - 1, i + window); j++)
        {
            if (measured[j])
            {
                float x = j - i;
                float y = heights[j];
                (n, sx, sy, sxx, sxy) = (n + 1f, sx + x, sy + y, sxx + (x * x), sxy + (x * y));
            }
        }

        float spread = (n * sxx) - (sx * sx);
        float slope = spread > 1e-6f ? ((n * sxy) - (sx * sy)) / spread : 0f;
        return ((sy - (slope * sx)) / n, slope);
    }

    /// <summary>
    /// The least-squares parabola through the <paramref name="measured"/> <paramref name="heights"/> (metres, one per
    /// fine step) within <paramref name="window"/> steps of step <paramref name="i"/>: its slope at <paramref name="i"/>
    /// (metres per step) and its bend (the coefficient of the squared step); the line's slope and no bend where fewer
    /// than five steps are measured or they do not fix a parabola.
    /// </summary>
    private static (float Slope, float Bend) FitBend(float[] heights, bool[] measured, int i, int window)
    {
        Span<double> s = stackalloc double[5];
        Span<double> t = stackalloc double[3];
        for (int j = Math.Max(0, i - window); j <= Math.Min(heights.Length - 1, i + window); j++)
        {
            if (measured[j])
            {
                double x = j - i;
                double power = 1.0;
                for (int k = 0; k < 5; k++)
                {
                    s[k] += power;
                    if (k < 3)
                    {
                        t[k] += power * heights[j];
                    }

                    power *= x;
                }
            }
        }

        // The normal equations of a + b·x + c·x², solved by Cramer's rule (3 × 3, once per fine step: no allocation).
        double det = Det3(s[0], s[1], s[2], s[1], s[2], s[3], s[2], s[3], s[4]);
        if (s[0] < 5 || !(Math.Abs(det) > 1e-9))
        {
            return (FitLine(heights, measured, i, window).Slope, 0f);
        }

        double b = Det3(s[0], t[0], s[2], s[1], t[1], s[3], s[2], t[2], s[4]) / det;
        double c = Det3(s[0], s[1], t[0], s[1], s[2], t[1], s[2], s[3], t[2]) / det;
        return ((float)b, (float)c);
    }

    /// <summary>The determinant of the 3 × 3 matrix given row by row.</summary>
    private static double Det3(double a, double b, double c, double d, double e, double f, double g, double h, double k) =>
        (a * ((e * k) - (f * h))) - (b * ((d * k) - (f * g))) + (c * ((d * h) - (e * g)));

    /// <summary>
    /// Lowers <paramref name="values"/> (metres, one per fine step) where they rise or fall faster than
    /// <paramref name="rate"/> per step, never raising any: each becomes the least of every measured value plus
    /// <paramref name="rate"/> times the steps between them (a forward and a backward pass). Steps not
    /// <paramref name="measured"/> are left as they are and bound none.
    /// </summary>
    internal static void LimitRate(float[] values, bool[] measured, float rate)
    {
        for (int pass = 0; pass < 2; pass++)
        {
            int previous = -1;
            for (int n = 0; n < values.Length; n++)
            {
                int i = pass == 0 ? n : values.Length - 1 - n;
                if (!measured[i])
                {
                    continue;
                }

                if (previous >= 0)
                {
                    values[i] = MathF.Min(values[i], values[previous] + (rate * Math.Abs(i - previous)));
                }

                previous = i;
            }
        }
    }

    /// <summary>What a contact pose lets one foot do: where it stands in the trunk's frame, how far the trunk may move either way along a direction with the foot held.</summary>
    private readonly record struct Footing(Vector3 Local, float Ahead, float Behind);

    /// <summary>One walk being animated: its fine grid, the angles at each fine step, and what went wrong.</summary>
    /// <summary>
    /// What the runs of one walk measure on its start and end stances, measured once: the hips' cruising lift and the
    /// angles holding it (<c>Run.Cruise</c>), and how far each foot's hold reaches along the trunk with the hips at a
    /// lift (<c>Run.Footings</c>; at the cruising lift the angles are those of the cruise, at none the stance's own).
    /// Each is a function of the stance, the lift and the gait alone, so every run gets what it would measure itself;
    /// each gets its own copy.
    /// </summary>
    private sealed class Stances(WalkGait gait)
    {
        private readonly Dictionary<bool, (float Lift, float[] Angles, Vector3 Hips)> _cruises = [];
        private readonly Dictionary<(bool Start, float Lift), Footing[]> _footings = [];

        public (float Lift, float[] Angles, Vector3 Hips) Cruise(bool start, Func<(float Lift, float[] Angles, Vector3 Hips)> measure)
        {
            if (!_cruises.TryGetValue(start, out (float Lift, float[] Angles, Vector3 Hips) cruise))
            {
                cruise = measure();
                _cruises[start] = cruise;
                Interlocked.Increment(ref gait._stanceMeasures);
            }

            return (cruise.Lift, (float[])cruise.Angles.Clone(), cruise.Hips);
        }

        public Footing[] Footings(bool start, float lift, Func<Footing[]> measure)
        {
            if (!_footings.TryGetValue((start, lift), out Footing[]? footings))
            {
                footings = measure();
                _footings[(start, lift)] = footings;
                Interlocked.Increment(ref gait._stanceMeasures);
            }

            return (Footing[])footings.Clone();
        }
    }

    private sealed class Run
    {
        private readonly WalkGait _gait;
        private readonly CharacterModel _model;
        private readonly Rig _rig;
        private readonly int _move;
        private readonly Walk _walk;
        private readonly ContactConfiguration _start;
        private readonly ContactConfiguration _end;
        private readonly int _steps;
        private readonly float _h;
        private readonly RootPose[] _roots;
        private readonly float[][] _angles;
        private readonly bool[] _colliding;
        private readonly Vector3[] _positions;
        private readonly Quaternion[] _rotations;

        /// <summary>The angles halfway between two fine steps (<see cref="MidwayCollides"/>), reused.</summary>
        private readonly float[] _midway;

        /// <summary>A touching-down foot's angles solved from the step before's (<see cref="Swing"/>), reused.</summary>
        private readonly float[] _along;

        /// <summary>A swinging foot's angles before a solve on its curve (<see cref="Smoothly"/>), reused.</summary>
        private readonly float[] _seed;

        /// <summary>The first solve on a swing's curve that held the foot but turned a joint too fast (<see cref="Smoothly"/>), reused.</summary>
        private readonly float[] _held;

        /// <summary>Two pools of angle arrays, one per fine step of a swing (<see cref="SwingPool"/>), reused by every swing.</summary>
        private readonly float[][][] _swingPools = [[], []];
        private readonly Dictionary<(int Limb, string Kind), (float Distance, int Count)> _failures = [];

        /// <summary>The problems at which the run stops as of no use (<see cref="AnimateWithFewer"/>).</summary>
        private int _limit = int.MaxValue;

        /// <summary>Whether the run has met its limit of problems: one per limb and kind of failure (<see cref="Fail"/>), plus those reported outright.</summary>
        private bool Enough => _problems.Count + _failures.Count >= _limit;

        private readonly List<JumpProblem> _problems = [];
        private readonly List<ContactPhase> _phases = [];
        private readonly List<float> _troubles = [];

        /// <summary>An earlier run's lifts per fine step (<see cref="Clip.Lifts"/>, metres, world up), added to the roots while the footholds are chosen; <c>null</c>: chosen at the unlifted roots.</summary>
        private readonly float[]? _raised;

        /// <summary>What this run's lift raised its roots by at each fine step (metres, world up); empty without a lift.</summary>
        private float[] _lifts = [];
        private readonly float[] _lowAt;

        /// <summary>How many places (times on the walk's clock, to the nearest 0.05 s) <paramref name="times"/> names.</summary>
        public static int Places(float[] times) => Rounded(times).Length;

        /// <summary>
        /// <paramref name="time"/> (seconds on walk <paramref name="from"/>'s clock) on the clock of <paramref name="to"/>,
        /// the same walk slowed elsewhere (<see cref="Walk.Slowed"/>): the same distance along it, or the same time into
        /// either turn in place.
        /// </summary>
        private static float OnClock(float time, Walk from, Walk to)
        {
            if (ReferenceEquals(from, to) || time <= from.StartTurn)
            {
                return time;
            }

            float walked = from.StartTurn + from.WalkTime;
            return time >= walked ? to.StartTurn + to.WalkTime + (time - walked) : to.TimeAtDistance(from.DistanceAt(time));
        }

        /// <summary>The step (metres) a walker of leg <paramref name="leg"/> (metres) takes at <paramref name="speed"/> (m/s): Alexander's stride 2.3·L·Fr^0.3 halved, Fr = v²/(g·L).</summary>
        private static float UprightStep(float leg, float speed) => 1.15f * leg * MathF.Pow(speed * speed / (9.81f * leg), 0.3f);

        /// <summary><paramref name="times"/> to the nearest 0.05 s, each once: where a walk is shortened.</summary>
        private static float[] Rounded(float[] times) => [.. times.Select(t => MathF.Round(t * 20f) / 20f).Distinct()];
        private readonly int _limbs;
        private float _leg;
        private float _stepHeight;
        private float _step;
        private float _stepLow;

        /// <summary>The step (metres) measured at the stances' height on whichever stance the legs reach farther: on a flight of steps, once the walk is under way (<see cref="Boundaries"/>).</summary>
        private float _stepLowCruise;
        private float _halfCycle = MinHalfCycle;
        private float[] _times = [];
        private float[] _cost = [0f, 1f];
        private float _cruiseStart;
        private float _cruiseEnd;
        private Vector3 _hipsStart;
        private Vector3 _hipsEnd;
        private bool _cruised;
        private int[] _swingStart = [];
        private int[] _swingEnd = [];
        private Vector3[] _startLocal = [];
        private Vector3[] _endLocal = [];
        private Vector3[] _startLocalLow = [];
        private Vector3[] _endLocalLow = [];
        private readonly bool _lift;
        private readonly bool _longSteps;
        private readonly bool _cruise;
        private readonly bool _roll;
        private readonly bool _arms;

        /// <summary>What this run measured on its start and end stances, shared with the other runs of the same walk.</summary>
        private readonly Stances _stances;

        /// <summary>The walk this run was asked to animate: <see cref="_walk"/> unless it slows around troubles (<see cref="Walk.Slowed"/>).</summary>
        private readonly Walk _given;

        /// <summary>Where (metres along the walk) and to what pace the walk slows around the troubles an earlier run met (<see cref="Clip.SlowedAt"/>).</summary>
        private readonly (float From, float To)[] _slowedAt = [];

        private readonly float _slowedPace = 1f;

        public Run(WalkGait gait, int move, Walk walk, ContactConfiguration start, ContactConfiguration end, float frameRate, bool lift, bool longSteps, bool cruise, bool roll = true, float[]? shortAt = null, float[]? lowAt = null, float shortShare = ShortStep, float shortSpan = ShortSpan, float[]? raised = null, Stances? stances = null)
        {
            _stances = gait.SharesStanceMeasures && stances is not null ? stances : new Stances(gait);
            _raised = raised;
            _roll = roll;
            _given = walk;
            if (shortAt is { Length: > 0 } && gait._restLeg > 0f && walk.Speed > 0f)
            {
                // Steps shortened around the troubles are taken at the walk's cadence: the walk slows there by as much
                // (Walk.PaceAt shortens the steps), over the span of steps either way and half a step more, in the
                // step of this leg at this speed.
                float natural = longSteps ? UprightStep(gait._restLeg, walk.Speed) : StepShare * gait._restLeg;
                float reach = (shortSpan + 0.5f) * natural;
                _slowedAt = [.. shortAt.Select(t => walk.DistanceAt(t)).Select(d => (d - reach, d + reach))];
                _slowedPace = shortShare;
                walk = walk.Slowed(_slowedAt, shortShare);
            }

            _lowAt = Rounded([.. (lowAt ?? []).Select(t => OnClock(t, _given, walk))]);
            _cruise = cruise;
            _arms = gait._restLeg > 0f && walk.Speed > 0f;
            _lift = lift && _arms;
            _longSteps = longSteps && _arms;
            _gait = gait;
            _model = gait._model;
            _rig = _model.Rig;
            _limbs = _model.Limbs.Count;
            _move = move;
            _walk = walk;
            _start = start;
            _end = end;
            int frames = Math.Max(2, (int)MathF.Ceiling(walk.Duration * frameRate));
            _steps = frames * Substeps;
            _h = walk.Duration / _steps;
            _roots = new RootPose[_steps + 1];
            _angles = new float[_steps + 1][];
            _colliding = new bool[_steps + 1];
            _positions = new Vector3[_rig.Joints.Count];
            _rotations = new Quaternion[_rig.Joints.Count];
            _midway = new float[_rig.DofCount];
            _along = new float[_rig.DofCount];
            _seed = new float[_rig.DofCount];
            _held = new float[_rig.DofCount];
        }

        /// <summary>Pool <paramref name="pool"/> (0 or 1) of angle arrays, at least <paramref name="count"/> of them, grown as needed.</summary>
        private float[][] SwingPool(int pool, int count)
        {
            float[][] keys = _swingPools[pool];
            if (keys.Length < count)
            {
                int had = keys.Length;
                Array.Resize(ref keys, count);
                for (int k = had; k < count; k++)
                {
                    keys[k] = new float[_rig.DofCount];
                }

                _swingPools[pool] = keys;
            }

            return keys;
        }

        private float Time(int i) => i >= _steps ? _walk.Duration : i * _h;

        private int Step(float time) => Math.Clamp((int)MathF.Round(time / _h), 0, _steps);

        private bool IsFoot(int l) => _model.Limbs[l].Kind == LimbKind.Foot;

        /// <summary>True when some foot holds a contact at <paramref name="t"/> (seconds into the walk, within 0.1 ms).</summary>
        private bool FootDown(float t)
        {
            foreach (ContactPhase p in _phases)
            {
                if (IsFoot(p.Limb) && t >= p.From - 1e-4f && t <= p.To + 1e-4f)
                {
                    return true;
                }
            }

            return false;
        }

        /// <summary>The walk animated.</summary>
        public Clip Animate() => AnimateWithFewer(int.MaxValue) ?? throw new UnreachableException("A run without a problem limit always finishes.");

        /// <summary>
        /// The walk animated, or <c>null</c> as soon as it has met <paramref name="limit"/> problems (a problem once
        /// met stays: the clip could then only have as many or more). Stopped early, a run leaves nothing behind; the
        /// clip it finishes is the one <see cref="Animate"/> makes.
        /// </summary>
        public Clip? AnimateWithFewer(int limit)
        {
            _limit = limit;
            if (!(_walk.Duration > 1e-6f))
            {
                _problems.Add(new JumpProblem(_move, "the walk has no length: its stances cannot be walked between"));
                RootPose root = _walk.PoseAt(0f);
                return new Clip([new AnimationFrame(0f, root, (float[])_start.Angles.Clone()), new AnimationFrame(0f, root, (float[])_end.Angles.Clone())], [], 0, _problems, 0f, 0);
            }

            WalkingLimits walking = _gait._scene.Character.Walking;
            _leg = MathF.Max(LegLength(_start), LegLength(_end));
            _stepHeight = walking.StepHeight > 0f ? walking.StepHeight : 0.25f * _leg;
            float[] raisedStart = _start.Angles;
            float[] raisedEnd = _end.Angles;
            if (_lift && _longSteps && _cruise)
            {
                // Upright: at full speed the trunk cruises with its hips CruiseHips of the leg above the held feet
                // (at the stances as far as their feet hold there, between them above the ground walked: RootAt), and
                // the step is measured there.
                (_cruiseStart, raisedStart, _hipsStart) = _stances.Cruise(start: true, () => Cruise(_start));
                (_cruiseEnd, raisedEnd, _hipsEnd) = _stances.Cruise(start: false, () => Cruise(_end));
                _cruised = true;
            }

            TrunkAndRoots();

            // What each foot can do on the contacts the walk starts and ends on, along the trunk's forward axis: where
            // to centre the footholds (the trunk turns in place to face the way it walks, then walks straight ahead).
            Footing[] startForward = _stances.Footings(start: true, _cruiseStart, () => Footings(_start, Forward(_start.Root), _cruiseStart, raisedStart));
            Footing[] endForward = _stances.Footings(start: false, _cruiseEnd, () => Footings(_end, Forward(_end.Root), _cruiseEnd, raisedEnd));
            _startLocal = [.. Enumerable.Range(0, _limbs).Select(l => Centred(startForward[l]))];
            _endLocal = [.. Enumerable.Range(0, _limbs).Select(l => Centred(endForward[l]))];
            (_startLocalLow, _endLocalLow) = ((Vector3[])_startLocal.Clone(), (Vector3[])_endLocal.Clone());
            if (_lift && _longSteps && _cruise && float.IsFinite(_gait._manyFeetReach))
            {
                // Upright, more than two feet: at full speed each foot is set down where the contact pose holds it
                // under the trunk, not where the stances at either end happen to place it: a foot planted out to the
                // side or far ahead of a stance would hold the hips down all the way (its range is FlatReach's).
                for (int l = 0; l < _limbs; l++)
                {
                    if (IsFoot(l))
                    {
                        _startLocal[l] = _startLocal[l] with { X = _gait._poseFeet[l].X, Z = _gait._poseFeet[l].Z };
                        _endLocal[l] = _endLocal[l] with { X = _gait._poseFeet[l].X, Z = _gait._poseFeet[l].Z };
                    }
                }
            }

            // The step: StepShare of the leg; long enough that a swing at full speed lasts MinSwing; short enough that a
            // held foot, from half a step (and an overlap) ahead of its centre to as much behind, stays within
            // ReachMargin of what its leg reaches.
            float natural = StepShare * _leg;
            float margin = ReachMargin;
            if (_longSteps)
            {
                // Upright: the step a walker of this leg takes at this speed (Alexander's stride 2.3·L·Fr^0.3, Fr =
                // v²/(g·L): about 0.75 L at a relaxed walk), as much of the reach as the hips dipping between steps allows.
                natural = UprightStep(_gait._restLeg, _walk.Speed);
                margin = UprightReachMargin;
            }

            bool cruising = _cruiseStart > 0f || _cruiseEnd > 0f;
            float reach = Reach(startForward, endForward, cruising);
            if (cruising && _gait._manyFeetReach >= ManyFeetShare * reach)
            {
                // More than two feet: some foot is always near the end of its range, holding the hips down; steps
                // no longer than the legs reach with the hips ManyFeetHips of the leg up keep the body upright
                // (unless that shortens them by more than a quarter: legs that barely reach that high walk as before).
                reach = MathF.Min(reach, _gait._manyFeetReach);
            }

            float fits = margin * reach / (0.5f + Overlap);
            if (2f * _walk.Speed * MinHalfCycle > fits && _walk.Speed > 0f)
            {
                // Short legs: a swing of MinSwing would carry the feet past their reach, so the half-cycle shortens
                // to the step they reach, no shorter than MinHalfCycle scaled to the leg as dynamic similarity says.
                float least = MinHalfCycle * MathF.Min(1f, MathF.Sqrt(MathF.Max(_gait._restLeg, _leg) / FullSizeLeg));
                _halfCycle = MathF.Max(least, fits / (2f * _walk.Speed));
            }

            float step = MathF.Max(natural, 2f * _walk.Speed * _halfCycle);
            _step = MathF.Max(MathF.Min(step, fits), MathF.Max(0.05f * _leg, 1e-3f));
            _stepLow = _step;
            _stepLowCruise = _step;
            if (cruising)
            {
                // Steps shorten as the trunk slows and sinks toward the stances at either end (or where the ground
                // is not level): there the step, and where the feet are centred, are those measured at the stances'
                // own height (a crouched leg reaches farther ahead than behind): as far as the legs reach on both
                // stances, but on a flight of steps the walk slows for (Walk.PaceAt), once it is under way, on
                // whichever stance they reach farther (a stance cramped by its ground, feet on one 0.3 m stair
                // tread, does not shorten every step of the flight up to it: those came 3.3-4.3 a second, a tread
                // each, at the walk's pace on the stairs; steps that do not fit near it are shortened there,
                // Troubles).
                Footing[] startLow = _stances.Footings(start: true, 0f, () => Footings(_start, Forward(_start.Root), 0f, _start.Angles));
                Footing[] endLow = _stances.Footings(start: false, 0f, () => Footings(_end, Forward(_end.Root), 0f, _end.Angles));
                _startLocalLow = [.. Enumerable.Range(0, _limbs).Select(l => Centred(startLow[l]))];
                _endLocalLow = [.. Enumerable.Range(0, _limbs).Select(l => Centred(endLow[l]))];
                float least = MathF.Max(0.05f * _leg, 1e-3f);
                _stepLow = MathF.Max(MathF.Min(step, margin * Reach(startLow, endLow, either: false) / (0.5f + Overlap)), least);
                _stepLowCruise = MathF.Max(MathF.Min(step, margin * Reach(startLow, endLow, either: true) / (0.5f + Overlap)), least);
            }

            // Feet in two groups; the group whose feet can stay least on the start contacts steps first.
            int[] group = Groups();
            int first = FirstGroup(group, startForward);
            _times = Boundaries(group, first);
            int n = _times.Length - 1;
            _swingStart = new int[n];
            _swingEnd = new int[n];
            for (int k = 0; k < n; k++)
            {
                float t0 = _times[k];
                float t1 = _times[k + 1];
                float overlap = Overlap * (t1 - t0);

                // Both groups hold before the first boundary and after the last, not across them: the feet on the
                // start contacts lift right at the first, those on the end contacts land right at the last.
                _swingStart[k] = Step(k == 1 && n > 2 ? t0 : t0 + overlap);
                _swingEnd[k] = Math.Max(_swingStart[k] + 1, Step(k == n - 2 && n > 2 ? t1 : t1 - overlap));
            }

            // The feet's footholds, then (upright) the hips lifted as far as the held feet let them, then the limbs moved.
            var plans = new List<Segment>?[_limbs];
            RootPose[]? unlifted = null;
            if (_raised is { } raised && raised.Length == _roots.Length)
            {
                // Footholds judged where an earlier run's lift held the hips (AnimateAnew); the lift is then made anew.
                unlifted = (RootPose[])_roots.Clone();
                for (int i = 0; i <= _steps; i++)
                {
                    _roots[i] = new RootPose(_roots[i].Position + (Vector3.UnitY * raised[i]), _roots[i].Rotation);
                }
            }

            for (int l = 0; l < _limbs; l++)
            {
                plans[l] = IsFoot(l) ? FootPlan(l, group[l] == first ? 0 : 1, n) : null;
                if (Enough)
                {
                    return null;
                }
            }

            if (unlifted is not null)
            {
                Array.Copy(unlifted, _roots, _roots.Length);
            }

            if (_lift)
            {
                Lift(plans);
            }

            for (int l = 0; l < _limbs; l++)
            {
                if (plans[l] is List<Segment> plan)
                {
                    Perform(l, plan);
                    if (Enough)
                    {
                        return null;
                    }
                }
            }

            for (int l = 0; l < _limbs; l++)
            {
                if (!IsFoot(l))
                {
                    // A swinging arm's free poses are checked against the level as they are shown, after the swing
                    // replaces the hanging pose (a T-posed rig's hang would meet a door frame its swinging arm clears).
                    List<Segment> plan = HandPlan(l, n);
                    bool swings = _arms && n > 2;
                    Perform(l, plan, checkFree: !swings);
                    if (swings)
                    {
                        SwingArm(l, _swingStart[0], _swingEnd[n - 1], plans);
                        CheckFree(l, plan);
                    }

                    if (Enough)
                    {
                        return null;
                    }
                }
            }

            // No foot steps to a new foothold faster than MinAirTime allows (it would read as a slide), shortened as the
            // half-cycle is for short legs: a walk too short or turning too fast for its steps says so. (A foot
            // rolling onto its ball, or back, keeps its foothold.)
            float minAir = JumpAnimator.MinAirTime * (_halfCycle / MinHalfCycle);
            foreach (IGrouping<int, ContactPhase> limbPhases in _phases.GroupBy(p => p.Limb))
            {
                ContactPhase[] ordered = [.. limbPhases.OrderBy(p => p.From)];
                for (int i = 1; i < ordered.Length; i++)
                {
                    float moved = Vector3.Distance(ordered[i].Position, ordered[i - 1].Position);
                    bool rolling = ordered[i].OnBall != ordered[i - 1].OnBall && _model.Limbs[ordered[i].Limb].Ball is RigLimb ball
                        && moved <= Vector3.Distance(ball.EffectorOffset, _model.Limbs[ordered[i].Limb].EffectorOffset) + (2f * Touch);
                    if (!rolling && ordered[i].From - ordered[i - 1].To < minAir && moved > 2f * Touch)
                    {
                        Fail(ordered[i].Limb, "would have to step faster than it can", Step(ordered[i - 1].To));
                    }
                }
            }

            // A walker always has a foot on the ground: a moment with every foot in the air is a problem (the
            // schedule assumes every foot ends on a contact; a foot the next jump takes off without may swing free
            // while the others make their last step).
            int[] feet = [.. Enumerable.Range(0, _limbs).Where(IsFoot)];
            if (feet.Length >= 2)
            {
                for (int i = 0; i <= _steps; i++)
                {
                    if (!FootDown(Time(i)))
                    {
                        Fail(feet[0], "is in the air with every other foot", i);
                        break;
                    }
                }
            }

            if (Enough)
            {
                return null;
            }

            // Frames at every fine step; a free chain (a tail) bends out of the level where it can, and bones of no
            // limb are checked on each.
            float[] seconds = [.. Enumerable.Range(0, _steps + 1).Select(Time)];
            _gait._free.Clear(seconds, i => _roots[i], _angles);
            var frames = new AnimationFrame[_steps + 1];
            bool trunkReported = false;
            var held = new List<Vector3>();
            for (int i = 0; i <= _steps; i++)
            {
                frames[i] = new AnimationFrame(Time(i), _roots[i], _angles[i]);
                _rig.Solve(_roots[i], _angles[i], _positions, _rotations);
                int bone = _gait._collision.OtherBoneColliding(_positions, _rotations);
                if (bone >= 0)
                {
                    _colliding[i] = true;
                    _troubles.Add(Time(i));
                    if (!trunkReported)
                    {
                        trunkReported = true;
                        _problems.Add(new JumpProblem(_move, $"bone '{_rig.Joints[bone].Name}' passes through the level {Time(i):0.000} s into the walk", _walk.DistanceAt(Time(i))));
                    }
                }

                // Each limb's sole (its effector joint to its contact point) clear of the level but near a contact held
                // then, as an importer sees the frame: the limbs' own checks allow for their IK's tolerance at their
                // own contact, this one for no more than a centimetre at any.
                float t = Time(i);
                held.Clear();
                foreach (ContactPhase phase in _phases)
                {
                    if (t >= phase.From - 1e-4f && t <= phase.To + 1e-4f)
                    {
                        held.Add(phase.Position);
                    }
                }

                for (int l = 0; l < _limbs; l++)
                {
                    RigLimb limb = _model.Limbs[l];
                    if (SoleThrough(_positions[limb.EffectorJoint], limb.EffectorPosition(_positions, _rotations), held))
                    {
                        _colliding[i] = true;
                        Fail(l, "sole passes through the level", i);
                    }
                }

                if (Enough)
                {
                    return null;
                }
            }

            foreach (((int limb, string kind), (float distance, int count)) in _failures.OrderBy(f => f.Key.Limb).ThenBy(f => f.Value.Distance))
            {
                string where = count > 1 ? $"{count} times, first {distance:0.00} m along the walk" : $"{distance:0.00} m along the walk";
                _problems.Add(new JumpProblem(_move, $"{_model.Limbs[limb].Name} {kind} ({where})", distance));
            }

            return new Clip(frames, _phases, _colliding.Count(c => c), _problems, _step, n) { Troubles = [.. _troubles.Select(t => OnClock(t, _walk, _given))], Lifts = _lifts, SlowedAt = _slowedAt, SlowedPace = _slowedPace };
        }

        /// <summary>The roots on the walk at every fine step; the trunk's angles (in no limb) going smoothly from the start pose's to the end pose's; limbs as at the start.</summary>
        private void TrunkAndRoots()
        {
            bool[] limbDof = new bool[_rig.DofCount];
            foreach (RigLimb limb in _model.Limbs)
            {
                foreach (int d in limb.ChainDofSpan)
                {
                    limbDof[d] = true;
                }
            }

            for (int i = 0; i <= _steps; i++)
            {
                _roots[i] = RootAt(Time(i));
                float w = Smooth(Time(i) / _walk.Duration);
                float[] q = (float[])_start.Angles.Clone();
                for (int d = 0; d < q.Length; d++)
                {
                    if (!limbDof[d])
                    {
                        q[d] = float.Lerp(_start.Angles[d], _end.Angles[d], w);
                    }
                }

                _angles[i] = q;
            }
        }

        /// <summary>
        /// Lifts the roots (world up) toward hips <see cref="UprightHips"/> of the rest leg above the held feet, in
        /// proportion to the walk's speed (none while it turns in place or stands): at each fine step as far as every
        /// held foot (and a swinging one near its footholds) stays within <see cref="KneeMargin"/> of its leg's length
        /// from the hip, its sole flat or, for a foot behind its hip that has a ball, rolled heel up onto it
        /// (<see cref="Rolled"/>: the hold then rolls it as <see cref="SoleHold"/> does); eroded then averaged over <see cref="LiftSmoothing"/>, so the lift never
        /// exceeds what the feet allow. The hips rise over each held foot and dip where the feet are apart: the bob.
        /// </summary>
        private void Lift(List<Segment>?[] plans)
        {
            _lifts = new float[_steps + 1];
            float target = UprightHips * _gait._restLeg;
            float[] raw = new float[_steps + 1];
            float[] height = new float[_steps + 1];
            bool[] measured = new bool[_steps + 1];
            var points = new List<(int Limb, Vector3 Point)>();
            for (int i = 0; i <= _steps; i++)
            {
                float w = Cruising(Time(i));
                if (w <= 0f)
                {
                    continue;
                }

                points.Clear();
                float heldY = 0f;
                int held = 0;
                for (int l = 0; l < _limbs; l++)
                {
                    if (plans[l] is not List<Segment> plan)
                    {
                        continue;
                    }

                    for (int s = 0; s < plan.Count; s++)
                    {
                        Segment segment = plan[s];
                        if (i < segment.From || i > segment.To)
                        {
                            continue;
                        }

                        if (segment is Holding hold)
                        {
                            points.Add((l, hold.Point));
                            heldY += hold.Point.Y;
                            held++;
                        }
                        else if (segment is Swinging swing)
                        {
                            float u = (i - swing.From) / (float)Math.Max(1, swing.To - swing.From);
                            if (u < SwingNearFoothold && s > 0 && plan[s - 1] is Holding before)
                            {
                                points.Add((l, before.Point));
                            }
                            else if (u > 1f - SwingNearFoothold && s + 1 < plan.Count && plan[s + 1] is Holding after)
                            {
                                points.Add((l, after.Point));
                            }
                        }

                        break;
                    }
                }

                if (held == 0)
                {
                    continue;
                }

                _rig.Solve(_roots[i], _angles[i], _positions, _rotations);
                float hips = 0f;
                int feet = 0;
                float lift = float.PositiveInfinity;
                foreach ((int l, Vector3 point) in points)
                {
                    Vector3 hip = _positions[_model.Limbs[l].RootJoint];
                    Vector3 ankle = point - Vector3.Transform(_gait._soles[l], _roots[i].Rotation);
                    float reach = KneeMargin * _gait._bones[l];
                    lift = MathF.Min(lift, MathF.Max(Reaching(hip, ankle, reach), Rolled(l, i, hip, point, ankle, reach)));
                    hips += hip.Y;
                    feet++;
                }

                float want = target - ((hips / feet) - (heldY / held));
                raw[i] = Math.Clamp(MathF.Min(want, lift), 0f, target) * w;
                height[i] = _roots[i].Position.Y + raw[i];
                measured[i] = true;
            }

            // The hips rise and fall at most MostBob of the leg within a step either way (a walker's pelvis bobs 4–5
            // cm): the peaks over each foot are kept within that of the dips between the steps, as the eye sees them,
            // in the world about the walk's own grade there (not over the held feet, whose mean jumps as a foot lands
            // higher up a dune: the desert skeleton's hips popped 0.1 L where a step up let them).
            int window = Math.Max(1, (int)MathF.Round(_step / _walk.Speed / _h));
            float bob = MostBob * _gait._restLeg;
            float[] capped = (float[])raw.Clone();
            float[] path = [.. _roots.Select(r => r.Position.Y)];
            for (int i = 0; i <= _steps; i++)
            {
                if (measured[i])
                {
                    // The walk's own grade and bend: the parabola (metres per fine step, and per step squared)
                    // through the unlifted roots. About a straight line, the ends of a window over a dune's crest lie
                    // below it and held the hips down there (the desert skeleton's lift of 0.25 m over a crest was
                    // cut to 0.02 m, its hips 0.74 L over the held foot).
                    (float slope, float bend) = FitBend(path, measured, i, window);
                    float above = height[i];
                    float floor = above;
                    for (int j = Math.Max(0, i - window); j <= Math.Min(_steps, i + window); j++)
                    {
                        if (measured[j])
                        {
                            float x = j - i;
                            floor = MathF.Min(floor, height[j] - (slope * x) - (bend * x * x));
                        }
                    }

                    capped[i] = MathF.Max(0f, raw[i] - MathF.Max(0f, above - (floor + bob)));
                }
            }

            raw = capped;

            // No faster rise or fall than a walker's (LiftRise): where the feet's reach lets the hips up less from one
            // moment to the next (a foot landing farther off, the other leaving), they are lowered ahead of it instead
            // of dropping (the desert skeleton's hips fell 9 cm in 0.07 s from a lift its next step did not allow). Only
            // ever lowered, so the feet stay within reach: the lift at each step is the least of every step's lift plus
            // the rate times the time between them (a forward and a backward pass). The dip each step is given below keeps
            // its own pace: it is the bob, drawn over the step.
            float halfCycle = (_times[^1] - _times[0]) / Math.Max(1, _times.Length - 1);
            LimitRate(raw, measured, MostBob * _gait._restLeg / MathF.Max(LiftRise * halfCycle, 1e-3f) * _h);

            // The hips dip at least LeastBob of the leg as the feet change over (both groups down, legs apart) below
            // their height mid-step (one group down, under the hips), as far as the walk is at speed: a walker vaults
            // over its stance legs instead of gliding, even where its legs would let the hips ride level (sprawled
            // legs, a crouched gait); below the walk's own path where the hips are not lifted at all. Where the legs'
            // reach already makes the hips rise and fall that much about their steady rise or sink (Swing), they are
            // left as they are.
            float dip = LeastBob * _gait._restLeg;
            int half = 0;
            var lifted = new (float Low, float High)[_steps + 1];
            float[] swings = new float[_steps + 1];
            float[] heights = [.. path.Select((y, i) => y + raw[i])];

            for (int i = 0; i <= _steps; i++)
            {
                lifted[i] = measured[i] ? Within(raw, measured, i, window) : default;
                swings[i] = measured[i] ? HipSwing(heights, measured, i, window) : 0f;
            }

            for (int i = 0; i <= _steps; i++)
            {
                float t = Time(i);
                while (half < _times.Length - 2 && t > _times[half + 1])
                {
                    half++;
                }

                float span = _times[half + 1] - _times[half];
                if (!measured[i] || !(span > 0f))
                {
                    continue;
                }

                float u = Math.Clamp((t - _times[half]) / span, 0f, 1f);
                float w = Cruising(t);
                float deficit = MathF.Max(0f, dip - swings[i]);
                raw[i] = MathF.Min(raw[i], lifted[i].High - (w * deficit * (1f - MathF.Sin(MathF.PI * u))));
            }

            int k = Math.Max(1, (int)MathF.Round(LiftSmoothing * (_halfCycle / MinHalfCycle) / _h));
            float[] eroded = new float[raw.Length];
            for (int i = 0; i < raw.Length; i++)
            {
                float least = float.PositiveInfinity;
                for (int j = Math.Max(0, i - k); j <= Math.Min(_steps, i + k); j++)
                {
                    least = MathF.Min(least, raw[j]);
                }

                eroded[i] = least;
            }

            for (int i = 0; i < raw.Length; i++)
            {
                float sum = 0f;
                for (int j = i - k; j <= i + k; j++)
                {
                    sum += eroded[Math.Clamp(j, 0, _steps)];
                }

                float lift = sum / ((2 * k) + 1);
                _roots[i] = new RootPose(_roots[i].Position + (Vector3.UnitY * lift), _roots[i].Rotation);
                _lifts[i] = lift;
            }
        }

        /// <summary>How far (metres, world up) a hip at <paramref name="hip"/> may rise with the ankle at <paramref name="ankle"/> still within <paramref name="reach"/> of it (negative: it must sink; <see cref="float.NegativeInfinity"/> where no height brings it within reach).</summary>
        private static float Reaching(Vector3 hip, Vector3 ankle, float reach)
        {
            Vector3 d = hip - ankle;
            float across = (d.X * d.X) + (d.Z * d.Z);
            return reach * reach > across ? MathF.Sqrt((reach * reach) - across) - d.Y : float.NegativeInfinity;
        }

        /// <summary>
        /// How far (metres, world up) the hip may rise over foot <paramref name="l"/> held at <paramref name="point"/>
        /// behind it at fine step <paramref name="i"/> when the foot rolls onto its ball (its heel up to
        /// <see cref="SoleHold.MostRoll"/>, the ball where the flat sole puts it, on the ground), as a walker's trailing
        /// foot peels off its heel; <see cref="float.NegativeInfinity"/> for a foot ahead of its hip or one that does not roll.
        /// </summary>
        private float Rolled(int l, int i, Vector3 hip, Vector3 point, Vector3 ankle, float reach)
        {
            Quaternion rotation = _roots[i].Rotation;
            if (!_roll || _gait._balls[l] is not Vector3 offset || Vector3.Dot(ankle - hip, Forward(_roots[i])) >= 0f)
            {
                return float.NegativeInfinity;
            }

            Vector3 flat = ankle + Vector3.Transform(offset, rotation);
            Vector3 toBall = flat - point;
            toBall.Y = 0f;
            if (toBall.LengthSquared() < 1e-8f || _gait._groundUnder(flat) is not Vector3 ball)
            {
                return float.NegativeInfinity;
            }

            // The heel rises about the ball's side axis: of the two senses of turning, the one that lifts the ankle.
            Vector3 side = Vector3.Normalize(Vector3.Cross(Vector3.UnitY, toBall));
            Vector3 back = ankle - flat;
            float best = float.NegativeInfinity;
            for (int k = 1; k <= RollTries; k++)
            {
                float tilt = k * SoleHold.MostRoll / RollTries;
                Vector3 a = Vector3.Transform(back, Quaternion.CreateFromAxisAngle(side, tilt));
                Vector3 b = Vector3.Transform(back, Quaternion.CreateFromAxisAngle(side, -tilt));
                best = MathF.Max(best, Reaching(hip, ball + (a.Y > b.Y ? a : b), reach));
            }

            return best;
        }

        /// <summary>The least and greatest of the measured <paramref name="values"/> within <paramref name="window"/> fine steps of step <paramref name="i"/> (itself measured).</summary>
        private (float Low, float High) Within(float[] values, bool[] measured, int i, int window)
        {
            (float low, float high) = (values[i], values[i]);
            for (int j = Math.Max(0, i - window); j <= Math.Min(_steps, i + window); j++)
            {
                if (measured[j])
                {
                    (low, high) = (MathF.Min(low, values[j]), MathF.Max(high, values[j]));
                }
            }

            return (low, high);
        }

        /// <summary>
        /// Swings hand <paramref name="l"/> fore and aft about its shoulder from fine step <paramref name="from"/> to
        /// <paramref name="to"/> (the first swing's start to the last swing's end: a short walk's arms swing fully while
        /// it cruises): by IK, its effector brought down beside the thigh over
        /// <see cref="ArmDrop"/> (a rig hanging its arms out in a T stays so no longer) and turned about the trunk's left axis by up to
        /// <see cref="ArmSwing"/>, forward as the foot on its side lifts and back as it lands (<see cref="Phases"/>), in proportion to the walk's speed.
        /// Where the swinging arm would touch the level (a door's jamb, a corridor's wall), it is held in over
        /// <see cref="ArmDrop"/> either side: the hand drawn toward the front of the thigh (<see cref="HeldIn"/>) and its
        /// swing faded out, as a walker squeezing through a doorway keeps their arms in; where that still touches, in
        /// front of the hips (<see cref="SqueezedIn"/>); where even that touches (or the arm cannot reach) it keeps its
        /// last pose, and the free limb's check reports it.
        /// </summary>
        private void SwingArm(int l, int from, int to, List<Segment>?[] plans)
        {
            RigLimb limb = _model.Limbs[l];
            _rig.Solve(_roots[from], _angles[from], _positions, _rotations);
            Vector3 shoulderLocal = ToLocal(_roots[from], _positions[limb.RootJoint]);
            // The foot on the arm's side and its partner on the other side (nearest the shoulder's mirror image).
            int foot = -1;
            int other = -1;
            float nearest = float.PositiveInfinity;
            float nearestOther = float.PositiveInfinity;
            Vector3 mirror = shoulderLocal with { X = -shoulderLocal.X };
            for (int o = 0; o < _limbs; o++)
            {
                Vector3 hip = ToLocal(_roots[from], _positions[_model.Limbs[o].RootJoint]);
                float d = Vector3.Distance(hip, shoulderLocal);
                float m = Vector3.Distance(hip, mirror);
                if (IsFoot(o) && hip.X * shoulderLocal.X > 0f && d < nearest)
                {
                    (nearest, foot) = (d, o);
                }
                else if (IsFoot(o) && hip.X * shoulderLocal.X < 0f && m < nearestOther)
                {
                    (nearestOther, other) = (m, o);
                }
            }

            if (foot < 0 || to - from < 2)
            {
                return;
            }

            float[]? phase = other >= 0 ? Phases(plans[foot], plans[other], from, to) : null;

            // The arm's free pose before the swing (the walk's own hanging pose), its chain's angles kept per fine step
            // (one array): a second pass holding the arm in starts from it again.
            IReadOnlyList<int> dofs = limb.ChainDofs;
            float[] hanging = new float[(to - from + 1) * dofs.Count];
            for (int k = 0; k <= to - from; k++)
            {
                for (int c = 0; c < dofs.Count; c++)
                {
                    hanging[(k * dofs.Count) + c] = _angles[from + k][dofs[c]];
                }
            }

            bool[] touched = SwingPass(l, foot, phase, from, to, null, HeldIn);
            if (!touched.Any(t => t))
            {
                return;
            }

            // Held in around every touch, faded in and out over ArmDrop.
            int ramp = Math.Max(1, (int)MathF.Round(ArmDrop / _h));
            float[] tuck = new float[to - from + 1];
            for (int k = 0; k < tuck.Length; k++)
            {
                if (!touched[k])
                {
                    continue;
                }

                for (int j = Math.Max(0, k - ramp); j <= Math.Min(tuck.Length - 1, k + ramp); j++)
                {
                    tuck[j] = MathF.Max(tuck[j], Smooth(1f - (Math.Abs(j - k) / (float)(ramp + 1))));
                }
            }

            Restore(from, dofs, hanging);
            if (!SwingPass(l, foot, phase, from, to, tuck, HeldIn).Any(t => t))
            {
                return;
            }

            // Still touching (an opening barely wider than the shoulders): held in further, the hands in front of the
            // hips, as a walker squeezing through a narrow door keeps them.
            Restore(from, dofs, hanging);
            SwingPass(l, foot, phase, from, to, tuck, SqueezedIn);
        }

        /// <summary>The arm's chain angles (<paramref name="dofs"/>) put back, from fine step <paramref name="from"/> on, to <paramref name="hanging"/> (one array, per fine step).</summary>
        private void Restore(int from, IReadOnlyList<int> dofs, float[] hanging)
        {
            for (int k = 0; k < hanging.Length / dofs.Count; k++)
            {
                for (int c = 0; c < dofs.Count; c++)
                {
                    _angles[from + k][dofs[c]] = hanging[(k * dofs.Count) + c];
                }
            }
        }

        /// <summary>
        /// Share of the arm's length (shoulder to effector) by which a held-in hand is drawn from beside the thigh toward
        /// the body's middle and forward, in front of the thigh.
        /// </summary>
        private const float HeldIn = 0.2f;

        /// <summary>Share of the arm's length by which a hand is held in where <see cref="HeldIn"/> still touches: in front of the hips.</summary>
        private const float SqueezedIn = 0.4f;

        /// <summary>
        /// One pass of <see cref="SwingArm"/> over fine steps <paramref name="from"/> to <paramref name="to"/> (the
        /// arm's chain starting at each step from its hanging pose there), the arm held in by <paramref name="tuck"/>
        /// (0 to 1 per step; <c>null</c>: nowhere) times <paramref name="heldIn"/> of its length: the steps (from <paramref name="from"/>) at which the swung hand's
        /// pose touched the level.
        /// </summary>
        private bool[] SwingPass(int l, int foot, float[]? phase, int from, int to, float[]? tuck, float heldIn)
        {
            RigLimb limb = _model.Limbs[l];
            _rig.Solve(_roots[from], _angles[from], _positions, _rotations);
            float side = MathF.Sign(ToLocal(_roots[from], _positions[limb.RootJoint]).X);
            int ramp = Math.Max(1, (int)MathF.Round(ArmDrop / _h));
            bool[] touched = new bool[to - from + 1];
            float[]? last = null;
            float[][] buffers = [new float[_rig.DofCount], new float[_rig.DofCount]];
            var none = new List<Vector3>();
            for (int i = from; i <= to; i++)
            {
                float held = tuck?[i - from] ?? 0f;
                _rig.Solve(_roots[i], _angles[i], _positions, _rotations);
                Vector3 shoulder = _positions[limb.RootJoint];
                Vector3 hangingHand = limb.EffectorPosition(_positions, _rotations);
                // In time with the steps (Phases); with no partner foot, against its own foot about its hip.
                float share = phase?[i - from] ?? Math.Clamp(Behind(i, foot) / MathF.Max(0.5f * _step, 1e-3f), -1f, 1f);
                float fade = MathF.Min(1f, MathF.Min(i - from, to - i) / (float)ramp);
                float angle = ArmSwing * share * Smooth(fade) * Cruising(Time(i)) * (1f - held);
                Vector3 left = Vector3.Transform(Vector3.UnitX, _roots[i].Rotation);
                Vector3 forward = Vector3.Transform(Vector3.UnitZ, _roots[i].Rotation);

                // The hand drops from its hanging pose to beside the thigh (the arm down, elbow a little bent, clear of
                // the body sideways), drawn in front of the thigh as far as it is held in, then swings about the shoulder.
                float reach = _gait._bones[l];
                float inward = (0.06f - (held * heldIn)) * reach;
                Vector3 down = shoulder + (-Vector3.UnitY * (0.96f * reach)) + (forward * ((0.08f + (held * heldIn)) * reach)) + (left * (side * inward));
                Vector3 hand = Vector3.Lerp(hangingHand, down, Smooth(fade));
                Vector3 target = shoulder + Vector3.Transform(hand - shoulder, Quaternion.CreateFromAxisAngle(left, -angle));
                // Into whichever buffer the last kept angles are not in (no array per fine step).
                float[] trial = ReferenceEquals(last, buffers[0]) ? buffers[1] : buffers[0];
                _angles[i].CopyTo(trial, 0);
                if (last is not null)
                {
                    foreach (int d in limb.ChainDofSpan)
                    {
                        trial[d] = last[d];
                    }
                }

                bool ok = _gait._swingIk.Reaches(_roots[i], trial, limb, target, null);
                if (ok)
                {
                    _rig.Solve(_roots[i], trial, _positions, _rotations);
                    ok = !_gait._collision.LimbCollides(limb, _positions, _rotations, null)
                        && !SoleThrough(_positions[limb.EffectorJoint], limb.EffectorPosition(_positions, _rotations), none);
                    touched[i - from] = !ok;
                }

                float[]? keep = ok ? trial : last;
                if (keep is not null)
                {
                    foreach (int d in limb.ChainDofSpan)
                    {
                        _angles[i][d] = keep[d];
                    }
                }

                last = keep;
            }

            return touched;
        }

        /// <summary>
        /// Where an arm is in its swing (+1 forward, −1 back) at each fine step from <paramref name="from"/> to
        /// <paramref name="to"/>, in time with the steps: from forward to back as the foot on its side swings
        /// (<paramref name="own"/>: it lifts from behind the hip and lands ahead), from back to forward as its partner
        /// swings (<paramref name="partner"/>), held while both feet are down; <c>null</c> when either foot has no plan.
        /// Timed by the steps, not read from where the feet stand: the swing keeps its amplitude whatever stands the
        /// feet ahead of or behind the hips (the user's human rig, its right foot cruising behind its hip toward a
        /// staggered stance, swung its right arm 4–20°, never back) and however uneven the steps (a short walk of
        /// steps 0.50 m, 0.17 m and 0.73 m apart swung it ±14°, then ±5°).
        /// </summary>
        private static float[]? Phases(List<Segment>? own, List<Segment>? partner, int from, int to)
        {
            if (own is null || partner is null)
            {
                return null;
            }

            // Each swing sets the arm's phase over its steps (the partner's first: a step both swing is the own foot's);
            // between swings the phase holds where the last one left it.
            float[] phase = new float[to - from + 1];
            bool[] set = new bool[phase.Length];
            foreach ((List<Segment> plan, float sign) in new[] { (partner, -1f), (own, 1f) })
            {
                foreach (Segment segment in plan)
                {
                    if (segment is not Swinging swing)
                    {
                        continue;
                    }

                    for (int i = Math.Max(from, swing.From); i <= Math.Min(to, swing.To); i++)
                    {
                        phase[i - from] = sign * MathF.Cos(MathF.PI * (i - swing.From) / Math.Max(1, swing.To - swing.From));
                        set[i - from] = true;
                    }
                }
            }

            for (int k = 1; k < phase.Length; k++)
            {
                if (!set[k])
                {
                    phase[k] = phase[k - 1];
                }
            }

            return phase;
        }

        /// <summary>How far (metres, along the trunk's forward at fine step <paramref name="i"/>, as last solved) foot <paramref name="leg"/> is behind its hip.</summary>
        private float Behind(int i, int leg)
        {
            RigLimb limb = _model.Limbs[leg];
            return ToLocal(_roots[i], _positions[limb.RootJoint]).Z - ToLocal(_roots[i], _positions[limb.EffectorJoint]).Z;
        }

        private void Fail(int limb, string kind, int step)
        {
            _troubles.Add(Time(step));
            float distance = _walk.DistanceAt(Time(step));
            _failures[(limb, kind)] = _failures.TryGetValue((limb, kind), out (float Distance, int Count) f) ? (MathF.Min(f.Distance, distance), f.Count + 1) : (distance, 1);
        }

        /// <summary>
        /// True when the segment from <paramref name="a"/> to <paramref name="b"/> (a sole) meets the level farther
        /// than a centimetre (and a sixteenth of its length) from every point of <paramref name="held"/>.
        /// </summary>
        private bool SoleThrough(Vector3 a, Vector3 b, List<Vector3> held)
        {
            const int pieces = 16;
            TriangleBvh bvh = _gait._scene.Bvh;
            if (!bvh.Raycast(a, b - a, 1f, out _))
            {
                return false;
            }

            float near = 0.01f + (Vector3.Distance(a, b) / pieces);
            for (int k = 0; k < pieces; k++)
            {
                Vector3 p = Vector3.Lerp(a, b, k / (float)pieces);
                Vector3 q = Vector3.Lerp(a, b, (k + 1) / (float)pieces);
                if (bvh.Raycast(p, q - p, 1f, out RayHit hit) && !AnyWithin(held, hit.Point, near))
                {
                    return true;
                }
            }

            return false;
        }

        /// <summary>True when a point of <paramref name="points"/> is within <paramref name="distance"/> metres of <paramref name="point"/>.</summary>
        private static bool AnyWithin(List<Vector3> points, Vector3 point, float distance)
        {
            foreach (Vector3 p in points)
            {
                if (Vector3.Distance(point, p) <= distance)
                {
                    return true;
                }
            }

            return false;
        }

        private static Vector3 Forward(RootPose root)
        {
            Vector3 f = root.Forward;
            f.Y = 0f;
            return f.LengthSquared() > 1e-8f ? Vector3.Normalize(f) : Vector3.UnitZ;
        }

        /// <summary>Where limb <paramref name="l"/> stands in <paramref name="config"/>, world: its contact, or where its effector is.</summary>
        private Vector3 Stand(ContactConfiguration config, int l)
        {
            if (config.ContactOf(l) is LimbContact c)
            {
                return c.Position;
            }

            _rig.Solve(config.Root, config.Angles, _positions, _rotations);
            return _model.Limbs[l].EffectorPosition(_positions, _rotations);
        }

        private Vector3 ToLocal(RootPose root, Vector3 world) => Vector3.Transform(world - root.Position, Quaternion.Conjugate(root.Rotation));

        /// <summary>The greatest height (metres, along the trunk's up axis) of a foot's root joint above where the foot stands.</summary>
        private float LegLength(ContactConfiguration config) => StanceDip.LegLength(_model, config, _positions, _rotations);

        /// <summary>The walk's root at <paramref name="t"/> seconds: the walk's pose, lifted (world up) by the cruise in proportion to the walk's speed.</summary>
        private RootPose RootAt(float t)
        {
            RootPose pose = _walk.PoseAt(t);
            float s = Smooth(t / _walk.Duration);
            float cruise;
            if (_cruised && !float.IsFinite(_gait._manyFeetReach))
            {
                // Two feet: between the stances the hips stand GroundHips of the leg above the ground the walk
                // crosses; near each stance as high as that stance's own feet hold them. (More feet keep the stances'
                // height: ManyFeetHips and their shorter steps hold them up.)
                float want = Between(pose, _walk.PointAt(_walk.DistanceAt(t)).Y, Vector3.Lerp(_hipsStart, _hipsEnd, s));
                cruise = float.Lerp(CruiseFrom(_cruiseStart, want, t - _walk.StartTurn - Walk.RampTime), CruiseFrom(_cruiseEnd, want, _walk.StartTurn + _walk.WalkTime - Walk.RampTime - t), s);
            }
            else
            {
                cruise = float.Lerp(_cruiseStart, _cruiseEnd, s);
            }

            cruise *= Weight(t, hips: true);
            return cruise > 0f ? new RootPose(pose.Position + (Vector3.UnitY * cruise), pose.Rotation) : pose;
        }

        /// <summary>
        /// The cruise lift (metres) a stance's end of the walk asks for <paramref name="away"/> seconds from where the
        /// walk reaches or leaves full speed: <paramref name="held"/> (what the stance's own feet hold) until then,
        /// rising smoothly over a step's time to <paramref name="want"/> (hips <see cref="GroundHips"/> of the rest
        /// leg over the ground): between the stances the feet stand on the gait's footholds, not the stance's, and a
        /// stance cramped by its ground does not hold the whole walk down.
        /// </summary>
        private float CruiseFrom(float held, float want, float away) => float.Lerp(held, want, Smooth(away / MathF.Max(StepTime, 1e-3f)));

        /// <summary>Seconds a full step takes at the walk's speed.</summary>
        private float StepTime => _step / MathF.Max(_walk.Speed, 1e-3f);

        /// <summary>
        /// How far (metres, world up) the walking <paramref name="pose"/> rises for the hips (at <paramref name="hips"/>
        /// in the trunk's frame) to stand <see cref="GroundHips"/> of the rest leg above <paramref name="ground"/> (the
        /// height of the path's ground point under the trunk): between the stances the feet step on the ground the walk
        /// crosses, not on a stance's contacts, which a dune or a rock may hold higher or lower.
        /// </summary>
        private float Between(RootPose pose, float ground, Vector3 hips)
        {
            float hip = pose.Position.Y + Vector3.Transform(hips, pose.Rotation).Y;
            float want = (GroundHips * _gait._restLeg) - (hip - ground);
            return float.IsFinite(want) ? Math.Clamp(want, 0f, _leg) : 0f;
        }

        /// <summary>
        /// How far into its cruise the walk is at <paramref name="t"/> seconds, 0 to 1: its speed over the walking
        /// speed, times the share of the path within <see cref="LevelWindow"/> either way that is level
        /// (<see cref="LevelShare"/>: on stairs and slopes a straight leg reaches less far down and up: the steps and
        /// the hips stay as at the stances), averaged over <paramref name="averaging"/> metres of travel either way;
        /// for the <paramref name="hips"/>' lift, level by the hips' wider grades (<see cref="HipsLevelGrade"/>).
        /// </summary>
        private float Weight(float t, float averaging = LevelWindow, bool hips = false)
        {
            float w = Cruising(t);
            if (!(w > 0f))
            {
                return 0f;
            }

            // Averaged over LevelWindow of travel either way: a stair's first riser coming within the window would
            // otherwise drop the hips the whole cruise lift within a frame or two.
            float distance = _walk.DistanceAt(t);
            float level = 0f;
            for (int k = -LevelSamples; k <= LevelSamples; k++)
            {
                level += LevelShare(distance + (k * averaging / LevelSamples), hips);
            }

            return w * level / ((2 * LevelSamples) + 1) * Lowered(t);
        }

        /// <summary>
        /// 0 within a step's time of a trouble that shorter steps did not clear (the hips at the stances' height there,
        /// the steps measured at that height), rising smoothly to 1 a step beyond; 1 where there is none.
        /// </summary>
        private float Lowered(float time) => Clear(time, _lowAt, StepTime, StepTime);

        /// <summary>
        /// 0 within <paramref name="span"/> seconds of the nearest of <paramref name="places"/> (times on the walk's
        /// clock), rising smoothly to 1 over <paramref name="fade"/> seconds beyond; 1 where there is none.
        /// </summary>
        private static float Clear(float time, float[] places, float span, float fade)
        {
            float clear = 1f;
            foreach (float at in places)
            {
                clear = MathF.Min(clear, Smooth((MathF.Abs(time - at) - span) / MathF.Max(fade, 1e-4f)));
            }

            return clear;
        }

        /// <summary>
        /// 1 where the path's grade over <see cref="LevelWindow"/> either way of <paramref name="distance"/> (metres
        /// along it) is under <see cref="LevelGrade"/> (<see cref="HipsLevelGrade"/> for the <paramref name="hips"/>),
        /// fading to 0 by <see cref="SteepGrade"/> (<see cref="HipsSteepGrade"/>). For a trunk that pitches with the
        /// ground (<see cref="Walk.PitchSpan"/>), the grade is taken from the trunk's own (<see cref="Walk.GradeAt"/>):
        /// up a plain ramp its legs reach as on the level.
        /// </summary>
        private float LevelShare(float distance, bool hips = false)
        {
            Vector3 d = _walk.PointAt(distance + LevelWindow) - _walk.PointAt(distance - LevelWindow);
            float across = new Vector2(d.X, d.Z).Length();
            float grade = across > 1e-3f ? MathF.Abs((d.Y / across) - _walk.GradeAt(distance)) : 0f;
            (float level, float steep) = hips ? (HipsLevelGrade, HipsSteepGrade) : (LevelGrade, SteepGrade);
            return Math.Clamp((steep - grade) / (steep - level), 0f, 1f);
        }

        /// <summary>
        /// The least half range (metres) any foot reaches along the trunk's forward axis on the start and end
        /// contacts; with <paramref name="either"/>, on whichever of the two it reaches farther (cruising, the feet
        /// are between the stances: one foot cramped by its stance's ground does not shorten every step).
        /// </summary>
        private float Reach(Footing[] start, Footing[] end, bool either)
        {
            float reach = float.PositiveInfinity;
            for (int l = 0; l < _limbs; l++)
            {
                float s = HalfRange(start[l]);
                float e = HalfRange(end[l]);
                reach = MathF.Min(reach, either ? MathF.Max(s, e) : MathF.Min(s, e));
            }

            return reach;
        }

        /// <summary>
        /// How far (metres, world up) the root of <paramref name="config"/> rises toward its hips <see cref="CruiseHips"/>
        /// of the rest leg above the lowest held foot, every held foot holding its contact by IK with no bone in the
        /// level, probed in small increments; the angles that hold them there; and where the hips sit in the trunk's
        /// frame (the mean of the feet's root joints, metres), for the lift between the stances (<see cref="Between"/>).
        /// </summary>
        private (float Lift, float[] Angles, Vector3 Hips) Cruise(ContactConfiguration config)
        {
            _rig.Solve(config.Root, config.Angles, _positions, _rotations);
            float low = float.NegativeInfinity;
            Vector3 hipSum = Vector3.Zero;
            int feet = 0;
            for (int l = 0; l < _limbs; l++)
            {
                if (IsFoot(l))
                {
                    hipSum += _positions[_model.Limbs[l].RootJoint];
                    feet++;
                    if (config.ContactOf(l) is LimbContact c)
                    {
                        low = MathF.Max(low, _positions[_model.Limbs[l].RootJoint].Y - c.Position.Y);
                    }
                }
            }

            // Where the hips sit in the trunk's frame: between the stances they are lifted to stand GroundHips of the
            // leg above the ground the walk crosses (RootAt), not above this stance's feet.
            Vector3 between = feet > 0 ? ToLocal(config.Root, hipSum / feet) : Vector3.Zero;
            float want = MathF.Min((CruiseHips * _gait._restLeg) - low, _leg);
            if (!(want > 0f) || !float.IsFinite(want))
            {
                return (0f, config.Angles, between);
            }

            int steps = Math.Clamp((int)MathF.Ceiling(want / (_leg / ProbeSteps)), 1, ProbeSteps);
            float[] q = config.Angles;
            float lo = 0f;
            for (int k = 1; k <= steps; k++)
            {
                float[] trial = (float[])q.Clone();
                if (!HoldsRaised(config, want * k / steps, trial))
                {
                    break;
                }

                (q, lo) = (trial, want * k / steps);
            }

            return (lo, q, between);
        }

        /// <summary>True when every held foot of <paramref name="config"/> holds its contact by IK from <paramref name="q"/> (updated) with the root lifted <paramref name="lift"/> metres, no bone in the level.</summary>
        private bool HoldsRaised(ContactConfiguration config, float lift, float[] q)
        {
            var root = new RootPose(config.Root.Position + (Vector3.UnitY * lift), config.Root.Rotation);
            for (int l = 0; l < _limbs; l++)
            {
                if (!IsFoot(l) || config.ContactOf(l) is not LimbContact c)
                {
                    continue;
                }

                // Flat: a stance's feet do not rise onto their toes to lift the trunk.
                RigLimb limb = _model.Limbs[l];
                if (!_gait._sole.Hold(root, q, limb, c.Position, c.Normal))
                {
                    return false;
                }

                _rig.Solve(root, q, _positions, _rotations);
                if (_gait._collision.LimbCollides(limb, _positions, _rotations, c.Position))
                {
                    return false;
                }
            }

            return true;
        }

        /// <summary>
        /// For each foot of <paramref name="config"/> with its root lifted <paramref name="lift"/> metres (world up),
        /// held there by the angles <paramref name="raised"/> (<see cref="Cruise"/>'s): where it stands in the trunk's frame, and how far (metres) the trunk may move along
        /// <paramref name="direction"/> (Ahead) and against it (Behind) while the foot holds its contact by IK, sole
        /// flat, no bone in the level, probed in small increments up to the leg length. Free feet and other limbs are
        /// not limited.
        /// </summary>
        private Footing[] Footings(ContactConfiguration config, Vector3 direction, float lift, float[] raised)
        {
            var footings = new Footing[_limbs];
            var start = new RootPose(config.Root.Position + (Vector3.UnitY * lift), config.Root.Rotation);
            for (int l = 0; l < _limbs; l++)
            {
                Vector3 local = ToLocal(start, Stand(config, l));
                if (!IsFoot(l) || config.ContactOf(l) is not LimbContact c)
                {
                    footings[l] = new Footing(local, float.PositiveInfinity, float.PositiveInfinity);
                    continue;
                }

                RigLimb limb = _model.Limbs[l];
                float[] reached = new float[2];
                float increment = _leg / ProbeSteps;
                for (int side = 0; side < 2; side++)
                {
                    float[] q = (float[])raised.Clone();
                    float x = 0f;
                    for (int k = 1; k <= ProbeSteps; k++)
                    {
                        var root = new RootPose(start.Position + (direction * ((side == 0 ? 1f : -1f) * k * increment)), start.Rotation);
                        float[] trial = (float[])q.Clone();
                        if (!_gait.Hold(root, trial, limb, c.Position, c.Normal))
                        {
                            break;
                        }

                        _rig.Solve(root, trial, _positions, _rotations);
                        if (_gait._collision.LimbCollides(limb, _positions, _rotations, c.Position))
                        {
                            break;
                        }

                        q = trial;
                        x = k * increment;
                    }

                    reached[side] = x;
                }

                footings[l] = new Footing(local, reached[0], reached[1]);
            }

            return footings;
        }

        /// <summary>The foot's stance position in the trunk's frame moved along the trunk's forward axis to the middle of the range its leg reaches.</summary>
        private static Vector3 Centred(Footing footing) =>
            float.IsFinite(footing.Ahead) && float.IsFinite(footing.Behind)
                ? footing.Local + (Vector3.UnitZ * ((footing.Behind - footing.Ahead) * 0.5f))
                : footing.Local;

        private static float HalfRange(Footing footing) => (footing.Ahead + footing.Behind) * 0.5f;

        /// <summary>Each foot's group (0 or 1): (side + rank front to back on its side) mod 2; −1 for other limbs.</summary>
        private int[] Groups()
        {
            var local = new Vector3[_limbs];
            for (int l = 0; l < _limbs; l++)
            {
                local[l] = _startLocal[l];
            }

            int[] group = new int[_limbs];
            for (int l = 0; l < _limbs; l++)
            {
                if (!IsFoot(l))
                {
                    group[l] = -1;
                    continue;
                }

                int side = local[l].X >= 0f ? 0 : 1;
                int rank = 0;
                for (int o = 0; o < _limbs; o++)
                {
                    if (o != l && IsFoot(o) && (local[o].X >= 0f ? 0 : 1) == side
                        && (local[o].Z > local[l].Z || (local[o].Z == local[l].Z && o < l)))
                    {
                        rank++;
                    }
                }

                group[l] = (side + rank) % 2;
            }

            return group;
        }

        /// <summary>The group to swing first: the one with the foot that can stay least on its start contact as the trunk walks off (the other holds meanwhile).</summary>
        private static int FirstGroup(int[] group, Footing[] along)
        {
            float[] least = [float.PositiveInfinity, float.PositiveInfinity];
            bool[] any = new bool[2];
            for (int l = 0; l < group.Length; l++)
            {
                if (group[l] >= 0)
                {
                    any[group[l]] = true;
                    least[group[l]] = MathF.Min(least[group[l]], along[l].Ahead);
                }
            }

            return !any[1] ? 0 : !any[0] ? 1 : least[1] < least[0] ? 1 : 0;
        }

        /// <summary>
        /// The half-cycles' boundaries in time, seconds. The trunk's motion is costed in steps: its travel plus what
        /// its turn moves the farthest foot under it (never more than a step per <see cref="MaxTurn"/>), and never less
        /// than its turn in <see cref="MaxTurn"/>s (at most one half-cycle per least half-cycle): a biped's
        /// turn along a curve barely shortens its steps, a long-bodied rig re-steps its feet as it turns. The first half-cycle lasts
        /// as long as the feet that stay on the start contacts can hold them (half a cycle of cost at most), the last
        /// from when the feet can hold the end contacts (half a cycle at most); those between are even in cost, each
        /// at most one, none shorter than the least half-cycle (<see cref="MinHalfCycle"/>, shorter for short legs: <see cref="FullSizeLeg"/>).
        /// Where the first and last, each kept to at least a half-cycle and to its half of the walk, would leave less
        /// than a half-cycle between them (a short walk that is mostly a turn in place, made first), there are three
        /// where they fit, the first and last half a cycle of cost long, drawn toward even in time as far as each needs
        /// to last a half-cycle; else two, split where half the cost is reached. A walk shorter than two half-cycles,
        /// or costing at most one, is split at half its time.
        /// </summary>
        private float[] Boundaries(int[] group, int first)
        {
            float duration = _walk.Duration;
            int samples = Math.Clamp((int)MathF.Ceiling(duration / 0.005f), 16, 200_000);
            float[] cost = new float[samples + 1];
            _cost = cost;
            RootPose previous = _walk.PoseAt(0f);
            float dt = duration / samples;
            for (int i = 1; i <= samples; i++)
            {
                RootPose pose = _walk.PoseAt(duration * i / samples);
                float turn = Rotations.AngleBetween(previous.Rotation, pose.Rotation);
                float moved = Vector3.Distance(previous.Position, pose.Position);
                // Steps shorten by the walk's pace where the trunk is or where the foot lands, half a step ahead:
                // the last step before a flight is already the flight's (a full step down onto it does not reach).
                // Climbing, the walk itself goes at the flight's pace Walk.ClimbLead before it, so the foot looks only
                // as far further ahead as its half step reaches beyond that: the step onto the flight is taken as
                // slowly as it is shortened.
                float t = duration * (i - 0.5f) / samples;
                float along = _walk.DistanceAt(t);
                float paceHere = _walk.PaceAt(along);
                float ahead = _walk.SlowsForSteps && _walk.ClimbsAt(along + (0.5f * _step)) ? MathF.Max(0f, (0.5f * _step) - (_walk.Speed * Walk.ClimbLead)) : 0.5f * _step;
                float pace = MathF.Min(paceHere, _walk.PaceAt(along + ahead));
                float low = paceHere < 1f ? float.Lerp(_stepLow, _stepLowCruise, Cruising(t)) : _stepLow;
                float stepHere = float.Lerp(low, _step, Weight(t, StepAveraging)) * pace;
                float maxTurn = float.Lerp(_gait._maxTurn, _gait._maxWalkingTurn, Cruising(t));
                float turnCost = turn * MathF.Min(_gait._footRadius / stepHere, 1f / maxTurn);
                cost[i] = cost[i - 1] + MathF.Min(MathF.Max((moved / stepHere) + turnCost, turn / maxTurn), dt / _halfCycle);
                previous = pose;
            }

            float total = cost[samples];
            if (duration < 2f * _halfCycle || total <= 1f)
            {
                // One step of each group: the first swings while the other holds the start contacts, then the other.
                return [0f, 0.5f * duration, duration];
            }

            // Half a cycle of cost from either end, as far as the feet can hold the start (end) contacts: probed once.
            float halfIn = TimeAtCost(0.5f);
            float halfOut = TimeAtCost(total - 0.5f);
            float early = MathF.Min(halfIn, HoldUntil(group, 1 - first, halfIn));
            float late = MathF.Max(halfOut, HoldFrom(halfOut));
            float firstEnd = Math.Clamp(early, _halfCycle, 0.5f * duration);
            float lastStart = Math.Clamp(late, 0.5f * duration, duration - _halfCycle);
            float span = lastStart - firstEnd;
            if (span < _halfCycle)
            {
                // The first and last half-cycles would meet: a short walk that is mostly a turn in place, made first.
                // Held on the start contacts until half its time, a group drifts from under its hips while the turn is
                // made (a spider's front foot, 0.6 m from its trunk's centre, 0.62 L sideways as the trunk turned 23°).
                // Where three half-cycles fit, the first ends and the last starts at half a cycle of cost from either
                // end (as the feet can hold the start and end contacts), drawn toward even in time as far as needed for
                // each to last a half-cycle; else two, split where half the cost is reached.
                if (duration >= 3f * _halfCycle)
                {
                    for (float blend = 0f; ; blend = MathF.Min(1f, blend + 0.1f))
                    {
                        float[] three = [0f, float.Lerp(early, duration / 3f, blend), float.Lerp(late, 2f * duration / 3f, blend), duration];
                        bool even = three[1] >= _halfCycle - 1e-4f && three[2] - three[1] >= _halfCycle - 1e-4f && duration - three[2] >= _halfCycle - 1e-4f;
                        if (even || blend >= 1f)
                        {
                            return three;
                        }
                    }
                }

                float least = MathF.Min(_halfCycle, 0.5f * duration);
                return [0f, Math.Clamp(TimeAtCost(0.5f * total), least, duration - least), duration];
            }

            float c0 = CostAt(firstEnd);
            float c1 = CostAt(lastStart);
            int middle = Math.Clamp((int)MathF.Ceiling(c1 - c0 - 1e-4f), 1, Math.Max(1, (int)(span / _halfCycle)));

            // Even in cost, drawn toward even in time as far as needed for every half-cycle to last the least half-cycle.
            var times = new float[middle + 3];
            times[0] = 0f;
            times[1] = firstEnd;
            times[middle + 1] = lastStart;
            times[middle + 2] = duration;
            for (float blend = 0f; ; blend = MathF.Min(1f, blend + 0.1f))
            {
                bool ok = true;
                for (int k = 1; k < middle; k++)
                {
                    float byCost = TimeAtCost(float.Lerp(c0, c1, k / (float)middle));
                    times[k + 1] = float.Lerp(byCost, float.Lerp(firstEnd, lastStart, k / (float)middle), blend);
                }

                for (int k = 1; k <= middle; k++)
                {
                    ok &= times[k + 1] - times[k] >= _halfCycle - 1e-4f;
                }

                if (ok || blend >= 1f)
                {
                    return times;
                }
            }
        }

        /// <summary>
        /// The walk's speed at <paramref name="t"/> seconds over its walking speed at its pace there, 0 to 1 (0 outside
        /// the walk): how far it has sped up from rest or slowed toward it, not how it slows on stairs (<see cref="Walk.PaceAt"/>).
        /// </summary>
        private float Cruising(float t) => Math.Clamp(_walk.CruiseAt(t), 0f, 1f);

        /// <summary>The time (seconds into the walk) at which the trunk's motion has cost <paramref name="c"/> half-cycles (<see cref="Boundaries"/>).</summary>
        private float TimeAtCost(float c)
        {
            int samples = _cost.Length - 1;
            int i = Array.BinarySearch(_cost, c);
            i = i >= 0 ? Math.Max(i, 1) : Math.Clamp(~i, 1, samples);
            float span = _cost[i] - _cost[i - 1];
            float f = span > 0f ? Math.Clamp((c - _cost[i - 1]) / span, 0f, 1f) : 1f;
            return _walk.Duration * (i - 1 + f) / samples;
        }

        /// <summary>The cost in half-cycles of the trunk's motion up to <paramref name="time"/> seconds into the walk.</summary>
        private float CostAt(float time)
        {
            int samples = _cost.Length - 1;
            float x = Math.Clamp(time / _walk.Duration, 0f, 1f) * samples;
            int i = Math.Min((int)x, samples - 1);
            return float.Lerp(_cost[i], _cost[i + 1], x - i);
        }

        /// <summary>
        /// How long (seconds into the walk, up to <paramref name="limit"/>) the feet of group <paramref name="g"/> can
        /// hold their start contacts by IK as the trunk moves off, probed every <see cref="HoldProbe"/>.
        /// </summary>
        private float HoldUntil(int[] group, int g, float limit)
        {
            float until = limit;
            for (int l = 0; l < _limbs; l++)
            {
                if (group[l] != g || _start.ContactOf(l) is not LimbContact c)
                {
                    continue;
                }

                float[] q = (float[])_start.Angles.Clone();
                for (float t = HoldProbe; t <= until; t += HoldProbe)
                {
                    if (!HoldsAt(l, t, c, q))
                    {
                        until = t - HoldProbe;
                        break;
                    }
                }
            }

            return until;
        }

        /// <summary>
        /// From when (seconds into the walk, from <paramref name="limit"/> on) every foot can hold its end contact by IK
        /// until the walk ends, probed every <see cref="HoldProbe"/> backward from the end.
        /// </summary>
        private float HoldFrom(float limit)
        {
            float from = limit;
            float duration = _walk.Duration;
            for (int l = 0; l < _limbs; l++)
            {
                if (!IsFoot(l) || _end.ContactOf(l) is not LimbContact c)
                {
                    continue;
                }

                float[] q = (float[])_end.Angles.Clone();
                for (float t = duration - HoldProbe; t >= from; t -= HoldProbe)
                {
                    if (!HoldsAt(l, t, c, q))
                    {
                        from = t + HoldProbe;
                        break;
                    }
                }
            }

            return from;
        }

        /// <summary>True when limb <paramref name="l"/> holds <paramref name="contact"/> at time <paramref name="t"/> of the walk by IK from the angles <paramref name="q"/> (updated when it does), no bone of it in the level.</summary>
        private bool HoldsAt(int l, float t, LimbContact contact, float[] q)
        {
            RigLimb limb = _model.Limbs[l];
            RootPose root = RootAt(t);
            float[] trial = (float[])q.Clone();
            if (!_gait.Hold(root, trial, limb, contact.Position, contact.Normal))
            {
                return false;
            }

            _rig.Solve(root, trial, _positions, _rotations);
            if (_gait._collision.LimbCollides(limb, _positions, _rotations, contact.Position))
            {
                return false;
            }

            Array.Copy(trial, q, q.Length);
            return true;
        }

        /// <summary>
        /// A foot's segments: the start contact (or free) until its first swing; after each swing the foothold of the
        /// next half-cycle (which its group holds) until its next swing; the end contact (or free) after its last.
        /// </summary>
        private List<Segment> FootPlan(int l, int parity, int halfCycles)
        {
            var plan = new List<Segment>();
            Segment Stance(int a, int b, bool atEnd)
            {
                ContactConfiguration config = atEnd ? _end : _start;
                return config.ContactOf(l) is LimbContact c
                    ? new Holding(a, b, c.Position, c.Normal, atEnd)
                    : new Free(a, b, config.Angles, config.Angles);
            }

            int last = (halfCycles - 1) % 2 == parity ? halfCycles - 1 : halfCycles - 2;
            Segment current = Stance(0, 0, atEnd: false);
            for (int k = parity; k < halfCycles; k += 2)
            {
                plan.Add(current with { To = _swingStart[k] });
                plan.Add(new Swinging(_swingStart[k], _swingEnd[k]));
                current = k == last ? Stance(_swingEnd[k], _steps, atEnd: true) : Foothold(l, k + 1, _swingEnd[k], _swingStart[k + 2]);
            }

            plan.Add(current);
            return plan;
        }

        /// <summary>A hand (or any limb that does not walk): lets go during the first half-cycle, hangs, and takes the end's contact during the last.</summary>
        private List<Segment> HandPlan(int l, int halfCycles)
        {
            float[] hang = Hang(l);
            int a0 = _swingStart[0];
            int b0 = _swingEnd[0];
            int a1 = _swingStart[halfCycles - 1];
            int b1 = _swingEnd[halfCycles - 1];
            var plan = new List<Segment>();
            if (_start.ContactOf(l) is LimbContact s)
            {
                plan.Add(new Holding(0, a0, s.Position, s.Normal, Settle: false));
                plan.Add(new Swinging(a0, b0));
            }
            else
            {
                plan.Add(new Free(0, a0, _start.Angles, _start.Angles));
                plan.Add(new Free(a0, b0, _start.Angles, hang));
            }

            plan.Add(new Free(b0, a1, hang, hang));
            if (_end.ContactOf(l) is LimbContact e)
            {
                plan.Add(new Swinging(a1, b1));
                plan.Add(new Holding(b1, _steps, e.Position, e.Normal, Settle: true));
            }
            else
            {
                plan.Add(new Free(a1, b1, hang, _end.Angles));
                plan.Add(new Free(b1, _steps, _end.Angles, _end.Angles));
            }

            return plan;
        }

        /// <summary>The angles a hand hangs in while walking: its free pose at the start or end, else one clear of the level mid-walk.</summary>
        private float[] Hang(int l)
        {
            if (_start.ContactOf(l) is null)
            {
                return _start.Angles;
            }

            if (_end.ContactOf(l) is null)
            {
                return _end.Angles;
            }

            float[] q = (float[])_angles[_steps / 2].Clone();
            _gait._contacts.KeepFree(_roots[_steps / 2], q, l);
            return q;
        }

        /// <summary>
        /// The foothold of foot <paramref name="l"/> in half-cycle <paramref name="k"/>, held from fine step
        /// <paramref name="from"/> to <paramref name="to"/>: its centred stance offset at the trunk pose mid-half-cycle,
        /// dropped on the ground, moved toward the path's centre line until the ground is there and the leg holds it
        /// (first only as far as keeps it within <see cref="OutOfPlace"/> of its place under the trunk);
        /// on a stair's tread, moved along the walk first until the whole sole lies on the tread (<see cref="OnTread"/>).
        /// </summary>
        private Holding Foothold(int l, int k, int from, int to)
        {
            float time = TimeAtCost((CostAt(Time(from)) + CostAt(Time(to))) * 0.5f);
            float distance = _walk.DistanceAt(time);
            RootPose pose = _walk.PoseAt(time);
            float u = Smooth(time / _walk.Duration);
            Vector3 nominal = pose.ToWorld(Vector3.Lerp(Vector3.Lerp(_startLocalLow[l], _endLocalLow[l], u), Vector3.Lerp(_startLocal[l], _endLocal[l], u), Weight(time)));
            Vector3 ground = _walk.PointAt(distance);
            Vector3 heading = Forward(pose);
            Vector3 across = nominal - ground;
            across.Y = 0f;
            Vector3 along = Vector3.Dot(across, heading) * heading;
            Vector3 lateral = across - along;
            WalkingLimits walking = _gait._scene.Character.Walking;
            float slope = walking.MaxGrade;
            var walkable = new GroundSlopeTest(walking);
            (Vector3 Point, Vector3 Normal)? grounded = null;
            int mid = Step(time);

            // The foothold is tried where the trunk is midway, then where the foot lands, then every HoldCheck fine
            // steps until it lifts: the trunk moves and turns over the foot, whose toes must stay out of uneven ground.
            var checks = new List<int> { mid, from };
            for (int i = from + HoldCheck; i < to; i += HoldCheck)
            {
                checks.Add(i);
            }

            checks.Add(to);
            int[] steps = [.. checks];

            // Re-stepped as the trunk turns in place on stairs, a foot may stand turned along a tread.
            bool fitAcross = _walk.SlowsForSteps && (time < _walk.StartTurn || time > _walk.StartTurn + _walk.WalkTime);

            // A foothold is first looked for within OutOfPlace of where the contact pose holds the foot under the
            // trunk, over the whole time it is held (a spider's foot whose place is over a ledge's drop was set down on
            // the brink under its body, 0.45 L inside its place); where there is none, the nearest one it can hold.
            foreach (bool inPlace in (bool[])[true, false])
            {
                if (Foothold(l, from, to, steps, ground, along, lateral, heading, slope, walkable, fitAcross, inPlace, ref grounded) is Holding found)
                {
                    return found;
                }
            }

            if (grounded is (Vector3 point, Vector3 normal))
            {
                Fail(l, "reaches no foothold it can stand on", mid);
                return new Holding(from, to, point, normal, Settle: false);
            }

            Fail(l, "finds no ground to step on", mid);
            return new Holding(from, to, new Vector3(nominal.X, ground.Y, nominal.Z), Vector3.UnitY, Settle: false);
        }

        /// <summary>
        /// The first of <see cref="FootholdTries"/> foot <paramref name="l"/> can hold from fine step
        /// <paramref name="from"/> to <paramref name="to"/> (see <see cref="Foothold(int, int, int, int)"/>): with
        /// <paramref name="inPlace"/>, only those that stay within <see cref="OutOfPlace"/> of where the contact pose
        /// holds the foot under the trunk at every check, else only the others (the first pass tried those).
        /// <paramref name="grounded"/> is set to the first ground found.
        /// </summary>
        private Holding? Foothold(int l, int from, int to, int[] steps, Vector3 ground, Vector3 along, Vector3 lateral, Vector3 heading, float slope, GroundSlopeTest walkable, bool fitAcross, bool inPlace, ref (Vector3 Point, Vector3 Normal)? grounded)
        {
            RigLimb limb = _model.Limbs[l];
            Dictionary<float, float>? brinks = null; // per shift along, the last share tried there with no ground (made only near a drop)
            foreach ((float share, float shift) in FootholdTries)
            {
                Vector3 column = ground + along + (lateral * share) + (heading * (shift * _step));
                if (At(column, false, ref grounded, out bool noGround) is Holding found)
                {
                    // Set down inward of a spot with no ground (past a ledge's edge, over a hole): nearer that edge,
                    // as near as a foothold is found by halving the way out to it, the foot stands closer to its place.
                    if (brinks is not null && brinks.TryGetValue(shift, out float outer) && outer > share)
                    {
                        float inner = share;
                        for (int k = 0; k < BrinkHalvings; k++)
                        {
                            float middle = 0.5f * (inner + outer);
                            if (At(ground + along + (lateral * middle) + (heading * (shift * _step)), true, ref grounded, out _) is Holding nearer)
                            {
                                (found, inner) = (nearer, middle);
                            }
                            else
                            {
                                outer = middle;
                            }
                        }
                    }

                    return found;
                }

                if (noGround)
                {
                    (brinks ??= [])[shift] = share;
                }
            }

            return null;

            // The foothold at the ground under column, if the foot can hold it (in place as asked, or either way with
            // anyPlace); noGround: no ground the foot could reach there.
            Holding? At(Vector3 column, bool anyPlace, ref (Vector3 Point, Vector3 Normal)? seen, out bool noGround)
            {
                float reach = _stepHeight + (slope * new Vector2(column.X - ground.X, column.Z - ground.Z).Length());
                float top = ground.Y + reach + 0.05f;
                noGround = !_gait._scene.Bvh.Raycast(new Vector3(column.X, top, column.Z), -Vector3.UnitY, (2f * reach) + 0.1f, out RayHit hit)
                    || MathF.Abs(hit.Point.Y - ground.Y) > reach;
                if (noGround
                    || _gait._scene.Surfaces.SurfaceOf(hit.Triangle) < 0
                    || !limb.Filter.Accepts(hit.Normal)
                    || hit.Normal.Y <= 0f
                    || !walkable.Accepts(hit.Normal, heading)
                    || !Reachable(ground, hit.Point, slope))
                {
                    return null;
                }

                seen ??= (hit.Point, hit.Normal);
                if (OnTread(hit.Point, heading, fitAcross) is (Vector3 onTread, Vector3 treadNormal) && (anyPlace || InPlace(l, onTread, steps) == inPlace) && CanHold(l, onTread, treadNormal, steps) is float[] fitted)
                {
                    return new Holding(from, to, onTread, treadNormal, Settle: false, fitted);
                }

                return (anyPlace || InPlace(l, hit.Point, steps) == inPlace) && CanHold(l, hit.Point, hit.Normal, steps) is float[] seed
                    ? new Holding(from, to, hit.Point, hit.Normal, Settle: false, seed)
                    : null;
            }
        }

        /// <summary>Times the way from a foothold found inward of a spot with no ground out to that spot is halved, looking for one nearer the edge (<c>Foothold</c>).</summary>
        private const int BrinkHalvings = 2;

        /// <summary>
        /// True when the ground from <paramref name="ground"/> (the walk's, under the trunk) out to a foothold at
        /// <paramref name="point"/> (world metres, on the level) rises or falls by no more than a step
        /// (<see cref="_stepHeight"/>) plus the walkable grade (<paramref name="slope"/>) between samples every
        /// <see cref="WalkSteering.SampleSpacing"/> across, as the walk's own ground is sampled: a foot walks up a slope or a stair's riser beside the path, not onto a
        /// platform's top beside the floor walked (a spider turning in place at the foot of a 0.6 m face set a foot on
        /// its top, 0.6 m above the floor and above its own hip, the sole tipped 2.7 cm off the ground). Where a
        /// sample finds no ground (a gap stepped across) it is skipped.
        /// </summary>
        private bool Reachable(Vector3 ground, Vector3 point, float slope)
        {
            var across = new Vector2(point.X - ground.X, point.Z - ground.Z);
            int samples = (int)MathF.Ceiling(across.Length() / WalkSteering.SampleSpacing);
            if (samples <= 1)
            {
                return true;
            }

            float top = MathF.Max(ground.Y, point.Y) + _stepHeight + 0.05f;
            float depth = top - MathF.Min(ground.Y, point.Y) + _stepHeight + 0.05f;
            float last = ground.Y;
            float gap = 0f;
            for (int i = 1; i <= samples; i++)
            {
                gap += WalkSteering.SampleSpacing;
                float y;
                if (i == samples)
                {
                    y = point.Y;
                }
                else if (_gait._scene.Bvh.Raycast(new Vector3(ground.X + (across.X * i / samples), top, ground.Z + (across.Y * i / samples)), -Vector3.UnitY, depth, out RayHit hit))
                {
                    y = hit.Point.Y;
                }
                else
                {
                    continue;
                }

                if (MathF.Abs(y - last) > _stepHeight + (slope * gap))
                {
                    return false;
                }

                (last, gap) = (y, 0f);
            }

            return true;
        }

        /// <summary>
        /// True when a foothold of foot <paramref name="l"/> at <paramref name="point"/> (world metres) lies within
        /// <see cref="OutOfPlace"/> rest legs, along the trunk's left, of where the contact pose holds the foot, at each
        /// of the fine steps given (the trunk moves and turns over it).
        /// </summary>
        private bool InPlace(int l, Vector3 point, int[] steps)
        {
            foreach (int i in steps)
            {
                if (_gait._contacts.Places.Off(l, _roots[i], point) > OutOfPlace * _gait._restLeg)
                {
                    return false;
                }
            }

            return true;
        }

        /// <summary>
        /// Where a foot set down at <paramref name="point"/> (world metres, on the level) lies wholly on the flat it is
        /// on, along <paramref name="heading"/> and across it: a stair tread, a step's top. Null where the ground is even
        /// within <see cref="HalfSole"/> of the rest leg either way along and, with <paramref name="fitAcross"/> (a foot
        /// re-stepped as the trunk turns in place at either end of a walk over stairs: it may stand turned along a tread,
        /// 1.6 cm from its nosing before), <see cref="HalfSoleWidth"/> of that
        /// across (the foot fits where it is), or the flat is too short for the sole (the foot is then kept where it
        /// was); otherwise the point moved to the flat's middle, or just far enough for the sole to clear its riser and
        /// its nosing, with the ground's normal there.
        /// </summary>
        private (Vector3 Point, Vector3 Normal)? OnTread(Vector3 point, Vector3 heading, bool fitAcross)
        {
            float half = HalfSole * _gait._restLeg;
            float rise = MathF.Max(0.02f, 0.5f * _stepHeight);
            float? Height(Vector3 p) =>
                _gait._scene.Bvh.Raycast(p + (Vector3.UnitY * (2f * rise)), -Vector3.UnitY, 4f * rise, out RayHit h) && h.Normal.Y > 0f ? h.Point.Y : null;
            bool Flat(Vector3 direction, float along) => Height(point + (direction * along)) is float y && MathF.Abs(y - point.Y) <= rise;

            // How far the sole moves along direction to lie on the flat (0 where it fits, or the flat is too short).
            float Shift(Vector3 direction, float halfLength)
            {
                if (Flat(direction, halfLength) && Flat(direction, -halfLength))
                {
                    return 0f;
                }

                // The flat's extent along direction, from the point, in steps of a tenth of the half sole.
                float step = MathF.Max(0.01f, 0.1f * half);
                float front = 0f;
                while (front < 3f * halfLength && Flat(direction, front + step))
                {
                    front += step;
                }

                float back = 0f;
                while (back < 3f * halfLength && Flat(direction, -(back + step)))
                {
                    back += step;
                }

                return front + back < 2f * halfLength ? 0f : front < halfLength ? front - halfLength : back < halfLength ? halfLength - back : 0f;
            }

            Vector3 side = new(-heading.Z, 0f, heading.X);
            side = side.LengthSquared() > 1e-8f ? Vector3.Normalize(side) : Vector3.UnitX;
            float along = Shift(heading, half);
            float across = fitAcross ? Shift(side, HalfSoleWidth * half) : 0f;
            if (along == 0f && across == 0f)
            {
                return null;
            }

            Vector3 column = point + (heading * along) + (side * across);
            return _gait._scene.Bvh.Raycast(column + (Vector3.UnitY * (2f * rise)), -Vector3.UnitY, 4f * rise, out RayHit hit) && hit.Normal.Y > 0f
                ? (hit.Point, hit.Normal) : null;
        }

        /// <summary>
        /// The angles with which limb <paramref name="l"/> holds <paramref name="point"/> by IK at the second of the
        /// fine steps given, when it holds it at each of them (from its stance angles, in order) with no bone in the
        /// level; <c>null</c> when it cannot.
        /// </summary>
        private float[]? CanHold(int l, Vector3 point, Vector3 normal, int[] steps)
        {
            RigLimb limb = _model.Limbs[l];
            float[] q = Stance(Time(steps[0]) / _walk.Duration);
            float[]? seed = null;
            float[] Seeded(int i, float[] chain)
            {
                float[] trial = (float[])_angles[i].Clone();
                foreach (int d in limb.ChainDofSpan)
                {
                    trial[d] = chain[d];
                }

                return trial;
            }

            foreach (int i in steps)
            {
                float[] trial = Seeded(i, q);

                // A foothold far from where the stances at either end hold this foot (a cruising foot set down under
                // the trunk, a stance's foot planted wide) may not be found from their angles: from the flexion
                // pose's (a bent leg the IK can straighten toward it), at the first check only.
                if (!_gait.Hold(_roots[i], trial, limb, point, normal)
                    && (i != steps[0] || !_gait.Hold(_roots[i], trial = Seeded(i, _model.FlexionPose), limb, point, normal)))
                {
                    return null;
                }

                _rig.Solve(_roots[i], trial, _positions, _rotations);
                if (_gait._collision.LimbCollides(limb, _positions, _rotations, point))
                {
                    return null;
                }

                seed = i == steps[1] ? trial : seed;
                q = trial;
            }

            return seed;
        }

        /// <summary>Checks limb <paramref name="l"/> against the level at every fine step of its free segments in <paramref name="plan"/>, as posed now.</summary>
        private void CheckFree(int l, List<Segment> plan)
        {
            foreach (Free free in plan.OfType<Free>())
            {
                for (int i = free.From; i <= free.To; i++)
                {
                    CheckFree(l, i);
                }
            }
        }

        /// <summary>Reports limb <paramref name="l"/> passing through the level at fine step <paramref name="i"/> (no contact of its own allowed for).</summary>
        private void CheckFree(int l, int i)
        {
            _rig.Solve(_roots[i], _angles[i], _positions, _rotations);
            if (_gait._collision.LimbCollides(_model.Limbs[l], _positions, _rotations, null))
            {
                _colliding[i] = true;
                Fail(l, "passes through the level", i);
            }
        }

        /// <summary>The angles a foot's chain tends to while walking, <paramref name="u"/> of the way along: the start pose's blended into the end pose's.</summary>
        private float[] Stance(float u)
        {
            float w = Smooth(u);
            float[] q = new float[_rig.DofCount];
            for (int d = 0; d < q.Length; d++)
            {
                q[d] = float.Lerp(_start.Angles[d], _end.Angles[d], w);
            }

            return q;
        }

        /// <summary>
        /// Moves limb <paramref name="l"/> through its segments, writing its angles at every fine step; with
        /// <paramref name="checkFree"/>, its free segments are checked against the level as they are written (else the
        /// caller checks them once it has posed them: <see cref="CheckFree(int, List{Segment})"/>).
        /// </summary>
        private void Perform(int l, List<Segment> plan, bool checkFree = true)
        {
            RigLimb limb = _model.Limbs[l];
            var holds = new List<Holding>();
            for (int s = 0; s < plan.Count; s++)
            {
                if (Enough)
                {
                    return; // the run stops (AnimateWithFewer)
                }

                switch (plan[s])
                {
                    case Holding hold:
                        HoldOn(l, hold);
                        holds.Add(hold);
                        break;
                    case Free free:
                        for (int i = free.From; i <= free.To; i++)
                        {
                            float w = free.To > free.From ? Smooth((i - free.From) / (float)(free.To - free.From)) : 1f;
                            foreach (int d in limb.ChainDofSpan)
                            {
                                _angles[i][d] = float.Lerp(free.Start[d], free.End[d], w);
                            }

                            if (checkFree)
                            {
                                CheckFree(l, i);
                            }
                        }

                        break;
                    case Swinging swing:
                        Swing(l, swing, s > 0 ? plan[s - 1] : null, s + 1 < plan.Count ? plan[s + 1] : null);
                        break;
                }
            }

            // Each hold is a contact phase, from the first fine step to the last when the effector is within Touch of
            // its point (the swings around it leave and reach it gradually), but no further than halfway through the
            // swings either side: a re-step shorter than twice Touch (a rat's 1.2 cm shuffle as it turns) leaves one
            // point and reaches the next within Touch of both, and its phases would overlap. Where the foot rolls onto
            // its ball (and back), the hold is phases on the sole and on the ball in turn.
            for (int h = 0; h < holds.Count; h++)
            {
                Holding hold = holds[h];
                int earliest = h > 0 ? ((holds[h - 1].To + hold.From) / 2) + 1 : 0;
                int latest = h + 1 < holds.Count ? (hold.To + holds[h + 1].From) / 2 : _steps;
                int from = hold.From;
                while (from > earliest && Touching(l, from - 1, hold))
                {
                    from--;
                }

                List<(int From, int To, bool OnBall)> runs = Runs(l, hold, out Vector3 ball);
                for (int r = 0; r < runs.Count; r++)
                {
                    (int a, int b, bool onBall) = runs[r];
                    Vector3 point = onBall ? ball : hold.Point;
                    RigLimb touching = onBall ? limb.Ball! : limb;
                    if (r == 0)
                    {
                        a = onBall ? a : from;
                        while (onBall && a > earliest && Near(touching, a - 1, point))
                        {
                            a--;
                        }
                    }
                    else if (Near(touching, a - 1, point))
                    {
                        // From the last step of the run before where this point is held already (the two phases meet).
                        a--;
                    }

                    if (r == runs.Count - 1)
                    {
                        while (b < latest && (onBall ? Near(touching, b + 1, point) : Touching(l, b + 1, hold)))
                        {
                            b++;
                        }
                    }

                    _phases.Add(new ContactPhase(l, point, Time(a), Time(b)) { OnBall = onBall });
                }
            }
        }

        /// <summary>
        /// Foot <paramref name="l"/>'s hold of <paramref name="hold"/> in runs of fine steps on its sole (its contact
        /// point within <see cref="Touch"/> of the hold's) and on its ball (the ball within <see cref="Touch"/> of
        /// <paramref name="ball"/>, where it first stood rolled), and on the sole again from where it is down on its point
        /// to the hold's end; a step on both before that, or on neither (a slip, which the problems already say), stays
        /// in the run it is in. One run on the sole for a foot that never rolls.
        /// </summary>
        private List<(int From, int To, bool OnBall)> Runs(int l, Holding hold, out Vector3 ball)
        {
            ball = hold.Point;
            var runs = new List<(int From, int To, bool OnBall)>();
            RigLimb? rolled = _model.Limbs[l].Ball;
            bool on = false;
            bool known = false;
            int start = hold.From;

            // From where the sole is down on its point to the hold's end (a walk settling on its end stance), the foot
            // is back on its sole; before that, a step with the sole on its point stays in the run it is in (at the
            // first degrees of a roll both the sole and the ball are within Touch of theirs).
            // (Whether the sole is on its point is solved once per step, for both passes.)
            bool[] down = rolled is null ? [] : [.. Enumerable.Range(hold.From, hold.To - hold.From + 1).Select(i => Near(l, i, hold.Point))];
            int flatFrom = hold.To + 1;
            while (rolled is not null && flatFrom > hold.From && down[flatFrom - 1 - hold.From])
            {
                flatFrom--;
            }

            for (int i = hold.From; i <= hold.To && rolled is not null; i++)
            {
                bool onBall = on;
                if (!down[i - hold.From])
                {
                    _rig.Solve(_roots[i], _angles[i], _positions, _rotations);
                    Vector3 at = rolled.EffectorPosition(_positions, _rotations);
                    if (!known && Vector3.Distance(at, hold.Point) < 2f * Vector3.Distance(rolled.EffectorOffset, _model.Limbs[l].EffectorOffset))
                    {
                        (ball, known) = (at, true);
                    }

                    onBall = known && (on || Vector3.Distance(at, ball) <= Touch);
                }
                else if (i >= flatFrom)
                {
                    onBall = false;
                }

                if (onBall != on && i > start)
                {
                    runs.Add((start, i - 1, on));
                    start = i;
                }

                on = onBall;
            }

            runs.Add((start, hold.To, on));
            return runs;
        }

        /// <summary>
        /// True when limb <paramref name="l"/>'s effector lies within <see cref="Touch"/> of <paramref name="hold"/>'s
        /// point at fine step <paramref name="i"/> (<see cref="Near(int, int, Vector3)"/>) and a loaded rig's foot skin,
        /// as the GLB draws it, within <see cref="BodyCollision.SkinDepth"/> of the hold's ground. A swing's first and
        /// last steps count in its contact phase only while the drawn foot touches the ground: a spider's tarsus skin,
        /// blended a fifth with its tibia, is drawn 1.1 cm above the rigid foot, and 0.8 cm more off the ground is a
        /// foot in the air.
        /// </summary>
        private bool Touching(int l, int i, Holding hold)
        {
            RigLimb limb = _model.Limbs[l];
            _rig.Solve(_roots[i], _angles[i], _positions, _rotations);
            return Vector3.Distance(limb.EffectorPosition(_positions, _rotations), hold.Point) <= Touch
                && (!_gait._collision.HasSoleSkin(limb) || _gait._collision.SoleHeight(limb, _positions, _rotations, hold.Point, Vector3.Normalize(hold.Normal)) <= BodyCollision.SkinDepth);
        }

        /// <summary>True when limb <paramref name="l"/>'s effector lies within <see cref="Touch"/> of <paramref name="point"/> at fine step <paramref name="i"/>.</summary>
        private bool Near(int l, int i, Vector3 point) => Near(_model.Limbs[l], i, point);

        /// <summary>True when <paramref name="limb"/>'s effector lies within <see cref="Touch"/> of <paramref name="point"/> at fine step <paramref name="i"/>.</summary>
        private bool Near(RigLimb limb, int i, Vector3 point)
        {
            _rig.Solve(_roots[i], _angles[i], _positions, _rotations);
            return Vector3.Distance(limb.EffectorPosition(_positions, _rotations), point) <= Touch;
        }

        /// <summary>Holds the segment's point by IK at every fine step, sole flat, from the angles the limb has at its first.</summary>
        private void HoldOn(int l, Holding hold)
        {
            RigLimb limb = _model.Limbs[l];
            float[] q = (float[])_angles[hold.From].Clone();
            bool slipped = false;
            Vector3? ball = null;
            for (int i = hold.From; i <= hold.To; i++)
            {
                float[] trial = _angles[i];
                float w = hold.Settle ? Easing.Pull(i - hold.From, hold.To - hold.From) : 0f;
                foreach (int d in limb.ChainDofSpan)
                {
                    trial[d] = float.Lerp(q[d], _end.Angles[d], w);
                }

                // Settling into the walk's end stance, the foot comes down flat as soon as it can (the stance it ends
                // on, which the next move starts from, has it flat); until then, and elsewhere, as Hold tries.
                if ((w > 0f && _gait._sole.Hold(_roots[i], trial, limb, hold.Point, hold.Normal))
                    || _gait.Hold(_roots[i], trial, limb, hold.Point, hold.Normal, ball) || Reseeded(i, trial, limb, hold, q, ball))
                {
                    // Once rolled onto its ball, the foot keeps the ball where it first put it.
                    _rig.Solve(_roots[i], trial, _positions, _rotations);
                    if (ball is null && limb.Ball is RigLimb rolled && Vector3.Distance(limb.EffectorPosition(_positions, _rotations), hold.Point) > Touch)
                    {
                        ball = rolled.EffectorPosition(_positions, _rotations);
                    }
                }
                else
                {
                    foreach (int d in limb.ChainDofSpan)
                    {
                        trial[d] = q[d];
                    }

                    if (!slipped)
                    {
                        slipped = true;
                        Fail(l, "cannot hold its foothold", i);
                    }
                }

                if (!slipped && ball is null && i - hold.From > EaseSteps + 1)
                {
                    EaseIntoHeldJump(limb, hold, i);
                }

                _rig.Solve(_roots[i], trial, _positions, _rotations);
                if (_gait._collision.LimbCollides(limb, _positions, _rotations, hold.Point))
                {
                    _colliding[i] = true;
                    Fail(l, "passes through the level while holding a foothold", i);
                }

                Array.Copy(trial, q, q.Length);
            }
        }

        /// <summary>
        /// Where a held foot's solve at fine step <paramref name="i"/> (in <see cref="_angles"/>) jumps
        /// (<see cref="Jumps"/>), the leg having gone over to another solution holding the same foothold (a user's human
        /// rig's hip twisting as its trunk turns over the planted foot), it is eased into (<see cref="EaseInto"/>), the
        /// foot held flat on its foothold (not rolled onto the ball) at each eased step.
        /// </summary>
        private void EaseIntoHeldJump(RigLimb limb, Holding hold, int i)
        {
            float[] jumped = _angles[i];
            if (!Jumped(limb, jumped, _angles[i - 1], _angles[i - 2]))
            {
                return;
            }

            // Over as many steps as keep each joint under MostBlendTurn a displayed frame where the hold began early
            // enough (the foot pivoting on its foothold over a tenth of a second, not in one frame), else over one frame.
            bool HoldAt(int k, float[] attempt) => _gait.Hold(_roots[k], attempt, limb, hold.Point, hold.Normal);
            int wide = EaseSpan(limb, _angles[i - 1], jumped);
            if (wide <= EaseSteps || i - hold.From <= wide + 1 || !EaseInto(limb, i, k => _angles[k], jumped, HoldAt, hold.Point, wide))
            {
                EaseInto(limb, i, k => _angles[k], jumped, HoldAt, hold.Point);
            }
        }

        /// <summary>
        /// Fine steps over which easing into a solve that jumps from <paramref name="before"/> to
        /// <paramref name="jumped"/> turns no joint of <paramref name="limb"/> more than <see cref="MostBlendTurn"/> a
        /// displayed frame (<see cref="EaseInto"/> draws the steps toward it evenly).
        /// </summary>
        private int EaseSpan(RigLimb limb, float[] before, float[] jumped) =>
            (int)MathF.Ceiling(MostTurn(limb, before, jumped) * Substeps / MostBlendTurn) - 1;

        /// <summary>Holds at fine step <paramref name="i"/> from the hold's known angles, then from the stance angles, when the limb's own fail.</summary>
        private bool Reseeded(int i, float[] trial, RigLimb limb, Holding hold, float[] q, Vector3? ball)
        {
            foreach (float[]? seed in new[] { hold.Seed, hold.Settle ? _end.Angles : Stance(Time(i) / _walk.Duration) })
            {
                if (seed is null)
                {
                    continue;
                }

                float[] attempt = (float[])trial.Clone();
                foreach (int d in limb.ChainDofSpan)
                {
                    attempt[d] = seed[d];
                }

                if (_gait.Hold(_roots[i], attempt, limb, hold.Point, hold.Normal, ball))
                {
                    Array.Copy(attempt, trial, trial.Length);
                    return true;
                }
            }

            return false;
        }

        /// <summary>
        /// True when limb <paramref name="limb"/>, its angles halfway between <paramref name="before"/> (fine step
        /// <paramref name="i"/> − 1) and <paramref name="after"/> (step <paramref name="i"/>) with the trunk halfway too,
        /// as a player shows it between the two, is in the level (away from <paramref name="contact"/>, the point it
        /// leaves or touches down on at either step, when not <c>null</c>).
        /// </summary>
        private bool MidwayCollides(RigLimb limb, int i, float[] before, float[] after, Vector3? contact)
        {
            float[] mid = _midway;
            after.CopyTo(mid, 0);
            foreach (int d in limb.ChainDofSpan)
            {
                mid[d] = float.Lerp(before[d], after[d], 0.5f);
            }

            RootPose previous = _roots[i - 1];
            RootPose now = _roots[i];
            _rig.Solve(new RootPose(Vector3.Lerp(previous.Position, now.Position, 0.5f), Quaternion.Slerp(previous.Rotation, now.Rotation, 0.5f)), mid, _positions, _rotations);
            return _gait._collision.LimbCollides(limb, _positions, _rotations, contact);
        }

        /// <summary>
        /// The contact (<paramref name="contact0"/> left, else <paramref name="contact1"/> reached) within
        /// <see cref="Touch"/> of <paramref name="limb"/>'s effector as last solved, or <c>null</c>; only on short
        /// legs that step faster than <see cref="MinHalfCycle"/> (always <c>null</c> otherwise, nothing computed): a rat's foot lifts a millimetre or two in its
        /// swing's first fine step, and its bones still touch the ground by its contact. Full-size legs lift theirs up
        /// to <see cref="FirstMove"/> at once and do without it (allowed there too, it changed which lift their swings
        /// took, and the desert skeleton's walks cruised lower: 0.796 L on one).
        /// </summary>
        private Vector3? Touched(RigLimb limb, Vector3? contact0, Vector3? contact1)
        {
            if (_halfCycle >= MinHalfCycle)
            {
                return null;
            }

            Vector3 effector = limb.EffectorPosition(_positions, _rotations);
            return contact0 is { } c0 && Vector3.Distance(effector, c0) <= Touch ? c0
                : contact1 is { } c1 && Vector3.Distance(effector, c1) <= Touch ? c1
                : null;
        }

        /// <summary>
        /// Whether <paramref name="ik"/> holds <paramref name="limb"/>'s effector at <paramref name="point"/>, its sole
        /// along <paramref name="normal"/>, at fine step <paramref name="i"/> from <paramref name="trial"/>, with no
        /// joint of the chain turning faster than <see cref="MaxJointTurn"/> from <paramref name="before"/> (the fine
        /// step before), nor faster than <see cref="SwingTurnFloor"/> and <see cref="SwingTurnRatio"/> times its turn
        /// from <paramref name="earlier"/> (the fine step before that, when the swing has one) to <paramref name="before"/>: true leaves the angles solved in <paramref name="trial"/>, false leaves it as it was; the first
        /// solve that holds the foot but turns a joint faster is kept in <see cref="_held"/> (<paramref name="kept"/>
        /// set), to be taken when no solve holds smoothly.
        /// </summary>
        private bool Smoothly(LimbIk ik, int i, float[] trial, float[] before, float[]? earlier, RigLimb limb, Vector3 point, Vector3 normal, ref bool kept)
        {
            float[] seed = _seed;
            Array.Copy(trial, seed, trial.Length);
            if (!ik.Reaches(_roots[i], trial, limb, point, normal))
            {
                return false;
            }

            foreach (int j in limb.ChainSpan)
            {
                if (Jumps(j, _rig.JointTurn(j, trial, before), before, earlier))
                {
                    if (!kept)
                    {
                        Array.Copy(trial, _held, trial.Length);
                        kept = true;
                    }

                    Array.Copy(seed, trial, trial.Length);
                    return false;
                }
            }

            return true;
        }

        /// <summary>
        /// True when joint <paramref name="joint"/> turning <paramref name="turn"/> (radians) in the fine step after
        /// <paramref name="before"/> jumps: past <see cref="MaxJointTurn"/>, or faster than <see cref="SwingTurnFloor"/>
        /// and <see cref="SwingTurnRatio"/> times its turn in the step from <paramref name="earlier"/> (when there is one)
        /// to <paramref name="before"/>.
        /// </summary>
        private bool Jumps(int joint, float turn, float[] before, float[]? earlier) =>
            turn > MaxJointTurn * _h
            || (earlier is not null && turn > SwingTurnFloor * _h && turn > SwingTurnRatio * _rig.JointTurn(joint, before, earlier));

        /// <summary>
        /// Eases <paramref name="limb"/> into a solve that jumps at fine step <paramref name="i"/>
        /// (<paramref name="jumped"/>, the only one holding its curve or foothold there): the <paramref name="steps"/>
        /// fine steps before it (<see cref="EaseSteps"/> unless the caller asks for more; angles
        /// <paramref name="anglesAt"/>) are solved again by <paramref name="holdAt"/>, each from its own angles drawn
        /// toward <paramref name="jumped"/> by its share of the way, so that the leg changes solution over a displayed
        /// frame or more instead of between two fine steps (a panda's upper arm reaching its 90° limit
        /// along a swing, its hand then turning 42° in 1/240 s). Kept only when every one of them holds, its effector
        /// within <see cref="Touch"/> of <paramref name="foothold"/> (a held foot's; <c>null</c> for a swing), the limb
        /// clear of the level at and between the steps, and no joint then turns even half as far in a fine step as in
        /// the jump (over more steps than <see cref="EaseSteps"/>, none faster than <see cref="BlendLimit"/> allows); else
        /// the steps stay as they were. The caller makes sure the steps exist (after the segment's first fine step and the
        /// one before the eased ones). True when it eased.
        /// </summary>
        private bool EaseInto(RigLimb limb, int i, Func<int, float[]> anglesAt, float[] jumped, Func<int, float[], bool> holdAt, Vector3? foothold, int steps = EaseSteps)
        {
            float jump = MostTurn(limb, anglesAt(i - 1), jumped);
            var solved = new float[steps][];
            float[] previous = anglesAt(i - steps - 1);
            float worst = 0f;
            for (int m = 1; m <= steps; m++)
            {
                int j = i - steps - 1 + m;
                float[] attempt = (float[])anglesAt(j).Clone();
                float share = m / (float)(steps + 1);
                foreach (int d in limb.ChainDofSpan)
                {
                    attempt[d] = float.Lerp(attempt[d], jumped[d], share);
                }

                if (!holdAt(j, attempt))
                {
                    return false;
                }

                _rig.Solve(_roots[j], attempt, _positions, _rotations);
                if ((foothold is { } point && Vector3.Distance(limb.EffectorPosition(_positions, _rotations), point) > Touch)
                    || _gait._collision.LimbCollides(limb, _positions, _rotations, foothold) || MidwayCollides(limb, j, previous, attempt, foothold))
                {
                    return false;
                }

                worst = MathF.Max(worst, MostTurn(limb, previous, attempt));
                previous = attempt;
                solved[m - 1] = attempt;
            }

            // Eased over more than a frame, no faster than the eye allows a frame in any fine step, or than the leg's
            // own fastest step there by more than an even share of the jump (as Unsnap).
            worst = MathF.Max(worst, MostTurn(limb, previous, jumped));
            if (worst >= 0.5f * jump || (steps > EaseSteps && worst > BlendLimit(limb, anglesAt, i - steps - 1, i - 1, jump / (steps + 1))) || MidwayCollides(limb, i, previous, jumped, foothold))
            {
                return false;
            }

            for (int m = 1; m <= steps; m++)
            {
                float[] angles = anglesAt(i - steps - 1 + m);
                foreach (int d in limb.ChainDofSpan)
                {
                    angles[d] = solved[m - 1][d];
                }
            }

            return true;
        }

        /// <summary>Whether any joint of <paramref name="limb"/>'s chain jumps from <paramref name="before"/> to <paramref name="after"/> (<see cref="Jumps"/>).</summary>
        private bool Jumped(RigLimb limb, float[] after, float[] before, float[]? earlier)
        {
            foreach (int j in limb.ChainSpan)
            {
                if (Jumps(j, _rig.JointTurn(j, after, before), before, earlier))
                {
                    return true;
                }
            }

            return false;
        }

        /// <summary>
        /// Blends a swinging <paramref name="limb"/> across a solve that jumped to another solution of the leg between
        /// fine steps <paramref name="from"/> and <paramref name="to"/> of the swing from <paramref name="a"/> to
        /// <paramref name="b"/> (angles <paramref name="keys"/>, by step from <paramref name="a"/>; the steps between
        /// the two, if any, eased into the new solution over a displayed frame, <see cref="EaseInto"/>): the jump, less
        /// the leg's own motion either side of it, is spread over the steps around it along a smoothstep (an offset
        /// blend: the steps before drawn toward the new solution, those after away from it toward the old), over as many
        /// steps as keep every joint under <see cref="MostBlendTurn"/> a displayed frame, within the swing (its
        /// lift-off and touch-down steps stay as they are). The foot leaves its curve a little while the leg turns from
        /// one solution to the other in the air. One displayed frame is too short for a jump the eye sees: a skeleton's
        /// hip whose rotation reached its limit mid-swing on the desert turned 52° between two frames of 4°. Kept only
        /// when every step blended is clear of the level, and between steps, and no joint turns faster in any fine step
        /// of it than <see cref="BlendLimit"/> allows; false otherwise, the steps as they were.
        /// </summary>
        private bool Unsnap(RigLimb limb, int a, int b, float[][] keys, int from, int to)
        {
            float[] before = keys[from - a];
            float[] after = keys[to - a];
            float jump = MostTurn(limb, before, after);
            float perStep = MostBlendTurn / Substeps;
            int gap = to - from;
            if (!(jump > gap * perStep))
            {
                return false;
            }

            // The jump less the leg's own motion (the mean of the steps either side, over the gap).
            ReadOnlySpan<int> dofs = limb.ChainDofSpan;
            var offset = new float[dofs.Length];
            for (int k = 0; k < dofs.Length; k++)
            {
                int d = dofs[k];
                float own = 0f;
                int sides = 0;
                if (from > a)
                {
                    own += before[d] - keys[from - a - 1][d];
                    sides++;
                }

                if (to < b)
                {
                    own += keys[to - a + 1][d] - after[d];
                    sides++;
                }

                offset[k] = after[d] - before[d] - (sides > 0 ? gap * own / sides : 0f);
            }

            // A smoothstep over n steps turns at most 1.5/n of the way in one: n so that is perStep, around the jump as
            // the swing leaves room (steps a + 1 to b − 1 may change).
            int span = Math.Min(Math.Max((int)MathF.Ceiling(1.5f * jump / perStep), gap + 1), b - a - 1);
            int first = Math.Max(a + 1, ((from + to) / 2) - (span / 2));
            int last = Math.Min(b - 1, first + span - 1);
            first = Math.Max(a + 1, last - span + 1);
            if (first > from + 1 || last < to - 1 || (first > from && last < to))
            {
                return false; // the window must hold the steps eased into the jump and one step beside it
            }

            // Blended copies of the steps first..last, checked before any is kept: each the leg's own motion (the
            // steps before the jump; those after it less the jump; between the two, the way from one to the other)
            // plus its smoothstep share of the jump.
            var blended = new float[last - first + 1][];
            for (int j = first; j <= last; j++)
            {
                float w = Easing.Smooth((j - first + 1) / (float)(last - first + 2));
                float[] angles = (float[])keys[j - a].Clone();
                for (int k = 0; k < dofs.Length; k++)
                {
                    int d = dofs[k];
                    float own = j <= from ? keys[j - a][d]
                        : j >= to ? keys[j - a][d] - offset[k]
                        : float.Lerp(before[d], after[d] - offset[k], (j - from) / (float)gap);
                    angles[d] = own + (offset[k] * w);
                }

                _rig.Clamp(angles);
                blended[j - first] = angles;
            }

            // No step turns faster than the eye allows a frame, or than the leg's own fastest step around the jump by
            // more than the blend's steepest share (BlendLimit: a swing under way turns fast on its own).
            float fastest = MathF.Max(BlendLimit(limb, k => keys[k - a], first - 1, from, 1.5f * perStep), BlendLimit(limb, k => keys[k - a], to, last + 1, 1.5f * perStep));
            float[] previous = keys[first - a - 1];
            for (int j = first; j <= last + 1; j++)
            {
                float[] angles = j <= last ? blended[j - first] : keys[j - a];
                if (MostTurn(limb, previous, angles) > fastest)
                {
                    return false;
                }

                // Clear of the level with no contact excused, at each step and between steps, the touch-down's too: the
                // swing's own checks excuse the foothold's bones next to it, but a blend may bring the foot down
                // early (a desert walk's foot in a dune 2 ms before its touch-down).
                _rig.Solve(_roots[j], angles, _positions, _rotations);
                if ((j <= last && _gait._collision.LimbCollides(limb, _positions, _rotations, null)) || MidwayCollides(limb, j, previous, angles, null))
                {
                    return false;
                }

                previous = angles;
            }

            for (int j = first; j <= last; j++)
            {
                foreach (int d in dofs)
                {
                    keys[j - a][d] = blended[j - first][d];
                }
            }

            return true;
        }

        /// <summary>
        /// Fastest (radians a fine step) a joint of <paramref name="limb"/> may turn in a blend or wide ease over the
        /// fine steps <paramref name="from"/> to <paramref name="to"/> (angles <paramref name="anglesAt"/>): what the eye
        /// allows a frame (<see cref="SwingTurnFloor"/>, below which no turn counts as a jump), or the leg's own fastest step there plus
        /// <paramref name="share"/>, the blend's steepest share of the jump (a swing under way turns fast on its own).
        /// </summary>
        private float BlendLimit(RigLimb limb, Func<int, float[]> anglesAt, int from, int to, float share)
        {
            float own = 0f;
            for (int j = from + 1; j <= to; j++)
            {
                own = MathF.Max(own, MostTurn(limb, anglesAt(j - 1), anglesAt(j)));
            }

            return MathF.Max(SwingTurnFloor * _h, own + share);
        }

        /// <summary>
        /// Most a leg's joint turns in a displayed frame (radians, 10°) while <see cref="Unsnap"/> blends it across a
        /// solve that jumped, or <see cref="EaseInto"/> eases a held foot's leg into one over more than a frame: two
        /// thirds of the turn the eye sees snap (15°).
        /// </summary>
        private const float MostBlendTurn = 10f * MathF.PI / 180f;

        /// <summary>Fine steps over which a leg eases into a solve that jumps (<see cref="EaseInto"/>): one displayed frame's.</summary>
        private const int EaseSteps = Substeps;

        /// <summary>The most (radians) any joint of <paramref name="limb"/>'s chain turns from <paramref name="from"/> to <paramref name="to"/>.</summary>
        private float MostTurn(RigLimb limb, float[] from, float[] to)
        {
            float most = 0f;
            foreach (int j in limb.ChainSpan)
            {
                most = MathF.Max(most, _rig.JointTurn(j, from, to));
            }

            return most;
        }

        /// <summary>
        /// How far (metres, along its normal) the foot touching down on <paramref name="target"/> at fine step
        /// <paramref name="b"/> from <paramref name="seed"/> will be held above its point: a loaded rig's foot is held
        /// higher where its skin would sink (<see cref="WalkGait.Hold"/>), so its swing comes down there, not to the point
        /// its skin would sink from. 0 for a foot without skin, or one that cannot hold the point.
        /// </summary>
        private float Raised(RigLimb limb, int b, float[] seed, Holding target)
        {
            if (!_gait._collision.HasSoleSkin(limb))
            {
                return 0f;
            }

            // In _along, which the touch-down's own solve fills again later.
            float[] q = _along;
            _angles[b].CopyTo(q, 0);
            foreach (int d in limb.ChainDofSpan)
            {
                q[d] = seed[d];
            }

            if (!_gait.Hold(_roots[b], q, limb, target.Point, target.Normal))
            {
                return 0f;
            }

            // Above the IK's own tolerance only: a foot held on its point is not lifted by the solve's error.
            _rig.Solve(_roots[b], q, _positions, _rotations);
            float raised = Vector3.Dot(limb.EffectorPosition(_positions, _rotations) - target.Point, Vector3.Normalize(target.Normal));
            return raised > _gait._sole.Flat.Settings.PositionTolerance ? raised : 0f;
        }

        /// <summary>
        /// A swing from the limb's state at its first fine step (holding a point, or free) to the next segment's state
        /// at its last: the effector on a lifted curve, the sole turning from one ground to the next where the leg can
        /// keep it so, the limb's angles drawn toward its stance angles; raised until no bone touches the level.
        /// </summary>
        private void Swing(int l, Swinging swing, Segment? previous, Segment? next)
        {
            RigLimb limb = _model.Limbs[l];
            int a = swing.From;
            int b = swing.To;
            float[] startAngles = (float[])_angles[a].Clone();
            _rig.Solve(_roots[a], startAngles, _positions, _rotations);
            Vector3 p0 = limb.EffectorPosition(_positions, _rotations);
            Vector3 n0 = limb.EffectorNormal(_rotations);
            Vector3? contact0 = null;
            Vector3 ground0 = Vector3.UnitY;
            if (previous is Holding held)
            {
                // From where the foot is: on its hold, or rolled onto its ball there.
                (contact0, ground0) = (held.Point, held.Normal);
                if (Vector3.Distance(p0, held.Point) <= 2f * _gait._sole.Flat.Settings.PositionTolerance)
                {
                    // On the point, at the height the hold left it (held higher where its skin would sink: Hold).
                    (p0, n0) = (held.Point + (held.Normal * MathF.Max(0f, Vector3.Dot(p0 - held.Point, held.Normal))), -held.Normal);
                }
            }

            float[] endAngles;
            Vector3 p1;
            Vector3 n1;
            Vector3? contact1 = null;
            Vector3 ground1 = Vector3.UnitY;
            if (next is Holding target)
            {
                (p1, n1, contact1, ground1) = (target.Point, -target.Normal, target.Point, target.Normal);
                endAngles = target.Seed ?? (target.Settle ? _end.Angles : Stance(Time(b) / _walk.Duration));
                p1 += target.Normal * Raised(limb, b, endAngles, target);
            }
            else
            {
                endAngles = next is Free free ? free.Start : _end.Angles;
                float[] q = (float[])_angles[b].Clone();
                foreach (int d in limb.ChainDofSpan)
                {
                    q[d] = endAngles[d];
                }

                _rig.Solve(_roots[b], q, _positions, _rotations);
                p1 = limb.EffectorPosition(_positions, _rotations);
                n1 = limb.EffectorNormal(_rotations);
            }

            Vector3 up = Vector3.Normalize(ground0 + ground1);

            float[][]? best = null;
            int bestFailures = int.MaxValue;
            int pool = 0;
            var jumps = new List<(int From, int To)>();
            var bestJumps = new List<(int From, int To)>();
            foreach (float share in Lifts)
            {
                // Each try's angles go into one of two reused pools, the best try's kept in the other.
                float[][] keys = SwingPool(pool, b - a + 1);
                // Straight up off the ground, straight down onto it (SwingCurve); its time warped (slower at both
                // ends) so that the effector moves at most FirstMove in the swing's first and last fine steps: still
                // touching then, and already clear of the ground.
                var curve = new SwingCurve(p0, p1, up, share * _stepHeight);
                Vector3 Curve(float s) => curve.At(s);
                float Warp(float tau, float slow) => tau - (slow * MathF.Sin(2f * MathF.PI * tau) / (2f * MathF.PI));
                float first = 1f / (b - a);
                float slow = 0f;
                while (slow < 0.99f && MathF.Max(Vector3.Distance(Curve(Warp(first, slow)), p0), Vector3.Distance(Curve(Warp(1f - first, slow)), p1)) > FirstMove)
                {
                    slow += 0.03f;
                }
                float[] q = startAngles;
                int failures = 0;
                bool onCurve = true;
                jumps.Clear();

                // The sole held flat on the curve at fine step k, else along its normal (as each step below tries).
                bool ReachesCurve(int k, float[] attempt)
                {
                    float along = Warp((k - a) / (float)(b - a), slow);
                    Vector3 point = Curve(along);
                    Vector3 normal = Vector3.Normalize(Vector3.Lerp(n0, n1, Smooth(along)));
                    return _gait._sole.Flat.Reaches(_roots[k], attempt, limb, point, normal) || _gait._swingIk.Reaches(_roots[k], attempt, limb, point, normal);
                }

                for (int i = a; i <= b; i++)
                {
                    float s = Warp((i - a) / (float)(b - a), slow);
                    float[] trial = keys[i - a];
                    _angles[i].CopyTo(trial, 0);
                    float w = Easing.Pull(i - a, b - a);
                    foreach (int d in limb.ChainDofSpan)
                    {
                        trial[d] = float.Lerp(q[d], endAngles[d], w);
                    }

                    if (i == b && contact1 is not null)
                    {
                        // Touch-down exactly on the foothold: from the angles of the step before when the leg can (no
                        // jump to another IK solution between the two), else from the foothold's.
                        Vector3 n = Vector3.Normalize(n1);
                        float[] along = _along;
                        trial.CopyTo(along, 0);
                        foreach (int d in limb.ChainDofSpan)
                        {
                            along[d] = q[d];
                        }

                        bool solved = _gait.Hold(_roots[i], along, limb, p1, -n);
                        if (solved)
                        {
                            along.CopyTo(trial, 0);
                        }
                        else
                        {
                            solved = _gait.Hold(_roots[i], trial, limb, p1, -n);
                        }

                        failures += solved ? 0 : 1;
                        if (solved && Jumped(limb, trial, q, i - a >= 2 ? keys[i - a - 2] : null))
                        {
                            jumps.Add((i - 1, i));
                        }
                    }
                    else if (i > a && i < b && onCurve)
                    {
                        // On the lifted curve while the leg reaches it; from the first point it does not (the trunk
                        // turning or slowing under it), the angles go straight on toward the foothold's.
                        Vector3 p = Curve(s);
                        Vector3 n = Vector3.Normalize(Vector3.Lerp(n0, n1, Smooth(s)));

                        // The sole held flat, else along the curve's normal: the first solve that turns no joint faster
                        // than MaxJointTurn from the step before (nor suddenly faster), else the first that holds, eased
                        // into over the frame before where the leg can (EaseInto); else the sole left free.
                        bool kept = false;
                        float[]? earlier = i - a >= 2 ? keys[i - a - 2] : null;
                        onCurve = Smoothly(_gait._sole.Flat, i, trial, q, earlier, limb, p, n, ref kept) || Smoothly(_gait._swingIk, i, trial, q, earlier, limb, p, n, ref kept);
                        if (!onCurve && kept)
                        {
                            Array.Copy(_held, trial, trial.Length);
                            onCurve = true;

                            // The step before the eased ones is not the lift-off's own (its contact is checked apart).
                            bool eased = i - a > EaseSteps + 1 && EaseInto(limb, i, k => keys[k - a], trial, ReachesCurve, null);
                            jumps.Add((eased ? i - EaseSteps - 1 : i - 1, i));
                        }
                        else if (!onCurve)
                        {
                            // Neither sole holds the curve: the effector alone on it.
                            onCurve = _gait._swingIk.Reaches(_roots[i], trial, limb, p, null);
                            if (onCurve && Jumped(limb, trial, q, earlier))
                            {
                                jumps.Add((i - 1, i));
                            }
                        }
                    }

                    _rig.Solve(_roots[i], trial, _positions, _rotations);
                    // An effector still or already within Touch of its contact touches it (a swing's first and last
                    // moments count in the contact phases around it): on short legs its bones may touch the ground
                    // there, as on the contact itself (Touched).
                    Vector3? touched = Touched(limb, contact0, contact1);
                    Vector3? near = i == a ? contact0 : i == b ? contact1 : touched;
                    Vector3? nearBefore = i - 1 == a ? contact0 : i == b ? contact1 : touched;
                    if (_gait._collision.LimbCollides(limb, _positions, _rotations, near))
                    {
                        failures++;
                    }
                    else if (i > a && MidwayCollides(limb, i, q, trial, nearBefore))
                    {
                        // Played between the two steps (angles interpolated), the limb must be clear too.
                        failures++;
                    }

                    q = trial;
                }

                if (failures < bestFailures)
                {
                    bestFailures = failures;
                    best = keys;
                    pool = 1 - pool;
                    bestJumps.Clear();
                    bestJumps.AddRange(jumps);
                }

                if (failures == 0)
                {
                    break;
                }
            }

            // Each solve of the try kept that jumped to another solution of the leg (eased into over a frame or not),
            // blended across over the steps around it where the leg can (Unsnap; it changes no try's failures, so it
            // waits for the one kept).
            foreach ((int from, int to) in bestJumps)
            {
                Unsnap(limb, a, b, best!, from, to);
            }

            for (int i = a; i <= b; i++)
            {
                foreach (int d in limb.ChainDofSpan)
                {
                    _angles[i][d] = best![i - a][d];
                }
            }

            if (bestFailures > 0)
            {
                for (int i = a; i <= b; i++)
                {
                    _rig.Solve(_roots[i], _angles[i], _positions, _rotations);
                    if (_gait._collision.LimbCollides(limb, _positions, _rotations, i == a ? contact0 : i == b ? contact1 : null))
                    {
                        _colliding[i] = true;
                    }
                }

                Fail(l, "cannot swing to its next foothold within reach and clear of the level", a);
            }
        }
    }
}
