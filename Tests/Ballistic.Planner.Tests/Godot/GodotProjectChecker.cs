using System.Text.RegularExpressions;

namespace Ballistic.Planner.Tests.Godot;

/// <summary>
/// Checks a <see cref="GodotProject"/> without an engine: what its scenes, resources, <c>plugin.cfg</c> and
/// <c>project.godot</c> refer to exists and fits. Each problem is one line,
/// <c>file:line: element: problem</c>, naming the section (e.g. <c>[ext_resource id="1_x"]</c>, <c>node "Floor/Mesh"</c>).
/// </summary>
/// <remarks>
/// Checked: every <c>ext_resource</c> path exists (<c>res://</c> is the project root) and its uid matches the file's;
/// scripts are C# files of ours under <c>addons/ballistic/</c> or <c>Scenes/</c> whose class is named like the file, is
/// <c>partial</c>, concrete, not generic and constructible without arguments; every <c>ExtResource</c> and
/// <c>SubResource</c> used is declared (sub-resources before use); ids are unique in a file and uids across files;
/// node parents are earlier nodes; a node has a known Godot <c>type=</c> or an <c>instance=</c>, not both; every
/// property set on a node or scripted resource is an exported C# member of its script (or its bases among ours) or a
/// property of its Godot type (<see cref="GodotClasses"/>); a script's Godot base fits the node type; connections name
/// existing nodes, and C# (PascalCase) signals and methods that the scripts declare; <c>project.godot</c>'s main scene,
/// autoloads, enabled plugins and every <c>res://</c> path it names exist; each <c>plugin.cfg</c> has name, description,
/// author, version and a <c>[Tool]</c> <c>EditorPlugin</c> script beside it.
/// </remarks>
public sealed partial class GodotProjectChecker
{
    private static readonly string[] ScriptFolders = ["addons/ballistic/", "Scenes/"];
    private static readonly string[] SceneExtensions = [".tscn", ".scn", ".glb", ".gltf", ".fbx", ".blend", ".dae", ".obj"];
    private static readonly string[] ImportedSceneExtensions = [".glb", ".gltf", ".fbx", ".blend", ".dae", ".obj"];
    private static readonly string[] PluginKeys = ["name", "description", "author", "version", "script"];

    /// <summary>Godot classes, beyond <see cref="GodotClasses"/>, that a class of ours may extend (editor and base types).</summary>
    private static readonly string[] OtherGodotBases =
    [
        "GodotObject", "EditorPlugin", "EditorNode3DGizmoPlugin", "EditorNode3DGizmo", "EditorInspectorPlugin",
        "EditorProperty", "EditorScenePostImport", "EditorScenePostImportPlugin", "EditorScript", "Control", "Container",
        "VBoxContainer", "HBoxContainer", "PanelContainer", "MarginContainer", "Button", "Label", "CanvasLayer", "Window",
        "AcceptDialog", "ConfirmationDialog", "ProgressBar", "ImmediateMesh", "ArrayMesh", "Mesh", "Material",
        "StandardMaterial3D",
    ];

    private readonly GodotProject _project;
    private readonly List<string> _issues = [];
    private readonly Dictionary<string, string> _uidToFile = new(StringComparer.Ordinal);
    private readonly Dictionary<string, string> _fileToUid = new(StringComparer.Ordinal);
    private readonly HashSet<CSharpScriptClass> _checkedScripts = [];
    private readonly HashSet<string> _reportedOnce = new(StringComparer.Ordinal);

    private GodotProjectChecker(GodotProject project)
    {
        _project = project;
    }

    /// <summary>Every problem found in <paramref name="project"/>, one line each; empty when it is sound.</summary>
    public static IReadOnlyList<string> Check(GodotProject project)
    {
        var checker = new GodotProjectChecker(project);
        checker.Run();
        return checker._issues;
    }

    [GeneratedRegex("^uid://[a-z0-9]+$")]
    private static partial Regex UidPattern();

    private void Run()
    {
        _issues.AddRange(_project.ParseErrors);
        _issues.AddRange(_project.Scripts.SyntaxErrors);
        CollectUids();
        foreach (GodotFile file in _project.Files)
        {
            switch (file.Kind)
            {
                case GodotFileKind.Scene or GodotFileKind.Resource:
                    CheckSceneOrResource(file);
                    break;
                case GodotFileKind.Config when file.Path.EndsWith("plugin.cfg", StringComparison.Ordinal):
                    CheckPlugin(file);
                    break;
                case GodotFileKind.Config when file.Path == "project.godot":
                    CheckProjectSettings(file);
                    break;
            }
        }

        if (!_project.Exists("project.godot"))
        {
            Report("project.godot", 1, "project", "project.godot is missing at the project root");
        }

        CheckGodotClassesOfOurs();
    }

