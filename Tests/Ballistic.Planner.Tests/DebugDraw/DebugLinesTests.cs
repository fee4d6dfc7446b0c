using System.Numerics;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;
using Ballistic.Planner.Tests.Runtime;
using Ballistic.Planner.Tests.Skeletons;
using Ballistic.Runtime.DebugDraw;
using Ballistic.Runtime.Paths;

namespace Ballistic.Planner.Tests.DebugDraw;

/// <summary>
/// Debug line geometry: arc polylines lie on their arcs, cones open at atan μ around their axes, caps hold and pick
/// evenly, the same calls give the same lines, and redrawing into cleared buffers allocates nothing.
/// </summary>
public sealed class DebugLinesTests
{
    private static Roadmap Roadmap => RuntimeWorlds.DesertSkeleton.Roadmap;

    [Test]
    public void RoadmapJumpsArePolylinesOnTheirArcsWithinTheCaps()
    {
        var settings = new DebugDrawSettings { MaxArcs = 40, MaxSegmentsPerArc = 6, SegmentLength = 0.2f };
        var lines = new DebugLines(4);
        DebugLineRange range = lines.AddRoadmapJumps(Roadmap, settings);
        int edges = Roadmap.Edges.Count;
        Assert.That(edges, Is.GreaterThan(40), "the roadmap has more jumps than the cap");

        int[] picked = [.. Enumerable.Range(0, 40).Select(k => DebugLines.Pick(k, edges, 40))];
        Assert.Multiple(() =>
        {
            Assert.That(picked[0], Is.Zero);
            Assert.That(picked, Is.Ordered.Ascending.And.Unique);
            Assert.That(picked.Zip(picked.Skip(1), (a, b) => b - a), Has.All.InRange(edges / 40, (edges / 40) + 1), "evenly spaced");
            Assert.That(range, Is.EqualTo(new DebugLineRange(0, lines.SegmentCount)));
        });

        // Walk the polylines: each picked arc's segments in order, joined end to start, every vertex on the arc.
        int segment = 0;
        ReadOnlySpan<Vector3> v = lines.Vertices;
        foreach (int e in picked)
        {
            BallisticArc arc = Roadmap.Edges[e].Arc;
            int n = DebugLines.SegmentsFor(arc, settings);
            Assert.That(n, Is.InRange(1, 6));
            for (int s = 0; s < n; s++, segment++)
            {
                Assert.That(DistanceToArc(arc, v[2 * segment]), Is.LessThan(1e-4f), $"edge {e} segment {s} start");
                Assert.That(DistanceToArc(arc, v[(2 * segment) + 1]), Is.LessThan(1e-4f), $"edge {e} segment {s} end");
                if (s > 0)
                {
                    Assert.That(v[2 * segment], Is.EqualTo(v[(2 * segment) - 1]), "joined");
                }
            }

            Assert.That(Vector3.Distance(v[(2 * segment) - 1], arc.End), Is.LessThan(1e-4f), $"edge {e} ends on landing");
        }

        Assert.That(segment, Is.EqualTo(lines.SegmentCount));
        Assert.That(lines.Colors.ToArray(), Has.All.EqualTo(DebugPalette.GodotDefaults.Jumps));

        // A cap of zero draws nothing; a cap above the count draws every jump.
        lines.Clear();
        Assert.That(lines.AddRoadmapJumps(Roadmap, settings with { MaxArcs = 0 }).Count, Is.Zero);
        Assert.That(lines.AddRoadmapJumps(Roadmap, settings with { MaxArcs = edges + 10 }).Count, Is.EqualTo(Roadmap.Edges.Sum(e => DebugLines.SegmentsFor(e.Arc, settings))));
    }

