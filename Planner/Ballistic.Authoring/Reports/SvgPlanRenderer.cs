using System.Globalization;
using System.Numerics;
using System.Text;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.IO;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Authoring.Reports;

/// <summary>
/// Draws a plan as an SVG page: a top view (the level as a shaded height map seen from +Y, the roadmap's nodes and
/// jumps, the path) and a side profile along the path, unrolled (the level's silhouette in a corridor around it, the
/// jumps' parabolas, the takeoff and landing friction cones). Jumps are solid lines; walks are dashed polylines
/// (<c>stroke-dasharray</c>) through their ground path's points as the report writes them
/// (<see cref="PlanReportWriter.ReportPath"/>), in both views. Moves are numbered from 1 in path order, as in the
/// report's <c>moves</c>.
/// </summary>
public static class SvgPlanRenderer
{
    private const float PageWidth = 1000f;
    private const float Margin = 30f;
    private const float Corridor = 1.5f;
    private const string JumpColor = "#e8590c";
    private const string WalkColor = "#0c8599";
    private const string WalkDash = "7 5";

    /// <summary>The SVG text of the report's plan over its roadmap (<paramref name="roadmap"/> may be <c>null</c>).</summary>
    public static string Render(PlanReport report, Roadmap? roadmap)
    {
        ArgumentNullException.ThrowIfNull(report);
        TriangleBvh bvh = report.Scene.Bvh;
        // The level, and the requested points where they lie off it (a goal placed within its tolerance of a point
        // past the level's edge): their markers are drawn inside the top view, never over the side profile.
        Aabb bounds = Finite(report.From) && Finite(report.To) ? report.Scene.Level.Bounds.Encapsulate(report.From).Encapsulate(report.To) : report.Scene.Level.Bounds;
        PlanResult result = report.Result;
        var svg = new StringBuilder();

        // Top view geometry: world X → right, world Z → down.
        float worldW = bounds.Max.X - bounds.Min.X;
        float worldD = bounds.Max.Z - bounds.Min.Z;
        float topScale = MathF.Min((PageWidth - (2 * Margin)) / MathF.Max(worldW, 1e-3f), 520f / MathF.Max(worldD, 1e-3f));
        float topW = worldW * topScale;
        float topH = worldD * topScale;
        float topX = (PageWidth - topW) / 2f;
        const float topY = 86f;
        float Tx(Vector3 p) => topX + ((p.X - bounds.Min.X) * topScale);
        float Ty(Vector3 p) => topY + ((p.Z - bounds.Min.Z) * topScale);

        // Side profile geometry: the path unrolled. Each jump keeps its own vertical plane (the plane its cones were
        // cut by), each straight piece of a walk its own; the horizontal axis is the distance travelled along the
        // path, the vertical axis the height.
        IReadOnlyList<Move> moves = result.Moves;
        var segments = new List<(Vector3 From, Vector3 To, float Offset)>();
        var moveOffsets = new float[moves.Count];
        var walkPaths = new IReadOnlyList<Vector3>[moves.Count];
        float travelled = 0f;
        for (int m = 0; m < moves.Count; m++)
        {
            moveOffsets[m] = travelled;
            if (moves[m] is Jump jump)
            {
                segments.Add((jump.Arc.Start, jump.Arc.End, travelled));
                travelled += Horizontal(jump.Arc.End - jump.Arc.Start).Length();
            }
            else if (moves[m] is Walk walk)
            {
                walkPaths[m] = PlanReportWriter.ReportPath(walk.Path);
                for (int i = 1; i < walk.Path.Count; i++)
                {
                    segments.Add((walk.Path[i - 1], walk.Path[i], travelled));
                    travelled += Horizontal(walk.Path[i] - walk.Path[i - 1]).Length();
                }
            }
        }

        if (segments.Count == 0)
        {
            segments.Add((report.From, report.To, 0f));
        }

        const float lead = 1.5f;
        float sMin = -lead;
        float sMax = segments[^1].Offset + Horizontal(segments[^1].To - segments[^1].From).Length() + lead;
        const int profileSamples = 480;
        (float[] profile, float[] beside) = GroundProfile(bvh, bounds, segments, sMin, sMax, profileSamples);

        var pathPoints = new List<Vector3> { report.From, report.To };
        foreach (Jump jump in result.Jumps)
        {
            for (int k = 0; k <= 24; k++)
            {
                pathPoints.Add(jump.Arc.PositionAt(jump.Arc.FlightTime * k / 24f));
            }
        }

        foreach (Walk walk in result.Walks)
        {
            pathPoints.AddRange(walk.Path);
        }

        float yLow = MathF.Min(profile.Where(float.IsFinite).DefaultIfEmpty(bounds.Min.Y).Min(), pathPoints.Min(p => p.Y)) - 0.5f;
        float yHigh = MathF.Max(profile.Concat(beside).Where(float.IsFinite).DefaultIfEmpty(bounds.Max.Y).Max(), pathPoints.Max(p => p.Y)) + 0.5f;
        float profileScale = MathF.Min((PageWidth - (2 * Margin)) / (sMax - sMin), 240f / (yHigh - yLow));
        float profileX = (PageWidth - ((sMax - sMin) * profileScale)) / 2f;
        float profileY = topY + topH + 60f;
        float profileH = (yHigh - yLow) * profileScale;
        float Sx(float s) => profileX + ((s - sMin) * profileScale);
        float Py(float y) => profileY + ((yHigh - y) * profileScale);
        float pageH = profileY + profileH + 70f;

        svg.Append(Invariant($"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{PageWidth}\" height=\"{pageH:0}\" viewBox=\"0 0 {PageWidth} {pageH:0}\" font-family=\"sans-serif\" font-size=\"12\">\n"));
        svg.Append("<rect width=\"100%\" height=\"100%\" fill=\"#fbfaf7\"/>\n");
        string status = PlanReportWriter.StatusName(result.Status);
        int walkCount = result.Walks.Count();
        svg.Append(Invariant($"<text x=\"{Margin}\" y=\"26\" font-size=\"18\" font-weight=\"bold\">Ballistic plan: {Escape(report.Scene.Character.Name)} on {Escape(Path.GetFileName(report.LevelPath))}</text>\n"));
        // Two lines: the status and reason, then the counts (one line ran past the page's right edge).
        svg.Append(Invariant($"<text x=\"{Margin}\" y=\"46\">{status}: {Escape(result.Reason)}</text>\n"));
        svg.Append(Invariant($"<text x=\"{Margin}\" y=\"62\">{result.Jumps.Count} jumps, {result.TotalFlightTime:0.00} s of flight; {walkCount} walks, {result.Walks.Sum(w => w.Length):0.0} m; {result.TotalDuration:0.00} s in all; roadmap {report.RoadmapNodes} nodes, {report.RoadmapEdges} jumps (seed {report.Seed})</text>\n"));

        // Top view.
        Level level = report.Scene.Level;
        string costly = level.HasSurfaceCosts ? "; red: surfaces with a travel or enter cost" : "";
        svg.Append(Invariant($"<text x=\"{topX}\" y=\"{topY - 8}\" font-weight=\"bold\">Top view (X right, Z down; shading = height {bounds.Min.Y:0.0}…{bounds.Max.Y:0.0} m{costly})</text>\n"));
        string map = HeightMapPng(bvh, bounds, Math.Max(2, (int)MathF.Min(topW, 480f)), Math.Max(2, (int)(MathF.Min(topW, 480f) * topH / topW)), level);
        svg.Append(Invariant($"<image x=\"{topX:0.#}\" y=\"{topY:0.#}\" width=\"{topW:0.#}\" height=\"{topH:0.#}\" preserveAspectRatio=\"none\" href=\"data:image/png;base64,{map}\"/>\n"));
        svg.Append(Invariant($"<rect x=\"{topX:0.#}\" y=\"{topY:0.#}\" width=\"{topW:0.#}\" height=\"{topH:0.#}\" fill=\"none\" stroke=\"#555\"/>\n"));
        string roadmapLegend = "roadmap jumps";
        if (roadmap is not null)
        {
            (List<(int From, int To)> drawn, int pairs) = DrawnEdges(roadmap);
            if (drawn.Count < pairs)
            {
                roadmapLegend = Invariant($"roadmap jumps ({drawn.Count:N0} of {pairs:N0} drawn)");
            }

            svg.Append("<g class=\"roadmap\" stroke=\"#2b4c7e\" stroke-opacity=\"0.25\" stroke-width=\"0.7\">\n");
            foreach ((int from, int to) in drawn)
            {
                Vector3 a = roadmap.Nodes[from].Pose.Position;
                Vector3 b = roadmap.Nodes[to].Pose.Position;
                svg.Append(Invariant($"<line x1=\"{Tx(a):0.#}\" y1=\"{Ty(a):0.#}\" x2=\"{Tx(b):0.#}\" y2=\"{Ty(b):0.#}\"/>\n"));
            }

            svg.Append("</g>\n<g fill=\"#2b4c7e\">\n");
            foreach (RoadmapNode node in roadmap.Nodes)
            {
                svg.Append(Invariant($"<circle cx=\"{Tx(node.Pose.Position):0.#}\" cy=\"{Ty(node.Pose.Position):0.#}\" r=\"2\"/>\n"));
            }

            svg.Append("</g>\n");
        }

        for (int m = 0; m < moves.Count; m++)
        {
            if (moves[m] is Jump jump)
            {
                svg.Append(Invariant($"<line x1=\"{Tx(jump.Arc.Start):0.#}\" y1=\"{Ty(jump.Arc.Start):0.#}\" x2=\"{Tx(jump.Arc.End):0.#}\" y2=\"{Ty(jump.Arc.End):0.#}\" stroke=\"{JumpColor}\" stroke-width=\"3\"/>\n"));
                Label(jump.Arc.Start, m, JumpColor, "#7a2e05");
            }
            else if (moves[m] is Walk)
            {
                IReadOnlyList<Vector3> path = walkPaths[m];
                string points = string.Join(" ", path.Select(p => Invariant($"{Tx(p):0.#},{Ty(p):0.#}")));
                svg.Append(Invariant($"<polyline class=\"walk\" data-view=\"top\" data-move=\"{m}\" points=\"{points}\" fill=\"none\" stroke=\"{WalkColor}\" stroke-width=\"3\" stroke-dasharray=\"{WalkDash}\"/>\n"));
                Label(path[0], m, WalkColor, "#0b4f5c");
            }
        }

        void Label(Vector3 at, int move, string ring, string text)
        {
            svg.Append(Invariant($"<circle cx=\"{Tx(at):0.#}\" cy=\"{Ty(at):0.#}\" r=\"4\" fill=\"#fff\" stroke=\"{ring}\" stroke-width=\"2\"/>\n"));
            svg.Append(Invariant($"<text x=\"{Tx(at) + 5:0.#}\" y=\"{Ty(at) - 5:0.#}\" font-size=\"11\" fill=\"{text}\">{move + 1}</text>\n"));
        }

        Marker(svg, Tx(report.From), Ty(report.From), "#2f9e44", "start");
        Marker(svg, Tx(report.To), Ty(report.To), "#c92a2a", "goal");

        // Side profile.
        svg.Append(Invariant($"<text x=\"{profileX}\" y=\"{profileY - 8}\" font-weight=\"bold\">Side profile along the path, unrolled (filled: ground under the track; outline: level up to {Corridor / 2f:0.##} m beside it; 1 m = {profileScale:0.#} px both ways)</text>\n"));
        var ground = new StringBuilder();
        ground.Append(Invariant($"M {Sx(sMin):0.#} {Py(yLow):0.#} "));
        for (int i = 0; i <= profileSamples; i++)
        {
            float s = sMin + ((sMax - sMin) * i / profileSamples);
            float h = float.IsFinite(profile[i]) ? profile[i] : yLow;
            ground.Append(Invariant($"L {Sx(s):0.#} {Py(h):0.#} "));
        }

        ground.Append(Invariant($"L {Sx(sMax):0.#} {Py(yLow):0.#} Z"));
        svg.Append(Invariant($"<path d=\"{ground}\" fill=\"#d9c9a3\" stroke=\"#8c7851\" stroke-width=\"1\"/>\n"));

        // What stands beside the track and rises above the ground under it (a wall, a trough's side, a block the jump
        // passes), as a thin outline over the ground: runs of two samples or more where it stands at least 5 cm higher.
        var besideRuns = new StringBuilder();
        var run = new List<string>();
        for (int i = 0; i <= profileSamples + 1; i++)
        {
            bool above = i <= profileSamples && float.IsFinite(beside[i]) && !(beside[i] <= (float.IsFinite(profile[i]) ? profile[i] : yLow) + 0.05f);
            if (above)
            {
                float s = sMin + ((sMax - sMin) * i / profileSamples);
                run.Add(Invariant($"{Sx(s):0.#} {Py(beside[i]):0.#}"));
            }
            else
            {
                if (run.Count >= 2)
                {
                    besideRuns.Append("M ").Append(string.Join(" L ", run)).Append(' ');
                }

                run.Clear();
            }
        }

        if (besideRuns.Length > 0)
        {
            svg.Append(Invariant($"<path class=\"beside\" d=\"{besideRuns.ToString().TrimEnd()}\" fill=\"none\" stroke=\"#8c7851\" stroke-width=\"1.3\" stroke-opacity=\"0.8\"/>\n"));
        }
        for (int m = 0; m < moves.Count; m++)
        {
            if (moves[m] is Walk)
            {
                // The ground path, unrolled: each point at the distance walked so far (across), at its height.
                IReadOnlyList<Vector3> path = walkPaths[m];
                float s = moveOffsets[m];
                var line = new StringBuilder();
                for (int i = 0; i < path.Count; i++)
                {
                    s += i == 0 ? 0f : Horizontal(path[i] - path[i - 1]).Length();
                    line.Append(Invariant($"{(i == 0 ? "" : " ")}{Sx(s):0.#},{Py(path[i].Y):0.#}"));
                }

                svg.Append(Invariant($"<polyline class=\"walk\" data-view=\"profile\" data-move=\"{m}\" points=\"{line}\" fill=\"none\" stroke=\"{WalkColor}\" stroke-width=\"2.5\" stroke-dasharray=\"{WalkDash}\"/>\n"));
                svg.Append(Invariant($"<text x=\"{Sx(moveOffsets[m]) + 3:0.#}\" y=\"{Py(path[0].Y) + 16:0.#}\" font-size=\"11\" fill=\"#0b4f5c\">{m + 1}</text>\n"));
                continue;
            }

            if (moves[m] is not Jump jump)
            {
                continue;
            }

            float offset = moveOffsets[m];
            Vector3 heading = Horizontal(jump.Arc.End - jump.Arc.Start);
            heading = heading.LengthSquared() > 1e-9f ? Vector3.Normalize(heading) : Vector3.UnitX;
            float X(Vector3 p) => Sx(offset + Vector3.Dot(Horizontal(p - jump.Arc.Start), heading));
            var arc = new StringBuilder();
            for (int k = 0; k <= 40; k++)
            {
                Vector3 p = jump.Arc.PositionAt(jump.Arc.FlightTime * k / 40f);
                arc.Append(Invariant($"{(k == 0 ? "M" : "L")} {X(p):0.#} {Py(p.Y):0.#} "));
            }

            svg.Append(Invariant($"<path d=\"{arc}\" fill=\"none\" stroke=\"{JumpColor}\" stroke-width=\"2.5\"/>\n"));
            if (report.Animation is { } animated && animated.Animation.Moves.Count == moves.Count && ReferenceEquals(animated.Animation.Moves[m], jump))
            {
                Poses(svg, animated.Animation, m, X, Py);
            }

            Cone(svg, jump.Takeoff, jump.Arc.Start, heading, X, Py, profileScale, "#1971c2");
            Cone(svg, jump.Landing, jump.Arc.End, heading, X, Py, profileScale, "#9c36b5");
            Vector3 tip = jump.Arc.Start + (jump.Arc.TakeoffVelocity * 0.08f);
            svg.Append(Invariant($"<line x1=\"{X(jump.Arc.Start):0.#}\" y1=\"{Py(jump.Arc.Start.Y):0.#}\" x2=\"{X(tip):0.#}\" y2=\"{Py(tip.Y):0.#}\" stroke=\"#000\" stroke-width=\"1.5\"/>\n"));
            svg.Append(Invariant($"<text x=\"{X(jump.Arc.Start) + 3:0.#}\" y=\"{Py(jump.Arc.Start.Y) + 16:0.#}\" font-size=\"11\" fill=\"#7a2e05\">{m + 1}</text>\n"));
        }

        // The legend: each item's sample then its words, laid out one after the other by the words' width (a long
        // roadmap line, "roadmap jumps (1,500 of 3,065 drawn)", ran into the next item at fixed places), on a second
        // row when the first is full.
        (Func<float, float, FormattableString> Sample, string Text)[] items =
        [
            ((x, y) => $"<line x1=\"{x}\" y1=\"{y}\" x2=\"{x + 24}\" y2=\"{y}\" stroke=\"{JumpColor}\" stroke-width=\"3\"/>", "jump (trunk centre)"),
            ((x, y) => $"<line x1=\"{x}\" y1=\"{y}\" x2=\"{x + 24}\" y2=\"{y}\" stroke=\"{WalkColor}\" stroke-width=\"3\" stroke-dasharray=\"{WalkDash}\"/>", "walk (ground path)"),
            ((x, y) => $"<line x1=\"{x}\" y1=\"{y}\" x2=\"{x + 24}\" y2=\"{y}\" stroke=\"#2b4c7e\" stroke-opacity=\"0.5\"/>", roadmapLegend),
            ((x, y) => $"<path d=\"M {x + 2} {y + 5} L {x + 12} {y - 6} L {x + 22} {y + 5} Z\" fill=\"#1971c2\" fill-opacity=\"0.25\" stroke=\"#1971c2\"/>", "takeoff cone"),
            ((x, y) => $"<path d=\"M {x + 2} {y + 5} L {x + 12} {y - 6} L {x + 22} {y + 5} Z\" fill=\"#9c36b5\" fill-opacity=\"0.25\" stroke=\"#9c36b5\"/>", "landing cone"),
            ((x, y) => $"<line x1=\"{x}\" y1=\"{y}\" x2=\"{x + 24}\" y2=\"{y}\" stroke=\"#000\" stroke-width=\"1.5\"/>", "takeoff velocity (×0.08 s)"),
        ];
        float legendX = Margin;
        float legendY = pageH - 34f;
        svg.Append("<g font-size=\"11\">");
        foreach ((Func<float, float, FormattableString> sample, string text) in items)
        {
            float width = LegendSample + LegendWidth(text);
            if (legendX > Margin && legendX + width > PageWidth - Margin)
            {
                (legendX, legendY) = (Margin, legendY + 16f);
            }

            svg.Append(Invariant(sample(legendX, legendY)));
            svg.Append(Invariant($"<text x=\"{legendX + LegendSample}\" y=\"{legendY + 4}\">{Escape(text)}</text>"));
            legendX += width + LegendGap;
        }

        svg.Append("</g>\n");
        svg.Append("</svg>\n");
        return svg.ToString();
    }

