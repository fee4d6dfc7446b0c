using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Rigs;

namespace Ballistic.Planner.Animation;

/// <summary>
/// Whole-body contact generation by projecting the contact reference pose onto the level (paper ref. [3], planning
/// notes §6.1): with the root fixed, each limb looks for surface points inside its workspace that its filter
/// accepts, nearest first to where the reference pose puts its effector (the planner's estimated contact is one of
/// them), starts IK from the nearest sample of its database, and keeps the first solution whose bones stay out of
/// the level. Limbs that find no contact keep the reference pose. The result is valid when the generated contacts'
/// centroidal cone accepts the jump's velocity.
/// </summary>
internal sealed class ContactGenerator
{
    private const int CandidatesPerLimb = 6;

    /// <summary>Most (radians, 50°) the effector joint of a rig loaded from a file turns from its contact pose to hold a contact.</summary>
    private const float MaxEffectorFold = 50f * MathF.PI / 180f;

    /// <summary>How far (share of the stretched limb) to the side of where the contact pose holds a limb's effector its contact is taken, the planner's estimate brought in from farther.</summary>
    private const float EstimateSideways = 0.1f;

    /// <summary>
    /// How far (share of the standing leg, <see cref="StanceDip.RestLegLength"/>) to the
    /// side of where the contact pose holds a limb's effector its contact is taken at most: a sprawled limb reaches far
    /// but stands low (the ant's 0.37 m legs hold its hips 0.13 m up), and a tenth of its reach put its feet 0.29 L
    /// to the side before its landings even sank.
    /// </summary>
    private const float EstimateSidewaysLeg = 0.2f;

    /// <summary>
    /// How far (metres, at most <see cref="DrawBackShare"/> of the stretched limb) each try moves a jump's estimated
    /// contact that the limb cannot hold along the trunk's forward axis, toward the limb's root and away from it,
    /// keeping its sideways place (<see cref="DrawBackTries"/> tries each way): a foot estimated at the foot of a wall,
    /// its toes in the wall; a foot under the hip of a low stance, its ankle folded too far.
    /// </summary>
    private const float DrawBack = 0.05f;

    /// <summary>The most each draw-back try (<see cref="DrawBack"/>) moves a contact, as a share of the stretched limb.</summary>
    private const float DrawBackShare = 0.1f;

    /// <summary>Draw-back tries of an estimated contact each way (<see cref="DrawBack"/>): at most 0.2 m, within the footholds' 0.25 m.</summary>
    private const int DrawBackTries = 4;

    /// <summary>How far (share of the standing leg) to the side of its place a fallback must stand a foot before the estimate is moved instead (<see cref="DrawBack"/>).</summary>
    private const float DrawBackSideways = 0.3f;

    /// <summary>How far (share of the standing leg) sideways of its place a free foot is first posed (<see cref="KeepFree"/>).</summary>
    private const float FreeSideways = 0.3f;

    /// <summary>Most database samples tried as a free foot's pose within <see cref="FreeSideways"/> of its place before any other (<see cref="KeepFree"/>).</summary>
    private const int InPlaceFreeTries = 64;

    /// <summary>Rigs of more feet than this may leave a foot free in a stance where its contact would stand it far out of its place (<see cref="Spared"/>): a quadruped, a hexapod or a spider stands without it, a biped does not stand on one foot.</summary>
    private const int ManyFeet = 3;

    /// <summary>How far (share of the standing leg) to the side of its place a foot of a many-footed rig stands before it is left free where the stance can spare it (<see cref="Spared"/>).</summary>
    private const float HangSideways = 0.3f;

    /// <summary>Most (metres) a drawn-back contact (<see cref="DrawBack"/>) lies above or below the estimate: on the same ground, not a lower stair tread.</summary>
    private const float DrawBackRise = 0.02f;

    /// <summary>A contact solve that ends farther than this (metres) from its point missed it; nearer, it stalled and is solved again for the point alone.</summary>
    private const float StallDistance = 0.01f;

    /// <summary>Only the samples closest to the contact pose are tried as contacts: the comfortable ones.</summary>
    private const int DatabaseScan = 400;

    private readonly PlanningScene _scene;
    private readonly LimbSampleDatabase[] _databases;
    private readonly BodyCollision _collision;
    private readonly float[] _reach;
    private readonly float _standing;

