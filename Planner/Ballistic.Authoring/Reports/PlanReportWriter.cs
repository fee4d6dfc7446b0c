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

namespace Ballistic.Authoring.Reports;

/// <summary>
/// Writes a plan as the <c>ballistic.plan/1</c> JSON report other tools read. Positions are trunk centres in world
/// metres (Y up), rotations unit quaternions [x, y, z, w], velocities m/s, times seconds. Besides the jumps it
/// states where the start and goal stances stand relative to the requested points (<c>start</c>, <c>goal</c>:
/// contact centre, distances across and up/down) and the jumps set aside because the body could not perform them
/// (<c>rejectedJumps</c>, with reasons).
/// </summary>
public static class PlanReportWriter
{
    /// <summary>The schema name written in every report.</summary>
    public const string Schema = "ballistic.plan/1";

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

    /// <summary>Writes the <c>character</c> block of a report: name, trunk, speed limits, gravity, friction, limbs.</summary>
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
        w.WriteStartArray("limbs");
        foreach (Limb limb in character.Limbs)
        {
            w.WriteStringValue(limb.Name);
        }

        w.WriteEndArray();
        w.WriteEndObject();
    }

    /// <summary>Writes one jump as an object of the report's <c>jumps</c> array: takeoff and landing stances, velocities, flight time, arc length, apex.</summary>
    internal static void WriteJump(Utf8JsonWriter w, Jump jump, ReducedCharacter character)
    {
        w.WriteStartObject();
        w.WritePropertyName("takeoff");
        WritePose(w, jump.Takeoff, character);
        w.WritePropertyName("landing");
        WritePose(w, jump.Landing, character);
        WriteVector(w, "takeoffVelocity", jump.Arc.TakeoffVelocity);
        WriteVector(w, "landingVelocity", jump.Arc.LandingVelocity);
        w.WriteNumber("flightTime", jump.Arc.FlightTime);
        w.WriteNumber("arcLength", jump.Arc.ArcLength);
        WriteVector(w, "apex", jump.Arc.Apex);
        w.WriteEndObject();
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

            w.WriteNumber("totalFlightTime", report.Result.TotalFlightTime);
            w.WriteStartArray("jumps");
            foreach (Jump jump in report.Result.Jumps)
            {
                WriteJump(w, jump, character);
            }

            w.WriteEndArray();

            w.WriteStartArray("rejectedJumps");
            foreach (RejectedJump rejected in report.Rejected)
            {
                w.WriteStartObject();
                Vector("from", rejected.Takeoff.Pose.Position);
                Vector("to", rejected.Landing.Pose.Position);
                w.WriteString("reason", rejected.Reason);
                w.WriteEndObject();
            }

            w.WriteEndArray();

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
