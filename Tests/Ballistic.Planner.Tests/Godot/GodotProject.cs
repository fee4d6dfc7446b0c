namespace Ballistic.Planner.Tests.Godot;

/// <summary>
/// The Godot project's files under a root folder (<c>res://</c>): its text scenes and resources, <c>plugin.cfg</c>
/// files, <c>project.godot</c>, the <c>.import</c> and <c>.uid</c> side files, and its C# sources (as syntax). Files
/// that do not parse are kept as one-line errors. Build output and tool folders are skipped, as Godot skips them:
/// <c>bin</c>, <c>obj</c>, <c>out</c>, <c>BenchmarkDotNet.Artifacts</c>, <c>TestResults</c>, <c>node_modules</c>,
/// hidden folders (<c>.godot</c>, <c>.git</c>, …) and folders holding a <c>.gdignore</c>.
/// </summary>
public sealed class GodotProject
{
    private static readonly string[] SkippedFolders = ["bin", "obj", "out", "BenchmarkDotNet.Artifacts", "TestResults", "node_modules"];

    /// <summary>Folders whose C# files are not part of the Godot game assembly (<c>Ballistic.csproj</c>'s DefaultItemExcludes).</summary>
    private static readonly string[] NonGodotSourceFolders = ["Planner/", "Tests/"];

    private readonly Dictionary<string, GodotFile> _byPath;
    private readonly HashSet<string> _files;

    private GodotProject(
        string root, List<string> files, List<GodotFile> parsed, List<GodotFile> imports, List<string> parseErrors,
        Dictionary<string, (string Uid, int Line)> uidFiles, CSharpScripts scripts)
    {
        Root = root;
        AllFiles = files;
        Files = parsed;
        ImportFiles = imports;
        ParseErrors = parseErrors;
        UidFiles = uidFiles;
        Scripts = scripts;
        _byPath = parsed.Concat(imports).ToDictionary(f => f.Path, StringComparer.Ordinal);
        _files = new HashSet<string>(files, StringComparer.Ordinal);
    }

    /// <summary>The project folder, the directory <c>res://</c> names.</summary>
    public string Root { get; }

    /// <summary>Every file of the project, repository-relative with '/'.</summary>
    public IReadOnlyList<string> AllFiles { get; }

    /// <summary>The parsed <c>*.tscn</c>, <c>*.tres</c>, <c>plugin.cfg</c> and <c>project.godot</c> files.</summary>
    public IReadOnlyList<GodotFile> Files { get; }

    /// <summary>The parsed <c>*.import</c> side files (imported assets' settings and uids).</summary>
    public IReadOnlyList<GodotFile> ImportFiles { get; }

    /// <summary>One line per file that could not be parsed: <c>file:line: problem</c>.</summary>
    public IReadOnlyList<string> ParseErrors { get; }

    /// <summary>The <c>*.uid</c> side files (Godot 4.4+, e.g. <c>X.cs.uid</c>): path → the uid it holds and its line.</summary>
    public IReadOnlyDictionary<string, (string Uid, int Line)> UidFiles { get; }

    /// <summary>The classes of the Godot project's C# sources (everything but <c>Planner/</c> and <c>Tests/</c>).</summary>
    public CSharpScripts Scripts { get; }

    /// <summary>Loads the project under <paramref name="root"/>.</summary>
    public static GodotProject Load(string root)
    {
        List<string> files = Enumerate(root).ToList();
        var parsed = new List<GodotFile>();
        var imports = new List<GodotFile>();
        var errors = new List<string>();
        var uidFiles = new Dictionary<string, (string, int)>(StringComparer.Ordinal);
        foreach (string file in files)
        {
            string name = System.IO.Path.GetFileName(file);
            bool godotText = file.EndsWith(".tscn", StringComparison.Ordinal) || file.EndsWith(".tres", StringComparison.Ordinal)
                || name is "plugin.cfg" or "project.godot";
            bool import = file.EndsWith(".import", StringComparison.Ordinal);
            if (godotText || import)
            {
                try
                {
                    (import ? imports : parsed).Add(GodotFile.Load(FullPath(root, file), file));
                }
                catch (GodotFormatException e)
                {
                    errors.Add(e.Message);
                }
            }
            else if (file.EndsWith(".uid", StringComparison.Ordinal))
            {
                string[] lines = File.ReadAllLines(FullPath(root, file));
                int index = Array.FindIndex(lines, l => l.Trim().Length > 0);
                uidFiles[file] = index < 0 ? ("", 1) : (lines[index].Trim(), index + 1);
            }
        }

        CSharpScripts scripts = CSharpScripts.Parse(files
            .Where(f => f.EndsWith(".cs", StringComparison.Ordinal) && !NonGodotSourceFolders.Any(p => f.StartsWith(p, StringComparison.Ordinal)))
            .Select(f => (f, File.ReadAllText(FullPath(root, f)))));
        return new GodotProject(root, files, parsed, imports, errors, uidFiles, scripts);
    }

    /// <summary>The parsed file at repository-relative <paramref name="path"/> (scene, resource, cfg or import file), or null.</summary>
    public GodotFile? FileAt(string path) => _byPath.GetValueOrDefault(path);

    /// <summary>True when the project has a file at repository-relative <paramref name="path"/> (exact case).</summary>
    public bool Exists(string path) => _files.Contains(path);

    /// <summary>True when <paramref name="path"/> is a folder of the project.</summary>
    public bool FolderExists(string path) => Directory.Exists(FullPath(Root, path));

    /// <summary>The repository-relative path a <c>res://</c> path names, or null when it is not a <c>res://</c> path.</summary>
    public static string? RelativePath(string resPath) =>
        resPath.StartsWith("res://", StringComparison.Ordinal) ? resPath["res://".Length..].TrimEnd('/') : null;

    private static string FullPath(string root, string relative) => System.IO.Path.Combine(root, relative.Replace('/', System.IO.Path.DirectorySeparatorChar));

    private static IEnumerable<string> Enumerate(string root)
    {
        var pending = new Stack<string>();
        pending.Push(root);
        var found = new List<string>();
        while (pending.Count > 0)
        {
            string folder = pending.Pop();
            foreach (string file in Directory.EnumerateFiles(folder))
            {
                found.Add(System.IO.Path.GetRelativePath(root, file).Replace(System.IO.Path.DirectorySeparatorChar, '/'));
            }

            foreach (string sub in Directory.EnumerateDirectories(folder))
            {
                string name = System.IO.Path.GetFileName(sub);
                if (name.StartsWith('.') || SkippedFolders.Contains(name) || File.Exists(System.IO.Path.Combine(sub, ".gdignore")))
                {
                    continue;
                }

                pending.Push(sub);
            }
        }

        found.Sort(StringComparer.Ordinal);
        return found;
    }
}
