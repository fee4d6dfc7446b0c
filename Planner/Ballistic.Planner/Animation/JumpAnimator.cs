using System.Numerics;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;

namespace Ballistic.Planner.Animation;

/// <summary>
/// Turns a planned path into a whole-body animation (paper §5): contact poses at takeoff and landing, each limb
/// keeping its contact by IK while the root moves along the arc until the IK fails (takeoff) or from the moment it
/// succeeds (landing), an extended pose at the apex, and per-angle interpolation between these key poses for each
/// limb, re-sampling a limb's apex pose when it would pass through the level. The root stays on the parabola in
/// flight. On the ground the body crouches before every takeoff and absorbs every landing (<see cref="StanceDip"/>:
/// the root sinks and rises on held contacts, at least <see cref="StanceDip.MinGroundTime"/> between a landing and the
/// next takeoff); when the landing contacts cannot push off for the next jump, the body stands up after absorbing,
/// the limbs whose contacts change step to the new ones one at a time (a swing of
/// <see cref="StepDuration"/> with the foot lifted clear) while the others hold. Whatever cannot be done cleanly
/// (no contact pose passing the no-slip test, a bone through the level) is reported per jump in
/// <see cref="JumpAnimation.Problems"/>, never hidden.
/// </summary>
public sealed class JumpAnimator : IJumpAnimator, IStepwiseAnimator
{
    /// <summary>Duration of one limb's step between two jumps, seconds.</summary>
    public const float StepDuration = 0.3f;

    private const int MaxResamples = 64;

    /// <summary>
    /// Share of the way from letting go to the apex (and from the apex to taking hold) over which a limb that would
    /// otherwise pass through the level moves to its flight pose (and from it): a quick retraction.
    /// </summary>
    private const float Retract = 0.25f;

    /// <summary>
    /// A limb that passes the apex within this share of its time in the air from letting go or from taking hold (or
    /// is in the air on one side of the apex only) steps across from its takeoff to its landing contact instead of
    /// reaching its flight pose (<see cref="StepAcross"/>).
    /// </summary>
    private const float AcrossShare = 0.25f;

    /// <summary>Heights (metres) the effector is lifted by at mid-step, tried in order until the swing is clear.</summary>
    private static readonly float[] StepLifts = [0.06f, 0.12f, 0.2f];

    /// <summary>Least time (seconds) a limb spends in the air between letting go of one contact point and taking another.</summary>
    public const float MinAirTime = 0.1f;

    /// <summary>Contact phases are stepped this many times finer than the frame rate, so that held contacts do not slide between frames.</summary>
    private const int ContactSubsteps = 4;

    /// <summary>
    /// Fastest (radians per second, 900°/s) a limb's joint turns while it holds its takeoff contact into the flight or
    /// takes its landing contact before it (<see cref="Hold"/>): a soft landing folds the knee 60–90° over 0.2–0.5 s,
    /// about twice that at its fastest. A limb that would turn faster to stay on its contact (the body already moving
    /// at the flight's speed) lets go (takes hold) there instead: held on, it turned as far as a frame's 15° in a
    /// hundredth of a second.
    /// </summary>
    internal const float MostHeldTurnRate = 900f * MathF.PI / 180f;

    /// <summary>Earliest and latest share of the flight at which its apex pose is keyed.</summary>
    private const float ApexKeyShare = 0.3f;

    /// <summary>Farthest (metres) a limb may stand from the contact the plan reports for it when a push is checked (<see cref="CanPush"/>).</summary>
    private const float ReportedFoothold = 0.25f;

    /// <summary>A jump's contact held farther than this (metres) from the planner's estimate is reported where it is held (<see cref="HeldStances"/>).</summary>
    private const float MovedFoothold = 0.1f;

    /// <summary>How close (metres) the uses of one stance hold a moved contact for it to be reported there (<see cref="HeldStances"/>), and how far off its surface the point is looked for.</summary>
    private const float HeldTogether = 0.01f;

    private readonly ContactGenerator _contacts;
    private readonly LimbIk _holdIk;
    private readonly BodyCollision _collision;
    private readonly int _requiredContacts;
    private readonly WalkGait _gait;
    private readonly HoldRefiner _refiner;
    private readonly StanceDip _dip;
    private readonly FreeBones _free;

    /// <summary>How high (metres) a foot leaving its takeoff contact is lifted straight off it (<see cref="LiftOff"/>): the character's step height.</summary>
    private readonly float _liftHeight;

    private readonly PlanningScene _scene;

