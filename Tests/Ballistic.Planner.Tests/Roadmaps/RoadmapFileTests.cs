using Ballistic.Authoring.Characters;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Planning;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Roadmaps;

public sealed class RoadmapFileTests
{
    private static readonly Lazy<PlanningScene> Scene = new(() => PlanningScene.Create(GapCourse.Build(), CharacterPresets.Skeleton()));
    private static readonly Lazy<Roadmap> Baked = new(() => new RoadmapBaker(Scene.Value).Bake(new BakeSettings { Seed = 21, MaxNodes = 30, Threads = 2 }).Roadmap);

    [Test]
    public void RoundTripsExactly()
    {
        byte[] bytes = RoadmapFile.ToBytes(Baked.Value);
        Roadmap back = RoadmapFile.FromBytes(bytes);
        Assert.Multiple(() =>
        {
            Assert.That(RoadmapBakerTests.Describe(back), Is.EqualTo(RoadmapBakerTests.Describe(Baked.Value)));
            Assert.That(RoadmapFile.ToBytes(back), Is.EqualTo(bytes));
            Assert.That(back.Edges.Select(e => e.Arc.LandingVelocity), Is.EqualTo(Baked.Value.Edges.Select(e => e.Arc.LandingVelocity)));
            Assert.That(back.Seed, Is.EqualTo(21));
        });
    }

    [Test]
    public void BakesAreByteIdenticalAcrossThreadCounts()
    {
        var baker = new RoadmapBaker(Scene.Value);
        byte[] one = RoadmapFile.ToBytes(baker.Bake(new BakeSettings { Seed = 21, MaxNodes = 30, Threads = 1 }).Roadmap);
        byte[] three = RoadmapFile.ToBytes(baker.Bake(new BakeSettings { Seed = 21, MaxNodes = 30, Threads = 3 }).Roadmap);
        Assert.That(three, Is.EqualTo(one));
    }

    [Test]
    public void DamagedFilesAreRefusedWithOneSentence()
    {
        byte[] good = RoadmapFile.ToBytes(Baked.Value);
        byte[] flipped = (byte[])good.Clone();
        flipped[good.Length / 2] ^= 0x40;
        byte[] newer = (byte[])good.Clone();
        newer[8] = 9;
        Assert.Multiple(() =>
        {
            Assert.That(() => RoadmapFile.FromBytes(good.AsSpan(0, good.Length - 100), "r.bin"), Throws.TypeOf<RoadmapFileException>().With.Message.Contains("corrupt or truncated"));
            Assert.That(() => RoadmapFile.FromBytes(good.AsSpan(0, 20), "r.bin"), Throws.TypeOf<RoadmapFileException>().With.Message.Contains("not a Ballistic roadmap"));
            Assert.That(() => RoadmapFile.FromBytes(flipped, "r.bin"), Throws.TypeOf<RoadmapFileException>().With.Message.Contains("checksum"));
            Assert.That(() => RoadmapFile.FromBytes(newer, "r.bin"), Throws.TypeOf<RoadmapFileException>().With.Message.Contains("version 9"));
            Assert.That(() => RoadmapFile.FromBytes("PK\u0003\u0004 a zip file, not a roadmap at all........."u8.ToArray(), "r.bin"), Throws.TypeOf<RoadmapFileException>().With.Message.Contains("r.bin"));
        });
    }

    [Test]
    public void MismatchedLevelOrCharacterIsRefused()
    {
        string path = Path.Combine(Path.GetTempPath(), $"ballistic-{Guid.NewGuid():N}.roadmap");
        try
        {
            RoadmapFile.Save(Baked.Value, path);
            Assert.Multiple(() =>
            {
                Assert.That(RoadmapFile.Load(path, Scene.Value.Level.Fingerprint, CharacterPresets.Skeleton()).Nodes, Has.Count.EqualTo(30));
                Assert.That(() => RoadmapFile.Load(path, new string('0', 64), CharacterPresets.Skeleton()), Throws.TypeOf<RoadmapFileException>().With.Message.Contains("another level"));
                Assert.That(() => RoadmapFile.Load(path, Scene.Value.Level.Fingerprint, CharacterPresets.Frog()), Throws.TypeOf<RoadmapFileException>().With.Message.Contains("'skeleton', not 'frog'"));
                Assert.That(() => RoadmapFile.Load(path + ".missing", Scene.Value.Level.Fingerprint, CharacterPresets.Skeleton()), Throws.TypeOf<RoadmapFileException>().With.Message.Contains("cannot be read"));
                Assert.That(Directory.GetFiles(Path.GetDirectoryName(path)!, $".{Path.GetFileName(path)}*"), Is.Empty, "no temporary file left behind");
            });
        }
        finally
        {
            File.Delete(path);
        }
    }
}
