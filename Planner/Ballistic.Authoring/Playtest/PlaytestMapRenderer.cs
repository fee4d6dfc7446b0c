using System.Globalization;
using System.Numerics;
using System.Text;
using Ballistic.Authoring.Reports;
using Ballistic.Planner.Geometry;

namespace Ballistic.Authoring.Playtest;

/// <summary>
/// The playtest seen from above: the level shaded by height, every executed jump as a line from takeoff to landing
/// (blue), every executed walk as its ground path dashed (green-blue), the spawn points (white), reached targets (green) and failed ones (red crosses, with a thin red line from
/// where the agent stood). As an SVG (vector marks over the shaded level, a title and a legend) and as a PNG (that SVG drawn).
/// World X → right, world Z → down.
/// </summary>
public static class PlaytestMapRenderer
{
    private const int Width = 900;

    /// <summary>Pixels drawn, then pixels skipped, along a walk's dashed line in the PNG.</summary>
    private const int DashOn = 5;
    private const int DashOff = 3;

    /// <summary>The map as an SVG document.</summary>
    public static string Svg(PlaytestResult result)
    {
        ArgumentNullException.ThrowIfNull(result);
        (int width, int height, Func<Vector3, Vector2> map) = Frame(result);
        byte[] rgb = SvgPlanRenderer.HeightMapRgb(result.Kind.Scene.Bvh, result.Kind.Scene.Level.Bounds, width, height, result.Kind.Scene.Level);
        string png = Convert.ToBase64String(PngEncoder.EncodeRgb(width, height, rgb));
        var svg = new StringBuilder();
        svg.Append(Invariant($"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width}\" height=\"{height + 40}\" viewBox=\"0 0 {width} {height + 40}\" font-family=\"sans-serif\" font-size=\"13\">\n"));
        svg.Append(Invariant($"<rect width=\"{width}\" height=\"{height + 40}\" fill=\"#ffffff\"/>\n"));
        svg.Append(Invariant($"<text x=\"8\" y=\"18\">{Escape(Title(result))}</text>\n"));
        svg.Append(Invariant($"<text x=\"8\" y=\"34\" fill=\"#555\">{Escape(Legend(result.Kind.Scene.Level))}</text>\n"));
        svg.Append(Invariant($"<image x=\"0\" y=\"40\" width=\"{width}\" height=\"{height}\" href=\"data:image/png;base64,{png}\"/>\n"));
        svg.Append("<g transform=\"translate(0,40)\">\n");
        foreach (PlaytestAgent agent in result.Agents)
        {
            foreach (ExecutedJump jump in agent.Jumps)
            {
                Vector2 a = map(jump.Jump.Arc.Start);
                Vector2 b = map(jump.Jump.Arc.End);
                svg.Append(Invariant($"<line x1=\"{a.X:0.#}\" y1=\"{a.Y:0.#}\" x2=\"{b.X:0.#}\" y2=\"{b.Y:0.#}\" stroke=\"#1f5fbf\" stroke-opacity=\"0.55\" stroke-width=\"1.2\"/>\n"));
            }

            foreach (ExecutedWalk walk in agent.Walks)
            {
                string points = string.Join(" ", walk.Walk.Path.Select(p => map(p)).Select(p => Invariant($"{p.X:0.#},{p.Y:0.#}")));
                svg.Append(Invariant($"<polyline class=\"walk\" points=\"{points}\" fill=\"none\" stroke=\"#138a72\" stroke-opacity=\"0.75\" stroke-width=\"1.4\" stroke-dasharray=\"{DashOn} {DashOff}\"/>\n"));
            }
        }

        foreach (PlaytestAgent agent in result.Agents)
        {
            Vector2 s = map(agent.Spawn);
            svg.Append(Invariant($"<circle cx=\"{s.X:0.#}\" cy=\"{s.Y:0.#}\" r=\"3.5\" fill=\"#ffffff\" stroke=\"#000\" stroke-width=\"0.8\"/>\n"));
            foreach (PlaytestTarget target in agent.Targets.Where(t => t.Reached))
            {
                Vector2 p = map(target.Target);
                svg.Append(Invariant($"<circle cx=\"{p.X:0.#}\" cy=\"{p.Y:0.#}\" r=\"2.5\" fill=\"#2e9d3a\"/>\n"));
            }
        }

        foreach ((Vector3 target, Vector3 from) in PlaytestReportWriter.Failures(result))
        {
            Vector2 p = map(target);
            Vector2 f = map(from);
            svg.Append(Invariant($"<line x1=\"{f.X:0.#}\" y1=\"{f.Y:0.#}\" x2=\"{p.X:0.#}\" y2=\"{p.Y:0.#}\" stroke=\"#d62728\" stroke-opacity=\"0.5\" stroke-width=\"0.8\" stroke-dasharray=\"3 2\"/>\n"));
            svg.Append(Invariant($"<path d=\"M{p.X - 5:0.#},{p.Y - 5:0.#} L{p.X + 5:0.#},{p.Y + 5:0.#} M{p.X - 5:0.#},{p.Y + 5:0.#} L{p.X + 5:0.#},{p.Y - 5:0.#}\" stroke=\"#d62728\" stroke-width=\"2.2\"/>\n"));
        }

        svg.Append("</g>\n</svg>\n");
        return svg.ToString();
    }

    /// <summary>The map's legend: its marks, and the red tint of surfaces with a travel or enter cost on a level that has them.</summary>
    internal static string Legend(Ballistic.Planner.Levels.Level level) =>
        "blue: jumps taken · dashed teal: walks · white: spawns · green: targets reached · red ×: targets failed (line from where the agent stood)"
        + (level.HasSurfaceCosts ? " · red ground: a travel or enter cost" : "");

    /// <summary>The map as a PNG image: the SVG, title and legend included, drawn by <see cref="SvgRaster"/>.</summary>
    public static byte[] Png(PlaytestResult result) => Png(Svg(result));

    /// <summary>The map's SVG (<see cref="Svg"/>) as a PNG image: for a caller writing both, so the level's height map is shaded once.</summary>
    public static byte[] Png(string svg) => SvgRaster.ToPng(svg);

    private static (int Width, int Height, Func<Vector3, Vector2> Map) Frame(PlaytestResult result)
    {
        Aabb bounds = result.Kind.Scene.Level.Bounds;
        float worldW = MathF.Max(bounds.Max.X - bounds.Min.X, 1e-3f);
        float worldD = MathF.Max(bounds.Max.Z - bounds.Min.Z, 1e-3f);
        float scale = Width / worldW;
        int height = Math.Clamp((int)MathF.Round(worldD * scale), 2, 4 * Width);
        return (Width, height, p => new Vector2((p.X - bounds.Min.X) * scale, (p.Z - bounds.Min.Z) * scale));
    }

    private static string Title(PlaytestResult result) =>
        Invariant($"{result.Kind.Name}: {result.Agents.Count} agents, {result.Settings.Seconds:0.#} s — {result.TargetsReached} targets reached, {result.TargetsFailed} failed, {result.JumpsTaken} jumps, {result.WalksTaken} walks");

    private static string Escape(string text) => text.Replace("&", "&amp;", StringComparison.Ordinal).Replace("<", "&lt;", StringComparison.Ordinal).Replace(">", "&gt;", StringComparison.Ordinal);

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
