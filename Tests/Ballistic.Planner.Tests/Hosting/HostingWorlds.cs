using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;
using Ballistic.Planner.Tests.Runtime;
using Ballistic.Planner.Tests.Support;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Hosting;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Planner.Tests.Hosting;

/// <summary>Kinds, server-like worlds and drivers for the hosting tests: the runtime's desert skeleton, a rebake of it, and a kind on another level.</summary>
internal static class HostingWorlds
{
    private static readonly Lazy<CharacterKind> DesertRebakeKind = new(() =>
    {
        CharacterKind desert = RuntimeWorlds.DesertSkeleton;
        Roadmap roadmap = new RoadmapBaker(desert.Scene).Bake(new BakeSettings { Seed = 8, MaxNodes = 250, Threads = 2 }).Roadmap;
        return new CharacterKind(desert.Scene, roadmap, desert.Animator);
    });

    private static readonly Lazy<CharacterKind> GapKind = new(() =>
    {
        var scene = PlanningScene.Create(GapCourse.Build(), CharacterPresets.Skeleton());
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 1, MaxNodes = 30, Threads = 2 }).Roadmap;
        return new CharacterKind(scene, roadmap, new JumpAnimator(scene, CharacterPresets.Model("skeleton")));
    });

    /// <summary>The desert skeleton of the runtime tests (300 nodes, seed 3).</summary>
    public static CharacterKind Desert => RuntimeWorlds.DesertSkeleton;

    /// <summary>The same scene and animator with another roadmap (seed 8, 250 nodes): a rebake.</summary>
    public static CharacterKind DesertRebaked => DesertRebakeKind.Value;

    /// <summary>The skeleton on the gap course: another level.</summary>
    public static CharacterKind Gap => GapKind.Value;

    /// <summary>The runtime's tolerance: how close a stance's contact centre comes to a point asked for.</summary>
    public static EndpointTolerance Tolerance => new WorldSettings().Tolerance;

    /// <summary>
    /// A world as the Godot server makes it (no level until a kind gets a roadmap), ticking on one thread
    /// (deterministic, no background animation), its paths jumps only (<see cref="RuntimeWorlds.JumpOnly"/>).
    /// </summary>
    public static JumpWorld Server() => new(RuntimeWorlds.JumpOnly);

    /// <summary>A server-like world with one desert kind, created without a roadmap and then given it, as a <c>JumpRoadmap3D</c> node does.</summary>
    public static (JumpWorld World, KindHandle Kind) DesertServer()
    {
        JumpWorld world = Server();
        KindHandle kind = world.CreateKind("desert");
        RuntimeResult set = world.ReplaceKind(kind, Desert);
        Assert.That(set.Ok, Is.True, set.ToString());
        return (world, kind);
    }

    /// <summary>True when <paramref name="point"/> lies within the runtime's tolerance of <paramref name="target"/> (across and up/down).</summary>
    public static bool WithinTolerance(Vector3 point, Vector3 target)
    {
        EndpointTolerance t = Tolerance;
        return new Vector2(point.X - target.X, point.Z - target.Z).Length() <= t.Across + 1e-4f && MathF.Abs(point.Y - target.Y) <= t.UpDown + 1e-4f;
    }

    /// <summary>Steps the world and reads the agents' events each tick until <paramref name="done"/> or <paramref name="maxTicks"/>; returns each agent's events.</summary>
    public static Dictionary<AgentHandle, List<JumpEvent>> Run(JumpWorld world, IReadOnlyList<AgentHandle> agents, int maxTicks, Func<Dictionary<AgentHandle, List<JumpEvent>>, bool> done)
    {
        var seen = agents.ToDictionary(a => a, _ => new List<JumpEvent>());
        for (int i = 0; i < maxTicks; i++)
        {
            world.Step();
            foreach (AgentHandle agent in agents)
            {
                seen[agent].AddRange(world.EventsOf(agent).ToArray());
            }

            if (done(seen))
            {
                break;
            }
        }

        return seen;
    }

    /// <summary>Steps the world and updates the logics each tick until <paramref name="done"/> holds or <paramref name="maxTicks"/> pass; returns every signal of <paramref name="logic"/>.</summary>
    public static List<AgentSignal> Run(JumpAgentLogic logic, int maxTicks, Func<List<AgentSignal>, bool> done, Action? afterTick = null)
    {
        var seen = new List<AgentSignal>();
        for (int i = 0; i < maxTicks; i++)
        {
            logic.World.Step();
            seen.AddRange(logic.Update());
            afterTick?.Invoke();
            if (done(seen))
            {
                break;
            }
        }

        return seen;
    }

    /// <summary>True once the signals hold a navigation finish.</summary>
    public static bool Finished(List<AgentSignal> seen) => seen.Any(s => s.Kind == AgentSignalKind.NavigationFinished);

    /// <summary>Seeded pairs of desert nodes whose planned path (on the roadmap alone) has exactly <paramref name="jumps"/> jumps.</summary>
    public static List<(RoadmapNode From, RoadmapNode To)> PairsWithJumps(int jumps, int count, int seed)
    {
        Roadmap roadmap = Desert.Roadmap;
        var query = new Planner.Query.PathQuery(Desert.Scene, roadmap);
        var pairs = new List<(RoadmapNode, RoadmapNode)>();
        foreach ((RoadmapNode from, RoadmapNode to) in RuntimeWorlds.ConnectedPairs(roadmap, 400, seed, minDistance: 1f))
        {
            if (roadmap.FindNode(RuntimeWorlds.Point(from), Tolerance) == from.Id && roadmap.FindNode(RuntimeWorlds.Point(to), Tolerance) == to.Id &&
                query.Plan(from, to, new Planner.Query.QuerySettings { Locomotion = Planner.Planning.Locomotion.Jump }).Moves.Count == jumps)
            {
                pairs.Add((from, to));
                if (pairs.Count == count)
                {
                    break;
                }
            }
        }

        return pairs;
    }
}
