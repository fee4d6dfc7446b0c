namespace Ballistic.Planner.Tests.Godot;

/// <summary>
/// A Godot text file (scene, resource, <c>plugin.cfg</c>, <c>project.godot</c>) that cannot be read. The message is one
/// line: <c>file:line: problem</c>.
/// </summary>
public sealed class GodotFormatException : Exception
{
    /// <summary>Creates the error for <paramref name="file"/> at 1-based <paramref name="line"/>.</summary>
    public GodotFormatException(string file, int line, string problem)
        : base($"{file}:{line}: {problem}")
    {
        File = file;
        Line = line;
        Problem = problem;
    }

    /// <summary>The file as it was named to the parser (a path relative to the repository root for repository files).</summary>
    public string File { get; }

    /// <summary>The 1-based line the problem was found on.</summary>
    public int Line { get; }

    /// <summary>The problem, without the file and line.</summary>
    public string Problem { get; }
}
