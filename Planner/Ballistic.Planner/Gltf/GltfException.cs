using Ballistic.Planner.IO;

namespace Ballistic.Planner.Gltf;

/// <summary>A glTF file cannot be read or written; the message names the file and what is wrong with it.</summary>
internal sealed class GltfException : BallisticInputException
{
    /// <summary>Creates the exception with a message naming the problem.</summary>
    public GltfException(string message)
        : base(message)
    {
    }

    /// <summary>Creates the exception with a message and its cause.</summary>
    public GltfException(string message, Exception innerException)
        : base(message, innerException)
    {
    }

    /// <summary>Creates the exception with a generic message.</summary>
    public GltfException()
        : base("The glTF file cannot be used.")
    {
    }
}
