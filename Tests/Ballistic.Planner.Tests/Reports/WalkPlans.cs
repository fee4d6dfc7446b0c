using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Authoring.Reports;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Reports;

/// <summary>
/// Plans on the gap course for the report tests: the jump-only plan of a small seeded bake, and the same jumps with a
/// walk before them (bent) and a walk after them (through a stance, <see cref="Walk.Via"/>), with a hand-made
/// animation over those moves (the root on the moves, rest angles, alternating foot phases while walking).
/// </summary>
internal static class WalkPlans
{
    public const float Speed = 1.2f;

    private static readonly Lazy<(PlanningScene Scene, Roadmap Roadmap, PlanResult Jumps)> Baked = new(() =>
    {
        var scene = PlanningScene.Create(GapCourse.Build(), CharacterPresets.Skeleton());
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 2, MaxNodes = 150, Threads = 2, Start = GapCourse.From, Goal = GapCourse.To }).Roadmap;
        PlanResult jumps = new PathQuery(scene, roadmap).Plan(GapCourse.From, GapCourse.To, new QuerySettings { Locomotion = Locomotion.Jump });
        Assert.That(jumps.Status, Is.EqualTo(PlannerStatus.Exact), jumps.Reason);
        return (scene, roadmap, jumps);
    });

    private static readonly Lazy<PlanResult> Walking = new(() =>
    {
        PlanResult jumps = Baked.Value.Jumps;
        RoadmapNode takeoff = jumps.Jumps[0].Takeoff;
        RoadmapNode landing = jumps.Jumps[^1].Landing;
        RoadmapNode start = Shifted(takeoff, 1000, new Vector3(-1f, 0f, 0.3f));
        RoadmapNode via = Shifted(landing, 1001, new Vector3(0.5f, 0f, 0.5f));
        RoadmapNode goal = Shifted(landing, 1002, new Vector3(0.9f, 0f, -0.2f));
        Vector3 s = start.ContactCentre;
        var first = new Walk(start, takeoff, [s, s + new Vector3(0.4f, 0f, -0.6f), takeoff.ContactCentre], Speed);
        var last = new Walk(landing, goal, [landing.ContactCentre, via.ContactCentre, goal.ContactCentre], Speed, [via]);
        return new PlanResult(PlannerStatus.Exact, "a hand-made walk and jump plan", start, goal, [first, .. jumps.Moves, last], TimeSpan.Zero);
    });

    private static readonly Lazy<JumpAnimation> Animated = new(() => Animate(Walking.Value.Moves));

    public static PlanningScene Scene => Baked.Value.Scene;

    public static Roadmap Roadmap => Baked.Value.Roadmap;

    /// <summary>The jump-only plan from <see cref="GapCourse.From"/> to <see cref="GapCourse.To"/>.</summary>
    public static PlanResult JumpOnly => Baked.Value.Jumps;

    /// <summary>Walk, the jumps of <see cref="JumpOnly"/>, walk.</summary>
    public static PlanResult WalkAndJump => Walking.Value;

    /// <summary>A hand-made animation of <see cref="WalkAndJump"/>'s moves.</summary>
    public static JumpAnimation Animation => Animated.Value;

    public static PlanReport Report(PlanResult result, JumpAnimation? animation = null) =>
        new("Scenes/levels/gap-course.glb", Scene, GapCourse.From, GapCourse.To, Roadmap.Nodes.Count, Roadmap.Edges.Count, Roadmap.Seed, 0.5, result, new Dictionary<string, double> { ["query"] = 0.01 })
        {
            Animation = animation is null ? null : new AnimationReport("models/skeleton.glb", "jumps", animation),
        };

    /// <summary>The node moved by <paramref name="by"/> (trunk and contacts), with a new id.</summary>
    public static RoadmapNode Shifted(RoadmapNode node, int id, Vector3 by) =>
        new(id, new RootPose(node.Pose.Position + by, node.Pose.Rotation), node.Cone, [.. node.Contacts.Select(c => c with { Position = c.Position + by })]);

    /// <summary>
    /// An animation over <paramref name="moves"/> made by hand: 0.2 s stances, frames every 1/30 s with the root on the
    /// moves and every angle 0, the feet alternating on the ground points of walks every 0.4 m, and each jump's
    /// takeoff and landing contacts held in the stances around it.
    /// </summary>
    public static JumpAnimation Animate(IReadOnlyList<Move> moves)
    {
        CharacterModel model = CharacterPresets.Model("skeleton");
        float[] stances = [.. Enumerable.Repeat(0.2f, moves.Count - 1)];
        var timing = new JumpAnimation(model, moves, stances, [], [], [], 0, 0);
        var frames = new List<AnimationFrame>();
        for (int f = 0; f * (1f / 30f) <= timing.Duration; f++)
        {
            float t = f / 30f;
            frames.Add(new AnimationFrame(t, timing.RootAt(t), new float[model.Rig.DofCount]));
        }

        var phases = new List<ContactPhase>();
        for (int m = 0; m < moves.Count; m++)
        {
            float start = timing.MoveStart(m);
            if (moves[m] is Walk walk)
            {
                int steps = Math.Max(1, (int)MathF.Ceiling(walk.Length / 0.4f));
                for (int k = 0; k < steps; k++)
                {
                    float d0 = walk.Length * k / steps;
                    float d1 = walk.Length * (k + 1) / steps;
                    phases.Add(new ContactPhase(k % 2, walk.PointAt(d0), start + (d0 / walk.Speed), start + (d1 / walk.Speed)));
                }
            }
            else
            {
                foreach (Contact c in moves[m].From.Contacts)
                {
                    phases.Add(new ContactPhase(c.Limb, c.Position, Math.Max(0f, start - 0.2f), start));
                }
            }
        }

        return new JumpAnimation(model, moves, stances, frames, phases, [], 0, 0);
    }
}