    /// <summary>Width (px) of a legend item's sample and the space before its words.</summary>
    private const float LegendSample = 30f;

    /// <summary>Space (px) between legend items.</summary>
    private const float LegendGap = 18f;

    /// <summary>
    /// The width (px) <paramref name="text"/> takes in the legend's 11 px sans-serif, at most: 6.2 px a character
    /// (wider than the average of DejaVu Sans and Arial at that size, whose widest common letters, m and w, are 9 px).
    /// </summary>
    internal static float LegendWidth(string text) => 6.2f * text.Length;

    /// <summary>Most roadmap jumps the top view draws: past it the layer hides the level and the path (the pond's 8,151).</summary>
    internal const int MaxDrawnJumps = 1_500;

    /// <summary>
    /// The roadmap jumps the top view draws: each pair of nodes once (a jump and its way back are one line), at most
    /// <see cref="MaxDrawnJumps"/> of them, taken evenly through the roadmap's order (the same every time); and how
    /// many pairs there are.
    /// </summary>
    internal static (List<(int From, int To)> Drawn, int Pairs) DrawnEdges(Roadmap roadmap)
    {
        var seen = new HashSet<(int, int)>();
        var pairs = new List<(int From, int To)>();
        foreach (RoadmapEdge edge in roadmap.Edges)
        {
            if (seen.Add((Math.Min(edge.From, edge.To), Math.Max(edge.From, edge.To))))
            {
                pairs.Add((edge.From, edge.To));
            }
        }

        if (pairs.Count <= MaxDrawnJumps)
        {
            return (pairs, pairs.Count);
        }

        var drawn = new List<(int From, int To)>(MaxDrawnJumps);
        for (int i = 0; i < MaxDrawnJumps; i++)
        {
            drawn.Add(pairs[(int)((long)i * pairs.Count / MaxDrawnJumps)]);
        }

        return (drawn, pairs.Count);
    }

