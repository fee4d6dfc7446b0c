using System.Numerics;
using System.Runtime.InteropServices;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;

namespace Ballistic.Planner.Animation;

/// <summary>
/// Checks that no bone of the character passes through the level. Every bone is the segment from its parent joint
/// to its joint, tested as a box around the segment: a limb's bones (its chain and everything below its effector,
/// such as toes, plus the segment from the effector to its contact point) are thin, since feet rest on the
/// surface; every other bone (spine, neck, head, tail, ears) is as thick as half its radius
/// (<see cref="CharacterModel.BoneRadii"/>), since it should not even touch the level, unless its parent's skin is
/// probed over its faces (a loaded rig's: that skin is the bone's flesh, checked point by point). Within
/// <see cref="ContactClearance"/> of a held contact point a bone may touch. Helper bones of a loaded rig that are no
/// body part (<see cref="CharacterSource.BodyBones"/>) are not checked. A loaded rig's limbs are also checked by
/// points of their skinned mesh (<see cref="CharacterSource.SkinProbes"/>: toes and heels reach beyond the segments
/// between joints; <see cref="CharacterSource.BlendProbes"/>: skin weighted to several of the limb's bones, posed by
/// linear blend skinning), and a character built in code by the corners of its bone boxes (<see cref="BoneBoxes"/>, the body
/// its GLB draws): none may be more than <see cref="SkinDepth"/> inside the level, when the level's triangles are
/// given. Thread-safe.
/// </summary>
internal sealed class BodyCollision
{
    /// <summary>Distance from a contact point within which a bone may touch the surface, metres.</summary>
    public const float ContactClearance = 0.01f;

    /// <summary>
    /// Deepest (metres) a point of a loaded rig's skinned limb may be inside the level: a held sole lies on the
    /// surface within a centimetre or so; a toe digging in goes deeper.
    /// </summary>
    public const float SkinDepth = 0.015f;

    /// <summary>
    /// Deepest (metres) a corner of a built character's held foot box may press into the surface it stands on: its box
    /// held within the IK's normal tolerance tilts an edge that far down (the animator's eye allows 2 cm).
    /// </summary>
    public const float SoleDepth = 0.02f;

    /// <summary>Farthest (metres) a held contact point lies off the plane of the surface its foot stands on.</summary>
    private const float ContactPlane = 0.01f;

    /// <summary>How far (metres) around a skin point the level's surface is looked for: deeper points are not seen.</summary>
    internal const float SkinReach = 0.1f;

    /// <summary>
    /// Metres within which two triangles count as equally near a point (an edge or corner they share): well above the
    /// rounding of single-precision coordinates tens of metres from the origin, well below any depth that matters.
    /// </summary>
    internal const float EdgeTie = 1e-4f;

    /// <summary>Half-thickness of a limb bone's box, metres.</summary>
    private const float Thickness = 0.002f;

    /// <summary>Least height (metres) in front of a triangle's plane at which <see cref="Inside"/> takes a point to be in front of it without the full test.</summary>
    private const float FrontMargin = 1e-3f;

    private readonly TriangleBvh _bvh;
    private readonly CharacterModel _model;
    private readonly int[][] _limbBones;
    private readonly int[] _otherBones;
    private readonly float[] _otherThickness;

    /// <summary>
    /// How far (metres) beyond its ends' bounds a bone of no limb checked as a box of its thickness can reach: twice
    /// the thickest, so that a box around every such bone's ends grown by it holds every bone's box.
    /// </summary>
    private readonly float _otherReach;
    private readonly Triangle[]? _triangles;

    /// <summary>Each level triangle's bounds and unit normal (<see cref="Inside"/> reads them for every skin point), computed once.</summary>
    private readonly (Aabb Bounds, Vector3 Normal)[] _shapes = [];
    private readonly (int Joint, Vector3 Point, SkinBlend[]? Blend)[][] _probes;
    private readonly float[] _probeReach;

    /// <summary>Per limb: the probes of its foot's skin (<see cref="SoleSink"/>).</summary>
    private readonly (int Joint, Vector3 Point, SkinBlend[]? Blend)[][] _soleProbes;

