using Ballistic.Planner.Tests.Support;
using Ballistic.Runtime.Hosting;

namespace Ballistic.Planner.Tests.Godot;

/// <summary>
/// The agent node re-emits every signal of its logic: each <see cref="AgentSignal"/> record has a <c>[Signal]</c> of the
/// same name (without the suffix) on <c>JumpAgent3D</c>, and the node's emitter handles it.
/// </summary>
public sealed class JumpAgentSignalsTests
{
    private const string File = "addons/ballistic/Nodes/JumpAgent3D.cs";

    [Test]
    public void EverySignalOfTheLogicIsASignalOfTheNode()
    {
        string text = System.IO.File.ReadAllText(Path.Combine(RepositoryFiles.Root, File));
        CSharpScriptClass node = CSharpScripts.Parse([(File, text)]).ClassInFile(File, "JumpAgent3D")
            ?? throw new AssertionException($"{File} declares no JumpAgent3D");
        string[] records = [.. typeof(AgentSignal).Assembly.GetTypes()
            .Where(t => t.IsSubclassOf(typeof(AgentSignal)) && !t.IsAbstract)
            .Select(t => t.Name)
            .Order(StringComparer.Ordinal)];
        Assert.That(records, Does.Contain(nameof(WalkStartedSignal)).And.Contain(nameof(WalkFinishedSignal)));
        Assert.That(node.Signals.Order(StringComparer.Ordinal), Is.EqualTo(records.Select(r => r[..^"Signal".Length])), "one [Signal] per signal record");
        foreach (string record in records)
        {
            Assert.That(text, Does.Contain($"case {record}"), $"the node emits {record}");
        }
    }
}
