using System.Numerics;
using System.Text;
using System.Text.Json;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.IO;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;
using Ballistic.Planner.Walking;

namespace Ballistic.Authoring.Reports;

/// <summary>
/// Writes a plan as the <c>ballistic.plan/2</c> JSON report other tools read. Positions are trunk centres in world
/// metres (Y up), rotations unit quaternions [x, y, z, w], velocities m/s, times seconds, lengths metres. It holds
/// everything <c>ballistic.plan/1</c> held (a <c>/1</c> reader that ignores unknown keys reads it) plus the path's
/// <c>moves</c> in order: each jump as <c>{"kind": "jump", …}</c> with the fields of a <c>jumps</c> entry (the same
/// object, byte for byte), each walk as <c>{"kind": "walk", "from", "to", "path", "duration", "length", "speed",
/// "via"}</c> with its ground path resampled to points at most <see cref="MaxWalkPointSpacing"/> apart; a
/// <c>summary</c> of the moves; and, with an animation, the clip times of every move. <c>jumps</c> lists the jump
/// moves only. Besides the moves it states where the start and goal stances stand relative to the requested points
/// (<c>start</c>, <c>goal</c>: contact centre, distances across and up/down) and the moves set aside because the body
/// could not perform them (<c>rejectedJumps</c>: each one's <c>kind</c>, <c>jump</c> or <c>walk</c>, with its
/// reason). <see cref="PlanReportReader"/> reads it back.
/// </summary>
public static class PlanReportWriter
{
    /// <summary>The schema name written in every report.</summary>
    public const string Schema = "ballistic.plan/2";

    /// <summary>The schema name of the reports written before walking (jumps only), which <see cref="PlanReportReader"/> still reads.</summary>
    public const string SchemaV1 = "ballistic.plan/1";

    /// <summary>The most distance between two consecutive points of a walk's <c>path</c> in a report, metres (along the straight line between them).</summary>
    public const float MaxWalkPointSpacing = 0.25f;

    /// <summary>The name of a <see cref="Locomotion"/> in reports and on the command line: <c>walk+jump</c> or <c>jump</c>.</summary>
    public static string LocomotionName(Locomotion locomotion) => locomotion switch
    {
        Locomotion.WalkAndJump => "walk+jump",
        Locomotion.Jump => "jump",
        _ => throw new ArgumentOutOfRangeException(nameof(locomotion), locomotion, "Unknown locomotion."),
    };

    /// <summary>The status names used in reports, by <see cref="PlannerStatus"/>.</summary>
    public static string StatusName(PlannerStatus status) => status switch
    {
        PlannerStatus.Exact => "exact",
        PlannerStatus.NoPath => "no_path",
        PlannerStatus.Timeout => "timeout",
        PlannerStatus.InvalidStart => "invalid_start",
        PlannerStatus.InvalidGoal => "invalid_goal",
        PlannerStatus.Cancelled => "cancelled",
        PlannerStatus.AnimationFailed => "animation_failed",
        _ => throw new ArgumentOutOfRangeException(nameof(status), status, "Unknown status."),
    };