    /// <summary>Per limb: its foot's skin as the GLB draws it (<see cref="SoleHeight"/>): a bone's blended points where it has any, else its own.</summary>
    private readonly (int Joint, Vector3 Point, SkinBlend[]? Blend)[][] _drawnSoleProbes;
    private readonly (int Joint, (int Joint, Vector3 Point, SkinBlend[]? Blend)[] Probes)[] _freeSkins;

    /// <summary>Per bone of <see cref="_freeSkins"/>: how far from its joint its posed skin can lie.</summary>
    private readonly SkinReachBound[] _freeReach;

    /// <summary>The skin of bones that belong to no limb (<see cref="OtherBoneColliding(ReadOnlySpan{Vector3}, ReadOnlySpan{Quaternion})"/>), each bone's probes with the bound of how far from its joint they lie posed.</summary>
    internal IEnumerable<(int Joint, (int Joint, Vector3 Point, SkinBlend[]? Blend)[] Probes, SkinReachBound Bound)> FreeSkins =>
        _freeSkins.Select((f, i) => (f.Joint, f.Probes, _freeReach[i]));

    /// <summary>Each thread's list of triangles near a limb's skin (the check runs at every fine step of every limb).</summary>
    [ThreadStatic]
    private static List<int>? s_near;

    /// <summary>Each thread's triangles nearly as near a skin point as the nearest (<see cref="Inside"/>).</summary>
    [ThreadStatic]
    private static List<(int Triangle, float Distance, float Front)>? s_candidates;

    /// <summary>Creates a checker of <paramref name="model"/>'s bones against a level.</summary>
    public BodyCollision(TriangleBvh bvh, CharacterModel model)
        : this(bvh, model, null)
    {
    }

