using System.Xml.Linq;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Godot;

/// <summary>
/// The Godot project's C# compiles, as far as it can be judged without GodotSharp (<see cref="AddonCompilation"/>), the
/// way a Godot game compiles it: no implicit usings, nullable off at project level, C# 12. Each kind of mistake the last
/// compile against the real Godot API found is planted once to show the check catches it.
/// </summary>
public sealed class AddonCompilationTests
{
    [TestCase(true, TestName = "The addon and scenes have no problem of our own in an editor build")]
    [TestCase(false, TestName = "The addon and scenes have no problem of our own in an exported game")]
    public void TheAddonHasNoProblemOfOurOwn(bool editor)
    {
        AddonCompilation compilation = AddonCompilation.OfRepository(editor);
        IReadOnlyList<string> problems = compilation.Problems();
        foreach (string problem in problems)
        {
            TestContext.Out.WriteLine(problem);
        }

        Assert.Multiple(() =>
        {
            Assert.That(compilation.Files, Has.Some.StartsWith("addons/ballistic/Nodes/").And.Some.StartsWith("Scenes/"));
            Assert.That(problems, Is.Empty);
        });
    }

    [Test]
    public void TheGodotProjectStatesItsImports()
    {
        XElement project = XDocument.Load(Path.Combine(RepositoryFiles.Root, "Ballistic.csproj")).Root!;
        string? implicitUsings = project.Descendants("ImplicitUsings").LastOrDefault()?.Value;
        Assert.Multiple(() =>
        {
            Assert.That(implicitUsings, Is.EqualTo("disable"), "Ballistic.csproj turns implicit usings off, as Godot's template has them");
            Assert.That(project.Descendants("Using"), Is.Empty, "no global usings through the project file");
            foreach (string file in AddonCompilation.OfRepository(editor: true).Files)
            {
                string text = File.ReadAllText(Path.Combine(RepositoryFiles.Root, file));
                Assert.That(text, Does.Not.Contain("global using"), file);
                Assert.That(text.Split('\n').Select(l => l.TrimEnd('\r')), Does.Contain("#nullable enable"),
                    $"{file}: a game's project has nullable off by default; the file turns it on for itself");
            }
        });
    }

    [Test]
    public void ANameOfBothGodotAndSystemIsReportedAsTheRealBuildWould()
    {
        IReadOnlyList<string> problems = AddonCompilation.Of([("addons/x/Loader.cs", """
            #nullable enable
            using System.IO;
            using Godot;

            namespace X;

            /// <summary>Reads with <see cref="FileAccess"/>.</summary>
            public static class Loader
            {
                public static byte[] Read(string path) => FileAccess.GetFileAsBytes(path);

                public static byte[] Fine(string path) => Godot.FileAccess.GetFileAsBytes(path);
            }
            """)], editor: false).Problems();
        Assert.Multiple(() =>
        {
            Assert.That(problems, Has.Member("addons/x/Loader.cs:7: CS0419: 'FileAccess' is ambiguous between 'Godot.FileAccess' and 'System.IO.FileAccess' (qualify it or alias it)"));
            Assert.That(problems, Has.Member("addons/x/Loader.cs:10: CS0104: 'FileAccess' is ambiguous between 'Godot.FileAccess' and 'System.IO.FileAccess' (qualify it or alias it)"));
            Assert.That(problems, Has.None.Contains(":12:"), "a qualified name is not ambiguous");
        });
    }

    /// <summary>
    /// A type internal to the Ballistic libraries used by the addon is reported (the addon read its version off the
    /// planner's Aabb, made internal in the public-surface cut; the real build still compiled it only because the
    /// game's assembly name matches the CLI's InternalsVisibleTo), and a public one beside it is not.
    /// </summary>
    [Test]
    public void ATypeInternalToTheLibrariesIsReported() =>
        AssertReportedBesideAPublicUse("addons/x/Info.cs", """
            #nullable enable
            using System.Reflection;
            using Ballistic.Planner.Geometry;

            namespace X;

            /// <summary>Versions.</summary>
            public static class Info
            {
                public static Assembly Internal => typeof(Aabb).Assembly;

                public static Assembly Public => typeof(RootPose).Assembly;
            }
            """,
            "addons/x/Info.cs:10: CS0122: 'Aabb' is internal to the Ballistic libraries: the addon sees only their public types",
            publicLine: 12,
            "RootPose is public");

    /// <summary>
    /// A member internal to the Ballistic libraries (the level's bounds) used by a node script that imports Godot is
    /// reported (Godot's unknown extension methods excuse a missing member on other types there, not on ours), and a
    /// public one beside it is not.
    /// </summary>
    [Test]
    public void AMemberInternalToTheLibrariesIsReportedInAGodotScript() =>
        AssertReportedBesideAPublicUse("addons/x/Bounds.cs", """
            #nullable enable
            using Ballistic.Planner.Levels;
            using Godot;

            namespace X;

            /// <summary>Level facts.</summary>
            public partial class Bounds : Node
            {
                public static object Box(Level level) => level.Bounds;

                public static int Count(Level level) => level.MaterialIndices.Count;
            }
            """,
            "addons/x/Bounds.cs:10: CS1061: 'Bounds' is no public member of Ballistic.Planner.Levels.Level: the addon sees only the Ballistic libraries' public API",
            publicLine: 12,
            "Level.MaterialIndices is public");

