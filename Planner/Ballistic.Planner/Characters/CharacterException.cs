using Ballistic.Planner.IO;

namespace Ballistic.Planner.Characters;

/// <summary>A character description cannot be used; the message names the character, limb or value at fault.</summary>
public sealed class CharacterException : BallisticInputException
{
    /// <summary>Creates the exception with a message naming the problem.</summary>
    public CharacterException(string message)
        : base(message)
    {
    }

    /// <summary>Creates the exception with a message and the error that caused it.</summary>
    public CharacterException(string message, Exception innerException)
        : base(message, innerException)
    {
    }

    /// <summary>Creates the exception with a generic message.</summary>
    public CharacterException()
        : base("The character cannot be used.")
    {
    }
}
