using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Tests.Support;

/// <summary>
/// An independent checker of a plan and its animation, written from the promises alone (not from the planner's
/// code): what a user's own verifier would assert. It never throws on a bad plan; it lists what is wrong.
/// </summary>
internal static class PlanAudit
{
    /// <summary>Stance contacts' centre must lie this close to the requested point, across (metres).</summary>
    public const float AcrossTolerance = 0.5f;

    /// <summary>… and this close up or down (metres).</summary>
    public const float UpDownTolerance = 0.25f;

    public static AuditReport Check(string name, PlanningScene scene, Vector3 from, Vector3 to, PlanResult plan, JumpAnimation? animation)
    {
        var report = new AuditReport(name, plan.Status, plan.Reason);
        if (plan.Status != PlannerStatus.Exact)
        {
            return report;
        }

        ReducedCharacter character = scene.Character;
        RoadmapNode? first = plan.Moves.Count > 0 ? plan.Moves[0].From : plan.Start;
        RoadmapNode? last = plan.Moves.Count > 0 ? plan.Moves[^1].To : plan.Goal;
        if (first is null || last is null)
        {
            report.Violations.Add("exact plan without start or goal node");
            return report;
        }

        (report.StartAcross, report.StartUpDown) = Offset(first, from);
        (report.GoalAcross, report.GoalUpDown) = Offset(last, to);
        if (report.StartAcross > AcrossTolerance || report.StartUpDown > UpDownTolerance)
        {
            report.Violations.Add($"starts {report.StartAcross:0.00} m across and {report.StartUpDown:0.00} m up/down from the requested start");
        }

        if (report.GoalAcross > AcrossTolerance || report.GoalUpDown > UpDownTolerance)
        {
            report.Violations.Add($"ends {report.GoalAcross:0.00} m across and {report.GoalUpDown:0.00} m up/down from the requested goal");
        }

        for (int m = 0; m < plan.Moves.Count; m++)
        {
            Move move = plan.Moves[m];
            if (m > 0 && (plan.Moves[m - 1].To.Id != move.From.Id || plan.Moves[m - 1].To.Pose != move.From.Pose))
            {
                report.Violations.Add($"move {m} does not start where move {m - 1} ended");
            }

            if (move is Jump jump)
            {
                CheckJump(scene, jump, $"move {m} (jump)", report);
            }
            else if (move is Walk walk)
            {
                report.Walks++;
                CheckWalk(scene, walk, $"move {m} (walk)", report);
            }

            CheckNode(scene, move.From, $"move {m} start", report);
            CheckNode(scene, move.To, $"move {m} end", report);
        }

        if (animation is not null)
        {
            CheckAnimation(scene, animation, report);
        }

        return report;
    }

    private static (float Across, float UpDown) Offset(RoadmapNode node, Vector3 requested)
    {
        if (node.Contacts.Count == 0)
        {
            return (float.PositiveInfinity, float.PositiveInfinity);
        }

        Vector3 centre = Vector3.Zero;
        foreach (Contact c in node.Contacts)
        {
            centre += c.Position;
        }

        centre /= node.Contacts.Count;
        return (new Vector2(centre.X - requested.X, centre.Z - requested.Z).Length(), MathF.Abs(centre.Y - requested.Y));
    }