    /// <summary>
    /// Creates a checker of <paramref name="model"/>'s bones, and of a loaded rig's skinned limbs, against the level
    /// whose <paramref name="triangles"/> (indexed as <paramref name="bvh"/> reports them) are given.
    /// </summary>
    public BodyCollision(TriangleBvh bvh, CharacterModel model, IReadOnlyList<Triangle>? triangles)
    {
        ArgumentNullException.ThrowIfNull(bvh);
        ArgumentNullException.ThrowIfNull(model);
        _bvh = bvh;
        _model = model;
        Rig rig = model.Rig;
        var owned = new bool[rig.Joints.Count];
        _limbBones = new int[model.Limbs.Count][];
        for (int l = 0; l < model.Limbs.Count; l++)
        {
            RigLimb limb = model.Limbs[l];
            var bones = new List<int>();
            for (int i = 1; i < limb.Chain.Count; i++)
            {
                bones.Add(limb.Chain[i]);
            }

            for (int j = 0; j < rig.Joints.Count; j++)
            {
                if (j != limb.EffectorJoint && rig.IsAncestor(limb.EffectorJoint, j))
                {
                    bones.Add(j);
                }
            }

            foreach (int j in bones)
            {
                owned[j] = true;
            }

            _limbBones[l] = [.. bones];
        }

        // Bones that are no body part (a loaded rig's helper bones: IK targets, control bones) are not checked.
        IReadOnlyList<bool> body = model.Source?.BodyBones ?? [];
        bool IsBody(int j) => body.Count == 0 || body[j];
        for (int l = 0; l < _limbBones.Length; l++)
        {
            _limbBones[l] = [.. _limbBones[l].Where(IsBody)];
        }

        var others = new List<int>();
        for (int j = 1; j < rig.Joints.Count; j++)
        {
            if (!owned[j] && IsBody(j))
            {
                others.Add(j);
            }
        }

        _otherBones = [.. others];

        // The skin points of each limb (a loaded rig's skinned mesh, the corners of a built character's bone boxes): its
        // chain's bones and those below its effector (a foot's toes and heel, a hand's fingers reach beyond the
        // segments between joints; a shin's box is as wide as its radius).
        _triangles = triangles is null ? null : triangles as Triangle[] ?? [.. triangles];
        if (triangles is not null)
        {
            _shapes = new (Aabb, Vector3)[triangles.Count];
            for (int t = 0; t < _shapes.Length; t++)
            {
                _shapes[t] = (triangles[t].Bounds, triangles[t].Normal);
            }
        }

        IReadOnlyList<Vector3[]> skin = triangles is null ? [] : model.Source is CharacterSource source ? source.SkinProbes : BoneBoxes.Of(model).InJointFrames();
        // A loaded rig's blended skin (a knee's back, carried by thigh and shin) where linear blend skinning puts it,
        // for the blended points whose bones all belong to the limb: the limb's bones bound where they can lie.
        IReadOnlyList<SkinBlend[][]> blends = triangles is null ? [] : model.Source?.BlendProbes ?? [];
        _probes = new (int, Vector3, SkinBlend[]?)[model.Limbs.Count][];
        for (int l = 0; l < model.Limbs.Count; l++)
        {
            RigLimb limb = model.Limbs[l];
            int[] joints = [.. limb.Chain.Concat(_limbBones[l]).Distinct().Where(j => IsBody(j) || j == limb.Chain[0])];
            var probes = new List<(int, Vector3, SkinBlend[]?)>();
            if (skin.Count == rig.Joints.Count)
            {
                probes.AddRange(joints.SelectMany(j => skin[j].Select(p => (j, p, (SkinBlend[]?)null))));
            }

            if (blends.Count == rig.Joints.Count)
            {
                // Skin blended between the limb's bones and the trunk bone it hangs from (a thigh's top, carried partly by
                // the pelvis) goes where the hip takes it too: a sinking hip beside a crate put it 9 cm into the crate.
                int trunk = rig.Joints[limb.Chain[0]].Parent;
                probes.AddRange(joints.SelectMany(j => blends[j].Where(b => b.All(part => joints.Contains(part.Joint) || part.Joint == trunk)).Select(b => (j, Vector3.Zero, (SkinBlend[]?)b))));
            }

            _probes[l] = [.. probes];
        }

        // How far a limb's skin reaches from the joints carrying it: a blended point lies within its parts' reach of theirs.
        _probeReach = [.. _probes.Select(probes => probes.Select(p => p.Blend is SkinBlend[] b ? b.Max(part => part.Point.Length()) : p.Point.Length()).DefaultIfEmpty(0f).Max())];

        // A loaded rig's foot skin (its effector bone's and the bones' below it), for SoleSink; none for a character built in code.
        _soleProbes = [.. Enumerable.Range(0, model.Limbs.Count).Select(l => model.Source is null ? [] : _probes[l]
            .Where(p => p.Joint == model.Limbs[l].EffectorJoint || rig.IsAncestor(model.Limbs[l].EffectorJoint, p.Joint)).ToArray())];

        // The points a bone's skin is probed with stand rigidly on it, the blended ones among them too; where that skin
        // is blended with another bone's (a spider's tarsus, a fifth to its tibia), its blended points are where the GLB
        // draws it.
        _drawnSoleProbes = [.. _soleProbes.Select(probes => probes.Where(p => p.Blend is not null || !probes.Any(o => o.Blend is not null && o.Joint == p.Joint)).ToArray())];

        // The skin of bones that belong to no limb: those that carry none and hang from none (a tail's tip reaches past
        // its last joint, a head) and the trunk's (a pelvis, a spine, the root bone too: the desert skeleton's pelvis
        // sank 3.3 cm into a dune as it crouched to jump).
        // A loaded rig's are also points spread over that skin: a door's jamb entered a box-shaped head 9.7 cm between
        // its extremes. And its skin blended between such bones, where linear blend skinning puts it: a spider's
        // abdomen, weighted 30 % to its cephalothorax and bent up clear of a dune's rise, was drawn 4.7 cm into it
        // where the abdomen's own points stood 1.2 cm in.
        int[] hips = [.. model.Limbs.Select(l => l.Chain[0])];
        IReadOnlyList<Vector3[]> spread = triangles is null ? [] : model.Source?.SpreadProbes ?? [];
        int[] free = skin.Count != rig.Joints.Count ? [] : [.. Enumerable.Range(0, rig.Joints.Count).Where(j => skin[j].Length > 0 && (j == 0 || others.Contains(j)) && !hips.Contains(j))];
        _freeSkins = [.. free.Select(j => (j, skin[j].Concat(spread.Count == rig.Joints.Count ? spread[j] : []).Distinct().Select(p => (j, p, (SkinBlend[]?)null))
            .Concat(blends.Count == rig.Joints.Count ? blends[j].Where(b => b.All(part => free.Contains(part.Joint))).Select(b => (j, Vector3.Zero, (SkinBlend[]?)b)) : [])
            .ToArray()))];

        _freeReach = [.. _freeSkins.Select(f => SkinReachBound.Of(f.Probes))];

        // A bone's radius is measured over its parent's skin (the flesh around the segment). Where that skin is probed
        // point by point, spread over its faces (a loaded rig's), the segment is checked thin: half its radius around
        // it would stand out of the skin it stands for where the segment runs near that skin's side (a Rigify panda's
        // link from its chest to its shoulder, 0.16 m out on a chest 0.24 m wide, measured 0.25 m from the chest's
        // skin: 4 cm beyond the body, in a door's jamb the body cleared).
        var probed = new HashSet<int>(spread.Count == rig.Joints.Count ? _freeSkins.Select(f => f.Joint) : []);
        _otherThickness = [.. others.Select(j => probed.Contains(rig.Joints[j].Parent) ? Thickness : MathF.Max(Thickness, 0.5f * model.BoneRadii[j]))];
        _otherReach = (2f * _otherThickness.DefaultIfEmpty(Thickness).Max()) + 1e-3f;
    }

