using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Surfaces;

namespace Ballistic.Planner.Contacts;

/// <summary>
/// FINDCONTACTS and COMPUTECONE of the paper: for a root pose, each limb whose workspace Wk touches an acceptable
/// surface gets an estimated contact on the largest such surface, at the point of the mesh nearest the centre of Wk's
/// intersection with it (or, for a limb derived from a rig, nearest its <see cref="Limb.Home"/>: where the contact
/// pose holds it), with the normal of the triangle that point lies on. A surface is acceptable when the limb's
/// filter accepts it, its face is turned toward the trunk (the underside of a slab the workspace pierces is not) and
/// the contact point can be seen from the trunk centre (not the floor under a crate the workspace reaches into).
/// The centroidal cone has the normalised sum of the contact normals as axis and the least friction as μ. A pose that
/// passes all of that must then pass the optional <see cref="IPoseValidator"/>. Thread-safe.
/// </summary>
internal sealed class ContactEstimator
{
    /// <summary>|Σ nᵢ| below this counts as force closure (normals cancelling out).</summary>
    public const float ForceClosureThreshold = 0.05f;

    /// <summary>Intersections smaller than this (square metres) are grazing touches, not contacts.</summary>
    public const float MinContactArea = 1e-4f;

    private readonly Level _level;
    private readonly TriangleBvh _bvh;
    private readonly SurfaceSet _surfaces;
    private readonly ReducedCharacter _character;

    /// <summary>Creates an estimator for one character on one level.</summary>
    /// <param name="level">The level.</param>
    /// <param name="bvh">Collision hierarchy over the level's triangles.</param>
    /// <param name="surfaces">The level's contact surfaces.</param>
    /// <param name="character">The reduced character.</param>
    /// <param name="poseValidator">An extra test valid poses must pass; <c>null</c> for none.</param>
    public ContactEstimator(Level level, TriangleBvh bvh, SurfaceSet surfaces, ReducedCharacter character, IPoseValidator? poseValidator = null)
    {
        ArgumentNullException.ThrowIfNull(level);
        ArgumentNullException.ThrowIfNull(bvh);
        ArgumentNullException.ThrowIfNull(surfaces);
        ArgumentNullException.ThrowIfNull(character);
        _level = level;
        _bvh = bvh;
        _surfaces = surfaces;
        _character = character;
        PoseValidator = poseValidator;
        _tryOrder = [.. Enumerable.Range(0, character.Limbs.Count).OrderBy(l => character.Limbs[l].Kind == LimbKind.Hand ? 0 : 1)];
        _triangles = level.Triangles as Triangle[] ?? [.. level.Triangles];
        _centres = new Vector3[_triangles.Length];
        _radii = new float[_triangles.Length];
        for (int t = 0; t < _triangles.Length; t++)
        {
            Triangle triangle = _triangles[t];
            _centres[t] = triangle.Centroid;
            _radii[t] = MathF.Sqrt(MathF.Max(Vector3.DistanceSquared(triangle.A, _centres[t]), MathF.Max(Vector3.DistanceSquared(triangle.B, _centres[t]), Vector3.DistanceSquared(triangle.C, _centres[t]))));
        }
    }

    /// <summary>Each triangle's centroid (world metres), by index: with <see cref="_radii"/>, a ball holding it.</summary>
    private readonly Vector3[] _centres;

    /// <summary>Each triangle's farthest vertex from its centroid (metres), by index.</summary>
    private readonly float[] _radii;

    /// <summary>The level's triangles (<see cref="Level.Triangles"/>), by index.</summary>
    private readonly Triangle[] _triangles;

    /// <summary>The extra test valid poses must pass; <c>null</c> when there is none.</summary>
    public IPoseValidator? PoseValidator { get; }

    [ThreadStatic]
    private static List<int>? s_scratch;

    [ThreadStatic]
    private static List<Piece>? s_pieces;

    /// <summary>Checks the trunk, estimates the contacts and computes the cone of <paramref name="pose"/>.</summary>
    public PoseEvaluation Evaluate(in RootPose pose) =>
        _bvh.Overlaps(new OrientedBox(pose.Position, _character.TrunkHalfExtents, pose.Rotation))
            ? new PoseEvaluation(pose, PoseValidity.TrunkCollides, [], default)
            : EvaluateContacts(pose);

