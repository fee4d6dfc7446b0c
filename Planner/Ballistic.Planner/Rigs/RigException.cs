using Ballistic.Planner.IO;

namespace Ballistic.Planner.Rigs;

/// <summary>A rig or limb description cannot be used; the message names the joint, bone or limb at fault.</summary>
public sealed class RigException : BallisticInputException
{
    /// <summary>Creates the exception with a message naming the problem.</summary>
    public RigException(string message)
        : base(message)
    {
    }

    /// <summary>Creates the exception with a message and its cause.</summary>
    public RigException(string message, Exception innerException)
        : base(message, innerException)
    {
    }

    /// <summary>Creates the exception with a generic message.</summary>
    public RigException()
        : base("The rig cannot be used.")
    {
    }
}