    /// <summary>
    /// Whether <see cref="OtherBoneColliding(ReadOnlySpan{Vector3})"/> looks for a triangle near a box around all the
    /// bones of no limb before checking them one by one (true, the default) or checks each every time (tests: the same
    /// answer).
    /// </summary>
    internal bool BoxesOtherBones { get; init; } = true;

    /// <summary>The bones (joint indices; each is the segment from its parent) checked with limb <paramref name="limb"/>.</summary>
    public IReadOnlyList<int> LimbBones(int limb) => _limbBones[limb];

    /// <summary>The bones that belong to no limb (spine, neck, head, tail…), checked with their radii.</summary>
    public IReadOnlyList<int> OtherBones => _otherBones;

    /// <summary>True when a bone of <paramref name="limb"/> (chain, bones below the effector, effector to contact point) passes through the level.</summary>
    /// <param name="limb">The limb.</param>
    /// <param name="positions">World positions of every joint.</param>
    /// <param name="rotations">World rotations of every joint.</param>
    /// <param name="contact">The contact point the limb holds, or <c>null</c>.</param>
    public bool LimbCollides(RigLimb limb, ReadOnlySpan<Vector3> positions, ReadOnlySpan<Quaternion> rotations, Vector3? contact)
    {
        ArgumentNullException.ThrowIfNull(limb);
        int l = IndexOf(limb);
        Rig rig = _model.Rig;
        Vector3 tip = limb.EffectorPosition(positions, rotations);

        // One box around the whole limb first: in flight it is usually clear of the level, and one query says so.
        Vector3 min = Vector3.Min(tip, positions[limb.EffectorJoint]);
        Vector3 max = Vector3.Max(tip, positions[limb.EffectorJoint]);
        foreach (int j in _limbBones[l])
        {
            min = Vector3.Min(min, Vector3.Min(positions[j], positions[rig.Joints[j].Parent]));
            max = Vector3.Max(max, Vector3.Max(positions[j], positions[rig.Joints[j].Parent]));
        }

        // The trunk joint the limb hangs from carries some of its blended skin (a thigh's top).
        if (rig.Joints[limb.Chain[0]].Parent is int trunk and >= 0)
        {
            min = Vector3.Min(min, positions[trunk]);
            max = Vector3.Max(max, positions[trunk]);
        }

        if (!_bvh.Overlaps(new OrientedBox((min + max) * 0.5f, ((max - min) * 0.5f) + new Vector3(Thickness + _probeReach[l]), Quaternion.Identity)))
        {
            return false;
        }

        foreach (int j in _limbBones[l])
        {
            if (SegmentCollides(positions[rig.Joints[j].Parent], positions[j], contact, Thickness))
            {
                return true;
            }
        }

        return SegmentCollides(positions[limb.EffectorJoint], tip, contact, Thickness) || SkinInside(_probes[l], positions, rotations, contact is Vector3 held ? (held, limb.EffectorJoint) : null);
    }

