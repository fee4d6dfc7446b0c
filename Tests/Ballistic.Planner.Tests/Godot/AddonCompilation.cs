using System.Collections.Immutable;
using System.Globalization;
using Ballistic.Planner.Tests.Support;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace Ballistic.Planner.Tests.Godot;

/// <summary>
/// The Godot project's C# sources (<c>addons/</c>, <c>Scenes/</c>) compiled by Roslyn the way a Godot game compiles
/// them, but without GodotSharp, which cannot be had here: no implicit usings and nullable off at project level (the
/// defaults of a project the Godot editor generates), the language version of <c>net8.0</c>, references to the .NET
/// library and the engine-free Ballistic libraries. Every Godot name is then unknown, and Roslyn stays silent about
/// whatever depends on one; what it still reports is ours: a call to our own or a .NET method used as if it returned
/// what it does not, a missing <c>using System…;</c>, a nullable annotation outside a nullable context. On top of the
/// compiler, <see cref="Problems"/> finds every simple name that the real build would find ambiguous between a Godot
/// type and a <c>System.*</c> type (CS0104, CS0419), from <see cref="GodotTypeNames"/>.
/// </summary>
public sealed class AddonCompilation
{
    /// <summary>
    /// Diagnostics that say a name is unknown (or, CS0122, names only a type internal to .NET, where Godot's public one
    /// is meant: <c>Error</c>): ours to report only when the name is a public .NET type's.
    /// </summary>
    private static readonly string[] UnknownName = ["CS0246", "CS0103", "CS1574", "CS0234", "CS0122"];

    /// <summary>
    /// Definite assignment through an expression of a Godot type (<c>x is T t || !godotDict.TryGetValue(…, out v)</c>)
    /// cannot be judged without Godot: Roslyn reports CS0165 there where the real build does not.
    /// </summary>
    private static readonly string[] NotJudgedWithoutGodot = ["CS0165"];

    /// <summary>A member looked up on a type whose base is a Godot class (inherited members are unknown here).</summary>
    private static readonly string[] MemberNotFound = ["CS1061", "CS0117"];

    /// <summary>A conversion between one of our node classes and a Godot class (their relation is unknown here).</summary>
    private static readonly string[] ConversionOfGodotTypes = ["CS1503", "CS0029", "CS0266", "CS0030", "CS0039"];

    private readonly ILookup<string, string> _systemTypes;
    private readonly ILookup<string, string> _systemExtensions;
    private readonly UsingDirectiveSyntax[] _globalUsings;

    private AddonCompilation(CSharpCompilation compilation, IReadOnlyList<string> files)
    {
        Compilation = compilation;
        Files = files;
        (string Name, string Namespace, INamedTypeSymbol Type)[] systemTypes = SystemTypes(compilation.GlobalNamespace).ToArray();
        _globalUsings = [.. compilation.SyntaxTrees.SelectMany(t => t.GetCompilationUnitRoot().Usings).Where(u => u.GlobalKeyword.IsKind(SyntaxKind.GlobalKeyword))];
        _systemTypes = systemTypes.ToLookup(t => t.Name, t => t.Namespace, StringComparer.Ordinal);
        _systemExtensions = systemTypes.Where(t => t.Type.IsStatic && t.Type.MightContainExtensionMethods)
            .SelectMany(t => t.Type.GetMembers().OfType<IMethodSymbol>().Where(m => m.IsExtensionMethod && m.DeclaredAccessibility == Accessibility.Public).Select(m => (m.Name, t.Namespace)))
            .ToLookup(m => m.Name, m => m.Namespace, StringComparer.Ordinal);
    }

    /// <summary>The compilation (one syntax tree per source file, path relative to the repository, with '/').</summary>
    public CSharpCompilation Compilation { get; }

    /// <summary>The repository-relative paths compiled.</summary>
    public IReadOnlyList<string> Files { get; }