    private void Report(string file, int line, string element, string problem) => _issues.Add($"{file}:{line}: {element}: {problem}");

    private void ReportOnce(string key, string file, int line, string element, string problem)
    {
        if (_reportedOnce.Add(key))
        {
            Report(file, line, element, problem);
        }
    }

    // ---- uids ---------------------------------------------------------------------------------------------------

    private void CollectUids()
    {
        foreach (GodotFile file in _project.Files.Where(f => f.Kind != GodotFileKind.Config))
        {
            GodotSection header = file.Header!;
            if (header.Attribute("uid") is { } uid)
            {
                AddUid(uid.AsString(), file.Path, file.Path, header.Line, header.Describe());
            }
        }

        foreach ((string path, (string uid, int line)) in _project.UidFiles)
        {
            AddUid(uid, path[..^".uid".Length], path, line, "uid file");
        }

        foreach (GodotFile import in _project.ImportFiles)
        {
            if (import.Section("remap") is { } remap && remap.Property("uid") is { } uid)
            {
                AddUid(uid.Value.AsString(), import.Path[..^".import".Length], import.Path, uid.Line, "[remap] uid");
            }
        }
    }

    private void AddUid(string? uid, string owner, string file, int line, string element)
    {
        if (uid is null || !UidPattern().IsMatch(uid))
        {
            Report(file, line, element, $"uid {uid ?? "(not a string)"} is not of the form uid://[a-z0-9]+");
            return;
        }

        if (_uidToFile.TryGetValue(uid, out string? other))
        {
            Report(file, line, element, $"uid {uid} is not unique: {other} has it too");
            return;
        }

        _uidToFile[uid] = owner;
        _fileToUid[owner] = uid;
    }

    // ---- scenes and resources -------------------------------------------------------------------------------------

    private sealed class NodeInfo(string path, GodotSection section)
    {
        public string Path { get; } = path;

        public GodotSection Section { get; } = section;

        public string? Type { get; set; }

        public CSharpScriptClass? Script { get; set; }

        public bool IsInstance { get; set; }

        /// <summary>True for a node inside an instanced scene (its type and children come from that scene).</summary>
        public bool InInstance { get; set; }

        public string Element => $"node \"{Path}\"";
    }

    private void CheckSceneOrResource(GodotFile file)
    {
        GodotSection header = file.Header!;
        Dictionary<string, GodotSection> ext = UniqueIds(file, file.ExtResources);
        Dictionary<string, GodotSection> sub = UniqueIds(file, file.SubResources);
        foreach (GodotSection resource in file.ExtResources)
        {
            CheckExtResource(file, resource);
        }

        foreach (GodotSection section in file.Sections)
        {
            CheckReferences(file, section, ext, sub);
        }

        foreach (GodotSection resource in file.SubResources)
        {
            if (resource.Property("script") is not null)
            {
                CheckScriptedObject(file, resource, resource.Describe(), resource.AttributeString("type")!, ext);
            }
        }

        if (file.Kind == GodotFileKind.Resource)
        {
            GodotSection resource = file.Section("resource")!;
            CSharpScriptClass? script = CheckScriptedObject(file, resource, "[resource]", header.AttributeString("type")!, ext);
            if (header.AttributeString("script_class") is { } scriptClass)
            {
                if (script is null)
                {
                    Report(file.Path, header.Line, header.Describe(), $"script_class=\"{scriptClass}\" but [resource] has no C# script");
                }
                else if (script.Name != scriptClass)
                {
                    Report(file.Path, header.Line, header.Describe(), $"script_class=\"{scriptClass}\" but the [resource] script's class is {script.Name}");
                }
                else if (!script.Attributes.Contains("GlobalClass"))
                {
                    Report(file.Path, header.Line, header.Describe(), $"script_class=\"{scriptClass}\" names {script.FullName}, which has no [GlobalClass]");
                }
            }

            return;
        }

        Dictionary<string, NodeInfo> nodes = CheckNodes(file, ext);
        foreach (GodotSection connection in file.Connections)
        {
            CheckConnection(file, connection, nodes);
        }

        foreach (GodotSection editable in file.Tagged("editable"))
        {
            string path = editable.AttributeString("path")!;
            if (!nodes.TryGetValue(path, out NodeInfo? node) || !(node.IsInstance || node.InInstance))
            {
                Report(file.Path, editable.Line, editable.Describe(), $"path \"{path}\" is not an instanced node of this scene");
            }
        }
    }

