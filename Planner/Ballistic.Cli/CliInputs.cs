using System.Globalization;
using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Authoring.Levels;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Collision;
using Ballistic.Planner.IO;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Sampling;

namespace Ballistic.Cli;

/// <summary>Parsing and loading of the tool's inputs: a bad value is a <see cref="CliException"/>, a missing or unusable file an <see cref="InputFileException"/>, each naming the input.</summary>
internal static class CliInputs
{
    /// <summary>Parses "x,y,z" (metres, invariant culture).</summary>
    public static Vector3 ParsePoint(string text, string option)
    {
        string[] parts = text.Split(',', StringSplitOptions.TrimEntries);
        if (parts.Length == 3 &&
            float.TryParse(parts[0], NumberStyles.Float, CultureInfo.InvariantCulture, out float x) &&
            float.TryParse(parts[1], NumberStyles.Float, CultureInfo.InvariantCulture, out float y) &&
            float.TryParse(parts[2], NumberStyles.Float, CultureInfo.InvariantCulture, out float z) &&
            float.IsFinite(x) && float.IsFinite(y) && float.IsFinite(z))
        {
            return new Vector3(x, y, z);
        }

        throw new CliException($"{option} takes a point as x,y,z in metres (for example 1.5,0,-2), not '{text}'.");
    }

    /// <summary>Refuses a path no file can have (empty, or with a NUL character), naming what it was for.</summary>
    public static void CheckPath(string path, string what)
    {
        if (path.Length == 0 || path.Contains('\0', StringComparison.Ordinal))
        {
            throw new InputFileException($"{what} '{path.Replace('\0', '?')}' is not a valid file path (empty, or with a NUL character).");
        }
    }

    /// <summary>Why <paramref name="path"/>, which is no file, cannot be read: a folder, or nothing there.</summary>
    private static string Missing(string path) =>
        Directory.Exists(path) ? "is a folder, not a file" : "does not exist";

    /// <summary>Parses "ACROSS[,UPDOWN]" (metres, invariant culture) as an endpoint tolerance; UPDOWN defaults to 0.25 m.</summary>
    public static EndpointTolerance ParseTolerance(string text, string option)
    {
        string[] parts = text.Split(',', StringSplitOptions.TrimEntries);
        if (parts.Length is 1 or 2 &&
            float.TryParse(parts[0], NumberStyles.Float, CultureInfo.InvariantCulture, out float across) &&
            across > 0f && float.IsFinite(across))
        {
            float upDown = 0.25f;
            if (parts.Length == 1 || (float.TryParse(parts[1], NumberStyles.Float, CultureInfo.InvariantCulture, out upDown) && upDown > 0f && float.IsFinite(upDown)))
            {
                return new EndpointTolerance(across, upDown);
            }
        }

        throw new CliException($"{option} takes ACROSS[,UPDOWN] in metres, both positive (for example 0.5,0.25), not '{text}'.");
    }

    /// <summary>Loads a level file (.glb or .gltf); what its reader repaired is said on <paramref name="notes"/>, once.</summary>
    public static Level LoadLevel(string path, TextWriter? notes = null)
    {
        CheckPath(path, "Level file");
        if (!File.Exists(path))
        {
            throw new InputFileException($"Level file '{path}' {Missing(path)}.");
        }

        string extension = Path.GetExtension(path).ToLowerInvariant();
        if (extension is not (".glb" or ".gltf"))
        {
            throw new InputFileException($"Level file '{path}' is not glTF: give a .glb or .gltf file.");
        }

        Level level = GltfLevelLoader.Load(path);
        if (level.Repaired is string repaired)
        {
            notes?.WriteLine($"note: {MessageText.Printable(path)} is not valid glTF ({repaired.TrimEnd('.')}); loaded as repaired.");
        }

        return level;
    }

    /// <summary>
    /// The bundled level file <paramref name="name"/>.glb under Scenes/levels, looked for upwards from the current
    /// folder and from the tool's own folder; <c>null</c> when it is not there.
    /// </summary>
    public static string? FindBundledLevel(string name)
    {
        foreach (string start in new[] { Directory.GetCurrentDirectory(), AppContext.BaseDirectory })
        {
            for (DirectoryInfo? dir = new(start); dir is not null; dir = dir.Parent)
            {
                string candidate = Path.Combine(dir.FullName, "Scenes", "levels", name + ".glb");
                if (File.Exists(candidate))
                {
                    return candidate;
                }
            }
        }

        return null;
    }

    /// <summary>
    /// The character named on the command line: a preset name, or a limb spec file (<c>NAME.limbs.json</c>) whose
    /// rigged glTF its <c>rig</c> key names or sits beside it as <c>NAME.glb</c> (or <c>NAME.gltf</c>). What the rig's
    /// reader repaired is said on <paramref name="notes"/>, once.
    /// </summary>
    public static (ReducedCharacter Reduced, CharacterModel Model) Character(string value, TextWriter? notes = null)
    {
        if (!value.EndsWith(".json", StringComparison.OrdinalIgnoreCase))
        {
            return (CharacterPresets.Get(value), CharacterPresets.Model(value));
        }

        CheckPath(value, "Limb spec");
        if (!File.Exists(value))
        {
            throw new InputFileException($"Limb spec '{value}' {Missing(value)}.");
        }

        (CharacterModel model, ReducedCharacter reduced) = CharacterSpecFile.Load(value);
        if (model.Source?.Model is { Repaired: string repaired } rig)
        {
            notes?.WriteLine($"note: {MessageText.Printable(rig.Name)} is not valid glTF ({repaired.TrimEnd('.')}); loaded as repaired.");
        }

        return (reduced, model);
    }

    /// <summary>Builds a generated level in memory.</summary>
    public static Level Generated(string name) => LevelGenerator.BuildLevel(name);

    /// <summary>The highest surface point under (x, z), or the given height when there is none.</summary>
    public static Vector3 OnGround(TriangleBvh bvh, float x, float z, float fallbackY)
    {
        float top = bvh.Bounds.Max.Y + 1f;
        float depth = top - bvh.Bounds.Min.Y + 2f;
        return bvh.Raycast(new Vector3(x, top, z), new Vector3(0f, -depth, 0f), 1f, out RayHit hit) ? hit.Point : new Vector3(x, fallbackY, z);
    }
}