    private static void CheckJump(PlanningScene scene, Jump jump, string context, AuditReport report)
    {
        ReducedCharacter c = scene.Character;
        var arc = jump.Arc;
        void Fail(string what) => report.Violations.Add($"{context}: {what}");
        if (Vector3.Distance(arc.PositionAt(0f), jump.Takeoff.Pose.Position) > 1e-3f)
        {
            Fail("arc does not start at the takeoff pose");
        }

        if (Vector3.Distance(arc.PositionAt(arc.FlightTime), jump.Landing.Pose.Position) > 5e-3f)
        {
            Fail($"arc lands {Vector3.Distance(arc.PositionAt(arc.FlightTime), jump.Landing.Pose.Position):0.000} m from the landing pose");
        }

        if (jump.Takeoff.Cone.AngleTo(arc.TakeoffVelocity) > jump.Takeoff.Cone.HalfAngle + 1e-3f)
        {
            Fail("takeoff velocity outside the takeoff cone");
        }

        if (jump.Landing.Cone.AngleTo(-arc.LandingVelocity) > jump.Landing.Cone.HalfAngle + 1e-3f)
        {
            Fail("reversed landing velocity outside the landing cone");
        }

        if (arc.TakeoffVelocity.Length() > c.TakeoffSpeedMax * 1.001f || arc.LandingVelocity.Length() > c.LandingSpeedMax * 1.001f)
        {
            Fail("speed above the limits");
        }

        float speed = MathF.Max(arc.TakeoffVelocity.Length(), arc.LandingVelocity.Length());
        int steps = Math.Max(8, (int)MathF.Ceiling(arc.FlightTime * speed / 0.02f));
        for (int k = 0; k <= steps; k++)
        {
            RootPose pose = arc.PoseAt(arc.FlightTime * k / steps);
            if (scene.Bvh.Overlaps(new OrientedBox(pose.Position, c.TrunkHalfExtents, pose.Rotation)))
            {
                Fail($"trunk in the level at t = {arc.FlightTime * k / steps:0.000} s");
                break;
            }
        }
    }

