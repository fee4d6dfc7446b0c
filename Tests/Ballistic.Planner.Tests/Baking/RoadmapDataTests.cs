using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime.Baking;
using Ballistic.Runtime.Core;

namespace Ballistic.Planner.Tests.Baking;

public sealed class RoadmapDataTests
{
    private const string ResourcePath = "res://levels/yard_roadmap.res";

    private static RoadmapData Baked => BakingLevels.Baked.Data!;

    private static Level Level => BakingLevels.FromSources().Build();

    /// <summary>What a Godot resource does: copy every primitive field out to its exports and back.</summary>
    private static RoadmapData ThroughExports(RoadmapData data, Func<RoadmapData, RoadmapData>? edit = null)
    {
        byte[] bytes = [.. data.RoadmapBytes];
        var copy = new RoadmapData
        {
            RoadmapBytes = bytes,
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
        return edit is null ? copy : edit(copy);
    }

    [Test]
    public void TheDataRecordsTheBakeAndRoundTripsThroughPrimitiveFields()
    {
        RoadmapData data = Baked;
        ReducedCharacter skeleton = CharacterPresets.Skeleton();
        Assert.Multiple(() =>
        {
            Assert.That(data.LevelFingerprint, Is.EqualTo(Level.Fingerprint));
            Assert.That(data.CharacterFingerprint, Is.EqualTo(skeleton.Fingerprint));
            Assert.That(data.CharacterName, Is.EqualTo("skeleton"));
            Assert.That(data.Seed, Is.EqualTo(3));
            Assert.That(data.MaxNodes, Is.EqualTo(40));
            Assert.That(data.TimeLimitSeconds, Is.Zero);
            Assert.That(data.NodeCount, Is.EqualTo(40));
            Assert.That(data.JumpCount, Is.EqualTo(BakingLevels.Baked.Roadmap!.Edges.Count).And.GreaterThan(40));
            Assert.That(data.BakeSeconds, Is.GreaterThan(0d));
            Assert.That(data.Summary, Does.StartWith($"40 nodes, {data.JumpCount} jumps for 'skeleton' (seed 3), baked in "));
        });

        Roadmap loaded = ThroughExports(data).Load(Level, skeleton, ResourcePath);
        Assert.Multiple(() =>
        {
            Assert.That(RoadmapFile.ToBytes(loaded), Is.EqualTo(data.RoadmapBytes), "the loaded roadmap is the baked one");
            Assert.That(loaded.Nodes, Has.Count.EqualTo(40));
            Assert.That(loaded.Edges, Has.Count.EqualTo(data.JumpCount));
            Assert.That(ThroughExports(data).Staleness(Level.Fingerprint, skeleton), Is.Null);
        });
    }

    private static IEnumerable<TestCaseData> CorruptBytes()
    {
        yield return new TestCaseData((Func<byte[], byte[]>)(b => { b[b.Length / 2] ^= 0x10; return b; }), "is corrupt or truncated (its checksum does not match)").SetName("AFlippedBit");
        yield return new TestCaseData((Func<byte[], byte[]>)(b => b[..(b.Length - 7)]), "is corrupt or truncated").SetName("Truncated");
        yield return new TestCaseData((Func<byte[], byte[]>)(b => [.. "not a roadmap at all, just text"u8]), "is not a Ballistic roadmap").SetName("NotARoadmap");
        yield return new TestCaseData((Func<byte[], byte[]>)(b => []), "is empty: bake the roadmap first").SetName("Empty");
    }

    [TestCaseSource(nameof(CorruptBytes))]
    public void CorruptBytesAreAOneLineErrorNamingTheResource(Func<byte[], byte[]> corrupt, string problem)
    {
        RoadmapData data = ThroughExports(Baked, d => new RoadmapData
        {
            RoadmapBytes = corrupt([.. d.RoadmapBytes]),
            LevelFingerprint = d.LevelFingerprint,
            CharacterFingerprint = d.CharacterFingerprint,
            CharacterName = d.CharacterName,
            Seed = d.Seed,
            NodeCount = d.NodeCount,
            JumpCount = d.JumpCount,
        });
        RoadmapFileException error = Assert.Throws<RoadmapFileException>(() => data.Load(Level, CharacterPresets.Skeleton(), ResourcePath))!;
        Assert.Multiple(() =>
        {
            Assert.That(error.Message, Does.Contain(ResourcePath));
            Assert.That(error.Message, Does.Contain(problem));
            Assert.That(error.Message, Does.Not.Contain('\n'));
        });
    }

    [Test]
    public void AnotherLevelOrCharacterIsRefusedInOneLine()
    {
        Level moved = BakingLevels.FromSources(BakingLevels.BlockCentre + new Vector3(0.5f, 0f, 0f)).Build();
        ReducedCharacter skeleton = CharacterPresets.Skeleton();
        ReducedCharacter stickySkeleton = new(skeleton.Name, skeleton.TrunkHalfExtents, skeleton.Limbs, skeleton.RequiredContacts, skeleton.TakeoffSpeedMax, skeleton.LandingSpeedMax, 0.9f)
        {
            StanceLift = skeleton.StanceLift,
        };
        string level = Assert.Throws<RoadmapFileException>(() => Baked.Load(moved, skeleton, ResourcePath))!.Message;
        string frog = Assert.Throws<RoadmapFileException>(() => Baked.Load(Level, CharacterPresets.Frog(), ResourcePath))!.Message;
        string version = Assert.Throws<RoadmapFileException>(() => Baked.Load(Level, stickySkeleton, ResourcePath))!.Message;
        Assert.Multiple(() =>
        {
            Assert.That(level, Does.StartWith($"Roadmap file {ResourcePath} was baked on another level (level fingerprint {Baked.LevelFingerprint[..12]}…, this level is {moved.Fingerprint[..12]}…)"));
            Assert.That(frog, Is.EqualTo($"Roadmap file {ResourcePath} was baked for the character 'skeleton', not 'frog'."));
            Assert.That(version, Is.EqualTo($"Roadmap file {ResourcePath} was baked for a different version of the character 'skeleton'; bake it again."));
        });
    }

    [Test]
    public void ANameWithLineBreaksOrTerminalEscapesIsRefusedInOneLineAndEscaped()
    {
        // A modder's character whose name fakes an error line and a stack frame, and clears the terminal.
        ReducedCharacter frog = CharacterPresets.Frog();
        ReducedCharacter hostile = new("frog\nerror: fake\n   at Evil.Frame()\u001b[2J", frog.TrunkHalfExtents, frog.Limbs, frog.RequiredContacts, frog.TakeoffSpeedMax, frog.LandingSpeedMax, frog.Friction)
        {
            StanceLift = frog.StanceLift,
        };
        string message = Assert.Throws<RoadmapFileException>(() => Baked.Load(Level, hostile, ResourcePath))!.Message;
        Assert.Multiple(() =>
        {
            Assert.That(message, Does.Not.Contain('\n').And.Not.Contain('\u001b'));
            Assert.That(message, Is.EqualTo($"Roadmap file {ResourcePath} was baked for the character 'skeleton', not 'frog\\u000aerror: fake\\u000a   at Evil.Frame()\\u001b[2J'."));
            Assert.That(new RuntimeResult(RuntimeStatus.Mismatch, "kind 'a\r\nerror: b'").Reason, Is.EqualTo("kind 'a\\u000d\\u000aerror: b'"), "the runtime's results too");
        });
    }

    [Test]
    public void FieldsThatDisagreeWithTheBytesAreRefused()
    {
        RoadmapData edited = ThroughExports(Baked, d => new RoadmapData
        {
            RoadmapBytes = d.RoadmapBytes,
            LevelFingerprint = d.LevelFingerprint,
            CharacterFingerprint = d.CharacterFingerprint,
            CharacterName = d.CharacterName,
            Seed = d.Seed,
            NodeCount = d.NodeCount + 1,
            JumpCount = d.JumpCount,
        });
        RoadmapData otherLevelField = ThroughExports(Baked, d => new RoadmapData
        {
            RoadmapBytes = d.RoadmapBytes,
            LevelFingerprint = new string('0', 64),
            CharacterFingerprint = d.CharacterFingerprint,
            CharacterName = d.CharacterName,
            Seed = d.Seed,
            NodeCount = d.NodeCount,
            JumpCount = d.JumpCount,
        });
        string counts = Assert.Throws<RoadmapFileException>(() => edited.Load(Level, CharacterPresets.Skeleton(), ResourcePath))!.Message;
        string fingerprint = Assert.Throws<RoadmapFileException>(() => otherLevelField.Load(Level, CharacterPresets.Skeleton(), ResourcePath))!.Message;
        Assert.Multiple(() =>
        {
            Assert.That(counts, Is.EqualTo($"Roadmap data {ResourcePath} is inconsistent: it counts 41 nodes and {Baked.JumpCount} jumps, its bytes 40 and {Baked.JumpCount}; bake it again."));
            Assert.That(fingerprint, Does.StartWith($"Roadmap data {ResourcePath} is inconsistent: its level fingerprint 000000000000… is not its bytes'"));
        });
    }

    [Test]
    public void StalenessNamesWhatChangedSinceTheBake()
    {
        ReducedCharacter skeleton = CharacterPresets.Skeleton();
        string current = Level.Fingerprint;
        string moved = BakingLevels.FromSources(BakingLevels.BlockCentre + new Vector3(0f, 0f, 1f)).Fingerprint;
        Assert.Multiple(() =>
        {
            Assert.That(Baked.Staleness(current, skeleton), Is.Null);
            Assert.That(Baked.Staleness(moved, skeleton), Is.EqualTo($"the level changed since the bake (fingerprint {current[..12]}… ≠ {moved[..12]}…)"));
            Assert.That(Baked.Staleness(current, CharacterPresets.Frog()), Is.EqualTo("the roadmap was baked for the character 'skeleton', not 'frog'"));
            Assert.That(Baked.Staleness(moved, CharacterPresets.Frog()), Is.EqualTo($"the level changed since the bake (fingerprint {current[..12]}… ≠ {moved[..12]}…); the roadmap was baked for the character 'skeleton', not 'frog'"));
            Assert.That(new RoadmapData { RoadmapBytes = [], LevelFingerprint = "", CharacterFingerprint = "" }.Staleness(current, skeleton), Is.EqualTo("no roadmap has been baked"));
        });
    }

    [Test]
    public void ACancelledOrEmptyBakeGivesNoData()
    {
        var scene = PlanningScene.Create(Level, CharacterPresets.Skeleton());
        var settings = new BakeSettings { Seed = 1, MaxNodes = 10, Threads = 1 };
        using var cancelled = new CancellationTokenSource();
        cancelled.Cancel();
        BakeResult result = new RoadmapBaker(scene).Bake(settings, TerminationCondition.Cancellation(cancelled.Token));
        Assert.That(result.Status, Is.EqualTo(PlannerStatus.Cancelled));
        ArgumentException error = Assert.Throws<ArgumentException>(() => RoadmapData.FromBake(result, settings))!;
        Assert.That(error.Message, Does.Contain("'Cancelled' with 0 nodes gives no roadmap data"));
    }
}