    private Dictionary<string, GodotSection> UniqueIds(GodotFile file, IEnumerable<GodotSection> sections)
    {
        var byId = new Dictionary<string, GodotSection>(StringComparer.Ordinal);
        foreach (GodotSection section in sections)
        {
            string id = section.AttributeString("id")!;
            if (!byId.TryAdd(id, section))
            {
                Report(file.Path, section.Line, section.Describe(), $"id \"{id}\" is already used by the [{section.Tag}] on line {byId[id].Line}");
            }
        }

        return byId;
    }

    private void CheckExtResource(GodotFile file, GodotSection resource)
    {
        string element = resource.Describe();
        string path = resource.AttributeString("path")!;
        string? relative = GodotProject.RelativePath(path);
        if (relative is null)
        {
            Report(file.Path, resource.Line, element, $"path \"{path}\" must start with res://");
            return;
        }

        if (!_project.Exists(relative))
        {
            Report(file.Path, resource.Line, element, $"path {path} does not exist");
        }

        if (resource.Attribute("uid") is { } uidValue)
        {
            string? uid = uidValue.AsString();
            if (uid is null || !UidPattern().IsMatch(uid))
            {
                Report(file.Path, resource.Line, element, $"uid {uidValue} is not of the form uid://[a-z0-9]+");
            }
            else if (_uidToFile.TryGetValue(uid, out string? owner) && owner != relative)
            {
                Report(file.Path, resource.Line, element, $"uid {uid} belongs to res://{owner}, not to {path}");
            }
            else if (_fileToUid.TryGetValue(relative, out string? actual) && actual != uid)
            {
                Report(file.Path, resource.Line, element, $"uid {uid} does not match {path}'s uid {actual}");
            }
        }

        bool isCSharp = relative.EndsWith(".cs", StringComparison.Ordinal);
        string? type = resource.AttributeString("type");
        if (type == "Script" && !isCSharp)
        {
            Report(file.Path, resource.Line, element, $"scripts must be C# files of ours (.cs), found {path}");
        }
        else if (isCSharp && type != "Script")
        {
            Report(file.Path, resource.Line, element, $"a .cs file must be an ext_resource of type=\"Script\", found type=\"{type}\"");
        }

        if (isCSharp && !ScriptFolders.Any(f => relative.StartsWith(f, StringComparison.Ordinal)))
        {
            Report(file.Path, resource.Line, element, $"script {path} is not one of ours (under res://addons/ballistic/ or res://Scenes/)");
        }
    }

    private void CheckReferences(GodotFile file, GodotSection section, Dictionary<string, GodotSection> ext, Dictionary<string, GodotSection> sub)
    {
        IEnumerable<GodotValue> values = section.Attributes.Select(a => a.Value).Concat(section.Properties.Select(p => p.Value));
        foreach (GodotValue value in values.SelectMany(v => v.DescendantsAndSelf()))
        {
            if (!value.TryGetResourceReference(out string kind, out string id))
            {
                continue;
            }

            string element = ElementOf(file, section);
            if (kind == "ExtResource" && !ext.ContainsKey(id))
            {
                Report(file.Path, value.Line, element, $"ExtResource(\"{id}\") is not declared by an [ext_resource]");
            }
            else if (kind == "SubResource")
            {
                if (!sub.TryGetValue(id, out GodotSection? declared))
                {
                    Report(file.Path, value.Line, element, $"SubResource(\"{id}\") is not declared by a [sub_resource]");
                }
                else if (declared.Line >= section.Line)
                {
                    Report(file.Path, value.Line, element, $"SubResource(\"{id}\") is used before its [sub_resource] on line {declared.Line}");
                }
            }
        }
    }

    private static string ElementOf(GodotFile file, GodotSection section)
    {
        if (section.Tag != "node")
        {
            return section.Describe();
        }

        string name = section.AttributeString("name") ?? "";
        string? parent = section.AttributeString("parent");
        string path = parent is null ? "." : parent == "." ? name : $"{parent}/{name}";
        return file.Nodes.First() == section ? $"node \"{name}\" (root)" : $"node \"{path}\"";
    }