    /// <summary>Estimates the contacts and cone of a pose whose trunk is already known to be free.</summary>
    internal PoseEvaluation EvaluateContacts(in RootPose pose)
    {
        var contacts = new List<Contact>(_character.Limbs.Count);
        List<int> touched = s_scratch ??= new List<int>(64);
        for (int limbIndex = 0; limbIndex < _character.Limbs.Count; limbIndex++)
        {
            if (TryEstimate(limbIndex, pose, touched, out Contact contact))
            {
                contacts.Add(contact);
            }
        }

        return contacts.Count < _character.RequiredContacts
            ? new PoseEvaluation(pose, PoseValidity.TooFewContacts, contacts, default)
            : Judged(pose, contacts);
    }

    /// <summary>
    /// <see cref="EvaluateContacts"/> of a pose wanted only when valid: the same evaluation when it is valid, otherwise
    /// <c>null</c>, given up as soon as the limbs left to try could no longer make up
    /// <see cref="ReducedCharacter.RequiredContacts"/>. Hands are tried before feet (in a stance a hand touches least
    /// often, so a stance whose feet reach nothing is refused without trying its last foot); the contacts are listed
    /// in limb order all the same.
    /// </summary>
    internal PoseEvaluation? ValidOrNull(in RootPose pose)
    {
        int count = _character.Limbs.Count;
        Span<Contact> found = count <= 32 ? stackalloc Contact[count] : new Contact[count];
        Span<bool> touches = count <= 32 ? stackalloc bool[count] : new bool[count];
        List<int> touched = s_scratch ??= new List<int>(64);
        int missing = 0;
        foreach (int limbIndex in _tryOrder)
        {
            if (TryEstimate(limbIndex, pose, touched, out found[limbIndex]))
            {
                touches[limbIndex] = true;
            }
            else if (count - ++missing < _character.RequiredContacts)
            {
                return null;
            }
        }

        var contacts = new List<Contact>(count);
        for (int limbIndex = 0; limbIndex < count; limbIndex++)
        {
            if (touches[limbIndex])
            {
                contacts.Add(found[limbIndex]);
            }
        }

        PoseEvaluation judged = Judged(pose, contacts);
        return judged.IsValid ? judged : null;
    }

    /// <summary>The limbs in the order <see cref="ValidOrNull"/> tries them: hands, then feet, each in limb order.</summary>
    private readonly int[] _tryOrder;

    /// <summary>The evaluation of a pose with enough <paramref name="contacts"/> (in limb order): their cone, and the validator's word.</summary>
    private PoseEvaluation Judged(in RootPose pose, List<Contact> contacts)
    {
        if (Contact.ConeOf(contacts) is not { } cone)
        {
            return new PoseEvaluation(pose, PoseValidity.ForceClosure, contacts, default);
        }

        var valid = new PoseEvaluation(pose, PoseValidity.Valid, contacts, cone);
        return PoseValidator is null || PoseValidator.IsValid(valid)
            ? valid
            : valid with { Validity = PoseValidity.Rejected };
    }