    /// <summary>Compiles every C# file under <c>addons/</c> and <c>Scenes/</c>, as an editor build (<paramref name="editor"/>) or an exported game sees it.</summary>
    public static AddonCompilation OfRepository(bool editor)
    {
        string root = RepositoryFiles.Root;
        var sources = new List<(string, string)>();
        foreach (string folder in new[] { "addons", "Scenes" })
        {
            foreach (string file in Directory.GetFiles(Path.Combine(root, folder), "*.cs", SearchOption.AllDirectories).Order(StringComparer.Ordinal))
            {
                sources.Add((Path.GetRelativePath(root, file).Replace('\\', '/'), File.ReadAllText(file)));
            }
        }

        if (ImplicitUsingsOn(root))
        {
            sources.Add(("obj/Ballistic.GlobalUsings.g.cs", string.Concat(ImplicitUsings.Select(u => $"global using global::{u};\n"))));
        }

        return Of(sources, editor);
    }

    /// <summary>The global usings <c>Microsoft.NET.Sdk</c> (and so <c>Godot.NET.Sdk</c>) adds when implicit usings are on.</summary>
    private static readonly string[] ImplicitUsings =
        ["System", "System.Collections.Generic", "System.IO", "System.Linq", "System.Net.Http", "System.Threading", "System.Threading.Tasks"];

    /// <summary>
    /// Whether the Godot project compiles with implicit usings: the last <c>ImplicitUsings</c> of
    /// <c>Directory.Build.props</c> and then <c>Ballistic.csproj</c> (MSBuild reads them in that order).
    /// </summary>
    private static bool ImplicitUsingsOn(string root)
    {
        string? value = null;
        foreach (string file in new[] { "Directory.Build.props", "Ballistic.csproj" })
        {
            string path = Path.Combine(root, file);
            if (File.Exists(path) && System.Xml.Linq.XDocument.Load(path).Descendants("ImplicitUsings").LastOrDefault() is { } element)
            {
                value = element.Value.Trim();
            }
        }

        return value is not null && (value.Equals("enable", StringComparison.OrdinalIgnoreCase) || value.Equals("true", StringComparison.OrdinalIgnoreCase));
    }

    /// <summary>Compiles <paramref name="sources"/> ((path, text) pairs) with the Godot game's settings.</summary>
    public static AddonCompilation Of(IEnumerable<(string Path, string Text)> sources, bool editor)
    {
        string[] symbols = editor
            ? ["TOOLS", "GODOT", "GODOT4", "GODOT4_OR_GREATER", "GODOT4_7", "GODOT4_7_OR_GREATER", "DEBUG"]
            : ["GODOT", "GODOT4", "GODOT4_OR_GREATER", "GODOT4_7", "GODOT4_7_OR_GREATER"];
        var options = new CSharpParseOptions(LanguageVersion.CSharp12, DocumentationMode.Diagnose, SourceCodeKind.Regular, symbols);
        List<(string Path, string Text)> list = sources.ToList();
        SyntaxTree[] trees = list.Select(s => CSharpSyntaxTree.ParseText(s.Text, options, s.Path)).ToArray();
        // Not the game's own assembly name (Ballistic): the libraries' InternalsVisibleTo("ballistic"), for the CLI,
        // matches it (assembly names compare ignoring case), so the real build sees their internal types; the addon
        // must not lean on that (a game whose assembly is named otherwise sees only the public surface).
        var compilation = CSharpCompilation.Create(
            "Ballistic.AddonCheck",
            trees,
            References.Value,
            new CSharpCompilationOptions(
                OutputKind.DynamicallyLinkedLibrary,
                nullableContextOptions: NullableContextOptions.Disable,
                specificDiagnosticOptions: [new("CS1591", ReportDiagnostic.Suppress)])); // no documentation file in a game's build
        return new AddonCompilation(compilation, list.Select(s => s.Path).ToArray());
    }

