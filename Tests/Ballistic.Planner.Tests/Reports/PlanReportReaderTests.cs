using System.Numerics;
using System.Text;
using System.Text.Json.Nodes;
using Ballistic.Authoring.Reports;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Reports;

/// <summary>Reading plan reports back: <c>/2</c> as written, <c>/1</c> as jump moves, anything malformed as one line naming the file and element.</summary>
public sealed class PlanReportReaderTests
{
    private static readonly string V1Sample = Path.Combine(RepositoryFiles.Root, "Tests", "Ballistic.Planner.Tests", "Reports", "plan-v1.json");

    [Test]
    public void AWrittenReportReadsBackMoveByMove()
    {
        PlanResult result = WalkPlans.WalkAndJump;
        PlanReportSummary read = PlanReportReader.Read(PlanReportWriter.ToJson(WalkPlans.Report(result)), "plan.json");
        Assert.Multiple(() =>
        {
            Assert.That(read.Schema, Is.EqualTo(PlanReportWriter.Schema));
            Assert.That(read.Status, Is.EqualTo(PlannerStatus.Exact));
            Assert.That(read.Reason, Is.EqualTo(result.Reason));
            Assert.That(read.From, Is.EqualTo(GapCourse.From));
            Assert.That(read.To, Is.EqualTo(GapCourse.To));
            Assert.That(read.Moves, Has.Count.EqualTo(result.Moves.Count));
            Assert.That(read.WalkCount, Is.EqualTo(2));
            Assert.That(read.JumpCount, Is.EqualTo(result.Jumps.Count));
            Assert.That(read.TotalDuration, Is.EqualTo(result.TotalDuration).Within(1e-4f));
        });

        for (int m = 0; m < result.Moves.Count; m++)
        {
            Move move = result.Moves[m];
            ReportedMove got = read.Moves[m];
            Assert.That(got.Kind, Is.EqualTo(move is Walk ? ReportedMoveKind.Walk : ReportedMoveKind.Jump), $"move {m}");
            Assert.That(got.From, Is.EqualTo(move.From.Pose.Position), $"move {m}");
            Assert.That(got.To, Is.EqualTo(move.To.Pose.Position), $"move {m}");
            Assert.That(got.Duration, Is.EqualTo(move.Duration), $"move {m}");
            Assert.That(got.Path, Is.EqualTo(move is Walk walk ? PlanReportWriter.ReportPath(walk.Path) : Array.Empty<Vector3>()), $"move {m}");
        }
    }

    [Test]
    public void AStoredFirstSchemaReportReadsAsJumpMoves()
    {
        byte[] bytes = File.ReadAllBytes(V1Sample);
        JsonNode json = JsonNode.Parse(bytes)!;
        PlanReportSummary read = PlanReportReader.Read(bytes, "plan-v1.json");
        Assert.Multiple(() =>
        {
            Assert.That(read.Schema, Is.EqualTo("ballistic.plan/1"));
            Assert.That(read.Status, Is.EqualTo(PlannerStatus.Exact));
            Assert.That(read.Reason, Is.EqualTo((string?)json["reason"]));
            Assert.That(read.From, Is.EqualTo(new Vector3(-6f, 0f, 0f)));
            Assert.That(read.To, Is.EqualTo(new Vector3(11.5f, 1f, 0f)));
            Assert.That(read.Moves, Has.Count.EqualTo(json["jumps"]!.AsArray().Count).And.Count.GreaterThan(2));
            Assert.That(read.Moves.Select(m => m.Kind), Has.All.EqualTo(ReportedMoveKind.Jump));
            Assert.That(read.Moves.Select(m => m.Path.Count), Has.All.Zero);
            Assert.That(read.TotalDuration, Is.EqualTo((float)json["totalFlightTime"]!).Within(1e-4f));
        });

        for (int m = 1; m < read.Moves.Count; m++)
        {
            Assert.That(read.Moves[m].From, Is.EqualTo(read.Moves[m - 1].To), "each jump takes off where the last landed");
        }

        Assert.That(read.Moves[0].Duration, Is.EqualTo((float)json["jumps"]![0]!["flightTime"]!));
    }

    private static JsonObject Written() => JsonNode.Parse(PlanReportWriter.ToJson(WalkPlans.Report(WalkPlans.WalkAndJump)))!.AsObject();

    private static JsonObject FirstSchema() => JsonNode.Parse(File.ReadAllBytes(V1Sample))!.AsObject();

