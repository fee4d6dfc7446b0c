using System.Text;
using System.Text.Json.Nodes;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Tests.Support;
using Ballistic.Runtime.Baking;

namespace Ballistic.Planner.Tests.Baking;

public sealed class CharacterAssetTests
{
    private static readonly string Folder = Path.Combine(RepositoryFiles.Root, "Scenes", "characters");

    private static readonly string SkeletonGlb = Path.Combine(Folder, "skeleton.glb");

    private static readonly string SkeletonSpec = Path.Combine(Folder, "skeleton.limbs.json");

    private static readonly Lazy<(CharacterModel Model, ReducedCharacter Reduced)> ByPaths = new(() => CharacterAsset.FromFiles(SkeletonGlb, SkeletonSpec).Load());

    private string _folder = "";

    [SetUp]
    public void MakeFolder() => _folder = Directory.CreateTempSubdirectory("ballistic-asset-").FullName;

    [TearDown]
    public void RemoveFolder() => Directory.Delete(_folder, recursive: true);

    [Test]
    public void TheBundledSkeletonLoadsTheSameByPathsAndByBytes()
    {
        (CharacterModel model, ReducedCharacter reduced) = ByPaths.Value;
        (CharacterModel fromBytes, ReducedCharacter reducedFromBytes) = CharacterAsset.FromBytes(
            File.ReadAllBytes(SkeletonGlb), "res://characters/skeleton.glb", File.ReadAllBytes(SkeletonSpec), "res://characters/skeleton.limbs.json").Load();
        Assert.Multiple(() =>
        {
            Assert.That(reducedFromBytes.Fingerprint, Is.EqualTo(reduced.Fingerprint));
            Assert.That(reduced.Fingerprint, Is.EqualTo(CharacterSpecFile.Load(SkeletonGlb, SkeletonSpec).Reduced.Fingerprint), "what the command line's --character loads");
            Assert.That(reduced.Name, Is.EqualTo("skeleton"));
            Assert.That(fromBytes.Rig.Joints.Select(j => j.Name), Is.EqualTo(model.Rig.Joints.Select(j => j.Name)));
            Assert.That(fromBytes.Limbs.Select(l => l.Name), Is.EqualTo(model.Limbs.Select(l => l.Name)));
            Assert.That(fromBytes.Source!.Model.Name, Is.EqualTo("res://characters/skeleton.glb"));
        });
    }

    [Test]
    public void OverridesGiveTheCharacterOfASpecHoldingThem()
    {
        JsonObject spec = JsonNode.Parse(File.ReadAllBytes(SkeletonSpec))!.AsObject();
        spec["takeoffSpeedMax"] = 6.5;
        spec["landingSpeedMax"] = 10;
        spec["friction"] = 0.8;
        byte[] edited = Encoding.UTF8.GetBytes(spec.ToJsonString());
        ReducedCharacter fromSpec = CharacterAsset.FromBytes(File.ReadAllBytes(SkeletonGlb), "skeleton.glb", edited, "edited.limbs.json").Load().Reduced;
        ReducedCharacter overridden = CharacterAsset.FromFiles(SkeletonGlb, SkeletonSpec, takeoffSpeedMax: 6.5f, landingSpeedMax: 10f, friction: 0.8f).Load().Reduced;
        Assert.Multiple(() =>
        {
            Assert.That(overridden.Fingerprint, Is.EqualTo(fromSpec.Fingerprint));
            Assert.That(overridden.Fingerprint, Is.Not.EqualTo(ByPaths.Value.Reduced.Fingerprint));
            Assert.That((overridden.TakeoffSpeedMax, overridden.LandingSpeedMax, overridden.Friction), Is.EqualTo((6.5f, 10f, 0.8f)));
            Assert.That(overridden.StanceLift, Is.EqualTo(ByPaths.Value.Reduced.StanceLift));
        });
    }

    [Test]
    public void BadJsonIsAOneLineErrorNamingTheFile()
    {
        byte[] broken = "{ \"schema\": \"ballistic.character/1\", \"limbs\": "u8.ToArray();
        RigException fromBytes = Assert.Throws<RigException>(() =>
            CharacterAsset.FromBytes(File.ReadAllBytes(SkeletonGlb), "res://characters/skeleton.glb", broken, "res://characters/broken.limbs.json").Load())!;
        string path = Path.Combine(_folder, "broken.limbs.json");
        File.WriteAllBytes(path, broken);
        RigException fromFile = Assert.Throws<RigException>(() => CharacterAsset.FromFiles(SkeletonGlb, path).Load())!;
        Assert.Multiple(() =>
        {
            Assert.That(fromBytes.Message, Does.StartWith("res://characters/broken.limbs.json is not valid JSON: "));
            Assert.That(fromFile.Message, Does.StartWith($"{path} is not valid JSON: "));
            Assert.That(fromBytes.Message, Does.Not.Contain('\n'));
            Assert.That(fromFile.Message, Does.Not.Contain('\n'));
        });
    }

    [Test]
    public void MissingFilesAndBadRigsAreNamed()
    {
        string missing = Path.Combine(_folder, "nobody.limbs.json");
        string noSpec = Assert.Throws<RigException>(() => CharacterAsset.FromFiles(SkeletonGlb, missing).Load())!.Message;
        string noRig = Assert.Throws<RigException>(() => CharacterAsset.FromFiles(Path.Combine(_folder, "nobody.glb"), SkeletonSpec).Load())!.Message;
        string badRig = Assert.Throws<RigException>(() =>
            CharacterAsset.FromBytes("not a glb"u8.ToArray(), "res://characters/junk.glb", File.ReadAllBytes(SkeletonSpec), "res://characters/skeleton.limbs.json").Load())!.Message;
        Assert.Multiple(() =>
        {
            Assert.That(noSpec, Is.EqualTo($"Limb spec {missing} cannot be read: it does not exist."));
            Assert.That(noRig, Does.Contain(Path.Combine(_folder, "nobody.glb")).And.Contain("does not exist"));
            Assert.That(badRig, Does.StartWith("res://characters/junk.glb"));
            Assert.That(new[] { noSpec, noRig, badRig }, Has.None.Contain('\n'));
        });
    }

    [TestCase(-1f, null, null, "the takeoff speed override must be positive and at most 1000 m/s, not -1.")]
    [TestCase(0f, null, null, "the takeoff speed override must be positive and at most 1000 m/s, not 0.")]
    [TestCase(null, float.NaN, null, "the landing speed override must be positive and at most 1000 m/s, not NaN.")]
    [TestCase(null, null, -0.1f, "the friction override must be between 0 and 1000 μ, not -0.1.")]
    [TestCase(null, null, float.PositiveInfinity, "the friction override must be between 0 and 1000 μ, not Infinity.")]
    public void AnOverrideOutOfRangeIsNamed(float? takeoff, float? landing, float? friction, string problem)
    {
        RigException error = Assert.Throws<RigException>(() => CharacterAsset.FromFiles(SkeletonGlb, SkeletonSpec, takeoff, landing, friction).Load())!;
        Assert.That(error.Message, Is.EqualTo($"{SkeletonSpec}: {problem}"));
    }
}