    /// <summary>The estimated contact of one limb, when its workspace touches an acceptable surface.</summary>
    public bool TryEstimate(int limbIndex, in RootPose pose, List<int> scratch, out Contact contact)
    {
        ArgumentNullException.ThrowIfNull(scratch);
        contact = default;
        Limb limb = _character.Limbs[limbIndex];
        OrientedBox workspace = limb.WorkspaceAt(pose);
        scratch.Clear();
        _bvh.TrianglesNearBox(workspace, scratch);
        if (scratch.Count == 0)
        {
            return false;
        }

        // Each near triangle is put in Wk's frame once, for the overlap test and the clipping alike; those no part of
        // the limb may touch are passed over before.
        Quaternion toLocal = Quaternion.Conjugate(workspace.Rotation);

        // Area, area-weighted centroid and normal of the intersection, per surface (few per workspace: a list); the
        // acceptable triangles' pieces inside Wk are kept for placing the contact on one of them.
        Span<SurfacePart> parts = stackalloc SurfacePart[16];
        int partCount = 0;
        List<Piece> pieces = s_pieces ??= new List<Piece>(64);
        pieces.Clear();
        foreach (int t in scratch)
        {
            int surface = _surfaces.SurfaceOf(t);
            if (surface < 0)
            {
                continue;
            }

            Vector3 normal = _surfaces.NormalOf(t);
            if (!limb.Filter.Accepts(normal))
            {
                continue;
            }

            ref readonly Triangle triangle = ref _triangles[t];
            Vector3 v0 = Vector3.Transform(triangle.A - workspace.Center, toLocal);
            Vector3 v1 = Vector3.Transform(triangle.B - workspace.Center, toLocal);
            Vector3 v2 = Vector3.Transform(triangle.C - workspace.Center, toLocal);
            (float area, Vector3 centroid) = BoxClipper.OverlapArea(workspace, triangle, v0, v1, v2);
            if (area <= 0f || !FacesTrunk(normal, centroid, pose.Position))
            {
                continue;
            }

            pieces.Add(new Piece(t, surface, centroid));
            int slot = 0;
            while (slot < partCount && parts[slot].Surface != surface)
            {
                slot++;
            }

            if (slot == partCount)
            {
                if (partCount == parts.Length)
                {
                    continue; // more than 16 surfaces in one workspace: the rest are tiny slivers
                }

                parts[partCount++] = new SurfacePart { Surface = surface };
            }

            parts[slot].Area += area;
            parts[slot].Moment += centroid * area;
            parts[slot].Normal += normal * area;
        }

        // Surfaces by decreasing area (ties: lower id): the largest one the limb can see from the trunk wins.
        Span<int> order = stackalloc int[partCount];
        for (int i = 0; i < partCount; i++)
        {
            order[i] = i;
        }

        for (int i = 1; i < partCount; i++)
        {
            for (int k = i; k > 0 && Before(parts[order[k]], parts[order[k - 1]]); k--)
            {
                (order[k], order[k - 1]) = (order[k - 1], order[k]);
            }
        }

        foreach (int p in order)
        {
            if (!(parts[p].Area > MinContactArea))
            {
                break;
            }

            Vector3 aim = limb.Home is { } home ? pose.ToWorld(home) : parts[p].Moment / parts[p].Area;
            (Vector3 Position, Vector3 Normal) onMesh = PointOn(parts[p].Surface, aim, workspace, pieces);
            onMesh = OffTheLedge(parts[p].Surface, aim, onMesh, parts[p].Moment / parts[p].Area, workspace, pieces);

            // A surface hidden from the trunk (the floor under a crate the workspace reaches into) cannot be reached.
            Vector3 seen = onMesh.Position + (onMesh.Normal * 0.01f);
            if (_bvh.Raycast(pose.Position, seen - pose.Position, 1f, out _))
            {
                continue;
            }

            ContactSurface surfaceInfo = _surfaces.Surfaces[parts[p].Surface];
            float mu = _level.Materials[surfaceInfo.MaterialIndex].Friction ?? _character.Friction;
            contact = new Contact(limbIndex, onMesh.Position, onMesh.Normal, mu, parts[p].Surface);
            return true;
        }

        return false;
    }

    private static bool Before(in SurfacePart a, in SurfacePart b) => a.Area > b.Area || (a.Area == b.Area && a.Surface < b.Surface);

    /// <summary>
    /// The contact on surface <paramref name="surface"/>: the point of its mesh inside Wk nearest <paramref name="aim"/>
    /// (the limb's home, or the patch's centre, which lies off a curved surface), or when that point leaves Wk the
    /// centre of the triangle's piece inside Wk (on the triangle and inside Wk, the piece being convex), with that
    /// triangle's normal.
    /// </summary>
    private (Vector3 Position, Vector3 Normal) PointOn(int surface, Vector3 aim, in OrientedBox workspace, List<Piece> pieces)
    {
        (Vector3 Position, Vector3 Normal) best = default;
        float nearest = float.PositiveInfinity;
        foreach (Piece piece in pieces)
        {
            if (piece.Surface != surface)
            {
                continue;
            }

            // A triangle whose ball lies farther than the nearest point found cannot hold a nearer one (with a margin
            // far above rounding, so that the same point is found as when every triangle is measured).
            float beyond = Vector3.Distance(aim, _centres[piece.Triangle]) - _radii[piece.Triangle];
            if (beyond > 0f && beyond * beyond > (nearest * 1.001f) + 1e-8f)
            {
                continue;
            }

            ref readonly Triangle triangle = ref _triangles[piece.Triangle];
            Vector3 closest = triangle.ClosestPoint(aim);
            float distance = Vector3.DistanceSquared(closest, aim);
            if (distance < nearest)
            {
                nearest = distance;
                best = (workspace.Contains(closest) ? closest : piece.Centroid, triangle.Normal);
            }
        }

        return best;
    }