    /// <summary>
    /// How far (metres, along <paramref name="normal"/>) the deepest skin point of <paramref name="limb"/>'s foot (its
    /// effector bone and the bones below it, blended as the GLB draws them) lies below the ground plane through
    /// <paramref name="contact"/>; 0 when none is below it or the rig has no skin (a character built in code). A loaded
    /// rig's foot skin blended with the shin (a Rigify panda's: a fifth) sinks below its sole as the shin leans.
    /// </summary>
    public float SoleSink(RigLimb limb, ReadOnlySpan<Vector3> positions, ReadOnlySpan<Quaternion> rotations, Vector3 contact, Vector3 normal)
    {
        ArgumentNullException.ThrowIfNull(limb);
        float deepest = 0f;
        foreach ((int Joint, Vector3 Point, SkinBlend[]? Blend) probe in _soleProbes[IndexOf(limb)])
        {
            deepest = MathF.Max(deepest, Vector3.Dot(contact - Posed(probe, positions, rotations), normal));
        }

        return deepest;
    }

    /// <summary>
    /// How high (metres, along <paramref name="normal"/>) the lowest skin point of <paramref name="limb"/>'s foot, as
    /// the GLB draws it, lies above the ground plane through <paramref name="contact"/>, negative below it; +∞ where the
    /// rig has no skin (a character built in code). A loaded rig's foot skin blended with the shin (a spider's tarsus:
    /// a fifth) rises off its sole as the shin leans.
    /// </summary>
    public float SoleHeight(RigLimb limb, ReadOnlySpan<Vector3> positions, ReadOnlySpan<Quaternion> rotations, Vector3 contact, Vector3 normal)
    {
        ArgumentNullException.ThrowIfNull(limb);
        float lowest = float.PositiveInfinity;
        foreach ((int Joint, Vector3 Point, SkinBlend[]? Blend) probe in _drawnSoleProbes[IndexOf(limb)])
        {
            lowest = MathF.Min(lowest, Vector3.Dot(Posed(probe, positions, rotations) - contact, normal));
        }

        return lowest;
    }

    /// <summary>Whether <paramref name="limb"/>'s foot has skin <see cref="SoleSink"/> reads (a loaded rig's); false for a character built in code.</summary>
    public bool HasSoleSkin(RigLimb limb) => _soleProbes[IndexOf(limb)].Length > 0;

    /// <summary>
    /// True when a skin point of <paramref name="probes"/> (joint, point in its frame) lies more than
    /// <see cref="SkinDepth"/> inside the level. For a character built in code, with <paramref name="sole"/> (a held
    /// contact point and the effector joint holding it), a corner of the box of the effector bone or a bone below it
    /// (the sole, the toes) up to <see cref="SoleDepth"/> inside the very surface the contact lies on does not count: a
    /// foot box held within the IK's normal tolerance may press its edge that far into the ground it stands on, never
    /// into another surface (a block beside it, a stair's riser). A loaded rig's skinned sole is held to
    /// <see cref="SkinDepth"/> everywhere.
    /// </summary>
    private bool SkinInside((int Joint, Vector3 Point, SkinBlend[]? Blend)[] probes, ReadOnlySpan<Vector3> positions, ReadOnlySpan<Quaternion> rotations, (Vector3 Contact, int Effector)? sole = null)
    {
        if (probes.Length == 0 || _triangles is null)
        {
            return false;
        }

        Span<Vector3> world = probes.Length <= 256 ? stackalloc Vector3[probes.Length] : new Vector3[probes.Length];
        for (int i = 0; i < probes.Length; i++)
        {
            world[i] = Posed(probes[i], positions, rotations);
        }

        List<int> near = s_near ??= [];

        // Bone by bone (the probes come grouped by joint): each bone's points against the triangles near that bone only.
        for (int start = 0; start < probes.Length;)
        {
            int end = start + 1;
            Aabb bone = new(world[start], world[start]);
            while (end < probes.Length && probes[end].Joint == probes[start].Joint)
            {
                bone = Aabb.Union(bone, new Aabb(world[end], world[end]));
                end++;
            }

            near.Clear();
            _bvh.TrianglesNear(bone.Inflate(SkinReach), near);
            int joint = probes[start].Joint;
            bool onSole = _model.Source is null && sole is (_, int effector) && (joint == effector || _model.Rig.IsAncestor(effector, joint));
            for (int i = start; i < end && near.Count > 0; i++)
            {
                if (Inside(world[i], near, out int by, out float depth) && !(onSole && depth <= SoleDepth && OnPlaneOf(by, sole!.Value.Contact)))
                {
                    return true;
                }
            }

            start = end;
        }

        return false;
    }