    /// <summary>Writes the SVG to <paramref name="path"/>, creating its folder.</summary>
    public static void Save(PlanReport report, Roadmap? roadmap, string path)
    {
        ArgumentNullException.ThrowIfNull(path);
        OutputFile.Write(path, new UTF8Encoding(false).GetBytes(Render(report, roadmap)));
    }

    /// <summary>Stick figures of the animated character at five moments of jump move <paramref name="move"/> (an index in the moves), in its plane.</summary>
    private static void Poses(StringBuilder svg, JumpAnimation animation, int move, Func<Vector3, float> px, Func<float, float> py)
    {
        Rig rig = animation.Model.Rig;
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        float start = animation.MoveStart(move);
        float duration = animation.Moves[move].Duration;
        svg.Append("<g stroke=\"#343a40\" stroke-width=\"1.4\" stroke-linecap=\"round\" stroke-opacity=\"0.75\">\n");
        foreach (float f in new[] { 0f, 0.25f, 0.5f, 0.75f, 1f })
        {
            animation.Joints(start + (f * duration), positions, rotations);
            for (int j = 1; j < rig.Joints.Count; j++)
            {
                Vector3 a = positions[rig.Joints[j].Parent];
                Vector3 b = positions[j];
                svg.Append(Invariant($"<line x1=\"{px(a):0.#}\" y1=\"{py(a.Y):0.#}\" x2=\"{px(b):0.#}\" y2=\"{py(b.Y):0.#}\"/>"));
            }

            foreach (RigLimb limb in animation.Model.Limbs)
            {
                Vector3 a = positions[limb.EffectorJoint];
                Vector3 b = limb.EffectorPosition(positions, rotations);
                svg.Append(Invariant($"<line x1=\"{px(a):0.#}\" y1=\"{py(a.Y):0.#}\" x2=\"{px(b):0.#}\" y2=\"{py(b.Y):0.#}\"/>"));
            }

            svg.Append('\n');
        }

        svg.Append("</g>\n");
    }

