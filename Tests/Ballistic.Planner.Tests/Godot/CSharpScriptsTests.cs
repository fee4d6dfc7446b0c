namespace Ballistic.Planner.Tests.Godot;

/// <summary>Reading Godot script classes from C# syntax: exports, partial declarations, constructors, signals, bases.</summary>
public sealed class CSharpScriptsTests
{
    private static CSharpScripts Read(params (string Path, string Text)[] sources) => CSharpScripts.Parse(sources);

    [Test]
    public void ExportedPropertiesAndFieldsAreFoundUnderEveryAttributeSpelling()
    {
        CSharpScripts scripts = Read(("a/Agent.cs", """
            using Godot;
            namespace Game.Nodes;

            [GlobalClass, Icon("res://icon.svg")]
            public partial class Agent : Node3D
            {
                [Export] public float Speed { get; set; }
                [Godot.Export(PropertyHint.Range, "0,1")] public float Friction { get; set; } = [0.5f][0];
                [ExportAttribute] public int Lives, Continues;
                [ExportStorage] private string _cache = "";
                [ExportToolButton("Bake")] public Callable BakeButton => Callable.From(Bake);
                [ExportGroup("Debug")] public bool NotAnExport { get; set; }
                public int Plain;
                private void Bake() { }
            }
            """));
        CSharpScriptClass agent = scripts.ClassInFile("a/Agent.cs", "Agent")!;
        Assert.Multiple(() =>
        {
            Assert.That(scripts.SyntaxErrors, Is.Empty);
            Assert.That(agent.FullName, Is.EqualTo("Game.Nodes.Agent"));
            Assert.That(agent.Exports.Keys, Is.EquivalentTo(new[] { "Speed", "Friction", "Lives", "Continues", "_cache", "BakeButton" }));
            Assert.That(agent.Exports["Lives"], Is.EqualTo(9));
            Assert.That(agent.Attributes, Is.EquivalentTo(new[] { "GlobalClass", "Icon" }));
            Assert.That(agent.BaseTypeName, Is.EqualTo("Node3D"));
            Assert.That(agent.IsPartial, Is.True);
            Assert.That(agent.HasParameterlessConstructor, Is.True);
            Assert.That(agent.Methods, Does.Contain("Bake"));
        });
    }

    [Test]
    public void PartialDeclarationsAcrossFilesMergeAndAllMustBePartial()
    {
        CSharpScripts scripts = Read(
            ("a/Runner.cs", "namespace G; public partial class Runner : Godot.Node { [Godot.Export] public int A { get; set; } }"),
            ("a/Runner.Signals.cs", "namespace G; public partial class Runner { [Godot.Signal] public delegate void LandedEventHandler(float speed); public void OnLanded(float s) { } }"),
            ("a/Half.cs", "namespace G; public partial class Half : Godot.Node { }"),
            ("a/Half.More.cs", "namespace G; public class Half { }"));
        CSharpScriptClass runner = scripts.Classes.Single(c => c.Name == "Runner");
        CSharpScriptClass half = scripts.Classes.Single(c => c.Name == "Half");
        Assert.Multiple(() =>
        {
            Assert.That(runner.Files, Is.EqualTo(new[] { "a/Runner.cs", "a/Runner.Signals.cs" }));
            Assert.That(runner.Exports.Keys, Is.EqualTo(new[] { "A" }));
            Assert.That(runner.Signals, Is.EquivalentTo(new[] { "Landed" }));
            Assert.That(runner.Methods, Is.EquivalentTo(new[] { "OnLanded" }));
            Assert.That(runner.IsPartial, Is.True);
            Assert.That(half.IsPartial, Is.False);
            Assert.That(scripts.ClassInFile("a/Runner.Signals.cs", "Runner"), Is.SameAs(runner));
        });
    }