    /// <summary>
    /// A walk as its promises say: ground path points at most 0.25 m apart, each on the ground (within 1 cm, found by
    /// a ray of our own), from one stance's contacts to the other's; no rise or drop between neighbouring points
    /// beyond the step height plus the steepest slope over their distance; no ground steeper than the slope at two
    /// neighbouring points; the trunk box as it moves (<see cref="Walk.PoseAt(float)"/>, turning in place included) clear
    /// of the level every 2 cm and 2°; the trunk exactly on the stances at both ends; the trunk never faster than
    /// the walking speed (so the duration at least the length at that speed), never turning faster than twice
    /// the character's <see cref="WalkingLimits.TurnRate"/>.
    /// </summary>
    private static void CheckWalk(PlanningScene scene, Walk walk, string context, AuditReport report)
    {
        ReducedCharacter c = scene.Character;
        WalkingLimits limits = c.Walking;
        void Fail(string what) => report.Violations.Add($"{context}: {what}");
        if (!limits.CanWalk)
        {
            Fail($"{c.Name} does not walk");
            return;
        }

        if (MathF.Abs(walk.Speed - limits.Speed) > 1e-4f || walk.Duration < (walk.Length / limits.Speed) - 1e-3f)
        {
            Fail($"walks at {walk.Speed:0.###} m/s for {walk.Duration:0.###} s, less than its length at {limits.Speed:0.###} m/s");
        }

        // The motion, sampled every 5 ms: the point on the ground path never faster than the speed, the trunk never
        // turning faster than twice the average turn rate (a smoothstep peaks at 1.5 times it).
        const float dt = 0.005f;
        RootPose before = walk.PoseAt(0f);
        Vector3 groundBefore = walk.PointAt(walk.DistanceAt(0f));
        for (float t = dt; t <= walk.Duration + dt; t += dt)
        {
            RootPose now = walk.PoseAt(MathF.Min(t, walk.Duration));
            Vector3 ground = walk.PointAt(walk.DistanceAt(MathF.Min(t, walk.Duration)));
            float step = MathF.Min(t, walk.Duration) - (t - dt);
            float turn = 2f * MathF.Acos(Math.Clamp(MathF.Abs(Quaternion.Dot(before.Rotation, now.Rotation)), 0f, 1f));
            if (step > 1e-6f && Vector3.Distance(groundBefore, ground) > (limits.Speed * step) + 1e-4f)
            {
                Fail($"the trunk moves faster than {limits.Speed:0.###} m/s at {t:0.000} s into the walk");
                break;
            }

            if (step > 1e-6f && turn > (2f * limits.TurnRate * step) + 1e-3f)
            {
                Fail($"the trunk turns at {turn / step:0.0} rad/s at {t:0.000} s into the walk");
                break;
            }

            before = now;
            groundBefore = ground;
        }

        if (Vector3.Distance(walk.PoseAt(0f).Position, walk.From.Pose.Position) > 1e-4f || Vector3.Distance(walk.PoseAt(walk.Duration).Position, walk.To.Pose.Position) > 1e-4f)
        {
            Fail("the trunk does not start and end on the stances");
        }

        float tan = MathF.Tan(limits.MaxSlopeDegrees * MathF.PI / 180f);
        float cos = MathF.Cos(limits.MaxSlopeDegrees * MathF.PI / 180f);
        float alongCos = MathF.Cos(limits.MaxSlopeAlongDegrees * MathF.PI / 180f);
        float grade = MathF.Tan(limits.MaxSlopeAlongDegrees * MathF.PI / 180f);
        bool steepBefore = false;
        var heading = new Vector3(walk.Path[^1].X - walk.Path[0].X, 0f, walk.Path[^1].Z - walk.Path[0].Z);
        for (int i = 0; i < walk.Path.Count; i++)
        {
            Vector3 p = walk.Path[i];
            if (!scene.Bvh.Raycast(p + new Vector3(0f, 0.05f, 0f), -Vector3.UnitY, 0.1f, out RayHit hit))
            {
                Fail($"path point {i} ({p.X:0.00}, {p.Y:0.00}, {p.Z:0.00}) has no ground within 5 cm under it");
                return;
            }

            report.MaxWalkGroundError = MathF.Max(report.MaxWalkGroundError, MathF.Abs(hit.Point.Y - p.Y));
            if (MathF.Abs(hit.Point.Y - p.Y) > 0.01f)
            {
                Fail($"path point {i} lies {MathF.Abs(hit.Point.Y - p.Y) * 100f:0.0} cm off the ground");
            }

            // Steeper than the slope walked on any way, and either steeper than the slope walked up or down or
            // falling to the side more than the first allows (the walk's heading from its first path point to its last).
            Vector3 n = hit.Normal.Y < 0f ? -hit.Normal : hit.Normal;
            float sideways = heading.LengthSquared() > 1e-12f ? MathF.Abs(Vector3.Dot(n, Vector3.Cross(Vector3.UnitY, Vector3.Normalize(heading)))) : float.PositiveInfinity;
            bool steep = n.Y < cos - 1e-3f && (n.Y < alongCos - 1e-3f || sideways > (n.Y * tan) + 1e-3f);
            if (steep && steepBefore)
            {
                Fail($"ground steeper than {limits.MaxSlopeDegrees}° (or {limits.MaxSlopeAlongDegrees}° straight ahead) at path point {i}");
            }

            steepBefore = steep;
            if (i > 0)
            {
                Vector3 q = walk.Path[i - 1];
                float across = new Vector2(p.X - q.X, p.Z - q.Z).Length();
                if (Vector3.Distance(p, q) > 0.25f + 1e-3f && across > 0.25f + 1e-3f)
                {
                    Fail($"path points {i - 1} and {i} are {Vector3.Distance(p, q):0.000} m apart");
                }

                float rise = MathF.Abs(p.Y - q.Y);
                report.MaxWalkRise = MathF.Max(report.MaxWalkRise, rise - (across * grade));
                if (rise > limits.StepHeight + (across * grade) + 1e-3f)
                {
                    Fail($"the ground rises or drops {rise:0.000} m between path points {i - 1} and {i}, above the {limits.StepHeight:0.000} m step");
                }
            }
        }

        for (float d = 0f; d <= walk.Length + 1e-4f; d += 0.02f)
        {
            RootPose pose = walk.PoseAtDistance(MathF.Min(d, walk.Length));
            if (scene.Bvh.Overlaps(new OrientedBox(pose.Position, c.TrunkHalfExtents, pose.Rotation)))
            {
                Fail($"trunk in the level {d:0.00} m along the walk");
                return;
            }
        }

        // Turning in place at both ends, every 2°.
        foreach ((float t0, float span) in new[] { (0f, walk.StartTurn), (walk.Duration - walk.EndTurn, walk.EndTurn) })
        {
            int n = Math.Max(1, (int)MathF.Ceiling(span * 2f * limits.TurnRate / (2f * MathF.PI / 180f)));
            for (int k = 0; k <= n; k++)
            {
                RootPose pose = walk.PoseAt(t0 + (span * k / n));
                if (scene.Bvh.Overlaps(new OrientedBox(pose.Position, c.TrunkHalfExtents, pose.Rotation)))
                {
                    Fail($"trunk in the level turning in place {t0 + (span * k / n):0.00} s into the walk");
                    return;
                }
            }
        }
    }

