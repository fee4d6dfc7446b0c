using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>The bundled desert with a baked skeleton roadmap, shared by the runtime tests, and helpers to drive worlds.</summary>
internal static class RuntimeWorlds
{
    private static readonly Lazy<CharacterKind> DesertSkeletonKind = new(() =>
    {
        Level level = SharedLevels.Bundled("desert");
        var scene = PlanningScene.Create(level, CharacterPresets.Skeleton());
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 3, MaxNodes = 300, Threads = 2, Locomotion = Locomotion.WalkAndJump }).Roadmap;
        return new CharacterKind(scene, roadmap, new JumpAnimator(scene, CharacterPresets.Model("skeleton")));
    });

    /// <summary>The skeleton on the desert: scene, 300-node roadmap (seed 3) and animator.</summary>
    public static CharacterKind DesertSkeleton => DesertSkeletonKind.Value;

    /// <summary>
    /// The settings of the jump tests' worlds: one thread, and jumps only, so that their paths are the jump sequences
    /// they check whatever the planner makes of walking (walks are tested with hand-made paths, <see cref="WalkingPaths"/>).
    /// </summary>
    public static WorldSettings JumpOnly { get; } = new() { AnimationThreads = 0, Locomotion = Locomotion.Jump, MaxAnimationWait = null };

    /// <summary>A world on the desert with the skeleton kind added (<see cref="JumpOnly"/> settings unless given).</summary>
    public static (JumpWorld World, KindHandle Kind) Desert(WorldSettings? settings = null)
    {
        var world = new JumpWorld(DesertSkeleton.Scene.Level, settings ?? JumpOnly);
        AddKindResult added = world.AddKind(DesertSkeleton);
        Assert.That(added.Ok, Is.True, added.Result.ToString());
        return (world, added.Kind);
    }

    /// <summary>The contact centre of a node of the desert roadmap: where a user would click to stand there.</summary>
    public static Vector3 Point(RoadmapNode node) => DesertSkeleton.Roadmap.ContactCentres[node.Id];

    /// <summary>Adds an agent on the start of the seeded connected pair and sends it to the pair's goal.</summary>
    public static (AgentHandle Agent, RoadmapNode From, RoadmapNode To) SendAcross(JumpWorld world, KindHandle kind, int seed)
    {
        (RoadmapNode from, RoadmapNode to) = ConnectedPairs(DesertSkeleton.Roadmap, 1, seed)[0];
        AddAgentResult added = world.AddAgent(kind, Point(from));
        Assert.That(added.Ok, Is.True, added.Result.ToString());
        Assert.That(world.SetTarget(added.Agent, Point(to)).Ok, Is.True);
        return (added.Agent, from, to);
    }

    /// <summary>True once the events seen hold an arrival or a failure.</summary>
    public static bool Concluded(JumpWorld world, IReadOnlyList<JumpEvent> seen) =>
        seen.Any(e => e.Kind is JumpEventKind.TargetReached or JumpEventKind.PathFailed);

    /// <summary>Seeded pairs of roadmap nodes (start, goal) where the start reaches the goal, at least <paramref name="minDistance"/> apart.</summary>
    public static List<(RoadmapNode From, RoadmapNode To)> ConnectedPairs(Roadmap roadmap, int count, int seed, float minDistance = 4f)
    {
        var random = new Random(seed);
        var pairs = new List<(RoadmapNode, RoadmapNode)>();
        for (int attempt = 0; attempt < 10_000 && pairs.Count < count; attempt++)
        {
            RoadmapNode a = roadmap.Nodes[random.Next(roadmap.Nodes.Count)];
            RoadmapNode b = roadmap.Nodes[random.Next(roadmap.Nodes.Count)];
            if (Vector3.Distance(a.Pose.Position, b.Pose.Position) >= minDistance && roadmap.Reaches(a.Id, b.Id))
            {
                pairs.Add((a, b));
            }
        }

        return pairs;
    }

    /// <summary>Steps until <paramref name="done"/> holds after a tick or <paramref name="maxTicks"/> pass; returns every event seen.</summary>
    public static List<JumpEvent> Run(JumpWorld world, int maxTicks, Func<JumpWorld, IReadOnlyList<JumpEvent>, bool>? done = null, Action<JumpWorld>? afterTick = null)
    {
        var seen = new List<JumpEvent>();
        for (int i = 0; i < maxTicks; i++)
        {
            world.Step();
            seen.AddRange(world.Events.ToArray());
            afterTick?.Invoke(world);
            if (done?.Invoke(world, seen) == true)
            {
                break;
            }
        }

        return seen;
    }
}