    /// <summary>The friction cone of a node cut by the profile plane, drawn as a wedge at <paramref name="at"/>.</summary>
    private static void Cone(StringBuilder svg, RoadmapNode node, Vector3 at, Vector3 along, Func<Vector3, float> px, Func<float, float> py, float scale, string color)
    {
        float length = 28f / scale;
        float half = node.Cone.HalfAngle;
        Vector3 axis = node.Cone.Axis;
        float a = MathF.Atan2(axis.Y, Vector3.Dot(axis, along));
        Vector3 Ray(float angle) => at + (((along * MathF.Cos(angle)) + (Vector3.UnitY * MathF.Sin(angle))) * length);
        Vector3 r1 = Ray(a - half);
        Vector3 r2 = Ray(a + half);
        svg.Append(Invariant($"<path d=\"M {px(at):0.#} {py(at.Y):0.#} L {px(r1):0.#} {py(r1.Y):0.#} L {px(r2):0.#} {py(r2.Y):0.#} Z\" fill=\"{color}\" fill-opacity=\"0.2\" stroke=\"{color}\" stroke-width=\"1\"/>\n"));
    }

    private static void Marker(StringBuilder svg, float x, float y, string color, string label)
    {
        svg.Append(Invariant($"<g stroke=\"{color}\" stroke-width=\"2.5\"><line x1=\"{x - 6:0.#}\" y1=\"{y - 6:0.#}\" x2=\"{x + 6:0.#}\" y2=\"{y + 6:0.#}\"/><line x1=\"{x - 6:0.#}\" y1=\"{y + 6:0.#}\" x2=\"{x + 6:0.#}\" y2=\"{y - 6:0.#}\"/></g>"));
        svg.Append(Invariant($"<text x=\"{x + 8:0.#}\" y=\"{y + 14:0.#}\" fill=\"{color}\" font-weight=\"bold\">{label}</text>\n"));
    }

