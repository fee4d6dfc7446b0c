using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;

namespace Ballistic.Planner.Animation;

/// <summary>
/// The root's dip on the ground around a jump, as an animator keys it: before takeoff the body sinks (a
/// countermovement, the legs flexing on their contacts) and drives up through the takeoff pose; after landing it keeps
/// sinking to absorb the impact before it rises. The root moves straight down (world −Y) from the contact pose by up to
/// <see cref="DepthShare"/> of the leg length; every limb in contact holds its point by IK at each depth (no bone in
/// the level, no trunk bone in it), free limbs fold toward the <c>flexion</c> pose with the depth where they stay clear;
/// where the legs cannot fold that far straight down, the body sinks leaning back or forward along its heading, or
/// pitching (a frog sinks onto its hind legs, its front held up).
/// Where a contact cannot be held (for a rig loaded from a file: with its sole flat on the surface), or (for such a rig) an ankle or wrist holding one would fold more than
/// 20° from its contact pose, the dip stops at the last depth that held. Timings scale with the leg's pendulum time
/// √(L/g) and the jump's speed. Each call works on buffers of its own; the IK solver is shared, as the animator's is.
/// </summary>
internal sealed class StanceDip
{
    /// <summary>Deepest dip, as a share of the leg length (the standing hip's height above the sole, or the rest pose's when longer).</summary>
    public const float DepthShare = 0.15f;

    /// <summary>Shallowest dip that reads as a crouch or a landing absorbed, as a share of the leg length; shallower is a problem of the jump.</summary>
    public const float LeastDepthShare = 0.085f;

    /// <summary>Least time (seconds) on the ground between a landing and the next takeoff.</summary>
    public const float MinGroundTime = 0.2f;

    /// <summary>
    /// Most (radians, 20°) a held effector joint of a rig loaded from a file turns from its contact pose as the body
    /// sinks: its skin is blended with the bone above, and folding further presses the sole's skin into the ground.
    /// </summary>
    internal const float MaxEffectorFold = 20f * MathF.PI / 180f;

    /// <summary>Depth samples solved from the contact pose down to the deepest dip.</summary>
    private const int Samples = 12;

    private readonly CharacterModel _model;
    private readonly LimbIk _ik;
    private readonly BodyCollision _collision;
    private readonly FreeBones _free;
    private readonly float _restLeg;
    private readonly Vector3 _pivot;