    public static IEnumerable<TestCaseData> Malformed()
    {
        TestCaseData Case(string name, Func<JsonObject> make, Action<JsonObject> change, string expected) =>
            new TestCaseData(make, change, expected).SetName($"Malformed: {name}");

        yield return Case("another schema", Written, j => j["schema"] = "ballistic.plan/3", "is not a Ballistic plan report (schema 'ballistic.plan/3'");
        yield return Case("no schema", Written, j => j.Remove("schema"), "is not a Ballistic plan report (no schema");
        yield return Case("a schema number", Written, j => j["schema"] = 2, "(schema a number");
        yield return Case("an unknown status", Written, j => j["status"] = "fine", "plan.json: status: 'fine' is not a plan status");
        yield return Case("no reason", Written, j => j.Remove("reason"), "plan.json: reason: is missing.");
        yield return Case("no request", Written, j => j.Remove("request"), "plan.json: request: is missing.");
        yield return Case("a request point as text", Written, j => j["request"]!["from"] = "0,0,0", "plan.json: request.from: must be an array of 3 numbers [x, y, z], not a string.");
        yield return Case("a request point of two numbers", Written, j => j["request"]!["to"] = new JsonArray(1, 2), "plan.json: request.to: must be an array of 3 numbers [x, y, z], not an array of 2.");
        yield return Case("no moves", Written, j => j.Remove("moves"), "plan.json: moves: is missing.");
        yield return Case("moves as an object", Written, j => j["moves"] = new JsonObject(), "plan.json: moves: must be an array, not an object.");
        yield return Case("a move that is a number", Written, j => j["moves"]![1] = 3, "plan.json: moves[1]: must be an object, not a number.");
        yield return Case("an unknown kind", Written, j => j["moves"]![1]!["kind"] = "fly", "plan.json: moves[1].kind: 'fly' is not a move kind (jump or walk).");
        yield return Case("a move without kind", Written, j => j["moves"]![0]!.AsObject().Remove("kind"), "plan.json: moves[0].kind: is missing.");
        yield return Case("a walk without its path", Written, j => j["moves"]![0]!.AsObject().Remove("path"), "plan.json: moves[0].path: is missing.");
        yield return Case("a walk path as a number", Written, j => j["moves"]![0]!["path"] = 4, "plan.json: moves[0].path: must be an array, not a number.");
        yield return Case("a walk path point with text", Written, j => j["moves"]![0]!["path"]![2]![1] = "up", "plan.json: moves[0].path[2][1]: must be a number, not a string.");
        yield return Case("a walk path of one point", Written, j => j["moves"]![0]!["path"] = new JsonArray(new JsonArray(0, 0, 0)), "plan.json: moves[0].path: has 1 points; a walk's path needs at least two.");
        yield return Case("walk path points too far apart", Written, j => j["moves"]![0]!["path"] = new JsonArray(new JsonArray(0, 0, 0), new JsonArray(0.5, 0, 0)), "plan.json: moves[0].path[1]: is 0.5 m from the point before it, more than the 0.25 m allowed.");
        yield return Case("a walk without its stance", Written, j => j["moves"]![0]!.AsObject().Remove("from"), "plan.json: moves[0].from: is missing.");
        yield return Case("a walk stance without position", Written, j => j["moves"]![0]!["to"]!.AsObject().Remove("position"), "plan.json: moves[0].to.position: is missing.");
        yield return Case("a walk duration as text", Written, j => j["moves"]![0]!["duration"] = "1 s", "plan.json: moves[0].duration: must be a number, not a string.");
        yield return Case("a negative walk duration", Written, j => j["moves"]![0]!["duration"] = -1, "plan.json: moves[0].duration: must not be negative, not -1.");
        yield return Case("a jump without flight time", Written, j => j["moves"]![1]!.AsObject().Remove("flightTime"), "plan.json: moves[1].flightTime: is missing.");
        yield return Case("a jump landing as an array", Written, j => j["moves"]![1]!["landing"] = new JsonArray(), "plan.json: moves[1].landing: must be an object, not an array.");
        yield return Case("a flight time beyond float", Written, j => j["moves"]![1]!["flightTime"] = JsonNode.Parse("1e39"), "plan.json: moves[1].flightTime: 1e39 is not a finite number.");
        yield return Case("no jumps", Written, j => j.Remove("jumps"), "plan.json: jumps: is missing.");
        yield return Case("a jump missing from jumps", Written, j => j["jumps"]!.AsArray().RemoveAt(0), "plan.json: jumps: lists");
        yield return Case("jumps out of order", Written, j => { JsonNode first = j["jumps"]![0]!.DeepClone(); j["jumps"]![0] = j["jumps"]![1]!.DeepClone(); j["jumps"]![1] = first; }, "plan.json: jumps[0]: is not the jump of moves[1]");
        yield return Case("/1: a jump as text", FirstSchema, j => j["jumps"]![2] = "jump", "plan.json: jumps[2]: must be an object, not a string.");
        yield return Case("/1: a negative flight time", FirstSchema, j => j["jumps"]![0]!["flightTime"] = -0.5, "plan.json: jumps[0].flightTime: must not be negative, not -0.5.");
        yield return Case("/1: a takeoff position of null", FirstSchema, j => j["jumps"]![1]!["takeoff"]!["position"] = null, "plan.json: jumps[1].takeoff.position: must be an array of 3 numbers [x, y, z], not null.");
        yield return Case("/1: no jumps", FirstSchema, j => j.Remove("jumps"), "plan.json: jumps: is missing.");
    }

