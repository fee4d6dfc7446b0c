using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace Ballistic.Planner.Tests.Godot;

/// <summary>
/// The classes of the Godot project's C# sources, read as Roslyn syntax trees (no compilation: GodotSharp is not
/// available here). Sources are parsed as an editor build sees them (<c>TOOLS</c> and <c>GODOT</c> defined), with the
/// newest language version this Roslyn knows.
/// </summary>
public sealed class CSharpScripts
{
    private static readonly string[] ExportAttributes = ["Export", "ExportStorage", "ExportToolButton"];

    private static readonly CSharpParseOptions Options = new(
        LanguageVersion.Preview,
        DocumentationMode.None,
        SourceCodeKind.Regular,
        ["TOOLS", "GODOT", "GODOT4", "GODOT4_OR_GREATER", "GODOT4_7", "GODOT4_7_OR_GREATER", "GODOT_LINUXBSD", "GODOT_PC", "DEBUG"]);

    private readonly Dictionary<string, CSharpScriptClass> _byFullName = new(StringComparer.Ordinal);
    private readonly List<CSharpScriptClass> _classes = [];
    private readonly List<string> _syntaxErrors = [];
    private readonly Dictionary<string, List<CSharpScriptClass>> _topLevelByFile = new(StringComparer.Ordinal);

    private CSharpScripts()
    {
    }

    /// <summary>Every class, in the order first declared.</summary>
    public IReadOnlyList<CSharpScriptClass> Classes => _classes;

    /// <summary>One line per syntax error: <c>file:line: C# syntax error CSxxxx: message</c>.</summary>
    public IReadOnlyList<string> SyntaxErrors => _syntaxErrors;

    /// <summary>Reads <paramref name="sources"/>: (repository-relative path with '/', C# text) pairs.</summary>
    public static CSharpScripts Parse(IEnumerable<(string Path, string Text)> sources)
    {
        var scripts = new CSharpScripts();
        foreach ((string path, string text) in sources)
        {
            scripts.Add(path, text);
        }

        return scripts;
    }

    /// <summary>The top-level class named <paramref name="name"/> declared in <paramref name="file"/>, or null.</summary>
    public CSharpScriptClass? ClassInFile(string file, string name) =>
        _topLevelByFile.TryGetValue(file, out List<CSharpScriptClass>? classes) ? classes.FirstOrDefault(c => c.Name == name) : null;

    /// <summary>The top-level classes declared in <paramref name="file"/>.</summary>
    public IReadOnlyList<CSharpScriptClass> ClassesInFile(string file) =>
        _topLevelByFile.TryGetValue(file, out List<CSharpScriptClass>? classes) ? classes : [];

    /// <summary>
    /// The class of ours that <paramref name="cls"/> names as its base, or null when its base is not one of our classes
    /// (a Godot class, an interface, or none). Same-namespace classes are preferred over same-named ones elsewhere.
    /// </summary>
    public CSharpScriptClass? BaseOf(CSharpScriptClass cls)
    {
        if (cls.BaseTypeName is null)
        {
            return null;
        }

        List<CSharpScriptClass> candidates = _classes.Where(c => c.Name == cls.BaseTypeName && c != cls && !c.IsNested).ToList();
        return candidates.FirstOrDefault(c => c.Namespace == cls.Namespace) ?? candidates.FirstOrDefault();
    }

    /// <summary><paramref name="cls"/> and its bases among our classes, nearest first (stops on a cycle).</summary>
    public IReadOnlyList<CSharpScriptClass> Chain(CSharpScriptClass cls)
    {
        var chain = new List<CSharpScriptClass>();
        for (CSharpScriptClass? current = cls; current is not null && !chain.Contains(current); current = BaseOf(current))
        {
            chain.Add(current);
        }

        return chain;
    }

    /// <summary>
    /// The first base of <paramref name="cls"/>'s chain that is not one of our classes: the Godot class it extends
    /// (e.g. <c>Node3D</c>), or null when the chain ends without a base.
    /// </summary>
    public string? NativeBaseOf(CSharpScriptClass cls)
    {
        CSharpScriptClass last = Chain(cls)[^1];
        return BaseOf(last) is null ? last.BaseTypeName : null;
    }

    /// <summary>The exported members of <paramref name="cls"/> and of its bases among our classes, with the class declaring each.</summary>
    public IReadOnlyDictionary<string, CSharpScriptClass> ExportsOf(CSharpScriptClass cls)
    {
        var exports = new Dictionary<string, CSharpScriptClass>(StringComparer.Ordinal);
        foreach (CSharpScriptClass c in Chain(cls))
        {
            foreach (string name in c.Exports.Keys)
            {
                exports.TryAdd(name, c);
            }
        }

        return exports;
    }

    private void Add(string path, string text)
    {
        SyntaxTree tree = CSharpSyntaxTree.ParseText(text, Options, path);
        foreach (Diagnostic error in tree.GetDiagnostics().Where(d => d.Severity == DiagnosticSeverity.Error))
        {
            int line = error.Location.GetLineSpan().StartLinePosition.Line + 1;
            _syntaxErrors.Add($"{path}:{line}: C# syntax error {error.Id}: {error.GetMessage(System.Globalization.CultureInfo.InvariantCulture)}");
        }

        foreach (ClassDeclarationSyntax declaration in tree.GetRoot().DescendantNodes().OfType<ClassDeclarationSyntax>())
        {
            AddDeclaration(path, declaration);
        }
    }

