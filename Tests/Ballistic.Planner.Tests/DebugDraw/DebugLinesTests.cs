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

        Assert.That(DebugLines.ContactCentre(Roadmap.Nodes[7]), Is.EqualTo(Roadmap.ContactCentres[7]));
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
        Assert.Multiple(() =>
        {
            Assert.That(arcs.Count, Is.EqualTo(path.Moves.Sum(m => DebugLines.SegmentsFor(m.Arc, settings))));
            Assert.That(cones, Is.EqualTo(new DebugLineRange(arcs.Count, path.Count * 2 * (1 + (2 * settings.ConeRays)))));
            Assert.That(lines.Colors[..(2 * arcs.Count)].ToArray(), Has.All.EqualTo(DebugPalette.GodotDefaults.Path));
            Assert.That(lines.Colors[(2 * arcs.Count)..].ToArray(), Has.All.EqualTo(DebugPalette.GodotDefaults.Cones));
        });

        ReadOnlySpan<Vector3> v = lines.VerticesOf(arcs);
        int segment = 0;
        foreach (PathMove move in path.Moves)
        {
            for (int s = 0; s < DebugLines.SegmentsFor(move.Arc, settings); s++, segment++)
            {
                Assert.That(DistanceToArc(move.Arc, v[2 * segment]), Is.LessThan(1e-4f));
                Assert.That(DistanceToArc(move.Arc, v[(2 * segment) + 1]), Is.LessThan(1e-4f));
            }
        }

        // Each move's takeoff cone stands at its takeoff stance's contact centre, its landing cone at the landing's.
        ReadOnlySpan<Vector3> c = lines.VerticesOf(cones);
        int verticesPerCone = 2 * (1 + (2 * settings.ConeRays));
        for (int m = 0; m < path.Count; m++)
        {
            Assert.That(c[2 * m * verticesPerCone], Is.EqualTo(DebugLines.ContactCentre(path.Moves[m].From)), $"move {m} takeoff cone");
            Assert.That(c[((2 * m) + 1) * verticesPerCone], Is.EqualTo(DebugLines.ContactCentre(path.Moves[m].To)), $"move {m} landing cone");
            Vector3 axis = c[(((2 * m) + 1) * verticesPerCone) + 1] - c[((2 * m) + 1) * verticesPerCone];
            Assert.That(Vector3.Distance(axis, path.Moves[m].To.Cone.Axis * settings.ConeLength), Is.LessThan(1e-5f), "along the landing stance's cone axis");
        }

        // From the last move on: only its arc.
        lines.Clear();
        Assert.That(lines.AddPath(path, path.Count - 1, settings).Count, Is.EqualTo(DebugLines.SegmentsFor(path.Moves[^1].Arc, settings)));
        Assert.That(lines.AddPath(path, path.Count, settings).Count, Is.Zero);
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
