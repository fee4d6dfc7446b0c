using System.Globalization;
using System.Numerics;
using System.Xml.Linq;
using Ballistic.Authoring.Reports;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Reports;

/// <summary>The SVG page: well-formed, walks as dashed polylines through their ground points in both views, jumps as before.</summary>
public sealed class SvgPlanRendererTests
{
    private static readonly XNamespace Svg = "http://www.w3.org/2000/svg";

    private static Vector2[] Points(XElement polyline) =>
        [.. polyline.Attribute("points")!.Value.Split(' ', StringSplitOptions.RemoveEmptyEntries).Select(p =>
        {
            string[] xy = p.Split(',');
            return new Vector2(float.Parse(xy[0], CultureInfo.InvariantCulture), float.Parse(xy[1], CultureInfo.InvariantCulture));
        })];

    [Test]
    public void TheHeaderFitsThePageWidth()
    {
        // The summary under the title was one line of some 190 characters: at 12 px sans-serif (about 6.5 px a
        // character) it ran past the 1000 px page. The status and reason, then the counts, are two lines now.
        XDocument svg = XDocument.Parse(SvgPlanRenderer.Render(WalkPlans.Report(WalkPlans.WalkAndJump, WalkPlans.Animation), WalkPlans.Roadmap));
        float width = float.Parse(svg.Root!.Attribute("width")!.Value, CultureInfo.InvariantCulture);
        XElement[] header = [.. svg.Root.Elements(Svg + "text").Take(3)];
        Assert.That(header[2].Value, Does.Contain("s of flight"));
        foreach (XElement line in header.Skip(1))
        {
            float x = float.Parse(line.Attribute("x")!.Value, CultureInfo.InvariantCulture);
            Assert.That(x + (line.Value.Length * 6.5f), Is.LessThanOrEqualTo(width), line.Value);
        }
    }