    /// <summary>
    /// Compiles one planted addon file (an export build) and asserts that its use of something internal to the
    /// Ballistic libraries is reported as <paramref name="expected"/> and that the public use on line
    /// <paramref name="publicLine"/> is not reported.
    /// </summary>
    private static void AssertReportedBesideAPublicUse(string path, string source, string expected, int publicLine, string because)
    {
        IReadOnlyList<string> problems = AddonCompilation.Of([(path, source)], editor: false).Problems();
        Assert.Multiple(() =>
        {
            Assert.That(problems, Has.Member(expected));
            Assert.That(problems, Has.None.Contains($":{publicLine}:"), because);
        });
    }

    [Test]
    public void AnAliasOrAGlobalUsingIsFollowed()
    {
        IReadOnlyList<string> aliased = AddonCompilation.Of([("a/A.cs", """
            #nullable enable
            using System;
            using Godot;
            using Environment = System.Environment;

            public static class A
            {
                public static int Cores => Math.Max(1, Environment.ProcessorCount);
            }
            """)], editor: false).Problems();
        IReadOnlyList<string> global = AddonCompilation.Of(
            [("a/Usings.cs", "global using Godot;\n"), ("a/B.cs", "#nullable enable\nusing System;\npublic static class B { public static int Cores => Environment.ProcessorCount; }\n")],
            editor: false).Problems();
        Assert.Multiple(() =>
        {
            Assert.That(aliased, Is.Empty);
            Assert.That(global, Is.EqualTo(new[] { "a/B.cs:3: CS0104: 'Environment' is ambiguous between 'Godot.Environment' and 'System.Environment' (qualify it or alias it)" }));
        });
    }

    [Test]
    public void AVoidMethodUsedAsAValueIsReported()
    {
        IReadOnlyList<string> problems = AddonCompilation.Of(
        [
            ("addons/x/Roadmap.cs", "#nullable enable\nusing Godot;\nnamespace X;\npublic partial class Roadmap : Node3D { public void BakeRoadmap(bool onThread = true) { } }\n"),
            ("addons/x/Toolbar.cs", "#nullable enable\nusing Godot;\nnamespace X;\npublic partial class Toolbar : HBoxContainer\n{\n    public Roadmap? Roadmap { get; set; }\n    private void OnBake()\n    {\n        if (Roadmap!.BakeRoadmap(onThread: true) is { Length: > 0 } refused) { GD.Print(refused); }\n    }\n}\n"),
        ], editor: true).Problems();
        Assert.That(problems, Has.Some.StartsWith("addons/x/Toolbar.cs:9: CS8117: "));
    }

    [Test]
    public void AMissingSystemUsingAndANullableAnnotationWithoutContextAreReported()
    {
        IReadOnlyList<string> problems = AddonCompilation.Of([("addons/x/Lines.cs", """
            using Godot;

            public static class Lines
            {
                public static string? Name;

                public static int Count(ReadOnlySpan<Vector3> points) => points.Length;
            }
            """)], editor: false).Problems();
        Assert.Multiple(() =>
        {
            Assert.That(problems, Has.Some.StartsWith("addons/x/Lines.cs:5: CS8632: "));
            Assert.That(problems, Has.Some.EqualTo("addons/x/Lines.cs:7: CS0246: 'ReadOnlySpan' is .NET's (System): the file needs a using directive (there are no implicit usings in a Godot project)"));
            Assert.That(problems, Has.None.Contains("'Vector3'"), "Vector3 is Godot's here");
        });
    }

    [Test]
    public void AUsingNeededOnlyInTheEditorBuildIsReportedInTheExportBuild()
    {
        (string, string)[] sources = [("addons/x/Tool.cs", "#nullable enable\nusing System.Collections.Generic;\n\npublic static class Tool\n{\n#if TOOLS\n    public static List<int> Items { get; } = [];\n#endif\n}\n")];
        Assert.Multiple(() =>
        {
            Assert.That(AddonCompilation.Of(sources, editor: true).Problems(), Is.Empty);
            Assert.That(AddonCompilation.Of(sources, editor: false).Problems(), Is.EqualTo(new[] { "addons/x/Tool.cs:2: IDE0005: unnecessary using directive (using System.Collections.Generic;) in this build" }));
        });
    }

    [Test]
    public void CSharp13IsNotAvailableToAGameOnNet8()
    {
        IReadOnlyList<string> problems = AddonCompilation.Of([("addons/x/Lock.cs", "#nullable enable\npublic static class Esc { public const char E = '\\e'; }\n")], editor: false).Problems();
        Assert.That(problems, Has.Some.Contains("CS8652").Or.Some.Contains("C# 12"));
    }
}