    private Dictionary<string, NodeInfo> CheckNodes(GodotFile file, Dictionary<string, GodotSection> ext)
    {
        var nodes = new Dictionary<string, NodeInfo>(StringComparer.Ordinal);
        foreach (GodotSection section in file.Nodes)
        {
            string name = section.AttributeString("name")!;
            string? parent = section.AttributeString("parent");
            string path = parent is null ? "." : parent == "." ? name : $"{parent}/{name}";
            var node = new NodeInfo(path, section);
            string element = parent is null ? $"node \"{name}\" (root)" : node.Element;

            if (name.Length == 0 || name.IndexOfAny(['.', ':', '@', '/', '"', '%']) >= 0)
            {
                Report(file.Path, section.Line, element, $"node name \"{name}\" is empty or holds one of . : @ / \" %");
            }

            if (parent is not null)
            {
                NodeInfo? parentNode = ResolveNode(nodes, parent);
                if (parentNode is null)
                {
                    Report(file.Path, section.Line, element, $"parent \"{parent}\" is not a node declared above it");
                }
                else
                {
                    node.InInstance = parentNode.IsInstance || parentNode.InInstance || !nodes.ContainsKey(parent);
                }
            }

            if (!nodes.TryAdd(path, node))
            {
                Report(file.Path, section.Line, element, $"a node at path \"{path}\" is already declared on line {nodes[path].Section.Line}");
            }

            ResolveNodeType(file, section, node, element, ext);
            // `script = null` removes an instanced scene's script; an unreadable script leaves the exports unknown.
            GodotProperty? script = section.Property("script");
            bool exportsKnown = true;
            if (script is { Value.Kind: GodotValueKind.Null })
            {
                node.Script = null;
            }
            else if (script is not null)
            {
                node.Script = ResolveScript(file, script, element, ext);
                exportsKnown = node.Script is not null;
                if (node.Script is not null && node.Type is not null)
                {
                    CheckScriptFitsType(file, section.Line, element, node.Script, node.Type);
                }
            }

            if (exportsKnown)
            {
                CheckProperties(file, section, element, node.Type, node.Script);
            }
        }

        return nodes;
    }

    private static NodeInfo? ResolveNode(Dictionary<string, NodeInfo> nodes, string path)
    {
        if (nodes.TryGetValue(path, out NodeInfo? node))
        {
            return node;
        }

        // A path below an instanced node (editable children) cannot be checked further here.
        string[] parts = path.Split('/');
        for (int length = parts.Length - 1; length >= 1; length--)
        {
            if (nodes.TryGetValue(string.Join('/', parts.Take(length)), out NodeInfo? prefix))
            {
                return prefix.IsInstance || prefix.InInstance ? prefix : null;
            }
        }

        return nodes.TryGetValue(".", out NodeInfo? root) && (root.IsInstance || root.InInstance) ? root : null;
    }

    private void ResolveNodeType(GodotFile file, GodotSection section, NodeInfo node, string element, Dictionary<string, GodotSection> ext)
    {
        string? type = section.AttributeString("type");
        GodotValue? instance = section.Attribute("instance");
        if (section.Attribute("type") is { } typeValue && type is null)
        {
            Report(file.Path, section.Line, element, $"type must be a string, found {typeValue}");
        }

        if (type is not null && instance is not null)
        {
            Report(file.Path, section.Line, element, "has both type= and instance= (an instanced scene's type comes from that scene)");
        }

        // Godot's instance_placeholder (a scene loaded later, on demand) must name a scene file of the project, as instance= must.
        if (section.AttributeString("instance_placeholder") is { } placeholder
            && (GodotProject.RelativePath(placeholder) is not { } placeholderPath || !_project.Exists(placeholderPath)))
        {
            Report(file.Path, section.Line, element, $"instance_placeholder {placeholder} does not exist");
        }

        if (type is not null)
        {
            if (GodotClasses.IsKnown(type))
            {
                node.Type = type;
            }
            else
            {
                Report(file.Path, section.Line, element, $"type \"{type}\" is not a Godot class known to GodotClasses (add it there, with its parent and properties, after checking the class reference)");
            }
        }
        else if (instance is not null)
        {
            node.IsInstance = true;
            if (!instance.TryGetResourceReference(out string kind, out string id) || kind != "ExtResource")
            {
                Report(file.Path, section.Line, element, $"instance must be ExtResource(\"id\"), found {instance}");
            }
            else if (ext.TryGetValue(id, out GodotSection? resource) && GodotProject.RelativePath(resource.AttributeString("path")!) is { } scenePath)
            {
                if (!SceneExtensions.Any(e => scenePath.EndsWith(e, StringComparison.OrdinalIgnoreCase)))
                {
                    Report(file.Path, section.Line, element, $"instance must be a scene (.tscn or an imported 3D scene), found res://{scenePath}");
                }
                else
                {
                    (node.Type, node.Script) = InstancedRoot(scenePath, 0);
                }
            }
        }
        else if (!node.InInstance)
        {
            Report(file.Path, section.Line, element, "has neither type= nor instance= (only nodes inside an instanced scene may omit both)");
        }
    }