    private static void CheckNode(PlanningScene scene, RoadmapNode node, string context, AuditReport report)
    {
        ReducedCharacter c = scene.Character;
        void Fail(string what) => report.Violations.Add($"{context}: {what}");
        if (node.Contacts.Count < c.RequiredContacts)
        {
            Fail($"{node.Contacts.Count} contacts, {c.RequiredContacts} required");
        }

        Vector3 sum = Vector3.Zero;
        foreach (Contact contact in node.Contacts)
        {
            sum += contact.Normal;
            (float distance, Vector3 normal) = NearestSurface(scene, contact.Position, contact.Normal);
            float angle = MathF.Acos(Math.Clamp(Vector3.Dot(normal, contact.Normal), -1f, 1f)) * 180f / MathF.PI;
            report.MaxContactOffMesh = MathF.Max(report.MaxContactOffMesh, distance);
            report.MaxContactNormalError = MathF.Max(report.MaxContactNormalError, angle);
            string limb = c.Limbs[contact.Limb].Name;
            if (distance > 0.01f)
            {
                Fail($"{limb} contact {distance * 100f:0.0} cm off the mesh");
            }
            else if (angle > 5f)
            {
                Fail($"{limb} contact normal {angle:0.0}° off the surface's");
            }

            if (Vector3.Dot(contact.Normal, node.Pose.Position - contact.Position) <= 0f)
            {
                Fail($"{limb} contact on a face turned away from the trunk");
            }

            if (!c.Limbs[contact.Limb].Filter.Accepts(contact.Normal))
            {
                Fail($"{limb} contact on a surface its limb may not touch");
            }
        }

        if (node.Contacts.Count > 0 && sum.Length() > 1e-3f && Vector3.Distance(node.Cone.Axis, Vector3.Normalize(sum)) > 1e-3f)
        {
            Fail("cone axis is not the normalised sum of the contact normals");
        }
    }

