using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Rigs;

/// <summary>
/// Derives the planner's reduced character from a whole character: the trunk box W0 bounds the trunk's bones in the
/// contact pose; each limb's workspace Wk bounds where its contact point goes over random configurations of its
/// joints in which the contact face could rest on a surface the limb may touch (the central part of that cloud,
/// trimmed per axis, so rare extreme reaches do not count). Contacts estimated inside Wk are then ones the whole
/// body can really make.
/// </summary>
internal static class ReducedModelBuilder
{
    /// <summary>
    /// The trunk box of the given joints, bones padded by their radii, in the root joint's frame with the root
    /// joint at the origin and the rig in <paramref name="pose"/>: its centre and half extents, metres.
    /// </summary>
    public static (Vector3 Center, Vector3 HalfExtents) TrunkBox(IReadOnlyList<Joint> joints, IReadOnlyList<int> trunkJoints, IReadOnlyList<float> radii, float[] pose) =>
        TrunkBox(joints, trunkJoints, radii, pose, null);

    /// <summary>
    /// The trunk box of the given joints with the rig in <paramref name="pose"/> and the root joint at the origin
    /// (axes of the trunk frame: +Y up, +Z forward), metres: a trunk joint with points (e.g. its skinned vertices)
    /// counts as those points, one without as a sphere of its radius around the joint.
    /// </summary>
    /// <param name="joints">The rig's joints.</param>
    /// <param name="trunkJoints">Indices of the trunk's joints.</param>
    /// <param name="radii">Radius of each joint, metres.</param>
    /// <param name="pose">One angle per degree of freedom, radians.</param>
    /// <param name="points">For each joint, points in its frame (metres) that bound it; <c>null</c> or an empty list keeps the sphere.</param>
    public static (Vector3 Center, Vector3 HalfExtents) TrunkBox(IReadOnlyList<Joint> joints, IReadOnlyList<int> trunkJoints, IReadOnlyList<float> radii, float[] pose, IReadOnlyList<IReadOnlyList<Vector3>>? points)
    {
        ArgumentNullException.ThrowIfNull(joints);
        ArgumentNullException.ThrowIfNull(trunkJoints);
        ArgumentNullException.ThrowIfNull(radii);
        var rig = new Rig(joints, Vector3.Zero);
        var positions = new Vector3[joints.Count];
        var rotations = new Quaternion[joints.Count];
        rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), pose, positions, rotations);
        Aabb box = Aabb.Empty;
        bool anyPoints = false;
        foreach (int j in trunkJoints)
        {
            if (points is not null && points[j].Count > 0)
            {
                anyPoints = true;
                foreach (Vector3 p in points[j])
                {
                    Vector3 world = positions[j] + Vector3.Transform(p, rotations[j]);
                    box = Aabb.Union(box, new Aabb(world, world));
                }

                continue;
            }

            float r = radii[j];
            box = Aabb.Union(box, new Aabb(positions[j] - new Vector3(r), positions[j] + new Vector3(r)));
        }

        // Vertices may all lie in a plane; a box needs some thickness.
        return (box.Center, anyPoints ? Vector3.Max(box.HalfExtents, new Vector3(0.005f)) : box.HalfExtents);
    }

    /// <summary>
    /// The reduced character of <paramref name="model"/>, with the speeds, friction and required contacts given.
    /// </summary>
    /// <param name="model">The whole character.</param>
    /// <param name="requiredContacts">How many limbs must touch.</param>
    /// <param name="takeoffSpeedMax">Largest takeoff speed, m/s.</param>
    /// <param name="landingSpeedMax">Largest landing speed, m/s.</param>
    /// <param name="friction">Default friction.</param>
    /// <param name="samples">Random configurations per limb.</param>
    /// <param name="trim">Fraction of the cloud cut off at each end of each axis.</param>
    public static ReducedCharacter Derive(CharacterModel model, int requiredContacts, float takeoffSpeedMax, float landingSpeedMax, float friction, int samples = 4_000, float trim = 0.05f)
    {
        ArgumentNullException.ThrowIfNull(model);
        Rig rig = model.Rig;
        (_, Vector3 trunkHalf) = TrunkBox(rig.Joints, model.TrunkJoints, model.BoneRadii, model.ContactPose);
        var identity = new RootPose(Vector3.Zero, Quaternion.Identity);
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        var limbs = new List<Limb>();

        // Each limb's home: where the contact pose holds its contact point, in the trunk frame.
        rig.Solve(identity, model.ContactPose, positions, rotations);
        Vector3[] homes = [.. model.Limbs.Select(l => l.EffectorPosition(positions, rotations))];
        for (int l = 0; l < model.Limbs.Count; l++)
        {
            RigLimb limb = model.Limbs[l];
            var random = new Random(1_000 + l);
            var xs = new List<float>(samples);
            var ys = new List<float>(samples);
            var zs = new List<float>(samples);
            float[] q = (float[])model.ContactPose.Clone();
            for (int s = 0; s < samples * 8 && xs.Count < samples; s++)
            {
                foreach (int d in limb.ChainDofSpan)
                {
                    JointAxis axis = rig.Dofs[d];
                    q[d] = axis.Min + ((float)random.NextDouble() * (axis.Max - axis.Min));
                }

                rig.Solve(identity, q, positions, rotations);

                // The surface under the contact face would have the face's reversed normal: the limb must accept it.
                if (!limb.Filter.Accepts(-limb.EffectorNormal(rotations)))
                {
                    continue;
                }

                Vector3 p = limb.EffectorPosition(positions, rotations);
                xs.Add(p.X);
                ys.Add(p.Y);
                zs.Add(p.Z);
            }

            if (xs.Count < 16)
            {
                throw new RigException($"Character '{model.Name}', limb '{limb.Name}': almost no configuration puts its contact face on a surface it may touch.");
            }

            xs.Sort();
            ys.Sort();
            zs.Sort();
            int lo = (int)(trim * xs.Count);
            int hi = xs.Count - 1 - lo;
            var min = new Vector3(xs[lo], ys[lo], zs[lo]);
            var max = new Vector3(xs[hi], ys[hi], zs[hi]);
            limbs.Add(new Limb(limb.Name, limb.Kind, (min + max) * 0.5f, Vector3.Max((max - min) * 0.5f, new Vector3(0.01f)), Quaternion.Identity, limb.Filter) { Home = homes[l] });
        }

        return new ReducedCharacter(model.Name, trunkHalf, limbs, requiredContacts, takeoffSpeedMax, landingSpeedMax, friction)
        {
            StanceLift = StanceLift(model, requiredContacts, trunkHalf),
            Walking = Walking(model, requiredContacts),
        };
    }

    /// <summary>
    /// Share of the legs' standing height (their root joints above their soles) under which the rig's root joint
    /// standing height is not taken for the leg (<see cref="Walking"/>): a control rig's root bone on the ground.
    /// </summary>
    public const float RootOnTheGround = 0.5f;

    /// <summary>
    /// Walking derived from the rig (<see cref="WalkingLimits.FromLeg"/>): a character with at least two feet that
    /// stands on its feet alone (no more required contacts than feet) walks, its leg length being the root joint's
    /// standing height above its contacts (as in <see cref="StanceLift"/>), or the feet's root joints' where the root
    /// joint stands under <see cref="RootOnTheGround"/> of theirs (a Rigify root bone on the ground), on slopes up to what its feet can stand on
    /// (<see cref="WalkableSlope"/>, and <see cref="WalkableSlopeAlong"/> straight up or down); any other (a frog that needs all four limbs down) only jumps.
    /// </summary>
    public static WalkingLimits Walking(CharacterModel model, int requiredContacts)
    {
        ArgumentNullException.ThrowIfNull(model);
        int feet = model.Limbs.Count(l => l.Kind == LimbKind.Foot);
        if (feet < 2 || requiredContacts > feet)
        {
            return WalkingLimits.None;
        }

        (float rootHeight, _) = Standing(model, requiredContacts);
        float hips = model.LegLengths().DefaultIfEmpty(0f).Max();
        if (rootHeight < RootOnTheGround * hips)
        {
            // The root joint is no hip: a root bone on the ground under the body, as Rigify and other control rigs
            // place one. The leg is the feet's root joints' standing height above their soles.
            rootHeight = hips;
        }

        WalkingLimits walking = WalkingLimits.FromLeg(rootHeight);
        if (!walking.CanWalk)
        {
            return walking;
        }

        FootPlanes planes = Planes(model, rootHeight);
        float slope = SteepestHeld(planes);
        return walking with { MaxSlopeDegrees = slope, MaxSlopeAlongDegrees = SteepestHeldAlong(planes, slope), TurnRate = TurnRate(model), PitchSpan = PitchSpan(model), RollSpan = RollSpan(model) };
    }

    /// <summary>
    /// How fast, at most, a turn in place carries a held foot sideways under the trunk, in that foot's own leg lengths
    /// per second at the average turn rate: a trunk turning by θ moves a foot standing d ahead of (or behind) its
    /// centre sideways by about d·θ. At this rate (1.5 times it at the turn's fastest) the gait's shortest half-cycle
    /// (<see cref="Animation.WalkGait.MinHalfCycle"/>, 0.2 s) turns no more than its feet allow
    /// (<see cref="Animation.WalkGait.TurnDrift"/> of a leg); a rig whose feet stand under its trunk (a biped, a dog)
    /// turns at <see cref="WalkingLimits.DefaultTurnRate"/>, well within it.
    /// </summary>
    public const float TurnSweep = 1.3f;

    /// <summary>
    /// The average rate (radians per second) at which the rig turns in place: <see cref="WalkingLimits.DefaultTurnRate"/>,
    /// or less where a foot of the contact pose stands so far ahead of or behind the trunk's centre that a turn would
    /// carry it sideways faster than <see cref="TurnSweep"/> of its leg per second (an ant's front and hind legs).
    /// </summary>
    public static float TurnRate(CharacterModel model)
    {
        ArgumentNullException.ThrowIfNull(model);
        return model.TurnLimit(TurnSweep, WalkingLimits.DefaultTurnRate);
    }

    /// <summary>
    /// Least distance (a share of the longest leg) by which, in the contact pose, some foot stands ahead of the
    /// trunk's centre and some foot behind it for the walking trunk to pitch with the ground (<see cref="PitchSpan"/>):
    /// a quadruped's or a spider's legs, not a biped's feet side by side.
    /// </summary>
    public const float PitchFeetApart = 0.25f;

    /// <summary>
    /// Half the distance (metres) between the rig's foremost and hindmost feet in the contact pose, along the trunk,
    /// when some foot stands at least <see cref="PitchFeetApart"/> of the longest leg ahead of the trunk's centre and
    /// some as far behind it (a quadruped, a spider): its walking trunk pitches with the ground over that span
    /// (<see cref="WalkingLimits.PitchSpan"/>), so that on a ramp its front legs do not fold while its hind legs
    /// stretch. 0 for a rig whose feet stand under its trunk (a biped): it walks upright.
    /// </summary>
    public static float PitchSpan(CharacterModel model)
    {
        ArgumentNullException.ThrowIfNull(model);
        (float ahead, float behind) = model.FeetAlongTrunk();
        float apart = PitchFeetApart * model.LegLengths().DefaultIfEmpty(0f).Max();
        return apart > 0f && ahead >= apart && behind >= apart ? 0.5f * (ahead + behind) : 0f;
    }

    /// <summary>
    /// Least distance (a share of its own leg) some foot stands out sideways of its hip in the contact pose for the
    /// rig's walking trunk to roll with the ground (<see cref="RollSpan"/>): legs that sprawl, a spider's (1.5 of its
    /// leg) or an ant's (1.7), not a mammal's under its hips (0 for every quadruped and biped made here or elsewhere).
    /// </summary>
    public const float SprawlShare = 0.5f;

    /// <summary>
    /// Half the distance (metres) between the rig's leftmost and rightmost feet in the contact pose, across the
    /// trunk, when some foot stands at least <see cref="SprawlShare"/> of its own leg out sideways of its hip (a
    /// spider, an ant): its walking trunk rolls with the ground over that span (<see cref="WalkingLimits.RollSpan"/>),
    /// so that on a dune's side its downhill feet reach the ground where they stand on the level, not under its body.
    /// 0 for a rig whose feet stand under its hips: its trunk walks level across.
    /// </summary>
    public static float RollSpan(CharacterModel model)
    {
        ArgumentNullException.ThrowIfNull(model);
        (float left, float right, float sprawl) = model.FeetAcrossTrunk();
        return sprawl >= SprawlShare && left > 0f && right > 0f ? 0.5f * (left + right) : 0f;
    }

    /// <summary>Steps (degrees) of the slopes tried by <see cref="WalkableSlope"/>.</summary>
    public const float SlopeStep = 2.5f;

    /// <summary>
    /// How far (a share of the leg) the trunk may stand lower than in the contact pose while <see cref="WalkableSlope"/>
    /// holds the feet on a plane, where they do not hold at its height: a twentieth of the leg, within the stances'
    /// range (<see cref="StanceLowest"/>) and above the eye's upright walk (hips 0.88 of the leg above the held feet).
    /// A rig whose legs are straight in its contact pose (most rigs made elsewhere) cannot move its trunk a tenth of its
    /// leg over a planted foot without bending its knee, on the level or on a slope: at that height the user's human
    /// and dog walked on no slope at all (0°). Lowered, each foot is first placed on the plane by the full IK (as a
    /// stance's contacts are solved) and then held as the gait holds it, the trunk moving a fortieth of the leg at a
    /// time (the gait tracks its feet in fine steps).
    /// </summary>
    public const float SlopeSink = 0.05f;

    /// <summary>
    /// How far (a share of the leg) the trunk may stand lower than in the contact pose in <see cref="WalkableSlope"/>
    /// for a rig whose feet hold no slope at all (not even <see cref="SlopeStep"/>) at its height or
    /// <see cref="SlopeSink"/> lower: a tenth of the leg, the hips then at 0.9 of it, still above the gait's cruise
    /// (<see cref="Animation.WalkGait.CruiseHips"/>, 0.88) and the eye's upright walk. The tailed quadruped's straight
    /// front legs cannot follow the trunk a fortieth of the leg at a twentieth lower (their solve stalls 2.5 mm short
    /// at a joint's limit), and the panda's mid-stride legs hold the level there but no slope: both walked on
    /// exactly level ground alone (0°). Rigs that hold a slope a twentieth lower keep that trial (the user's human and
    /// dog: a tenth lower would give them the 35° cap, steeper than their gait walks well).
    /// </summary>
    public const float LowSlopeSink = 0.1f;

    /// <summary>
    /// The steepest slope (degrees, a multiple of <see cref="SlopeStep"/>, at most
    /// <see cref="WalkingLimits.DefaultMaxSlopeDegrees"/>) the rig's feet can walk on: on a plane of that slope falling
    /// forward, backward, left or right, every foot of the rig holds the point under it in the contact pose by IK with
    /// its sole on the plane as the gait holds it (<see cref="SoleHold"/>), no bone below its effector (toes) under the
    /// plane, while the trunk, upright, stands over it and moves a tenth of <paramref name="legLength"/> either way
    /// along the plane: at the contact pose's height, or <see cref="SlopeSink"/> of the leg lower (legs straight in
    /// their contact pose reach no further, and a walker lowers its hips), or <see cref="LowSlopeSink"/> lower for a
    /// rig whose feet hold no slope at all a twentieth lower. Ankles that cannot tilt the sole as far
    /// as the ground does (a rig's joint limits) give a lower slope: the gait could not hold the feet there, so the
    /// planner does not walk there. 0 when the feet cannot even stand level.
    /// </summary>
    /// <param name="model">The character.</param>
    /// <param name="legLength">The root joint's standing height above its contacts, metres.</param>
    public static float WalkableSlope(CharacterModel model, float legLength)
    {
        ArgumentNullException.ThrowIfNull(model);
        return SteepestHeld(Planes(model, legLength));
    }

    /// <summary><see cref="WalkableSlope"/> on the feet's test made once.</summary>
    private static float SteepestHeld(FootPlanes feet) => Steepest(0f, feet.HoldAnyWay);

    /// <summary>
    /// The feet's test for <paramref name="model"/>: with the trunk <see cref="SlopeSink"/> lower where it holds the
    /// gentlest slope (<see cref="SlopeStep"/>) any way there, else <see cref="LowSlopeSink"/> lower.
    /// </summary>
    private static FootPlanes Planes(CharacterModel model, float legLength)
    {
        var feet = new FootPlanes(model, legLength, SlopeSink);
        return feet.HoldAnyWay(SlopeStep) ? feet : new FootPlanes(model, legLength, LowSlopeSink);
    }

    /// <summary>
    /// The steepest slope (degrees, a multiple of <see cref="SlopeStep"/>, from <paramref name="slope"/> to
    /// <see cref="WalkingLimits.DefaultMaxSlopeDegrees"/>) the rig's feet can walk straight up or down
    /// (<see cref="WalkingLimits.MaxSlopeAlongDegrees"/>): one <see cref="SlopeStep"/> less than the steepest on whose
    /// planes the feet hold as in <see cref="WalkableSlope"/>, falling forward or backward, and falling partly to the
    /// side, by <paramref name="slope"/> across (each way); never less than <paramref name="slope"/>. An ankle usually
    /// bends further than it rolls, so this is steeper than <paramref name="slope"/>, the slope held whichever way the
    /// ground falls. The step less is for ground that is not a plane: a walk straight up a slope crosses crests and
    /// hollows where the stride meets steeper ground than the path (on the bundled desert, 71 % of the walks planned
    /// animate with 25° and 65 % with the planes' 27.5°, for the skeleton).
    /// </summary>
    /// <param name="model">The character.</param>
    /// <param name="legLength">The root joint's standing height above its contacts, metres.</param>
    /// <param name="slope">The slope held whichever way the ground falls (<see cref="WalkableSlope"/>), degrees.</param>
    public static float WalkableSlopeAlong(CharacterModel model, float legLength, float slope)
    {
        ArgumentNullException.ThrowIfNull(model);
        return SteepestHeldAlong(Planes(model, legLength), slope);
    }

    /// <summary><see cref="WalkableSlopeAlong"/> on the feet's test made once.</summary>
    private static float SteepestHeldAlong(FootPlanes feet, float slope)
    {
        float cosAcross = MathF.Cos(slope * MathF.PI / 180f);
        float planes = Steepest(slope, degrees =>
        {
            // Normals (x across, z along) of slope `degrees` whose fall across the walk is `slope`: tan(across) =
            // |x| / y with y = cos(degrees), so z² = 1 − y² / cos²(slope).
            float angle = degrees * MathF.PI / 180f;
            float y = MathF.Cos(angle);
            float x = y * MathF.Tan(slope * MathF.PI / 180f);
            float z = MathF.Sqrt(MathF.Max(0f, 1f - (y * y / (cosAcross * cosAcross))));
            var planes = new List<Vector3> { new(0f, y, MathF.Sin(angle)), new(0f, y, -MathF.Sin(angle)) };
            if (slope > 0f)
            {
                planes.AddRange([new(x, y, z), new(-x, y, z), new(x, y, -z), new(-x, y, -z)]);
            }

            return planes.All(feet.Hold);
        });
        return MathF.Max(slope, planes - SlopeStep);
    }

    /// <summary>The steepest multiple of <see cref="SlopeStep"/> from <paramref name="from"/> up to the default limit for which <paramref name="holds"/> (and every step below it) holds; <paramref name="from"/> when none does.</summary>
    private static float Steepest(float from, Func<float, bool> holds)
    {
        float slope = from;
        for (float degrees = from; degrees <= WalkingLimits.DefaultMaxSlopeDegrees + 1e-3f; degrees += SlopeStep)
        {
            if (!holds(degrees))
            {
                break;
            }

            slope = degrees;
        }

        return slope;
    }

    /// <summary>The feet of a rig held on planes through the points under them in its contact pose (<see cref="WalkableSlope"/>).</summary>
    private sealed class FootPlanes
    {
        private readonly CharacterModel _model;
        private readonly SoleHold _sole;
        private readonly Vector3[] _positions;
        private readonly Quaternion[] _rotations;
        private readonly RigLimb[] _feet;
        private readonly Vector3[] _stands;
        private readonly int[][] _below;
        private readonly float _shift;

        /// <summary>The full IK (restarts and all) that places a foot on the plane under a lowered trunk before it is held.</summary>
        private readonly LimbIk _place;

        /// <summary>Each plane's verdict (by its normal), once tested: the slope tests ask again for the planes they share.</summary>
        private readonly Dictionary<Vector3, bool> _held = [];

        /// <summary>How far the trunk may stand lower than in the contact pose, metres (<see cref="SlopeSink"/> or <see cref="LowSlopeSink"/> of the leg).</summary>
        private readonly float _sink;

        /// <summary>The trunk's places along the plane with the trunk lowered (metres): out to the shift, back to the other side, home again, a quarter of the shift at a time.</summary>
        private readonly float[] _fineShifts;

        public FootPlanes(CharacterModel model, float legLength, float sink)
        {
            _model = model;
            Rig rig = model.Rig;
            _sole = new SoleHold(rig);
            _place = new LimbIk(rig, new IkSettings { NormalTolerance = SoleHold.FlatTolerance, ReleaseLimits = true });
            _positions = new Vector3[rig.Joints.Count];
            _rotations = new Quaternion[rig.Joints.Count];
            _feet = [.. model.Limbs.Where(l => l.Kind == LimbKind.Foot)];
            rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), model.ContactPose, _positions, _rotations);
            _stands = [.. _feet.Select(l => l.EffectorPosition(_positions, _rotations))];
            _below = [.. _feet.Select(l => Enumerable.Range(0, rig.Joints.Count).Where(j => j != l.EffectorJoint && rig.IsAncestor(l.EffectorJoint, j)).ToArray())];
            _shift = 0.1f * legLength;
            _sink = sink * legLength;
            _fineShifts = [.. Enumerable.Range(0, 17).Select(i => (i <= 4 ? i : i <= 12 ? 8 - i : i - 16) * 0.25f * _shift)];
        }

        /// <summary>True when the feet hold planes of <paramref name="degrees"/> falling forward, backward, left and right (<see cref="Hold"/>).</summary>
        public bool HoldAnyWay(float degrees)
        {
            float angle = degrees * MathF.PI / 180f;
            return new[] { Vector3.UnitZ, -Vector3.UnitZ, Vector3.UnitX, -Vector3.UnitX }.All(down => Hold((down * MathF.Sin(angle)) + (Vector3.UnitY * MathF.Cos(angle))));
        }

        /// <summary>
        /// True when every foot holds the plane of unit normal <paramref name="normal"/> (rig frame: +Z forward, +X to
        /// the side) while the upright trunk moves forward and back along it, at the contact pose's height or
        /// <see cref="_sink"/> lower.
        /// </summary>
        public bool Hold(Vector3 normal)
        {
            if (!_held.TryGetValue(normal, out bool held))
            {
                _held[normal] = held = HoldAt(normal, 0f) || HoldAt(normal, _sink);
            }

            return held;
        }

        /// <summary><see cref="Hold"/> with the trunk <paramref name="sink"/> metres lower than in the contact pose (0: at its height, each foot starting from its contact pose).</summary>
        private bool HoldAt(Vector3 normal, float sink)
        {
            Rig rig = _model.Rig;
            for (int f = 0; f < _feet.Length; f++)
            {
                float[] q = (float[])_model.ContactPose.Clone();
                if (sink > 0f && !_place.Reaches(new RootPose(new Vector3(0f, -sink, 0f), Quaternion.Identity), q, _feet[f], _stands[f], -normal))
                {
                    return false;
                }

                // At the contact pose's height the trunk's places are the four it always had (the preset characters'
                // limits, the README's 22.5° and 25°, come from them); lowered, the fine ones.
                foreach (float x in sink > 0f ? _fineShifts : [0f, _shift, -_shift, 0f])
                {
                    // The trunk moves along the plane, keeping its height above it.
                    var root = new RootPose(new Vector3(0f, (-x * normal.Z / normal.Y) - sink, x), Quaternion.Identity);
                    float[] trial = (float[])q.Clone();
                    if (!_sole.Hold(root, trial, _feet[f], _stands[f], normal))
                    {
                        return false;
                    }

                    rig.Solve(root, trial, _positions, _rotations);
                    foreach (int j in _below[f])
                    {
                        if (Vector3.Dot(_positions[j] - _stands[f], normal) < -BodyClearance)
                        {
                            return false;
                        }
                    }

                    q = trial;
                }
            }

            return true;
        }
    }

    /// <summary>How far (metres) a toe may dip under the plane in <see cref="WalkableSlope"/>: 5 mm, within what the level's collision checks let a held foot's bones touch near its contact (1 cm).</summary>
    private const float BodyClearance = 0.005f;

    /// <summary>Lowest share of the rest-pose root height the root keeps above its contacts in stance.</summary>
    public const float StanceLowest = 0.7f;

    /// <summary>
    /// The range of heights (metres) of the trunk centre above the supporting surface in stance: the root joint
    /// between <see cref="StanceLowest"/> and 100 % of its standing height above the contacts, the trunk centre
    /// keeping its offset from the root joint. The standing height is the higher of the rest pose's (every angle at
    /// zero: legs as modelled, near straight for a humanoid) and the contact pose's (for rigs modelled with splayed
    /// legs, such as an insect); the contacts are the <paramref name="requiredContacts"/> lowest limbs' contact points.
    /// </summary>
    public static HeightRange StanceLift(CharacterModel model, int requiredContacts, Vector3 trunkHalfExtents)
    {
        ArgumentNullException.ThrowIfNull(model);
        (float rootHeight, float centreAboveRoot) = Standing(model, requiredContacts);
        float floor = trunkHalfExtents.Y + 0.02f;
        float max = MathF.Max(floor, rootHeight + centreAboveRoot);
        float min = Math.Clamp((StanceLowest * rootHeight) + centreAboveRoot, floor, max);
        return new HeightRange(min, max);
    }

    /// <summary>The root joint's standing height above its lowest contacts and the trunk centre's height above the root joint, metres.</summary>
    private static (float RootHeight, float CentreAboveRoot) Standing(CharacterModel model, int requiredContacts)
    {
        Rig rig = model.Rig;
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        float rootHeight = 0f;
        float centreAboveRoot = 0f;
        foreach (float[] pose in new[] { rig.Neutral(), model.ContactPose })
        {
            rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), pose, positions, rotations);
            float contacts = model.Limbs
                .Select(l => l.EffectorPosition(positions, rotations).Y)
                .Order()
                .Take(Math.Clamp(requiredContacts, 1, model.Limbs.Count))
                .Average();
            rootHeight = MathF.Max(rootHeight, positions[0].Y - contacts); // root joint above the contacts
            centreAboveRoot = -positions[0].Y; // the trunk centre is the origin
        }

        return (rootHeight, centreAboveRoot);
    }
}
