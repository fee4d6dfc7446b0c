using System.Globalization;
using System.Numerics;
using System.Text.Json;
using Ballistic.Planner.IO;
using Ballistic.Planner.Planning;

namespace Ballistic.Authoring.Reports;

/// <summary>
/// Reads a plan report (<c>ballistic.plan/2</c>, or <c>ballistic.plan/1</c> from before walking) into a
/// <see cref="PlanReportSummary"/>: schema, status, reason, requested points and the moves with their stances'
/// trunk centres, durations and walks' ground paths. A <c>/1</c> report reads as jump moves only. Anything
/// malformed (not JSON, another schema, a key missing or of the wrong type, a number not finite, a walk path with
/// fewer than two points or points farther apart than <see cref="PlanReportWriter.MaxWalkPointSpacing"/>, a
/// <c>/2</c> report whose <c>jumps</c> are not its jump moves) is a <see cref="PlanReportException"/> with one line
/// naming the file, the element and the problem.
/// </summary>
public static class PlanReportReader
{
    // Rounding slack when checking the spacing of walk path points, metres.
    private const float SpacingSlack = 1e-4f;

    /// <summary>Reads the report's UTF-8 JSON bytes; <paramref name="file"/> names it in error messages.</summary>
    /// <exception cref="PlanReportException">The bytes are not a readable <c>ballistic.plan/1</c> or <c>/2</c> report.</exception>
    public static PlanReportSummary Read(byte[] bytes, string file)
    {
        ArgumentNullException.ThrowIfNull(bytes);
        ArgumentNullException.ThrowIfNull(file);
        var reader = new Reader(Printable(file));
        ReadOnlyMemory<byte> json = bytes;
        if (bytes.AsSpan().StartsWith("\uFEFF"u8))
        {
            json = json[3..];
        }

        if (!System.Text.Unicode.Utf8.IsValid(json.Span))
        {
            throw new PlanReportException($"{reader.File} is not valid JSON: it is not UTF-8 text.");
        }

        JsonDocument document;
        try
        {
            document = JsonDocument.Parse(json);
        }
        catch (JsonException e)
        {
            throw new PlanReportException($"{reader.File} is not valid JSON: {Planner.IO.MessageText.Json(e)}.", e);
        }

        using (document)
        {
            return reader.Read(document.RootElement);
        }
    }

    /// <summary>The text cut to 80 characters, control characters escaped, for messages.</summary>
    private static string Printable(string text) =>
        MessageText.Printable(text.Length > 80 ? string.Concat(text.AsSpan(0, 77), "...") : text);

    private sealed class Reader(string file)
    {
        public string File { get; } = file;

        public PlanReportSummary Read(JsonElement root)
        {
            if (root.ValueKind != JsonValueKind.Object)
            {
                throw new PlanReportException($"{File} is not a Ballistic plan report: its JSON is {Describe(root)}, not an object.");
            }

            string schema = root.TryGetProperty("schema", out JsonElement s) && s.ValueKind == JsonValueKind.String ? String(s, "schema") : "";
            if (schema != PlanReportWriter.Schema && schema != PlanReportWriter.SchemaV1)
            {
                string found = root.TryGetProperty("schema", out JsonElement given) ? given.ValueKind == JsonValueKind.String ? $"schema '{Printable(schema)}'" : $"schema {Describe(given)}" : "no schema";
                throw new PlanReportException($"{File} is not a Ballistic plan report ({found}, expected '{PlanReportWriter.Schema}' or '{PlanReportWriter.SchemaV1}').");
            }

            string statusName = Text(root, "status", "");
            PlannerStatus status = Enum.GetValues<PlannerStatus>().FirstOrDefault(x => PlanReportWriter.StatusName(x) == statusName, (PlannerStatus)(-1));
            if (status == (PlannerStatus)(-1))
            {
                throw Error("status", $"'{Printable(statusName)}' is not a plan status (one of {string.Join(", ", Enum.GetValues<PlannerStatus>().Select(PlanReportWriter.StatusName))}).");
            }

            string reason = Text(root, "reason", "");
            JsonElement request = Object(root, "request", "");
            Vector3 from = Vector(request, "from", "request");
            Vector3 to = Vector(request, "to", "request");

            var moves = new List<ReportedMove>();
            JsonElement jumps = Array(root, "jumps", "");
            if (schema == PlanReportWriter.SchemaV1)
            {
                int j = 0;
                foreach (JsonElement jump in jumps.EnumerateArray())
                {
                    moves.Add(Jump(jump, $"jumps[{j++}]"));
                }

                return new PlanReportSummary(schema, status, reason, from, to, moves);
            }

            int m = 0;
            foreach (JsonElement move in Array(root, "moves", "").EnumerateArray())
            {
                string where = $"moves[{m++}]";
                if (move.ValueKind != JsonValueKind.Object)
                {
                    throw Error(where, $"must be an object, not {Describe(move)}.");
                }

                string kind = Text(move, "kind", where);
                moves.Add(kind switch
                {
                    "jump" => Jump(move, where),
                    "walk" => Walk(move, where),
                    _ => throw Error($"{where}.kind", $"'{Printable(kind)}' is not a move kind (jump or walk)."),
                });
            }

            // The jumps array lists the jump moves, in order.
            int[] jumpMoves = [.. Enumerable.Range(0, moves.Count).Where(i => moves[i].Kind == ReportedMoveKind.Jump)];
            if (jumps.GetArrayLength() != jumpMoves.Length)
            {
                throw Error("jumps", $"lists {jumps.GetArrayLength()} jumps but 'moves' holds {jumpMoves.Length} jump moves.");
            }

            int k = 0;
            foreach (JsonElement jump in jumps.EnumerateArray())
            {
                string where = $"jumps[{k}]";
                ReportedMove listed = Jump(jump, where);
                ReportedMove move = moves[jumpMoves[k]];
                if (listed.From != move.From || listed.To != move.To || listed.Duration != move.Duration)
                {
                    throw Error(where, $"is not the jump of moves[{jumpMoves[k]}] (its takeoff, landing or flight time differ).");
                }

                k++;
            }

            return new PlanReportSummary(schema, status, reason, from, to, moves);
        }

