namespace Ballistic.Planner.Tests.Godot;

/// <summary>
/// A parsed Godot text file: a <c>.tscn</c> scene or <c>.tres</c> resource (format 3, or 4 when it holds base64 packed
/// arrays), or a ConfigFile such as <c>plugin.cfg</c>, <c>project.godot</c> or a <c>.import</c> file. Parsing checks
/// the syntax and the shape of scenes and resources (which sections may appear, their required attributes, one root
/// node first); what the file refers to is checked by <see cref="GodotProjectChecker"/>.
/// </summary>
public sealed class GodotFile
{
    private static readonly string[] SceneTags = ["gd_scene", "ext_resource", "sub_resource", "node", "connection", "editable"];
    private static readonly string[] ResourceTags = ["gd_resource", "ext_resource", "sub_resource", "resource"];

    private GodotFile(string path, GodotFileKind kind, IReadOnlyList<GodotSection> sections)
    {
        Path = path;
        Kind = kind;
        Sections = sections;
    }

    /// <summary>The file's name as given to <see cref="Parse"/> (repository-relative, with '/', for repository files).</summary>
    public string Path { get; }

    /// <summary>Which format the file is.</summary>
    public GodotFileKind Kind { get; }

    /// <summary>Every section in written order (for scenes and resources the header comes first).</summary>
    public IReadOnlyList<GodotSection> Sections { get; }

    /// <summary>The <c>[gd_scene]</c> or <c>[gd_resource]</c> header; null for ConfigFiles.</summary>
    public GodotSection? Header => Kind == GodotFileKind.Config ? null : Sections[0];

    /// <summary>The <c>[ext_resource]</c> sections.</summary>
    public IEnumerable<GodotSection> ExtResources => Tagged("ext_resource");

    /// <summary>The <c>[sub_resource]</c> sections.</summary>
    public IEnumerable<GodotSection> SubResources => Tagged("sub_resource");

    /// <summary>The <c>[node]</c> sections; the first is the root.</summary>
    public IEnumerable<GodotSection> Nodes => Tagged("node");

    /// <summary>The <c>[connection]</c> sections.</summary>
    public IEnumerable<GodotSection> Connections => Tagged("connection");

    /// <summary>The sections tagged <paramref name="tag"/>, in order.</summary>
    public IEnumerable<GodotSection> Tagged(string tag) => Sections.Where(s => s.Tag == tag);

    /// <summary>The first section tagged <paramref name="tag"/>, or null.</summary>
    public GodotSection? Section(string tag) => Sections.FirstOrDefault(s => s.Tag == tag);

    /// <summary>
    /// Parses <paramref name="text"/>; <paramref name="path"/> names the file in errors and picks the format by its
    /// extension (<c>.tscn</c> scene, <c>.tres</c> resource, anything else a ConfigFile).
    /// </summary>
    /// <exception cref="GodotFormatException">The text is malformed: the one-line message names file, line and problem.</exception>
    public static GodotFile Parse(string text, string path)
    {
        GodotFileKind kind = path.EndsWith(".tscn", StringComparison.OrdinalIgnoreCase) ? GodotFileKind.Scene
            : path.EndsWith(".tres", StringComparison.OrdinalIgnoreCase) ? GodotFileKind.Resource
            : GodotFileKind.Config;
        List<GodotSection> sections = GodotTextReader.ReadSections(text, path);
        var file = new GodotFile(path, kind, sections);
        file.CheckShape();
        return file;
    }

    /// <summary>Reads and parses <paramref name="fullPath"/>, naming it <paramref name="path"/> in errors.</summary>
    /// <exception cref="GodotFormatException">The file is malformed.</exception>
    public static GodotFile Load(string fullPath, string path) => Parse(File.ReadAllText(fullPath), path);

    /// <summary>One value in Godot's text syntax, e.g. <c>Transform3D(1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0)</c>.</summary>
    /// <exception cref="GodotFormatException">The text is not one well-formed value.</exception>
    public static GodotValue ParseValue(string text, string path = "value") => GodotTextReader.ReadValue(text, path);

    private void CheckShape()
    {
        if (Kind == GodotFileKind.Config)
        {
            return;
        }

        string headerTag = Kind == GodotFileKind.Scene ? "gd_scene" : "gd_resource";
        string[] allowed = Kind == GodotFileKind.Scene ? SceneTags : ResourceTags;
        if (Sections.Count == 0)
        {
            throw Error(1, $"empty file: a {(Kind == GodotFileKind.Scene ? "scene" : "resource")} starts with [{headerTag} …]");
        }

        GodotSection header = Sections[0];
        if (header.Tag != headerTag)
        {
            throw Error(header.Line, header.Tag.Length == 0
                ? $"properties before the [{headerTag} …] header"
                : $"the file must start with [{headerTag} …], found [{header.Tag} …]");
        }

        GodotValue? format = header.Attribute("format");
        if (format is null || format.Kind != GodotValueKind.Int || format.Int is not (3 or 4))
        {
            throw Error(header.Line, $"[{headerTag}] needs format=3 (Godot 4 text format), found {format?.ToString() ?? "none"}");
        }

        if (Kind == GodotFileKind.Resource)
        {
            Require(header, "type");
        }

        bool seenRoot = false;
        bool seenResource = false;
        foreach (GodotSection section in Sections)
        {
            if (section != header && section.Tag == headerTag)
            {
                throw Error(section.Line, $"a second [{headerTag}] header");
            }

            if (!allowed.Contains(section.Tag))
            {
                throw Error(section.Line, $"[{section.Tag}] does not belong in a {(Kind == GodotFileKind.Scene ? ".tscn scene" : ".tres resource")}");
            }

            if (section.Tag is "gd_scene" or "gd_resource" or "ext_resource" or "connection" or "editable" && section.Properties.Count > 0)
            {
                throw Error(section.Properties[0].Line, $"{section.Describe()} takes no properties, found '{section.Properties[0].Key}'");
            }

            switch (section.Tag)
            {
                case "ext_resource":
                    Require(section, "path");
                    Require(section, "id");
                    break;
                case "sub_resource":
                    Require(section, "type");
                    Require(section, "id");
                    break;
                case "node":
                    Require(section, "name");
                    if (section.Attribute("parent") is null)
                    {
                        if (seenRoot)
                        {
                            throw Error(section.Line, $"{section.Describe()} has no parent, but the scene already has its root node");
                        }
                    }
                    else
                    {
                        Require(section, "parent");
                        if (!seenRoot)
                        {
                            throw Error(section.Line, $"{section.Describe()}: the first node is the scene's root and has no parent");
                        }
                    }

                    seenRoot = true;
                    break;
                case "connection":
                    Require(section, "signal");
                    Require(section, "from");
                    Require(section, "to");
                    Require(section, "method");
                    break;
                case "editable":
                    Require(section, "path");
                    break;
                case "resource":
                    if (seenResource)
                    {
                        throw Error(section.Line, "a second [resource] section");
                    }

                    seenResource = true;
                    break;
            }
        }

        if (Kind == GodotFileKind.Resource && !seenResource)
        {
            throw Error(header.Line, "a .tres resource needs a [resource] section");
        }
    }

    private void Require(GodotSection section, string attribute)
    {
        GodotValue? value = section.Attribute(attribute);
        if (value is null)
        {
            throw Error(section.Line, $"{section.Describe()} needs the attribute {attribute}=\"…\"");
        }

        if (!value.IsText)
        {
            throw Error(section.Line, $"{section.Describe()}: {attribute} must be a string, found {value}");
        }
    }

    private GodotFormatException Error(int line, string problem) => new(Path, line, problem);
}
