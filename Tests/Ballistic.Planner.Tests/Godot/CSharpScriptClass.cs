namespace Ballistic.Planner.Tests.Godot;

/// <summary>
/// A C# class declared in the Godot project's sources, as read from their syntax (the sources cannot be compiled
/// here): what Godot needs of a script class and what a scene may set on it. Partial declarations are merged.
/// </summary>
public sealed class CSharpScriptClass
{
    internal CSharpScriptClass(string name, string ns, string fullName, bool isNested)
    {
        Name = name;
        Namespace = ns;
        FullName = fullName;
        IsNested = isNested;
    }

    /// <summary>The class name, e.g. <c>JumpRoadmap3D</c>.</summary>
    public string Name { get; }

    /// <summary>The namespace, e.g. <c>Ballistic.Addon</c> (empty for the global namespace).</summary>
    public string Namespace { get; }

    /// <summary>Namespace, containing classes and name, dot-separated.</summary>
    public string FullName { get; }

    /// <summary>True for a class declared inside another class.</summary>
    public bool IsNested { get; }

    /// <summary>Repository-relative files ('/'-separated) holding a declaration, in the order read.</summary>
    public List<string> Files { get; } = [];

    /// <summary>The file of the first declaration.</summary>
    public string File => Files[0];

    /// <summary>The 1-based line of the first declaration.</summary>
    public int Line { get; internal set; }

    /// <summary>True when every declaration is <c>partial</c> (Godot's source generators need it).</summary>
    public bool IsPartial { get; internal set; } = true;

    /// <summary>True when a declaration is <c>abstract</c>.</summary>
    public bool IsAbstract { get; internal set; }

    /// <summary>True when the class has type parameters.</summary>
    public bool IsGeneric { get; internal set; }

    /// <summary>The attributes on the class, by simple name without the <c>Attribute</c> suffix (<c>GlobalClass</c>, <c>Tool</c>).</summary>
    public HashSet<string> Attributes { get; } = new(StringComparer.Ordinal);

    /// <summary>The simple name of the first type in the base list (a class or an interface), or null.</summary>
    public string? BaseTypeName { get; internal set; }

    /// <summary>
    /// Members marked <c>[Export]</c>, <c>[ExportStorage]</c> or <c>[ExportToolButton]</c> (properties and fields), by
    /// C# name (which is also their property name in scenes), with their 1-based line.
    /// </summary>
    public Dictionary<string, int> Exports { get; } = new(StringComparer.Ordinal);

    /// <summary>The names of the methods declared.</summary>
    public HashSet<string> Methods { get; } = new(StringComparer.Ordinal);

    /// <summary>The signals declared: each <c>[Signal]</c> delegate's name without the <c>EventHandler</c> suffix.</summary>
    public HashSet<string> Signals { get; } = new(StringComparer.Ordinal);

    /// <summary>
    /// True when the class can be made with no arguments: no instance constructor (the implicit one), or one with no
    /// parameters; a primary constructor with parameters and no parameterless constructor makes this false.
    /// </summary>
    public bool HasParameterlessConstructor =>
        (!HasConstructorWithParameters && !HasPrimaryConstructorWithParameters) || HasDeclaredParameterlessConstructor;

    internal bool HasConstructorWithParameters { get; set; }

    internal bool HasPrimaryConstructorWithParameters { get; set; }

    internal bool HasDeclaredParameterlessConstructor { get; set; }

    /// <inheritdoc />
    public override string ToString() => FullName;
}
