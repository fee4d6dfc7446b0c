namespace Ballistic.Planner.Tests.Godot;

/// <summary>The engine-free reader of Godot's text scenes, resources and ConfigFiles, on small inline samples.</summary>
public sealed class GodotTextParserTests
{
    private const string Scene = """
        [gd_scene load_steps=4 format=3 uid="uid://cq1abc"]

        [ext_resource type="Script" uid="uid://b2def" path="res://addons/ballistic/Nodes/JumpRoadmap3D.cs" id="1_roadmap"]
        [ext_resource type="PackedScene" path="res://Scenes/levels/desert.glb" id="2_desert"]

        [sub_resource type="ArrayMesh" id="ArrayMesh_x"]
        _surfaces = [{
        "aabb": AABB(-1, 0, -1, 2, 0.5, 2),
        "format": 34896613377,
        "primitive": 3,
        "vertex_data": PackedByteArray(0, 0, 128, 191, 0, 0, 0, 0),
        "vertex_count": 2
        }]
        blend_shape_mode = 0

        [node name="Main" type="Node3D" groups=["level", "bake"]]
        metadata/_edit_group_ = true ; editor only

        [node name="Roadmap" type="Node3D" parent="." unique_id=12345]
        script = ExtResource("1_roadmap")
        Seed = -42
        TimeLimit = 2.5e-1
        Label = "tab\there \"quoted\" \u00e9 back\\slash
        second line"
        Layers = Array[int]([1, 2, 3])
        Scenes = Array[ExtResource("2_desert")]([ExtResource("2_desert")])
        Target = NodePath("../Level")
        Groups = &"jumpers"
        Path = ^"Level/Floor"
        Weights = {
        &"front": 0.5,
        "back": [1, null, false, inf, -inf, nan]
        }

        [node name="Desert" parent="." instance=ExtResource("2_desert")]

        [connection signal="BakeFinished" from="Roadmap" to="." method="OnBaked" flags=3 binds=[1, "x"]]
        """;

    [Test]
    public void ASceneParsesIntoSectionsAttributesAndValues()
    {
        GodotFile file = GodotFile.Parse(Scene, "main.tscn");
        GodotSection roadmap = file.Nodes.ElementAt(1);
        Assert.Multiple(() =>
        {
            Assert.That(file.Kind, Is.EqualTo(GodotFileKind.Scene));
            Assert.That(file.Sections.Select(s => s.Tag), Is.EqualTo(new[]
            {
                "gd_scene", "ext_resource", "ext_resource", "sub_resource", "node", "node", "node", "connection",
            }));
            Assert.That(file.Header!.Attribute("load_steps")!.Int, Is.EqualTo(4));
            Assert.That(file.Header.AttributeString("uid"), Is.EqualTo("uid://cq1abc"));
            Assert.That(file.ExtResources.Select(e => e.AttributeString("id")), Is.EqualTo(new[] { "1_roadmap", "2_desert" }));
            Assert.That(file.ExtResources.First().AttributeString("path"), Is.EqualTo("res://addons/ballistic/Nodes/JumpRoadmap3D.cs"));
            Assert.That(file.Nodes.First().Attribute("groups")!.Strings(), Is.EqualTo(new[] { "level", "bake" }));
            Assert.That(file.Nodes.First().Property("metadata/_edit_group_")!.Value.Bool, Is.True);
            Assert.That(roadmap.Line, Is.EqualTo(19));
            Assert.That(roadmap.Attribute("unique_id")!.Int, Is.EqualTo(12345));
            Assert.That(roadmap.Property("Seed")!.Value.Int, Is.EqualTo(-42));
            Assert.That(roadmap.Property("TimeLimit")!.Value.Kind, Is.EqualTo(GodotValueKind.Float));
            Assert.That(roadmap.Property("TimeLimit")!.Value.Number, Is.EqualTo(0.25));
            Assert.That(roadmap.Property("Label")!.Value.AsString(), Is.EqualTo("tab\there \"quoted\" \u00e9 back\\slash\nsecond line"));
            Assert.That(roadmap.Property("Layers")!.Line, Is.EqualTo(25), "a multi-line string moves the following lines");
            Assert.That(roadmap.Property("Layers")!.Value.Items.Single().Items.Select(v => v.Int), Is.EqualTo(new long[] { 1, 2, 3 }));
            Assert.That(roadmap.Property("Layers")!.Value.TypeArguments.Single().Text, Is.EqualTo("int"));
            Assert.That(roadmap.Property("Groups")!.Value.Kind, Is.EqualTo(GodotValueKind.StringName));
            Assert.That(roadmap.Property("Path")!.Value.Kind, Is.EqualTo(GodotValueKind.NodePath));
            Assert.That(roadmap.Property("Target")!.Value.Items.Single().AsString(), Is.EqualTo("../Level"));
            Assert.That(roadmap.Property("Weights")!.Value.Entries.Select(e => e.Key.Text), Is.EqualTo(new[] { "front", "back" }));
            Assert.That(roadmap.Property("Weights")!.Value.Entries[1].Value.Items.Select(v => v.Kind), Is.EqualTo(new[]
            {
                GodotValueKind.Int, GodotValueKind.Null, GodotValueKind.Bool, GodotValueKind.Float, GodotValueKind.Float, GodotValueKind.Float,
            }));
            Assert.That(double.IsNegativeInfinity(roadmap.Property("Weights")!.Value.Entries[1].Value.Items[4].Number), Is.True);
            Assert.That(file.Connections.Single().Attribute("binds")!.Items, Has.Count.EqualTo(2));
        });
    }

