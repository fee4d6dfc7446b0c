using Ballistic.Planner.IO;

namespace Ballistic.Cli;

/// <summary>An input file named on the command line is missing or of the wrong kind (exit code <see cref="ExitCode.Input"/>).</summary>
public sealed class InputFileException : BallisticInputException
{
    /// <summary>Creates the exception with the line to print.</summary>
    public InputFileException(string message)
        : base(message)
    {
    }

    /// <summary>Creates the exception with the line to print and its cause.</summary>
    public InputFileException(string message, Exception innerException)
        : base(message, innerException)
    {
    }

    /// <summary>Creates the exception with a generic message.</summary>
    public InputFileException()
        : base("An input file cannot be used.")
    {
    }
}