    /// <summary>
    /// Every problem of our own making, one line each (<c>file:line: CSxxxx: message</c>): the compiler's errors and
    /// warnings that do not depend on a Godot name, unknown names that are .NET types (a missing <c>using</c>), and
    /// names the real build would find ambiguous between Godot and .NET.
    /// </summary>
    public IReadOnlyList<string> Problems()
    {
        var problems = new List<string>();
        foreach (Diagnostic d in Compilation.GetDiagnostics().Where(d => d.Severity >= DiagnosticSeverity.Warning || d.Id == "CS8019"))
        {
            // An unnecessary using is IDE0005, an error in our Godot build (warnings as errors, code style enforced),
            // and can be so in one build only (a namespace used inside #if TOOLS alone). Usings of Godot are not
            // judged: nothing of Godot resolves here.
            if (d.Id == "CS8019")
            {
                string directive = d.Location.SourceTree?.GetText().ToString(d.Location.SourceSpan) ?? "";
                if (!directive.Contains("Godot", StringComparison.Ordinal))
                {
                    problems.Add($"{Where(d.Location)}: IDE0005: unnecessary using directive ({directive.Trim()}) in this build");
                }

                continue;
            }

            if (NotJudgedWithoutGodot.Contains(d.Id) || IsNullableFlowWarning(d.Id))
            {
                continue;
            }

            if (d.Id == "CS1061" && _systemExtensions[NameIn(d)].ToArray() is { Length: > 0 } extensionNamespaces)
            {
                problems.Add($"{Where(d.Location)}: {d.Id}: '{NameIn(d)}' is an extension method of .NET's ({string.Join(", ", extensionNamespaces.Distinct().Order(StringComparer.Ordinal))}): the file needs a using directive (there are no implicit usings in a Godot project)");
                continue;
            }

            if (MemberNotFound.Contains(d.Id) && OurReceiver(d) is { } ours)
            {
                problems.Add($"{Where(d.Location)}: {d.Id}: '{NameIn(d)}' is no public member of {ours.ToDisplayString()}: the addon sees only the Ballistic libraries' public API");
                continue;
            }

            if ((MemberNotFound.Contains(d.Id) && (ReceiverExtendsGodot(d) || ImportsGodot(d)))
                || (ConversionOfGodotTypes.Contains(d.Id) && ConvertsGodotTypes(d)))
            {
                continue;
            }

            if (UnknownName.Contains(d.Id))
            {
                string name = NameIn(d);
                if (OurInternalTypes.Value.Contains(name) && !(GodotTypeNames.InGodot.Contains(name) && ImportsGodot(d)))
                {
                    problems.Add($"{Where(d.Location)}: {d.Id}: '{name}' is internal to the Ballistic libraries: the addon sees only their public types");
                    continue;
                }

                string[] namespaces = _systemTypes[name].ToArray();
                if (namespaces.Length > 0 && !GodotTypeNames.InGodot.Contains(name))
                {
                    problems.Add($"{Where(d.Location)}: {d.Id}: '{name}' is .NET's ({string.Join(", ", namespaces.Order(StringComparer.Ordinal))}): the file needs a using directive (there are no implicit usings in a Godot project)");
                }

                continue;
            }

            problems.Add($"{Where(d.Location)}: {d.Id}: {d.GetMessage(CultureInfo.InvariantCulture)}");
        }

        problems.AddRange(Ambiguities());
        return problems;
    }

    /// <summary>
    /// Simple names that bind here to a <c>System.*</c> type through a namespace import, in a file that also imports
    /// the Godot namespace holding a type of that name: CS0104 (CS0419 in a <c>cref</c>) in the real build.
    /// </summary>
    private IEnumerable<string> Ambiguities()
    {
        foreach (SyntaxTree tree in Compilation.SyntaxTrees)
        {
            SemanticModel model = Compilation.GetSemanticModel(tree);
            foreach (SimpleNameSyntax name in tree.GetRoot().DescendantNodes(descendIntoTrivia: true).OfType<SimpleNameSyntax>())
            {
                if (IsQualifiedPart(name) || model.GetAliasInfo(name) is not null)
                {
                    continue;
                }

                string text = name.Identifier.ValueText;
                if (!GodotTypeNames.ByNamespace.TryGetValue(text, out string? godotNamespace) || !Imports(model, name.SpanStart, godotNamespace))
                {
                    continue;
                }

                ISymbol? symbol = model.GetSymbolInfo(name).Symbol ?? model.GetSymbolInfo(name).CandidateSymbols.FirstOrDefault();
                if (symbol is INamedTypeSymbol type && type.ContainingNamespace.ToDisplayString() is { } ns && (ns == "System" || ns.StartsWith("System.", StringComparison.Ordinal)))
                {
                    string id = name.Ancestors(ascendOutOfTrivia: false).Any(a => a is CrefSyntax) ? "CS0419" : "CS0104";
                    yield return $"{Where(name.GetLocation())}: {id}: '{text}' is ambiguous between '{godotNamespace}.{text}' and '{ns}.{text}' (qualify it or alias it)";
                }
            }
        }
    }

