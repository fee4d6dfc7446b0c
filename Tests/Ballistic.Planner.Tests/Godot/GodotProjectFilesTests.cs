using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Godot;

/// <summary>
/// The Godot files this repository ships (every <c>.tscn</c>, <c>.tres</c>, <c>plugin.cfg</c> and
/// <c>project.godot</c>, and the addon's C# scripts), checked without an engine by <see cref="GodotProjectChecker"/>.
/// </summary>
public sealed class GodotProjectFilesTests
{
    private static readonly Lazy<GodotProject> Project = new(() => GodotProject.Load(RepositoryFiles.Root));

    [Test]
    public void TheProjectHoldsTheFilesTheseTestsCheck()
    {
        GodotProject project = Project.Value;
        Assert.Multiple(() =>
        {
            Assert.That(project.FileAt("project.godot"), Is.Not.Null, "project.godot is parsed");
            Assert.That(project.Files.Where(f => f.Path.EndsWith("plugin.cfg", StringComparison.Ordinal)), Is.Not.Empty, "a plugin.cfg is parsed");
            Assert.That(project.Files.Where(f => f.Kind == GodotFileKind.Scene), Is.Not.Empty, "scenes are parsed");
            Assert.That(project.Scripts.Classes.Select(c => c.File), Has.Some.StartsWith("addons/ballistic/"), "the addon's C# classes are read");
            Assert.That(project.AllFiles, Has.None.StartsWith("Tests/Ballistic.Planner.Tests/bin/"), "build output is skipped");
            Assert.That(project.Scripts.Classes.Select(c => c.File), Has.None.StartsWith("Planner/").And.None.StartsWith("Tests/"),
                "only the Godot assembly's sources are scripts");
        });
    }

    [Test]
    public void EveryGodotTextFileParses() =>
        Assert.That(Project.Value.ParseErrors, Is.Empty, () => string.Join(Environment.NewLine, Project.Value.ParseErrors));

    [Test]
    public void EveryCSharpSourceOfTheGodotProjectParses() =>
        Assert.That(Project.Value.Scripts.SyntaxErrors, Is.Empty, () => string.Join(Environment.NewLine, Project.Value.Scripts.SyntaxErrors));

    [Test]
    public void ScenesResourcesPluginAndProjectSettingsAreSound()
    {
        IReadOnlyList<string> issues = GodotProjectChecker.Check(Project.Value);
        Assert.That(issues, Is.Empty, () => string.Join(Environment.NewLine, issues));
    }
}