    /// <summary>Where a skin probe lies posed (world metres): on its bone, or for a blended one, where linear blend skinning puts it.</summary>
    internal static Vector3 Posed((int Joint, Vector3 Point, SkinBlend[]? Blend) probe, ReadOnlySpan<Vector3> positions, ReadOnlySpan<Quaternion> rotations)
    {
        if (probe.Blend is not SkinBlend[] blend)
        {
            return positions[probe.Joint] + Vector3.Transform(probe.Point, rotations[probe.Joint]);
        }

        Vector3 sum = Vector3.Zero;
        foreach (SkinBlend part in blend)
        {
            sum += part.Weight * (positions[part.Joint] + Vector3.Transform(part.Point, rotations[part.Joint]));
        }

        return sum;
    }

    /// <summary>
    /// True when <paramref name="p"/> lies behind the nearest of the triangles <paramref name="near"/> by more than
    /// <see cref="SkinDepth"/>; <paramref name="by"/> is that triangle (−1 when none is within reach),
    /// <paramref name="depth"/> how far behind it (metres, 0 in front). Where several are nearest within
    /// <see cref="EdgeTie"/> (the point is nearest an edge or corner they share), the one it is most in front of
    /// decides: a point beside a crate, below its top's plane, is nearest the top's edge and in front of the side.
    /// The search stops at the first triangle within <see cref="SkinDepth"/> of the point (false; <paramref name="by"/>
    /// that triangle, <paramref name="depth"/> 0): no nearer one can make the point deeper than that. A point more than
    /// <see cref="FrontMargin"/> in front of the plane of every triangle of <paramref name="near"/> is not searched at
    /// all (false; <paramref name="by"/> −1, <paramref name="depth"/> 0): whichever is nearest, it is in front of it.
    /// </summary>
    internal bool Inside(Vector3 p, List<int> near, out int by, out float depth)
    {
        // A point in front of the plane of every triangle near it lies behind none of them, whichever is nearest: not
        // inside (most skin points, above the ground they move over). The margin keeps a point within rounding of a
        // plane, whose side the closest point below could read either way, for the full test.
        ReadOnlySpan<int> triangles = CollectionsMarshal.AsSpan(near);
        bool behind = false;
        foreach (int t in triangles)
        {
            if (Vector3.Dot(p - _triangles![t].A, _shapes[t].Normal) <= FrontMargin)
            {
                behind = true;
                break;
            }
        }

        if (!behind)
        {
            (by, depth) = (-1, 0f);
            return false;
        }

        List<(int Triangle, float Distance, float Front)> candidates = s_candidates ??= [];
        candidates.Clear();
        float nearest = SkinReach;
        foreach (int t in triangles)
        {
            ref readonly (Aabb Bounds, Vector3 Normal) shape = ref _shapes[t];
            float bound = (nearest + EdgeTie) * (nearest + EdgeTie);
            Vector3 outside = Vector3.Max(Vector3.Max(shape.Bounds.Min - p, p - shape.Bounds.Max), Vector3.Zero);
            if (outside.LengthSquared() > bound)
            {
                continue; // its box is already farther than the nearest triangle
            }

            ref readonly Triangle triangle = ref _triangles![t];
            float plane = Vector3.Dot(p - triangle.A, shape.Normal);
            if (plane * plane > bound)
            {
                continue; // its plane is already farther: so is every point of it
            }

            Vector3 closest = triangle.ClosestPoint(p);
            float distance = Vector3.Distance(closest, p);
            if (distance <= SkinDepth)
            {
                // A surface this near: the point is not that deep, whichever side of it it lies.
                (by, depth) = (t, 0f);
                return false;
            }

            if (distance <= nearest + EdgeTie)
            {
                candidates.Add((t, distance, Vector3.Dot(p - closest, shape.Normal)));
                nearest = MathF.Min(nearest, distance);
            }
        }

        (by, float side) = (-1, 1f);
        foreach ((int t, float distance, float front) in candidates)
        {
            if (distance <= nearest + EdgeTie && (by < 0 || front > side))
            {
                (by, side) = (t, front);
            }
        }

        depth = by >= 0 && side < 0f ? nearest : 0f;
        return depth > SkinDepth;
    }

