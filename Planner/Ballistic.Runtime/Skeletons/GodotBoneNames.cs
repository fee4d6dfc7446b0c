using System.Text;

namespace Ballistic.Runtime.Skeletons;

/// <summary>
/// How bone names change between a rig file and an engine's skeleton, used to match a runtime rig's joints to a
/// target skeleton's bones. Godot 4's glTF (and FBX) importer keeps a node's name as its bone name, replacing ':'
/// and '/' with '_' (<c>SkinTool::_sanitize_bone_name</c>), naming an unnamed bone "bone", and making repeated names
/// unique with "_2", "_3"… (<c>SkinTool::_gen_unique_bone_name</c>): "mixamorig:Hips" becomes "mixamorig_Hips".
/// </summary>
internal static class GodotBoneNames
{
    /// <summary>The bone name Godot's importer gives a node called <paramref name="name"/> (before making it unique): ':' and '/' become '_', an empty name "bone".</summary>
    public static string Sanitize(string name)
    {
        ArgumentNullException.ThrowIfNull(name);
        return name.Length == 0 ? "bone" : name.Replace(':', '_').Replace('/', '_');
    }

    /// <summary>
    /// A key under which names that differ only in case and in separators match: letters and digits lower-cased,
    /// every other character (':', '/', '.', '_', '-', spaces…) dropped. "mixamorig:LeftUpLeg", "mixamorig_leftupleg"
    /// and "Mixamorig.Left-Up-Leg" share the key "mixamorigleftupleg".
    /// </summary>
    public static string LooseKey(string name)
    {
        ArgumentNullException.ThrowIfNull(name);
        var key = new StringBuilder(name.Length);
        foreach (char c in name)
        {
            if (char.IsLetterOrDigit(c))
            {
                key.Append(char.ToLowerInvariant(c));
            }
        }

        return key.ToString();
    }
}