    private static Vector3 Horizontal(Vector3 v) => new(v.X, 0f, v.Z);

    /// <summary>The point of the unrolled path at distance <paramref name="s"/> (extrapolated before and after it).</summary>
    private static Vector3 AlongPath(List<(Vector3 From, Vector3 To, float Offset)> segments, float s)
    {
        for (int i = 0; i < segments.Count; i++)
        {
            (Vector3 from, Vector3 to, float offset) = segments[i];
            float length = Horizontal(to - from).Length();
            if (s <= offset + length || i == segments.Count - 1)
            {
                Vector3 heading = length > 1e-6f ? Horizontal(to - from) / length : Vector3.UnitX;
                return from + (heading * (s - offset));
            }
        }

        return segments[^1].To;
    }

    private static Vector3 HeadingAt(List<(Vector3 From, Vector3 To, float Offset)> segments, float s)
    {
        foreach ((Vector3 from, Vector3 to, float offset) in segments)
        {
            float length = Horizontal(to - from).Length();
            if (s <= offset + length)
            {
                return length > 1e-6f ? Horizontal(to - from) / length : Vector3.UnitX;
            }
        }

        Vector3 last = Horizontal(segments[^1].To - segments[^1].From);
        return last.LengthSquared() > 1e-12f ? Vector3.Normalize(last) : Vector3.UnitX;
    }