    /// <summary>
    /// Writes the <c>character</c> block of a report: name, trunk, speed limits, gravity, friction, limbs, and its
    /// walking limits under the character spec's own keys (<c>walkSpeed</c> m/s, 0 when it does not walk;
    /// <c>maxSlope</c> and <c>maxSlopeAlong</c> degrees; <c>stepHeight</c> m), as derived from the rig or given by the spec.
    /// </summary>
    internal static void WriteCharacter(Utf8JsonWriter w, ReducedCharacter character)
    {
        w.WriteStartObject("character");
        w.WriteString("name", character.Name);
        WriteVector(w, "trunkHalfExtents", character.TrunkHalfExtents);
        w.WriteNumber("takeoffSpeedMax", character.TakeoffSpeedMax);
        w.WriteNumber("landingSpeedMax", character.LandingSpeedMax);
        WriteVector(w, "gravity", new Vector3(0f, -character.Limits.Gravity, 0f));
        w.WriteNumber("friction", character.Friction);
        w.WriteNumber("requiredContacts", character.RequiredContacts);
        WalkingLimits walking = character.Walking;
        w.WriteStartObject("walking");
        w.WriteNumber("walkSpeed", walking.CanWalk ? walking.Speed : 0f);
        w.WriteNumber("maxSlope", walking.MaxSlopeDegrees);
        w.WriteNumber("maxSlopeAlong", walking.MaxSlopeAlongDegrees);
        w.WriteNumber("stepHeight", walking.StepHeight);
        w.WriteEndObject();
        w.WriteStartArray("limbs");
        foreach (Limb limb in character.Limbs)
        {
            w.WriteStringValue(limb.Name);
        }

        w.WriteEndArray();
        w.WriteEndObject();
    }

    /// <summary>Writes one jump as an object of the playtest report's <c>jumps</c> array: takeoff and landing stances, velocities, flight time, arc length, apex.</summary>
    internal static void WriteJump(Utf8JsonWriter w, Jump jump, ReducedCharacter character)
    {
        w.WriteStartObject();
        WriteJumpFields(w, jump, character);
        w.WriteEndObject();
    }

    /// <summary>
    /// Writes one jump as an object of the plan report's <c>moves</c> and <c>jumps</c> arrays: <c>"kind": "jump"</c>,
    /// the fields of <see cref="WriteJump"/>, and its <c>duration</c> (the flight time, seconds).
    /// </summary>
    internal static void WriteJumpMove(Utf8JsonWriter w, Jump jump, ReducedCharacter character)
    {
        w.WriteStartObject();
        w.WriteString("kind", "jump");
        WriteJumpFields(w, jump, character);
        w.WriteNumber("duration", jump.Duration);
        w.WriteEndObject();
    }

    /// <summary>
    /// Writes one walk as an object of the plan report's <c>moves</c> array: <c>"kind": "walk"</c>, the stances it
    /// goes <c>from</c> and <c>to</c> (as a jump's takeoff and landing), its ground <c>path</c> (world metres, points at
    /// most <see cref="MaxWalkPointSpacing"/> apart, the walk's own first and last points exactly), <c>duration</c>
    /// (s), <c>length</c> (m, along the path), <c>speed</c> (m/s) and <c>via</c> (ids of the stances passed through).
    /// </summary>
    internal static void WriteWalkMove(Utf8JsonWriter w, Walk walk, ReducedCharacter character)
    {
        w.WriteStartObject();
        w.WriteString("kind", "walk");
        w.WritePropertyName("from");
        WritePose(w, walk.From, character);
        w.WritePropertyName("to");
        WritePose(w, walk.To, character);
        WriteWalkFields(w, walk, ReportPath(walk.Path));
        w.WriteEndObject();
    }

    /// <summary>
    /// Writes the fields every report gives a walk: its ground <c>path</c> (<paramref name="path"/>, world metres: the
    /// plan report's <see cref="ReportPath"/>, the playtest's the walk's own points), <c>duration</c> (s), <c>length</c>
    /// (m, along the path), <c>speed</c> (m/s) and <c>via</c> (ids of the stances passed through).
    /// </summary>
    internal static void WriteWalkFields(Utf8JsonWriter w, Walk walk, IReadOnlyList<Vector3> path)
    {
        w.WriteStartArray("path");
        foreach (Vector3 p in path)
        {
            w.WriteStartArray();
            w.WriteNumberValue(p.X);
            w.WriteNumberValue(p.Y);
            w.WriteNumberValue(p.Z);
            w.WriteEndArray();
        }

        w.WriteEndArray();
        w.WriteNumber("duration", walk.Duration);
        w.WriteNumber("length", walk.Length);
        w.WriteNumber("speed", walk.Speed);
        w.WriteStartArray("via");
        foreach (RoadmapNode node in walk.Via)
        {
            w.WriteNumberValue(node.Id);
        }

        w.WriteEndArray();
    }