    [Test]
    public void AThickRoadmapLayerIsThinnedAndTheLegendSaysHowMuch()
    {
        // The pond's 8,151 roadmap jumps buried its top view; a jump and its way back are one line, and past
        // MaxDrawnJumps pairs an even share of them is drawn, the legend saying how many of how many.
        Roadmap roadmap = Runtime.RuntimeWorlds.DesertSkeleton.Roadmap;
        int pairs = roadmap.Edges.Select(e => (Math.Min(e.From, e.To), Math.Max(e.From, e.To))).Distinct().Count();
        Assume.That(pairs, Is.GreaterThan(SvgPlanRenderer.MaxDrawnJumps), "a roadmap thicker than the layer draws");
        (List<(int From, int To)> drawn, int counted) = SvgPlanRenderer.DrawnEdges(roadmap);
        Assert.That(counted, Is.EqualTo(pairs));
        Assert.That(drawn, Has.Count.EqualTo(SvgPlanRenderer.MaxDrawnJumps));
        Assert.That(drawn.Select(e => (Math.Min(e.From, e.To), Math.Max(e.From, e.To))).Distinct().Count(), Is.EqualTo(drawn.Count), "each pair once");
        Assert.That(drawn.All(e => roadmap.Edges.Any(r => r.From == e.From && r.To == e.To)), Is.True, "roadmap jumps only");
        Assert.That(drawn.Select(e => e.From).Distinct().Count(), Is.GreaterThan(roadmap.Nodes.Count * 3 / 4), "spread over the whole roadmap, not its first nodes");

        XDocument svg = XDocument.Parse(SvgPlanRenderer.Render(WalkPlans.Report(WalkPlans.WalkAndJump, WalkPlans.Animation), roadmap));
        XElement layer = svg.Descendants(Svg + "g").Single(g => (string?)g.Attribute("class") == "roadmap");
        Assert.That(layer.Elements(Svg + "line").Count(), Is.EqualTo(SvgPlanRenderer.MaxDrawnJumps));
        Assert.That(svg.Descendants(Svg + "text").Select(t => t.Value), Has.Some.EqualTo(string.Create(CultureInfo.InvariantCulture, $"roadmap jumps ({SvgPlanRenderer.MaxDrawnJumps:N0} of {pairs:N0} drawn)")));

        // The legend's items, the long roadmap line among them, stand apart and within the page: each item's words
        // end (at 6.2 px a character) before the next item's sample begins on its row.
        float page = float.Parse(svg.Root!.Attribute("width")!.Value, CultureInfo.InvariantCulture);
        XElement legend = svg.Root.Elements(Svg + "g").Last();
        var rows = legend.Elements(Svg + "text")
            .Select(t => (X: float.Parse(t.Attribute("x")!.Value, CultureInfo.InvariantCulture), Y: t.Attribute("y")!.Value, Text: t.Value))
            .GroupBy(t => t.Y).ToList();
        Assert.That(rows.Sum(r => r.Count()), Is.EqualTo(6), "six legend items");
        foreach (var row in rows)
        {
            var ordered = row.OrderBy(t => t.X).ToList();
            for (int i = 0; i < ordered.Count; i++)
            {
                float end = ordered[i].X + SvgPlanRenderer.LegendWidth(ordered[i].Text);
                Assert.That(end, Is.LessThanOrEqualTo(page), ordered[i].Text);
                if (i + 1 < ordered.Count)
                {
                    Assert.That(ordered[i + 1].X - 30f, Is.GreaterThan(end), $"'{ordered[i].Text}' runs into '{ordered[i + 1].Text}'");
                }
            }
        }

        string readme = File.ReadAllText(Path.Combine(RepositoryFiles.Root, "README.md"));
        Assert.That(readme.ReplaceLineEndings(" "), Does.Contain(string.Create(CultureInfo.InvariantCulture, $"at most {SvgPlanRenderer.MaxDrawnJumps:N0} pairs")), "the README's figure");

        // A thin roadmap (its first 40 nodes' jumps among themselves) is drawn whole, each pair once, under the plain legend.
        var builder = new RoadmapBuilder(roadmap.LevelFingerprint, roadmap.CharacterFingerprint, roadmap.CharacterName, roadmap.Seed);
        foreach (RoadmapNode node in roadmap.Nodes)
        {
            builder.AddNode(node);
        }

        foreach (RoadmapEdge edge in roadmap.Edges.Where(e => e.From < 40 && e.To < 40))
        {
            builder.AddEdge(edge);
        }

        Roadmap thin = builder.Freeze();
        int thinPairs = thin.Edges.Select(e => (Math.Min(e.From, e.To), Math.Max(e.From, e.To))).Distinct().Count();
        Assert.That(thinPairs, Is.InRange(1, SvgPlanRenderer.MaxDrawnJumps));
        Assert.That(thin.Edges, Has.Count.GreaterThan(thinPairs), "some jumps go both ways");
        (List<(int From, int To)> thinDrawn, int thinCounted) = SvgPlanRenderer.DrawnEdges(thin);
        Assert.That((thinDrawn.Count, thinCounted), Is.EqualTo((thinPairs, thinPairs)), "drawn whole");
        XDocument thinSvg = XDocument.Parse(SvgPlanRenderer.Render(WalkPlans.Report(WalkPlans.WalkAndJump, WalkPlans.Animation), thin));
        Assert.That(thinSvg.Descendants(Svg + "text").Select(t => t.Value), Has.Some.EqualTo("roadmap jumps"));
    }

