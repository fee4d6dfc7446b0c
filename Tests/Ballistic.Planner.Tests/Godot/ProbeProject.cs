namespace Ballistic.Planner.Tests.Godot;

/// <summary>
/// A small, sound Godot project written to a temporary folder, for planting one defect at a time and checking that
/// <see cref="GodotProjectChecker"/> names it. It uses every construct the checker accepts: scripted nodes with
/// exported members and built-in properties, sub-resources, an instanced scene, an imported scene, a connection, a
/// scripted <c>.tres</c>, an inherited scene, uid side files, an autoload and an editor plugin.
/// </summary>
public sealed class ProbeProject : IDisposable
{
    /// <summary>The files of the sound project, by repository-relative path.</summary>
    public static readonly IReadOnlyDictionary<string, string> SoundFiles = new Dictionary<string, string>
    {
        ["project.godot"] = """
            ; Engine configuration file.
            config_version=5

            [application]

            config/name="Probe"
            run/main_scene="res://Scenes/main.tscn"
            config/features=PackedStringArray("4.7", "C#", "Forward Plus")

            [autoload]

            ProbeServer="*res://addons/ballistic/ProbeServer.cs"

            [dotnet]

            project/assembly_name="Probe"
            project/solution_directory=".godot-sln"

            [editor_plugins]

            enabled=PackedStringArray("res://addons/ballistic/plugin.cfg")

            [input]

            toggle_debug={
            "deadzone": 0.2,
            "events": [Object(InputEventKey,"resource_local_to_scene":false,"resource_name":"","device":-1,"keycode":4194332,"unicode":0,"script":null)
            ]
            }
            """,
        ["Probe.csproj"] = "<Project Sdk=\"Godot.NET.Sdk/4.7.2\" />\n",
        [".godot-sln/Probe.sln"] = "\n",
        [".godot-sln/.gdignore"] = "",
        ["addons/ballistic/plugin.cfg"] = """
            [plugin]

            name="Probe"
            description="A probe plugin."
            author="Ballistic"
            version="0.1.0"
            script="ProbePlugin.cs"
            """,
        ["addons/ballistic/ProbePlugin.cs"] = """
            #if TOOLS
            using Godot;

            namespace Probe;

            [Tool]
            public partial class ProbePlugin : EditorPlugin
            {
            }
            #endif
            """,
        ["addons/ballistic/ProbeBase3D.cs"] = """
            using Godot;

            namespace Probe;

            public abstract partial class ProbeBase3D : Node3D
            {
                [Export(PropertyHint.Range, "0,10")] public float Speed { get; set; } = 1;
            }
            """,
        ["addons/ballistic/ProbeNode3D.cs"] = """
            using Godot;

            namespace Probe;

            [GlobalClass]
            public partial class ProbeNode3D : ProbeBase3D
            {
                [Signal] public delegate void ArrivedEventHandler(Vector3 where);

                [Export] public ProbeResource? Settings { get; set; }
                [Export] public int Count, Limit;
                [ExportStorage] private string _memo = "";
                public int NotExported { get; set; }

                public void OnArrived(Vector3 where) { }
            }
            """,
        ["addons/ballistic/ProbeNode3D.cs.uid"] = "uid://b1probenode\n",
        ["addons/ballistic/ProbeResource.cs"] = """
            using Godot;

            namespace Probe;

            [GlobalClass]
            public partial class ProbeResource : Resource
            {
                [Export] public float Gravity { get; set; } = 9.81f;
            }
            """,
        ["addons/ballistic/ProbeServer.cs"] = """
            using Godot;

            namespace Probe;

            public partial class ProbeServer : Node
            {
                public ProbeServer() { }

                public ProbeServer(int capacity) { }
            }
            """,
        ["Scenes/prop.glb"] = "glTF",
        ["Scenes/child.tscn"] = """
            [gd_scene format=3 uid="uid://c2probechild"]

            [ext_resource type="Script" uid="uid://b1probenode" path="res://addons/ballistic/ProbeNode3D.cs" id="1_node"]

            [node name="Child" type="Node3D"]
            script = ExtResource("1_node")
            Speed = 2.0

            [node name="Inner" type="Node3D" parent="."]
            """,
        ["Scenes/variant.tscn"] = """
            [gd_scene format=3 uid="uid://e5probevariant"]

            [ext_resource type="PackedScene" uid="uid://c2probechild" path="res://Scenes/child.tscn" id="1_child"]

            [node name="Variant" instance=ExtResource("1_child")]
            Speed = 6.0

            [node name="Inner" parent="." index="0"]
            script = null
            visible = false

            [node name="Extra" type="Marker3D" parent="Inner"]
            gizmo_extents = 0.5
            """,
        ["Scenes/probe.tres"] = """
            [gd_resource type="Resource" script_class="ProbeResource" format=3 uid="uid://d3proberes"]

            [ext_resource type="Script" path="res://addons/ballistic/ProbeResource.cs" id="1_res"]

            [resource]
            script = ExtResource("1_res")
            Gravity = 3.7
            resource_name = "mars"
            """,
        ["Scenes/main.tscn"] = """
            [gd_scene load_steps=7 format=3 uid="uid://a4probemain"]

            [ext_resource type="Script" uid="uid://b1probenode" path="res://addons/ballistic/ProbeNode3D.cs" id="1_node"]
            [ext_resource type="PackedScene" uid="uid://c2probechild" path="res://Scenes/child.tscn" id="2_child"]
            [ext_resource type="Resource" path="res://Scenes/probe.tres" id="3_res"]
            [ext_resource type="PackedScene" path="res://Scenes/prop.glb" id="4_prop"]

            [sub_resource type="BoxMesh" id="BoxMesh_a"]
            size = Vector3(2, 0.5, 2)

            [sub_resource type="StandardMaterial3D" id="Mat_a"]
            albedo_color = Color(1, 0.5, 0.25, 1)

            [node name="Main" type="Node3D"]
            metadata/_edit_lock_ = true

            [node name="Probe" type="Node3D" parent="."]
            transform = Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 1,
            0)
            script = ExtResource("1_node")
            Speed = 4.5
            Count = 3
            Limit = -2
            _memo = "a \"quoted\"\nmemo"
            Settings = ExtResource("3_res")

            [node name="Mesh" type="MeshInstance3D" parent="Probe"]
            mesh = SubResource("BoxMesh_a")
            surface_material_override/0 = SubResource("Mat_a")

            [node name="Child" parent="." instance=ExtResource("2_child")]
            Count = 7

            [node name="Inner" parent="Child"]
            visible = false

            [node name="Prop" parent="." instance=ExtResource("4_prop")]
            transform = Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, 3, 0, 0)

            [node name="Label" type="Label3D" parent="Probe"]
            text = "state"
            billboard = 1

            [node name="Agent" type="NavigationAgent3D" parent="Probe"]
            target_position = Vector3(1, 0, 1)

            [connection signal="Arrived" from="Probe" to="Probe" method="OnArrived"]
            [connection signal="visibility_changed" from="Probe" to="Child" method="queue_free"]

            [editable path="Child"]
            """,
    };