    /// <summary>The longest leg of <paramref name="model"/> (metres): a foot's hip above its contact point in the rest pose (1 m for a rig without feet).</summary>
    private static float RestLeg(CharacterModel model)
    {
        Rig rig = model.Rig;
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), rig.Neutral(), positions, rotations);
        float leg = 0f;
        foreach (RigLimb limb in model.Limbs.Where(l => l.Kind == LimbKind.Foot))
        {
            leg = MathF.Max(leg, positions[limb.RootJoint].Y - limb.EffectorPosition(positions, rotations).Y);
        }

        return leg > 0f ? leg : 1f;
    }

    private static void CheckAnimation(PlanningScene scene, JumpAnimation animation, AuditReport report)
    {
        CharacterModel model = animation.Model;
        Rig rig = model.Rig;
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        report.Animated = true;
        report.AnimatorProblems = [.. animation.Problems.Select(p => $"jump {p.Jump}: {p.Reason}")];
        int before = report.Violations.Count;

        // Stance effectors hold their contact points (sampled at 240 Hz), on the mesh.
        foreach (ContactPhase phase in animation.ContactPhases)
        {
            RigLimb limb = model.Limbs[phase.Limb];
            for (float t = phase.From; t <= phase.To + 1e-6f; t += 1f / 240f)
            {
                animation.Joints(MathF.Min(t, phase.To), positions, rotations);
                float slip = Vector3.Distance(phase.Touching(limb, positions, rotations), phase.Position);
                report.MaxStanceSlip = MathF.Max(report.MaxStanceSlip, slip);
                if (slip > 0.01f)
                {
                    report.Violations.Add($"animation: {limb.Name} {slip * 100f:0.0} cm off its contact at {t:0.000} s");
                    break;
                }
            }

            if (NearestSurface(scene, phase.Position).Distance > 0.01f)
            {
                report.Violations.Add($"animation: {limb.Name} holds a point off the mesh");
            }
        }

        // No contact point jumps: a limb's next contact within 0.1 s of its last lies within 2 cm of it. For legs shorter
        // than a metre the 0.1 s shrinks with √(leg ÷ 1 m): the same step taken by a smaller body lasts that much
        // less (dynamic similarity: a 4.5 cm rat's feet swing in about 0.02 s where a person's take 0.1 s).
        float quick = 0.1f * MathF.Min(1f, MathF.Sqrt(RestLeg(model)));
        foreach (IGrouping<int, ContactPhase> limbPhases in animation.ContactPhases.GroupBy(p => p.Limb))
        {
            ContactPhase[] ordered = [.. limbPhases.OrderBy(p => p.From)];
            for (int i = 1; i < ordered.Length; i++)
            {
                float gap = ordered[i].From - ordered[i - 1].To;
                float moved = Vector3.Distance(ordered[i].Position, ordered[i - 1].Position);
                if (ordered[i].OnBall != ordered[i - 1].OnBall && gap <= 0.01f && model.Limbs[ordered[i].Limb].Ball is RigLimb ball
                    && moved <= Vector3.Distance(ball.EffectorOffset, model.Limbs[ordered[i].Limb].EffectorOffset) + 0.02f)
                {
                    // A foot rolling heel up onto its ball (or back down): its sole held its point to the end of the
                    // one phase and its ball holds its own from the start of the next (each checked above), a ball's
                    // length apart: nothing moved.
                    continue;
                }

                if (gap < quick && moved > 0.02f)
                {
                    report.MaxContactJump = MathF.Max(report.MaxContactJump, moved);
                    report.Violations.Add($"animation: {model.Limbs[ordered[i].Limb].Name} contact moves {moved * 100f:0.0} cm in {gap:0.000} s at {ordered[i].From:0.000} s");
                }
            }
        }

        // No bone through the level at any frame: every bone segment (parent → joint, effector → contact point) of
        // the body (a loaded rig's helper bones such as IK targets are no body part), less its part within 1 cm of a
        // contact held at that time, made less than one sample (1/120 s) later or released less than one sample before:
        // a sole lifting off its point (a heel rolling up onto its ball) leaves it at a finite speed, still touching it
        // just after the phase's end, and a landing sole arriving at its point touches it just before the phase's start
        // (a rat's paw, held within the animator's 2 mm of its point, 0.4 mm under it 0.3 ms before its landing).
        int boneHits = 0;
        const float step = 1f / 120f;
        for (float t = 0f; t <= animation.Duration + 1e-6f && boneHits == 0; t += step)
        {
            float time = MathF.Min(t, animation.Duration);
            animation.Joints(time, positions, rotations);
            var held = new List<Vector3>();
            foreach (ContactPhase p in animation.ContactPhases)
            {
                if (time >= p.From - step && time <= p.To + step)
                {
                    held.Add(p.Position);
                }
            }

            IReadOnlyList<bool> body = model.Source?.BodyBones ?? [];
            for (int j = 1; j < rig.Joints.Count && boneHits == 0; j++)
            {
                if ((body.Count == 0 || body[j]) && SegmentHits(scene.Bvh, positions[rig.Joints[j].Parent], positions[j], held))
                {
                    boneHits++;
                    report.Violations.Add($"animation: bone {rig.Joints[j].Name} in the level at {time:0.000} s");
                }
            }

            foreach (RigLimb limb in model.Limbs)
            {
                if (boneHits == 0 && SegmentHits(scene.Bvh, positions[limb.EffectorJoint], limb.EffectorPosition(positions, rotations), held))
                {
                    boneHits++;
                    report.Violations.Add($"animation: {limb.Name} sole in the level at {time:0.000} s");
                }
            }
        }

        report.CleanAnimation = report.Violations.Count == before;
    }

    /// <summary>True when the segment crosses a triangle outside 1 cm of every held contact point.</summary>
    private static bool SegmentHits(TriangleBvh bvh, Vector3 a, Vector3 b, List<Vector3> held)
    {
        const int pieces = 16;
        for (int k = 0; k < pieces; k++)
        {
            Vector3 p = Vector3.Lerp(a, b, k / (float)pieces);
            Vector3 q = Vector3.Lerp(a, b, (k + 1) / (float)pieces);
            if (!bvh.Raycast(p, q - p, 1f, out RayHit hit))
            {
                continue;
            }

            bool nearContact = false;
            foreach (Vector3 c in held)
            {
                nearContact |= Vector3.Distance(hit.Point, c) <= 0.01f + (Vector3.Distance(a, b) / pieces);
            }

            if (!nearContact)
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>
    /// Distance from <paramref name="p"/> to the nearest triangle and that triangle's normal; among triangles equally
    /// near (within 1 mm: coincident faces, shared edges) the one whose normal is closest to <paramref name="expected"/>.
    /// </summary>
    public static (float Distance, Vector3 Normal) NearestSurface(PlanningScene scene, Vector3 p, Vector3? expected = null)
    {
        var near = new List<int>();
        for (float r = 0.05f; r <= 1.7f; r *= 2f)
        {
            near.Clear();
            scene.Bvh.TrianglesNear(new Aabb(p - new Vector3(r), p + new Vector3(r)), near);
            if (near.Count > 0)
            {
                break;
            }
        }

        float best = float.PositiveInfinity;
        foreach (int t in near)
        {
            best = MathF.Min(best, Vector3.Distance(scene.Level.Triangles[t].ClosestPoint(p), p));
        }

        Vector3 normal = Vector3.UnitY;
        float agreement = float.NegativeInfinity;
        foreach (int t in near)
        {
            Triangle tri = scene.Level.Triangles[t];
            if (Vector3.Distance(tri.ClosestPoint(p), p) <= best + 1e-3f)
            {
                float dot = expected is Vector3 e ? Vector3.Dot(tri.Normal, e) : 0f;
                if (dot > agreement)
                {
                    agreement = dot;
                    normal = tri.Normal;
                }
            }
        }

        return (best, normal);
    }
}

/// <summary>What <see cref="PlanAudit"/> found about one plan.</summary>
internal sealed class AuditReport(string name, PlannerStatus status, string reason)
{
    public string Name { get; } = name;

    public PlannerStatus Status { get; } = status;

    public string Reason { get; } = reason;

    public List<string> Violations { get; } = [];

    public float StartAcross { get; set; }

    public float StartUpDown { get; set; }

    public float GoalAcross { get; set; }

    public float GoalUpDown { get; set; }

    public float MaxContactOffMesh { get; set; }

    public float MaxContactNormalError { get; set; }

    public float MaxStanceSlip { get; set; }

    public float MaxContactJump { get; set; }

    /// <summary>How many walks the plan holds.</summary>
    public int Walks { get; set; }

    /// <summary>The largest distance (metres) between a walk's path point and the ground found under it.</summary>
    public float MaxWalkGroundError { get; set; }

    /// <summary>The largest rise or drop (metres) between neighbouring walk path points beyond what the slope allows over their distance.</summary>
    public float MaxWalkRise { get; set; }

    public bool Animated { get; set; }

    /// <summary>What the animator itself said was wrong (not an audit finding).</summary>
    public List<string> AnimatorProblems { get; set; } = [];

    public bool CleanAnimation { get; set; }

    /// <summary>What an animator sees in the exported GLB (null when there is no exact animated plan).</summary>
    public AnimatorEye.Look? Look { get; set; }

    /// <summary>Exact, every invariant held, animated cleanly.</summary>
    public bool FullyRight => Status == PlannerStatus.Exact && Violations.Count == 0 && Animated;

    /// <summary>Claimed success although something is wrong: the one outcome never allowed.</summary>
    public bool WrongAnswer => Status == PlannerStatus.Exact && Violations.Count > 0;

    public override string ToString() =>
        $"{Name}: {Status} ({Reason})" + (Violations.Count > 0 ? "; " + string.Join("; ", Violations.Take(4)) + (Violations.Count > 4 ? $" (+{Violations.Count - 4} more)" : "") : "") +
        (AnimatorProblems.Count > 0 ? "; animator: " + string.Join("; ", AnimatorProblems.Take(3)) : "");
}
