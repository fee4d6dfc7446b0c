using System.Globalization;
using System.Numerics;
using System.Text;
using Ballistic.Planner.Animation;
using Ballistic.Planner.IO;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Steering;

namespace Ballistic.Authoring.Reports;

/// <summary>
/// Draws one jump of an animation as a side-view strip (SVG): the character's bones, seen from its right in the
/// jump's vertical plane (its direction across to the right, up up), at five moments, one panel each: the deepest
/// crouch before takeoff, takeoff, the flight's key pose, landing, and the deepest point of the landing's absorption.
/// The limbs on the character's right (near) are drawn dark over the trunk, those on its left (far) light behind; the
/// ground under held contacts is a line. Each panel says what the animation does there and which spec pose shapes it. The jump drawn is the first
/// that travels the farthest across, within a tenth of a metre.
/// </summary>
public static class PhaseStripRenderer
{
    private const float Panel = 170f;
    private const float Height = 250f;
    private const float Figure = 150f;
    private const float Window = 0.6f;

    /// <summary>The strip of <paramref name="animation"/>'s longest jump; null when the animation has no jump.</summary>
    public static string? Render(JumpAnimation animation)
    {
        ArgumentNullException.ThrowIfNull(animation);
        if (animation.Arcs.Count == 0)
        {
            return null;
        }

        float longest = animation.Arcs.Max(Across);
        int jump = Enumerable.Range(0, animation.Arcs.Count).First(j => Across(animation.Arcs[j]) >= longest - 0.1f);
        BallisticArc arc = animation.Arcs[jump];
        int move = animation.MoveOfJump(jump);
        float takeoff = animation.JumpStart(jump);
        float landing = takeoff + arc.FlightTime;
        float before = Math.Max(move > 0 ? animation.MoveEnd(move - 1) : 0f, takeoff - Window);
        float after = Math.Min(move + 1 < animation.Moves.Count ? animation.MoveStart(move + 1) : animation.Duration, landing + Window);
        (string Name, float Time, string What)[] phases =
        [
            ("crouch", Lowest(animation, before, takeoff), "sinking; free limbs toward flexion"),
            ("takeoff", takeoff, "contact pose, driving up"),
            ("flight", takeoff + JumpAnimator.ApexKeyTime(arc), "extending pose"),
            ("landing", landing, "contact pose, touching down"),
            ("absorb", Lowest(animation, landing, after), "sinking, then rising"),
        ];

        Vector3 across = arc.End - arc.Start;
        across.Y = 0f;
        across = across.LengthSquared() > 1e-8f ? Vector3.Normalize(across) : Vector3.UnitZ;
        Rig rig = animation.Model.Rig;
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        var poses = new List<(Vector3[] Points, Vector3[] Ends, Vector3 Root, float? Ground)>();
        float extent = 0.1f;
        foreach ((string _, float time, string _) in phases)
        {
            animation.Joints(time, positions, rotations);
            Vector3[] ends = [.. animation.Model.Limbs.Select(l => l.EffectorPosition(positions, rotations))];
            float? ground = animation.ContactPhases.Where(p => p.From <= time + 1e-4f && p.To >= time - 1e-4f).Select(p => (float?)p.Position.Y).DefaultIfEmpty(null).Min();
            Vector3 root = positions[0];
            poses.Add(((Vector3[])positions.Clone(), ends, root, ground));
            foreach (Vector3 p in positions.Concat(ends))
            {
                extent = MathF.Max(extent, MathF.Max(MathF.Abs(Vector3.Dot(p - root, across)), MathF.Abs(p.Y - root.Y)));
            }
        }

        bool[] onLeftSide = LeftSide(animation.Model);
        float scale = 0.5f * Figure / extent;
        float width = Panel * phases.Length;
        var svg = new StringBuilder();
        svg.Append(Invariant($"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width:0}\" height=\"{Height + 70f:0}\" viewBox=\"0 0 {width:0} {Height + 70f:0}\" font-family=\"sans-serif\" font-size=\"11\">\n"));
        svg.Append(Invariant($"<rect width=\"{width:0}\" height=\"{Height + 70f:0}\" fill=\"#ffffff\"/>\n"));
        svg.Append(Invariant($"<text x=\"8\" y=\"16\" font-weight=\"bold\">{Escape(animation.Model.Name)}, jump {jump + 1} of {animation.Arcs.Count} ({Across(arc):0.0} m across, {arc.FlightTime:0.00} s in the air), seen from its right; 1 m = {scale:0} px</text>\n"));
        for (int k = 0; k < phases.Length; k++)
        {
            (string name, float time, string what) = phases[k];
            (Vector3[] points, Vector3[] ends, Vector3 root, float? ground) = poses[k];
            float cx = (Panel * k) + (0.5f * Panel);
            float cy = 30f + (0.5f * Height);
            float X(Vector3 p) => cx + (scale * Vector3.Dot(p - root, across));
            float Y(float y) => cy - (scale * (y - root.Y));
            if (k > 0)
            {
                svg.Append(Invariant($"<line x1=\"{Panel * k:0}\" y1=\"26\" x2=\"{Panel * k:0}\" y2=\"{Height + 34f:0}\" stroke=\"#dee2e6\"/>\n"));
            }

            if (ground is float g)
            {
                svg.Append(Invariant($"<line x1=\"{cx - (0.45f * Panel):0.#}\" y1=\"{Y(g):0.#}\" x2=\"{cx + (0.45f * Panel):0.#}\" y2=\"{Y(g):0.#}\" stroke=\"#868e96\" stroke-width=\"2\"/>\n"));
            }

            // Seen from its right: the left limbs first (far, light), then the trunk and the right limbs (near, dark).
            foreach (bool left in new[] { true, false })
            {
                string color = left ? "#74c0fc" : "#212529";
                svg.Append(Invariant($"<g stroke=\"{color}\" stroke-width=\"2.2\" stroke-linecap=\"round\">"));
                for (int j = 1; j < rig.Joints.Count; j++)
                {
                    bool onLeft = onLeftSide[j];
                    if (onLeft == left)
                    {
                        Vector3 a = points[rig.Joints[j].Parent];
                        Vector3 b = points[j];
                        svg.Append(Invariant($"<line x1=\"{X(a):0.#}\" y1=\"{Y(a.Y):0.#}\" x2=\"{X(b):0.#}\" y2=\"{Y(b.Y):0.#}\"/>"));
                    }
                }

                for (int l = 0; l < animation.Model.Limbs.Count; l++)
                {
                    RigLimb limb = animation.Model.Limbs[l];
                    if (onLeftSide[limb.RootJoint] == left)
                    {
                        Vector3 a = points[limb.EffectorJoint];
                        svg.Append(Invariant($"<line x1=\"{X(a):0.#}\" y1=\"{Y(a.Y):0.#}\" x2=\"{X(ends[l]):0.#}\" y2=\"{Y(ends[l].Y):0.#}\"/>"));
                    }
                }

                svg.Append("</g>\n");
            }

            svg.Append(Invariant($"<text x=\"{cx:0.#}\" y=\"{Height + 44f:0}\" text-anchor=\"middle\" font-weight=\"bold\">{k + 1}. {name} ({time:0.00} s)</text>\n"));
            svg.Append(Invariant($"<text x=\"{cx:0.#}\" y=\"{Height + 58f:0}\" text-anchor=\"middle\" font-size=\"9\">{Escape(what)}</text>\n"));
        }

        svg.Append("</svg>\n");
        return svg.ToString();
    }