    /// <summary>The Godot type and C# script of the root of the scene at <paramref name="scenePath"/>, as far as known.</summary>
    private (string? Type, CSharpScriptClass? Script) InstancedRoot(string scenePath, int depth)
    {
        if (ImportedSceneExtensions.Any(e => scenePath.EndsWith(e, StringComparison.OrdinalIgnoreCase)))
        {
            // An imported 3D scene's root is a Node3D unless its import settings choose another root type.
            string? rootType = _project.FileAt(scenePath + ".import")?.Section("params")?.Property("nodes/root_type")?.Value.AsString();
            string imported = string.IsNullOrEmpty(rootType) ? "Node3D" : rootType;
            return (GodotClasses.IsKnown(imported) ? imported : null, null);
        }

        if (depth > 8 || _project.FileAt(scenePath) is not { Kind: GodotFileKind.Scene } scene || scene.Nodes.FirstOrDefault() is not { } root)
        {
            return (null, null);
        }

        string? type = root.AttributeString("type");
        CSharpScriptClass? script = null;
        if (type is null && root.Attribute("instance") is { } instance && ExtResourcePath(scene, instance) is { } innerScene)
        {
            (type, script) = InstancedRoot(innerScene, depth + 1);
        }

        if (root.Property("script")?.Value is { } scriptValue && ExtResourcePath(scene, scriptValue) is { } scriptFile)
        {
            script = _project.Scripts.ClassInFile(scriptFile, Path.GetFileNameWithoutExtension(scriptFile)) ?? script;
        }

        return (GodotClasses.IsKnown(type ?? "") ? type : null, script);
    }

    /// <summary>The repository-relative path of the file <paramref name="reference"/> (an <c>ExtResource("id")</c>) names in <paramref name="file"/>.</summary>
    private static string? ExtResourcePath(GodotFile file, GodotValue reference) =>
        reference.TryGetResourceReference(out string kind, out string id) && kind == "ExtResource"
            && file.ExtResources.FirstOrDefault(e => e.AttributeString("id") == id)?.AttributeString("path") is { } path
            ? GodotProject.RelativePath(path)
            : null;

    /// <summary>The C# class of the script a <c>script = ExtResource("id")</c> property names; reports what is wrong with it.</summary>
    private CSharpScriptClass? ResolveScript(GodotFile file, GodotProperty script, string element, Dictionary<string, GodotSection> ext)
    {
        if (!script.Value.TryGetResourceReference(out string kind, out string id) || kind != "ExtResource")
        {
            Report(file.Path, script.Line, element, $"script must be ExtResource(\"id\") naming a .cs file of ours, found {script.Value}");
            return null;
        }

        if (!ext.TryGetValue(id, out GodotSection? resource) || GodotProject.RelativePath(resource.AttributeString("path")!) is not { } relative
            || !relative.EndsWith(".cs", StringComparison.Ordinal) || !_project.Exists(relative))
        {
            return null; // Reported with the ext_resource or the reference.
        }

        string className = Path.GetFileNameWithoutExtension(relative);
        CSharpScriptClass? cls = _project.Scripts.ClassInFile(relative, className);
        if (cls is null)
        {
            ReportOnce($"noclass:{file.Path}:{relative}", file.Path, resource.Line, resource.Describe(),
                $"script res://{relative} declares no top-level class {className} (Godot .NET finds a script's class by its file name)");
            return null;
        }

        CheckScriptClass(cls, $"script res://{relative}");
        return cls;
    }

    private void CheckScriptClass(CSharpScriptClass cls, string usedAs)
    {
        if (!_checkedScripts.Add(cls))
        {
            return;
        }

        string element = $"class {cls.Name}";
        if (!cls.IsPartial)
        {
            Report(cls.File, cls.Line, element, $"{usedAs}'s class must be partial (Godot's source generators extend it)");
        }

        if (cls.IsAbstract)
        {
            Report(cls.File, cls.Line, element, $"{usedAs}'s class is abstract, so Godot cannot instantiate it");
        }

        if (cls.IsGeneric)
        {
            Report(cls.File, cls.Line, element, $"{usedAs}'s class is generic, which Godot scripts cannot be");
        }

        if (!cls.HasParameterlessConstructor)
        {
            Report(cls.File, cls.Line, element, $"{usedAs}'s class has no parameterless constructor, which Godot needs to instantiate it");
        }

        string? native = _project.Scripts.NativeBaseOf(cls);
        if (native is null || !(GodotClasses.IsKnown(native) || OtherGodotBases.Contains(native)))
        {
            Report(cls.File, cls.Line, element, $"{usedAs}'s class extends {native ?? "nothing"}, which is neither one of our classes nor a Godot class known to GodotClasses");
        }
    }

    private void CheckScriptFitsType(GodotFile file, int line, string element, CSharpScriptClass script, string type)
    {
        string? native = _project.Scripts.NativeBaseOf(script);
        if (native is not null && GodotClasses.IsKnown(native) && !GodotClasses.Inherits(type, native))
        {
            Report(file.Path, line, element, $"script class {script.Name} extends {native}, but the type here is {type}, which is not a {native}");
        }
        else if (native is not null && !GodotClasses.IsKnown(native) && OtherGodotBases.Contains(native))
        {
            Report(file.Path, line, element, $"script class {script.Name} extends {native}, which cannot be attached to a {type}");
        }
    }

