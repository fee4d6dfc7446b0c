using Ballistic.Planner.Tests.Support;
using Ballistic.Runtime.Hosting;

namespace Ballistic.Planner.Tests.Godot;

/// <summary>
/// The agent node re-emits every signal of its logic: each <see cref="AgentSignalKind"/> has a <c>[Signal]</c> of the
/// same name on <c>JumpAgent3D</c>, and the node's emitter emits it under that name.
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
        string[] kinds = [.. Enum.GetNames<AgentSignalKind>().Order(StringComparer.Ordinal)];
        Assert.That(kinds, Does.Contain(nameof(AgentSignalKind.WalkStarted)).And.Contain(nameof(AgentSignalKind.WalkFinished)));
        Assert.That(node.Signals.Order(StringComparer.Ordinal), Is.EqualTo(kinds), "one [Signal] per kind of signal");
        foreach (string kind in kinds)
        {
            string[] emitted = [.. text.Split($"case AgentSignalKind.{kind}:").Skip(1).Select(rest => rest.Split("break;")[0])];
            Assert.That(emitted, Has.Length.EqualTo(1), $"the node handles {kind} once");
            Assert.That(emitted[0], Does.Contain($"EmitSignal(SignalName.{kind}"), $"the node emits {kind} as {kind}");
        }
    }
}
