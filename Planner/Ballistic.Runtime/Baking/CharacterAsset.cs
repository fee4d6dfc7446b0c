using System.Globalization;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Rigs;
using Ballistic.Runtime.Core;

namespace Ballistic.Runtime.Baking;

/// <summary>
/// A kind of character as an engine resource describes it (Godot's <c>JumpCharacter</c>), engine-free: a rigged
/// glTF (<c>.glb</c>) and its limb spec (<c>ballistic.character/1</c> JSON), given as file paths (the editor, the
/// command line) or as bytes read by the caller (an exported game reads <c>res://</c> files with <c>FileAccess</c>),
/// and optional overrides of the spec's speed limits and friction. <see cref="Load"/> turns it into the planner's
/// <see cref="ReducedCharacter"/> and <see cref="CharacterModel"/> with <see cref="CharacterSpecFile"/>, as the command
/// line's <c>--character NAME.limbs.json</c> does. The bundled characters are <c>Scenes/characters/NAME.glb</c> with
/// <c>NAME.limbs.json</c> beside them (skeleton, frog, jumperman, ant).
/// </summary>
public sealed class CharacterAsset
{
    private readonly string? _rigPath;
    private readonly string? _specPath;
    private readonly byte[]? _rigBytes;
    private readonly byte[]? _specBytes;

    private CharacterAsset(string rigName, string specName, string? rigPath, string? specPath, byte[]? rigBytes, byte[]? specBytes, float? takeoffSpeedMax, float? landingSpeedMax, float? friction)
    {
        RigName = rigName;
        SpecName = specName;
        _rigPath = rigPath;
        _specPath = specPath;
        _rigBytes = rigBytes;
        _specBytes = specBytes;
        TakeoffSpeedMax = takeoffSpeedMax;
        LandingSpeedMax = landingSpeedMax;
        Friction = friction;
    }

    /// <summary>Names the rig in messages: its path, or the name given with its bytes.</summary>
    public string RigName { get; }

    /// <summary>Names the limb spec in messages: its path, or the name given with its bytes.</summary>
    public string SpecName { get; }

    /// <summary>Largest takeoff speed, m/s, replacing the spec's; <c>null</c> keeps the spec's.</summary>
    public float? TakeoffSpeedMax { get; }

    /// <summary>Largest landing speed, m/s, replacing the spec's; <c>null</c> keeps the spec's.</summary>
    public float? LandingSpeedMax { get; }

    /// <summary>Default Coulomb friction μ of every surface, replacing the spec's; <c>null</c> keeps the spec's.</summary>
    public float? Friction { get; }

    /// <summary>A character read from files.</summary>
    /// <param name="rigPath">The rigged <c>.glb</c> or <c>.gltf</c> (a filesystem path; globalize <c>res://</c> paths first).</param>
    /// <param name="specPath">Its limb spec (<c>NAME.limbs.json</c>).</param>
    /// <param name="takeoffSpeedMax">Override of the largest takeoff speed, m/s, or <c>null</c>.</param>
    /// <param name="landingSpeedMax">Override of the largest landing speed, m/s, or <c>null</c>.</param>
    /// <param name="friction">Override of the default friction μ, or <c>null</c>.</param>
    public static CharacterAsset FromFiles(string rigPath, string specPath, float? takeoffSpeedMax = null, float? landingSpeedMax = null, float? friction = null)
    {
        ArgumentNullException.ThrowIfNull(rigPath);
        ArgumentNullException.ThrowIfNull(specPath);
        return new CharacterAsset(OneLine.Of(rigPath), OneLine.Of(specPath), rigPath, specPath, null, null, takeoffSpeedMax, landingSpeedMax, friction);
    }

    /// <summary>
    /// A character from the files' bytes, read by the caller. The glTF must hold its buffers (a <c>.glb</c>, or a
    /// <c>.gltf</c> with data URIs).
    /// </summary>
    /// <param name="rigBytes">The rigged <c>.glb</c>'s content.</param>
    /// <param name="rigName">Names the rig in messages (e.g. <c>res://characters/frog.glb</c>).</param>
    /// <param name="specBytes">The limb spec's content.</param>
    /// <param name="specName">Names the limb spec in messages (e.g. <c>res://characters/frog.limbs.json</c>).</param>
    /// <param name="takeoffSpeedMax">Override of the largest takeoff speed, m/s, or <c>null</c>.</param>
    /// <param name="landingSpeedMax">Override of the largest landing speed, m/s, or <c>null</c>.</param>
    /// <param name="friction">Override of the default friction μ, or <c>null</c>.</param>
    public static CharacterAsset FromBytes(byte[] rigBytes, string rigName, byte[] specBytes, string specName, float? takeoffSpeedMax = null, float? landingSpeedMax = null, float? friction = null)
    {
        ArgumentNullException.ThrowIfNull(rigBytes);
        ArgumentNullException.ThrowIfNull(rigName);
        ArgumentNullException.ThrowIfNull(specBytes);
        ArgumentNullException.ThrowIfNull(specName);
        return new CharacterAsset(OneLine.Of(rigName), OneLine.Of(specName), null, null, rigBytes, specBytes, takeoffSpeedMax, landingSpeedMax, friction);
    }

    /// <summary>
    /// Reads the rig and spec and derives the character (a fraction of a second for the bundled ones: cache the
    /// result, and load again when the files or overrides change). The overrides give the same character as a spec
    /// holding those values.
    /// </summary>
    /// <exception cref="RigException">One line naming the file and the problem: missing or unreadable file, invalid JSON, a spec that breaks the schema or does not fit the rig, or an override out of range.</exception>
    public (CharacterModel Model, ReducedCharacter Reduced) Load()
    {
        CheckOverride(TakeoffSpeedMax, "takeoff speed", "m/s", allowZero: false);
        CheckOverride(LandingSpeedMax, "landing speed", "m/s", allowZero: false);
        CheckOverride(Friction, "friction", "μ", allowZero: true);
        (CharacterModel model, ReducedCharacter reduced) = _rigBytes is not null
            ? CharacterSpecFile.FromBytes(_rigBytes, RigName, _specBytes!, SpecName)
            : CharacterSpecFile.Load(_rigPath!, _specPath!);
        if (TakeoffSpeedMax is null && LandingSpeedMax is null && Friction is null)
        {
            return (model, reduced);
        }

        try
        {
            // The spec's speeds and friction reach the reduced character unchanged (the workspaces and stance do not
            // depend on them), so replacing them here is what a spec holding the overrides would give.
            var overridden = new ReducedCharacter(reduced.Name, reduced.TrunkHalfExtents, reduced.Limbs, reduced.RequiredContacts,
                TakeoffSpeedMax ?? reduced.TakeoffSpeedMax, LandingSpeedMax ?? reduced.LandingSpeedMax, Friction ?? reduced.Friction)
            {
                StanceLift = reduced.StanceLift,
                Walking = reduced.Walking,
            };
            return (model, overridden);
        }
        catch (CharacterException e)
        {
            throw new RigException($"{SpecName}: {OneLine.Of(e.Message)}", e);
        }
    }

    private void CheckOverride(float? value, string what, string unit, bool allowZero)
    {
        const float max = 1e3f;
        if (value is not float v)
        {
            return;
        }

        bool aboveMin = allowZero ? v >= 0f : v > 0f;
        if (!aboveMin || !(v <= max))
        {
            throw new RigException(string.Create(CultureInfo.InvariantCulture,
                $"{SpecName}: the {what} override must be {(allowZero ? "between 0 and" : "positive and at most")} {max:0} {unit}, not {v}."));
        }
    }
}
