using System.Xml.Linq;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Godot;

/// <summary>
/// The two builds that share this checkout stay apart: <c>dotnet test</c> at the root builds <c>Ballistic.slnx</c>
/// (engine-free projects only, never the Godot project), and the Godot project does not compile the planner's or the
/// tests' sources.
/// </summary>
public sealed class GodotBuildLayoutTests
{
    private static string Root => RepositoryFiles.Root;

    [Test]
    public void TheRootCommandLineBuildIsTheSolutionNotTheGodotProject()
    {
        // MSBuild, given a folder with one solution and one project of the same base name, builds the solution.
        string[] solutions = Directory.GetFiles(Root, "*.sln").Concat(Directory.GetFiles(Root, "*.slnx")).Select(Path.GetFileName).ToArray()!;
        string[] projects = Directory.GetFiles(Root, "*.*proj").Select(Path.GetFileName).ToArray()!;
        Assert.Multiple(() =>
        {
            Assert.That(solutions, Is.EqualTo(new[] { "Ballistic.slnx" }));
            Assert.That(projects, Is.EqualTo(new[] { "Ballistic.csproj" }));
            Assert.That(XDocument.Load(Path.Combine(Root, "Ballistic.slnx")).Descendants("Project").Select(p => (string?)p.Attribute("Path")),
                Has.None.EqualTo("Ballistic.csproj").And.All.StartWith("Planner/").Or.StartWith("Tests/"));
        });
    }

    [Test]
    public void TheGodotProjectCompilesNeitherThePlannerNorTheTests()
    {
        string excludes = XDocument.Load(Path.Combine(Root, "Ballistic.csproj")).Descendants("DefaultItemExcludes").Single().Value;
        Assert.That(excludes.Split(';'), Does.Contain("Planner/**").And.Contain("Tests/**"));
    }

    [Test]
    public void TheTestsCompileNoGodotSource()
    {
        XDocument project = XDocument.Load(Path.Combine(Root, "Tests/Ballistic.Planner.Tests/Ballistic.Planner.Tests.csproj"));
        string[] includes = project.Descendants().Where(e => e.Name.LocalName is "Compile" or "ProjectReference")
            .Select(e => (string?)e.Attribute("Include") ?? "").ToArray();
        Assert.Multiple(() =>
        {
            Assert.That(includes, Has.None.Contains("addons").And.None.Contains("Scenes").And.None.Contains("Ballistic.csproj"));
            Assert.That(project.Descendants("PackageReference").Select(p => (string?)p.Attribute("Include")), Has.None.StartWith("Godot"));
        });
    }

    [Test]
    public void TheGodotProjectIsTheOneTheEditorBuilds()
    {
        GodotFile settings = GodotFile.Load(Path.Combine(Root, "project.godot"), "project.godot");
        string sdk = (string)XDocument.Load(Path.Combine(Root, "Ballistic.csproj")).Root!.Attribute("Sdk")!;
        Assert.Multiple(() =>
        {
            Assert.That(settings.Section("dotnet")!.Property("project/assembly_name")!.Value.AsString(), Is.EqualTo("Ballistic"));
            Assert.That(sdk, Does.Match("^Godot\\.NET\\.Sdk/4\\.7\\.[0-9]+$"));
            Assert.That(settings.Section("application")!.Property("config/features")!.Value.Strings(), Does.Contain("4.7").And.Contain("C#"));
        });
    }
}
