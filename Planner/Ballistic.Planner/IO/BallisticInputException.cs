namespace Ballistic.Planner.IO;

/// <summary>
/// Input that cannot be used: a level, character, limb spec, roadmap or glTF file, or a value given to the planner.
/// The message is one sentence naming the file, the element (node, accessor, limb, bone, option) and what is wrong;
/// every failure caused by input is one of these, never a .NET exception from deep inside. The message is always one
/// line: control characters in it (a name read from a file holding a line break or a terminal escape) are escaped.
/// </summary>
public abstract class BallisticInputException : Exception
{
    /// <summary>Creates the exception with a message naming the problem.</summary>
    protected BallisticInputException(string message)
        : base(MessageText.Printable(message))
    {
    }

    /// <summary>Creates the exception with a message and the error that caused it.</summary>
    protected BallisticInputException(string message, Exception innerException)
        : base(MessageText.Printable(message), innerException)
    {
    }
}
