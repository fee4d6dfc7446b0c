namespace Ballistic.Planner.Tests.Godot;

/// <summary>
/// Each kind of defect the scene tests exist for, planted once in an otherwise sound <see cref="ProbeProject"/>: the
/// checker must report it in one line that names the file, the line and the element.
/// </summary>
public sealed class GodotPlantedDefectTests
{
    /// <summary>One planted defect: in <c>File</c>, <c>Find</c> becomes <c>Replacement</c>; the issue must hold every expected fragment.</summary>
    public sealed record Defect(string Name, string File, string Find, string Replacement, string[] Expected)
    {
        public override string ToString() => Name;
    }

    private const string Main = "Scenes/main.tscn";
    private const string ProbeNode = "addons/ballistic/ProbeNode3D.cs";

    private static readonly Defect[] Defects =
    [
        new("missing ext_resource file", Main, "path=\"res://Scenes/prop.glb\"", "path=\"res://Scenes/gone.glb\"",
            [$"{Main}:6: [ext_resource id=\"4_prop\"]", "res://Scenes/gone.glb does not exist"]),
        new("ext_resource path not res://", Main, "path=\"res://Scenes/prop.glb\"", "path=\"Scenes/prop.glb\"",
            [$"{Main}:6: [ext_resource id=\"4_prop\"]", "must start with res://"]),
        new("unknown property on a scripted node", Main, "Count = 3", "Cont = 3",
            [$"{Main}:", "node \"Probe\"", "property \"Cont\" is neither an [Export] member of Probe.ProbeNode3D", "Godot class Node3D"]),
        new("property not exported", Main, "Count = 3", "NotExported = 3",
            ["node \"Probe\"", "property \"NotExported\" is neither an [Export] member"]),
        new("C# member written in snake_case", Main, "Count = 3", "count = 3",
            ["node \"Probe\"", "property \"count\"", "the C# member is Count"]),
        new("unknown built-in property on a plain node", Main, "text = \"state\"", "txt = \"state\"",
            [$"{Main}:", "node \"Probe/Label\"", "property \"txt\" is not a property of Godot class Label3D"]),
        new("property of another class", Main, "target_position = Vector3(1, 0, 1)", "mesh = SubResource(\"BoxMesh_a\")",
            ["node \"Probe/Agent\"", "property \"mesh\" is not a property of Godot class NavigationAgent3D"]),
        new("unknown property on a scripted resource", "Scenes/probe.tres", "Gravity = 3.7", "Gravty = 3.7",
            ["Scenes/probe.tres:", "[resource]", "property \"Gravty\" is neither an [Export] member of Probe.ProbeResource", "Godot class Resource"]),
        new("unknown property on an inherited scene's root", "Scenes/variant.tscn", "Speed = 6.0", "Sped = 6.0",
            ["Scenes/variant.tscn:6: node \"Variant\" (root)", "property \"Sped\" is neither an [Export] member of Probe.ProbeNode3D"]),
        new("unknown property below an inherited node", "Scenes/variant.tscn", "gizmo_extents = 0.5", "gizmo_extent = 0.5",
            ["Scenes/variant.tscn:13: node \"Inner/Extra\"", "property \"gizmo_extent\" is not a property of Godot class Marker3D"]),
        new("property set twice", Main, "Limit = -2", "Count = -2",
            ["node \"Probe\"", "property \"Count\" is set twice"]),
        new("duplicate uid across files", "Scenes/child.tscn", "uid=\"uid://c2probechild\"]", "uid=\"uid://a4probemain\"]",
            ["uid uid://a4probemain is not unique", "Scenes/child.tscn", "Scenes/main.tscn"]),
        new("duplicate uid in a uid file", "addons/ballistic/ProbeNode3D.cs.uid", "uid://b1probenode", "uid://d3proberes",
            ["uid uid://d3proberes is not unique"]),
        new("malformed uid", "Scenes/child.tscn", "uid=\"uid://c2probechild\"]", "uid=\"c2probechild\"]",
            ["Scenes/child.tscn:1: [gd_scene]", "uid c2probechild is not of the form uid://"]),
        new("ext_resource uid of another file", Main, "uid=\"uid://c2probechild\" path", "uid=\"uid://d3proberes\" path",
            [$"{Main}:4: [ext_resource id=\"2_child\"]", "uid uid://d3proberes belongs to res://Scenes/probe.tres"]),
        new("duplicate ext_resource id", Main, "id=\"4_prop\"", "id=\"3_res\"",
            [$"{Main}:6: [ext_resource id=\"3_res\"]", "id \"3_res\" is already used"]),
        new("duplicate sub_resource id", Main, "id=\"Mat_a\"", "id=\"BoxMesh_a\"",
            [$"{Main}:11: [sub_resource id=\"BoxMesh_a\"]", "already used"]),
        new("undeclared ExtResource", Main, "Settings = ExtResource(\"3_res\")", "Settings = ExtResource(\"9_nope\")",
            ["node \"Probe\"", "ExtResource(\"9_nope\") is not declared"]),
        new("undeclared SubResource", Main, "mesh = SubResource(\"BoxMesh_a\")", "mesh = SubResource(\"BoxMesh_b\")",
            ["node \"Probe/Mesh\"", "SubResource(\"BoxMesh_b\") is not declared"]),
        new("SubResource used before it is declared", Main, "size = Vector3(2, 0.5, 2)", "size = Vector3(2, 0.5, 2)\nmaterial = SubResource(\"Mat_a\")",
            ["[sub_resource id=\"BoxMesh_a\"]", "SubResource(\"Mat_a\") is used before its [sub_resource]"]),
        new("parent that does not exist", Main, "parent=\"Probe\"]\nmesh", "parent=\"Prob\"]\nmesh",
            ["node \"Prob/Mesh\"", "parent \"Prob\" is not a node declared above it"]),
        new("duplicate node path", Main, "[node name=\"Label\"", "[node name=\"Mesh\"",
            ["node \"Probe/Mesh\"", "is already declared"]),
        new("invalid node name", Main, "[node name=\"Label\"", "[node name=\"La.bel\"",
            ["node \"Probe/La.bel\"", "holds one of"]),
        new("unknown node type", Main, "type=\"Label3D\"", "type=\"Label4D\"",
            ["node \"Probe/Label\"", "type \"Label4D\" is not a Godot class known to GodotClasses"]),
        new("type and instance together", Main, "[node name=\"Prop\" parent=\".\"", "[node name=\"Prop\" type=\"Node3D\" parent=\".\"",
            ["node \"Prop\"", "has both type= and instance="]),
        new("neither type nor instance", Main, "[node name=\"Agent\" type=\"NavigationAgent3D\"", "[node name=\"Agent\"",
            ["node \"Probe/Agent\"", "has neither type= nor instance="]),
        new("instance of a non-scene", Main, "instance=ExtResource(\"4_prop\")", "instance=ExtResource(\"3_res\")",
            ["node \"Prop\"", "instance must be a scene"]),
        new("script on a node type it does not fit", Main, "[node name=\"Probe\" type=\"Node3D\"", "[node name=\"Probe\" type=\"Node\"",
            ["node \"Probe\"", "script class ProbeNode3D extends Node3D, but the type here is Node"]),
        new("script that is not partial", ProbeNode, "public partial class ProbeNode3D", "public class ProbeNode3D",
            [$"{ProbeNode}:6: class ProbeNode3D", "must be partial"]),
        new("script without a parameterless constructor", ProbeNode, "public int NotExported { get; set; }",
            "public int NotExported { get; set; }\n    public ProbeNode3D(int n) { }",
            [$"{ProbeNode}:6: class ProbeNode3D", "no parameterless constructor"]),
        new("abstract script", ProbeNode, "public partial class ProbeNode3D", "public abstract partial class ProbeNode3D",
            ["class ProbeNode3D", "is abstract"]),
        new("script whose class is not named like its file", ProbeNode, "public partial class ProbeNode3D : ProbeBase3D", "public partial class ProbeNode : ProbeBase3D",
            [$"{Main}:3: [ext_resource id=\"1_node\"]", "declares no top-level class ProbeNode3D"]),
        new("script that is not C#", Main, "path=\"res://addons/ballistic/ProbeNode3D.cs\" id=\"1_node\"", "path=\"res://Scenes/prop.glb\" id=\"1_node\"",
            [$"{Main}:3: [ext_resource id=\"1_node\"]", "scripts must be C# files of ours"]),
        new("script that is not ours", Main, "path=\"res://addons/ballistic/ProbeNode3D.cs\" id=\"1_node\"", "path=\"res://Tools/Other.cs\" id=\"1_node\"",
            [$"{Main}:3: [ext_resource id=\"1_node\"]", "is not one of ours"]),
        new("connection from a missing node", Main, "from=\"Probe\" to=\"Probe\"", "from=\"Probes\" to=\"Probe\"",
            ["[connection signal=\"Arrived\" from=\"Probes\"", "from=\"Probes\" is not a node of this scene"]),
        new("connection to an undeclared C# method", Main, "method=\"OnArrived\"", "method=\"OnArive\"",
            ["[connection signal=\"Arrived\"", "method OnArive is not declared by Probe.ProbeNode3D"]),
        new("connection of an undeclared C# signal", Main, "signal=\"Arrived\"", "signal=\"Arrive\"",
            ["[connection signal=\"Arrive\"", "signal Arrive is not a [Signal] of Probe.ProbeNode3D"]),
        new("editable path that is not an instance", Main, "[editable path=\"Child\"]", "[editable path=\"Probe\"]",
            ["[editable path=\"Probe\"]", "is not an instanced node"]),
        new("script_class naming another class", "Scenes/probe.tres", "script_class=\"ProbeResource\"", "script_class=\"ProbeSettings\"",
            ["Scenes/probe.tres:1: [gd_resource]", "script_class=\"ProbeSettings\" but the [resource] script's class is ProbeResource"]),
        new("main scene that does not exist", "project.godot", "run/main_scene=\"res://Scenes/main.tscn\"", "run/main_scene=\"res://Scenes/mian.tscn\"",
            ["project.godot:", "[application] run/main_scene", "main scene res://Scenes/mian.tscn does not exist"]),
        new("autoload that does not exist", "project.godot", "ProbeServer=\"*res://addons/ballistic/ProbeServer.cs\"", "ProbeServer=\"*res://addons/ballistic/Server.cs\"",
            ["project.godot:", "[autoload] ProbeServer", "res://addons/ballistic/Server.cs does not exist"]),
        new("autoload that is not a Node", "project.godot", "ProbeServer=\"*res://addons/ballistic/ProbeServer.cs\"", "ProbeServer=\"*res://addons/ballistic/ProbeResource.cs\"",
            ["[autoload] ProbeServer", "an autoload must be a Node; ProbeResource extends Resource"]),
        new("enabled plugin that does not exist", "project.godot", "\"res://addons/ballistic/plugin.cfg\"", "\"res://addons/probe/plugin.cfg\"",
            ["project.godot:", "[editor_plugins] enabled", "res://addons/probe/plugin.cfg does not exist"]),
        new("plugin.cfg without an author", "addons/ballistic/plugin.cfg", "author=\"Ballistic\"\n", "",
            ["addons/ballistic/plugin.cfg:", "[plugin]", "author=\"…\" is missing"]),
        new("plugin script that does not exist", "addons/ballistic/plugin.cfg", "script=\"ProbePlugin.cs\"", "script=\"Plugin.cs\"",
            ["addons/ballistic/plugin.cfg:7: [plugin] script", "does not exist beside plugin.cfg"]),
        new("plugin script without [Tool]", "addons/ballistic/ProbePlugin.cs", "[Tool]", "",
            ["addons/ballistic/ProbePlugin.cs:", "class ProbePlugin", "needs [Tool]"]),
        new("Godot class of ours that is not partial", "addons/ballistic/ProbeBase3D.cs", "public abstract partial class", "public abstract class",
            ["addons/ballistic/ProbeBase3D.cs:5: class ProbeBase3D", "not partial"]),
        new("assembly name without its project", "project.godot", "project/assembly_name=\"Probe\"", "project/assembly_name=\"Prob\"",
            ["[dotnet] project/assembly_name", "Prob.csproj"]),
        new("malformed scene", Main, "billboard = 1", "billboard = ture",
            [$"{Main}:", "unexpected identifier 'ture'"]),
        new("C# syntax error", ProbeNode, "public int NotExported { get; set; }", "public int NotExported { get; set; ",
            [$"{ProbeNode}:", "C# syntax error"]),
    ];

