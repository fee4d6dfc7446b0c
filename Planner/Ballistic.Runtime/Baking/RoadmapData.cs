using System.Globalization;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime.Core;

namespace Ballistic.Runtime.Baking;

/// <summary>
/// A baked roadmap as an engine resource holds it (Godot's <c>JumpRoadmapData</c>), engine-free: every field is a
/// primitive (<c>byte[]</c>, <c>string</c>, <c>int</c>, <c>double</c>) that the resource copies to and from its
/// exported properties. The bytes are the <see cref="RoadmapFile"/> format, which carries its own checksum and
/// fingerprints; the other fields repeat what the inspector shows and what <see cref="Staleness"/> needs without
/// parsing the bytes. <see cref="Load"/> checks that both agree.
/// </summary>
public sealed class RoadmapData
{
    private readonly byte[] _bytes = [];
    private readonly string _levelFingerprint = "";
    private readonly string _characterFingerprint = "";
    private readonly string _characterName = "";

    /// <summary>The roadmap in <see cref="RoadmapFile"/> format (<see cref="RoadmapFile.ToBytes"/>). Empty: nothing baked. Do not change the array.</summary>
    public required byte[] RoadmapBytes { get => _bytes; init => _bytes = value ?? []; }

    /// <summary>The hex <see cref="Level.Fingerprint"/> of the level it was baked on.</summary>
    public required string LevelFingerprint { get => _levelFingerprint; init => _levelFingerprint = value ?? ""; }

    /// <summary>The hex <see cref="ReducedCharacter.Fingerprint"/> of the character it was baked for.</summary>
    public required string CharacterFingerprint { get => _characterFingerprint; init => _characterFingerprint = value ?? ""; }

    /// <summary>The name of the character it was baked for.</summary>
    public string CharacterName { get => _characterName; init => _characterName = value ?? ""; }

    /// <summary>The bake's seed (<see cref="BakeSettings.Seed"/>).</summary>
    public int Seed { get; init; }

    /// <summary>The bake's node budget (<see cref="BakeSettings.MaxNodes"/>), or 0 when it had none.</summary>
    public int MaxNodes { get; init; }

    /// <summary>The bake's time limit in seconds (<see cref="BakeSettings.TimeLimit"/>), or 0 when it had none.</summary>
    public double TimeLimitSeconds { get; init; }

    /// <summary>Nodes in the roadmap.</summary>
    public int NodeCount { get; init; }

    /// <summary>Jumps (directed edges) in the roadmap.</summary>
    public int JumpCount { get; init; }

    /// <summary>Wall-clock seconds the bake took (<see cref="BakeResult.Elapsed"/>).</summary>
    public double BakeSeconds { get; init; }

    /// <summary>True when no roadmap is held (no bytes).</summary>
    public bool IsEmpty => _bytes.Length == 0;

    /// <summary>One line for the inspector, e.g. "200 nodes, 3114 jumps for 'skeleton' (seed 1), baked in 12.3 s".</summary>
    public string Summary => IsEmpty
        ? "no roadmap baked"
        : string.Create(CultureInfo.InvariantCulture, $"{NodeCount} nodes, {JumpCount} jumps for '{CharacterName}' (seed {Seed}), baked in {BakeSeconds:0.0} s");

    /// <summary>The data of a finished bake.</summary>
    /// <param name="result">The bake's result: not cancelled, its start and goal placed, at least one node.</param>
    /// <param name="settings">The settings it was baked with.</param>
    /// <exception cref="ArgumentException">The bake was cancelled, failed to place its start or goal, or holds no node: it has no data to keep.</exception>
    public static RoadmapData FromBake(BakeResult result, BakeSettings settings)
    {
        ArgumentNullException.ThrowIfNull(result);
        ArgumentNullException.ThrowIfNull(settings);
        if (result.Status is PlannerStatus.Cancelled or PlannerStatus.InvalidStart or PlannerStatus.InvalidGoal || result.Roadmap.Nodes.Count == 0)
        {
            throw new ArgumentException($"A bake that ended '{result.Status}' with {result.Roadmap.Nodes.Count} nodes gives no roadmap data ({OneLine.Of(result.Reason)}).", nameof(result));
        }

        Roadmap roadmap = result.Roadmap;
        return new RoadmapData
        {
            RoadmapBytes = RoadmapFile.ToBytes(roadmap),
            LevelFingerprint = roadmap.LevelFingerprint,
            CharacterFingerprint = roadmap.CharacterFingerprint,
            CharacterName = roadmap.CharacterName,
            Seed = roadmap.Seed,
            MaxNodes = settings.MaxNodes ?? 0,
            TimeLimitSeconds = settings.TimeLimit?.TotalSeconds ?? 0d,
            NodeCount = roadmap.Nodes.Count,
            JumpCount = roadmap.Edges.Count,
            BakeSeconds = result.Elapsed.TotalSeconds,
        };
    }

