using Ballistic.Authoring.Rigs;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Rigs;

namespace Ballistic.Authoring.Characters;

/// <summary>
/// The reduced characters of the original scenarios (planning notes §7): friction, speed limits, limbs and how
/// many must touch follow the original scripts; every trunk box and limb workspace is derived from the character's
/// rig by sampling its joints (<see cref="ReducedModelBuilder"/>).
/// </summary>
public static class CharacterPresets
{
    /// <summary>The names of every preset, in a stable order.</summary>
    public static IReadOnlyList<string> Names { get; } = ["skeleton", "frog", "ant", "jumperman"];

    /// <summary>The preset called <paramref name="name"/> (case-insensitive).</summary>
    /// <exception cref="CharacterException">No preset has that name; the message lists the presets.</exception>
    public static ReducedCharacter Get(string name) => name?.ToLowerInvariant() switch
    {
        "skeleton" => Skeleton(),
        "frog" => Frog(),
        "ant" => Ant(),
        "jumperman" => Jumperman(),
        _ => throw new CharacterException($"Unknown character '{name}'. Known characters: {string.Join(", ", Names)}."),
    };

    /// <summary>
    /// A 1.8 m humanoid skeleton: two feet and two hands, any two must touch; μ 0.5, 8 m/s takeoff, 12 m/s landing.
    /// Trunk and workspaces derived from the 39-DOF humanoid rig (<see cref="HumanoidBuilder"/>).
    /// </summary>
    public static ReducedCharacter Skeleton() => SkeletonReduced.Value;

    /// <summary>
    /// A city-scale superhero: the humanoid rig with feet that need level ground and hands that may push off walls;
    /// any two must touch; μ 1.2, 30 m/s takeoff and landing.
    /// </summary>
    public static ReducedCharacter Jumperman() => JumpermanReduced.Value;

    /// <summary>The whole character (rig, limbs, reference poses) behind a preset.</summary>
    /// <exception cref="CharacterException">No preset has that name.</exception>
    public static CharacterModel Model(string name) => name?.ToLowerInvariant() switch
    {
        "skeleton" => SkeletonModel.Value,
        "jumperman" => JumpermanModel.Value,
        "frog" => FrogModel.Value,
        "ant" => AntModel.Value,
        _ => throw new CharacterException($"Unknown character '{name}'. Known characters: {string.Join(", ", Names)}."),
    };

    private static readonly Lazy<CharacterModel> SkeletonModel = new(() => HumanoidBuilder.Build("skeleton", handsOnWalls: false));
    private static readonly Lazy<CharacterModel> JumpermanModel = new(() => HumanoidBuilder.Build("jumperman", handsOnWalls: true));

    private static readonly Lazy<CharacterModel> FrogModel = new(FrogBuilder.Build);

    private static readonly Lazy<CharacterModel> AntModel = new(AntBuilder.Build);

    private static readonly Lazy<ReducedCharacter> FrogReduced = new(() => ReducedModelBuilder.Derive(FrogModel.Value, requiredContacts: 4, takeoffSpeedMax: 5f, landingSpeedMax: 9f, friction: 1.2f));

    private static readonly Lazy<ReducedCharacter> AntReduced = new(() => ReducedModelBuilder.Derive(AntModel.Value, requiredContacts: 3, takeoffSpeedMax: 8f, landingSpeedMax: 11f, friction: 1.2f));

    private static readonly Lazy<ReducedCharacter> SkeletonReduced = new(() => ReducedModelBuilder.Derive(SkeletonModel.Value, requiredContacts: 2, takeoffSpeedMax: 8f, landingSpeedMax: 12f, friction: 0.5f));

    private static readonly Lazy<ReducedCharacter> JumpermanReduced = new(() => ReducedModelBuilder.Derive(JumpermanModel.Value, requiredContacts: 2, takeoffSpeedMax: 30f, landingSpeedMax: 30f, friction: 1.2f));

    /// <summary>A 35 cm frog with long hind legs: all four limbs must touch; μ 1.2, 5 m/s takeoff, 9 m/s landing (rig: <see cref="FrogBuilder"/>).</summary>
    public static ReducedCharacter Frog() => FrogReduced.Value;

    /// <summary>A 60 cm six-legged ant: any three legs must touch; μ 1.2, 8 m/s takeoff, 11 m/s landing (rig: <see cref="AntBuilder"/>).</summary>
    public static ReducedCharacter Ant() => AntReduced.Value;
}