    /// <summary>Creates a generator for a character model on a scene baked for its reduced model.</summary>
    /// <exception cref="RigException">The model's limbs do not match the scene character's limbs by name and order.</exception>
    public ContactGenerator(PlanningScene scene, CharacterModel model, IkSettings? ik = null)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(model);
        if (!model.Limbs.Select(l => l.Name).SequenceEqual(scene.Character.Limbs.Select(l => l.Name)))
        {
            throw new RigException($"Character '{model.Name}': its limbs ({string.Join(", ", model.Limbs.Select(l => l.Name))}) do not match the planner's ({string.Join(", ", scene.Character.Limbs.Select(l => l.Name))}).");
        }

        _scene = scene;
        Model = model;
        Ik = new LimbIk(model.Rig, ik ?? new IkSettings { Restarts = 0, MaxIterations = 30 });
        _databases = [.. model.Limbs.Select(l => new LimbSampleDatabase(model, l))];
        _reach = [.. model.Limbs.Select(l => l.Chain.Skip(1).Sum(j => model.Rig.Joints[j].Offset.Length()) + l.EffectorOffset.Length())];
        float standing = StanceDip.RestLegLength(model);
        _standing = standing > 0f ? standing : float.PositiveInfinity; // no feet: the reach alone bounds the sideways shift
        _collision = new BodyCollision(scene.Bvh, model, scene.Level.Triangles);
        Places = new FootPlaces(model);
        _manyFeet = model.Limbs.Count(l => l.Kind == LimbKind.Foot) > ManyFeet;
    }

    /// <summary>Whether the rig has more than <see cref="ManyFeet"/> feet (<see cref="Spared"/>).</summary>
    private readonly bool _manyFeet;

    /// <summary>The whole character.</summary>
    public CharacterModel Model { get; }

    /// <summary>The IK used for projections.</summary>
    public LimbIk Ik { get; }

    /// <summary>Where the contact pose holds each limb's effector across the trunk: its place.</summary>
    public FootPlaces Places { get; }

    /// <summary>Bone collision checks.</summary>
    public BodyCollision Collision => _collision;

    /// <summary>The sample database of limb <paramref name="limb"/>.</summary>
    public LimbSampleDatabase Database(int limb) => _databases[limb];

    /// <summary>Generates a contact pose at <paramref name="root"/>.</summary>
    /// <param name="root">The root pose, fixed.</param>
    /// <param name="estimated">The planner's estimated contacts at this pose (tried among the candidates), or empty.</param>
    /// <param name="velocity">The velocity the contacts must produce (takeoff velocity) or absorb (reversed landing velocity), m/s.</param>
    public ContactConfiguration Generate(in RootPose root, IReadOnlyList<Contact> estimated, Vector3 velocity) => Generate(root, estimated, velocity, 0f);

    /// <summary>
    /// Generates a contact pose at <paramref name="root"/> whose every contact the limb also holds, clear of the level,
    /// with the root <paramref name="crouch"/> metres lower (world −Y): a takeoff the body can crouch on, a landing it
    /// can absorb. For a rig loaded from a file, holding it there must not fold the effector joint more than
    /// <see cref="StanceDip.MaxEffectorFold"/> from the contact.
    /// </summary>
    /// <param name="root">The root pose, fixed.</param>
    /// <param name="estimated">The planner's estimated contacts at this pose, or empty.</param>
    /// <param name="velocity">The velocity the contacts must produce or absorb, m/s.</param>
    /// <param name="crouch">How much lower (metres) the root must be able to dip with every contact held.</param>
    /// <param name="onEstimates">
    /// True for a jump's takeoff or landing: each limb stands on its estimated contact first (the one the plan reports
    /// and its no-slip test used), brought sideways to within <see cref="EstimateSideways"/> of the limb (and
    /// <see cref="EstimateSidewaysLeg"/> of the standing leg) from where the
    /// contact pose holds it; otherwise on the surface nearest the contact pose first.
    /// </param>
    internal ContactConfiguration Generate(in RootPose root, IReadOnlyList<Contact> estimated, Vector3 velocity, float crouch, bool onEstimates = false)
    {
        ArgumentNullException.ThrowIfNull(estimated);
        ContactConfiguration projected = Project(root, estimated, velocity, crouch, onEstimates);
        if (projected.Valid || estimated.Count == 0)
        {
            return projected;
        }

        // The projected contacts' cone rejects the velocity: fall back on the planner's estimated contacts, whose
        // cone accepted it, reached by IK where the limbs can.
        ContactConfiguration planned = OnEstimated(root, estimated, velocity, crouch);
        return planned.Valid || planned.Contacts.Count > projected.Contacts.Count ? planned : projected;
    }

    private ContactConfiguration OnEstimated(in RootPose root, IReadOnlyList<Contact> estimated, Vector3 velocity, float crouch)
    {
        Rig rig = Model.Rig;
        float[] q = (float[])Model.ContactPose.Clone();
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        var contacts = new List<LimbContact>();
        float[] trial = (float[])q.Clone();
        for (int l = 0; l < Model.Limbs.Count; l++)
        {
            bool made = false;
            foreach (Contact c in estimated)
            {
                if (c.Limb != l)
                {
                    continue;
                }

                // The estimate is the centre of a patch, which on a curved surface lies off it: project it back.
                if (NearestSurfacePoint(c.Position, Model.Limbs[l], root.Position, 0.2f, []) is not { } surface)
                {
                    continue;
                }

                if (SolveFromNearest(root, q, trial, l, surface.Point, surface.Normal, crouch, positions, rotations))
                {
                    Array.Copy(trial, q, q.Length);
                    contacts.Add(new LimbContact(l, surface.Point, surface.Normal, c.Mu));
                    made = true;
                }
            }

            if (!made)
            {
                KeepFree(root, q, l);
            }
        }

        return Finish(root, q, contacts, velocity);
    }

    private ContactConfiguration Project(in RootPose root, IReadOnlyList<Contact> estimated, Vector3 velocity, float crouch, bool onEstimates)
    {
        Rig rig = Model.Rig;
        float[] q = (float[])Model.ContactPose.Clone();
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        rig.Solve(root, q, positions, rotations);
        var contacts = new List<LimbContact>();
        var nearby = new List<int>();
        for (int l = 0; l < Model.Limbs.Count; l++)
        {
            RigLimb limb = Model.Limbs[l];
            Vector3 reference = limb.EffectorPosition(positions, rotations);
            if (TryContact(root, q, l, reference, estimated, crouch, onEstimates, nearby, out LimbContact contact))
            {
                contacts.Add(contact);
            }
            else
            {
                KeepFree(root, q, l);
            }
        }

        ContactConfiguration made = Finish(root, q, contacts, velocity);
        return made.Valid ? Spared(made, velocity) : made;
    }

    /// <summary>
    /// A valid stance of a rig of many feet (more than <see cref="ManyFeet"/>) with the feet that stand
    /// more than <see cref="HangSideways"/> of the standing leg sideways of their places (<see cref="Places"/>) left
    /// free, where the others still
    /// number the required contacts and their cone still accepts <paramref name="velocity"/>: a spider landing by a
    /// ledge, its hind feet's places over the drop, holds them on the brink under its body otherwise; a panda taking
    /// off sideways at the foot of a flight, its right forefoot's place in the riser, held it 0.41 L aside. Else
    /// <paramref name="made"/> itself.
    /// </summary>
    private ContactConfiguration Spared(ContactConfiguration made, Vector3 velocity)
    {
        if (!_manyFeet)
        {
            return made;
        }

        bool OutOfPlace(LimbContact c) =>
            Model.Limbs[c.Limb].Kind == LimbKind.Foot && Places.Off(c.Limb, made.Root, c.Position) > HangSideways * _standing;
        if (!made.Contacts.Any(OutOfPlace))
        {
            return made;
        }

        List<LimbContact> kept = [.. made.Contacts.Where(c => !OutOfPlace(c))];
        if (kept.Count < _scene.Character.RequiredContacts)
        {
            return made;
        }

        float[] q = (float[])made.Angles.Clone();
        foreach (LimbContact c in made.Contacts.Where(OutOfPlace))
        {
            KeepFree(made.Root, q, c.Limb);
        }

        ContactConfiguration spared = Finish(made.Root, q, kept, velocity);
        return spared.Valid ? spared : made;
    }

    private static ContactConfiguration Finish(in RootPose root, float[] q, List<LimbContact> contacts, Vector3 velocity)
    {
        if (contacts.Count == 0)
        {
            return new ContactConfiguration(root, q, contacts, default, false, "no limb could reach a surface");
        }

        Vector3 sum = Vector3.Zero;
        float mu = float.PositiveInfinity;
        foreach (LimbContact c in contacts)
        {
            sum += c.Normal;
            mu = MathF.Min(mu, c.Mu);
        }

        if (sum.Length() < ContactEstimator.ForceClosureThreshold)
        {
            return new ContactConfiguration(root, q, contacts, default, false, "the generated contacts' normals cancel out");
        }

        var cone = new FrictionCone(sum, mu);
        bool accepts = cone.Contains(velocity, 1e-3f);
        return new ContactConfiguration(root, q, contacts, cone, accepts, accepts ? null : "the generated contacts' cone does not contain the jump's velocity");
    }

    /// <summary>
    /// Puts limb <paramref name="l"/> in a free pose that does not pass through the level: the pose it hangs in
    /// standing (<see cref="CharacterModel.HangingPose"/>: the contact pose, or a T-posed rig's hands at its sides), for
    /// a hand hanging straighter down (<see cref="CharacterModel.LoweredPose"/>), the flexion pose, the extending pose or a database sample (nearest the contact pose first). For a foot, first only
    /// those that keep it within <see cref="FreeSideways"/> of the standing leg sideways (along the trunk's left) of
    /// where the contact pose holds it: a panda's forefoot left free on a flight, its place in the riser ahead, was
    /// splayed 0.45 L aside in the flexion pose.
    /// </summary>
    public void KeepFree(in RootPose root, float[] q, int l)
    {
        RigLimb limb = Model.Limbs[l];
        Rig rig = Model.Rig;
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        PoseChain(q, limb, Model.HangingPose);
        rig.Solve(root, q, positions, rotations);
        if (!_collision.LimbCollides(limb, positions, rotations, null))
        {
            return;
        }

        // A foot first takes only the poses within most of its place sideways; the second pass skips those (tried:
        // they pass through the level) among the first scanned samples.
        float most = limb.Kind == LimbKind.Foot ? FreeSideways * _standing : float.PositiveInfinity;
        RootPose at = root;
        int scanned = 0;
        if ((float.IsFinite(most) && Free(inPlace: true)) || Free(inPlace: false))
        {
            return;
        }

        PoseChain(q, limb, Model.HangingPose);

        // The first free pose (with inPlace, within most of the place sideways) clear of the level, set in q: a hand
        // first hanging straighter down.
        bool Free(bool inPlace)
        {
            foreach (float[] pose in limb.Kind == LimbKind.Hand ? [Model.LoweredPose, Model.FlexionPose, Model.ExtendingPose] : new[] { Model.FlexionPose, Model.ExtendingPose })
            {
                PoseChain(q, limb, pose);
                rig.Solve(at, q, positions, rotations);
                bool near = Places.Off(l, at, limb.EffectorPosition(positions, rotations)) <= most;
                if (near == inPlace || (!inPlace && !float.IsFinite(most)))
                {
                    if (!_collision.LimbCollides(limb, positions, rotations, null))
                    {
                        return true;
                    }
                }
            }

            LimbSampleDatabase database = _databases[l];
            int tried = 0;
            for (int s = 0; s < database.Count && (!inPlace || tried < InPlaceFreeTries); s++)
            {
                bool near = MathF.Abs(database.PointOf(s).X - Places.Side(l)) <= most;
                if (inPlace ? !near : (near && s < scanned && float.IsFinite(most)))
                {
                    continue;
                }

                tried++;
                scanned = inPlace ? s + 1 : scanned;
                database.Apply(s, q);
                rig.Solve(at, q, positions, rotations);
                if (!_collision.LimbCollides(limb, positions, rotations, null))
                {
                    return true;
                }
            }

            return false;
        }
    }

    /// <summary>Sets <paramref name="limb"/>'s angles in <paramref name="q"/> to those of <paramref name="pose"/>.</summary>
    private static void PoseChain(float[] q, RigLimb limb, float[] pose)
    {
        foreach (int d in limb.ChainDofSpan)
        {
            q[d] = pose[d];
        }
    }

    /// <summary>Tries to put limb <paramref name="l"/> on a surface point: its estimated contact first when <paramref name="onEstimates"/>, then nearest to its reference effector position.</summary>
    private bool TryContact(in RootPose root, float[] q, int l, Vector3 reference, IReadOnlyList<Contact> estimated, float crouch, bool onEstimates, List<int> nearby, out LimbContact contact)
    {
        contact = default;
        RigLimb limb = Model.Limbs[l];
        Limb reducedLimb = _scene.Character.Limbs[l];
        OrientedBox workspace = reducedLimb.WorkspaceAt(root);
        nearby.Clear();
        _scene.Bvh.OverlappingTriangles(workspace, nearby);
        var candidates = new List<(float Distance, Vector3 Point, Vector3 Normal, float Mu)>();
        Aabb surfaceBounds = Aabb.Empty;
        Vector3 slabNormal = Vector3.Zero;
        Vector3 slabCentre = Vector3.Zero;
        float slabArea = 0f;
        foreach (int t in nearby)
        {
            int surface = _scene.Surfaces.SurfaceOf(t);
            Triangle triangle = _scene.Level.Triangles[t];
            Vector3 normal = triangle.Normal;
            if (surface < 0 || !limb.Filter.Accepts(normal))
            {
                continue;
            }

            Vector3 point = triangle.ClosestPoint(reference);
            if (!ContactEstimator.FacesTrunk(normal, point, root.Position))
            {
                continue; // the far side of a thin slab: no limb can press on it from here
            }

            candidates.Add((Vector3.Distance(point, reference), point, normal, _scene.Level.FrictionOf(t, _scene.Character.Friction)));
            surfaceBounds = Aabb.Union(surfaceBounds, triangle.Bounds);
            float area = triangle.Area;
            slabNormal += normal * area;
            slabCentre += triangle.Centroid * area;
            slabArea += area;
        }

        foreach (Contact c in estimated)
        {
            if (c.Limb == l)
            {
                candidates.Add((Vector3.Distance(c.Position, reference), c.Position, c.Normal, c.Mu));
            }
        }

        candidates.Sort((a, b) => a.Distance.CompareTo(b.Distance));
        Rig rig = Model.Rig;
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        float[] trial = (float[])q.Clone();
        rig.Solve(root, q, positions, rotations);
        Vector3 limbRoot = positions[limb.RootJoint];

        // Then the database: samples nearest the contact pose whose contact point lies within 6 cm of an acceptable
        // surface, started from that very sample; then the surface points nearest the reference effector position.
        LimbSampleDatabase database = _databases[l];
        Aabb surfaceNear = surfaceBounds.Inflate(0.06f); // samples farther from every acceptable surface cannot touch one

        // The acceptable surfaces lie in a slab around their mean plane: samples outside it need no triangle query.
        Vector3 slabAxis = slabNormal.LengthSquared() > 1e-12f ? Vector3.Normalize(slabNormal) : Vector3.UnitY;
        slabCentre = slabArea > 0f ? slabCentre / slabArea : Vector3.Zero;
        float slabHalf = 0.06f;
        foreach (int t in nearby)
        {
            if (_scene.Surfaces.SurfaceOf(t) >= 0 && limb.Filter.Accepts(_scene.Level.Triangles[t].Normal))
            {
                Triangle tri = _scene.Level.Triangles[t];
                slabHalf = MathF.Max(slabHalf, 0.06f + MathF.Max(MathF.Abs(Vector3.Dot(tri.A - slabCentre, slabAxis)), MathF.Max(MathF.Abs(Vector3.Dot(tri.B - slabCentre, slabAxis)), MathF.Abs(Vector3.Dot(tri.C - slabCentre, slabAxis)))));
            }
        }

        // For a jump, the planner's estimated contact first (the stance the plan reports stands on it), brought sideways (the
        // trunk's left axis) to within EstimateSideways of where the contact pose holds the effector (legs neither
        // splayed nor crossed) and onto the surface: from the contact pose itself, then from the database sample
        // nearest it.
        Vector3 left = Vector3.Transform(Vector3.UnitX, root.Rotation);
        float most = MathF.Min(EstimateSideways * _reach[l], EstimateSidewaysLeg * _standing);
        var near = new List<int>();
        var targets = new List<(Vector3 Target, Contact Estimate)>();
        foreach (Contact c in onEstimates ? estimated : [])
        {
            if (c.Limb != l)
            {
                continue;
            }

            float side = Vector3.Dot(c.Position - reference, left);
            Vector3 target = c.Position - (left * (side - Math.Clamp(side, -most, most)));
            targets.Add((target, c));
            if (NearestSurfacePoint(target, limb, root.Position, 0.2f, near) is not { } onSurface
                || Vector3.Distance(onSurface.Point, limbRoot) > _reach[l])
            {
                continue;
            }

            if (Holds(root, q, trial, l, onSurface.Point, onSurface.Normal, crouch, positions, rotations))
            {
                contact = new LimbContact(l, onSurface.Point, onSurface.Normal, c.Mu);
                return true;
            }
        }

        // Otherwise the fallbacks below. Where they stand a foot out of its place, far to its side (a spider's foot
        // estimated at the foot of a wall, its toes in the wall, stood 0.16 m inside it) or farther from the estimate
        // than the tries below reach (a human's foot under its hip on a low stance, its ankle folded past
        // MaxEffectorFold, stood 0.58 m ahead in a lunge), the estimate is moved along the trunk's forward axis on the
        // same ground instead, keeping its sideways place: toward the limb's root first, then away, a step further
        // each time, if the limb holds it there.
        RootPose at = root;
        if (!Fallbacks(out contact))
        {
            return false;
        }

        // A walk's stance moves its nearest surface point the same way (a walk from a low stance stood the human's
        // right foot 0.70 m ahead of its root, and could not turn on it).
        if (!onEstimates && candidates.Count > 0)
        {
            (_, Vector3 point, Vector3 normal, float mu) = candidates[0];
            targets.Add((point, new Contact(l, point, normal, mu, -1)));
        }

        float each = MathF.Min(DrawBack, DrawBackShare * _reach[l]);
        float far = (DrawBackTries + 1) * each;
        Vector3 fallback = contact.Position;
        bool outOfPlace = MathF.Abs(Vector3.Dot(fallback - reference, left)) > DrawBackSideways * _standing
            || targets.Exists(t => Vector3.Distance(fallback, t.Estimate.Position) > far);
        if (limb.Kind != LimbKind.Foot || !outOfPlace)
        {
            return true;
        }

        Vector3 forward = root.Forward with { Y = 0f };
        forward = forward.LengthSquared() > 1e-8f ? Vector3.Normalize(forward) : Vector3.Zero;
        foreach ((Vector3 target, Contact c) in targets)
        {
            Vector3 back = Vector3.Dot(target - limbRoot, forward) >= 0f ? -forward : forward;
            for (int k = 1; k <= 2 * DrawBackTries; k++)
            {
                Vector3 moved = target + (back * (((k + 1) / 2) * each * (k % 2 == 1 ? 1f : -1f)));
                if (NearestSurfacePoint(moved, limb, root.Position, 0.2f, near) is not { } onSurface
                    || Vector3.Distance(onSurface.Point, limbRoot) > _reach[l]
                    || MathF.Abs(onSurface.Point.Y - c.Position.Y) > DrawBackRise)
                {
                    continue;
                }

                if (Holds(root, q, trial, l, onSurface.Point, onSurface.Normal, crouch, positions, rotations))
                {
                    contact = new LimbContact(l, onSurface.Point, onSurface.Normal, c.Mu);
                    return true;
                }
            }
        }

        return true;

        bool Fallbacks(out LimbContact held)
        {
            held = default;

            // The surface point nearest the reference effector position, from the contact pose itself (the limb as the
            // rig holds it, bending the way it bends there), then from the flexion pose: a rig whose contact pose is its
            // straight-legged bind pose cannot be solved from there to a foot under the lowered hip (a straight chain is
            // a singular start for IK), and would otherwise stand on a database sample's foothold far ahead or behind.
            if (candidates.Count > 0 && Vector3.Distance(candidates[0].Point, limbRoot) <= _reach[l])
            {
                foreach (float[] from in new[] { Model.ContactPose, Model.FlexionPose })
                {
                    Array.Copy(q, trial, q.Length);
                    PoseChain(trial, limb, from);

                    if (TrySolve(at, trial, limb, candidates[0].Point, candidates[0].Normal, crouch, positions, rotations))
                    {
                        Array.Copy(trial, q, q.Length);
                        held = new LimbContact(l, candidates[0].Point, candidates[0].Normal, candidates[0].Mu);
                        return true;
                    }
                }
            }

            int tried = 0;
            for (int s = 0; s < Math.Min(database.Count, DatabaseScan) && tried < CandidatesPerLimb; s++)
            {
                Vector3 world = at.ToWorld(database.PointOf(s));
                if (!surfaceNear.Contains(world) || MathF.Abs(Vector3.Dot(world - slabCentre, slabAxis)) > slabHalf || !workspace.Contains(world))
                {
                    continue;
                }

                (Vector3 Point, Vector3 Normal, float Mu)? best = NearestSurfacePoint(world, limb, at.Position, 0.06f, near);
                if (best is not { } found)
                {
                    continue;
                }

                tried++;
                Array.Copy(q, trial, q.Length);
                database.Apply(s, trial);
                if (TrySolve(at, trial, limb, found.Point, found.Normal, crouch, positions, rotations))
                {
                    Array.Copy(trial, q, q.Length);
                    held = new LimbContact(l, found.Point, found.Normal, found.Mu);
                    return true;
                }
            }

            Vector3? previous = null;
            tried = 0;
            foreach ((_, Vector3 point, Vector3 normal, float mu) in candidates)
            {
                if (tried >= CandidatesPerLimb)
                {
                    break;
                }

                if (previous is Vector3 p && Vector3.Distance(p, point) < 0.02f)
                {
                    continue; // neighbouring triangles give the same closest point
                }

                previous = point;
                if (Vector3.Distance(point, limbRoot) > _reach[l])
                {
                    continue; // farther than the stretched limb: no IK can get there
                }

                tried++;
                if (SolveFromNearest(at, q, trial, l, point, normal, crouch, positions, rotations))
                {
                    Array.Copy(trial, q, q.Length);
                    held = new LimbContact(l, point, normal, mu);
                    return true;
                }
            }

            return false;
        }
    }

    /// <summary>
    /// The nearest point within <paramref name="radius"/> metres of <paramref name="point"/> on a surface the limb may
    /// touch whose face is turned toward the trunk centre <paramref name="trunk"/>, with that surface's normal and
    /// friction; <c>null</c> when there is none.
    /// </summary>
    private (Vector3 Point, Vector3 Normal, float Mu)? NearestSurfacePoint(Vector3 point, RigLimb limb, Vector3 trunk, float radius, List<int> scratch)
    {
        scratch.Clear();
        _scene.Bvh.TrianglesNear(new Aabb(point - new Vector3(radius), point + new Vector3(radius)), scratch);
        (Vector3 Point, Vector3 Normal, float Mu)? best = null;
        float bestDistance = radius;
        foreach (int t in scratch)
        {
            Triangle triangle = _scene.Level.Triangles[t];
            if (_scene.Surfaces.SurfaceOf(t) < 0 || !limb.Filter.Accepts(triangle.Normal))
            {
                continue;
            }

            Vector3 closest = triangle.ClosestPoint(point);
            float distance = Vector3.Distance(closest, point);
            if (distance < bestDistance && ContactEstimator.FacesTrunk(triangle.Normal, closest, trunk))
            {
                bestDistance = distance;
                best = (closest, triangle.Normal, _scene.Level.FrictionOf(t, _scene.Character.Friction));
            }
        }

        return best;
    }

    /// <summary>
    /// Limb <paramref name="l"/> on a surface point, solved from <paramref name="q"/> itself, then as
    /// <see cref="SolveFromNearest"/> does; <paramref name="q"/> takes the solution when the limb holds the point.
    /// </summary>
    private bool Holds(in RootPose root, float[] q, float[] trial, int l, Vector3 point, Vector3 normal, float crouch, Vector3[] positions, Quaternion[] rotations)
    {
        Array.Copy(q, trial, q.Length);
        if (TrySolve(root, trial, Model.Limbs[l], point, normal, crouch, positions, rotations)
            || SolveFromNearest(root, q, trial, l, point, normal, crouch, positions, rotations))
        {
            Array.Copy(trial, q, q.Length);
            return true;
        }

        return false;
    }

    /// <summary>
    /// IK of limb <paramref name="l"/> to a surface point into <paramref name="trial"/>, from the database sample whose
    /// effector lies nearest the point (the configuration <paramref name="q"/> otherwise), then from the flexion pose
    /// (a sample can start the solver toward a twisted solution the effector-fold check refuses).
    /// </summary>
    private bool SolveFromNearest(in RootPose root, float[] q, float[] trial, int l, Vector3 point, Vector3 normal, float crouch, Vector3[] positions, Quaternion[] rotations)
    {
        Array.Copy(q, trial, q.Length);
        int start = _databases[l].Nearest(Vector3.Transform(point - root.Position, Quaternion.Conjugate(root.Rotation)));
        if (start < 0)
        {
            return false;
        }

        _databases[l].Apply(start, trial);
        if (TrySolve(root, trial, Model.Limbs[l], point, normal, crouch, positions, rotations))
        {
            return true;
        }

        Array.Copy(q, trial, q.Length);
        PoseChain(trial, Model.Limbs[l], Model.FlexionPose);

        return TrySolve(root, trial, Model.Limbs[l], point, normal, crouch, positions, rotations);
    }

    /// <summary>
    /// IK to a surface point with the contact face against the surface, then the bone check; with
    /// <paramref name="crouch"/> metres, the same with the root that much lower.
    /// </summary>
    private bool TrySolve(in RootPose root, float[] trial, RigLimb limb, Vector3 point, Vector3 normal, float crouch, Vector3[] positions, Quaternion[] rotations)
    {
        Span<float> stalled = trial.Length <= 256 ? stackalloc float[trial.Length] : new float[trial.Length];
        IkResult result = Ik.Solve(root, trial, limb, point, -normal, 1, stalled);
        if (!result.Success && !PositionFirst(root, trial, limb, point, normal, result, stalled, positions, rotations))
        {
            return false;
        }

        // A user's skinned mesh blends the sole with the bone above the effector: an ankle or wrist folded far from its
        // contact pose presses the sole's skin into the ground (linear blend skinning). Another candidate, then.
        if (Model.Source is not null)
        {
            Rig rig = Model.Rig;
            int effector = limb.EffectorJoint;
            if (rig.JointTurn(effector, trial, Model.ContactPose) > MaxEffectorFold)
            {
                return false;
            }
        }

        Model.Rig.Solve(root, trial, positions, rotations);
        if (_collision.LimbCollides(limb, positions, rotations, point))
        {
            return false;
        }

        return !(crouch > 0f) || HoldsCrouched(root, trial, limb, point, normal, crouch, positions, rotations);
    }

    /// <summary>
    /// The second try of a solve that stalled a few millimetres short with its contact face already within the IK's
    /// normal tolerance of the surface: the damped solve weighs the last degrees of face alignment against the last
    /// millimetre of position and can settle between them (a sprawled insect leg near full stretch on a slope). The
    /// point is solved alone from where the solve stalled (<paramref name="stalled"/>, its face already turned onto
    /// the surface: started from the contact pose instead, a foot held level on a 15° slope would keep its toe in
    /// the rising ground) and kept when the face still lies within the tolerance.
    /// </summary>
    private bool PositionFirst(in RootPose root, float[] trial, RigLimb limb, Vector3 point, Vector3 normal, IkResult failed, ReadOnlySpan<float> stalled, Vector3[] positions, Quaternion[] rotations)
    {
        if (!(failed.PositionError < StallDistance) || !(failed.NormalError <= Ik.Settings.NormalTolerance))
        {
            return false;
        }

        float[] position = stalled.ToArray();
        if (!Ik.Reaches(root, position, limb, point, null, seed: 1))
        {
            return false;
        }

        Model.Rig.Solve(root, position, positions, rotations);
        if (Vector3.Dot(limb.EffectorNormal(rotations), -normal) < MathF.Cos(Ik.Settings.NormalTolerance))
        {
            return false;
        }

        Array.Copy(position, trial, trial.Length);
        return true;
    }

    /// <summary>
    /// True when <paramref name="limb"/>, posed in <paramref name="q"/> on <paramref name="point"/>, still holds it
    /// with the root <paramref name="crouch"/> metres lower, as a dip holds it (<see cref="StanceDip.Hold"/>).
    /// </summary>
    private bool HoldsCrouched(in RootPose root, float[] q, RigLimb limb, Vector3 point, Vector3 normal, float crouch, Vector3[] positions, Quaternion[] rotations)
    {
        var low = new RootPose(root.Position - (crouch * Vector3.UnitY), root.Rotation);
        return StanceDip.Hold(Ik, Model, _collision, low, (float[])q.Clone(), limb, point, normal, q, positions, rotations, seed: 1) is null;
    }
}
