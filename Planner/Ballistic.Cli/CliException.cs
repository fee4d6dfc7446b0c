namespace Ballistic.Cli;

/// <summary>A problem with the command line or its inputs, reported to the user as one line.</summary>
public sealed class CliException : Exception
{
    /// <summary>Creates the exception with the line to print.</summary>
    public CliException(string message)
        : base(message)
    {
    }

    /// <summary>Creates the exception with the line to print and its cause.</summary>
    public CliException(string message, Exception innerException)
        : base(message, innerException)
    {
    }

    /// <summary>Creates the exception with a generic message.</summary>
    public CliException()
        : base("Invalid command line.")
    {
    }
}
