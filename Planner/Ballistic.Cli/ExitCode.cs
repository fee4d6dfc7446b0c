namespace Ballistic.Cli;

/// <summary>The exit codes of the <c>ballistic</c> tool, one per class of outcome (listed in the README).</summary>
public static class ExitCode
{
    /// <summary>The job succeeded.</summary>
    public const int Success = 0;

    /// <summary>The job ran but did not succeed: no path, no valid start or goal, no clean animation, out of time.</summary>
    public const int NotFound = 1;

    /// <summary>The command line is wrong: an unknown command or option, a value out of range.</summary>
    public const int Usage = 2;

    /// <summary>An input file cannot be used: a level, character, limb spec, roadmap or glTF file (missing, malformed, or for something else).</summary>
    public const int Input = 3;

    /// <summary>An output file cannot be written (nothing was replaced).</summary>
    public const int Output = 4;

    /// <summary>A fault of the tool itself; please report it (run again with --verbose for the details).</summary>
    public const int Internal = 70;

    /// <summary>Cancelled by Ctrl-C or SIGTERM; no output file was replaced.</summary>
    public const int Cancelled = 130;
}