    /// <summary>
    /// The frozen roadmap, checked for this level and character: the bytes' checksum, every value, the level and
    /// character fingerprints, and that the other fields agree with the bytes.
    /// </summary>
    /// <param name="level">The level it will be used on.</param>
    /// <param name="character">The character it will be used for.</param>
    /// <param name="name">Names the data in messages (e.g. the resource's <c>res://</c> path).</param>
    /// <exception cref="RoadmapFileException">One line: nothing baked, bytes corrupt or truncated, baked on another level or for another character, or fields that disagree with the bytes.</exception>
    public Roadmap Load(Level level, ReducedCharacter character, string name = "(roadmap data)")
    {
        ArgumentNullException.ThrowIfNull(level);
        ArgumentNullException.ThrowIfNull(character);
        ArgumentNullException.ThrowIfNull(name);
        name = OneLine.Of(name);
        if (IsEmpty)
        {
            throw new RoadmapFileException($"Roadmap data {name} is empty: bake the roadmap first.");
        }

        Roadmap roadmap = RoadmapFile.FromBytes(_bytes, name, level, character);
        string? disagreement =
            roadmap.LevelFingerprint != LevelFingerprint ? $"its level fingerprint {OneLine.Short(OneLine.Of(LevelFingerprint))} is not its bytes' {OneLine.Short(roadmap.LevelFingerprint)}"
            : roadmap.CharacterFingerprint != CharacterFingerprint ? $"its character fingerprint {OneLine.Short(OneLine.Of(CharacterFingerprint))} is not its bytes' {OneLine.Short(roadmap.CharacterFingerprint)}"
            : roadmap.CharacterName != CharacterName ? $"its character name '{OneLine.Of(CharacterName)}' is not its bytes' '{OneLine.Of(roadmap.CharacterName)}'"
            : roadmap.Seed != Seed ? $"its seed {Seed} is not its bytes' {roadmap.Seed}"
            : roadmap.Nodes.Count != NodeCount || roadmap.Edges.Count != JumpCount ? $"it counts {NodeCount} nodes and {JumpCount} jumps, its bytes {roadmap.Nodes.Count} and {roadmap.Edges.Count}"
            : null;
        return disagreement is null
            ? roadmap
            : throw new RoadmapFileException($"Roadmap data {name} is inconsistent: {disagreement}; bake it again.");
    }

    /// <summary>
    /// Why the roadmap no longer fits, for a configuration warning, or <c>null</c> when it was baked on this level for
    /// this character. Compares fingerprints only (cheap); <see cref="Load"/> checks the bytes too.
    /// </summary>
    /// <param name="levelFingerprint">The current level's fingerprint (<see cref="SourceGeometry.Fingerprint"/>).</param>
    /// <param name="character">The current character.</param>
    /// <returns>
    /// <c>null</c>, or one line such as "the level changed since the bake (fingerprint 3fa2… ≠ 9c01…)"; several
    /// reasons are joined with "; ".
    /// </returns>
    public string? Staleness(string levelFingerprint, ReducedCharacter character)
    {
        ArgumentNullException.ThrowIfNull(levelFingerprint);
        ArgumentNullException.ThrowIfNull(character);
        if (IsEmpty)
        {
            return "no roadmap has been baked";
        }

        var reasons = new List<string>(2);
        if (!string.Equals(LevelFingerprint, levelFingerprint, StringComparison.Ordinal))
        {
            reasons.Add($"the level changed since the bake (fingerprint {OneLine.Short(OneLine.Of(LevelFingerprint))} ≠ {OneLine.Short(OneLine.Of(levelFingerprint))})");
        }

        if (!string.Equals(CharacterFingerprint, character.Fingerprint, StringComparison.Ordinal))
        {
            reasons.Add(CharacterName == character.Name
                ? $"the character '{OneLine.Of(character.Name)}' changed since the bake (fingerprint {OneLine.Short(OneLine.Of(CharacterFingerprint))} ≠ {OneLine.Short(character.Fingerprint)})"
                : $"the roadmap was baked for the character '{OneLine.Of(CharacterName)}', not '{OneLine.Of(character.Name)}'");
        }

        return reasons.Count == 0 ? null : string.Join("; ", reasons);
    }
}
