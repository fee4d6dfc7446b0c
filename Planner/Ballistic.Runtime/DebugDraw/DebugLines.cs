using System.Numerics;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;
using Ballistic.Runtime.Paths;

namespace Ballistic.Runtime.DebugDraw;

/// <summary>
/// Engine-free line geometry for debug drawing: a list of segments (world metres, Y up), each vertex with a colour,
/// filled by the drawing calls below and read as flat spans. The editor gizmo passes <see cref="Vertices"/> (or a
/// <see cref="DebugLineRange"/>'s slice of it) to <c>EditorNode3DGizmo.AddLines</c>; the runtime view feeds an
/// <c>ImmediateMesh</c> surface of <c>Mesh.PrimitiveType.Lines</c> with <c>SurfaceSetColor(Colors[i])</c> and
/// <c>SurfaceAddVertex(Vertices[i])</c>. <see cref="Clear"/> keeps the buffers, so redrawing the same scene each
/// frame allocates nothing once they have grown. Deterministic: the same calls give the same vertices. Not
/// thread-safe.
/// </summary>
public sealed class DebugLines
{
    private static readonly DebugDrawSettings Defaults = new();
    private Vector3[] _vertices;
    private DebugColor[] _colors;
    private int _segments;

    /// <summary>Creates an empty list with room for <paramref name="segments"/> segments (it grows as needed).</summary>
    public DebugLines(int segments = 256)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(segments);
        _vertices = new Vector3[Math.Max(2, 2 * segments)];
        _colors = new DebugColor[_vertices.Length];
    }

    /// <summary>Number of segments.</summary>
    public int SegmentCount => _segments;

    /// <summary>The segments' end points, two per segment: segment i runs from <c>Vertices[2i]</c> to <c>Vertices[2i + 1]</c>, world metres.</summary>
    public ReadOnlySpan<Vector3> Vertices => _vertices.AsSpan(0, 2 * _segments);

    /// <summary>The colour of each vertex (both ends of a segment share it), parallel to <see cref="Vertices"/>.</summary>
    public ReadOnlySpan<DebugColor> Colors => _colors.AsSpan(0, 2 * _segments);

    /// <summary>The vertices of the segments in <paramref name="range"/>.</summary>
    public ReadOnlySpan<Vector3> VerticesOf(DebugLineRange range) => Vertices.Slice(2 * range.First, 2 * range.Count);

    /// <summary>Removes every segment, keeping the buffers.</summary>
    public void Clear() => _segments = 0;

    /// <summary>Adds one segment from <paramref name="a"/> to <paramref name="b"/> (world metres).</summary>
    public void AddSegment(Vector3 a, Vector3 b, DebugColor color)
    {
        if (2 * (_segments + 1) > _vertices.Length)
        {
            int size = Math.Max(2 * (_segments + 1), 2 * _vertices.Length);
            Array.Resize(ref _vertices, size);
            Array.Resize(ref _colors, size);
        }

        int v = 2 * _segments;
        _vertices[v] = a;
        _vertices[v + 1] = b;
        _colors[v] = color;
        _colors[v + 1] = color;
        _segments++;
    }

    /// <summary>A cross of three axis-aligned strokes of half length <paramref name="halfSize"/> (metres) centred on <paramref name="centre"/>.</summary>
    public DebugLineRange AddCross(Vector3 centre, float halfSize, DebugColor color)
    {
        int first = _segments;
        AddSegment(centre - new Vector3(halfSize, 0f, 0f), centre + new Vector3(halfSize, 0f, 0f), color);
        AddSegment(centre - new Vector3(0f, halfSize, 0f), centre + new Vector3(0f, halfSize, 0f), color);
        AddSegment(centre - new Vector3(0f, 0f, halfSize), centre + new Vector3(0f, 0f, halfSize), color);
        return new DebugLineRange(first, 3);
    }

    /// <summary>
    /// An arc as a polyline of <see cref="SegmentsFor"/> segments whose vertices lie exactly on it
    /// (<see cref="BallisticArc.PositionAt"/> at equal time steps from takeoff to landing).
    /// </summary>
    public DebugLineRange AddArc(in BallisticArc arc, DebugColor color, DebugDrawSettings? settings = null)
    {
        settings = Checked(settings);
        int first = _segments;
        int n = SegmentsFor(arc, settings);
        Vector3 previous = arc.PositionAt(0f);
        for (int k = 1; k <= n; k++)
        {
            Vector3 next = k == n ? arc.PositionAt(arc.FlightTime) : arc.PositionAt(arc.FlightTime * k / n);
            AddSegment(previous, next, color);
            previous = next;
        }

        return new DebugLineRange(first, n);
    }

    /// <summary>
    /// A walk as the path of its trunk centre, from the first stance's trunk centre to the last's: where the trunk
    /// moves as it turns in place at either end (standing up over its contacts from a stance leaning with a slope), a
    /// straight segment; along the ground path (<see cref="Walk.PoseAtDistance(float)"/>), dashed: the path cut into an odd
    /// number of equal lengths of about <see cref="DebugDrawSettings.WalkDashLength"/>, every other one drawn as a
    /// straight segment between its ends, the first and the last included (at most
    /// <see cref="DebugDrawSettings.MaxSegmentsPerWalk"/> dashes). With a dash length of 0, a solid polyline of about
    /// <see cref="DebugDrawSettings.SegmentLength"/> segments. Every vertex lies exactly on the trunk's path.
    /// </summary>
    public DebugLineRange AddWalk(Walk walk, DebugColor color, DebugDrawSettings? settings = null)
    {
        ArgumentNullException.ThrowIfNull(walk);
        settings = Checked(settings);
        int first = _segments;
        float length = walk.Length;
        Vector3 walking = walk.PoseAtDistance(0f).Position;
        Vector3 stopped = walk.PoseAtDistance(length).Position;
        if (walk.From.Pose.Position != walking)
        {
            AddSegment(walk.From.Pose.Position, walking, color);
        }

        if (settings.WalkDashLength <= 0f)
        {
            int n = Pieces(length, settings.SegmentLength, settings.MaxSegmentsPerWalk);
            Vector3 previous = walking;
            for (int k = 1; k <= n; k++)
            {
                Vector3 next = walk.PoseAtDistance(k == n ? length : length * k / n).Position;
                AddSegment(previous, next, color);
                previous = next;
            }
        }
        else
        {
            int pieces = Pieces(length, settings.WalkDashLength, (2 * settings.MaxSegmentsPerWalk) - 1);
            pieces |= 1; // odd (at most the odd cap): dashes at both ends
            for (int k = 0; k < pieces; k += 2)
            {
                AddSegment(walk.PoseAtDistance(length * k / pieces).Position, walk.PoseAtDistance(k + 1 == pieces ? length : length * (k + 1) / pieces).Position, color);
            }
        }

        if (stopped != walk.To.Pose.Position)
        {
            AddSegment(stopped, walk.To.Pose.Position, color);
        }

        return new DebugLineRange(first, _segments - first);
    }

    /// <summary>
    /// A friction cone as a fan: its axis, then <see cref="DebugDrawSettings.ConeRays"/> rays from the apex, evenly
    /// spaced around the axis and each at the cone's half-angle atan μ from it, then the ring joining the rays' ends.
    /// Every stroke is <see cref="DebugDrawSettings.ConeLength"/> long from the apex (1 + 2 × rays segments).
    /// </summary>
    /// <param name="apex">Where the cone is drawn (a stance's contact centre), world metres.</param>
    /// <param name="cone">The cone: unit axis (world) and μ.</param>
    /// <param name="color">Colour of every stroke.</param>
    /// <param name="settings">Length and rays; defaults when <c>null</c>.</param>
    public DebugLineRange AddFrictionCone(Vector3 apex, in FrictionCone cone, DebugColor color, DebugDrawSettings? settings = null)
    {
        settings = Checked(settings);
        int first = _segments;
        Vector3 axis = cone.Axis;
        float length = settings.ConeLength;
        Vector3 helper = MathF.Abs(axis.Y) < 0.9f ? Vector3.UnitY : Vector3.UnitX;
        Vector3 e1 = Vector3.Normalize(Vector3.Cross(axis, helper));
        Vector3 e2 = Vector3.Cross(axis, e1);
        float half = cone.HalfAngle;
        float along = MathF.Cos(half);
        float across = MathF.Sin(half);
        int rays = settings.ConeRays;
        AddSegment(apex, apex + (axis * length), color);
        for (int k = 0; k < rays; k++)
        {
            AddSegment(apex, apex + (length * Ray(k)), color);
        }

        for (int k = 0; k < rays; k++)
        {
            AddSegment(apex + (length * Ray(k)), apex + (length * Ray((k + 1) % rays)), color);
        }

        return new DebugLineRange(first, 1 + (2 * rays));

        Vector3 Ray(int k)
        {
            float phi = 2f * MathF.PI * k / rays;
            return (along * axis) + (across * ((MathF.Cos(phi) * e1) + (MathF.Sin(phi) * e2)));
        }
    }

    /// <summary>
    /// A cross at each roadmap node's contact centre (<see cref="Roadmap.ContactCentres"/>), in the palette's node
    /// colour; at most <see cref="DebugDrawSettings.MaxNodes"/> nodes, evenly spaced by id (<see cref="Pick"/>).
    /// </summary>
    public DebugLineRange AddRoadmapNodes(Roadmap roadmap, DebugDrawSettings? settings = null)
    {
        ArgumentNullException.ThrowIfNull(roadmap);
        settings = Checked(settings);
        int first = _segments;
        ReadOnlySpan<Vector3> centres = roadmap.ContactCentres;
        int drawn = Math.Min(centres.Length, settings.MaxNodes);
        for (int k = 0; k < drawn; k++)
        {
            AddCross(centres[Pick(k, centres.Length, drawn)], settings.CrossHalfSize, settings.Colors.Nodes);
        }

        return new DebugLineRange(first, _segments - first);
    }

    /// <summary>
    /// Each roadmap jump's arc as a polyline, in the palette's jump colour; at most
    /// <see cref="DebugDrawSettings.MaxArcs"/> arcs, evenly spaced by edge index (<see cref="Pick"/>).
    /// </summary>
    public DebugLineRange AddRoadmapJumps(Roadmap roadmap, DebugDrawSettings? settings = null)
    {
        ArgumentNullException.ThrowIfNull(roadmap);
        settings = Checked(settings);
        int first = _segments;
        IReadOnlyList<RoadmapEdge> edges = roadmap.Edges;
        int drawn = Math.Min(edges.Count, settings.MaxArcs);
        for (int k = 0; k < drawn; k++)
        {
            AddArc(edges[Pick(k, edges.Count, drawn)].Arc, settings.Colors.Jumps, settings);
        }

        return new DebugLineRange(first, _segments - first);
    }

    /// <summary>
    /// The moves of an agent's path from move <paramref name="firstMove"/> on (the move it is in, or its next), in the
    /// palette's path colour: each jump's arc (<see cref="AddArc"/>) and each walk dashed (<see cref="AddWalk"/>).
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="firstMove"/> is negative.</exception>
    public DebugLineRange AddPath(AgentPath path, int firstMove = 0, DebugDrawSettings? settings = null)
    {
        ArgumentNullException.ThrowIfNull(path);
        ArgumentOutOfRangeException.ThrowIfNegative(firstMove);
        settings = Checked(settings);
        int first = _segments;
        IReadOnlyList<PathMove> moves = path.Moves;
        for (int m = firstMove; m < moves.Count; m++)
        {
            if (moves[m].Walk is { } walk)
            {
                AddWalk(walk, settings.Colors.Path, settings);
            }
            else
            {
                AddArc(moves[m].Arc, settings.Colors.Path, settings);
            }
        }

        return new DebugLineRange(first, _segments - first);
    }

    /// <summary>
    /// The takeoff and landing friction cones of an agent's path from move <paramref name="firstMove"/> on: for each
    /// jump its takeoff stance's cone, then its landing stance's, each at the stance's contact centre
    /// (<see cref="RoadmapNode.ContactCentre"/>), in the palette's cone colour. Walks have none.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="firstMove"/> is negative.</exception>
    public DebugLineRange AddPathCones(AgentPath path, int firstMove = 0, DebugDrawSettings? settings = null)
    {
        ArgumentNullException.ThrowIfNull(path);
        ArgumentOutOfRangeException.ThrowIfNegative(firstMove);
        settings = Checked(settings);
        int first = _segments;
        IReadOnlyList<PathMove> moves = path.Moves;
        for (int m = firstMove; m < moves.Count; m++)
        {
            PathMove move = moves[m];
            if (move.Kind != MoveKind.Jump)
            {
                continue;
            }

            AddFrictionCone(move.From.ContactCentre, move.From.Cone, settings.Colors.Cones, settings);
            AddFrictionCone(move.To.ContactCentre, move.To.Cone, settings.Colors.Cones, settings);
        }

        return new DebugLineRange(first, _segments - first);
    }

    /// <summary>A stance's friction cone at its contact centre, in the palette's cone colour.</summary>
    public DebugLineRange AddNodeCone(RoadmapNode node, DebugDrawSettings? settings = null)
    {
        ArgumentNullException.ThrowIfNull(node);
        settings = Checked(settings);
        return AddFrictionCone(node.ContactCentre, node.Cone, settings.Colors.Cones, settings);
    }

    /// <summary>
    /// Segments of an arc's polyline: its length over <see cref="DebugDrawSettings.SegmentLength"/>, rounded up,
    /// between 1 and <see cref="DebugDrawSettings.MaxSegmentsPerArc"/>.
    /// </summary>
    public static int SegmentsFor(in BallisticArc arc, DebugDrawSettings settings)
    {
        ArgumentNullException.ThrowIfNull(settings);
        float wanted = arc.ArcLength / settings.SegmentLength;
        return float.IsFinite(wanted) ? Math.Clamp((int)MathF.Ceiling(wanted), 1, settings.MaxSegmentsPerArc) : 1;
    }

    /// <summary>Pieces of about <paramref name="piece"/> metres in <paramref name="length"/> metres: rounded up, between 1 and <paramref name="max"/>.</summary>
    private static int Pieces(float length, float piece, int max)
    {
        float wanted = length / piece;
        return float.IsFinite(wanted) ? Math.Clamp((int)MathF.Ceiling(wanted), 1, max) : 1;
    }

    /// <summary>
    /// The <paramref name="k"/>-th of <paramref name="drawn"/> items chosen evenly among <paramref name="count"/>:
    /// ⌊k · count / drawn⌋ (every item when <paramref name="drawn"/> = <paramref name="count"/>).
    /// </summary>
    public static int Pick(int k, int count, int drawn) => (int)((long)k * count / drawn);

    private static DebugDrawSettings Checked(DebugDrawSettings? settings)
    {
        settings ??= Defaults;
        return settings.Problem() is { } problem ? throw new ArgumentException($"Debug draw settings: {problem}.", nameof(settings)) : settings;
    }
}