    [Test]
    public void RoadmapNodesAreCrossesAtTheirContactCentres()
    {
        var lines = new DebugLines();
        var settings = new DebugDrawSettings { MaxNodes = 25, CrossHalfSize = 0.1f };
        DebugLineRange range = lines.AddRoadmapNodes(Roadmap, settings);
        Assert.That(range.Count, Is.EqualTo(3 * 25));
        ReadOnlySpan<Vector3> v = lines.Vertices;
        for (int k = 0; k < 25; k++)
        {
            Vector3 centre = Roadmap.ContactCentres[DebugLines.Pick(k, Roadmap.Nodes.Count, 25)];
            for (int s = 0; s < 3; s++)
            {
                Vector3 a = v[2 * ((3 * k) + s)];
                Vector3 b = v[(2 * ((3 * k) + s)) + 1];
                Assert.That(Vector3.Distance((a + b) / 2f, centre), Is.LessThan(1e-5f));
                Assert.That(Vector3.Distance(a, b), Is.EqualTo(0.2f).Within(1e-5f));
            }
        }

        Assert.That(Roadmap.Nodes[7].ContactCentre, Is.EqualTo(Roadmap.ContactCentres[7]));
    }

    [TestCase(0.5f)]
    [TestCase(1.2f)]
    [TestCase(0f)]
    public void ConeRaysMakeTheConesHalfAngleWithItsAxis(float mu)
    {
        var lines = new DebugLines();
        var apex = new Vector3(1f, 2f, 3f);
        var cone = new FrictionCone(new Vector3(0.3f, 1f, -0.2f), mu);
        var settings = new DebugDrawSettings { ConeRays = 9, ConeLength = 0.8f };
        DebugLineRange range = lines.AddFrictionCone(apex, cone, DebugPalette.GodotDefaults.Cones, settings);
        Assert.That(range.Count, Is.EqualTo(1 + (2 * 9)));
        ReadOnlySpan<Vector3> v = lines.Vertices;
        Assert.That(Vector3.Distance(v[1] - v[0], cone.Axis * 0.8f), Is.LessThan(1e-5f), "the axis first");
        var ends = new List<Vector3>();
        for (int k = 1; k <= 9; k++)
        {
            Vector3 ray = v[(2 * k) + 1] - v[2 * k];
            Assert.That(v[2 * k], Is.EqualTo(apex), "rays leave the apex");
            Assert.That(ray.Length(), Is.EqualTo(0.8f).Within(1e-5f));
            Assert.That(cone.AngleTo(ray), Is.EqualTo(MathF.Atan(mu)).Within(2e-4f), $"ray {k}");
            ends.Add(v[(2 * k) + 1]);
        }

        // The ring joins the ends in turn; the rays spread evenly around the axis.
        for (int k = 0; k < 9; k++)
        {
            Assert.That(v[2 * (10 + k)], Is.EqualTo(ends[k]));
            Assert.That(v[(2 * (10 + k)) + 1], Is.EqualTo(ends[(k + 1) % 9]));
        }

        if (mu > 0f)
        {
            float chord = Vector3.Distance(ends[0], ends[1]);
            Assert.That(ends.Zip(ends.Skip(1).Append(ends[0]), Vector3.Distance), Has.All.EqualTo(chord).Within(1e-4f));
        }
    }

    [Test]
    public void APathIsItsArcsAndItsStancesCones()
    {
        AgentPath path = AnimationClipBakerTests.SampledPath;
        var lines = new DebugLines();
        var settings = new DebugDrawSettings { MaxSegmentsPerArc = 10 };
        DebugLineRange arcs = lines.AddPath(path, firstMove: 0, settings);
        DebugLineRange cones = lines.AddPathCones(path, firstMove: 0, settings);
        var jumps = path.Moves.Where(m => m.Kind == MoveKind.Jump).ToList();
        Assert.Multiple(() =>
        {
            Assert.That(jumps, Is.Not.Empty);
            Assert.That(arcs.Count, Is.EqualTo(path.Moves.Sum(m => Segments(m, settings))));
            Assert.That(cones, Is.EqualTo(new DebugLineRange(arcs.Count, jumps.Count * 2 * (1 + (2 * settings.ConeRays)))));
            Assert.That(lines.Colors[..(2 * arcs.Count)].ToArray(), Has.All.EqualTo(DebugPalette.GodotDefaults.Path));
            Assert.That(lines.Colors[(2 * arcs.Count)..].ToArray(), Has.All.EqualTo(DebugPalette.GodotDefaults.Cones));
        });

        ReadOnlySpan<Vector3> v = lines.VerticesOf(arcs);
        int segment = 0;
        foreach (PathMove move in path.Moves)
        {
            for (int s = 0; s < Segments(move, settings); s++, segment++)
            {
                Assert.That(DistanceToMove(move, v[2 * segment]), Is.LessThan(1e-4f));
                Assert.That(DistanceToMove(move, v[(2 * segment) + 1]), Is.LessThan(1e-4f));
            }
        }

        // Each jump's takeoff cone stands at its takeoff stance's contact centre, its landing cone at the landing's.
        ReadOnlySpan<Vector3> c = lines.VerticesOf(cones);
        int verticesPerCone = 2 * (1 + (2 * settings.ConeRays));
        for (int m = 0; m < jumps.Count; m++)
        {
            Assert.That(c[2 * m * verticesPerCone], Is.EqualTo(jumps[m].From.ContactCentre), $"jump {m} takeoff cone");
            Assert.That(c[((2 * m) + 1) * verticesPerCone], Is.EqualTo(jumps[m].To.ContactCentre), $"jump {m} landing cone");
            Vector3 axis = c[(((2 * m) + 1) * verticesPerCone) + 1] - c[((2 * m) + 1) * verticesPerCone];
            Assert.That(Vector3.Distance(axis, jumps[m].To.Cone.Axis * settings.ConeLength), Is.LessThan(1e-5f), "along the landing stance's cone axis");
        }

        // From the last move on: only its own lines.
        lines.Clear();
        Assert.That(lines.AddPath(path, path.Count - 1, settings).Count, Is.EqualTo(Segments(path.Moves[^1], settings)));
        Assert.That(lines.AddPath(path, path.Count, settings).Count, Is.Zero);
    }