    /// <summary>
    /// The contact moved in from a ledge's brink: where the limb's <paramref name="aim"/> lies beyond a surface facing
    /// up (a platform's edge, a beam's side), the nearest point of the surface is on its very edge, where a foot would
    /// stand half over the drop; when no ground facing up lies just past that edge within the character's step height
    /// above or below it (a drop, or a wall), the contact is moved <see cref="LedgeInset"/> (at most half the way)
    /// toward <paramref name="centre"/>, the centre of the surface's patch inside the workspace, and put back on the
    /// mesh, if still inside the workspace. Elsewhere (the aim over the surface, a stair's nosing with its tread below,
    /// its riser with the next tread above) it is kept.
    /// </summary>
    private (Vector3 Position, Vector3 Normal) OffTheLedge(int surface, Vector3 aim, (Vector3 Position, Vector3 Normal) onMesh, Vector3 centre, in OrientedBox workspace, List<Piece> pieces)
    {
        Vector3 n = onMesh.Normal;
        Vector3 off = aim - onMesh.Position;
        Vector3 beyond = off - (Vector3.Dot(off, n) * n);
        if (!(n.Y >= 0.7f) || !(beyond.LengthSquared() > EdgeSlack * EdgeSlack))
        {
            return onMesh;
        }

        float stepDown = _character.StepReach;
        Vector3 past = onMesh.Position + (Vector3.Normalize(beyond) * EdgeProbe) + (Vector3.UnitY * stepDown);
        if (_bvh.Raycast(past, -Vector3.UnitY, 2f * stepDown, out RayHit ground) && ground.Normal.Y > 0f)
        {
            return onMesh;
        }

        Vector3 inward = centre - onMesh.Position;
        inward -= Vector3.Dot(inward, n) * n;
        float room = inward.Length();
        if (!(room > EdgeSlack))
        {
            return onMesh;
        }

        Vector3 moved = onMesh.Position + (inward * (MathF.Min(LedgeInset, 0.5f * room) / room));
        (Vector3 Position, Vector3 Normal) inside = PointOn(surface, moved, workspace, pieces);
        return workspace.Contains(inside.Position) ? inside : onMesh;
    }

    /// <summary>How far (metres) a contact whose limb aims past a ledge's brink is moved in from it (<see cref="OffTheLedge"/>).</summary>
    public const float LedgeInset = 0.05f;

    /// <summary>How far past a surface's edge (metres) the ground is looked for (<see cref="OffTheLedge"/>).</summary>
    private const float EdgeProbe = 0.02f;

    /// <summary>How far (metres, along the surface) the aim may lie from its nearest surface point and still count as over the surface (rounding).</summary>
    private const float EdgeSlack = 1e-3f;

    /// <summary>
    /// True when a face of unit normal <paramref name="normal"/> at <paramref name="point"/> is turned toward the
    /// trunk centre <paramref name="trunk"/>: a limb can only press on the side of a surface it stands on.
    /// </summary>
    public static bool FacesTrunk(Vector3 normal, Vector3 point, Vector3 trunk) => Vector3.Dot(normal, trunk - point) > 0f;

    /// <summary>An acceptable triangle's piece inside a workspace: the triangle, its surface and the piece's centre.</summary>
    private readonly record struct Piece(int Triangle, int Surface, Vector3 Centroid);

    private struct SurfacePart
    {
        public int Surface;
        public float Area;
        public Vector3 Moment;
        public Vector3 Normal;
    }
}
