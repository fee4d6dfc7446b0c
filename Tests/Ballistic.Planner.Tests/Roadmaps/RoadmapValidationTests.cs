using System.Numerics;
using System.Security.Cryptography;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Roadmaps;

/// <summary>A checksum only says the bytes are as written: roadmaps edited with the checksum recomputed are checked value by value.</summary>
public sealed class RoadmapValidationTests
{
    private static readonly Lazy<PlanningScene> Scene = new(() => PlanningScene.Create(GapCourse.Build(), CharacterPresets.Skeleton()));
    private static readonly Lazy<Roadmap> Baked = new(() => new RoadmapBaker(Scene.Value).Bake(new BakeSettings { Seed = 21, MaxNodes = 30, Threads = 2 }).Roadmap);

    private string _folder = "";

    [SetUp]
    public void MakeFolder()
    {
        _folder = Path.Combine(Path.GetTempPath(), $"ballistic-roadmap-{Guid.NewGuid():N}");
        Directory.CreateDirectory(_folder);
    }

    [TearDown]
    public void RemoveFolder() => Directory.Delete(_folder, recursive: true);

    /// <summary>The baked roadmap with one node or edge replaced, written with a valid checksum.</summary>
    private string Tampered(Func<RoadmapNode, RoadmapNode>? node = null, Func<RoadmapEdge, RoadmapEdge>? edge = null)
    {
        Roadmap good = Baked.Value;
        var copy = new RoadmapBuilder(good.LevelFingerprint, good.CharacterFingerprint, good.CharacterName, good.Seed);
        foreach (RoadmapNode n in good.Nodes)
        {
            copy.AddNode(n.Id == 3 && node is not null ? node(n) : n);
        }

        for (int e = 0; e < good.Edges.Count; e++)
        {
            copy.AddEdge(e == 5 && edge is not null ? edge(good.Edges[e]) : good.Edges[e]);
        }

        string path = Path.Combine(_folder, $"{Guid.NewGuid():N}.roadmap");
        File.WriteAllBytes(path, RoadmapFile.ToBytes(copy.Freeze()));
        return path;
    }

    private static RoadmapEdge WithArc(RoadmapEdge e, Vector3 velocity, float time, float gravity) =>
        e with { Arc = new BallisticArc(e.Arc.Takeoff, e.Arc.Landing, velocity, time, gravity) };

    [Test]
    public void AnUntouchedRoadmapLoadsWithTheLevel()
    {
        string path = Tampered();
        Assert.That(RoadmapFile.Load(path, Scene.Value.Level, CharacterPresets.Skeleton()).Edges, Has.Count.EqualTo(Baked.Value.Edges.Count));
    }