    /// <summary>Checks a sub-resource or [resource] that may carry a C# script; returns the script's class.</summary>
    private CSharpScriptClass? CheckScriptedObject(GodotFile file, GodotSection section, string element, string type, Dictionary<string, GodotSection> ext)
    {
        GodotProperty? property = section.Property("script");
        CSharpScriptClass? script = property is null or { Value.Kind: GodotValueKind.Null } ? null : ResolveScript(file, property, element, ext);
        if (property is not null && property.Value.Kind != GodotValueKind.Null && script is null)
        {
            return null; // Reported where the script is resolved; its exports are unknown.
        }

        if (script is not null)
        {
            if (!GodotClasses.IsKnown(type))
            {
                Report(file.Path, section.Line, element, $"type \"{type}\" of this scripted resource is not a Godot class known to GodotClasses (add it there to check its properties)");
                return script;
            }

            CheckScriptFitsType(file, section.Line, element, script, type);
        }

        if (script is not null || section.Tag == "resource")
        {
            CheckProperties(file, section, element, GodotClasses.IsKnown(type) ? type : null, script);
        }

        return script;
    }

    private void CheckProperties(GodotFile file, GodotSection section, string element, string? type, CSharpScriptClass? script)
    {
        IReadOnlyDictionary<string, CSharpScriptClass> exports = script is null
            ? new Dictionary<string, CSharpScriptClass>()
            : _project.Scripts.ExportsOf(script);
        var seen = new Dictionary<string, int>(StringComparer.Ordinal);
        foreach (GodotProperty property in section.Properties)
        {
            if (!seen.TryAdd(property.Key, property.Line))
            {
                Report(file.Path, property.Line, element, $"property \"{property.Key}\" is set twice (also on line {seen[property.Key]})");
            }

            if (property.Key == "script" || exports.ContainsKey(property.Key) || type is null || GodotClasses.HasProperty(type, property.Key))
            {
                continue;
            }

            string near = exports.Keys.FirstOrDefault(e => Normalize(e) == Normalize(property.Key)) is { } match
                ? $" (the C# member is {match}: scenes use the C# name verbatim)"
                : "";
            Report(file.Path, property.Line, element, script is null
                ? $"property \"{property.Key}\" is not a property of Godot class {type}{near}"
                : $"property \"{property.Key}\" is neither an [Export] member of {script.FullName} (or its bases) nor a property of Godot class {type}{near}");
        }
    }

    private static string Normalize(string name) => name.Replace("_", "", StringComparison.Ordinal).ToUpperInvariant();

    private void CheckConnection(GodotFile file, GodotSection connection, Dictionary<string, NodeInfo> nodes)
    {
        string element = connection.Describe();
        NodeInfo? from = ResolveConnectionNode(file, connection, "from", nodes);
        NodeInfo? to = ResolveConnectionNode(file, connection, "to", nodes);
        string signal = connection.AttributeString("signal")!;
        string method = connection.AttributeString("method")!;
        if (signal.Length == 0 || method.Length == 0)
        {
            Report(file.Path, connection.Line, element, "signal and method must not be empty");
            return;
        }

        // Built-in signals and methods are snake_case; a PascalCase name is a C# one and must be declared by the script.
        if (from is { InInstance: false } && char.IsUpper(signal[0])
            && (from.Script is null || !_project.Scripts.Chain(from.Script).Any(c => c.Signals.Contains(signal))))
        {
            Report(file.Path, connection.Line, element, from.Script is null
                ? $"signal {signal} looks like a C# signal, but node \"{from.Path}\" has no C# script"
                : $"signal {signal} is not a [Signal] of {from.Script.FullName} (declare {signal}EventHandler)");
        }

        if (to is { InInstance: false } && char.IsUpper(method[0])
            && (to.Script is null || !_project.Scripts.Chain(to.Script).Any(c => c.Methods.Contains(method))))
        {
            Report(file.Path, connection.Line, element, to.Script is null
                ? $"method {method} looks like a C# method, but node \"{to.Path}\" has no C# script"
                : $"method {method} is not declared by {to.Script.FullName} or its bases");
        }
    }

    private NodeInfo? ResolveConnectionNode(GodotFile file, GodotSection connection, string attribute, Dictionary<string, NodeInfo> nodes)
    {
        string path = connection.AttributeString(attribute)!;
        NodeInfo? node = ResolveNode(nodes, path);
        if (node is null)
        {
            Report(file.Path, connection.Line, connection.Describe(), $"{attribute}=\"{path}\" is not a node of this scene");
        }

        return node is not null && node.Path != path ? new NodeInfo(path, node.Section) { InInstance = true } : node;
    }

