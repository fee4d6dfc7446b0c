using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;
using Ballistic.Runtime.Paths;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>
/// The runtime with rigs and levels made the way other tools make them: every path an agent follows passes the
/// independent plan audit (contacts on the mesh, stance feet holding, no bone in the level), and every jump takes
/// off where the agent stood.
/// </summary>
public sealed class ForeignRuntimeTests
{
    [TestCase("tailed", "stairs")]
    [TestCase("human-zup", "thin-slabs")]
    [TestCase("dog", "curved")]
    public void PathsFollowedByForeignRigsPassTheAudit(string rigName, string levelName)
    {
        ForeignCharacter rig = ForeignCharacters.Named(rigName);
        string folder = Path.Combine(Path.GetTempPath(), $"ballistic-runtime-{Guid.NewGuid():N}");
        Directory.CreateDirectory(folder);
        try
        {
            (string gltf, string spec) = rig.Write(folder);
            (CharacterModel model, Ballistic.Planner.Characters.ReducedCharacter reduced) = CharacterSpecFile.Load(gltf, spec);
            (Level level, _) = ForeignLevels.Get(levelName);
            var scene = PlanningScene.Create(level, reduced);
            Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 2, MaxNodes = 250, Threads = 2 }).Roadmap;
            var kind = new CharacterKind(scene, roadmap, new JumpAnimator(scene, model));
            using var world = new JumpWorld(level, RuntimeWorlds.JumpOnly with { AnimationThreads = 2 });
            KindHandle handle = world.AddKind(kind).Kind;

            // Three agents sent across seeded pairs of connected stances at least 2 m apart.
            var random = new Random(9);
            var agents = new List<AgentHandle>();
            for (int attempt = 0; attempt < 2_000 && agents.Count < 3; attempt++)
            {
                RoadmapNode a = roadmap.Nodes[random.Next(roadmap.Nodes.Count)];
                RoadmapNode b = roadmap.Nodes[random.Next(roadmap.Nodes.Count)];
                if (Vector3.Distance(a.Pose.Position, b.Pose.Position) >= 2f && roadmap.Reaches(a.Id, b.Id) && world.AddAgent(handle, roadmap.ContactCentres[a.Id]) is { Ok: true } added)
                {
                    world.SetTarget(added.Agent, roadmap.ContactCentres[b.Id]);
                    agents.Add(added.Agent);
                }
            }

            Assert.That(agents, Has.Count.EqualTo(3), $"{rigName} on {levelName}: agents placed");
            var stoodAt = agents.ToDictionary(a => a, a => world.GetRootPose(a).Position);
            var audits = new List<AuditReport>();
            int concluded = 0;
            for (int tick = 0; tick < 60 * 120 && concluded < agents.Count; tick++)
            {
                world.Step();
                foreach (JumpEvent e in world.Events)
                {
                    switch (e.Kind)
                    {
                        case JumpEventKind.PathFound:
                            AgentPath path = world.GetPath(e.Agent)!;
                            var plan = new PlanResult(PlannerStatus.Exact, "runtime path", path.Start, path.Goal, [.. path.Moves.Select(m => new Jump(m.From, m.To, m.Arc))], TimeSpan.Zero);
                            audits.Add(PlanAudit.Check($"{rigName}/{levelName} {e.Agent}", scene, Centre(path.Start), path.Target, plan, path.Animation));
                            break;
                        case JumpEventKind.JumpStarted:
                            Assert.That(Vector3.Distance(e.From, stoodAt[e.Agent]), Is.LessThan(1e-4f), $"{e.Agent} took off away from where it stood");
                            break;
                        case JumpEventKind.Landed:
                            stoodAt[e.Agent] = e.To;
                            break;
                        case JumpEventKind.TargetReached or JumpEventKind.PathFailed:
                            concluded++;
                            break;
                    }
                }
            }

            Assert.That(audits, Is.Not.Empty, $"{rigName} on {levelName}: no path was followed");
            Assert.That(audits.Where(a => a.Violations.Count > 0).Select(a => a.ToString()), Is.Empty, "a path the runtime followed breaks an invariant");
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    private static Vector3 Centre(RoadmapNode node) =>
        node.Contacts.Aggregate(Vector3.Zero, (sum, c) => sum + c.Position) / node.Contacts.Count;
}