    /// <summary>True when triangle <paramref name="triangle"/>'s plane passes within <see cref="ContactPlane"/> of <paramref name="contact"/>: the surface a held foot stands on.</summary>
    private bool OnPlaneOf(int triangle, Vector3 contact)
    {
        Triangle t = _triangles![triangle];
        return MathF.Abs(Vector3.Dot(contact - t.A, t.Normal)) <= ContactPlane;
    }

    /// <summary>
    /// The first bone that belongs to no limb (spine, neck, head, tail…) and passes through the level, or −1: each
    /// bone the segment from its parent joint, with its radius; and the skin (a loaded rig's mesh, a built character's
    /// bone boxes) of bones that carry no limb and hang from none (a tail's tip, a head) more than
    /// <see cref="SkinDepth"/> inside.
    /// </summary>
    public int OtherBoneColliding(ReadOnlySpan<Vector3> positions, ReadOnlySpan<Quaternion> rotations)
    {
        int bone = OtherBoneColliding(positions);
        if (bone >= 0)
        {
            return bone;
        }

        for (int f = 0; f < _freeSkins.Length; f++)
        {
            // A bone whose skin lies in a sphere around its joint with no triangle near it is passed without posing it
            // (the trunk's, the head's, most of the time): none of its points could be inside.
            (int joint, (int Joint, Vector3 Point, SkinBlend[]? Blend)[] probes) = _freeSkins[f];
            float radius = _freeReach[f].Radius(positions, joint);
            Vector3 centre = positions[joint];
            if (_bvh.AnyTriangleNear(new Aabb(centre - new Vector3(radius), centre + new Vector3(radius)).Inflate(SkinReach)) && SkinInside(probes, positions, rotations))
            {
                return joint;
            }
        }

        return -1;
    }

    /// <summary>
    /// The first bone that belongs to no limb (spine, neck, head, tail…) and passes through the level, or −1: each
    /// bone the segment from its parent joint, with its radius; no skin.
    /// </summary>
    public int OtherBoneColliding(ReadOnlySpan<Vector3> positions)
    {
        Rig rig = _model.Rig;
        if (_otherBones.Length == 0)
        {
            return -1;
        }

        if (BoxesOtherBones && !AnyTriangleNearOtherBones(positions))
        {
            return -1;
        }

        for (int i = 0; i < _otherBones.Length; i++)
        {
            int j = _otherBones[i];
            if (SegmentCollides(positions[rig.Joints[j].Parent], positions[j], null, _otherThickness[i]))
            {
                return j;
            }
        }

        return -1;
    }

    /// <summary>
    /// Whether a triangle's bounds meet the box around the ends of every bone of no limb, grown by
    /// <see cref="_otherReach"/>: with none, no such bone's box touches the level.
    /// </summary>
    private bool AnyTriangleNearOtherBones(ReadOnlySpan<Vector3> positions)
    {
        // With no triangle near the box (a trunk upright over open ground, in the air), no bone's box can touch one,
        // and one query says so.
        Rig rig = _model.Rig;
        Vector3 min = new(float.PositiveInfinity);
        Vector3 max = new(float.NegativeInfinity);
        foreach (int j in _otherBones)
        {
            Vector3 a = positions[rig.Joints[j].Parent];
            Vector3 b = positions[j];
            min = Vector3.Min(min, Vector3.Min(a, b));
            max = Vector3.Max(max, Vector3.Max(a, b));
        }

        return _bvh.AnyTriangleNear(new Aabb(min - new Vector3(_otherReach), max + new Vector3(_otherReach)));
    }