    [TestCaseSource(nameof(Malformed))]
    public void AMalformedReportIsOneLineNamingTheFileAndElement(Func<JsonObject> make, Action<JsonObject> change, string expected)
    {
        JsonObject json = make();
        change(json);
        PlanReportException? e = Assert.Throws<PlanReportException>(() => PlanReportReader.Read(Encoding.UTF8.GetBytes(json.ToJsonString()), "plan.json"));
        Assert.That(e!.Message, Does.Contain(expected));
        Assert.That(e.Message, Does.StartWith("plan.json"));
        Assert.That(e.Message, Does.Not.Contain('\n'));
    }

    [TestCase("", "plan.json is not valid JSON")]
    [TestCase("{\"schema\": ", "plan.json is not valid JSON")]
    [TestCase("{\"schema\": \"ballistic.plan/2\", \"status\": \"\\ud800\"}", "plan.json: status: is not valid text")]
    [TestCase("{\"schema\": \"\\udc00\"}", "plan.json: schema: is not valid text")]
    [TestCase("[1, 2]", "plan.json is not a Ballistic plan report: its JSON is an array, not an object.")]
    [TestCase("\"ballistic.plan/2\"", "its JSON is a string")]
    public void TextThatIsNotAReportIsOneLine(string text, string expected)
    {
        PlanReportException? e = Assert.Throws<PlanReportException>(() => PlanReportReader.Read(Encoding.UTF8.GetBytes(text), "plan.json"));
        Assert.That(e!.Message, Does.Contain(expected).And.Not.Contain('\n'));
    }

    [Test]
    public void BytesThatAreNotUtf8OrNestTooDeepAreOneLine()
    {
        byte[] invalid = [(byte)'{', (byte)'"', 0xff, 0xfe, (byte)'"', (byte)':', (byte)'1', (byte)'}'];
        byte[] deep = Encoding.UTF8.GetBytes(new string('[', 5000) + new string(']', 5000));
        foreach (byte[] bytes in new[] { invalid, deep })
        {
            PlanReportException? e = Assert.Throws<PlanReportException>(() => PlanReportReader.Read(bytes, "odd\nname.json"));
            Assert.That(e!.Message, Does.StartWith("odd\\u000aname.json is not valid JSON").And.Not.Contain('\n'));
        }

        // A byte order mark is fine.
        byte[] written = PlanReportWriter.ToJson(WalkPlans.Report(WalkPlans.JumpOnly));
        Assert.That(PlanReportReader.Read([0xef, 0xbb, 0xbf, .. written], "bom.json").JumpCount, Is.EqualTo(WalkPlans.JumpOnly.Jumps.Count));
    }

    [Test]
    public void DamagedReportsNeverEscapeAsAnotherException()
    {
        // Seeded: cut the report short or overwrite a byte, many times; the reader reads it or says why, nothing else.
        byte[] written = PlanReportWriter.ToJson(WalkPlans.Report(WalkPlans.WalkAndJump));
        var random = new Random(11);
        int refused = 0;
        for (int i = 0; i < 400; i++)
        {
            byte[] bytes = (byte[])written.Clone();
            if (i % 2 == 0)
            {
                bytes = bytes[..random.Next(bytes.Length)];
            }
            else
            {
                const string junk = "{}[]\",:0-.e x\u00ff";
                bytes[random.Next(bytes.Length)] = (byte)junk[random.Next(junk.Length)];
            }

            try
            {
                PlanReportReader.Read(bytes, "damaged.json");
            }
            catch (PlanReportException e)
            {
                Assert.That(e.Message, Does.StartWith("damaged.json").And.Not.Contain('\n'));
                refused++;
            }
        }

        Assert.That(refused, Is.GreaterThan(200), "most damage is found");
    }
}