    [Test]
    public void AWalkIsDrawnDashedOnItsTrunksPath()
    {
        IReadOnlyList<Move> moves = WalkingPaths.WalkJumpWalk();
        var walk = (Walk)moves[2];
        var lines = new DebugLines();
        var settings = new DebugDrawSettings { WalkDashLength = 0.1f };
        DebugLineRange dashes = lines.AddWalk(walk, DebugPalette.GodotDefaults.Path, settings);
        ReadOnlySpan<Vector3> v = lines.VerticesOf(dashes);

        // Where the trunk moves as it turns in place at either end (standing up over the contacts), a segment; along
        // the ground path, an odd number of equal pieces of about 0.1 m, every other one drawn, the first and the last included.
        int head = walk.From.Pose.Position != walk.PoseAtDistance(0f).Position ? 1 : 0;
        int tail = walk.To.Pose.Position != walk.PoseAtDistance(walk.Length).Position ? 1 : 0;
        int pieces = (int)MathF.Ceiling(walk.Length / 0.1f) | 1;
        Assert.That(dashes.Count, Is.EqualTo(((pieces + 1) / 2) + head + tail));
        Assert.That(v[0], Is.EqualTo(walk.From.Pose.Position), "starts on the first stance's trunk centre");
        Assert.That(v[^1], Is.EqualTo(walk.To.Pose.Position), "ends on the last stance's trunk centre");
        float drawn = 0f;
        for (int i = 0; i < v.Length; i++)
        {
            Assert.That(DistanceToWalk(walk, v[i]), Is.LessThan(1e-4f), $"vertex {i} on the trunk's path");
        }

        for (int k = head; k < dashes.Count - tail; k++)
        {
            float dash = Vector3.Distance(v[2 * k], v[(2 * k) + 1]);
            Assert.That(dash, Is.LessThanOrEqualTo((walk.Length / pieces) + 1e-4f), $"dash {k}");
            drawn += dash;
            if (k > head)
            {
                Assert.That(Vector3.Distance(v[(2 * k) - 1], v[2 * k]), Is.GreaterThan(0.5f * walk.Length / pieces), $"a gap before dash {k}");
            }
        }

        Assert.That(drawn, Is.InRange(0.4f * walk.Length, 0.6f * walk.Length + (walk.Length / pieces)), "about half the walk is drawn");

        // Solid: a connected polyline of short segments, every vertex on the path.
        lines.Clear();
        DebugLineRange solid = lines.AddWalk(walk, DebugPalette.GodotDefaults.Path, settings with { WalkDashLength = 0f, SegmentLength = 0.2f });
        v = lines.VerticesOf(solid);
        Assert.That(solid.Count, Is.EqualTo((int)MathF.Ceiling(walk.Length / 0.2f) + head + tail));
        for (int k = 0; k < solid.Count; k++)
        {
            Assert.That(Vector3.Distance(v[2 * k], v[(2 * k) + 1]), Is.LessThanOrEqualTo(k < head || k >= solid.Count - tail ? walk.TurnTravel + 1e-4f : 0.2f + 1e-4f));
            Assert.That(DistanceToWalk(walk, v[(2 * k) + 1]), Is.LessThan(1e-4f));
            if (k > 0)
            {
                Assert.That(v[2 * k], Is.EqualTo(v[(2 * k) - 1]), "connected");
            }
        }

        // The cap: a long walk keeps at most MaxSegmentsPerWalk dashes.
        lines.Clear();
        Assert.That(lines.AddWalk(walk, DebugPalette.GodotDefaults.Path, settings with { WalkDashLength = 0.001f, MaxSegmentsPerWalk = 7 }).Count, Is.EqualTo(7 + head + tail));
        Assert.That(new DebugDrawSettings { WalkDashLength = -1f }.Problem(), Does.Contain("dash"));
        Assert.That(new DebugDrawSettings { MaxSegmentsPerWalk = 0 }.Problem(), Does.Contain("per walk"));
    }