    /// <summary>
    /// A walk's ground path as the report writes it: every point of <paramref name="path"/> kept exactly, in order,
    /// with points added evenly along each straight piece longer than <see cref="MaxWalkPointSpacing"/> so that no
    /// two consecutive points are farther apart. World metres.
    /// </summary>
    public static IReadOnlyList<Vector3> ReportPath(IReadOnlyList<Vector3> path)
    {
        ArgumentNullException.ThrowIfNull(path);
        var points = new List<Vector3>(path.Count);
        if (path.Count == 0)
        {
            return points;
        }

        // A little under the limit, so that rounding to float never puts two points farther apart than it.
        const float step = MaxWalkPointSpacing * 0.999f;
        points.Add(path[0]);
        for (int i = 1; i < path.Count; i++)
        {
            Vector3 a = path[i - 1];
            Vector3 b = path[i];
            int pieces = Math.Max(1, (int)MathF.Ceiling(Vector3.Distance(a, b) / step));
            for (int k = 1; k < pieces; k++)
            {
                points.Add(Vector3.Lerp(a, b, (float)k / pieces));
            }

            points.Add(b);
        }

        return points;
    }

    private static void WriteJumpFields(Utf8JsonWriter w, Jump jump, ReducedCharacter character)
    {
        w.WritePropertyName("takeoff");
        WritePose(w, jump.Takeoff, character);
        w.WritePropertyName("landing");
        WritePose(w, jump.Landing, character);
        WriteVector(w, "takeoffVelocity", jump.Arc.TakeoffVelocity);
        WriteVector(w, "landingVelocity", jump.Arc.LandingVelocity);
        w.WriteNumber("flightTime", jump.Arc.FlightTime);
        w.WriteNumber("arcLength", jump.Arc.ArcLength);
        WriteVector(w, "apex", jump.Arc.Apex);
    }

    /// <summary>Writes a named [x, y, z] array.</summary>
    internal static void WriteVector(Utf8JsonWriter w, string name, Vector3 v)
    {
        w.WriteStartArray(name);
        w.WriteNumberValue(v.X);
        w.WriteNumberValue(v.Y);
        w.WriteNumberValue(v.Z);
        w.WriteEndArray();
    }

    private static void WritePose(Utf8JsonWriter w, RoadmapNode node, ReducedCharacter character)
    {
        w.WriteStartObject();
        WriteVector(w, "position", node.Pose.Position);
        w.WriteStartArray("rotation");
        w.WriteNumberValue(node.Pose.Rotation.X);
        w.WriteNumberValue(node.Pose.Rotation.Y);
        w.WriteNumberValue(node.Pose.Rotation.Z);
        w.WriteNumberValue(node.Pose.Rotation.W);
        w.WriteEndArray();
        w.WriteStartObject("cone");
        WriteVector(w, "axis", node.Cone.Axis);
        w.WriteNumber("mu", node.Cone.Mu);
        w.WriteEndObject();
        w.WriteStartArray("contacts");
        foreach (Contact c in node.Contacts)
        {
            w.WriteStartObject();
            w.WriteString("limb", character.Limbs[c.Limb].Name);
            WriteVector(w, "position", c.Position);
            WriteVector(w, "normal", c.Normal);
            w.WriteNumber("mu", c.Mu);
            w.WriteEndObject();
        }

        w.WriteEndArray();
        w.WriteEndObject();
    }