    [TestCase("public partial class C : Godot.Node { }", true)]
    [TestCase("public partial class C : Godot.Node { public C() { } public C(int a) { } }", true)]
    [TestCase("public partial class C : Godot.Node { public C(int a) { } }", false)]
    [TestCase("public partial class C : Godot.Node { public C(int a = 1) { } }", false)]
    [TestCase("public partial class C : Godot.Node { static C() { } }", true)]
    [TestCase("public partial class C(int a) : Godot.Node { }", false)]
    [TestCase("public partial class C() : Godot.Node { }", true)]
    public void AParameterlessConstructorIsTheImplicitOneOrADeclaredOne(string source, bool parameterless)
    {
        CSharpScriptClass c = Read(("C.cs", source)).Classes.Single();
        Assert.That(c.HasParameterlessConstructor, Is.EqualTo(parameterless));
    }

    [Test]
    public void ExportsAndTheGodotBaseAreFollowedThroughOurBaseClasses()
    {
        CSharpScripts scripts = Read(
            ("n/Base.cs", "namespace N; public abstract partial class Base : Godot.CharacterBody3D { [Godot.Export] public float Mass { get; set; } }"),
            ("n/Mid.cs", "namespace N; public partial class Mid : Base, System.IDisposable { [Godot.Export] public float Mass2 { get; set; } public void Dispose() { } }"),
            ("n/Leaf.cs", "namespace N; public partial class Leaf : Mid { [Godot.Export] public int Legs { get; set; } }"),
            ("n/Loose.cs", "namespace N; public sealed class Loose : System.IDisposable { public void Dispose() { } }"));
        CSharpScriptClass leaf = scripts.ClassInFile("n/Leaf.cs", "Leaf")!;
        Assert.Multiple(() =>
        {
            Assert.That(scripts.Chain(leaf).Select(c => c.Name), Is.EqualTo(new[] { "Leaf", "Mid", "Base" }));
            Assert.That(scripts.NativeBaseOf(leaf), Is.EqualTo("CharacterBody3D"));
            Assert.That(scripts.ExportsOf(leaf).Keys, Is.EquivalentTo(new[] { "Legs", "Mass2", "Mass" }));
            Assert.That(scripts.ExportsOf(leaf)["Mass"].Name, Is.EqualTo("Base"));
            Assert.That(scripts.NativeBaseOf(scripts.ClassInFile("n/Loose.cs", "Loose")!), Is.EqualTo("IDisposable"));
            Assert.That(scripts.ClassInFile("n/Base.cs", "Base")!.IsAbstract, Is.True);
        });
    }

    [Test]
    public void EditorOnlyCodeIsReadAsAnEditorBuildSeesIt()
    {
        CSharpScripts scripts = Read(("p/Plugin.cs", """
            #if TOOLS
            using Godot;
            [Tool]
            public partial class Plugin : EditorPlugin { }
            #endif
            """));
        CSharpScriptClass plugin = scripts.ClassInFile("p/Plugin.cs", "Plugin")!;
        Assert.Multiple(() =>
        {
            Assert.That(plugin.Attributes, Does.Contain("Tool"));
            Assert.That(plugin.Namespace, Is.Empty);
            Assert.That(plugin.Line, Is.EqualTo(4));
        });
    }

    [Test]
    public void NestedAndGenericClassesAreToldApart()
    {
        CSharpScripts scripts = Read(("g/Outer.cs", "public partial class Outer : Godot.Node { public partial class Inner : Godot.Node { } } public partial class Box<T> : Godot.Node { }"));
        Assert.Multiple(() =>
        {
            Assert.That(scripts.Classes.Single(c => c.Name == "Inner").IsNested, Is.True);
            Assert.That(scripts.Classes.Single(c => c.Name == "Inner").FullName, Is.EqualTo("Outer.Inner"));
            Assert.That(scripts.ClassInFile("g/Outer.cs", "Inner"), Is.Null, "a script's class is a top-level class");
            Assert.That(scripts.Classes.Single(c => c.Name == "Box").IsGeneric, Is.True);
        });
    }

    [Test]
    public void SyntaxErrorsAreOneLineNamingFileAndLine()
    {
        CSharpScripts scripts = Read(("bad/Broken.cs", "public partial class Broken : Godot.Node\n{\n    public int X { get; set;\n}\n"));
        Assert.That(scripts.SyntaxErrors, Is.Not.Empty);
        Assert.That(scripts.SyntaxErrors, Has.All.Match("^bad/Broken\\.cs:[0-9]+: C# syntax error CS[0-9]+: [^\\n]+$"));
    }
}