    // ---- plugin.cfg and project.godot ---------------------------------------------------------------------------

    private void CheckPlugin(GodotFile file)
    {
        GodotSection? plugin = file.Section("plugin");
        if (plugin is null)
        {
            Report(file.Path, 1, "plugin.cfg", "has no [plugin] section");
            return;
        }

        foreach (string key in PluginKeys)
        {
            GodotProperty? property = plugin.Property(key);
            if (property?.Value.AsString() is not { Length: > 0 })
            {
                Report(file.Path, property?.Line ?? plugin.Line, "[plugin]", $"{key}=\"…\" is missing or not a non-empty string");
            }
        }

        if (plugin.Property("script") is not { } scriptProperty || scriptProperty.Value.AsString() is not { Length: > 0 } script)
        {
            return;
        }

        string folder = file.Path.Contains('/', StringComparison.Ordinal) ? file.Path[..(file.Path.LastIndexOf('/') + 1)] : "";
        string relative = folder + script;
        if (script.Contains("://", StringComparison.Ordinal) || script.Contains('/', StringComparison.Ordinal) || !script.EndsWith(".cs", StringComparison.Ordinal))
        {
            Report(file.Path, scriptProperty.Line, "[plugin] script", $"script \"{script}\" must be a .cs file named relative to plugin.cfg, beside it");
            return;
        }

        if (!_project.Exists(relative))
        {
            Report(file.Path, scriptProperty.Line, "[plugin] script", $"script {script} does not exist beside plugin.cfg (res://{relative})");
            return;
        }

        string className = Path.GetFileNameWithoutExtension(script);
        CSharpScriptClass? cls = _project.Scripts.ClassInFile(relative, className);
        if (cls is null)
        {
            Report(file.Path, scriptProperty.Line, "[plugin] script", $"res://{relative} declares no top-level class {className} (built with TOOLS defined)");
            return;
        }

        CheckScriptClass(cls, $"plugin script res://{relative}");
        if (!cls.Attributes.Contains("Tool"))
        {
            Report(cls.File, cls.Line, $"class {cls.Name}", "an editor plugin's class needs [Tool]");
        }

        if (_project.Scripts.NativeBaseOf(cls) != "EditorPlugin")
        {
            Report(cls.File, cls.Line, $"class {cls.Name}", $"an editor plugin's class must extend EditorPlugin, found {_project.Scripts.NativeBaseOf(cls) ?? "nothing"}");
        }
    }

    private void CheckProjectSettings(GodotFile file)
    {
        GodotProperty? version = file.Section("")?.Property("config_version");
        if (version?.Value is not { Kind: GodotValueKind.Int, Int: 5 })
        {
            Report(file.Path, version?.Line ?? 1, "config_version", $"config_version=5 (Godot 4) is expected, found {version?.Value.ToString() ?? "none"}");
        }

        GodotProperty? mainScene = file.Section("application")?.Property("run/main_scene");
        if (mainScene?.Value.AsString() is not { } main)
        {
            Report(file.Path, mainScene?.Line ?? 1, "[application] run/main_scene", "run/main_scene=\"res://….tscn\" is missing");
        }
        else
        {
            string? scene = main.StartsWith("uid://", StringComparison.Ordinal) ? _uidToFile.GetValueOrDefault(main) : GodotProject.RelativePath(main);
            if (scene is null || !_project.Exists(scene))
            {
                Report(file.Path, mainScene!.Line, "[application] run/main_scene", $"main scene {main} does not exist");
            }
            else if (!scene.EndsWith(".tscn", StringComparison.Ordinal) && !scene.EndsWith(".scn", StringComparison.Ordinal))
            {
                Report(file.Path, mainScene!.Line, "[application] run/main_scene", $"main scene {main} is not a scene");
            }
        }

        foreach (GodotProperty autoload in file.Section("autoload")?.Properties ?? [])
        {
            CheckAutoload(file, autoload);
        }

        foreach (GodotProperty enabled in file.Section("editor_plugins")?.Properties.Where(p => p.Key == "enabled") ?? [])
        {
            foreach (string plugin in enabled.Value.Strings().Where(p => !p.EndsWith("plugin.cfg", StringComparison.Ordinal)))
            {
                Report(file.Path, enabled.Line, "[editor_plugins] enabled", $"{plugin} is not a plugin.cfg");
            }
        }

        // Every other res:// path the settings name must exist too (the main scene and autoloads are checked above).
        foreach (GodotSection section in file.Sections.Where(s => s.Tag != "autoload"))
        {
            foreach (GodotProperty property in section.Properties.Where(p => p != mainScene))
            {
                foreach (string path in property.Value.Strings().Where(s => s.StartsWith("res://", StringComparison.Ordinal)))
                {
                    string relative = GodotProject.RelativePath(path.TrimStart('*'))!;
                    if (relative.StartsWith(".godot/", StringComparison.Ordinal) || relative.Length == 0)
                    {
                        continue;
                    }

                    if (!_project.Exists(relative) && !_project.FolderExists(relative))
                    {
                        Report(file.Path, property.Line, $"[{section.Tag}] {property.Key}", $"{path} does not exist");
                    }
                }
            }
        }

        if (file.Section("dotnet")?.Property("project/assembly_name") is { } assembly && assembly.Value.AsString() is { } name)
        {
            if (!_project.Exists(name + ".csproj"))
            {
                Report(file.Path, assembly.Line, "[dotnet] project/assembly_name", $"Godot builds {name}.csproj, which is not at the project root");
            }

            if (file.Section("dotnet")?.Property("project/solution_directory") is { } solutionDirectory && solutionDirectory.Value.AsString() is { } folder
                && !(_project.FolderExists(folder) && (File.Exists(Path.Combine(_project.Root, folder, name + ".sln")) || File.Exists(Path.Combine(_project.Root, folder, name + ".slnx")))))
            {
                Report(file.Path, solutionDirectory.Line, "[dotnet] project/solution_directory", $"{folder}/{name}.sln, the editor's solution, does not exist");
            }
        }
    }