    [Test]
    public void ResourceReferencesAreFoundWhereverTheyAreNested()
    {
        GodotFile file = GodotFile.Parse(Scene, "main.tscn");
        var references = file.Sections
            .SelectMany(s => s.Attributes.Select(a => a.Value).Concat(s.Properties.Select(p => p.Value)))
            .SelectMany(v => v.DescendantsAndSelf())
            .Select(v => v.TryGetResourceReference(out string kind, out string id) ? $"{kind}:{id}" : null)
            .Where(r => r is not null)
            .ToList();
        Assert.That(references, Is.EqualTo(new[]
        {
            "ExtResource:1_roadmap", "ExtResource:2_desert", "ExtResource:2_desert", "ExtResource:2_desert",
        }));
    }

    [Test]
    public void AMultiLineSubResourceKeepsItsBytesAndTheNextProperty()
    {
        GodotSection mesh = GodotFile.Parse(Scene, "main.tscn").SubResources.Single();
        GodotValue surface = mesh.Property("_surfaces")!.Value.Items.Single();
        GodotValue bytes = surface.Entries.Single(e => e.Key.Text == "vertex_data").Value;
        Assert.Multiple(() =>
        {
            Assert.That(surface.Entries.Single(e => e.Key.Text == "format").Value.Int, Is.EqualTo(34896613377));
            Assert.That(bytes.Text, Is.EqualTo("PackedByteArray"));
            Assert.That(bytes.Items.Select(b => b.Int), Is.EqualTo(new long[] { 0, 0, 128, 191, 0, 0, 0, 0 }));
            Assert.That(mesh.Property("blend_shape_mode")!.Line, Is.EqualTo(14));
        });
    }

