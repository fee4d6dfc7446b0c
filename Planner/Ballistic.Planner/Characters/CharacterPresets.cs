using System.Numerics;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Rigs.Procedural;

namespace Ballistic.Planner.Characters;

/// <summary>
/// The reduced characters of the original scenarios (planning notes §7): friction, speed limits, limbs and how
/// many must touch follow the original scripts. The humanoids' trunk and workspace boxes are derived from their
/// rigs; the frog's and the ant's are still set by hand.
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

    /// <summary>The whole character behind a preset, for animation; <c>null</c> for presets that have no rig yet.</summary>
    public static CharacterModel? Model(string name) => name?.ToLowerInvariant() switch
    {
        "skeleton" => SkeletonModel.Value,
        "jumperman" => JumpermanModel.Value,
        _ => null,
    };

    private static readonly Lazy<CharacterModel> SkeletonModel = new(() => HumanoidBuilder.Build("skeleton", handsOnWalls: false));
    private static readonly Lazy<CharacterModel> JumpermanModel = new(() => HumanoidBuilder.Build("jumperman", handsOnWalls: true));

    private static readonly Lazy<ReducedCharacter> SkeletonReduced = new(() => ReducedModelBuilder.Derive(SkeletonModel.Value, requiredContacts: 2, takeoffSpeedMax: 8f, landingSpeedMax: 12f, friction: 0.5f));

    private static readonly Lazy<ReducedCharacter> JumpermanReduced = new(() => ReducedModelBuilder.Derive(JumpermanModel.Value, requiredContacts: 2, takeoffSpeedMax: 30f, landingSpeedMax: 30f, friction: 1.2f));

    /// <summary>A 35 cm frog with long hind legs: all four limbs must touch; μ 1.2, 5 m/s takeoff, 9 m/s landing.</summary>
    public static ReducedCharacter Frog()
    {
        NormalFilter any = NormalFilter.None;
        Vector3 fore = new(0.08f, 0.10f, 0.10f);
        Vector3 hind = new(0.12f, 0.12f, 0.15f);
        return new ReducedCharacter(
            "frog",
            new Vector3(0.09f, 0.06f, 0.15f),
            [
                new Limb("left_fore", LimbKind.Hand, new Vector3(0.12f, -0.13f, 0.13f), fore, Quaternion.Identity, any),
                new Limb("right_fore", LimbKind.Hand, new Vector3(-0.12f, -0.13f, 0.13f), fore, Quaternion.Identity, any),
                new Limb("left_hind", LimbKind.Foot, new Vector3(0.16f, -0.15f, -0.12f), hind, Quaternion.Identity, any),
                new Limb("right_hind", LimbKind.Foot, new Vector3(-0.16f, -0.15f, -0.12f), hind, Quaternion.Identity, any),
            ],
            requiredContacts: 4,
            takeoffSpeedMax: 5f,
            landingSpeedMax: 9f,
            friction: 1.2f);
    }

    /// <summary>A 60 cm six-legged ant: any three legs must touch; μ 1.2, 8 m/s takeoff, 11 m/s landing.</summary>
    public static ReducedCharacter Ant()
    {
        NormalFilter up = NormalFilter.Upward(0.3f);
        Vector3 leg = new(0.16f, 0.14f, 0.12f);
        var limbs = new List<Limb>();
        string[] rows = ["front", "middle", "hind"];
        float[] z = [0.22f, 0f, -0.22f];
        for (int i = 0; i < 3; i++)
        {
            limbs.Add(new Limb($"left_{rows[i]}", LimbKind.Foot, new Vector3(0.28f, -0.17f, z[i]), leg, Quaternion.Identity, up));
            limbs.Add(new Limb($"right_{rows[i]}", LimbKind.Foot, new Vector3(-0.28f, -0.17f, z[i]), leg, Quaternion.Identity, up));
        }

        return new ReducedCharacter("ant", new Vector3(0.12f, 0.07f, 0.30f), limbs, requiredContacts: 3, takeoffSpeedMax: 8f, landingSpeedMax: 11f, friction: 1.2f);
    }
}