    private static bool IsQualifiedPart(SimpleNameSyntax name) => name.Parent switch
    {
        QualifiedNameSyntax q => q.Right == name,
        MemberAccessExpressionSyntax m => m.Name == name,
        QualifiedCrefSyntax q => q.Member.DescendantNodesAndSelf().Contains(name),
        _ => false,
    };

    /// <summary>Whether the usings in scope at <paramref name="position"/> (or a global using anywhere) import <paramref name="ns"/>.</summary>
    private bool Imports(SemanticModel model, int position, string ns)
    {
        if (_globalUsings.Any(u => IsImportOf(u, ns)))
        {
            return true;
        }

        for (SyntaxNode? node = model.SyntaxTree.GetRoot().FindToken(position).Parent; node is not null; node = node.Parent)
        {
            SyntaxList<UsingDirectiveSyntax> usings = node switch
            {
                CompilationUnitSyntax unit => unit.Usings,
                BaseNamespaceDeclarationSyntax declaration => declaration.Usings,
                _ => default,
            };
            if (usings.Any(u => IsImportOf(u, ns)))
            {
                return true;
            }
        }

        return false;
    }

    private static bool IsImportOf(UsingDirectiveSyntax u, string ns) =>
        u.Alias is null && u.StaticKeyword.IsKind(SyntaxKind.None) && u.Name?.ToString() is { } name && (name == ns || name == "global::" + ns);

    /// <summary>Whether the member access at <paramref name="d"/> is on a type that is, or derives from, a type unknown here.</summary>
    private bool ReceiverExtendsGodot(Diagnostic d)
    {
        if (d.Location.SourceTree is not { } tree)
        {
            return false;
        }

        SyntaxNode? node = tree.GetRoot().FindNode(d.Location.SourceSpan, getInnermostNodeForTie: true);
        ExpressionSyntax? receiver = node?.AncestorsAndSelf().OfType<MemberAccessExpressionSyntax>().FirstOrDefault()?.Expression;
        ITypeSymbol? type = receiver is null
            ? node?.AncestorsAndSelf().OfType<TypeDeclarationSyntax>().FirstOrDefault() is { } declaration ? Compilation.GetSemanticModel(tree).GetDeclaredSymbol(declaration) : null
            : Compilation.GetSemanticModel(tree).GetTypeInfo(receiver).Type;
        return ExtendsUnknown(type);
    }

    /// <summary>
    /// The type of the expression whose member <paramref name="d"/> does not find, when one of the Ballistic libraries
    /// the addon references defines it (Godot adds no members to it, so the member is missing or not public there), not
    /// the addon itself (its nodes extend Godot's); otherwise <c>null</c>.
    /// </summary>
    private ITypeSymbol? OurReceiver(Diagnostic d)
    {
        if (d.Location.SourceTree is not { } tree)
        {
            return null;
        }

        SyntaxNode? node = tree.GetRoot().FindNode(d.Location.SourceSpan, getInnermostNodeForTie: true);
        ExpressionSyntax? receiver = node?.AncestorsAndSelf().OfType<MemberAccessExpressionSyntax>().FirstOrDefault()?.Expression;
        ITypeSymbol? type = receiver is null ? null : Compilation.GetSemanticModel(tree).GetTypeInfo(receiver).Type;
        return type is { TypeKind: not TypeKind.Error } && !SymbolEqualityComparer.Default.Equals(type.ContainingAssembly, Compilation.Assembly)
            && type.ContainingAssembly?.Name.StartsWith("Ballistic.", StringComparison.Ordinal) == true ? type : null;
    }

    /// <summary>
    /// Whether the file of <paramref name="d"/> imports the Godot namespace, whose extension methods (on <c>string</c>:
    /// <c>GetBaseDir</c>, <c>GetFile</c>…) are unknown here.
    /// </summary>
    private bool ImportsGodot(Diagnostic d) =>
        d.Location.SourceTree is { } tree && Imports(Compilation.GetSemanticModel(tree), d.Location.SourceSpan.Start, "Godot");

    /// <summary>Whether the expression converted at <paramref name="d"/> has, or derives from, a type unknown here.</summary>
    private bool ConvertsGodotTypes(Diagnostic d)
    {
        if (d.Location.SourceTree is not { } tree)
        {
            return false;
        }

        SyntaxNode? node = tree.GetRoot().FindNode(d.Location.SourceSpan, getInnermostNodeForTie: true);
        ExpressionSyntax? expression = node?.DescendantNodesAndSelf().OfType<ExpressionSyntax>().FirstOrDefault();
        if (expression is null)
        {
            return false;
        }

        TypeInfo info = Compilation.GetSemanticModel(tree).GetTypeInfo(expression);
        return ExtendsUnknown(info.Type) || ExtendsUnknown(info.ConvertedType);
    }