    [Test]
    public void TheSoundProbeProjectHasNoIssues()
    {
        using var probe = new ProbeProject();
        IReadOnlyList<string> issues = probe.Check();
        Assert.That(issues, Is.Empty, () => string.Join(Environment.NewLine, issues));
    }

    [Test]
    public void TheSoundProbeProjectUsesTheConstructsTheDefectsBreak()
    {
        using var probe = new ProbeProject();
        GodotProject project = probe.Load();
        GodotFile main = project.FileAt(Main)!;
        CSharpScriptClass node = project.Scripts.ClassInFile(ProbeNode, "ProbeNode3D")!;
        Assert.Multiple(() =>
        {
            Assert.That(main.Nodes.Count(), Is.EqualTo(8));
            Assert.That(project.Scripts.ExportsOf(node).Keys, Is.EquivalentTo(new[] { "Speed", "Settings", "Count", "Limit", "_memo" }));
            Assert.That(project.Scripts.NativeBaseOf(node), Is.EqualTo("Node3D"));
            Assert.That(project.UidFiles.Keys, Is.EqualTo(new[] { "addons/ballistic/ProbeNode3D.cs.uid" }));
        });
    }

    [TestCaseSource(nameof(Defects))]
    public void APlantedDefectIsReportedNamingFileLineAndElement(Defect defect)
    {
        using var probe = new ProbeProject();
        if (defect.Name == "script that is not ours")
        {
            probe.Write("Tools/Other.cs", "namespace Probe;\n\npublic partial class Other : Godot.Node3D\n{\n}\n");
        }

        probe.Replace(defect.File, defect.Find, defect.Replacement);
        IReadOnlyList<string> issues = probe.Check();
        string all = string.Join(Environment.NewLine, issues);
        Assert.Multiple(() =>
        {
            Assert.That(issues.Where(i => defect.Expected.All(e => i.Contains(e, StringComparison.Ordinal))), Is.Not.Empty,
                $"no issue holds all of [{string.Join(" | ", defect.Expected)}]; issues:{Environment.NewLine}{all}");
            Assert.That(issues, Has.All.Matches<string>(i => !i.Contains('\n', StringComparison.Ordinal) && IssueFormat(i)),
                $"every issue is one line 'file:line: element: problem':{Environment.NewLine}{all}");
        });
    }

    private static bool IssueFormat(string issue)
    {
        string[] parts = issue.Split(':', 3);
        return parts.Length == 3 && parts[0].Length > 0 && int.TryParse(parts[1], out int line) && line >= 1;
    }
}