    [Test]
    public void ARequestedPointOffTheLevelIsMarkedInsideTheTopView()
    {
        // A goal asked for past the level's edge (placed within its tolerance): its marker was drawn below the top
        // view, over the side profile's title.
        PlanReport report = WalkPlans.Report(WalkPlans.WalkAndJump, WalkPlans.Animation);
        Vector3 past = new(report.Scene.Level.Bounds.Max.X + 3f, report.To.Y, report.Scene.Level.Bounds.Max.Z + 4f);
        XDocument svg = XDocument.Parse(SvgPlanRenderer.Render(report with { To = past }, roadmap: null));
        XElement frame = svg.Root!.Elements(Svg + "rect").First(r => (string?)r.Attribute("fill") == "none");
        float Number(XElement e, string name) => float.Parse(e.Attribute(name)!.Value, CultureInfo.InvariantCulture);
        (float left, float top, float right, float bottom) = (Number(frame, "x"), Number(frame, "y"), Number(frame, "x") + Number(frame, "width"), Number(frame, "y") + Number(frame, "height"));
        XElement goal = svg.Root.Elements(Svg + "text").Single(t => t.Value == "goal");
        (float x, float y) = (Number(goal, "x") - 8f, Number(goal, "y") - 14f); // the cross's centre
        Assert.That(x, Is.InRange(left, right + 0.1f), "inside the top view across");
        Assert.That(y, Is.InRange(top, bottom + 0.1f), "and down");
        XElement profileTitle = svg.Root.Elements(Svg + "text").Single(t => t.Value.StartsWith("Side profile", StringComparison.Ordinal));
        Assert.That(Number(profileTitle, "y"), Is.GreaterThan(bottom), "the side profile starts below the top view");
    }

    [Test]
    public void TheProfilesGroundIsWhatTheTrackStandsOnNotTheRoofOrTheWallBesideIt()
    {
        // A floor; a roof 2.6 m over it (a room, or the floor above: the old profile drew it as solid ground); a wall
        // 0.5 m beside the track, 1.2 m high (drawn filled before, as if walked over); a 0.5 m step the track climbs.
        Level level = new LevelBuilder("room")
            .AddFloor(-2f, -3f, 12f, 3f, 0f)
            .AddBox(new Vector3(2f, 2.6f, -3f), new Vector3(4f, 2.8f, 3f))
            .AddBox(new Vector3(6f, 0f, 0.4f), new Vector3(7f, 1.2f, 0.6f))
            .AddBox(new Vector3(9f, 0f, -3f), new Vector3(12f, 0.5f, 3f))
            .Build();
        var bvh = level.Bvh;
        List<(Vector3 From, Vector3 To, float Offset)> track = [(new(0f, 0f, 0f), new(9f, 0f, 0f), 0f), (new(9f, 0.5f, 0f), new(11f, 0.5f, 0f), 9f)];
        (float[] ground, float[] beside) = SvgPlanRenderer.GroundProfile(bvh, level.Bounds, track, 0f, 11f, 110);
        float At(float[] line, float s) => line[(int)MathF.Round(s * 10f)];
        Assert.Multiple(() =>
        {
            Assert.That(At(ground, 3f), Is.EqualTo(0f).Within(1e-4f), "under the roof the ground is the floor");
            Assert.That(At(beside, 3f), Is.EqualTo(0f).Within(1e-4f), "the roof, out of reach above, is not beside the track either");
            Assert.That(At(ground, 6.5f), Is.EqualTo(0f).Within(1e-4f), "beside the wall the ground is the floor");
            Assert.That(At(beside, 6.5f), Is.EqualTo(1.2f).Within(1e-4f), "the wall stands beside the track");
            Assert.That(At(ground, 10f), Is.EqualTo(0.5f).Within(1e-4f), "the step's tread the track climbed");
            Assert.That(At(ground, 1f), Is.EqualTo(0f).Within(1e-4f));
        });
    }

