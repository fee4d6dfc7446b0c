#nullable enable
using Ballistic.Planner.Characters;
using Ballistic.Planner.Rigs;
using Ballistic.Runtime.Baking;
using Godot;

namespace Ballistic.Addon;

/// <summary>
/// A kind of jumping character, as an inspector resource: its rigged glTF binary (<c>.glb</c>) and limb spec
/// (<c>NAME.limbs.json</c>, schema <c>ballistic.character/1</c>), and optional overrides of the spec's speed limits and
/// friction. The bundled presets are <c>res://Scenes/characters/{skeleton,frog,jumperman,ant}.tres</c>. The files are
/// read with <see cref="Godot.FileAccess"/>, so they work in exported games; everything else is
/// <see cref="CharacterAsset"/>'s.
/// </summary>
[Tool]
[GlobalClass]
[Icon("res://addons/ballistic/icons/JumpCharacter.svg")]
public partial class JumpCharacter : Resource
{
    private (string Key, CharacterModel Model, ReducedCharacter Reduced)? _loaded;

    /// <summary>A name for messages and the inspector.</summary>
    [Export]
    public string DisplayName { get; set; } = "";

    /// <summary>The rigged character, a <c>.glb</c> file (<c>res://</c> path).</summary>
    [Export(PropertyHint.File, "*.glb")]
    public string RigPath { get; set; } = "";

    /// <summary>The limb spec, a <c>*.limbs.json</c> file (<c>res://</c> path).</summary>
    [Export(PropertyHint.File, "*.json")]
    public string LimbSpecPath { get; set; } = "";

    /// <summary>Largest takeoff speed, m/s; 0 keeps the spec's.</summary>
    [ExportGroup("Overrides")]
    [Export(PropertyHint.Range, "0,50,0.1,or_greater")]
    public float TakeoffSpeedMax { get; set; }

    /// <summary>Largest landing speed, m/s; 0 keeps the spec's.</summary>
    [Export(PropertyHint.Range, "0,50,0.1,or_greater")]
    public float LandingSpeedMax { get; set; }

    /// <summary>Coulomb friction μ of surfaces without their own; 0 keeps the spec's.</summary>
    [Export(PropertyHint.Range, "0,3,0.01,or_greater")]
    public float Friction { get; set; }

    /// <summary>
    /// The planner's character: the rig and the reduced model (trunk box, limb workspaces), loaded once per set of
    /// property values.
    /// </summary>
    /// <exception cref="Planner.IO.BallisticInputException">A file is missing or invalid (one line naming it).</exception>
    public (CharacterModel Model, ReducedCharacter Reduced) Load()
    {
        string key = $"{RigPath}|{LimbSpecPath}|{TakeoffSpeedMax}|{LandingSpeedMax}|{Friction}";
        if (_loaded is { } cached && cached.Key == key)
        {
            return (cached.Model, cached.Reduced);
        }

        CharacterAsset asset = CharacterAsset.FromBytes(
            Read(RigPath, "rig"), RigPath, Read(LimbSpecPath, "limb spec"), LimbSpecPath,
            TakeoffSpeedMax > 0f ? TakeoffSpeedMax : null,
            LandingSpeedMax > 0f ? LandingSpeedMax : null,
            Friction > 0f ? Friction : null);
        (CharacterModel model, ReducedCharacter reduced) = asset.Load();
        _loaded = (key, model, reduced);
        return (model, reduced);
    }

    private byte[] Read(string path, string what)
    {
        if (string.IsNullOrEmpty(path))
        {
            throw new CharacterException($"JumpCharacter '{DisplayName}' ({ResourcePath}): no {what} file is set.");
        }

        byte[] bytes = Godot.FileAccess.GetFileAsBytes(path);
        return bytes.Length > 0
            ? bytes
            : throw new CharacterException($"JumpCharacter '{DisplayName}': the {what} file {path} cannot be read ({Godot.FileAccess.GetOpenError()}).");
    }
}