    private static bool ExtendsUnknown(ITypeSymbol? type)
    {
        for (ITypeSymbol? t = type; t is not null; t = t.BaseType)
        {
            if (t.TypeKind == TypeKind.Error || (t is INamedTypeSymbol { IsGenericType: true } generic && generic.TypeArguments.Any(ExtendsUnknown)))
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>
    /// Nullable flow analysis (CS8600–CS8669) follows values through Godot calls it cannot see here (a null check by
    /// <c>IsInstanceValid</c>); the real build judges those. The annotation check CS8632 is not flow analysis and stays.
    /// </summary>
    private static bool IsNullableFlowWarning(string id) =>
        id != "CS8632" && id.StartsWith("CS86", StringComparison.Ordinal) && int.TryParse(id.AsSpan(2), out int n) && n is >= 8600 and <= 8669;

    private static string NameIn(Diagnostic d)
    {
        string name = d.Location.SourceTree is { } tree ? tree.GetText().ToString(d.Location.SourceSpan) : "";
        int generic = name.IndexOf('<', StringComparison.Ordinal);
        name = generic >= 0 ? name[..generic] : name;
        int dot = name.LastIndexOf('.');
        return dot >= 0 ? name[(dot + 1)..] : name.Trim();
    }

    private static string Where(Location location)
    {
        FileLinePositionSpan span = location.GetLineSpan();
        return $"{span.Path}:{span.StartLinePosition.Line + 1}";
    }

    private static IEnumerable<(string Name, string Namespace, INamedTypeSymbol Type)> SystemTypes(INamespaceSymbol global)
    {
        INamespaceSymbol? system = global.GetNamespaceMembers().FirstOrDefault(n => n.Name == "System");
        var stack = new Stack<INamespaceSymbol>();
        if (system is not null)
        {
            stack.Push(system);
        }

        while (stack.Count > 0)
        {
            INamespaceSymbol ns = stack.Pop();
            string nsName = ns.ToDisplayString();
            foreach (INamedTypeSymbol type in ns.GetTypeMembers().Where(t => t.DeclaredAccessibility == Accessibility.Public))
            {
                yield return (type.Name, nsName, type);
            }

            foreach (INamespaceSymbol child in ns.GetNamespaceMembers())
            {
                stack.Push(child);
            }
        }
    }

    /// <summary>
    /// Names of the engine-free Ballistic libraries' internal types (namespace level): such a name in the addon does not
    /// resolve (Roslyn reports it inaccessible, CS0122, or unknown, which for other names means Godot's), and a user's
    /// game, whose assembly the libraries give no <c>InternalsVisibleTo</c>, fails to build on it.
    /// </summary>
    private static readonly Lazy<HashSet<string>> OurInternalTypes = new(() =>
        [.. new[] { typeof(Ballistic.Planner.Levels.Level).Assembly, typeof(Ballistic.Runtime.JumpWorld).Assembly }
            .SelectMany(a => a.GetTypes()).Where(t => !t.IsVisible && !t.IsNested && !t.Name.StartsWith('<'))
            .Select(t => t.Name.Split('`')[0])]);

    private static readonly Lazy<ImmutableArray<MetadataReference>> References = new(() =>
    {
        string[] platform = ((string)AppContext.GetData("TRUSTED_PLATFORM_ASSEMBLIES")!).Split(Path.PathSeparator)
            .Where(p => Path.GetFileName(p).StartsWith("System.", StringComparison.Ordinal) || Path.GetFileName(p) is "mscorlib.dll" or "netstandard.dll")
            .ToArray();
        IEnumerable<string> ours = new[]
        {
            typeof(Ballistic.Planner.Levels.Level).Assembly,
            typeof(Ballistic.Runtime.JumpWorld).Assembly,
            typeof(MathNet.Numerics.Constants).Assembly,
        }.Select(a => a.Location);
        return platform.Concat(ours).Distinct().Select(p => (MetadataReference)MetadataReference.CreateFromFile(p)).ToImmutableArray();
    });
}