    private readonly string _root;

    /// <summary>Writes the sound project to a new temporary folder.</summary>
    public ProbeProject()
    {
        _root = Path.Combine(Path.GetTempPath(), "ballistic-godot-probe-" + Guid.NewGuid().ToString("N"));
        foreach ((string path, string text) in SoundFiles)
        {
            Write(path, text);
        }
    }

    /// <summary>Writes (or overwrites) <paramref name="path"/>.</summary>
    public void Write(string path, string text)
    {
        string full = Path.Combine(_root, path);
        Directory.CreateDirectory(Path.GetDirectoryName(full)!);
        File.WriteAllText(full, text.ReplaceLineEndings("\n") + (text.EndsWith('\n') || text.Length == 0 ? "" : "\n"));
    }

    /// <summary>Replaces the one occurrence of <paramref name="find"/> in <paramref name="path"/>.</summary>
    public void Replace(string path, string find, string replacement)
    {
        string full = Path.Combine(_root, path);
        string text = File.ReadAllText(full);
        int at = text.IndexOf(find, StringComparison.Ordinal);
        if (at < 0 || text.IndexOf(find, at + 1, StringComparison.Ordinal) >= 0)
        {
            throw new InvalidOperationException($"'{find}' does not occur exactly once in {path}");
        }

        File.WriteAllText(full, string.Concat(text.AsSpan(0, at), replacement, text.AsSpan(at + find.Length)));
    }

    /// <summary>Deletes <paramref name="path"/>.</summary>
    public void Delete(string path) => File.Delete(Path.Combine(_root, path));

    /// <summary>Loads and checks the project as it is now.</summary>
    public IReadOnlyList<string> Check() => GodotProjectChecker.Check(GodotProject.Load(_root));

    /// <summary>Loads the project as it is now.</summary>
    public GodotProject Load() => GodotProject.Load(_root);

    /// <inheritdoc />
    public void Dispose() => Directory.Delete(_root, recursive: true);
}
