using System.Numerics;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>
/// Hand-made paths with walks for the runtime tests, until the planner makes them: a walk onto the takeoff of a jump
/// of the desert roadmap, the jump, and a walk with a corner from its landing; and the desert skeleton kind whose
/// paths are animated by <see cref="SimpleMoveAnimator"/>.
/// </summary>
internal static class WalkingPaths
{
    /// <summary>Speed of the first walk, m/s.</summary>
    public const float FirstSpeed = 1.25f;

    /// <summary>Speed of the last walk, m/s.</summary>
    public const float LastSpeed = 0.9f;

    private static readonly Lazy<CharacterKind> WalkingKind = new(() =>
    {
        CharacterKind desert = RuntimeWorlds.DesertSkeleton;
        return new CharacterKind(desert.Scene, desert.Roadmap, desert.Animator, new SimpleMoveAnimator(desert.Animator));
    });

    /// <summary>The desert skeleton (same scene, roadmap and animator) with its paths animated by <see cref="SimpleMoveAnimator"/>.</summary>
    public static CharacterKind Kind => WalkingKind.Value;

    /// <summary>A world on the desert with <see cref="Kind"/> added, ticking on one thread.</summary>
    public static (JumpWorld World, KindHandle Kind) World(WorldSettings? settings = null)
    {
        var world = new JumpWorld(Kind.Scene.Level, settings ?? new WorldSettings { AnimationThreads = 0, Locomotion = Locomotion.WalkAndJump });
        AddKindResult added = world.AddKind(Kind);
        Assert.That(added.Ok, Is.True, added.Result.ToString());
        return (world, added.Kind);
    }

    /// <summary>
    /// Adds <paramref name="count"/> agents, the i-th performing <see cref="WalkJumpWalk"/>(i), each walk's code used
    /// once (so that a measure after it sees none of its first-use costs).
    /// </summary>
    public static List<AgentHandle> SetOff(JumpWorld world, KindHandle kind, int count)
    {
        var agents = new List<AgentHandle>();
        for (int i = 0; i < count; i++)
        {
            IReadOnlyList<Move> moves = WalkJumpWalk(i);
            AgentHandle agent = world.AddAgent(kind, Centre(moves[0].To)).Agent;
            Assert.That(world.PerformMoves(agent, moves).Ok, Is.True);
            agents.Add(agent);
            ((Walk)moves[0]).PoseAt(0.3f);
        }

        return agents;
    }

    /// <summary>
    /// Walk → jump → walk around the <paramref name="which"/>-th jump of the desert roadmap that leaves and lands on
    /// level ground more than a metre across: a 1.6 m straight walk onto its takeoff, the roadmap's jump, then a walk
    /// with one corner from its landing (ground points at the stances' contact centres, so the body point walks the
    /// ground path itself).
    /// </summary>
    public static IReadOnlyList<Move> WalkJumpWalk(int which = 0)
    {
        Roadmap roadmap = RuntimeWorlds.DesertSkeleton.Roadmap;
        RoadmapEdge edge = roadmap.Edges.Where(e =>
            roadmap.Nodes[e.From].Cone.Axis.Y > 0.97f && roadmap.Nodes[e.To].Cone.Axis.Y > 0.97f &&
            Horizontal(roadmap.Nodes[e.To].Pose.Position - roadmap.Nodes[e.From].Pose.Position).Length() > 1f).Skip(which).First();
        RoadmapNode takeoff = roadmap.Nodes[edge.From];
        RoadmapNode landing = roadmap.Nodes[edge.To];
        Vector3 d = Vector3.Normalize(Horizontal(landing.Pose.Position - takeoff.Pose.Position));
        Vector3 side = Vector3.Cross(Vector3.UnitY, d);
        RoadmapNode start = Shift(takeoff, -1.6f * d);
        RoadmapNode end = Shift(landing, (1.4f * d) + (0.9f * side));
        Vector3 corner = Centre(landing) + (1.0f * d) + (0.1f * side);
        var first = new Walk(start, takeoff, [Centre(start), Centre(takeoff)], FirstSpeed);
        var last = new Walk(landing, end, [Centre(landing), corner, Centre(end)], LastSpeed);
        return [first, new Jump(takeoff, landing, edge.Arc), last];
    }

    /// <summary>The mean of a stance's contact positions, world metres.</summary>
    public static Vector3 Centre(RoadmapNode node) => node.Contacts.Aggregate(Vector3.Zero, (s, c) => s + c.Position) / node.Contacts.Count;

    /// <summary>The distance from <paramref name="point"/> to the polyline through <paramref name="points"/>, metres.</summary>
    public static float DistanceToPolyline(Vector3 point, IReadOnlyList<Vector3> points)
    {
        float best = float.PositiveInfinity;
        for (int i = 1; i < points.Count; i++)
        {
            Vector3 a = points[i - 1];
            Vector3 ab = points[i] - a;
            float u = Math.Clamp(Vector3.Dot(point - a, ab) / ab.LengthSquared(), 0f, 1f);
            best = MathF.Min(best, Vector3.Distance(point, a + (u * ab)));
        }

        return best;
    }

    /// <summary>A copy of <paramref name="node"/> moved by <paramref name="by"/> (pose and contacts), off the roadmap (id −1).</summary>
    private static RoadmapNode Shift(RoadmapNode node, Vector3 by) =>
        new(-1, new RootPose(node.Pose.Position + by, node.Pose.Rotation), node.Cone, [.. node.Contacts.Select(c => c with { Position = c.Position + by })]);

    private static Vector3 Horizontal(Vector3 v) => new(v.X, 0f, v.Z);
}
