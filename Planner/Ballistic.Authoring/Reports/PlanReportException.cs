using Ballistic.Planner.IO;

namespace Ballistic.Authoring.Reports;

/// <summary>
/// A plan report cannot be read: not JSON, not a <c>ballistic.plan/1</c> or <c>/2</c> report, or an element missing
/// or of the wrong type. The message is one line naming the file, the element (e.g. <c>moves[2].path[5]</c>) and the problem.
/// </summary>
public sealed class PlanReportException : BallisticInputException
{
    /// <summary>Creates the exception with one line naming the file, the element and the problem.</summary>
    public PlanReportException(string message)
        : base(message)
    {
    }

    /// <summary>Creates the exception with a message and its cause.</summary>
    public PlanReportException(string message, Exception innerException)
        : base(message, innerException)
    {
    }

    /// <summary>Creates the exception with a generic message.</summary>
    public PlanReportException()
        : base("The plan report cannot be read.")
    {
    }
}