    /// <summary>Height of the highest surface under (x, z), or null where there is none.</summary>
    /// <summary>How far above the track (metres) the ground under it is looked for: a roof or a ceiling higher up is not ground.</summary>
    private const float GroundReach = 1f;

    /// <summary>How far above the track (metres) the level beside it is drawn: a wall, a trough's side, a block; not the ceiling over a room.</summary>
    private const float BesideReach = 2.5f;

    /// <summary>
    /// The side profile's two lines, sampled <paramref name="samples"/> + 1 times from <paramref name="sMin"/> to
    /// <paramref name="sMax"/> along the unrolled track (<paramref name="segments"/>): the ground under the track (the
    /// highest surface straight below a point <see cref="GroundReach"/> above it, where a walk treads and a jump
    /// lands), and the highest surface within <see cref="Corridor"/>/2 either side below <see cref="BesideReach"/>
    /// above the track. NaN where there is none. The track's height runs linearly along each segment.
    /// </summary>
    internal static (float[] Ground, float[] Beside) GroundProfile(TriangleBvh bvh, Aabb bounds, List<(Vector3 From, Vector3 To, float Offset)> segments, float sMin, float sMax, int samples)
    {
        var ground = new float[samples + 1];
        var beside = new float[samples + 1];
        for (int i = 0; i <= samples; i++)
        {
            float s = sMin + ((sMax - sMin) * i / samples);
            Vector3 column = AlongPath(segments, s);
            column.Y = TrackHeight(segments, s);
            Vector3 side = Vector3.Cross(Vector3.UnitY, HeadingAt(segments, s));
            ground[i] = GroundBelow(bvh, bounds, column.X, column.Y + GroundReach, column.Z) ?? float.NaN;
            float best = float.NaN;
            for (int c = -4; c <= 4; c++)
            {
                Vector3 probe = column + (side * (Corridor * c / 8f));
                if (GroundBelow(bvh, bounds, probe.X, column.Y + BesideReach, probe.Z) is float h && !(h <= best))
                {
                    best = h;
                }
            }

            beside[i] = best;
        }

        return (ground, beside);
    }