    [Test]
    public void APathWithWalksDrawsTheirDashesAndOnlyTheJumpsCones()
    {
        IReadOnlyList<Move> moves = WalkingPaths.WalkJumpWalk();
        var path = new AgentPath(Vector3.Zero, moves, new SimpleMoveAnimator(RuntimeWorlds.DesertSkeleton.Animator).Animate(moves));
        var lines = new DebugLines();
        var settings = new DebugDrawSettings();
        DebugLineRange drawn = lines.AddPath(path, 0, settings);
        int first = lines.AddWalk((Walk)moves[0], settings.Colors.Path, settings).Count;
        int arc = lines.AddArc(((Jump)moves[1]).Arc, settings.Colors.Path, settings).Count;
        int last = lines.AddWalk((Walk)moves[2], settings.Colors.Path, settings).Count;
        Assert.That(drawn.Count, Is.EqualTo(first + arc + last));
        Vector3[] byPath = lines.Vertices[..(2 * drawn.Count)].ToArray();
        Vector3[] oneByOne = lines.Vertices[(2 * drawn.Count)..].ToArray();
        Assert.That(byPath, Is.EqualTo(oneByOne), "the walk, the arc, the walk");
        Assert.That(lines.VerticesOf(drawn)[0], Is.EqualTo(moves[0].From.Pose.Position));
        Assert.That(lines.VerticesOf(drawn)[^1], Is.EqualTo(moves[2].To.Pose.Position));

        lines.Clear();
        Assert.That(lines.AddPathCones(path, 0, settings).Count, Is.EqualTo(2 * (1 + (2 * settings.ConeRays))), "the jump's two cones only");
        Assert.That(lines.Vertices[0], Is.EqualTo(moves[1].From.ContactCentre));
        lines.Clear();
        Assert.That(lines.AddPath(path, 1, settings).Count, Is.EqualTo(arc + last), "from the jump on");
    }

    [Test]
    public void TheSameCallsGiveTheSameLinesAndRedrawingAllocatesNothing()
    {
        AgentPath path = AnimationClipBakerTests.SampledPath;
        var settings = new DebugDrawSettings { MaxArcs = 300, MaxNodes = 200 };
        void Draw(DebugLines lines)
        {
            lines.Clear();
            lines.AddRoadmapNodes(Roadmap, settings);
            lines.AddRoadmapJumps(Roadmap, settings);
            lines.AddPath(path, 0, settings);
            lines.AddPathCones(path, 0, settings);
            lines.AddNodeCone(Roadmap.Nodes[3], settings);
        }

        var a = new DebugLines();
        var b = new DebugLines(1);
        Draw(a);
        Draw(b);
        Assert.That(b.Vertices.ToArray(), Is.EqualTo(a.Vertices.ToArray()));
        Assert.That(b.Colors.ToArray(), Is.EqualTo(a.Colors.ToArray()));

        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 0; i < 5; i++)
        {
            Draw(a);
        }