    [Test]
    public void AResourceAndConfigFilesParse()
    {
        GodotFile resource = GodotFile.Parse("""
            [gd_resource type="Resource" script_class="JumpCharacter" load_steps=2 format=3 uid="uid://x1"]

            [ext_resource type="Script" path="res://addons/ballistic/JumpCharacter.cs" id="1"]

            [resource]
            script = ExtResource("1")
            Rig = PackedByteArray("AAECAwQ=")
            """, "frog.tres");
        GodotFile project = GodotFile.Parse("""
            ; Engine configuration file.
            config_version=5

            [application]
            config/name="Ballistic"
            "key with space"="value"

            [input]
            jump={
            "deadzone": 0.5,
            "events": [Object(InputEventKey,"resource_local_to_scene":false,"keycode":32,"script":null)
            ]
            }
            """, "project.godot");
        Assert.Multiple(() =>
        {
            Assert.That(resource.Kind, Is.EqualTo(GodotFileKind.Resource));
            Assert.That(resource.Header!.AttributeString("script_class"), Is.EqualTo("JumpCharacter"));
            Assert.That(resource.Section("resource")!.Property("Rig")!.Value.Items.Single().Text, Is.EqualTo("AAECAwQ="));
            Assert.That(project.Kind, Is.EqualTo(GodotFileKind.Config));
            Assert.That(project.Section("")!.Property("config_version")!.Value.Int, Is.EqualTo(5));
            Assert.That(project.Section("application")!.Property("key with space")!.Value.AsString(), Is.EqualTo("value"));
            GodotValue key = project.Section("input")!.Property("jump")!.Value.Entries[1].Value.Items.Single();
            Assert.That(key.Text, Is.EqualTo("Object"));
            Assert.That(key.Items.Single().Kind, Is.EqualTo(GodotValueKind.Identifier));
            Assert.That(key.Entries.Single(e => e.Key.Text == "keycode").Value.Int, Is.EqualTo(32));
        });
    }

    [Test]
    public void ValuesPrintBackInGodotSyntax()
    {
        GodotValue value = GodotFile.ParseValue("Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, 0, -0.5, 2)");
        Assert.Multiple(() =>
        {
            Assert.That(value.ToString(), Is.EqualTo("Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, 0, -0.5, 2)"));
            Assert.That(GodotFile.ParseValue("{ \"a\": [&\"b\", ^\"c\"] }").ToString(), Is.EqualTo("{\"a\": [&\"b\", ^\"c\"]}"));
        });
    }