    /// <summary>The track's height at distance <paramref name="s"/>: linear between the ends of the segment there (held before and after the track).</summary>
    private static float TrackHeight(List<(Vector3 From, Vector3 To, float Offset)> segments, float s)
    {
        foreach ((Vector3 from, Vector3 to, float offset) in segments)
        {
            float length = Horizontal(to - from).Length();
            if (s <= offset + length)
            {
                return length > 1e-6f ? float.Lerp(from.Y, to.Y, Math.Clamp((s - offset) / length, 0f, 1f)) : to.Y;
            }
        }

        return segments[^1].To.Y;
    }

    /// <summary>The highest surface straight below (<paramref name="x"/>, <paramref name="top"/>, <paramref name="z"/>), down to under the level; <c>null</c> where there is none.</summary>
    private static float? GroundBelow(TriangleBvh bvh, Aabb bounds, float x, float top, float z)
    {
        float depth = top - bounds.Min.Y + 2f;
        return depth > 0f && bvh.Raycast(new Vector3(x, top, z), new Vector3(0f, -depth, 0f), 1f, out RayHit hit) ? hit.Point.Y : null;
    }

    private static string HeightMapPng(TriangleBvh bvh, Aabb bounds, int width, int height, Level level) =>
        Convert.ToBase64String(PngEncoder.EncodeRgb(width, height, HeightMapRgb(bvh, bounds, width, height, level)));

