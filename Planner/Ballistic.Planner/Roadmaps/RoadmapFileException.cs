using Ballistic.Planner.IO;

namespace Ballistic.Planner.Roadmaps;

/// <summary>A roadmap file cannot be used: truncated, corrupt, of an unknown version, or baked for another level or character.</summary>
internal sealed class RoadmapFileException : BallisticInputException
{
    /// <summary>Creates the exception with one sentence naming the file and the problem.</summary>
    public RoadmapFileException(string message)
        : base(message)
    {
    }

    /// <summary>Creates the exception with a message and its cause.</summary>
    public RoadmapFileException(string message, Exception innerException)
        : base(message, innerException)
    {
    }

    /// <summary>Creates the exception with a generic message.</summary>
    public RoadmapFileException()
        : base("The roadmap file cannot be used.")
    {
    }
}