    /// <summary>Malformed text: the file name it is parsed as, the line the error must name, a fragment of the problem.</summary>
    private static readonly object[][] Malformed =
    [
        ["a.tscn", "[gd_scene format=3]\n\n[node name=\"A\" type=\"Node3D\"]\nvisible = ture\n", 4, "unexpected identifier 'ture'"],
        ["a.tscn", "[gd_scene format=3]\n[node name=\"A\" type=\"Node3D\"]\ntext = \"open\n\nmore\n", 3, "string starting on line 3 is not closed"],
        ["a.tscn", "[gd_scene format=3]\n[node name=\"A\" type=\"Node3D\"\nvisible = true\n", 2, "[node … is not closed with ']'"],
        ["a.tscn", "[gd_scene format=3]\n[node name=\"A\" type=\"Node3D\"]\nvisible true\n", 3, "expected 'key = value', found 'visible true'"],
        ["a.tscn", "[gd_scene format=3]\n[node name=\"A\" type=\"Node3D\"]\nvisible =\nscale = Vector3(1, 1, 1)\n", 3, "missing value after 'visible ='"],
        ["a.tscn", "[gd_scene format=3]\n[node name=\"A\" type=\"Node3D\"]\nscale = Vector3(1, 1, 1\nvisible = true\n", 4, "expected ',' or ')' in the arguments of Vector3"],
        ["a.tscn", "[gd_scene format=3]\n[node name=\"A\" type=\"Node3D\"]\nitems = [1, 2,]\n", 3, "unexpected character ']'"],
        ["a.tscn", "[gd_scene format=3]\n[node name=\"A\" type=\"Node3D\"]\nitems = {\"a\" 1}\n", 3, "expected ':' after dictionary key"],
        ["a.tscn", "[gd_scene format=3]\n[node name=\"A\" type=\"Node3D\"]\ntext = \"bad \\q escape\"\n", 3, "invalid escape '\\q'"],
        ["a.tscn", "[gd_scene format=3]\n[node name=\"A\" type=\"Node3D\"]\nvisible = true false\n", 3, "unexpected 'false' after the value of 'visible'"],
        ["a.tscn", "[gd_scene format=3]\n[node name=\"A\" type=\"Node3D\"]\nvalue = 1.5.2\n", 3, "unexpected '.2' after the value of 'value'"],
        ["a.tscn", "[gd_scene format=3]\n[node name=\"A\" type=\"Node3D\"]\nvalue = 12abc\n", 3, "malformed number '12abc'"],
        ["a.tscn", "[gd_scene format=3]\n[node name=\"A\" type=\"Node3D\"]\nscript = ExtResource(\"1\", \"2\")\n", 3, "ExtResource(…) takes one id"],
        ["a.tscn", "[gd_scene format=3]\n[node name=\"A\" type=\"Node3D\" name=\"B\"]\n", 2, "attribute 'name' is given twice"],
        ["a.tscn", "[gd_scene format=2]\n", 1, "needs format=3"],
        ["a.tscn", "[node name=\"A\" type=\"Node3D\"]\n", 1, "must start with [gd_scene"],
        ["a.tscn", "[gd_scene format=3]\n[resource]\n", 2, "[resource] does not belong in a .tscn scene"],
        ["a.tscn", "[gd_scene format=3]\n[ext_resource type=\"Script\" path=\"res://a.cs\"]\n", 2, "needs the attribute id="],
        ["a.tscn", "[gd_scene format=3]\n[ext_resource type=\"Script\" path=\"res://a.cs\" id=\"1\"]\nfoo = 1\n", 3, "takes no properties"],
        ["a.tscn", "[gd_scene format=3]\n[node name=\"A\" type=\"Node3D\"]\n[node name=\"B\" type=\"Node3D\"]\n", 3, "already has its root node"],
        ["a.tscn", "[gd_scene format=3]\n[node name=\"A\" type=\"Node3D\" parent=\".\"]\n", 2, "the first node is the scene's root and has no parent"],
        ["a.tscn", "[gd_scene format=3]\n[node name=A type=\"Node3D\"]\n", 2, "unexpected identifier 'A'"],
        ["a.tscn", "[gd_scene format=3]\n[node name=\"A\" type=\"Node3D\"] junk\n", 2, "unexpected 'junk' after [node …]"],
        ["a.tres", "[gd_resource format=3]\n[resource]\n", 1, "needs the attribute type="],
        ["a.tres", "[gd_resource type=\"Resource\" format=3]\n", 1, "needs a [resource] section"],
        ["a.tres", "[gd_resource type=\"Resource\" format=3]\n[resource]\n[resource]\n", 3, "a second [resource] section"],
        ["a.tres", "a = 1\n[gd_resource type=\"Resource\" format=3]\n[resource]\n", 1, "properties before the [gd_resource"],
        ["project.godot", "[application]\n\nconfig/name = \"x\"\n[]\n", 4, "empty section header"],
        ["project.godot", "[application]\nconfig/name = Object(InputEventKey, \"a\": 1\n", 2, "Object( opened on line 2 is not closed"],
        ["project.godot", "[application]\nbad key = 1\n", 2, "property name 'bad key' contains whitespace"],
    ];

    [TestCaseSource(nameof(Malformed))]
    public void MalformedTextFailsWithOneLineNamingFileLineAndProblem(string file, string text, int line, string problem)
    {
        GodotFormatException error = Assert.Throws<GodotFormatException>(() => GodotFile.Parse(text, file))!;
        Assert.Multiple(() =>
        {
            Assert.That(error.Message, Does.StartWith($"{file}:{line}: "));
            Assert.That(error.Message, Does.Contain(problem));
            Assert.That(error.Message, Does.Not.Contain('\n'));
            Assert.That(error.File, Is.EqualTo(file));
            Assert.That(error.Line, Is.EqualTo(line));
        });
    }
}