        Assert.That(GC.GetAllocatedBytesForCurrentThread() - before, Is.Zero, "redrawing into grown buffers");
        Assert.That(a.Vertices.ToArray(), Is.EqualTo(b.Vertices.ToArray()));
    }

    [Test]
    public void ThePaletteIsGodotsNavigationDebugDefaults()
    {
        DebugPalette palette = DebugPalette.GodotDefaults;
        Assert.Multiple(() =>
        {
            Assert.That(palette.Nodes, Is.EqualTo(new DebugColor(0.5f, 1f, 1f, 1f)));
            Assert.That(palette.Jumps, Is.EqualTo(new DebugColor(1f, 0.5f, 1f, 1f)));
            Assert.That(palette.Path, Is.EqualTo(new DebugColor(1f, 0f, 0f, 1f)));
            Assert.That(palette.Cones, Is.EqualTo(new DebugColor(1f, 0f, 1f, 1f)));
            Assert.That(new[] { DebugPalette.NodeSetting, DebugPalette.JumpSetting, DebugPalette.PathSetting, DebugPalette.ConeSetting, DebugPalette.DisabledSetting }, Has.All.StartsWith("debug/shapes/navigation/3d/"));
            Assert.That(System.Runtime.InteropServices.Marshal.SizeOf<DebugColor>(), Is.EqualTo(16), "four floats, as Godot's Color");
        });
    }

    [Test]
    public void BadSettingsAreRefusedWithTheReason()
    {
        var lines = new DebugLines();
        Assert.Multiple(() =>
        {
            Assert.That(() => lines.AddRoadmapJumps(Roadmap, new DebugDrawSettings { MaxSegmentsPerArc = 0 }), Throws.ArgumentException.With.Message.Contains("segments per arc"));
            Assert.That(() => lines.AddRoadmapNodes(Roadmap, new DebugDrawSettings { CrossHalfSize = float.NaN }), Throws.ArgumentException.With.Message.Contains("cross half size"));
            Assert.That(() => lines.AddNodeCone(Roadmap.Nodes[0], new DebugDrawSettings { ConeRays = 2 }), Throws.ArgumentException.With.Message.Contains("cone rays"));
            Assert.That(() => lines.AddPath(AnimationClipBakerTests.SampledPath, -1), Throws.InstanceOf<ArgumentOutOfRangeException>());
        });
        Assert.That(lines.SegmentCount, Is.Zero, "nothing drawn by a refused call");
    }

    /// <summary>Segments <see cref="DebugLines.AddPath"/> draws for a move: an arc's polyline, or a walk's dashes (half its odd number of pieces, rounded up).</summary>
    private static int Segments(in PathMove move, DebugDrawSettings settings) =>
        move.Walk is { } walk
            ? (Math.Clamp((int)MathF.Ceiling(walk.Length / settings.WalkDashLength), 1, (2 * settings.MaxSegmentsPerWalk) - 1) | 1) / 2 + 1
            : DebugLines.SegmentsFor(move.Arc, settings);

    private static float DistanceToMove(in PathMove move, Vector3 p) => move.Walk is { } walk ? DistanceToWalk(walk, p) : DistanceToArc(move.Arc, p);

    /// <summary>Distance to the trunk's path along a walk, sampled every millimetre.</summary>
    private static float DistanceToWalk(Walk walk, Vector3 p)
    {
        int n = Math.Max(1, (int)MathF.Ceiling(walk.Length / 1e-3f));
        var points = new Vector3[n + 3];
        points[0] = walk.From.Pose.Position;
        for (int k = 0; k <= n; k++)
        {
            points[k + 1] = walk.PoseAtDistance(walk.Length * k / n).Position;
        }

        points[^1] = walk.To.Pose.Position;
        return WalkingPaths.DistanceToPolyline(p, points);
    }

    /// <summary>How far <paramref name="p"/> is from the arc's point at the time its horizontal progress gives.</summary>
    private static float DistanceToArc(in BallisticArc arc, Vector3 p)
    {
        var horizontal = new Vector3(arc.TakeoffVelocity.X, 0f, arc.TakeoffVelocity.Z);
        float t = horizontal.LengthSquared() > 1e-8f
            ? Vector3.Dot(p - arc.Start, horizontal) / horizontal.LengthSquared()
            : 0f;
        return horizontal.LengthSquared() > 1e-8f ? Vector3.Distance(arc.PositionAt(t), p) : MathF.Abs(p.X - arc.Start.X) + MathF.Abs(p.Z - arc.Start.Z);
    }
}
