#nullable enable
using Ballistic.Runtime.Baking;
using Godot;

namespace Ballistic.Addon;

/// <summary>
/// A baked jump roadmap, saved as a binary <c>.res</c> beside the scene (like a baked <c>NavigationMesh</c>): the
/// roadmap's bytes, the fingerprints of the level and character it was baked for, and the settings and counts of the
/// bake. A mirror of <see cref="RoadmapData"/>, whose checks (<see cref="RoadmapData.Load"/>,
/// <see cref="RoadmapData.Staleness"/>) decide whether the data can be used.
/// </summary>
[Tool]
[GlobalClass]
[Icon("res://addons/ballistic/icons/JumpRoadmapData.svg")]
public partial class JumpRoadmapData : Resource
{
    /// <summary>The roadmap (<c>RoadmapFile</c> bytes).</summary>
    [Export]
    public byte[] RoadmapBytes { get; set; } = [];

    /// <summary>Fingerprint of the level geometry the roadmap was baked on.</summary>
    [Export]
    public string LevelFingerprint { get; set; } = "";

    /// <summary>Fingerprint of the character the roadmap was baked for.</summary>
    [Export]
    public string CharacterFingerprint { get; set; } = "";

    /// <summary>Name of the character the roadmap was baked for.</summary>
    [Export]
    public string CharacterName { get; set; } = "";

    /// <summary>The bake's seed.</summary>
    [Export]
    public int Seed { get; set; }

    /// <summary>The bake's node budget.</summary>
    [Export]
    public int MaxNodes { get; set; }

    /// <summary>The bake's time limit, seconds (0: none).</summary>
    [Export]
    public double TimeLimitSeconds { get; set; }

    /// <summary>Stances (roadmap nodes) baked.</summary>
    [Export]
    public int NodeCount { get; set; }

    /// <summary>Jumps (roadmap edges) baked.</summary>
    [Export]
    public int JumpCount { get; set; }

    /// <summary>How long the bake took, seconds.</summary>
    [Export]
    public double BakeSeconds { get; set; }

    /// <summary>The data as the runtime reads it.</summary>
    public RoadmapData ToData() => new()
    {
        RoadmapBytes = RoadmapBytes,
        LevelFingerprint = LevelFingerprint,
        CharacterFingerprint = CharacterFingerprint,
        CharacterName = CharacterName,
        Seed = Seed,
        MaxNodes = MaxNodes,
        TimeLimitSeconds = TimeLimitSeconds,
        NodeCount = NodeCount,
        JumpCount = JumpCount,
        BakeSeconds = BakeSeconds,
    };

    /// <summary>A resource holding <paramref name="data"/>.</summary>
    public static JumpRoadmapData FromData(RoadmapData data)
    {
        System.ArgumentNullException.ThrowIfNull(data);
        return new JumpRoadmapData
        {
            RoadmapBytes = data.RoadmapBytes,
            LevelFingerprint = data.LevelFingerprint,
            CharacterFingerprint = data.CharacterFingerprint,
            CharacterName = data.CharacterName,
            Seed = data.Seed,
            MaxNodes = data.MaxNodes,
            TimeLimitSeconds = data.TimeLimitSeconds,
            NodeCount = data.NodeCount,
            JumpCount = data.JumpCount,
            BakeSeconds = data.BakeSeconds,
        };
    }
}
