using System.Numerics;
using System.Reflection;
using System.Runtime.Loader;
using System.Text.RegularExpressions;
using Ballistic.Planner.Tests.Runtime;
using Ballistic.Planner.Tests.Support;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;

namespace Ballistic.Planner.Tests.Readme;

/// <summary>
/// The README's ECS example (a game component, a system inserted between locomotion and pose, a query, the command
/// buffer) is code that compiles against the runtime as a game project sees it, and does what the README says when run.
/// </summary>
public sealed partial class ReadmeEcsExampleTests
{
    [Test]
    public void TheReadmesEcsExampleCompilesAndTiresJumpingAgentsUntilTheyStop()
    {
        string readme = File.ReadAllText(Path.Combine(RepositoryFiles.Root, "README.md"));
        Match block = EcsBlock().Match(readme);
        Assert.That(block.Success, Is.True, "the README's ECS block (the csharp block declaring TireSystem)");

        string[] platform = ((string)AppContext.GetData("TRUSTED_PLATFORM_ASSEMBLIES")!).Split(Path.PathSeparator);
        MetadataReference[] references = [.. platform.Append(typeof(JumpWorld).Assembly.Location).Append(typeof(global::Ballistic.Planner.Geometry.RootPose).Assembly.Location)
            .Distinct().Select(p => MetadataReference.CreateFromFile(p))];
        var compilation = CSharpCompilation.Create(
            "ReadmeEcs",
            [CSharpSyntaxTree.ParseText(block.Groups["code"].Value, new CSharpParseOptions(LanguageVersion.CSharp12))],
            references,
            new CSharpCompilationOptions(OutputKind.DynamicallyLinkedLibrary, nullableContextOptions: NullableContextOptions.Enable, generalDiagnosticOption: ReportDiagnostic.Error));
        using var image = new MemoryStream();
        Microsoft.CodeAnalysis.Emit.EmitResult emitted = compilation.Emit(image);
        Assert.That(emitted.Diagnostics.Where(d => d.Severity >= DiagnosticSeverity.Warning).Select(d => d.ToString()), Is.Empty);

        // Run it: the setup inserts the system after locomotion; the agent's stamina drains only while it jumps, and
        // once it is spent the recorded ClearTarget stops the agent.
        image.Position = 0;
        var context = new AssemblyLoadContext("readme-ecs", isCollectible: true);
        try
        {
            Assembly example = context.LoadFromStream(image);
            (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert();
            using (world)
            {
                AgentHandle npc = RuntimeWorlds.SendAcross(world, kind, seed: 11).Agent;
                example.GetType("Game")!.GetMethod("Setup")!.Invoke(null, [world, npc, 0.5f]);
                Assert.That(world.Systems.Select(s => s.GetType().Name), Is.EqualTo(new[] { "BuiltInSystem", "BuiltInSystem", "TireSystem", "BuiltInSystem", "BuiltInSystem" }));
                Assert.That(world.Systems[1], Is.SameAs(world.LocomotionSystem));

                int jumpingTicks = 0;
                long cleared = 0;
                int planned = 0;
                List<JumpEvent> seen = RuntimeWorlds.Run(world, 2400, (w, _) => cleared > 0 && w.GetPath(npc) is null, w =>
                {
                    jumpingTicks += (AgentStates.Jumping & (AgentStates)(1 << (int)w.GetState(npc))) != 0 ? 1 : 0;
                    cleared = cleared == 0 && w.GetTarget(npc) is null ? w.Tick : cleared;
                    planned = Math.Max(planned, w.GetPath(npc)?.JumpCount ?? 0);
                });
                Assert.That(cleared, Is.GreaterThan(0), "the stamina ran out and the recorded ClearTarget stopped the agent");
                Assert.That(seen.Where(e => e.Kind == JumpEventKind.TargetReached), Is.Empty, "stopped before its target");
                Assert.That(jumpingTicks, Is.GreaterThanOrEqualTo(30), "half a second of jumping before it tired");
                Assert.That(seen.Where(e => e.Kind == JumpEventKind.JumpStarted && e.Tick > cleared), Is.Empty, "no takeoff once tired");
                int started = seen.Count(e => e.Kind == JumpEventKind.JumpStarted);
                Assert.That(started, Is.InRange(1, planned - 1), $"it took off {started} times of the {planned} jumps planned");

                // Spawned through the command buffer toward a point off the level: added on the next tick, then
                // stranded (its path failed), which the polled count sees.
                Type game = example.GetType("Game")!;
                Vector3 at = RuntimeWorlds.Point(RuntimeWorlds.DesertSkeleton.Roadmap.Nodes[2]);
                game.GetMethod("Spawn")!.Invoke(null, [world, kind, at, new Vector3(500f, 0f, 500f)]);
                Assert.That((int)game.GetMethod("Stranded")!.Invoke(null, [world])!, Is.Zero);
                List<JumpEvent> spawned = RuntimeWorlds.Run(world, 600, (_, events) => events.Any(e => e.Kind == JumpEventKind.PathFailed));
                JumpEvent added = spawned.Single(e => e.Kind == JumpEventKind.Added);
                Assert.That(added.From, Is.EqualTo(at));
                Assert.That(spawned.Single(e => e.Kind == JumpEventKind.PathFailed).Agent, Is.EqualTo(added.Agent), "the target recorded on the pending handle reached the spawned agent");
                Assert.That((int)game.GetMethod("Stranded")!.Invoke(null, [world])!, Is.EqualTo(1));
            }
        }
        finally
        {
            context.Unload();
        }
    }

    [GeneratedRegex(@"```csharp\n(?<code>(?:(?!```)[\s\S])*?class TireSystem[\s\S]*?)```")]
    private static partial Regex EcsBlock();
}