    /// <summary>The report as indented UTF-8 JSON.</summary>
    public static byte[] ToJson(PlanReport report)
    {
        ArgumentNullException.ThrowIfNull(report);
        ReducedCharacter character = report.Scene.Character;
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true }))
        {
            w.WriteStartObject();
            w.WriteString("schema", Schema);
            w.WriteString("level", report.LevelPath);
            WriteCharacter(w, character);

            w.WriteStartObject("request");
            Vector("from", report.From);
            Vector("to", report.To);
            w.WriteStartObject("tolerance");
            w.WriteNumber("across", report.Tolerance.Across);
            w.WriteNumber("upDown", report.Tolerance.UpDown);
            w.WriteEndObject();
            if (report.Locomotion is Locomotion locomotion)
            {
                w.WriteString("locomotion", LocomotionName(locomotion));
            }

            w.WriteEndObject();

            // Where the stances stand: their contacts' centre and its distances from the requested points.
            Placement("start", report.Result.StartPlacement);
            Placement("goal", report.Result.GoalPlacement);

            w.WriteString("status", StatusName(report.Result.Status));
            w.WriteString("reason", report.Result.Reason);

            w.WriteStartObject("roadmap");
            w.WriteNumber("nodes", report.RoadmapNodes);
            w.WriteNumber("edges", report.RoadmapEdges);
            w.WriteNumber("seed", report.Seed);
            w.WriteNumber("bakeSeconds", Math.Round(report.BakeSeconds, 6));
            w.WriteEndObject();

            PlanResult result = report.Result;
            w.WriteNumber("totalFlightTime", result.TotalFlightTime);
            w.WriteStartObject("summary");
            w.WriteNumber("moves", result.Moves.Count);
            w.WriteNumber("jumps", result.Jumps.Count);
            w.WriteNumber("walks", result.Walks.Count());
            w.WriteNumber("flightTime", result.TotalFlightTime);
            w.WriteNumber("walkLength", result.Walks.Sum(walk => walk.Length));
            w.WriteNumber("walkTime", result.Walks.Sum(walk => walk.Duration));
            w.WriteNumber("totalDuration", result.TotalDuration);
            w.WriteEndObject();

            w.WriteStartArray("moves");
            foreach (Move move in result.Moves)
            {
                switch (move)
                {
                    case Jump jump:
                        WriteJumpMove(w, jump, character);
                        break;
                    case Walk walk:
                        WriteWalkMove(w, walk, character);
                        break;
                    default:
                        throw new InvalidOperationException($"A plan report cannot write a move of kind {move.GetType().Name}.");
                }
            }

            w.WriteEndArray();

            w.WriteStartArray("jumps");
            foreach (Jump jump in result.Jumps)
            {
                WriteJumpMove(w, jump, character);
            }

            w.WriteEndArray();

            w.WriteStartArray("rejectedJumps");
            foreach (RejectedJump rejected in report.Rejected)
            {
                w.WriteStartObject();
                w.WriteString("kind", rejected.IsWalk ? "walk" : "jump");
                Vector("from", rejected.Takeoff.Pose.Position);
                Vector("to", rejected.Landing.Pose.Position);
                w.WriteString("reason", rejected.Reason);
                w.WriteEndObject();
            }

            w.WriteEndArray();

            // Why each jump of the path is not a walk (a request planned with jumps only says so by its locomotion).
            if (report.Locomotion != Locomotion.Jump)
            {
                w.WriteStartArray("notWalked");
                foreach ((int move, WalkFailure failure, string reason) in WalkRefusals.Of(report.Scene, result.Moves))
                {
                    w.WriteStartObject();
                    w.WriteNumber("move", move);
                    Vector("from", result.Moves[move].From.Pose.Position);
                    Vector("to", result.Moves[move].To.Pose.Position);
                    w.WriteString("walk", WalkRefusals.Name(failure));
                    w.WriteString("reason", reason);
                    w.WriteEndObject();
                }

                w.WriteEndArray();
            }

            if (report.Animation is { } animation)
            {
                WriteAnimation(w, animation);
            }

            w.WriteStartObject("timings");
            foreach ((string name, double seconds) in report.Timings)
            {
                w.WriteNumber(name, Math.Round(seconds, 6));
            }

            w.WriteEndObject();
            w.WriteEndObject();

            void Vector(string name, Vector3 v)
            {
                w.WriteStartArray(name);
                w.WriteNumberValue(v.X);
                w.WriteNumberValue(v.Y);
                w.WriteNumberValue(v.Z);
                w.WriteEndArray();
            }

            void Placement(string name, EndpointPlacement? placement)
            {
                if (placement is null)
                {
                    return;
                }

                w.WriteStartObject(name);
                Vector("requested", placement.Requested);
                w.WriteBoolean("placed", placement.Placed);
                if (placement.Placed)
                {
                    Vector("contactCentre", placement.ContactCentre);
                    w.WriteNumber("across", placement.Across);
                    w.WriteNumber("upDown", placement.UpDown);
                }
                else if (placement.NearestValid is float nearest)
                {
                    w.WriteNumber("nearestValidPose", nearest);
                }

                w.WriteEndObject();
            }
        }

        return stream.ToArray();
    }

    private static void WriteAnimation(Utf8JsonWriter w, AnimationReport report)
    {
        JumpAnimation animation = report.Animation;
        w.WriteStartObject("animation");
        w.WriteString("glb", report.GlbPath.Replace('\\', '/'));
        w.WriteString("clip", report.Clip);
        w.WriteNumber("duration", animation.Duration);
        w.WriteNumber("frames", animation.Frames.Count);
        w.WriteNumber("failedContactPoses", animation.FailedContactPoses);
        w.WriteStartArray("moves");
        for (int m = 0; m < animation.Moves.Count; m++)
        {
            w.WriteStartObject();
            w.WriteString("kind", animation.Moves[m] is Walk ? "walk" : "jump");
            w.WriteNumber("start", animation.MoveStart(m));
            w.WriteNumber("end", animation.MoveEnd(m));
            w.WriteEndObject();
        }

        w.WriteEndArray();
        w.WriteStartObject("limbs");
        foreach (RigLimb limb in animation.Model.Limbs)
        {
            w.WriteStartObject(limb.Name);
            w.WriteString("effectorBone", animation.Model.Rig.Joints[limb.EffectorJoint].Name);
            w.WriteStartArray("effectorOffset");
            w.WriteNumberValue(limb.EffectorOffset.X);
            w.WriteNumberValue(limb.EffectorOffset.Y);
            w.WriteNumberValue(limb.EffectorOffset.Z);
            w.WriteEndArray();
            if (limb.Ball is RigLimb ball)
            {
                // Where a foot rolled heel up touches (phases "on": "ball"), in the same frame.
                w.WriteStartArray("ballOffset");
                w.WriteNumberValue(ball.EffectorOffset.X);
                w.WriteNumberValue(ball.EffectorOffset.Y);
                w.WriteNumberValue(ball.EffectorOffset.Z);
                w.WriteEndArray();
            }

            w.WriteEndObject();
        }

        w.WriteEndObject();
        w.WriteStartArray("contactPhases");
        foreach (ContactPhase phase in animation.ContactPhases)
        {
            w.WriteStartObject();
            w.WriteString("limb", animation.Model.Limbs[phase.Limb].Name);
            w.WriteStartArray("position");
            w.WriteNumberValue(phase.Position.X);
            w.WriteNumberValue(phase.Position.Y);
            w.WriteNumberValue(phase.Position.Z);
            w.WriteEndArray();
            w.WriteNumber("from", phase.From);
            w.WriteNumber("to", phase.To);
            if (phase.OnBall)
            {
                w.WriteString("on", "ball");
            }

            w.WriteEndObject();
        }

        w.WriteEndArray();
        w.WriteEndObject();
    }

    /// <summary>Writes the report to <paramref name="path"/>, creating its folder.</summary>
    public static void Save(PlanReport report, string path)
    {
        ArgumentNullException.ThrowIfNull(path);
        OutputFile.Write(path, ToJson(report));
    }

    /// <summary>The report as a string (for tests and logs).</summary>
    public static string ToJsonString(PlanReport report) => Encoding.UTF8.GetString(ToJson(report));
}
