using Ballistic.Planner.Rigs;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Rigs;

/// <summary>
/// A rig read with the wrong up axis lies on its side (a Z-up export without <c>upAxis</c>) or stands on its head: it
/// is refused in one line naming <c>upAxis</c> and <c>forwardAxis</c> and the axis the rig seems to use, never planned
/// lying down.
/// </summary>
public sealed class LyingRigTests
{
    private string _folder = "";

    [SetUp]
    public void MakeFolder()
    {
        _folder = Path.Combine(Path.GetTempPath(), $"ballistic-lying-{Guid.NewGuid():N}");
        Directory.CreateDirectory(_folder);
    }

    [TearDown]
    public void RemoveFolder() => Directory.Delete(_folder, recursive: true);

    [TestCase("human-zup", "\"upAxis\":\"+Z\",\"forwardAxis\":\"-Y\",", "", "+Z", TestName = "A Z-up human without upAxis is refused, naming +Z")]
    [TestCase("human", "\"name\":", "\"upAxis\":\"-Y\",\"forwardAxis\":\"-Z\",\"name\":", "+Y", TestName = "A Y-up human read upside down is refused, naming +Y")]
    [TestCase("dog", "\"name\":", "\"upAxis\":\"+X\",\"forwardAxis\":\"+Z\",\"name\":", "+Y", TestName = "A dog read with X up is refused, naming +Y")]
    public void ARigLyingDownIsRefusedInOneLine(string character, string from, string to, string seemsUp)
    {
        ForeignCharacter rig = ForeignCharacters.Named(character);
        (string gltf, string spec) = rig.Write(_folder);
        string text = File.ReadAllText(spec);
        Assert.That(text, Does.Contain(from), "the spec as written");
        File.WriteAllText(spec, ReplaceFirst(text, from, to));

        RigException? refused = Assert.Throws<RigException>(() => CharacterSpecFile.Load(gltf, spec));
        Assert.Multiple(() =>
        {
            Assert.That(refused!.Message, Does.StartWith(spec + ": keys 'upAxis' and 'forwardAxis'"));
            Assert.That(refused.Message, Does.Contain($"seems to use {seemsUp} as up"));
            Assert.That(refused.Message.Split('\n'), Has.Length.EqualTo(1));
        });
    }

    [TestCase("human")]
    [TestCase("human-zup")]
    [TestCase("dog")]
    [TestCase("tailed")]
    public void RigsStandingUprightLoad(string character)
    {
        (string gltf, string spec) = ForeignCharacters.Named(character).Write(_folder);
        Assert.DoesNotThrow(() => CharacterSpecFile.Load(gltf, spec));
    }

    private static string ReplaceFirst(string text, string from, string to)
    {
        int at = text.IndexOf(from, StringComparison.Ordinal);
        return text[..at] + to + text[(at + from.Length)..];
    }
}