    [Test]
    public void ABigBakedRoadmapPassesItsOwnChecks()
    {
        Level desert = SharedLevels.Bundled("desert");
        var scene = PlanningScene.Create(desert, CharacterPresets.Skeleton());
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 3, MaxNodes = 300, Threads = 2 }).Roadmap;
        string path = Path.Combine(_folder, "desert.roadmap");
        RoadmapFile.Save(roadmap, path);
        Assert.That(RoadmapFile.Load(path, desert, CharacterPresets.Skeleton()).Edges, Has.Count.EqualTo(roadmap.Edges.Count));
    }

    /// <summary>
    /// A stance edited to lie about the level, with the checksum recomputed, is refused in one line naming the node
    /// and what is false (before: contacts lifted 0.35 m off the ground, or normals and cones turned to point down,
    /// loaded and were planned on as "exact").
    /// </summary>
    [Test]
    public void StancesThatLieAboutTheLevelAreRefused()
    {
        ReducedCharacter skeleton = CharacterPresets.Skeleton();
        Level level = Scene.Value.Level;
        Vector3 up = new(0f, 0.35f, 0f);
        var cases = new (string Path, string Expected)[]
        {
            (Tampered(node: n => n with { Contacts = [.. n.Contacts.Select(c => c with { Position = c.Position + up })] }), "node 3's contact of limb 0 is 0.35 m off the level's surface"),
            (Tampered(node: n => n with { Contacts = [.. n.Contacts.Select(c => c with { Normal = -c.Normal })], Cone = new FrictionCone(-n.Cone.Axis, n.Cone.Mu) }), "node 3's contact of limb 0 has a normal that is not its surface's"),
            (Tampered(node: n => n with { Cone = new FrictionCone(-n.Cone.Axis, n.Cone.Mu) }), "node 3's friction cone points 180° away from its contacts' normals"),
            (Tampered(node: n => n with { Cone = new FrictionCone(n.Cone.Axis, n.Cone.Mu + 0.5f) }), $"node 3's friction cone claims a friction of {Baked.Value.Nodes[3].Cone.Mu + 0.5f:G4}, its contacts' least is"),
            (Tampered(node: n => n with { Contacts = [.. n.Contacts.Select(c => c with { Mu = c.Mu + 1f })], Cone = new FrictionCone(n.Cone.Axis, n.Cone.Mu + 1f) }), "node 3's contact of limb 0 claims a friction of"),
            (Tampered(node: n => n with { Contacts = [.. n.Contacts.Take(skeleton.RequiredContacts - 1)] }), $"node 3 has {skeleton.RequiredContacts - 1} contact"),
        };
        Assume.That(Baked.Value.Nodes[3].Contacts[0].Limb, Is.Zero);
        Assume.That(skeleton.RequiredContacts, Is.GreaterThan(1));
        foreach ((string path, string expected) in cases)
        {
            Assert.That(() => RoadmapFile.Load(path, level, skeleton), Throws.TypeOf<RoadmapFileException>().With.Message.Contains(expected).And.Message.Contains(path).And.Message.Contains("bake it again").And.Message.Not.Contains("\n"), expected);
        }

        // The same stances in memory (an engine resource's bytes) are refused the same way.
        byte[] bytes = File.ReadAllBytes(cases[0].Path);
        Assert.That(() => RoadmapFile.FromBytes(bytes, "res://lifted.tres", level, skeleton), Throws.TypeOf<RoadmapFileException>().With.Message.Contains("0.35 m off the level's surface"));
    }

    [Test]
    public void EditedValuesAreRefusedWithASentence()
    {
        ReducedCharacter skeleton = CharacterPresets.Skeleton();
        Level level = Scene.Value.Level;
        var cases = new (string Path, string Expected)[]
        {
            (Tampered(node: n => n with { Pose = new RootPose(new Vector3(float.NaN, 0f, 0f), n.Pose.Rotation) }), "node 3 has a position that is not finite"),
            (Tampered(node: n => n with { Pose = new RootPose(new Vector3(1e30f, 0f, 0f), n.Pose.Rotation) }), "node 3 has a position that is not finite or lies beyond"),
            (Tampered(node: n => n with { Pose = new RootPose(n.Pose.Position + new Vector3(0f, 500f, 0f), n.Pose.Rotation) }), "outside the level's bounds"),
            (Tampered(node: n => n with { Pose = new RootPose(n.Pose.Position, new Quaternion(0f, 0f, 0f, 3f)) }), "not a unit quaternion"),
            (Tampered(node: n => n with { Contacts = [n.Contacts[0] with { Limb = 17 }] }), "contact of limb 17, but skeleton has 4 limbs"),
            (Tampered(node: n => n with { Contacts = [n.Contacts[0] with { Limb = -2 }] }), "negative limb"),
            (Tampered(node: n => n with { Contacts = [n.Contacts[0] with { Mu = float.PositiveInfinity }] }), "μ outside"),
            (Tampered(edge: e => WithArc(e, e.Arc.TakeoffVelocity, 0f, e.Arc.Gravity)), "flight time of 0 s"),
            (Tampered(edge: e => WithArc(e, e.Arc.TakeoffVelocity, -1f, e.Arc.Gravity)), "flight time of -1 s"),
            (Tampered(edge: e => WithArc(e, new Vector3(float.NaN), e.Arc.FlightTime, e.Arc.Gravity)), "velocity that is not finite"),
            (Tampered(edge: e => WithArc(e, e.Arc.TakeoffVelocity, e.Arc.FlightTime, 5f)), "gravity of 5 m/s²"),
            (Tampered(edge: e => WithArc(e, e.Arc.TakeoffVelocity, e.Arc.FlightTime * 0.95f, e.Arc.Gravity)), "do not fit its ends"),
            (Tampered(edge: e => WithArc(e, e.Arc.TakeoffVelocity * 40f, e.Arc.FlightTime, e.Arc.Gravity)), "faster than skeleton's speed limits"),
        };
        foreach ((string path, string expected) in cases)
        {
            Assert.That(() => RoadmapFile.Load(path, level, skeleton), Throws.TypeOf<RoadmapFileException>().With.Message.Contains(expected).And.Message.Contains(path), expected);
        }
    }

    [Test]
    public void ATooLongVarintOrAnUnfinishedNameIsCorruptNotACrash()
    {
        byte[] good = RoadmapFile.ToBytes(Baked.Value);
        int nameAt = 8 + 2 + 32 + 32; // magic, version, fingerprints: then the name's 7-bit length
        foreach (byte[] prefix in new[] { new byte[] { 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF }, [0xFF, 0xFF, 0xFF, 0x7F] })
        {
            byte[] bad = [.. good.AsSpan(0, nameAt), .. prefix, .. good.AsSpan(nameAt + 1, good.Length - nameAt - 1 - 32)];
            bad = [.. bad, .. SHA256.HashData(bad)];
            Assert.That(() => RoadmapFile.FromBytes(bad, "varint.roadmap"), Throws.TypeOf<RoadmapFileException>().With.Message.Contains("varint.roadmap").And.Message.Contains("corrupt"));
        }
    }

    [Test]
    public void OnlyRegularFilesAreRead()
    {
        ReducedCharacter skeleton = CharacterPresets.Skeleton();
        Assert.Multiple(() =>
        {
            Assert.That(() => RoadmapFile.Load(_folder, Scene.Value.Level, skeleton), Throws.TypeOf<RoadmapFileException>().With.Message.Contains("is a folder"));
            if (OperatingSystem.IsLinux())
            {
                Assert.That(() => RoadmapFile.Load("/dev/zero", Scene.Value.Level, skeleton), Throws.TypeOf<RoadmapFileException>().With.Message.Contains("not a regular file"));
                string link = Path.Combine(_folder, "zero.roadmap");
                File.CreateSymbolicLink(link, "/dev/zero");
                Assert.That(() => RoadmapFile.Load(link, Scene.Value.Level, skeleton), Throws.TypeOf<RoadmapFileException>().With.Message.Contains("not a regular file"));
            }
        });
    }
}
