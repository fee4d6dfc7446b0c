namespace Ballistic.Planner.Tests.Godot;

/// <summary>
/// One bracketed section of a Godot text file, <c>[tag attr=value …]</c>, with the <c>key = value</c> properties that
/// follow it. ConfigFile properties written before any header belong to a section whose <see cref="Tag"/> is empty.
/// </summary>
public sealed class GodotSection
{
    internal GodotSection(
        string tag, int line, IReadOnlyList<KeyValuePair<string, GodotValue>> attributes, IReadOnlyList<GodotProperty> properties)
    {
        Tag = tag;
        Line = line;
        Attributes = attributes;
        Properties = properties;
    }

    /// <summary>The section's tag: <c>gd_scene</c>, <c>ext_resource</c>, <c>node</c>, <c>application</c>, …</summary>
    public string Tag { get; }

    /// <summary>The 1-based line of the header (1 for the implicit leading ConfigFile section).</summary>
    public int Line { get; }

    /// <summary>The header's attributes in written order.</summary>
    public IReadOnlyList<KeyValuePair<string, GodotValue>> Attributes { get; }

    /// <summary>The properties in written order.</summary>
    public IReadOnlyList<GodotProperty> Properties { get; }

    /// <summary>The attribute <paramref name="name"/>, or null.</summary>
    public GodotValue? Attribute(string name) =>
        Attributes.Where(a => a.Key == name).Select(a => a.Value).FirstOrDefault();

    /// <summary>The attribute <paramref name="name"/> when it is a string, or null.</summary>
    public string? AttributeString(string name) => Attribute(name)?.AsString();

    /// <summary>The last property named <paramref name="key"/> (Godot keeps the last), or null.</summary>
    public GodotProperty? Property(string key) => Properties.LastOrDefault(p => p.Key == key);

    /// <summary>The section for messages, e.g. <c>[ext_resource id="1_x"]</c> or <c>[node name="Floor" parent="."]</c>.</summary>
    public string Describe()
    {
        string[] keys = Tag switch
        {
            "ext_resource" or "sub_resource" => ["id"],
            "node" => ["name", "parent"],
            "connection" => ["signal", "from", "to", "method"],
            "editable" => ["path"],
            _ => [],
        };
        string attributes = string.Concat(keys
            .Select(k => (Key: k, Value: AttributeString(k)))
            .Where(a => a.Value is not null)
            .Select(a => $" {a.Key}=\"{a.Value}\""));
        return Tag.Length == 0 ? "(top of file)" : $"[{Tag}{attributes}]";
    }

    /// <inheritdoc />
    public override string ToString() => Describe();
}
