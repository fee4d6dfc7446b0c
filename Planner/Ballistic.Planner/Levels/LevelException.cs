using Ballistic.Planner.IO;

namespace Ballistic.Planner.Levels;

/// <summary>The level given to the planner cannot be used; the message names the mesh, file or value at fault.</summary>
public sealed class LevelException : BallisticInputException
{
    /// <summary>Creates the exception with a message naming the problem.</summary>
    public LevelException(string message)
        : base(message)
    {
    }

    /// <summary>Creates the exception with a message naming the problem and the error that caused it.</summary>
    public LevelException(string message, Exception innerException)
        : base(message, innerException)
    {
    }

    /// <summary>Creates the exception with a generic message.</summary>
    public LevelException()
        : base("The level cannot be used.")
    {
    }
}
