using System.Reflection;
using System.Xml.Linq;
using Ballistic.Authoring.Reports;
using Ballistic.Cli;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Tests.Support;
using Ballistic.Runtime;

namespace Ballistic.Planner.Tests.Architecture;

/// <summary>
/// The libraries' layering, checked on the compiled assemblies (and their project files): the planner's, the
/// authoring library's and the runtime's namespaces form no cycle, the shipped planner uses neither the authoring
/// library nor the engine, and the authoring library does not use the command-line tool.
/// </summary>
public sealed class LayeringTests
{
    private static readonly Assembly PlannerAssembly = typeof(Aabb).Assembly;
    private static readonly Assembly AuthoringAssembly = typeof(PlanReportWriter).Assembly;
    private static readonly Assembly CliAssembly = typeof(BallisticCli).Assembly;
    private static readonly Assembly RuntimeAssembly = typeof(JumpWorld).Assembly;

    [Test]
    public void PlannerNamespacesFormNoCycle() => AssertAcyclic(PlannerAssembly);

    [Test]
    public void AuthoringNamespacesFormNoCycle() => AssertAcyclic(AuthoringAssembly);

    [Test]
    public void RuntimeNamespacesFormNoCycle() => AssertAcyclic(RuntimeAssembly);

    /// <summary>
    /// The public surface only shrinks (issue 22: a game needs about 15–20 types): a type made public again, or a new
    /// one, fails here until it is counted on purpose. Planner 74 (from 101) and runtime 61 types (NavigationStatus added) on 2026-12-01; planner 71 on
    /// 2026-12-02 (the glTF loader's exception, the output-file exception and roadmap walk records are the CLI's and the
    /// runtime's, not a game's; the loader itself stays public: a game outside Godot loads its level with it, as
    /// .ci/game does); planner 68
    /// on 2026-12-03 (Aabb, OrientedBox and Rotations are the collision checks' and the IK's geometry; the level's,
    /// triangles' and BVH's members that take or give them are internal too); planner 52 on 2026-12-05 (the level's
    /// triangles, BVH and builder, rig joints and axes, animation frames, contact phases and problems, roadmap edges,
    /// endpoint placements, steering limits, the stance-lift range, sampler and surface settings nobody passed, the
    /// repair loop's state and the roadmap file's exception: a game loads a level, raycasts it with Level.Raycast and
    /// samples an animation, it does not take them apart); helpers the
    /// tools and tests use are internal, visible to them by <c>InternalsVisibleTo</c>.
    /// </summary>
    [TestCase("planner", 52)]
    [TestCase("runtime", 61)]
    public void ThePublicSurfaceDoesNotGrow(string library, int most)
    {
        Assembly assembly = library == "planner" ? PlannerAssembly : RuntimeAssembly;
        Type[] exported = [.. assembly.GetExportedTypes().Where(t => !t.IsNested)];
        Assert.That(exported, Has.Length.LessThanOrEqualTo(most), string.Join(", ", exported.Select(t => t.Name).Order()));
    }

    [Test]
    public void PlannerUsesNeitherAuthoringNorGodot()
    {
        string authoring = AuthoringAssembly.GetName().Name!;
        bool Forbidden(string name) => name == authoring || name.StartsWith("Godot", StringComparison.OrdinalIgnoreCase);
        Assert.Multiple(() =>
        {
            Assert.That(ReferencedAssemblies(PlannerAssembly).Where(Forbidden), Is.Empty, "Ballistic.Planner references these assemblies");
            Assert.That(ProjectReferences("Planner/Ballistic.Planner/Ballistic.Planner.csproj").Where(r => r.Contains("Authoring", StringComparison.OrdinalIgnoreCase) || r.Contains("Godot", StringComparison.OrdinalIgnoreCase)), Is.Empty, "Ballistic.Planner.csproj references these");
        });
    }

    [Test]
    public void AuthoringDoesNotUseTheCli()
    {
        string[] cli = [CliAssembly.GetName().Name!, "Ballistic.Cli"];
        Assert.Multiple(() =>
        {
            Assert.That(ReferencedAssemblies(AuthoringAssembly).Where(cli.Contains), Is.Empty, "Ballistic.Authoring references these assemblies");
            Assert.That(ProjectReferences("Planner/Ballistic.Authoring/Ballistic.Authoring.csproj").Where(r => r.Contains("Ballistic.Cli", StringComparison.OrdinalIgnoreCase)), Is.Empty, "Ballistic.Authoring.csproj references these");
        });
    }

    [Test]
    public void TheCycleSearchFindsACycleAndSaysWhy()
    {
        var graph = new NamespaceGraph();
        graph.AddEdge("A", "B", "a uses b");
        graph.AddEdge("B", "C", "b uses c");
        graph.AddEdge("C", "A", "c uses a");
        graph.AddEdge("C", "D", "c uses d");
        IReadOnlyList<string>? cycle = graph.FindCycle();
        Assert.That(cycle, Is.EqualTo(new[] { "A", "B", "C", "A" }));
        Assert.That(graph.Describe(cycle!), Does.Contain("B -> C: b uses c"));
    }

    [Test]
    public void TheDependencyScanSeesCallsInsideMethodBodies()
    {
        // BodyCollision uses Rotations only inside a method body, never in a signature or field.
        Type bodyCollision = typeof(BodyCollision);
        Assert.That(TypeDependencies.Of(bodyCollision), Does.Contain(typeof(Rotations)));
    }

    private static void AssertAcyclic(Assembly assembly)
    {
        var graph = NamespaceGraph.Of(assembly);
        Assert.That(graph.Namespaces, Is.Not.Empty, "the scan found the assembly's namespaces");
        IReadOnlyList<string>? cycle = graph.FindCycle();
        Assert.That(cycle, Is.Null, () => $"{graph.Describe(cycle!)}{Environment.NewLine}Namespace graph of {assembly.GetName().Name}:{Environment.NewLine}{graph}");
    }

    /// <summary>Every assembly <paramref name="assembly"/> references, in its metadata or through the types its types use.</summary>
    private static SortedSet<string> ReferencedAssemblies(Assembly assembly)
    {
        var names = new SortedSet<string>(assembly.GetReferencedAssemblies().Select(a => a.Name!), StringComparer.Ordinal);
        foreach (Type type in TypeDependencies.AllTypes(assembly))
        {
            foreach (Type used in TypeDependencies.Of(type))
            {
                names.Add(used.Assembly.GetName().Name!);
            }
        }

        return names;
    }

    /// <summary>The project and package references of a project file of this repository.</summary>
    private static IEnumerable<string> ProjectReferences(string project) =>
        XDocument.Load(Path.Combine(RepositoryFiles.Root, project))
            .Descendants()
            .Where(e => e.Name.LocalName is "ProjectReference" or "PackageReference")
            .Select(e => (string?)e.Attribute("Include") ?? string.Empty)
            .ToList();
}