    /// <summary>A dip solver for <paramref name="model"/>, its contacts held by <paramref name="ik"/>, bones checked by <paramref name="collision"/>, free bones (a tail) bent clear by <paramref name="free"/>, free feet kept near their <paramref name="places"/>.</summary>
    public StanceDip(CharacterModel model, LimbIk ik, BodyCollision collision, FreeBones free, FootPlaces places)
    {
        _model = model;
        _places = places;
        _ik = ik;
        _collision = collision;
        _free = free;

        var positions = new Vector3[model.Rig.Joints.Count];
        model.Rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), model.Rig.Neutral(), positions, new Quaternion[model.Rig.Joints.Count]);
        _pivot = positions[0];
        _restLeg = RestLegLength(model);
    }

    /// <summary>Where the contact pose holds each limb's effector across the trunk: its place.</summary>
    private readonly FootPlaces _places;

    /// <summary>
    /// Farthest (share of the standing leg) a free foot folding toward the flexion pose as the body sinks may stand
    /// sideways of its place (<see cref="FootPlaces"/>); farther, it keeps its pose (a spider's flexion pose draws its
    /// feet 0.4 L in under its body).
    /// </summary>
    private const float FoldSideways = 0.3f;

    /// <summary>
    /// The standing leg (metres): a foot's root joint's greatest height above its contact point with every angle at
    /// rest (a rig modelled standing) or in the spec's contact pose, whichever is higher (a rig modelled with its legs
    /// spread flat, an insect's, stands only in its contact pose); 0 without feet.
    /// </summary>
    public static float RestLegLength(CharacterModel model) => model.LegLengths().DefaultIfEmpty(0f).Max();

    /// <summary>
    /// How the body sinks from a contact pose at <paramref name="Root"/>, moving along −<paramref name="Up"/> and
    /// pitching nose up by <paramref name="Pitch"/> radians per metre of drop about the root joint (at
    /// <paramref name="Pivot"/> in the trunk's frame, so that the joint drops exactly the depth): the <paramref name="Angles"/> at evenly spaced
    /// depths from 0 (exactly the contact pose's) to <paramref name="Depth"/> metres, the deepest that every contact
    /// held; <paramref name="Leg"/> is the leg length, metres; <paramref name="Stop"/> says what stopped the dip short
    /// of <see cref="DepthShare"/> of the leg, or is null.
    /// </summary>
    public sealed record Table(RootPose Root, Vector3 Up, float Pitch, Vector3 Pivot, float Depth, float[][] Angles, float Leg, string? Stop = null)
    {
        /// <summary>The root at <paramref name="depth"/> metres below the contact pose.</summary>
        public RootPose RootAt(float depth) => Dipped(Root, Up, Pitch, Pivot, depth);

        /// <summary>The angles at <paramref name="depth"/> metres (clamped to the table), interpolated between samples.</summary>
        public float[] AnglesAt(float depth)
        {
            if (Angles.Length == 1 || !(Depth > 0f))
            {
                return (float[])Angles[0].Clone();
            }

            float x = Math.Clamp(depth / Depth, 0f, 1f) * (Angles.Length - 1);
            int i = Math.Min((int)x, Angles.Length - 2);
            float w = x - i;
            var q = new float[Angles[i].Length];
            for (int d = 0; d < q.Length; d++)
            {
                q[d] = float.Lerp(Angles[i][d], Angles[i + 1][d], w);
            }

            return q;
        }
    }

    /// <summary>The leg length (metres): the greatest height, along the trunk's up axis, of a foot's root joint above where the foot stands; 0.5 m without feet.</summary>
    public static float LegLength(CharacterModel model, ContactConfiguration config, Vector3[] positions, Quaternion[] rotations)
    {
        float leg = 0f;
        model.Rig.Solve(config.Root, config.Angles, positions, rotations);
        for (int l = 0; l < model.Limbs.Count; l++)
        {
            RigLimb limb = model.Limbs[l];
            if (limb.Kind == LimbKind.Foot)
            {
                Vector3 foot = config.ContactOf(l) is LimbContact c ? c.Position : limb.EffectorPosition(positions, rotations);
                leg = MathF.Max(leg, Vector3.Dot(positions[limb.RootJoint] - foot, config.Root.Up));
            }
        }

        return leg > 0f ? leg : 0.5f;
    }

    /// <summary>
    /// Solves the dip table of <paramref name="config"/> (its contacts held, its free limbs folding): the root sinks
    /// straight down, or down and back, or down and forward along the trunk's heading (the legs that cannot fold more
    /// reaching out instead), whichever goes deepest; the first that reaches <see cref="DepthShare"/> of the leg wins.
    /// </summary>
    public Table Solve(ContactConfiguration config)
    {
        Rig rig = _model.Rig;
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        float leg = MathF.Max(LegLength(_model, config, positions, rotations), _restLeg);
        if (config.Contacts.Count == 0)
        {
            return new Table(config.Root, Vector3.UnitY, 0f, _pivot, 0f, [(float[])config.Angles.Clone()], leg);
        }

        // Motions tried: straight down, leaning back or forward along the heading, pitching nose up (the body sinking
        // onto its hind legs, the front held up) or nose down, so that the front rises or falls about as much as the
        // root sinks.
        Vector3 heading = config.Root.Forward with { Y = 0f };
        heading = heading.LengthSquared() > 1e-8f ? Vector3.Normalize(heading) : Vector3.Zero;
        rig.Solve(config.Root, config.Angles, positions, rotations);
        float reach = 0f;
        foreach (RigLimb limb in _model.Limbs)
        {
            reach = MathF.Max(reach, MathF.Abs(Vector3.Dot(positions[limb.RootJoint] - config.Root.Position, config.Root.Forward)));
        }

        float pitch = 1f / MathF.Max(reach, 0.5f * leg);
        (float Lean, float Pitch)[] motions = [(0f, 0f), (0.5f, 0f), (-0.5f, 0f), (0f, pitch), (0f, -pitch)];
        Table? best = null;
        foreach ((float lean, float turn) in motions)
        {
            Table table = Solve(config, Vector3.UnitY - (lean * heading), turn, leg, positions, rotations);
            if (best is null || table.Depth > best.Depth + 1e-5f)
            {
                best = table;
            }

            if (best.Stop is null)
            {
                break;
            }
        }

        return best!;
    }

    /// <summary>The dip along −<paramref name="up"/> pitching nose up by <paramref name="pitch"/> (per metre of drop), as deep as every contact holds.</summary>
    private Table Solve(ContactConfiguration config, Vector3 up, float pitch, float leg, Vector3[] positions, Quaternion[] rotations)
    {
        Rig rig = _model.Rig;
        float deepest = DepthShare * leg;
        var table = new List<float[]> { (float[])config.Angles.Clone() };
        float[] q = (float[])config.Angles.Clone();
        string? stop = null;
        for (int k = 1; k <= Samples; k++)
        {
            float depth = deepest * k / Samples;
            float fold = depth / deepest;
            RootPose root = Dipped(config.Root, up, pitch, _pivot, depth);
            float[] next = (float[])q.Clone();
            foreach (LimbContact c in config.Contacts)
            {
                if (Hold(_ik, _model, _collision, root, next, _model.Limbs[c.Limb], c.Position, c.Normal, config.Angles, positions, rotations) is string why)
                {
                    stop = $"{_model.Limbs[c.Limb].Name} {why} {depth * 100f:0.0} cm down";
                    break;
                }
            }

            if (stop is null)
            {
                // A tail behind the sinking body bends up out of the step it would enter.
                (int bone, next) = _free.Colliding(root, next, positions, rotations);
                if (bone >= 0)
                {
                    stop ??= $"bone '{rig.Joints[bone].Name}' enters the level {depth * 100f:0.0} cm down";
                }
            }

            if (stop is not null)
            {
                break;
            }

            // Free limbs fold toward the flexion pose as the body sinks, where they stay clear of the level.
            for (int l = 0; l < _model.Limbs.Count; l++)
            {
                if (config.ContactOf(l) is not null)
                {
                    continue;
                }

                // Half-way to the flexion pose at the deepest (a foot no farther than FoldSideways from its place);
                // else as it was; else a quarter, then half of the way on from where it was to the flexion pose; else
                // tucked up fully: the least move that stays clear first, so that a limb does not tuck fully at one
                // depth and unfold at the next (a Rigify panda's free forelimb absorbing a landing on a 29° dune face,
                // 33° and 35° in a displayed frame between frames of 9–15°). Each clear at this depth and half-way
                // between its angles and the last depth's at the depth between, as a player interpolates the rows: a
                // spider's free leg, raised for its landing, tucked fully in one row and swept through a plank between them.
                RigLimb limb = _model.Limbs[l];
                bool clear = false;
                foreach ((bool onFromLast, float share) in ((bool, float)[])[(false, 0.5f * fold), (true, 0f), (true, 0.25f), (true, 0.5f), (true, 1f)])
                {
                    float[] folded = (float[])next.Clone();
                    foreach (int d in limb.ChainDofSpan)
                    {
                        folded[d] = float.Lerp(onFromLast ? next[d] : config.Angles[d], _model.FlexionPose[d], share);
                    }

                    rig.Solve(root, folded, positions, rotations);
                    if (!onFromLast && share > 0f && limb.Kind == LimbKind.Foot && _restLeg > 0f
                        && _places.Off(l, root, limb.EffectorPosition(positions, rotations)) > FoldSideways * _restLeg)
                    {
                        continue;
                    }

                    if (_collision.LimbCollides(limb, positions, rotations, null))
                    {
                        continue;
                    }

                    if (ClearBetween(limb, next, folded, depth, deepest / Samples, config.Root, up, pitch, positions, rotations))
                    {
                        Array.Copy(folded, next, next.Length);
                        clear = true;
                        break;
                    }
                }

                if (!clear)
                {
                    stop ??= $"{limb.Name}, in the air, would touch the level {depth * 100f:0.0} cm down";
                    break;
                }
            }

            if (stop is not null)
            {
                break;
            }

            table.Add(next);
            q = next;
        }

        return new Table(config.Root, up, pitch, _pivot, deepest * (table.Count - 1) / Samples, [.. table], leg, stop);
    }

    /// <summary>Points between two rows of a dip at which a free limb moving between them is checked clear of the level (<see cref="ClearBetween"/>).</summary>
    private const int BetweenChecks = 8;

    /// <summary>
    /// True when <paramref name="limb"/>, free, stays clear of the level as a player interpolates from its angles in
    /// <paramref name="from"/> (the row <paramref name="row"/> metres above <paramref name="depth"/>) to those in
    /// <paramref name="to"/> (at <paramref name="depth"/>): checked at <see cref="BetweenChecks"/> − 1 points between,
    /// the root and the angles interpolated alike. Checked at the half-way point alone, a Rigify panda's free forefoot
    /// folding 20 cm up from its place on a dune swept 2 mm through the sand a third of the way.
    /// </summary>
    private bool ClearBetween(RigLimb limb, float[] from, float[] to, float depth, float row, in RootPose root, Vector3 up, float pitch, Vector3[] positions, Quaternion[] rotations)
    {
        float[] between = (float[])to.Clone();
        for (int k = 1; k < BetweenChecks; k++)
        {
            float w = k / (float)BetweenChecks;
            foreach (int d in limb.ChainDofSpan)
            {
                between[d] = float.Lerp(from[d], to[d], w);
            }

            _model.Rig.Solve(Dipped(root, up, pitch, _pivot, depth - ((1f - w) * row)), between, positions, rotations);
            if (_collision.LimbCollides(limb, positions, rotations, null))
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>
    /// Holds <paramref name="limb"/> on <paramref name="point"/> (surface normal <paramref name="normal"/>) by IK into
    /// <paramref name="q"/> with the root at <paramref name="root"/>, as a dip holds it: the sole or palm flat on the
    /// surface where it can, otherwise rolling on its point (a heel lifting in a deep crouch, a frog's wrist), the limb
    /// clear of the level. Not a user's skinned paw: rolling on its point, or folding its ankle or wrist more than
    /// <see cref="MaxEffectorFold"/> from <paramref name="reference"/>, presses the sole's blended skin into the
    /// ground (linear blend skinning; 2.4 cm measured on the tailed quadruped's front paws), and neither may its
    /// foot's skin sink more than <see cref="BodyCollision.SkinDepth"/> below the surface's plane as the shin leans
    /// (<see cref="BodyCollision.SoleSink"/>). Returns why it cannot ("cannot hold its contact", "would fold its
    /// 'ankle' more than 20°", "enters the level", "would press its sole's skin into the ground"), or <c>null</c>.
    /// </summary>
    internal static string? Hold(LimbIk ik, CharacterModel model, BodyCollision collision, in RootPose root, float[] q, RigLimb limb, Vector3 point, Vector3 normal, float[] reference, Vector3[] positions, Quaternion[] rotations, int seed = 0)
    {
        bool skinned = model.Source is not null;
        if (!ik.Reaches(root, q, limb, point, -normal, seed) && (skinned || !ik.Reaches(root, q, limb, point, null, seed)))
        {
            return "cannot hold its contact";
        }

        Rig rig = model.Rig;
        if (skinned && rig.JointTurn(limb.EffectorJoint, q, reference) > MaxEffectorFold)
        {
            return $"would fold its '{rig.Joints[limb.EffectorJoint].Name}' more than {MaxEffectorFold * 180f / MathF.PI:0}°";
        }

        rig.Solve(root, q, positions, rotations);
        if (collision.LimbCollides(limb, positions, rotations, point))
        {
            return "enters the level";
        }

        // A loaded rig's foot skin blended with the shin sinks below the sole as the shin leans (a Rigify panda's, in
        // a deep crouch on a tread tilted 8°: 1.7 cm): the dip goes no deeper than the skin stays on the ground.
        return skinned && collision.HasSoleSkin(limb) && collision.SoleSink(limb, positions, rotations, point, Vector3.Normalize(normal)) > BodyCollision.SkinDepth
            ? "would press its sole's skin into the ground"
            : null;
    }

    /// <summary>
    /// <paramref name="root"/> with its joint at <paramref name="pivot"/> (trunk frame) moved <paramref name="depth"/>
    /// metres along −<paramref name="up"/>, the trunk pitched nose up about it by <paramref name="pitch"/> radians per metre.
    /// </summary>
    private static RootPose Dipped(RootPose root, Vector3 up, float pitch, Vector3 pivot, float depth)
    {
        Quaternion rotation = Quaternion.Normalize(root.Rotation * Quaternion.CreateFromAxisAngle(Vector3.UnitX, -pitch * depth));
        return new RootPose(root.Position - (depth * up) + Vector3.Transform(pivot, root.Rotation) - Vector3.Transform(pivot, rotation), rotation);
    }

    /// <summary>Seconds for the body to sink into its crouch, or to absorb a landing at <paramref name="speed"/> m/s.</summary>
    public static float SinkTime(Table table, float speed) => Between(3f * table.Depth / MathF.Max(speed, 0.5f), 0.1f, 0.7f * Pendulum(table));

    /// <summary>Seconds for the body to drive up from its crouch to the takeoff pose at <paramref name="speed"/> m/s.</summary>
    public static float PushTime(Table table, float speed) => Between(2.5f * table.Depth / MathF.Max(speed, 0.5f), 0.08f, 0.45f * Pendulum(table));

    /// <summary>
    /// The drive up out of <paramref name="table"/>'s dip over <paramref name="duration"/> seconds into a takeoff at
    /// <paramref name="velocity"/> (m/s, world): the depth's share (1 at the dip's bottom, 0 at the contact pose) at a
    /// share of the time, from rest at the bottom to rising along the dip's up axis as fast as the takeoff does (its
    /// velocity's component along that axis, at most <see cref="MostDipRate"/> times the mean rate; none for a takeoff
    /// going down), so that the legs extend on into the flight without a jolt. A cubic: at twice the mean rate (the
    /// push before 2026-12-05, whatever the takeoff) it accelerates evenly.
    /// </summary>
    public static Func<float, float> Push(Table table, float duration, Vector3 velocity)
    {
        float k = PushEndRate(table, duration, velocity);
        return s => 1f + ((k - 3f) * s * s) + ((2f - k) * s * s * s);
    }

    /// <summary>
    /// The rate at which <see cref="Push"/> (over <paramref name="duration"/> seconds into a takeoff at
    /// <paramref name="velocity"/>, m/s, world) ends rising, in times the dip's mean rate (depth over duration): its
    /// depth share falls that many times faster than on average in its last instant.
    /// </summary>
    public static float PushEndRate(Table table, float duration, Vector3 velocity) => Rate(table, duration, Vector3.Dot(velocity, table.Up));

    /// <summary>
    /// The sink into <paramref name="table"/>'s dip over <paramref name="duration"/> seconds after a landing at
    /// <paramref name="velocity"/> (m/s, world): the depth's share (0 at the contact pose, 1 at the dip's bottom) at a
    /// share of the time, sinking at first as fast as the landing comes down along the dip's up axis (at most
    /// <see cref="MostDipRate"/> times the mean rate), coming to rest at the bottom: <see cref="Push"/> played backwards.
    /// </summary>
    public static Func<float, float> Sink(Table table, float duration, Vector3 velocity)
    {
        Func<float, float> push = Push(table, duration, -velocity);
        return s => push(1f - s);
    }

    /// <summary>
    /// Most a push ends (a sink starts) at, in times the dip's mean rate (depth over duration). Up to 3 the depth
    /// changes one way only; at 3 the push's drive would peak in its last instant, and the spider's free legs, still
    /// folding with the depth, swept a foot bone into the debris between two frames.
    /// </summary>
    internal const float MostDipRate = 2.5f;

    /// <summary>A speed (m/s) along the dip's up axis over the mean rate of a dip of <paramref name="duration"/> seconds, within [0, <see cref="MostDipRate"/>].</summary>
    private static float Rate(Table table, float duration, float speed) =>
        table.Depth > 0f && duration > 0f ? Math.Clamp(speed * duration / table.Depth, 0f, MostDipRate) : 2f;

    /// <summary>Seconds for the body to rise back to its stance after absorbing, or to settle into a crouch from standing.</summary>
    public static float RiseTime(Table table) => MathF.Max(0.15f, 0.8f * Pendulum(table));

    /// <summary><paramref name="x"/> within [<paramref name="least"/>, <paramref name="most"/>], the least winning when they cross.</summary>
    private static float Between(float x, float least, float most) => MathF.Max(least, MathF.Min(x, most));

    /// <summary>The leg's pendulum time √(L/g), seconds.</summary>
    private static float Pendulum(Table table) => MathF.Sqrt(table.Leg / 9.81f);
}