    private void AddDeclaration(string path, ClassDeclarationSyntax declaration)
    {
        string ns = string.Join('.', declaration.Ancestors().OfType<BaseNamespaceDeclarationSyntax>().Reverse().Select(n => n.Name.ToString()));
        string[] outer = declaration.Ancestors().OfType<TypeDeclarationSyntax>().Reverse().Select(t => t.Identifier.Text).ToArray();
        string name = declaration.Identifier.Text;
        string fullName = string.Join('.', new[] { ns }.Concat(outer).Append(name).Where(s => s.Length > 0));
        if (!_byFullName.TryGetValue(fullName, out CSharpScriptClass? cls))
        {
            cls = new CSharpScriptClass(name, ns, fullName, outer.Length > 0)
            {
                Line = declaration.Identifier.GetLocation().GetLineSpan().StartLinePosition.Line + 1,
            };
            _byFullName.Add(fullName, cls);
            _classes.Add(cls);
        }

        if (!cls.Files.Contains(path))
        {
            cls.Files.Add(path);
        }

        if (!cls.IsNested)
        {
            if (!_topLevelByFile.TryGetValue(path, out List<CSharpScriptClass>? inFile))
            {
                _topLevelByFile[path] = inFile = [];
            }

            if (!inFile.Contains(cls))
            {
                inFile.Add(cls);
            }
        }

        cls.IsPartial &= declaration.Modifiers.Any(SyntaxKind.PartialKeyword);
        cls.IsAbstract |= declaration.Modifiers.Any(SyntaxKind.AbstractKeyword);
        cls.IsGeneric |= declaration.TypeParameterList is not null;
        foreach (AttributeSyntax attribute in declaration.AttributeLists.SelectMany(l => l.Attributes))
        {
            cls.Attributes.Add(SimpleAttributeName(attribute));
        }

        if (declaration.BaseList?.Types.FirstOrDefault() is { } firstBase)
        {
            cls.BaseTypeName ??= SimpleTypeName(firstBase.Type);
        }

        if (declaration.ParameterList is { } primary)
        {
            if (primary.Parameters.Count == 0)
            {
                cls.HasDeclaredParameterlessConstructor = true;
            }
            else
            {
                cls.HasPrimaryConstructorWithParameters = true;
            }
        }

        foreach (MemberDeclarationSyntax member in declaration.Members)
        {
            AddMember(cls, member);
        }
    }

    private static void AddMember(CSharpScriptClass cls, MemberDeclarationSyntax member)
    {
        switch (member)
        {
            case PropertyDeclarationSyntax property when IsExported(property.AttributeLists):
                cls.Exports.TryAdd(property.Identifier.Text, LineOf(property.Identifier));
                break;
            case FieldDeclarationSyntax field when IsExported(field.AttributeLists):
                foreach (VariableDeclaratorSyntax variable in field.Declaration.Variables)
                {
                    cls.Exports.TryAdd(variable.Identifier.Text, LineOf(variable.Identifier));
                }

                break;
            case MethodDeclarationSyntax method:
                cls.Methods.Add(method.Identifier.Text);
                break;
            case DelegateDeclarationSyntax signal when signal.AttributeLists.SelectMany(l => l.Attributes).Any(a => SimpleAttributeName(a) == "Signal"):
                string name = signal.Identifier.Text;
                cls.Signals.Add(name.EndsWith("EventHandler", StringComparison.Ordinal) ? name[..^"EventHandler".Length] : name);
                break;
            case ConstructorDeclarationSyntax constructor when !constructor.Modifiers.Any(SyntaxKind.StaticKeyword):
                if (constructor.ParameterList.Parameters.Count == 0)
                {
                    cls.HasDeclaredParameterlessConstructor = true;
                }
                else
                {
                    cls.HasConstructorWithParameters = true;
                }

                break;
        }
    }

    private static bool IsExported(SyntaxList<AttributeListSyntax> lists) =>
        lists.SelectMany(l => l.Attributes).Any(a => ExportAttributes.Contains(SimpleAttributeName(a)));

    private static string SimpleAttributeName(AttributeSyntax attribute)
    {
        string name = SimpleTypeName(attribute.Name);
        return name.EndsWith("Attribute", StringComparison.Ordinal) && name.Length > "Attribute".Length ? name[..^"Attribute".Length] : name;
    }

    private static string SimpleTypeName(TypeSyntax type) => type switch
    {
        QualifiedNameSyntax qualified => SimpleTypeName(qualified.Right),
        AliasQualifiedNameSyntax alias => SimpleTypeName(alias.Name),
        GenericNameSyntax generic => generic.Identifier.Text,
        SimpleNameSyntax simple => simple.Identifier.Text,
        _ => type.ToString(),
    };

    private static int LineOf(SyntaxToken token) => token.GetLocation().GetLineSpan().StartLinePosition.Line + 1;
}