    /// <summary>Creates an animator for a character model on a planning scene of its reduced model.</summary>
    public JumpAnimator(PlanningScene scene, CharacterModel model)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(model);
        _contacts = new ContactGenerator(scene, model);
        _holdIk = new LimbIk(model.Rig, new IkSettings { Restarts = 0, MaxIterations = 12 });
        _collision = _contacts.Collision;
        _requiredContacts = scene.Character.RequiredContacts;
        _gait = new WalkGait(scene, model, _contacts);
        _refiner = new HoldRefiner(model, _collision);
        _free = _gait.FreeBones;
        _dip = new StanceDip(model, new LimbIk(model.Rig, new IkSettings { Restarts = 0, MaxIterations = 24 }), _collision, _free, _contacts.Places);
        _liftHeight = scene.Character.StepReach;
        _scene = scene;
        Model = model;
    }

    /// <summary>The character.</summary>
    public CharacterModel Model { get; }

    /// <summary>The contact generator (its databases and collision checks).</summary>
    internal ContactGenerator Contacts => _contacts;

    /// <inheritdoc />
    /// <remarks>
    /// The contact pose's limbs are kept clear of the level by the contact generator; the bones of no limb (the links
    /// from the chest to the shoulders, the spine, head and a tail bent clear where it can be) are checked here: a
    /// quadruped standing on a tread facing up a flight has its chest in the riser ahead.
    /// </remarks>
    public bool CanStand(PoseEvaluation pose)
    {
        ArgumentNullException.ThrowIfNull(pose);
        ContactConfiguration stance = _contacts.Generate(pose.Pose, pose.Contacts, pose.Cone.Axis);
        if (stance.Contacts.Count < Math.Min(_requiredContacts, Model.Limbs.Count))
        {
            return false;
        }

        var positions = new Vector3[Model.Rig.Joints.Count];
        var rotations = new Quaternion[Model.Rig.Joints.Count];
        return _free.Colliding(stance.Root, stance.Angles, positions, rotations).Bone < 0;
    }

    /// <inheritdoc />
    /// <remarks>
    /// The contact pose a jump's animation takes off (lands) on, each limb on its reported contact first: valid, and
    /// every limb the plan puts on a contact within <see cref="ReportedFoothold"/> of it.
    /// </remarks>
    public bool CanPush(RootPose root, IReadOnlyList<Contact> contacts, Vector3 velocity)
    {
        ArgumentNullException.ThrowIfNull(contacts);
        ContactConfiguration pose = _contacts.Generate(root, contacts, velocity, 0f, onEstimates: true);
        if (!pose.Valid)
        {
            return false;
        }

        foreach (Contact c in contacts)
        {
            if (pose.ContactOf(c.Limb) is not LimbContact held || Vector3.Distance(held.Position, c.Position) > ReportedFoothold)
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>
    /// Animates the moves at <paramref name="frameRate"/> frames per second: jumps as flights between contact poses,
    /// walks with a gait (<see cref="WalkGait"/>) from where the previous move left the feet to the contact pose the
    /// next one needs. Frames during a walk and on the ground around a jump come at every fine step
    /// (<see cref="ContactSubsteps"/> per frame interval) since feet hold contacts throughout. The animation's
    /// <see cref="JumpAnimation.Moves"/> are the moves as animated: walks slowed where their steps shorten, and each
    /// jump's takeoff and landing stance without an estimated contact the animation cannot hold.
    /// </summary>
    /// <exception cref="ArgumentException">No moves, a null move, or a non-positive frame rate.</exception>
    public JumpAnimation Animate(IReadOnlyList<Move> moves, float frameRate = 60f)
    {
        Check(moves, frameRate);
        return Stepwise.Last(Steps(moves, frameRate));
    }

    /// <inheritdoc />
    IEnumerable<JumpAnimation?> IStepwiseAnimator.AnimateSteps(IReadOnlyList<Move> moves, float frameRate)
    {
        Check(moves, frameRate);
        return Steps(moves, frameRate);
    }

    /// <summary>Refuses what <see cref="Animate"/> cannot animate.</summary>
    private static void Check(IReadOnlyList<Move> moves, float frameRate)
    {
        ArgumentNullException.ThrowIfNull(moves);
        if (moves.Count == 0)
        {
            throw new ArgumentException("There are no moves to animate.", nameof(moves));
        }

        for (int m = 0; m < moves.Count; m++)
        {
            if (moves[m] is not (Jump or Walk))
            {
                throw new ArgumentException($"Move {m} is {(moves[m] is null ? "null" : "of an unknown kind")}.", nameof(moves));
            }
        }

        if (!(frameRate > 0f) || !float.IsFinite(frameRate))
        {
            throw new ArgumentException("The frame rate must be positive.", nameof(frameRate));
        }
    }

    /// <summary><see cref="Animate"/>'s body in steps: a pause after each jump's clip and each walk's gait.</summary>
    private IEnumerable<JumpAnimation?> Steps(IReadOnlyList<Move> moves, float frameRate)
    {
        // Each jump: its contact poses and flight. The landing contacts push off again when they can; a jump after a
        // walk takes off from the contact pose generated for it, which the walk ends on.
        var clips = new Clip?[moves.Count];
        var problems = new List<JumpProblem>();
        var dips = new Dictionary<ContactConfiguration, StanceDip.Table>(ReferenceEqualityComparer.Instance);
        int failed = 0;
        for (int m = 0; m < moves.Count; m++)
        {
            if (moves[m] is not Jump jump)
            {
                continue;
            }

            BallisticArc arc = jump.Arc;
            ContactConfiguration? landed = m > 0 ? clips[m - 1]?.Landing : null;
            Clip clip;
            if (m > 0 && moves[m - 1] is Walk)
            {
                clip = AnimateJump(m, jump, Pose(arc.Takeoff, jump.Takeoff.Contacts, arc.TakeoffVelocity, dips), dips, frameRate);
            }
            else if (landed is { Valid: true } && landed.Cone.Contains(arc.TakeoffVelocity, 1e-3f))
            {
                clip = AnimateJump(m, jump, landed, dips, frameRate);
                if (clip.Problems.Count > 0)
                {
                    Clip fresh = AnimateJump(m, jump, null, dips, frameRate);
                    clip = fresh.Problems.Count < clip.Problems.Count ? fresh : clip;
                }
            }
            else
            {
                clip = AnimateJump(m, jump, null, dips, frameRate);
            }

            failed += (clip.Takeoff.Valid ? 0 : 1) + (clip.Landing.Valid ? 0 : 1);
            problems.AddRange(clip.Problems);
            clips[m] = clip;
            yield return null;
        }

        // Each walk: from the previous move's landing (or walk's end) pose, or the first stance's, to the next jump's
        // takeoff pose, or the last stance's.
        var walks = new WalkGait.Clip?[moves.Count];
        Move[] animated = [.. moves];
        ContactConfiguration? left = null;
        for (int m = 0; m < moves.Count; m++)
        {
            if (moves[m] is not Walk walk)
            {
                left = clips[m]!.Landing;
                continue;
            }

            ContactConfiguration start = left ?? Stand(m, walk.From, "start", problems);
            ContactConfiguration end = m + 1 < moves.Count && clips[m + 1] is Clip next ? next.Takeoff : Stand(m, walk.To, "end", problems);
            WalkGait.Clip walked = _gait.Animate(m, walk, start, end, frameRate);
            problems.AddRange(walked.Problems);
            walks[m] = walked;
            animated[m] = walked.Walked(walk);
            left = end;
            yield return null;
        }

        // A walk whose steps shorten around rough ground slows there (WalkGait), and a jump's stances are those its
        // takeoff and landing stand on: the moves as animated.
        moves = HeldStances(animated, clips);

        // Assemble: moves, and on the ground around each jump its crouch and landing with the steps between them;
        // contact phases along the way.
        var frames = new List<AnimationFrame>();
        var phases = new List<ContactPhase>();
        var stances = new List<float>();
        var open = new Dictionary<int, (Vector3 Position, float From, bool OnBall)>();
        int colliding = 0;
        float clock = 0f;
        float leadIn = 0f;
        float leadOut = 0f;
        for (int m = 0; m < moves.Count; m++)
        {
            if (walks[m] is WalkGait.Clip walked)
            {
                AddWalk(walked, clock, m == 0, frames, phases, open);
                colliding += walked.CollidingFrames;
                clock += moves[m].Duration;
                if (m + 1 < moves.Count)
                {
                    // A jump after a walk: the body crouches on the takeoff contacts the walk ended on.
                    float crouch = clips[m + 1] is Clip after ? Crouch(Dip(after.Takeoff, m + 1, ProblemStance.Takeoff, problems, dips), ((Jump)moves[m + 1]).Arc, clock, frames, 0f, frameRate) : 0f;
                    stances.Add(crouch);
                    clock += crouch;
                }

                continue;
            }

            Jump jump = (Jump)moves[m];
            Clip clip = clips[m]!;
            if (m == 0)
            {
                foreach (LimbContact c in clip.Takeoff.Contacts)
                {
                    open[c.Limb] = (c.Position, 0f, false);
                }

                StanceDip.Table first = Dip(clip.Takeoff, m, ProblemStance.Takeoff, problems, dips);
                frames.Add(new AnimationFrame(0f, first.Root, (float[])clip.Takeoff.Angles.Clone()));
                leadIn = Crouch(first, jump.Arc, 0f, frames, 0f, frameRate);
                clock = leadIn;
            }

            // Takeoff contacts are held until they break; landing contacts are held from when they are made.
            foreach (LimbContact c in clip.Takeoff.Contacts)
            {
                if (open.Remove(c.Limb, out (Vector3 Position, float From, bool OnBall) o))
                {
                    phases.Add(new ContactPhase(c.Limb, o.Position, o.From, clock + clip.Breaks[c.Limb]) { OnBall = o.OnBall });
                }
            }

            foreach ((int limb, (Vector3 position, float from, bool onBall)) in open)
            {
                phases.Add(new ContactPhase(limb, position, from, clock) { OnBall = onBall });
            }

            open.Clear();
            foreach (LimbContact c in clip.Landing.Contacts)
            {
                open[c.Limb] = (c.Position, clock + clip.Makes[c.Limb], false);
            }

            foreach (AnimationFrame f in clip.Frames[1..])
            {
                frames.Add(f with { Time = clock + f.Time });
            }

            colliding += clip.CollidingFrames;
            clock += jump.Arc.FlightTime;
            float landed = clock;
            StanceDip.Table landing = Dip(clip.Landing, m, ProblemStance.Landing, problems, dips);
            float landingSpeed = jump.Arc.LandingVelocity.Length();
            if (m + 1 < moves.Count && clips[m + 1] is Clip following)
            {
                Jump next = (Jump)moves[m + 1];
                if (ReferenceEquals(clip.Landing, following.Takeoff))
                {
                    // Landing flows into the next crouch: sink, hold as long as the ground time asks, drive up.
                    float sink = StanceDip.SinkTime(landing, landingSpeed);
                    float push = StanceDip.PushTime(landing, next.Arc.TakeoffVelocity.Length());
                    clock = Dip(landing, clock, sink, StanceDip.Sink(landing, sink, jump.Arc.LandingVelocity), frames, frameRate);
                    float hold = MathF.Max(StanceDip.MinGroundTime - sink - push, 0.25f * sink);
                    clock = Dip(landing, clock, hold, _ => 1f, frames, frameRate);
                    clock = Dip(landing, clock, push, StanceDip.Push(landing, push, next.Arc.TakeoffVelocity), frames, frameRate);
                }
                else
                {
                    // Absorb, stand, step to the takeoff contacts, crouch on them, drive up.
                    clock = Absorb(landing, jump.Arc.LandingVelocity, clock, frames, frameRate);
                    Stance stance = Restep(m + 1, jump.Arc.Landing, clip.Landing, following.Takeoff, frameRate);
                    problems.AddRange(stance.Problems);
                    foreach ((int limb, float start, LimbContact? step) in stance.Steps)
                    {
                        if (open.Remove(limb, out (Vector3 Position, float From, bool OnBall) o))
                        {
                            phases.Add(new ContactPhase(limb, o.Position, o.From, clock + start) { OnBall = o.OnBall });
                        }

                        if (step is LimbContact c)
                        {
                            open[limb] = (c.Position, clock + start + StepDuration, false);
                        }
                    }

                    foreach (AnimationFrame f in stance.Frames.Skip(1))
                    {
                        frames.Add(f with { Time = clock + f.Time });
                    }

                    clock += stance.Duration;
                    clock += Crouch(Dip(following.Takeoff, m + 1, ProblemStance.Takeoff, problems, dips), next.Arc, clock, frames, StanceDip.MinGroundTime - (clock - landed), frameRate);
                }

                stances.Add(clock - landed);
            }
            else
            {
                // A walk follows, or the clip ends: the landing absorbed and the body standing again.
                clock = Absorb(landing, jump.Arc.LandingVelocity, clock, frames, frameRate);
                if (m + 1 < moves.Count)
                {
                    stances.Add(clock - landed);
                }
                else
                {
                    leadOut = clock - landed;
                }
            }
        }

        foreach ((int limb, (Vector3 position, float from, bool onBall)) in open)
        {
            phases.Add(new ContactPhase(limb, position, from, clock) { OnBall = onBall });
        }

        phases.Sort((a, b) => a.From != b.From ? a.From.CompareTo(b.From) : a.Limb.CompareTo(b.Limb));
        colliding += ClearFreeBones(moves, stances, frames, phases, problems, failed, leadIn, leadOut);

        // Held contacts must hold between frames too, as a player interpolates them.
        var animation = new JumpAnimation(Model, moves, stances, frames, phases, problems, failed, colliding, leadIn, leadOut);
        (List<AnimationFrame> refined, List<(int Limb, float Time)> slips) = _refiner.Refine(animation);
        if (refined.Count == frames.Count && slips.Count == 0)
        {
            problems.Sort((a, b) => a.Jump.CompareTo(b.Jump));
            yield return new JumpAnimation(Model, moves, stances, frames, phases, problems, failed, colliding, leadIn, leadOut);
            yield break;
        }

        foreach ((int limb, float time) in slips.GroupBy(s => s.Limb).Select(g => g.First()))
        {
            int move = Enumerable.Range(0, moves.Count).LastOrDefault(m => animation.MoveStart(m) <= time);
            float along = moves[move] is Walk walk ? walk.DistanceAt(time - animation.MoveStart(move)) : float.NaN;
            problems.Add(new JumpProblem(move, $"{Model.Limbs[limb].Name} cannot hold its contact between frames ({time:0.000} s into the clip)", along));
        }

        problems.Sort((a, b) => a.Jump.CompareTo(b.Jump));
        yield return new JumpAnimation(Model, moves, stances, refined, phases, problems, failed, colliding + slips.Count, leadIn, leadOut);
    }

    /// <summary>
    /// The free chains (a tail) bent out of the level over the whole clip, crouches, landings and re-steps included
    /// (<see cref="FreeBones"/>), then every frame checked for a bone of no limb in the level: the first such frame of
    /// a move not already reported is a problem of that move. Returns how many frames are left colliding that were
    /// not counted before.
    /// </summary>
    private int ClearFreeBones(IReadOnlyList<Move> moves, List<float> stances, List<AnimationFrame> frames, List<ContactPhase> phases, List<JumpProblem> problems, int failed, float leadIn, float leadOut)
    {
        float[] times = [.. frames.Select(f => f.Time)];
        float[][] angles = [.. frames.Select(f => f.Angles)];
        if (_free.Clear(times, k => frames[k].Root, angles) > 0)
        {
            for (int k = 0; k < frames.Count; k++)
            {
                frames[k] = frames[k] with { Angles = angles[k] };
            }
        }

        var timeline = new JumpAnimation(Model, moves, stances, frames, phases, problems, failed, 0, leadIn, leadOut);
        Rig rig = Model.Rig;
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        var reported = new HashSet<int>(problems.Where(p => p.Reason.StartsWith("bone '", StringComparison.Ordinal)).Select(p => p.Jump));
        int colliding = 0;
        for (int k = 0; k < frames.Count; k++)
        {
            rig.Solve(frames[k].Root, frames[k].Angles, positions, rotations);
            int bone = _collision.OtherBoneColliding(positions, rotations);
            if (bone < 0)
            {
                continue;
            }

            int move = Enumerable.Range(0, moves.Count).LastOrDefault(m => timeline.MoveStart(m) <= frames[k].Time);
            if (reported.Add(move))
            {
                colliding++;
                problems.Add(new JumpProblem(move, $"bone '{rig.Joints[bone].Name}' passes through the level {frames[k].Time:0.000} s into the clip"));
            }
        }

        return colliding;
    }

    /// <summary>
    /// The dip of <paramref name="config"/> (<see cref="StanceDip.Solve(ContactConfiguration)"/>); one shallower than
    /// <see cref="StanceDip.LeastDepthShare"/> of the leg is a problem of move <paramref name="move"/>: the body cannot
    /// crouch on its takeoff stance or absorb the landing on its landing stance (<paramref name="stance"/>), and a jump
    /// without its crouch or its landing does not read as a jump. Tables already solved in this animation are in
    /// <paramref name="dips"/>.
    /// </summary>
    private StanceDip.Table Dip(ContactConfiguration config, int move, ProblemStance stance, List<JumpProblem> problems, Dictionary<ContactConfiguration, StanceDip.Table> dips)
    {
        StanceDip.Table table = DipOf(config, dips);
        if (!Deep(config, table))
        {
            string what = stance == ProblemStance.Takeoff ? "crouch before takeoff" : "absorb the landing";
            problems.Add(new JumpProblem(move, $"the body cannot {what} ({table.Depth * 100f:0.0} cm of the {StanceDip.LeastDepthShare * table.Leg * 100f:0.0} cm needed: {table.Stop})") { Stance = stance });
        }

        return table;
    }

    /// <summary>The dip table of <paramref name="config"/>, solved once per animation (<paramref name="dips"/>).</summary>
    private StanceDip.Table DipOf(ContactConfiguration config, Dictionary<ContactConfiguration, StanceDip.Table> dips)
    {
        if (!dips.TryGetValue(config, out StanceDip.Table? table))
        {
            table = _dip.Solve(config);
            dips[config] = table;
        }

        return table;
    }

    /// <summary>True when <paramref name="table"/> dips at least <see cref="StanceDip.LeastDepthShare"/> of the leg, or <paramref name="config"/> holds nothing.</summary>
    private static bool Deep(ContactConfiguration config, StanceDip.Table table) =>
        config.Contacts.Count == 0 || table.Depth >= (StanceDip.LeastDepthShare * table.Leg) - 1e-5f;

    /// <summary>
    /// The contact pose at <paramref name="root"/> for a takeoff (or a landing: <paramref name="velocity"/> reversed);
    /// where the body cannot crouch (or absorb) on the contacts found first, contacts each limb also holds with the
    /// root as low as the least crouch, when the body dips deeper on them.
    /// </summary>
    private ContactConfiguration Pose(in RootPose root, IReadOnlyList<Contact> estimated, Vector3 velocity, Dictionary<ContactConfiguration, StanceDip.Table> dips)
    {
        ContactConfiguration first = _contacts.Generate(root, estimated, velocity, 0f, onEstimates: true);
        if (!first.Valid)
        {
            return first;
        }

        StanceDip.Table table = DipOf(first, dips);
        if (Deep(first, table))
        {
            return Tucked(first, dips);
        }

        // A little deeper than the least crouch: the dip is solved in steps, from the contact pose down.
        ContactConfiguration lower = _contacts.Generate(root, estimated, velocity, 1.2f * StanceDip.LeastDepthShare * table.Leg, onEstimates: true);
        return Tucked(lower.Valid && DipOf(lower, dips).Depth > table.Depth ? lower : first, dips);
    }

    /// <summary>
    /// Most (radians, 15°) a free limb's joint turns between two depths of a dip before the limb is held tucked in the
    /// stance itself (<see cref="Tucked"/>).
    /// </summary>
    private const float TuckedAtOnce = 15f * MathF.PI / 180f;

    /// <summary>The depths below a dip's contact pose, of its twelve, at which a free limb tucked at once is held tucked in the stance (<see cref="Tucked"/>): its first third, which a drive up crosses fastest.</summary>
    private const int TuckRows = 4;

    /// <summary>
    /// <paramref name="config"/> with each free limb that its dip tucks at once near the contact pose (a joint turning
    /// more than <see cref="TuckedAtOnce"/> between two of its first <see cref="TuckRows"/> depths: a free foot
    /// hovering just above a dune, which a slight sink would put into it) already tucked as at that depth, where the
    /// limb is clear of the level in the contact pose and the body dips as deep: the stance shows the limb tucked, and its flight leaves from the tuck.
    /// Before, the limb folded as the crouch began and unfolded in the last 1/240 s of its drive up, as it reached the
    /// contact pose again: a Rigify panda's forearm turned 101° in one displayed frame at takeoff.
    /// </summary>
    private ContactConfiguration Tucked(ContactConfiguration config, Dictionary<ContactConfiguration, StanceDip.Table> dips)
    {
        StanceDip.Table table = DipOf(config, dips);
        if (!config.Valid || table.Angles.Length < 2)
        {
            return config;
        }

        float[]? angles = null;
        List<RigLimb>? tucked = null;
        for (int l = 0; l < Model.Limbs.Count; l++)
        {
            RigLimb limb = Model.Limbs[l];
            if (config.ContactOf(l) is not null)
            {
                continue;
            }

            for (int r = 1; r <= Math.Min(TuckRows, table.Angles.Length - 1); r++)
            {
                float most = 0f;
                foreach (int d in limb.ChainDofSpan)
                {
                    most = MathF.Max(most, MathF.Abs(table.Angles[r][d] - table.Angles[r - 1][d]));
                }

                if (most > TuckedAtOnce)
                {
                    angles ??= (float[])config.Angles.Clone();
                    foreach (int d in limb.ChainDofSpan)
                    {
                        angles[d] = table.Angles[r][d];
                    }

                    (tucked ??= []).Add(limb);
                    break;
                }
            }
        }

        if (angles is null || tucked is null)
        {
            return config;
        }

        var positions = new Vector3[Model.Rig.Joints.Count];
        var rotations = new Quaternion[Model.Rig.Joints.Count];
        Model.Rig.Solve(config.Root, angles, positions, rotations);
        if (tucked.Any(limb => _collision.LimbCollides(limb, positions, rotations, null)))
        {
            return config;
        }

        ContactConfiguration held = config with { Angles = angles };
        return DipOf(held, dips).Depth >= table.Depth - 1e-5f ? held : config;
    }

    /// <summary>
    /// Appends the frames of the root dipping on <paramref name="table"/> from clip time <paramref name="from"/> for
    /// <paramref name="duration"/> seconds, at <paramref name="share"/>(s) of the table's depth (s from 0 to 1), every
    /// contact held; returns the clip time it ends at.
    /// </summary>
    private static float Dip(StanceDip.Table table, float from, float duration, Func<float, float> share, List<AnimationFrame> frames, float frameRate)
    {
        int count = Math.Max(2, (int)MathF.Ceiling(duration * frameRate * ContactSubsteps));
        for (int k = 1; k <= count; k++)
        {
            float s = k / (float)count;
            float depth = table.Depth * share(s);
            frames.Add(new AnimationFrame(from + (duration * s), table.RootAt(depth), table.AnglesAt(depth)));
        }

        return from + duration;
    }

    /// <summary>
    /// The crouch before <paramref name="arc"/>'s takeoff: from standing on <paramref name="table"/>'s contact pose the
    /// body settles into its dip, holds there until at least <paramref name="least"/> seconds have passed, and drives
    /// up through the takeoff pose (accelerating, as a push does). Returns its duration, seconds.
    /// </summary>
    private static float Crouch(StanceDip.Table table, BallisticArc arc, float from, List<AnimationFrame> frames, float least, float frameRate)
    {
        float settle = StanceDip.RiseTime(table);
        float push = StanceDip.PushTime(table, arc.TakeoffVelocity.Length());
        float clock = Dip(table, from, settle, s => s * s * (3f - (2f * s)), frames, frameRate);
        if (settle + push < least)
        {
            clock = Dip(table, clock, least - settle - push, _ => 1f, frames, frameRate);
        }

        return Dip(table, clock, push, StanceDip.Push(table, push, arc.TakeoffVelocity), frames, frameRate) - from;
    }

    /// <summary>
    /// A landing at <paramref name="velocity"/> (m/s, world) absorbed on <paramref name="table"/>'s contact pose: the
    /// body keeps sinking (at first as fast as it came down, <see cref="StanceDip.Sink"/>, then decelerating) to its dip,
    /// then rises back to the contact pose. Returns the clip time it ends at.
    /// </summary>
    private static float Absorb(StanceDip.Table table, Vector3 velocity, float from, List<AnimationFrame> frames, float frameRate)
    {
        float sink = StanceDip.SinkTime(table, velocity.Length());
        float clock = Dip(table, from, sink, StanceDip.Sink(table, sink, velocity), frames, frameRate);
        return Dip(table, clock, StanceDip.RiseTime(table), s => 1f - (s * s * (3f - (2f * s))), frames, frameRate);
    }

    /// <summary>
    /// Appends a walk's frames (but its first, the previous move's last, unless it comes first) and contact phases at
    /// <paramref name="clock"/>: a foot still on the contact the previous move left it on continues that phase; the
    /// phases that last to the walk's end stay open for the next move.
    /// </summary>
    private static void AddWalk(WalkGait.Clip walk, float clock, bool first, List<AnimationFrame> frames, List<ContactPhase> phases, Dictionary<int, (Vector3 Position, float From, bool OnBall)> open)
    {
        float end = walk.Frames[^1].Time;
        var left = new Dictionary<int, (Vector3 Position, float From, bool OnBall)>(open);
        open.Clear();
        foreach (ContactPhase phase in walk.Phases.OrderBy(p => p.From))
        {
            float from = clock + phase.From;
            if (phase.From <= 1e-6f && left.TryGetValue(phase.Limb, out (Vector3 Position, float From, bool OnBall) o) && o.OnBall == phase.OnBall && Vector3.Distance(o.Position, phase.Position) <= 1e-3f)
            {
                from = o.From;
                left.Remove(phase.Limb);
            }

            if (phase.To >= end - 1e-6f)
            {
                open[phase.Limb] = (phase.Position, from, phase.OnBall);
            }
            else
            {
                phases.Add(phase with { From = from, To = clock + phase.To });
            }
        }

        foreach ((int limb, (Vector3 position, float from, bool onBall)) in left)
        {
            phases.Add(new ContactPhase(limb, position, from, clock) { OnBall = onBall });
        }

        foreach (AnimationFrame f in first ? walk.Frames : walk.Frames[1..])
        {
            frames.Add(f with { Time = clock + f.Time });
        }
    }

    /// <summary>The contact pose at stance <paramref name="node"/> a walk starts or ends on; a pose that is not valid is a problem of walk <paramref name="move"/>.</summary>
    private ContactConfiguration Stand(int move, RoadmapNode node, string which, List<JumpProblem> problems)
    {
        ContactConfiguration stance = _contacts.Generate(node.Pose, node.Contacts, node.Cone.Axis);
        if (!stance.Valid)
        {
            problems.Add(new JumpProblem(move, $"the walk's {which} stance: {stance.Reason}"));
        }

        return stance;
    }

    /// <summary>
    /// The moves with each jump's takeoff and landing stance as the animation stands on it: a contact the planner
    /// estimated whose limb the generated contact pose cannot hold (a spider's hind foot aimed at a ledge's brink
    /// under its body, where no flat foot reaches) is left out of the stance the plan reports, and one held farther
    /// than <see cref="MovedFoothold"/> from its estimate is reported where it is held, with the cone of the
    /// contacts left, when those still number the required contacts and their cone still contains the jump's
    /// velocity (every use of the stance: a landing that pushes off again); otherwise the stance stays as planned.
    /// Walks that end or start on a changed stance get the same record of it.
    /// </summary>
    private Move[] HeldStances(Move[] moves, Clip?[] clips)
    {
        var uses = new Dictionary<(int Id, RootPose Pose), List<(RoadmapNode Node, ContactConfiguration Config, Vector3 Velocity)>>();
        for (int m = 0; m < moves.Length; m++)
        {
            if (moves[m] is Jump jump && clips[m] is Clip clip)
            {
                Use(jump.Takeoff, clip.Takeoff, jump.Arc.TakeoffVelocity);
                Use(jump.Landing, clip.Landing, -jump.Arc.LandingVelocity);
            }
        }

        var held = new Dictionary<(int Id, RootPose Pose), RoadmapNode>();
        foreach (((int Id, RootPose Pose) key, List<(RoadmapNode Node, ContactConfiguration Config, Vector3 Velocity)> list) in uses)
        {
            RoadmapNode node = list[0].Node;
            if (list.Exists(u => !u.Config.Valid))
            {
                continue;
            }

            Contact[] kept = [.. node.Contacts.Where(c => list.TrueForAll(u => u.Config.ContactOf(c.Limb) is not null)).Select(c => Moved(c, list))];
            if ((kept.Length == node.Contacts.Count && kept.SequenceEqual(node.Contacts)) || kept.Length < _requiredContacts)
            {
                continue;
            }

            if (Contact.ConeOf(kept) is { } cone && list.TrueForAll(u => cone.Contains(u.Velocity, 1e-3f)))
            {
                held[key] = node with { Contacts = kept, Cone = cone };
            }
        }

        if (held.Count == 0)
        {
            return moves;
        }

        RoadmapNode Held(RoadmapNode node) => held.GetValueOrDefault((node.Id, node.Pose), node);
        return [.. moves.Select(move => move switch
        {
            Jump jump => jump with { Takeoff = Held(jump.Takeoff), Landing = Held(jump.Landing) },
            Walk walk => walk.Between(Held(walk.From), Held(walk.To)),
            _ => move,
        })];

        // A contact every use holds at one point (within HeldTogether) farther than MovedFoothold from the estimate
        // (a panda's forefoot estimated on a tread its leg cannot fold up to, set down on the tread below) is reported
        // where it is held, on that point's surface.
        Contact Moved(Contact c, List<(RoadmapNode Node, ContactConfiguration Config, Vector3 Velocity)> list)
        {
            LimbContact first = list[0].Config.ContactOf(c.Limb)!.Value;
            if (Vector3.Distance(first.Position, c.Position) <= MovedFoothold
                || !list.TrueForAll(u => Vector3.Distance(u.Config.ContactOf(c.Limb)!.Value.Position, first.Position) <= HeldTogether)
                || !_scene.Bvh.Raycast(first.Position + (first.Normal * HeldTogether), -first.Normal, 2f * HeldTogether, out RayHit hit)
                || _scene.Surfaces.SurfaceOf(hit.Triangle) is not (>= 0 and int surface))
            {
                return c;
            }

            return new Contact(c.Limb, first.Position, first.Normal, first.Mu, surface);
        }

        void Use(RoadmapNode node, ContactConfiguration config, Vector3 velocity)
        {
            if (!uses.TryGetValue((node.Id, node.Pose), out List<(RoadmapNode, ContactConfiguration, Vector3)>? list))
            {
                uses[(node.Id, node.Pose)] = list = [];
            }

            list.Add((node, config, velocity));
        }
    }

    /// <summary>One jump animated on its own: frames from takeoff (t = 0) to landing, the contact poses, when each limb's contact breaks and is made.</summary>
    private sealed record Clip(AnimationFrame[] Frames, ContactConfiguration Takeoff, ContactConfiguration Landing, float[] Breaks, float[] Makes, int CollidingFrames, List<JumpProblem> Problems);

    /// <summary>A stance between two jumps: frames from 0 to its duration, and each step (limb, start time, the contact it steps to).</summary>
    private sealed record Stance(float Duration, AnimationFrame[] Frames, List<(int Limb, float Start, LimbContact? Next)> Steps, List<JumpProblem> Problems);

    private Clip AnimateJump(int index, Jump jump, ContactConfiguration? takeoffPose, Dictionary<ContactConfiguration, StanceDip.Table> dips, float frameRate)
    {
        BallisticArc arc = jump.Arc;
        ContactConfiguration takeoff = takeoffPose ?? Pose(arc.Takeoff, jump.Takeoff.Contacts, arc.TakeoffVelocity, dips);
        ContactConfiguration landing = Pose(arc.Landing, jump.Landing.Contacts, -arc.LandingVelocity, dips);
        var problems = new List<JumpProblem>();

        // A stance no limb reaches from is one every jump from (to) it fails on, whatever its velocity: a problem of
        // the stance, which the repair then sets aside as a takeoff (landing) for every jump at once.
        if (!takeoff.Valid)
        {
            problems.Add(new JumpProblem(index, $"takeoff: {takeoff.Reason}") { Stance = takeoff.Contacts.Count == 0 ? ProblemStance.Takeoff : ProblemStance.None });
        }

        if (!landing.Valid)
        {
            problems.Add(new JumpProblem(index, $"landing: {landing.Reason}") { Stance = landing.Contacts.Count == 0 ? ProblemStance.Landing : ProblemStance.None });
        }

        Rig rig = Model.Rig;
        int frames = Math.Max(2, (int)MathF.Ceiling(arc.FlightTime * frameRate));
        int steps = frames * ContactSubsteps;
        float h = arc.FlightTime / steps;
        float Time(int i) => i >= steps ? arc.FlightTime : i * h;
        int limbs = Model.Limbs.Count;
        var held = new Dictionary<int, float[]>[limbs];
        int[] breaks = new int[limbs];
        int[] makes = new int[limbs];

        // Contact phases on the fine grid: hold each contact by IK, forward from takeoff and backward from landing.
        for (int l = 0; l < limbs; l++)
        {
            held[l] = [];
            breaks[l] = Hold(arc, takeoff, l, 0, +1, steps / 2, held[l], h, steps);
            makes[l] = Hold(arc, landing, l, steps, -1, Math.Max(breaks[l] + 1, steps / 2), held[l], h, steps);
        }

        // A limb that lets go of one point and takes another must be in the air long enough for the eye (and for a
        // foot's speed): at least MinAirTime between break and make, shortening both holds about mid-flight.
        int minAir = (int)MathF.Ceiling(MinAirTime / h);
        for (int l = 0; l < limbs; l++)
        {
            if (takeoff.ContactOf(l) is { } up && landing.ContactOf(l) is { } down && Vector3.Distance(up.Position, down.Position) > 0.02f && makes[l] - breaks[l] < minAir)
            {
                int centre = (breaks[l] + makes[l]) / 2;
                breaks[l] = Math.Max(0, Math.Min(breaks[l], centre - (minAir / 2)));
                makes[l] = Math.Min(steps, Math.Max(makes[l], breaks[l] + minAir));
                if (makes[l] - breaks[l] < minAir)
                {
                    problems.Add(new JumpProblem(index, $"{Model.Limbs[l].Name} would move from its takeoff to its landing contact in under {MinAirTime:0.##} s"));
                }
            }
        }

        // The times that become frames: every frame, and every fine step while some limb holds a contact.
        var grid = new SortedSet<int>();
        for (int f = 0; f <= frames; f++)
        {
            grid.Add(f * ContactSubsteps);
        }

        for (int i = 0; i <= breaks.Max(); i++)
        {
            grid.Add(i);
        }

        for (int i = makes.Min(); i <= steps; i++)
        {
            grid.Add(i);
        }

        int[] times = [.. grid];
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];

        // Apex: the extending pose, each limb kept out of the level.
        int apex = Math.Clamp((int)MathF.Round(ApexKeyTime(arc) / h), 1, steps - 1);
        RootPose apexRoot = arc.PoseAt(Time(apex));
        float[] apexAngles = (float[])Model.ExtendingPose.Clone();
        for (int l = 0; l < limbs; l++)
        {
            rig.Solve(apexRoot, apexAngles, positions, rotations);
            if (_collision.LimbCollides(Model.Limbs[l], positions, rotations, null))
            {
                _contacts.KeepFree(apexRoot, apexAngles, l);
            }
        }

        var limbDof = new bool[rig.DofCount];
        foreach (RigLimb limb in Model.Limbs)
        {
            foreach (int d in limb.ChainDofSpan)
            {
                limbDof[d] = true;
            }
        }

        // Trunk angles (in no limb): takeoff → apex → landing.
        float[][] TrunkAngles(int[] at)
        {
            var trunk = new float[at.Length][];
            for (int k = 0; k < at.Length; k++)
            {
                int i = at[k];
                trunk[k] = new float[rig.DofCount];
                for (int d = 0; d < rig.DofCount; d++)
                {
                    if (!limbDof[d])
                    {
                        trunk[k][d] = i <= apex
                            ? float.Lerp(takeoff.Angles[d], apexAngles[d], i / (float)apex)
                            : float.Lerp(apexAngles[d], landing.Angles[d], (i - apex) / (float)(steps - apex));
                    }
                }
            }

            return trunk;
        }

        float[][] angles = TrunkAngles(times);

        // Each limb: held angles in its contact phases; in flight, break → apex → make, re-sampling the apex pose of
        // every limb that would put a bone through the level. Every fine step is checked (angles between frames are
        // interpolated the same way), with one forward kinematics per step for all the limbs being checked.
        int colliding = 0;
        var random = new Random(17);
        var limbApex = new float[limbs][];
        var firstHit = new float[limbs];
        var pending = new List<int>();
        for (int l = 0; l < limbs; l++)
        {
            limbApex[l] = (float[])apexAngles.Clone();
            pending.Add(l);
        }

        // A limb that passes through the level whatever its apex pose may be retracted quickly: it reaches its apex
        // pose Retract of the way from letting go to the apex and leaves it as late before taking hold (a leg lifted
        // clear of a ledge's face right after takeoff, put down onto the ledge only as the body comes over it).
        var quickUp = new int[limbs];
        var quickDown = new int[limbs];
        var quick = new bool[limbs];

        // A limb that still passes through the level, retracted quickly or not, is lifted straight off its takeoff
        // contact first (LiftOff), then retracted quickly from there: a foot on a stair's tread, a riser just ahead of
        // its toes, rises above the riser before the body's forward motion carries it on.
        var lifted = new Dictionary<int, float[]>?[limbs];
        var leaves = (int[])breaks.Clone();
        for (int l = 0; l < limbs; l++)
        {
            quickUp[l] = Math.Min(apex, breaks[l] + Math.Max(1, (int)MathF.Round(Retract * (apex - breaks[l]))));
            quickDown[l] = Math.Max(apex, makes[l] - Math.Max(1, (int)MathF.Round(Retract * (makes[l] - apex))));
        }

        bool Airborne(int l, int i) => !(held[l].ContainsKey(i) && (i <= breaks[l] || i >= makes[l]));

        // Each limb's angular velocity (radians a fine step, per degree of freedom) as it leaves the ground: its last
        // held step's, or, letting go at takeoff, the drive up's as it ends (Kicks); null where none is carried on.
        var kicks = new float[]?[limbs];
        int kickSteps = (int)MathF.Round(KickTime / h);
        void LimbAt(int l, int i, float[] target)
        {
            RigLimb limb = Model.Limbs[l];
            if (!Airborne(l, i))
            {
                float[] holding = held[l][i];
                foreach (int d in limb.ChainDofSpan)
                {
                    target[d] = holding[d];
                }

                return;
            }

            if (lifted[l] is { } lift && lift.TryGetValue(i, out float[]? up))
            {
                foreach (int d in limb.ChainDofSpan)
                {
                    target[d] = up[d];
                }

                return;
            }

            float[] from = leaves[l] > breaks[l] ? lifted[l]![leaves[l]] : held[l][breaks[l]];
            float[] to = held[l][makes[l]];
            float[] top = limbApex[l];
            if (quick[l])
            {
                float u = i <= apex
                    ? Math.Clamp((i - leaves[l]) / (float)(quickUp[l] - leaves[l]), 0f, 1f)
                    : Math.Clamp((i - quickDown[l]) / (float)(makes[l] - quickDown[l]), 0f, 1f);
                foreach (int d in limb.ChainDofSpan)
                {
                    target[d] = i <= apex ? float.Lerp(from[d], top[d], u) : float.Lerp(top[d], to[d], u);
                }

                return;
            }

            foreach (int d in limb.ChainDofSpan)
            {
                target[d] = apex > breaks[l] && apex < makes[l]
                    ? (i <= apex ? float.Lerp(from[d], top[d], (i - breaks[l]) / (float)(apex - breaks[l])) : float.Lerp(top[d], to[d], (i - apex) / (float)(makes[l] - apex)))
                    : float.Lerp(from[d], to[d], (i - breaks[l]) / (float)(makes[l] - breaks[l]));
            }

            // Leaving the ground, the limb carries on at the speed it left with and eases into its way to the apex
            // over KickTime: x(1 − x/K)² steps of the difference, its slope that difference at the break and 0 at K.
            if (kicks[l] is { } kick && i > breaks[l] && i - breaks[l] < kickSteps)
            {
                float x = i - breaks[l];
                float g = x * (1f - (x / kickSteps)) * (1f - (x / kickSteps));
                ReadOnlySpan<int> dofs = limb.ChainDofSpan;
                for (int c = 0; c < dofs.Length; c++)
                {
                    int d = dofs[c];
                    float along = (top[d] - from[d]) / (apex - breaks[l]);
                    target[d] += (kick[c] - along) * g;
                }

                rig.Clamp(target);
            }
        }

        float[] probe = new float[rig.DofCount];
        float[] half = new float[rig.DofCount];
        var halfPositions = new Vector3[rig.Joints.Count];
        var halfRotations = new Quaternion[rig.Joints.Count];
        var hit = new bool[limbs];
        int attempts = 3 * (MaxResamples + 1);
        var stuck = new List<int>();

        // A limb in the air on one side of the apex only, holding its takeoff contact until the apex or taking its
        // landing contact before it (a spider's leg on a low hop), or passing the apex in the first or last
        // AcrossShare of its time in the air, steps across: its effector on a lifted curve from the one contact to the
        // other (StepAcross), as a walking foot swings, neither swept low between the two nor flung up to its flight
        // pose and back down within a few hundredths of a second. Where that passes through the level, it moves as
        // any other limb.
        var steppingAcross = new bool[limbs];
        for (int l = 0; l < limbs; l++)
        {
            float share = (apex - breaks[l]) / (float)Math.Max(1, makes[l] - breaks[l]);
            if ((share <= AcrossShare || share >= 1f - AcrossShare) && StepAcross(arc, takeoff, landing, l, breaks[l], makes[l], held[l], h, steps) is { } across)
            {
                lifted[l] = across;
                steppingAcross[l] = true;
            }
        }

        Kicks(arc, takeoff, held, breaks, apex, kickSteps, h, dips, kicks);
        float[] kickNow = new float[rig.DofCount];
        float[] kickBefore = new float[rig.DofCount];
        for (int l = 0; l < limbs; l++)
        {
            // Kept only where the limb stays clear of the level with it, at each step and between steps.
            if (kicks[l] is null || steppingAcross[l])
            {
                kicks[l] = null;
                continue;
            }

            // The trunk's angles of the frame at or before each step, as the checks below take them.
            int frame = 0;
            bool first = true;
            for (int i = breaks[l] + 1; i < breaks[l] + kickSteps && kicks[l] is not null; i++)
            {
                while (frame + 1 < times.Length && times[frame + 1] <= i)
                {
                    frame++;
                }

                Array.Copy(angles[frame], kickNow, kickNow.Length);
                LimbAt(l, i, kickNow);
                rig.Solve(arc.PoseAt(Time(i)), kickNow, positions, rotations);
                bool clear = !_collision.LimbCollides(Model.Limbs[l], positions, rotations, null);
                if (clear && !first)
                {
                    Array.Copy(kickNow, half, half.Length);
                    foreach (int d in Model.Limbs[l].ChainDofSpan)
                    {
                        half[d] = 0.5f * (kickBefore[d] + kickNow[d]);
                    }

                    rig.Solve(arc.PoseAt(Time(i) - (0.5f * h)), half, halfPositions, halfRotations);
                    clear = !_collision.LimbCollides(Model.Limbs[l], halfPositions, halfRotations, null);
                }

                kicks[l] = clear ? kicks[l] : null;
                (kickBefore, kickNow) = (kickNow, kickBefore);
                first = false;
            }
        }

        for (int n = 0; n < attempts && pending.Count > 0; n++)
        {
            // Re-sampling: the tucked and contact poses first, then random samples of the limb's database; the
            // limbs none of them keeps clear try them again retracted quickly.
            int attempt = n % (MaxResamples + 1);
            if (n == MaxResamples + 1)
            {
                // Only a limb in the air on both sides of the apex can be retracted; the others have failed.
                stuck.AddRange(pending.Where(l => !(apex > breaks[l] && apex < makes[l])));
                pending.RemoveAll(stuck.Contains);
                foreach (int l in pending)
                {
                    quick[l] = true;
                    limbApex[l] = (float[])apexAngles.Clone();
                }
            }
            else if (n == 2 * (MaxResamples + 1))
            {
                // Only a limb leaving a takeoff contact can be lifted off it; the others have failed.
                foreach (int l in pending)
                {
                    if (LiftOff(arc, takeoff, l, breaks[l], apex, held[l][breaks[l]], h, steps) is { Count: > 0 } lift)
                    {
                        lifted[l] = lift;
                        leaves[l] = lift.Keys.Max();
                        quickUp[l] = Math.Min(apex, leaves[l] + Math.Max(1, (int)MathF.Round(Retract * (apex - leaves[l]))));
                        limbApex[l] = (float[])apexAngles.Clone();
                    }
                    else
                    {
                        stuck.Add(l);
                    }
                }

                pending.RemoveAll(stuck.Contains);
            }

            foreach (int l in pending)
            {
                hit[l] = false;
                RigLimb limb = Model.Limbs[l];
                if (attempt is 1 or 2)
                {
                    float[] pose = attempt == 1 ? Model.FlexionPose : Model.ContactPose;
                    foreach (int d in limb.ChainDofSpan)
                    {
                        limbApex[l][d] = pose[d];
                    }
                }
                else if (attempt > 2)
                {
                    _contacts.Database(l).Apply(random.Next(_contacts.Database(l).Count), limbApex[l]);
                }
            }

            int k = 0;
            for (int i = 0; i <= steps; i++)
            {
                while (k + 1 < times.Length && times[k + 1] <= i)
                {
                    k++;
                }

                bool any = false;
                foreach (int l in pending)
                {
                    any |= !hit[l] && Airborne(l, i);
                }

                if (!any)
                {
                    continue;
                }

                // The trunk's angles of the frame at or before this step; the pending limbs' own at this step.
                Array.Copy(angles[k], probe, probe.Length);
                foreach (int l in pending)
                {
                    LimbAt(l, i, probe);
                }

                rig.Solve(arc.PoseAt(Time(i)), probe, positions, rotations);
                foreach (int l in pending)
                {
                    if (!hit[l] && Airborne(l, i) && _collision.LimbCollides(Model.Limbs[l], positions, rotations, null))
                    {
                        hit[l] = true;
                        firstHit[l] = Time(i);
                    }
                }

                // Half a fine step from a limb's letting go (or to its taking hold), where the clip interpolates
                // between the held frame and the next: a foot whipped off the ground sweeps along it there (4 cm, 1
                // mm deep, in the 2 ms after a spider's hop took off), the part within the clearance of its contact cut.
                foreach (int l in pending)
                {
                    if (!hit[l] && Airborne(l, i) && (i - 1 == breaks[l] ? takeoff.ContactOf(l) : i + 1 == makes[l] ? landing.ContactOf(l) : null) is { } touching)
                    {
                        int other = i - 1 == breaks[l] ? i - 1 : i + 1;
                        Array.Copy(probe, half, half.Length);
                        LimbAt(l, other, half);
                        foreach (int d in Model.Limbs[l].ChainDofSpan)
                        {
                            half[d] = 0.5f * (half[d] + probe[d]);
                        }

                        rig.Solve(arc.PoseAt(0.5f * (Time(i) + Time(other))), half, halfPositions, halfRotations);
                        if (_collision.LimbCollides(Model.Limbs[l], halfPositions, halfRotations, touching.Position))
                        {
                            hit[l] = true;
                            firstHit[l] = 0.5f * (Time(i) + Time(other));
                        }
                    }
                }
            }

            // A limb stepping across that hits the level moves as any other instead, from the next attempt on.
            foreach (int l in pending.Where(l => steppingAcross[l] && hit[l]))
            {
                (lifted[l], steppingAcross[l]) = (null, false);
            }

            pending.RemoveAll(l => !hit[l]);
        }

        if (quick.Any(q => q) || steppingAcross.Any(a => a))
        {
            // The quick limbs' corners become frames, so that the clip's linear interpolation between frames moves
            // them as was checked.
            for (int l = 0; l < limbs; l++)
            {
                if (quick[l])
                {
                    grid.Add(quickUp[l]);
                    grid.Add(quickDown[l]);
                }

                if (lifted[l] is { } lift)
                {
                    grid.UnionWith(lift.Keys);
                }
            }

            times = [.. grid];
            angles = TrunkAngles(times);
        }

        // The frames: every limb at its chosen poses.
        for (int k = 0; k < times.Length; k++)
        {
            for (int l = 0; l < limbs; l++)
            {
                LimbAt(l, times[k], angles[k]);
            }
        }

        foreach (int l in pending.Concat(stuck).Order())
        {
            colliding++;
            float share = firstHit[l] / arc.FlightTime;
            problems.Add(new JumpProblem(index, $"{Model.Limbs[l].Name} passes through the level in flight ({firstHit[l]:0.000} s after takeoff) whatever pose it takes")
            {
                Near = share <= JumpProblem.NearShare ? ProblemStance.Takeoff : share >= 1f - JumpProblem.NearShare ? ProblemStance.Landing : ProblemStance.None,
            });
        }

        // Bones of no limb (spine, head, tail…) follow the trunk; a free chain (a tail) bends out of the level where
        // it can, and a hit left is a problem.
        float[] seconds = [.. times.Select(Time)];
        _free.Clear(seconds, k => arc.PoseAt(seconds[k]), angles);
        var result = new AnimationFrame[times.Length];
        bool trunkReported = false;
        for (int k = 0; k < times.Length; k++)
        {
            float t = Time(times[k]);
            RootPose root = arc.PoseAt(t);
            result[k] = new AnimationFrame(t, root, angles[k]);
            if (!trunkReported)
            {
                rig.Solve(root, angles[k], positions, rotations);
                int bone = _collision.OtherBoneColliding(positions, rotations);
                if (bone >= 0)
                {
                    trunkReported = true;
                    colliding++;
                    problems.Add(new JumpProblem(index, $"bone '{rig.Joints[bone].Name}' passes through the level {t:0.000} s after takeoff"));
                }
            }
        }

        return new Clip(result, takeoff, landing, [.. breaks.Select(b => Time(b))], [.. makes.Select(m => Time(m))], colliding, problems);
    }

    /// <summary>
    /// When (seconds after takeoff) the flight's apex pose is keyed: at the top of the arc, kept within the middle of the
    /// flight (0.3 of it from either end) so that a jump rising to its landing or falling from its takeoff still has
    /// time to reach that pose and leave it.
    /// </summary>
    public static float ApexKeyTime(BallisticArc arc) =>
        Math.Clamp(arc.ApexTime, ApexKeyShare * arc.FlightTime, (1f - ApexKeyShare) * arc.FlightTime);

    /// <summary>
    /// The stance at <paramref name="root"/> between a landing and the next takeoff: each limb whose contact (or
    /// pose) differs steps from the landing's to the takeoff's, one at a time, lifted clear of the level at mid-step,
    /// while the others hold. No step when the takeoff pose is the landing pose.
    /// </summary>
    private Stance Restep(int nextJump, RootPose root, ContactConfiguration landing, ContactConfiguration takeoff, float frameRate)
    {
        var steps = new List<(int Limb, float Start, LimbContact? Next)>();
        var problems = new List<JumpProblem>();
        float[] q = (float[])landing.Angles.Clone();
        var frames = new List<AnimationFrame> { new(0f, root, (float[])q.Clone()) };
        if (ReferenceEquals(landing, takeoff))
        {
            return new Stance(0f, [.. frames], steps, problems);
        }

        Rig rig = Model.Rig;
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        int perStep = Math.Max(4, (int)MathF.Ceiling(StepDuration * frameRate));
        float clock = 0f;
        for (int l = 0; l < Model.Limbs.Count; l++)
        {
            RigLimb limb = Model.Limbs[l];
            LimbContact? from = landing.ContactOf(l);
            LimbContact? to = takeoff.ContactOf(l);
            bool samePoint = from is { } a && to is { } b && Vector3.Distance(a.Position, b.Position) <= 1e-4f;
            bool sameAngles = limb.ChainDofs.All(d => MathF.Abs(q[d] - takeoff.Angles[d]) <= 1e-4f);
            if ((samePoint || (from is null && to is null)) && sameAngles)
            {
                continue;
            }

            // Mid-step: the effector lifted along the surface normal above the middle of its travel, by IK.
            float[] start = (float[])q.Clone();
            float[] end = (float[])q.Clone();
            foreach (int d in limb.ChainDofSpan)
            {
                end[d] = takeoff.Angles[d];
            }

            rig.Solve(root, start, positions, rotations);
            Vector3 p0 = limb.EffectorPosition(positions, rotations);
            rig.Solve(root, end, positions, rotations);
            Vector3 p1 = limb.EffectorPosition(positions, rotations);
            Vector3 up = (from?.Normal ?? Vector3.Zero) + (to?.Normal ?? Vector3.Zero);
            up = up.LengthSquared() > 1e-6f ? Vector3.Normalize(up) : root.Up;
            float[][]? path = null;
            foreach (float lift in StepLifts)
            {
                float[] mid = (float[])start.Clone();
                foreach (int d in limb.ChainDofSpan)
                {
                    mid[d] = float.Lerp(start[d], end[d], 0.5f);
                }

                _holdIk.Solve(root, mid, limb, ((p0 + p1) * 0.5f) + (up * lift), null);
                float[][] candidate = Swing(start, mid, end, limb, perStep);
                if (SwingClear(root, candidate, limb, from, to, positions, rotations))
                {
                    path = candidate;
                    break;
                }
            }

            if (path is null)
            {
                // No clear lifted swing: the tucked pose at mid-step, then give up honestly.
                float[] tucked = (float[])start.Clone();
                foreach (int d in limb.ChainDofSpan)
                {
                    tucked[d] = Model.FlexionPose[d];
                }

                path = Swing(start, tucked, end, limb, perStep);
                if (!SwingClear(root, path, limb, from, to, positions, rotations))
                {
                    problems.Add(new JumpProblem(nextJump, $"{limb.Name} cannot step to its takeoff contact without passing through the level"));
                }
            }

            steps.Add((l, clock, to));
            for (int k = 1; k < path.Length; k++)
            {
                frames.Add(new AnimationFrame(clock + (StepDuration * k / (path.Length - 1)), root, path[k]));
            }

            Array.Copy(end, q, q.Length);
            clock += StepDuration;
        }

        // Angles of no limb (the trunk's) are the contact pose's in both; any difference is taken over at the end.
        float[] last = (float[])takeoff.Angles.Clone();
        if (!frames[^1].Angles.AsSpan().SequenceEqual(last))
        {
            clock += 1f / frameRate;
            frames.Add(new AnimationFrame(clock, root, last));
        }

        return new Stance(clock, [.. frames], steps, problems);
    }

    /// <summary>Keys of one limb's swing: start → mid → end in <paramref name="count"/> steps (smoothstep in time).</summary>
    private static float[][] Swing(float[] start, float[] mid, float[] end, RigLimb limb, int count)
    {
        var keys = new float[count + 1][];
        for (int k = 0; k <= count; k++)
        {
            float s = k / (float)count;
            s = s * s * (3f - (2f * s));
            float[] q = (float[])start.Clone();
            foreach (int d in limb.ChainDofSpan)
            {
                q[d] = s <= 0.5f ? float.Lerp(start[d], mid[d], s * 2f) : float.Lerp(mid[d], end[d], (s - 0.5f) * 2f);
            }

            keys[k] = q;
        }

        return keys;
    }

    private bool SwingClear(RootPose root, float[][] path, RigLimb limb, LimbContact? from, LimbContact? to, Vector3[] positions, Quaternion[] rotations)
    {
        for (int k = 0; k < path.Length; k++)
        {
            Model.Rig.Solve(root, path[k], positions, rotations);
            Vector3? near = k == 0 ? from?.Position : k == path.Length - 1 ? to?.Position : null;
            if (_collision.LimbCollides(limb, positions, rotations, near))
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>
    /// Limb <paramref name="l"/>'s angles on the fine steps after it lets go of its takeoff contact (step
    /// <paramref name="from"/>, angles <paramref name="leaving"/>), its effector held by IK over that contact point and
    /// raised along the contact's normal as far as the trunk has risen, up to the character's step height, until the
    /// apex or until the IK no longer reaches; empty when the limb holds no takeoff contact or cannot rise at all.
    /// </summary>
    private Dictionary<int, float[]> LiftOff(BallisticArc arc, ContactConfiguration config, int l, int from, int apex, float[] leaving, float h, int steps)
    {
        var lift = new Dictionary<int, float[]>();
        if (config.ContactOf(l) is not LimbContact contact)
        {
            return lift;
        }

        RigLimb limb = Model.Limbs[l];
        float[] q = (float[])leaving.Clone();
        float start = arc.PoseAt(from * h).Position.Y;
        for (int i = from + 1; i < apex; i++)
        {
            RootPose root = arc.PoseAt(i >= steps ? arc.FlightTime : i * h);
            float up = MathF.Min(_liftHeight, MathF.Max(0f, root.Position.Y - start));
            if (!_holdIk.Reaches(root, q, limb, contact.Position + (contact.Normal * up), -contact.Normal))
            {
                break;
            }

            lift[i] = (float[])q.Clone();
            if (up >= _liftHeight)
            {
                break;
            }
        }

        return lift;
    }

    /// <summary>
    /// Limb <paramref name="l"/>'s angles on every fine step between letting go of its takeoff contact (step
    /// <paramref name="from"/>) and taking its landing contact (step <paramref name="to"/>), for a limb in the air on
    /// one side of the apex only (or passing it near one end: <see cref="AcrossShare"/>): its effector by IK on a curve
    /// from the one contact point to the other, rising off the one surface and coming down onto the other, at most the
    /// character's step height above the higher of the two (less on a short step: at most half its length), the sole
    /// turning from the one surface to the other. <c>null</c> when the limb lacks either contact, the two are within
    /// 2 cm, or the IK does not reach a point of the curve.
    /// </summary>
    private Dictionary<int, float[]>? StepAcross(BallisticArc arc, ContactConfiguration takeoff, ContactConfiguration landing, int l, int from, int to, Dictionary<int, float[]> held, float h, int steps)
    {
        if (takeoff.ContactOf(l) is not LimbContact up || landing.ContactOf(l) is not LimbContact down || to - from < 2 || !held.TryGetValue(from, out float[]? leaving)
            || Vector3.Distance(up.Position, down.Position) <= 0.02f)
        {
            return null;
        }

        // As a walking foot swings: a step height above the higher of the two surfaces at most (half the step's
        // length on a short one).
        RigLimb limb = Model.Limbs[l];
        var curve = new SwingCurve(up.Position, down.Position, Vector3.Normalize(up.Normal + down.Normal), MathF.Min(_liftHeight, 0.5f * Vector3.Distance(up.Position, down.Position)));
        float[] q = (float[])leaving.Clone();
        float[]? arriving = held.GetValueOrDefault(to);
        var across = new Dictionary<int, float[]>();
        for (int i = from + 1; i < to; i++)
        {
            float u = (i - from) / (float)(to - from);

            // Each solve starts from the step before, drawn toward the landing's held angles by a smoothstep's share of
            // what is left (as a walk's swing is drawn toward its foothold's), so that the leg arrives in the landing's
            // own solution, not another one holding the same point (an ant's foreleg stepping across a hop took its
            // landing pose 38° away in the frame of landing).
            if (arriving is not null)
            {
                float pull = Easing.Pull(i - from, to - from);
                foreach (int d in limb.ChainDofSpan)
                {
                    q[d] = float.Lerp(q[d], arriving[d], pull);
                }
            }

            Vector3 point = curve.At(u);
            Vector3 normal = -Vector3.Normalize(Vector3.Lerp(up.Normal, down.Normal, Easing.Smooth(u)));
            RootPose root = arc.PoseAt(i >= steps ? arc.FlightTime : i * h);
            if (!_holdIk.Reaches(root, q, limb, point, normal) && !_holdIk.Reaches(root, q, limb, point, null))
            {
                return null;
            }

            across[i] = (float[])q.Clone();
        }

        return across;
    }

    /// <summary>
    /// Records limb <paramref name="l"/>'s angles at fine step <paramref name="start"/> and onward by
    /// <paramref name="direction"/> while it holds its contact in <paramref name="config"/> by IK (with no bone through
    /// the level) and no joint of it turns faster than <see cref="MostHeldTurnRate"/>, up to step
    /// <paramref name="limit"/>. Returns the last step where it held (the start for a free limb).
    /// </summary>
    private int Hold(BallisticArc arc, ContactConfiguration config, int l, int start, int direction, int limit, Dictionary<int, float[]> held, float h, int steps)
    {
        Rig rig = Model.Rig;
        RigLimb limb = Model.Limbs[l];
        float[] q = (float[])config.Angles.Clone();
        held[start] = (float[])q.Clone();
        if (config.ContactOf(l) is not LimbContact contact)
        {
            return start;
        }

        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        int last = start;
        float mostTurn = MostHeldTurnRate * h;
        for (int i = start + direction; direction > 0 ? i <= limit : i >= limit; i += direction)
        {
            RootPose root = arc.PoseAt(i >= steps ? arc.FlightTime : i * h);
            IkResult result = _holdIk.Solve(root, q, limb, contact.Position, -contact.Normal);
            if (!result.Success || !TurnsWithin(held[last], q, limb, mostTurn))
            {
                break;
            }

            rig.Solve(root, q, positions, rotations);
            if (_collision.LimbCollides(limb, positions, rotations, contact.Position))
            {
                break;
            }

            held[i] = (float[])q.Clone();
            last = i;
        }

        return last;
    }

    /// <summary>
    /// How long (seconds, 0.1) a limb leaving the ground carries on at the speed it left with, easing into its way to
    /// the flight's apex pose: a frog's wrist or ankle, extending 15–16° a frame as its drive up ended, stopped dead
    /// at takeoff (2–4° a frame on), which the eye sees snap.
    /// </summary>
    private const float KickTime = 0.1f;

    /// <summary>
    /// Fills <paramref name="kicks"/>: each limb's angular velocity as it leaves the ground (radians a fine step of
    /// <paramref name="h"/> seconds, per degree of freedom of its chain), from its last two held fine steps where it
    /// holds its takeoff contact into the flight, else from the drive up out of the takeoff's dip as it ends
    /// (<see cref="StanceDip.Push"/>: rising along the dip's up axis at the rate the push ends with, the angles moving
    /// from the dip's first depth to the contact pose); null for a limb without room to ease before the apex
    /// (<paramref name="kickSteps"/> fine steps) or leaving at rest.
    /// </summary>
    private void Kicks(BallisticArc arc, ContactConfiguration takeoff, Dictionary<int, float[]>[] held, int[] breaks, int apex, int kickSteps, float h, Dictionary<ContactConfiguration, StanceDip.Table> dips, float[]?[] kicks)
    {
        StanceDip.Table? table = takeoff.Valid ? DipOf(takeoff, dips) : null;
        float rate = 0f;
        if (table is { Depth: > 0f, Angles.Length: >= 2 })
        {
            // The depth's share falls at k times the mean rate as the push ends.
            float push = StanceDip.PushTime(table, arc.TakeoffVelocity.Length());
            float k = StanceDip.PushEndRate(table, push, arc.TakeoffVelocity);
            rate = k > 0f && push > 0f ? (table.Angles.Length - 1) * k / push * h : 0f;
        }

        for (int l = 0; l < kicks.Length; l++)
        {
            kicks[l] = null;
            int b = breaks[l];
            if (b + kickSteps >= apex || kickSteps < 2)
            {
                continue;
            }

            ReadOnlySpan<int> dofs = Model.Limbs[l].ChainDofSpan;
            var kick = new float[dofs.Length];
            for (int c = 0; c < dofs.Length; c++)
            {
                int d = dofs[c];
                kick[c] = b > 0 && held[l].TryGetValue(b - 1, out float[]? before)
                    ? held[l][b][d] - before[d]
                    : table is not null && rate > 0f ? (table.Angles[0][d] - table.Angles[1][d]) * rate : 0f;
            }

            kicks[l] = kick.AsSpan().ContainsAnyExcept(0f) ? kick : null;
        }
    }

    /// <summary>True when no angle of <paramref name="limb"/>'s chain differs between <paramref name="from"/> and <paramref name="to"/> by more than <paramref name="most"/> (radians).</summary>
    private static bool TurnsWithin(float[] from, float[] to, RigLimb limb, float most)
    {
        foreach (int d in limb.ChainDofSpan)
        {
            if (MathF.Abs(to[d] - from[d]) > most)
            {
                return false;
            }
        }

        return true;
    }
}