        private ReportedMove Jump(JsonElement jump, string where)
        {
            if (jump.ValueKind != JsonValueKind.Object)
            {
                throw Error(where, $"must be an object, not {Describe(jump)}.");
            }

            Vector3 from = Vector(Object(jump, "takeoff", where), "position", $"{where}.takeoff");
            Vector3 to = Vector(Object(jump, "landing", where), "position", $"{where}.landing");
            float duration = Number(jump, "flightTime", where);
            if (duration < 0f)
            {
                throw Error($"{where}.flightTime", $"must not be negative, not {Format(duration)}.");
            }

            return new ReportedMove(ReportedMoveKind.Jump, from, to, duration, []);
        }

        private ReportedMove Walk(JsonElement walk, string where)
        {
            Vector3 from = Vector(Object(walk, "from", where), "position", $"{where}.from");
            Vector3 to = Vector(Object(walk, "to", where), "position", $"{where}.to");
            JsonElement pathJson = Array(walk, "path", where);
            if (pathJson.GetArrayLength() < 2)
            {
                throw Error($"{where}.path", $"has {pathJson.GetArrayLength()} points; a walk's path needs at least two.");
            }

            var path = new List<Vector3>(pathJson.GetArrayLength());
            foreach (JsonElement point in pathJson.EnumerateArray())
            {
                string at = $"{where}.path[{path.Count}]";
                Vector3 p = Vector(point, at);
                if (path.Count > 0 && Vector3.Distance(path[^1], p) is float gap && gap > PlanReportWriter.MaxWalkPointSpacing + SpacingSlack)
                {
                    throw Error(at, $"is {Format(gap)} m from the point before it, more than the {Format(PlanReportWriter.MaxWalkPointSpacing)} m allowed.");
                }

                path.Add(p);
            }

            float duration = Number(walk, "duration", where);
            if (duration < 0f)
            {
                throw Error($"{where}.duration", $"must not be negative, not {Format(duration)}.");
            }

            return new ReportedMove(ReportedMoveKind.Walk, from, to, duration, path);
        }

        private PlanReportException Error(string element, string problem) => new($"{File}: {element}: {problem}");

        private static string Name(string parent, string key) => parent.Length == 0 ? key : $"{parent}.{key}";

        private JsonElement Property(JsonElement parent, string key, string where) =>
            parent.TryGetProperty(key, out JsonElement value) ? value : throw Error(Name(where, key), "is missing.");

        private JsonElement Object(JsonElement parent, string key, string where)
        {
            JsonElement value = Property(parent, key, where);
            return value.ValueKind == JsonValueKind.Object ? value : throw Error(Name(where, key), $"must be an object, not {Describe(value)}.");
        }

        private JsonElement Array(JsonElement parent, string key, string where)
        {
            JsonElement value = Property(parent, key, where);
            return value.ValueKind == JsonValueKind.Array ? value : throw Error(Name(where, key), $"must be an array, not {Describe(value)}.");
        }

        private string Text(JsonElement parent, string key, string where)
        {
            JsonElement value = Property(parent, key, where);
            return value.ValueKind == JsonValueKind.String ? String(value, Name(where, key)) : throw Error(Name(where, key), $"must be a string, not {Describe(value)}.");
        }

        private string String(JsonElement value, string element)
        {
            try
            {
                return value.GetString()!;
            }
            catch (InvalidOperationException e)
            {
                // An escape naming half of a UTF-16 surrogate pair, for one.
                throw new PlanReportException($"{File}: {element}: is not valid text ({Printable(e.Message)})", e);
            }
        }

        private float Number(JsonElement parent, string key, string where) => Number(Property(parent, key, where), Name(where, key));

        private float Number(JsonElement value, string element)
        {
            if (value.ValueKind != JsonValueKind.Number)
            {
                throw Error(element, $"must be a number, not {Describe(value)}.");
            }

            return value.TryGetSingle(out float f) && float.IsFinite(f) ? f : throw Error(element, $"{Printable(value.GetRawText())} is not a finite number.");
        }

        private Vector3 Vector(JsonElement parent, string key, string where) => Vector(Property(parent, key, where), Name(where, key));

        private Vector3 Vector(JsonElement value, string element)
        {
            if (value.ValueKind != JsonValueKind.Array || value.GetArrayLength() != 3)
            {
                string found = value.ValueKind == JsonValueKind.Array ? $"an array of {value.GetArrayLength()}" : Describe(value);
                throw Error(element, $"must be an array of 3 numbers [x, y, z], not {found}.");
            }

            return new Vector3(Number(value[0], $"{element}[0]"), Number(value[1], $"{element}[1]"), Number(value[2], $"{element}[2]"));
        }

        private static string Describe(JsonElement value) => value.ValueKind switch
        {
            JsonValueKind.Object => "an object",
            JsonValueKind.Array => "an array",
            JsonValueKind.String => "a string",
            JsonValueKind.Number => "a number",
            JsonValueKind.True => "true",
            JsonValueKind.False => "false",
            _ => "null",
        };

        private static string Format(float value) => value.ToString("0.###", CultureInfo.InvariantCulture);
    }
}