    /// <summary>
    /// The level seen from above, shaded by height and slope: RGB bytes, row by row, world X → right, world Z → down;
    /// with <paramref name="level"/> (whose triangles <paramref name="bvh"/> holds) having surface costs, the surfaces
    /// with a travel or enter cost tinted red (<see cref="LevelMaterial.TravelCost"/>).
    /// </summary>
    internal static byte[] HeightMapRgb(TriangleBvh bvh, Aabb bounds, int width, int height, Level? level = null)
    {
        var heights = new float[width * height];
        var normals = new Vector3[width * height];
        bool[]? costly = level is { HasSurfaceCosts: true } ? new bool[width * height] : null;
        float top = bounds.Max.Y + 1f;
        float depth = top - bounds.Min.Y + 2f;
        for (int j = 0; j < height; j++)
        {
            for (int i = 0; i < width; i++)
            {
                float x = bounds.Min.X + ((bounds.Max.X - bounds.Min.X) * (i + 0.5f) / width);
                float z = bounds.Min.Z + ((bounds.Max.Z - bounds.Min.Z) * (j + 0.5f) / height);
                bool hit = bvh.Raycast(new Vector3(x, top, z), new Vector3(0f, -depth, 0f), 1f, out RayHit result);
                heights[(j * width) + i] = hit ? result.Point.Y : float.NaN;
                normals[(j * width) + i] = hit ? result.Normal : Vector3.UnitY;
                if (costly is not null && hit)
                {
                    costly[(j * width) + i] = level!.Materials[level.MaterialIndices[result.Triangle]].HasCost;
                }
            }
        }

        float span = MathF.Max(bounds.Max.Y - bounds.Min.Y, 1e-3f);
        var light = Vector3.Normalize(new Vector3(-0.5f, 1f, -0.4f));
        byte[] rgb = new byte[width * height * 3];
        for (int p = 0; p < heights.Length; p++)
        {
            Vector3 color;
            if (float.IsNaN(heights[p]))
            {
                color = new Vector3(0.55f, 0.7f, 0.85f); // nothing below: water or void
            }
            else
            {
                float t = (heights[p] - bounds.Min.Y) / span;
                Vector3 low = new(0.45f, 0.42f, 0.36f);
                Vector3 high = new(0.96f, 0.9f, 0.78f);
                float shade = 0.55f + (0.45f * MathF.Max(0f, Vector3.Dot(normals[p], light)));
                color = Vector3.Lerp(low, high, t) * shade;
                if (costly?[p] == true)
                {
                    color = Vector3.Lerp(color, new Vector3(0.85f, 0.25f, 0.2f) * shade, 0.55f);
                }
            }

            rgb[3 * p] = (byte)Math.Clamp(color.X * 255f, 0f, 255f);
            rgb[(3 * p) + 1] = (byte)Math.Clamp(color.Y * 255f, 0f, 255f);
            rgb[(3 * p) + 2] = (byte)Math.Clamp(color.Z * 255f, 0f, 255f);
        }

        return rgb;
    }

    private static bool Finite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);

    private static string Escape(string text) => text.Replace("&", "&amp;", StringComparison.Ordinal).Replace("<", "&lt;", StringComparison.Ordinal).Replace(">", "&gt;", StringComparison.Ordinal);

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