    /// <summary>True when the segment from <paramref name="a"/> to <paramref name="b"/>, less the part near <paramref name="contact"/>, touches the level (as a 2 mm thin box).</summary>
    public bool SegmentCollides(Vector3 a, Vector3 b, Vector3? contact) => SegmentCollides(a, b, contact, Thickness);

    private bool SegmentCollides(Vector3 a, Vector3 b, Vector3? contact, float thickness)
    {
        if (contact is Vector3 c)
        {
            // Cut the segment where it comes within the clearance of the contact point.
            bool aNear = Vector3.Distance(a, c) <= ContactClearance;
            bool bNear = Vector3.Distance(b, c) <= ContactClearance;
            if (aNear && bNear)
            {
                return false;
            }

            Vector3 d = b - a;
            float length = d.Length();
            if (length > 1e-6f)
            {
                Vector3 dir = d / length;
                if (bNear)
                {
                    b = a + (dir * MathF.Max(0f, length - ContactClearance - Vector3.Distance(b, c)));
                }
                else if (aNear)
                {
                    a += dir * MathF.Min(length, ContactClearance + Vector3.Distance(a, c));
                }
            }
        }

        Vector3 segment = b - a;
        float half = segment.Length() * 0.5f;
        if (half < 1e-5f)
        {
            return false;
        }

        Quaternion rotation = Rotations.AlignUp(segment / (2f * half));
        return _bvh.Overlaps(new OrientedBox((a + b) * 0.5f, new Vector3(thickness, half, thickness), rotation));
    }

    private int IndexOf(RigLimb limb)
    {
        for (int l = 0; l < _model.Limbs.Count; l++)
        {
            if (ReferenceEquals(_model.Limbs[l], limb))
            {
                return l;
            }
        }

        throw new ArgumentException($"Limb '{limb.Name}' is not a limb of {_model.Name}.", nameof(limb));
    }

    /// <summary>
    /// What bounds how far from their joint a bone's skin probes lie posed: a rigid point its own offset's length; a
    /// blended one, linear blend skinning's weighted sum, its weights' total times the farthest of its bones' joints
    /// (from this one) plus that bone's offset.
    /// </summary>
    internal readonly record struct SkinReachBound(float Rigid, float Weight, (int Joint, float Reach)[] Parts)
    {
        /// <summary>Added to every bound (metres, and as a share): rounding in posing, never in the bound's favour.</summary>
        private const float Slack = 1e-3f;

        /// <summary>The bound of <paramref name="probes"/>.</summary>
        public static SkinReachBound Of((int Joint, Vector3 Point, SkinBlend[]? Blend)[] probes)
        {
            float rigid = 0f;
            float weight = 0f;
            var parts = new SortedDictionary<int, float>();
            foreach ((_, Vector3 point, SkinBlend[]? blend) in probes)
            {
                if (blend is null)
                {
                    rigid = MathF.Max(rigid, point.Length());
                    continue;
                }

                weight = MathF.Max(weight, blend.Sum(part => MathF.Abs(part.Weight)));
                foreach (SkinBlend part in blend)
                {
                    parts[part.Joint] = MathF.Max(parts.GetValueOrDefault(part.Joint), part.Point.Length());
                }
            }

            return new SkinReachBound(rigid, weight, [.. parts.Select(p => (p.Key, p.Value))]);
        }

        /// <summary>How far (metres) from <paramref name="joint"/>'s position every probe lies at most, posed at <paramref name="positions"/>.</summary>
        public float Radius(ReadOnlySpan<Vector3> positions, int joint)
        {
            float blended = 0f;
            foreach ((int part, float reach) in Parts)
            {
                blended = MathF.Max(blended, Vector3.Distance(positions[part], positions[joint]) + reach);
            }

            return (MathF.Max(Rigid, Weight * blended) * (1f + Slack)) + Slack;
        }
    }
}