    private void CheckAutoload(GodotFile file, GodotProperty autoload)
    {
        string element = $"[autoload] {autoload.Key}";
        string? value = autoload.Value.AsString();
        string? relative = value is null ? null : GodotProject.RelativePath(value.TrimStart('*'));
        if (relative is null)
        {
            Report(file.Path, autoload.Line, element, $"an autoload is \"*res://path\" (a .tscn or .cs), found {autoload.Value}");
            return;
        }

        if (!_project.Exists(relative))
        {
            Report(file.Path, autoload.Line, element, $"res://{relative} does not exist");
            return;
        }

        if (relative.EndsWith(".cs", StringComparison.Ordinal))
        {
            string className = Path.GetFileNameWithoutExtension(relative);
            CSharpScriptClass? cls = _project.Scripts.ClassInFile(relative, className);
            if (cls is null)
            {
                Report(file.Path, autoload.Line, element, $"res://{relative} declares no top-level class {className}");
                return;
            }

            CheckScriptClass(cls, $"autoload res://{relative}");
            if (_project.Scripts.NativeBaseOf(cls) is { } native && GodotClasses.IsKnown(native) && !GodotClasses.Inherits(native, "Node"))
            {
                Report(file.Path, autoload.Line, element, $"an autoload must be a Node; {cls.Name} extends {native}");
            }
        }
        else if (!relative.EndsWith(".tscn", StringComparison.Ordinal) && !relative.EndsWith(".scn", StringComparison.Ordinal))
        {
            Report(file.Path, autoload.Line, element, $"an autoload is a scene or a C# script, found res://{relative}");
        }
    }

    // ---- classes of ours ------------------------------------------------------------------------------------------

    private void CheckGodotClassesOfOurs()
    {
        foreach (CSharpScriptClass cls in _project.Scripts.Classes.Where(c => !c.IsNested))
        {
            string? native = _project.Scripts.NativeBaseOf(cls);
            bool godotBase = native is not null && (GodotClasses.IsKnown(native) || OtherGodotBases.Contains(native));
            bool global = cls.Attributes.Contains("GlobalClass");
            if (!godotBase && !global && !cls.Attributes.Contains("Tool"))
            {
                continue;
            }

            string element = $"class {cls.Name}";
            if (!cls.IsPartial && !_checkedScripts.Contains(cls))
            {
                Report(cls.File, cls.Line, element, $"extends Godot class {native ?? "(none)"} but is not partial (Godot's source generators extend it)");
            }

            bool node = native is not null && GodotClasses.IsKnown(native) && GodotClasses.Inherits(native, "Node");
            if ((global || node) && !cls.HasParameterlessConstructor && !_checkedScripts.Contains(cls))
            {
                Report(cls.File, cls.Line, element, "has no parameterless constructor, which Godot needs to create it from the editor or a scene");
            }

            if (global && Path.GetFileNameWithoutExtension(cls.File) != cls.Name)
            {
                Report(cls.File, cls.Line, element, $"a [GlobalClass] must live in a file named {cls.Name}.cs");
            }

            if (global && !godotBase)
            {
                Report(cls.File, cls.Line, element, $"[GlobalClass] on a class that extends {native ?? "nothing"}, not a Godot class");
            }
        }
    }
}
