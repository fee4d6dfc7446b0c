namespace Ballistic.Planner.Tests.Godot;

/// <summary>
/// Godot 4.7 C# type names that are also public type names in .NET's <c>System.*</c> namespaces: where a file imports
/// both namespaces, a simple name among these is ambiguous (CS0104) in the real build. Made by intersecting every
/// public top-level type of .NET 10's <c>System.*</c> namespaces with Godot's class reference (<c>doc/classes</c>) and
/// GodotSharp's core sources (<c>modules/mono/glue/GodotSharp/GodotSharp/Core</c>), C# names as GodotSharp spells them.
/// </summary>
internal static class GodotTypeNames
{
    /// <summary>Each clashing name and the Godot namespace that holds it.</summary>
    public static IReadOnlyDictionary<string, string> ByNamespace { get; } = Build();

    /// <summary>The clashing names.</summary>
    public static IReadOnlySet<string> InGodot { get; } = ByNamespace.Keys.ToHashSet(StringComparer.Ordinal);

    private static Dictionary<string, string> Build()
    {
        string[] godot =
        [
            "Color", "Container", "Environment", "Expression", "FileAccess", "HttpClient", "Label", "Mutex", "Plane",
            "Quaternion", "Range", "RandomNumberGenerator", "Semaphore", "Thread", "Timer", "Vector2", "Vector3", "Vector4",
            "X509Certificate",
        ];
        string[] collections = ["Array", "Dictionary"];
        var names = new Dictionary<string, string>(StringComparer.Ordinal);
        foreach (string name in godot)
        {
            names.Add(name, "Godot");
        }

        foreach (string name in collections)
        {
            names.Add(name, "Godot.Collections");
        }

        return names;
    }
}
