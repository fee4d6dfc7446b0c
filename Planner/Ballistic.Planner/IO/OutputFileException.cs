namespace Ballistic.Planner.IO;

/// <summary>An output file cannot be written; the message names the file the user gave and why. Nothing was replaced.</summary>
internal sealed class OutputFileException : Exception
{
    /// <summary>Creates the exception with a message naming the file and the problem.</summary>
    public OutputFileException(string message)
        : base(message)
    {
    }

    /// <summary>Creates the exception with a message and the error that caused it.</summary>
    public OutputFileException(string message, Exception innerException)
        : base(message, innerException)
    {
    }

    /// <summary>Creates the exception with a generic message.</summary>
    public OutputFileException()
        : base("The output file cannot be written.")
    {
    }
}