    /// <summary>Writes the strip of <paramref name="animation"/>'s longest jump to <paramref name="path"/>; false (nothing written) when it has no jump.</summary>
    public static bool Save(JumpAnimation animation, string path)
    {
        ArgumentNullException.ThrowIfNull(path);
        string? svg = Render(animation);
        if (svg is null)
        {
            return false;
        }

        OutputFile.Write(path, new UTF8Encoding(false).GetBytes(svg));
        return true;
    }

    private static float Across(BallisticArc arc) => new Vector2(arc.End.X - arc.Start.X, arc.End.Z - arc.Start.Z).Length();

    /// <summary>The time in [<paramref name="from"/>, <paramref name="to"/>] at which the root is lowest (sampled every 1/120 s).</summary>
    private static float Lowest(JumpAnimation animation, float from, float to)
    {
        var positions = new Vector3[animation.Model.Rig.Joints.Count];
        var rotations = new Quaternion[animation.Model.Rig.Joints.Count];
        float best = from;
        float lowest = float.PositiveInfinity;
        for (float t = from; t <= to + 1e-6f; t += 1f / 120f)
        {
            animation.Joints(MathF.Min(t, to), positions, rotations);
            if (positions[0].Y < lowest - 1e-6f)
            {
                lowest = positions[0].Y;
                best = MathF.Min(t, to);
            }
        }

        return best;
    }

    /// <summary>For each joint, whether it lies on the character's left (+X) in the contact pose, more than a centimetre from the middle.</summary>
    private static bool[] LeftSide(CharacterModel model)
    {
        var positions = new Vector3[model.Rig.Joints.Count];
        var rotations = new Quaternion[model.Rig.Joints.Count];
        model.Rig.Solve(new(Vector3.Zero, Quaternion.Identity), model.ContactPose, positions, rotations);
        return [.. positions.Select(p => p.X - positions[0].X > 0.01f)];
    }

    private static string Escape(string text) => text.Replace("&", "&amp;", StringComparison.Ordinal).Replace("<", "&lt;", StringComparison.Ordinal).Replace(">", "&gt;", StringComparison.Ordinal);

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