    [Test]
    public void WalksAreDashedPolylinesThroughTheirGroundPointsInBothViews()
    {
        PlanResult result = WalkPlans.WalkAndJump;
        string text = SvgPlanRenderer.Render(WalkPlans.Report(result, WalkPlans.Animation), WalkPlans.Roadmap);
        XDocument svg = XDocument.Parse(text);
        Assert.That(svg.Root!.Name, Is.EqualTo(Svg + "svg"));
        XElement[] dashed = [.. svg.Descendants().Where(e => e.Attribute("stroke-dasharray") is not null)];
        XElement[] walks = [.. dashed.Where(e => e.Name == Svg + "polyline")];
        Assert.That(walks, Has.Length.EqualTo(2 * result.Walks.Count()), "one per walk in each view");

        for (int m = 0; m < result.Moves.Count; m++)
        {
            if (result.Moves[m] is not Walk walk)
            {
                continue;
            }

            IReadOnlyList<Vector3> path = PlanReportWriter.ReportPath(walk.Path);
            string move = m.ToString(CultureInfo.InvariantCulture);
            Vector2[] top = Points(walks.Single(e => e.Attribute("data-move")!.Value == move && e.Attribute("data-view")!.Value == "top"));
            Vector2[] profile = Points(walks.Single(e => e.Attribute("data-move")!.Value == move && e.Attribute("data-view")!.Value == "profile"));
            Assert.That(top, Has.Length.EqualTo(path.Count));
            Assert.That(profile, Has.Length.EqualTo(path.Count));

            // Top view: the points are the ground points' (X, Z), scaled and moved alike (X right, Z down).
            int far = Enumerable.Range(1, path.Count - 1).MaxBy(i => new Vector2(path[i].X - path[0].X, path[i].Z - path[0].Z).Length());
            float scale = Vector2.Distance(top[far], top[0]) / new Vector2(path[far].X - path[0].X, path[far].Z - path[0].Z).Length();
            Assert.That(scale, Is.GreaterThan(5f), "pixels per metre");
            for (int i = 0; i < path.Count; i++)
            {
                Vector2 expected = top[0] + (new Vector2(path[i].X - path[0].X, path[i].Z - path[0].Z) * scale);
                Assert.That(Vector2.Distance(top[i], expected), Is.LessThan(0.3f), $"move {m} point {i} in the top view");
            }

            // Side profile: across by the horizontal distance walked, at the ground's height (flat platforms here).
            float walked = 0f;
            float across = (profile[^1].X - profile[0].X) / walk.Path.Zip(walk.Path.Skip(1), (a, b) => new Vector2(b.X - a.X, b.Z - a.Z).Length()).Sum();
            for (int i = 0; i < path.Count; i++)
            {
                walked += i == 0 ? 0f : new Vector2(path[i].X - path[i - 1].X, path[i].Z - path[i - 1].Z).Length();
                Assert.That(profile[i].X, Is.EqualTo(profile[0].X + (walked * across)).Within(0.3f), $"move {m} point {i} across the profile");
                Assert.That(profile[i].Y, Is.EqualTo(profile[0].Y).Within(0.1f), $"move {m} point {i} on the flat ground");
            }
        }

        Assert.That(text, Does.Contain("jump (trunk centre)").And.Contain("walk (ground path)"), "the legend names both");
        Assert.That(text, Does.Contain("2 walks"));
        Assert.That(svg.Descendants(Svg + "path").Count(e => e.Attribute("stroke")?.Value == "#e8590c"), Is.EqualTo(result.Jumps.Count), "each jump's parabola, solid");
    }

    [Test]
    public void AJumpOnlyPlanHasNoDashedPathAndIsWellFormed()
    {
        PlanResult result = WalkPlans.JumpOnly;
        XDocument svg = XDocument.Parse(SvgPlanRenderer.Render(WalkPlans.Report(result, WalkPlans.Animate(result.Moves)), WalkPlans.Roadmap));
        Assert.That(svg.Descendants().Where(e => e.Attribute("stroke-dasharray") is not null && e.Name != Svg + "line"), Is.Empty, "only the legend's sample is dashed");
        Assert.That(svg.Descendants(Svg + "path").Count(e => e.Attribute("stroke")?.Value == "#e8590c"), Is.EqualTo(result.Jumps.Count));
    }

    [Test]
    public void AFailedPlanWithoutMovesStillDraws()
    {
        var failed = new PlanResult(Ballistic.Planner.Planning.PlannerStatus.NoPath, "no way <across> & none", null, null, [], TimeSpan.Zero);
        XDocument svg = XDocument.Parse(SvgPlanRenderer.Render(WalkPlans.Report(failed), roadmap: null));
        Assert.That(svg.Descendants(Svg + "polyline"), Is.Empty);
        Assert.That(svg.Root!.Value, Does.Contain("no way <across> & none"));
    }
}
